//! The numbers layer: one scalar abstraction shared by every number system.
//!
//! * [`Scalar`] — field operations, constants taken from `&self`, parsing, exact
//!   square roots where they exist.  Implemented for `f64`, [`rug::Float`] (MPFR at
//!   any precision), [`Cplx`] (complex numbers over any [`Real`], e.g. `Cplx<f64>`),
//!   [`rug::Complex`] (MPC), [`num_rational::BigRational`] (exact) and [`Dual`]
//!   (forward-mode automatic differentiation over any scalar).
//! * [`Real`] — an ordered scalar with the elementary transcendental functions:
//!   `f64`, `rug::Float`, `Dual<R>`.
//! * [`ComplexScalar`] — a complex scalar with its real type: `Cplx<R>`, `rug::Complex`.
//!
//! **Precision travels with the values.**  `rug::Float` is not `Copy` and carries its
//! own precision, so every constant or conversion is made from an existing value
//! (`x.from_f64(0.5)`, `x.pi()`), and the result has that value's precision.  There
//! is no global precision setting.
//!
//! ```
//! use eulertop_numerics::numbers::{Real, Scalar};
//! let x = rug::Float::with_val(256, 2);
//! let r = Real::sqrt(&x);          // 256-bit square root of 2
//! assert_eq!(Real::prec(&r), 256);
//! let back = r.clone() * r - x.from_i64(2);
//! assert!(back.magnitude() < 1e-75);
//! ```

#[cfg(feature = "arb")]
mod ball;
#[cfg(feature = "arb")]
mod ball_elliptic;
mod complex;
mod dual;
mod dual_elliptic;
mod float64;
pub mod gmp_kernels;
mod mpfr;
mod rational;

#[cfg(feature = "arb")]
pub use ball::{Ball, Decisions};
pub use complex::{C64, Cplx};
pub use dual::Dual;

/// `(sn, cn, dn)` as dual numbers over `R`.
pub type DualTriple<R> = (Dual<R>, Dual<R>, Dual<R>);
pub use rational::{Rational, parse_rational};

use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Is `s` (trimmed) a decimal of the one number grammar of every input:
/// `[+-]? (d+ (. d*)? | . d+) ([eE] [+-]? d+)?` with ASCII digits `d`: no underscores,
/// no `inf` or `nan`, no hexadecimal.
///
/// ```
/// use eulertop_numerics::numbers::is_decimal;
/// assert!(is_decimal("-1.5e-3") && is_decimal(".5") && is_decimal("2."));
/// assert!(!is_decimal("1_000") && !is_decimal("inf") && !is_decimal("0x10"));
/// ```
pub fn is_decimal(s: &str) -> bool {
    let b = s.trim().as_bytes();
    let mut i = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let digits = |i: &mut usize| {
        let start = *i;
        while b.get(*i).is_some_and(u8::is_ascii_digit) {
            *i += 1;
        }
        *i - start
    };
    let mut n = digits(&mut i);
    if b.get(i) == Some(&b'.') {
        i += 1;
        n += digits(&mut i);
    }
    if n == 0 {
        return false;
    }
    if matches!(b.get(i), Some(b'e' | b'E')) {
        i += 1;
        if matches!(b.get(i), Some(b'+' | b'-')) {
            i += 1;
        }
        if digits(&mut i) == 0 {
            return false;
        }
    }
    i == b.len()
}

/// Does the mantissa of a decimal (the part before any exponent) have a nonzero digit?
/// (Then a value of 0 is an underflow.)
///
/// ```
/// assert!(eulertop_numerics::numbers::nonzero_mantissa("1.5e-324"));
/// assert!(!eulertop_numerics::numbers::nonzero_mantissa("0.0e5"));
/// ```
pub fn nonzero_mantissa(t: &str) -> bool {
    let mant = t.split(['e', 'E']).next().unwrap_or("");
    mant.bytes().any(|b| (b'1'..=b'9').contains(&b))
}

/// Is the decimal `s` exactly 1 (`1`, `1.000`, `0.1e1`, `+1`)?  `false` for anything
/// else, text that is not a decimal included.
///
/// ```
/// use eulertop_numerics::numbers::decimal_is_one;
/// assert!(decimal_is_one("1.000") && decimal_is_one("10e-1"));
/// assert!(!decimal_is_one("0.99999999999999999999999"));
/// ```
pub fn decimal_is_one(s: &str) -> bool {
    let t = s.trim();
    if !is_decimal(t) {
        return false;
    }
    // a decimal of n digits other than 1 differs from 1 by at least 10^-n, far more
    // than the rounding at 4n + 64 bits
    let bits = u32::try_from(4 * t.len() + 64).unwrap_or(u32::MAX);
    rug::Float::parse(t).is_ok_and(|p| rug::Float::with_val(bits, p) == 1)
}

/// Errors of the numbers layer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum NumError {
    /// A string that is not a number of the expected form.
    #[error("malformed number '{0}'")]
    Parse(String),
    /// An exact square root of a value that is not a perfect square.
    #[error("square root of {0} is not rational")]
    NotPerfectSquare(String),
    /// A square root of a negative real.
    #[error("square root of negative value {0}")]
    NegativeSqrt(String),
    /// An operation the number system cannot do (e.g. `exp` on exact rationals).
    #[error("{0} is not available for exact rationals")]
    NotExact(&'static str),
    /// Division by an exact zero.
    #[error("division by zero")]
    DivisionByZero,
}

/// A field element of some number system.
///
/// All constructors take `&self` so that the result inherits the receiver's
/// precision (for MPFR) or exactness (for rationals).
pub trait Scalar:
    Clone
    + Debug
    + PartialEq
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// Zero, with the precision of `self`.
    fn zero(&self) -> Self;
    /// One, with the precision of `self`.
    fn one(&self) -> Self;
    /// The integer `n`, with the precision of `self` (correctly rounded).
    fn from_i64(&self, n: i64) -> Self;
    /// The f64 value `x`, with the precision of `self` (exact when the precision is
    /// at least 53 bits or the scalar is exact).
    fn from_f64(&self, x: f64) -> Self;
    /// The fraction `n/d`, correctly rounded to the precision of `self`.
    fn from_ratio(&self, n: i64, d: i64) -> Self {
        self.from_i64(n) / self.from_i64(d)
    }
    /// Parses a decimal literal (`1.25`, `-3e-4`, and for exact scalars `3/4`) at the
    /// precision of `self`.
    fn parse_like(&self, s: &str) -> Result<Self, NumError>;
    /// Working precision in bits; `None` for exact arithmetic.
    fn precision(&self) -> Option<u32>;
    /// Is this exactly zero?
    fn is_zero(&self) -> bool;
    /// Is this zero, for `==` and `!=` in an expression language?  A number answers
    /// [`Scalar::is_zero`]; a symbolic value whose normal form is not 0 decides on the
    /// points of its domain that it is nonzero (and records that), or cannot decide.
    fn test_zero(&self) -> bool {
        self.is_zero()
    }
    /// The sign (−1, 0, 1) for `sign` and `abs` in an expression language.  A number
    /// answers by comparison; a symbolic value answers only when its sign is exact (a
    /// rational, or exactly 0), because a sign decided at sample points of the domain
    /// would be the very condition such a formula states.
    fn stated_sign(&self) -> Result<i32, String>
    where
        Self: PartialOrd,
    {
        let z = self.zero();
        Ok(if *self > z {
            1
        } else if *self < z {
            -1
        } else {
            0
        })
    }
    /// A symbol `σ = sign(x)` standing for this value's sign, where a symbolic backend
    /// carries the sign of an indeterminate that way; `None` (the default, and always
    /// for numbers) otherwise.
    fn sign_symbol(&self) -> Result<Option<Self>, String> {
        Ok(None)
    }
    /// The value of `sign(x)` in an expression language: [`Scalar::sign_symbol`] if
    /// there is one, else [`Scalar::stated_sign`] as a number.
    fn stated_sign_value(&self) -> Result<Self, String>
    where
        Self: PartialOrd,
    {
        if let Some(sigma) = self.sign_symbol()? {
            return Ok(sigma);
        }
        Ok(self.from_i64(i64::from(self.stated_sign()?)))
    }
    /// The value of `abs(x)` in an expression language: `σ·x` for a
    /// [`Scalar::sign_symbol`] `σ`, else `x` or `−x` by [`Scalar::stated_sign`].
    fn stated_abs(&self) -> Result<Self, String>
    where
        Self: PartialOrd,
    {
        if let Some(sigma) = self.sign_symbol()? {
            return Ok(sigma * self.clone());
        }
        Ok(match self.stated_sign()? {
            s if s < 0 => -self.clone(),
            // −0 + 0 = +0 (round to nearest), so |−0| is +0; the derivative is kept
            0 => self.clone() + self.zero(),
            _ => self.clone(),
        })
    }
    /// The absolute value (modulus), rounded to `f64`.  Used for residual scaling.
    fn magnitude(&self) -> f64;
    /// The value rounded to `f64` (for complex scalars: the real part).
    fn to_f64(&self) -> f64;
    /// Is the value finite (not NaN or infinite)?  Exact scalars always are.
    fn is_finite(&self) -> bool;
    /// `log2 |self|` without underflow or overflow of the `f64` result's argument
    /// (−∞ for zero): the size of a value at any precision.
    fn log2_abs(&self) -> f64 {
        self.magnitude().log2()
    }
    /// A square root: correctly rounded for floating types (principal branch for
    /// complex ones, error for negative reals), and exact for rationals, where it is an
    /// error unless the argument is a perfect square.
    fn try_sqrt(&self) -> Result<Self, NumError>;
    /// `1/self`.
    fn recip(&self) -> Self {
        self.one() / self.clone()
    }
    /// `a₁b₁ + a₂b₂ + a₃b₃`, in that order (an exact backend may sum the products
    /// over one denominator instead).
    fn dot3(a: [&Self; 3], b: [&Self; 3]) -> Self {
        a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
    }
    /// `a·b − c·d` (an exact backend may subtract over one denominator instead).
    fn det2(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
        a.clone() * b.clone() - c.clone() * d.clone()
    }
    /// `self` squared.
    fn sqr(&self) -> Self {
        self.clone() * self.clone()
    }
    /// Integer power by repeated squaring (negative `n` inverts).
    fn powi(&self, n: i32) -> Self {
        let mut base = if n < 0 { self.recip() } else { self.clone() };
        let mut e = n.unsigned_abs();
        let mut acc = self.one();
        while e > 0 {
            if e & 1 == 1 {
                acc = acc * base.clone();
            }
            e >>= 1;
            if e > 0 {
                base = base.sqr();
            }
        }
        acc
    }
    /// Decimal rendering with `digits` significant digits (exact form for rationals).
    fn to_decimal(&self, digits: usize) -> String;
}

/// An ordered real scalar with elementary functions.
pub trait Real: Scalar + PartialOrd {
    /// Is the precision fixed by the type (`f64`, `Dual<f64>`), so that algorithms get
    /// no guard bits and every rounding counts?  `false` for `rug::Float`, whose
    /// precision travels with each value and can be raised for intermediate results.
    ///
    /// ```
    /// use eulertop_numerics::numbers::{Dual, Real};
    /// assert!(<f64 as Real>::FIXED && <Dual<f64> as Real>::FIXED);
    /// assert!(!<rug::Float as Real>::FIXED);
    /// ```
    const FIXED: bool;
    /// Does this type evaluate the elliptic functions by rules of its own instead of the
    /// numerical algorithms of `special`?  A symbolic scalar does (it expands `sn`, `cn`,
    /// `dn` by the addition theorems); then [`Real::sncndn_by_rule`] and
    /// [`Real::quarter_period_by_rule`] answer, and every other function of `special`
    /// (am, F, the inverse, complex arguments) is refused with a clear error rather than
    /// iterated on symbols.  `false` for every numeric type.
    const BY_RULE: bool = false;
    /// Is every value of this type a plain `f64` (`to_f64` loses nothing and
    /// `x.from_f64(v)` is `v`)?  Then data that depends on a parameter only (e.g. the
    /// per-modulus data of the Jacobi functions in [`crate::special`]) can be computed in
    /// `f64` once and shared between calls.  `true` for `f64` only (`Dual<f64>` carries
    /// derivative parts).
    ///
    /// ```
    /// use eulertop_numerics::numbers::{Dual, Real};
    /// assert!(<f64 as Real>::PLAIN_F64 && !<Dual<f64> as Real>::PLAIN_F64);
    /// ```
    const PLAIN_F64: bool = false;
    /// The value as an MPFR number when the type is one (`rug::Float`), so that
    /// algorithms can take in-place MPFR paths and share multi-precision data between
    /// calls; `None` for every other type.
    ///
    /// ```
    /// use eulertop_numerics::numbers::Real;
    /// let x = rug::Float::with_val(128, 2);
    /// assert_eq!(x.as_mpfr(), Some(&x));
    /// assert!(2.0_f64.as_mpfr().is_none());
    /// ```
    fn as_mpfr(&self) -> Option<&rug::Float> {
        None
    }
    /// An MPFR number as a value of this type: `Some` exactly for the types whose
    /// [`Real::as_mpfr`] answers (the inverse of it).
    fn from_mpfr(_x: rug::Float) -> Option<Self> {
        None
    }
    /// Is every value of this type an enclosure (an Arb ball, `Ball` with the feature
    /// `arb`, or a dual number over balls), so that an algorithm whose result is not an
    /// enclosure (an iteration stopped after some steps) must not run on it?  `false`
    /// for every other type.
    const ENCLOSES: bool = false;
    /// Does this type check the domain of `ln` itself (the prover's symbols: an opaque
    /// symbol whose values are undefined where the argument is not positive), so that
    /// the evaluator must not compare the argument with 0 (a sign the prover would have
    /// to prove)?  `false` for every numeric type.
    const DEFERS_DOMAIN_CHECKS: bool = false;
    /// The value as a [`Ball`] when the type is one; `None` for every other type.
    #[cfg(feature = "arb")]
    fn as_ball(&self) -> Option<&Ball> {
        None
    }
    /// A [`Ball`] as a value of this type: `Some` exactly for [`Ball`].
    #[cfg(feature = "arb")]
    fn from_ball(_x: Ball) -> Option<Self> {
        None
    }
    /// Why a value is meaningless, for number systems that record failures inside
    /// operators (the prover's symbolic values); `None` for the others.
    fn failure(&self) -> Option<String> {
        None
    }
    /// `(sn, cn, dn)(u, k)` by the type's own rule (only called when [`Real::BY_RULE`]).
    fn sncndn_by_rule(_u: &Self, _k: &Self) -> Result<(Self, Self, Self), String> {
        Err("sn, cn, dn have no rule for this type".into())
    }
    /// `(sn, cn, dn)(u, k)` of dual numbers over this type by its own rule, for a type
    /// that evaluates by rules but does not enclose (only called when
    /// [`Real::BY_RULE`] and not [`Real::ENCLOSES`]).
    fn sncndn_dual_by_rule(_u: &Dual<Self>, _k: &Dual<Self>) -> Result<DualTriple<Self>, String> {
        Err("sn, cn, dn have no rule for this type".into())
    }
    /// The amplitude `am(u, k)` by the type's own rule (only called when
    /// [`Real::BY_RULE`]).
    fn am_by_rule(_u: &Self, _k: &Self) -> Result<Self, String> {
        Err("am is not algebraic: no exact rule for it".into())
    }
    /// The quarter period `K(k)` (or `K'(k)` when `complementary`) by the type's own rule
    /// (only called when [`Real::BY_RULE`]).
    fn quarter_period_by_rule(_k: &Self, _complementary: bool) -> Result<Self, String> {
        Err("K has no rule for this type".into())
    }
    /// The incomplete elliptic integral `F(φ, k)` by the type's own rule (only called
    /// when [`Real::BY_RULE`]).
    fn ellipf_by_rule(_phi: &Self, _k: &Self) -> Result<Self, String> {
        Err("F has no rule for this type".into())
    }
    /// The complete integral `E(k)` (or `E'(k) = E(√(1−k²))` when `complementary`) by
    /// the type's own rule (only called when [`Real::BY_RULE`]); used by the derivatives
    /// of the rules in `k`.
    fn ellipe_by_rule(_k: &Self, _complementary: bool) -> Result<Self, String> {
        Err("E has no rule for this type".into())
    }
    /// The incomplete integral `E(φ, k)` by the type's own rule (only called when
    /// [`Real::BY_RULE`]); used by the derivatives of the rules in `k`.
    fn ellipeinc_by_rule(_phi: &Self, _k: &Self) -> Result<Self, String> {
        Err("E(phi, k) has no rule for this type".into())
    }
    /// The argument `u` with `(sn, cn, dn)(u, k) = (sn, cn, dn)` by the type's own rule
    /// (only called when [`Real::BY_RULE`]).
    fn jacobi_inverse_by_rule(
        _sn: &Self,
        _cn: &Self,
        _dn: &Self,
        _k: &Self,
    ) -> Result<Self, String> {
        Err("the inverse of sn, cn, dn has no rule for this type".into())
    }
    /// A value that the type's rules cannot expand, standing for `f(args)` (only called
    /// when [`Real::BY_RULE`]): a symbolic scalar makes it an opaque symbol, free in its
    /// proofs, whose numeric value at each point is `values` of the arguments' values
    /// there (`None` where `f` is undefined).  An identity proved with the symbol free
    /// holds for every value of it, the actual one included.
    fn opaque_by_rule(
        f: &str,
        _args: &[&Self],
        _values: &dyn Fn(&[rug::Float]) -> Option<rug::Float>,
    ) -> Result<Self, String> {
        Err(format!("{f} has no rule for this type"))
    }
    /// Precision in bits (53 for `f64`).
    fn prec(&self) -> u32;
    /// The same value rounded to `bits` of precision (identity for `f64`).
    fn with_prec(&self, bits: u32) -> Self;
    /// π at the precision of `self`.
    fn pi(&self) -> Self;
    /// Machine epsilon at the precision of `self`: `2^(1-prec)`.
    fn epsilon(&self) -> Self {
        self.one().mul_2si(1 - self.prec() as i32)
    }
    /// `self · 2^n`, exactly.
    fn mul_2si(&self, n: i32) -> Self;
    /// `|self|`.
    fn abs(&self) -> Self;
    /// Square root; NaN (not a panic) for negative arguments.
    fn sqrt(&self) -> Self;
    /// `e^self`.
    fn exp(&self) -> Self;
    /// `e^self − 1`, accurate also for small `|self|`.  The default `exp − 1` loses
    /// relative accuracy near 0; `f64`, `rug::Float` and `Dual` override it.
    fn exp_m1(&self) -> Self {
        self.exp() - self.one()
    }
    /// Natural logarithm.
    fn ln(&self) -> Self;
    /// Sine.
    fn sin(&self) -> Self;
    /// Cosine.
    fn cos(&self) -> Self;
    /// Sine and cosine together.
    fn sin_cos(&self) -> (Self, Self) {
        (self.sin(), self.cos())
    }
    /// Sine and cosine of an argument already reduced to `|x| ≤ π/4·(1 + 2⁻²⁰)`.
    ///
    /// Callers that know their argument is small (e.g. the bottom of the Landen chain in
    /// [`crate::special`]) use this to let fixed-precision types skip the argument
    /// reduction of a general `sin_cos`.  The default is [`Real::sin_cos`]; `f64` uses
    /// the fdlibm kernel polynomials (error below 1 ulp on `[−π/4, π/4]`).  Outside the
    /// stated range the result is unspecified (but never a panic).
    ///
    /// ```
    /// use eulertop_numerics::numbers::Real;
    /// let (s, c) = 0.5_f64.sin_cos_kernel();
    /// assert!((s - 0.5_f64.sin()).abs() <= f64::EPSILON / 2.0);
    /// assert!((c - 0.5_f64.cos()).abs() <= f64::EPSILON / 2.0);
    /// ```
    fn sin_cos_kernel(&self) -> (Self, Self) {
        self.sin_cos()
    }
    /// Tangent.
    fn tan(&self) -> Self {
        let (s, c) = self.sin_cos();
        s / c
    }
    /// Arc tangent.
    fn atan(&self) -> Self;
    /// Four-quadrant arc tangent `atan2(self, x)`.
    fn atan2(&self, x: &Self) -> Self;
    /// Arc sine.
    fn asin(&self) -> Self;
    /// Hyperbolic sine.
    fn sinh(&self) -> Self;
    /// Hyperbolic cosine.
    fn cosh(&self) -> Self;
    /// Hyperbolic tangent.
    fn tanh(&self) -> Self;
    /// Inverse hyperbolic sine.
    fn asinh(&self) -> Self;
    /// Inverse hyperbolic tangent.
    fn atanh(&self) -> Self;
    /// Largest integer not above `self`.
    fn floor(&self) -> Self;
    /// Nearest integer (ties away from zero).
    fn round(&self) -> Self;
    /// `self^y` for real `y` (`exp(y ln self)`, self > 0).
    fn powf(&self, y: &Self) -> Self {
        (y.clone() * self.ln()).exp()
    }
    /// The larger of two values.
    fn max_of(&self, other: &Self) -> Self {
        if self >= other {
            self.clone()
        } else {
            other.clone()
        }
    }
    /// The smaller of two values.
    fn min_of(&self, other: &Self) -> Self {
        if self <= other {
            self.clone()
        } else {
            other.clone()
        }
    }
    /// The sign as a value of the type: −1, 0 or 1 for numbers.  A number system whose
    /// values stand for several signs at once (the prover's sign symbols `σ`, `σ² = 1`)
    /// may answer a value that is not a constant, such as `σ` for `σ·x` with `x > 0`.
    ///
    /// ```
    /// use eulertop_numerics::numbers::Real;
    /// assert_eq!((-2.5f64).signum_value(), -1.0);
    /// assert_eq!(0.0f64.signum_value(), 0.0);
    /// ```
    fn signum_value(&self) -> Self {
        self.from_i64(i64::from(self.signum_i()))
    }
    /// Sign: -1, 0 or 1.
    fn signum_i(&self) -> i32 {
        if self.is_zero() {
            0
        } else if *self > self.zero() {
            1
        } else {
            -1
        }
    }
}

/// A complex scalar over a real type.
pub trait ComplexScalar: Scalar {
    /// The underlying real type.
    type R: Real;
    /// `re + i·im`.
    fn from_parts(re: Self::R, im: Self::R) -> Self;
    /// Real part.
    fn re(&self) -> Self::R;
    /// Imaginary part.
    fn im(&self) -> Self::R;
    /// Complex conjugate.
    fn conj(&self) -> Self {
        Self::from_parts(self.re(), -self.im())
    }
    /// Modulus.
    fn abs(&self) -> Self::R {
        let (a, b) = (self.re(), self.im());
        (a.sqr() + b.sqr()).sqrt()
    }
    /// Argument in (-π, π].
    fn arg(&self) -> Self::R {
        self.im().atan2(&self.re())
    }
    /// The imaginary unit at the precision of `self`.
    fn i(&self) -> Self {
        let z = self.re().zero();
        Self::from_parts(z.clone(), z.one())
    }
    /// Embeds a real of the same precision.
    fn from_real(x: Self::R) -> Self {
        let z = x.zero();
        Self::from_parts(x, z)
    }
    /// Principal square root.
    fn sqrt(&self) -> Self {
        let (a, b) = (self.re(), self.im());
        let r = self.abs();
        let zero = a.zero();
        if r.is_zero() {
            return Self::from_parts(zero.clone(), zero);
        }
        let half = a.from_ratio(1, 2);
        // sqrt((r + |a|)/2) computed without cancellation
        let t = ((r + a.abs()) * half.clone()).sqrt();
        if a >= zero {
            let im = b / (t.clone() * a.from_i64(2));
            Self::from_parts(t, im)
        } else {
            let re = b.abs() / (t.clone() * a.from_i64(2));
            let im = if b < zero { -t } else { t };
            Self::from_parts(re, im)
        }
    }
    /// Complex exponential.
    fn exp(&self) -> Self {
        let e = self.re().exp();
        let (s, c) = self.im().sin_cos();
        Self::from_parts(e.clone() * c, e * s)
    }
    /// Principal logarithm.
    fn ln(&self) -> Self {
        Self::from_parts(self.abs().ln(), self.arg())
    }
}
