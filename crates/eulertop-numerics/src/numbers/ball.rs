//! Real balls (Arb's `arb_t`, through FLINT) as a [`Scalar`] and [`Real`]: rigorous
//! enclosures.
//!
//! A [`Ball`] is a midpoint and a radius; every operation returns a ball that contains
//! the exact result for every choice of the arguments inside their balls (Arb's
//! guarantee, outward rounding included).  So an expression evaluated in balls encloses
//! the exact value of that expression for every input in the input balls, as long as
//! the evaluation takes no decision the balls cannot make:
//!
//! * a comparison (`<`, `<=`, `==`, [`Scalar::is_zero`], `floor`) of balls that overlap
//!   where the answer would differ is **undecided**: it answers `false` (or a wide ball)
//!   and is recorded, per thread ([`Decisions`]).  An evaluation with an undecided
//!   comparison proves nothing;
//! * no numerical iteration of [`crate::special`], whose truncation error the balls would
//!   not see, ever runs on balls ([`Real::BY_RULE`]): K, F, sn, cn, dn and their inverse
//!   are Arb's own enclosures (module `ball_elliptic`), every other elliptic function is
//!   refused.
//!
//! ```
//! use eulertop_numerics::numbers::{Ball, Decisions, Real, Scalar};
//! let two = Ball::exact(2.0, 128);
//! let r = Real::sqrt(&two);
//! // the ball of √2 is tight (it excludes the nearest double) and its square holds 2
//! assert!(!r.contains_f64(std::f64::consts::SQRT_2) && r.rad_f64() < 1e-36);
//! assert!((r.clone() * r).contains_f64(2.0));
//! let span = Decisions::start();
//! let wide = Ball::with_radius(0.0, 1.0, 128); // [-1, 1]
//! assert!(!(wide > two.zero()));
//! assert!(!span.all_decided(), "0 < [-1, 1] cannot be decided");
//! ```

use super::{NumError, Real, Scalar};
use flint_sys::arb::*;
use flint_sys::arb_types::arb_struct;
use flint_sys::arf::{arf_get_d, arf_rnd_t_ARF_RND_NEAR};
use std::cell::Cell;
use std::cmp::Ordering;
use std::mem::MaybeUninit;
use std::ops::{Add, Div, Mul, Neg, Sub};

thread_local! {
    static UNDECIDED: Cell<u64> = const { Cell::new(0) };
}

/// Records a comparison the balls could not decide.
fn undecided() {
    UNDECIDED.with(|c| c.set(c.get() + 1));
}

/// A span of evaluation on this thread, for whether a comparison of balls in it was
/// undecided.  Spans nest (an enclosure computed inside another evaluation opens its
/// own): the count of undecided comparisons only grows.
///
/// ```
/// use eulertop_numerics::numbers::{Ball, Decisions};
/// let outer = Decisions::start();
/// let _ = Ball::with_radius(1.0, 0.5, 64) < Ball::exact(1.2, 64); // undecided
/// let inner = Decisions::start();
/// assert!(inner.all_decided() && !outer.all_decided());
/// ```
pub struct Decisions(u64);

impl Decisions {
    /// Opens a span here.
    pub fn start() -> Decisions {
        Decisions(UNDECIDED.with(Cell::get))
    }

    /// Was every comparison of balls on this thread since the start decided?  An
    /// evaluation in balls is an enclosure only then.
    pub fn all_decided(&self) -> bool {
        UNDECIDED.with(Cell::get) == self.0
    }
}

/// A real ball of Arb at a working precision (bits).
///
/// ```
/// use eulertop_numerics::numbers::{Ball, Real};
/// let x = Ball::with_radius(0.5, 1e-10, 128); // [0.5 ± 1e-10]
/// let s = Real::sin(&x);                       // every sin of the ball
/// assert!(s.contains_f64(0.479425538604203) && s.rad_f64() < 2e-10);
/// ```
pub struct Ball {
    b: arb_struct,
    prec: u32,
}

// SAFETY: an arb_t owns its limbs (no shared state); Arb's functions only read their
// `const` arguments, so a ball may be sent to and read from other threads.
unsafe impl Send for Ball {}
// SAFETY: as above.
unsafe impl Sync for Ball {}

impl Drop for Ball {
    fn drop(&mut self) {
        // SAFETY: the ball was initialised by arb_init and is cleared once.
        unsafe { arb_clear(&mut self.b) }
    }
}

impl Clone for Ball {
    fn clone(&self) -> Ball {
        let mut r = Ball::new_zero(self.prec);
        // SAFETY: both balls are initialised.
        unsafe { arb_set(&mut r.b, &self.b) };
        r
    }
}

impl std::fmt::Debug for Ball {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.show(20))
    }
}

fn slong(prec: u32) -> i64 {
    i64::from(prec)
}

impl Ball {
    fn new_zero(prec: u32) -> Ball {
        let mut b = MaybeUninit::<arb_struct>::uninit();
        // SAFETY: arb_init initialises the struct it is given (exact zero).
        unsafe {
            arb_init(b.as_mut_ptr());
            Ball {
                b: b.assume_init(),
                prec,
            }
        }
    }

    /// The exact value `x` (radius 0) at working precision `prec`.
    pub fn exact(x: f64, prec: u32) -> Ball {
        let mut r = Ball::new_zero(prec);
        // SAFETY: the ball is initialised.
        unsafe { arb_set_d(&mut r.b, x) };
        r
    }

    /// The ball `[mid − rad, mid + rad]` (the radius rounded up).
    pub fn with_radius(mid: f64, rad: f64, prec: u32) -> Ball {
        let r = Ball::exact(mid, prec);
        r.inflate(rad.abs())
    }

    /// This ball widened by `rad` (the exact bound `rad` added to its radius).
    pub fn inflate(&self, rad: f64) -> Ball {
        let mut r = self.clone();
        let e = Ball::exact(rad, self.prec);
        // SAFETY: the balls are initialised; arb_add_error adds |e| to the radius.
        unsafe { arb_add_error(&mut r.b, &e.b) };
        r
    }

    fn un(&self, f: unsafe extern "C" fn(*mut arb_struct, *const arb_struct, i64)) -> Ball {
        let mut r = Ball::new_zero(self.prec);
        // SAFETY: every ball is initialised; Arb allows aliasing.
        unsafe { f(&mut r.b, &self.b, slong(self.prec)) };
        r
    }

    fn bin(
        &self,
        o: &Ball,
        f: unsafe extern "C" fn(*mut arb_struct, *const arb_struct, *const arb_struct, i64),
    ) -> Ball {
        let prec = self.prec.max(o.prec);
        let mut r = Ball::new_zero(prec);
        // SAFETY: every ball is initialised; Arb allows aliasing.
        unsafe { f(&mut r.b, &self.b, &o.b, slong(prec)) };
        r
    }

    /// The Arb ball itself, for the Arb functions of this module's siblings.
    pub(super) fn arb(&self) -> &arb_struct {
        &self.b
    }

    /// A copy of an Arb ball, with working precision `prec`.
    pub(super) fn from_arb(x: &arb_struct, prec: u32) -> Ball {
        let mut r = Ball::new_zero(prec);
        // SAFETY: both balls are initialised.
        unsafe { arb_set(&mut r.b, x) };
        r
    }

    /// The working precision in bits.
    pub fn prec_bits(&self) -> u32 {
        self.prec
    }

    /// Does the ball contain the number `x`?
    pub fn contains_f64(&self, x: f64) -> bool {
        let e = Ball::exact(x, 64);
        // SAFETY: both balls are initialised.
        unsafe { arb_contains(&self.b, &e.b) != 0 }
    }

    /// Does the interior of this ball contain all of `inner`?
    pub fn contains_interior(&self, inner: &Ball) -> bool {
        // SAFETY: both balls are initialised.
        unsafe { arb_contains_interior(&self.b, &inner.b) != 0 }
    }

    /// Does the ball contain 0?
    pub fn contains_zero(&self) -> bool {
        // SAFETY: the ball is initialised.
        unsafe { arb_contains_zero(&self.b) != 0 }
    }

    /// The midpoint, rounded to the nearest `f64`.
    pub fn mid_f64(&self) -> f64 {
        // SAFETY: the ball is initialised; the midpoint is an arf_t.
        unsafe { arf_get_d(&self.b.mid, arf_rnd_t_ARF_RND_NEAR) }
    }

    /// An upper bound of the radius as an `f64`.
    pub fn rad_f64(&self) -> f64 {
        // SAFETY: the radius is an initialised mag_t.
        let r = unsafe { flint_sys::mag::mag_get_d(&self.b.rad) };
        // mag_get_d rounds up (as Arb documents for mag_t conversions)
        r
    }

    /// The ball as Arb prints it (`[mid +/- rad]`), with `digits` digits.
    pub fn show(&self, digits: i64) -> String {
        // SAFETY: the ball is initialised; arb_get_str returns a NUL-terminated string
        // allocated by FLINT, freed here once.
        unsafe {
            let p = arb_get_str(&self.b, digits, 0);
            let s = std::ffi::CStr::from_ptr(p).to_string_lossy().into_owned();
            flint_sys::flint::flint_free(p.cast());
            s
        }
    }

    fn is_exact(&self) -> bool {
        // SAFETY: the ball is initialised.
        unsafe { arb_is_exact(&self.b) != 0 }
    }

    /// Certain `<` (1), certain `>=` (0), or undecided (recorded; `false`).
    fn decide(certain: bool, certainly_not: bool) -> bool {
        if certain {
            true
        } else {
            if !certainly_not {
                undecided();
            }
            false
        }
    }

    /// `floor` or `nint` when it is one integer on the whole ball; else undecided.
    fn integer_part(
        &self,
        f: unsafe extern "C" fn(*mut arb_struct, *const arb_struct, i64),
    ) -> Ball {
        let r = self.un(f);
        if !r.is_exact() {
            undecided();
        }
        r
    }
}

/// `==` is the identity of the balls (same midpoint and radius), as the evaluator's
/// memory of calls needs: a call with identical argument balls has the same enclosure.
/// It is not the equality of the values the balls stand for: the language's `==` tests
/// the difference with [`Scalar::is_zero`], which decides only a certain zero or a
/// certain nonzero (and records the rest as undecided).
impl PartialEq for Ball {
    fn eq(&self, o: &Ball) -> bool {
        // SAFETY: both balls are initialised.
        unsafe { arb_equal(&self.b, &o.b) != 0 }
    }
}

impl PartialOrd for Ball {
    fn partial_cmp(&self, o: &Ball) -> Option<Ordering> {
        // SAFETY: both balls are initialised.
        unsafe {
            if arb_lt(&self.b, &o.b) != 0 {
                Some(Ordering::Less)
            } else if arb_gt(&self.b, &o.b) != 0 {
                Some(Ordering::Greater)
            } else if arb_eq(&self.b, &o.b) != 0 {
                Some(Ordering::Equal)
            } else {
                undecided();
                None
            }
        }
    }
    fn lt(&self, o: &Ball) -> bool {
        // SAFETY: both balls are initialised.
        unsafe { Ball::decide(arb_lt(&self.b, &o.b) != 0, arb_ge(&self.b, &o.b) != 0) }
    }
    fn le(&self, o: &Ball) -> bool {
        // SAFETY: both balls are initialised.
        unsafe { Ball::decide(arb_le(&self.b, &o.b) != 0, arb_gt(&self.b, &o.b) != 0) }
    }
    fn gt(&self, o: &Ball) -> bool {
        o.lt(self)
    }
    fn ge(&self, o: &Ball) -> bool {
        o.le(self)
    }
}

macro_rules! binop {
    ($($tr:ident, $m:ident => $f:ident);* $(;)?) => {$(
        impl $tr for Ball {
            type Output = Ball;
            fn $m(self, o: Ball) -> Ball {
                self.bin(&o, $f)
            }
        }
    )*};
}
binop!(Add, add => arb_add; Sub, sub => arb_sub; Mul, mul => arb_mul; Div, div => arb_div);

impl Neg for Ball {
    type Output = Ball;
    fn neg(self) -> Ball {
        let mut r = Ball::new_zero(self.prec);
        // SAFETY: both balls are initialised.
        unsafe { arb_neg(&mut r.b, &self.b) };
        r
    }
}

impl Scalar for Ball {
    fn zero(&self) -> Self {
        Ball::new_zero(self.prec)
    }
    fn one(&self) -> Self {
        self.from_i64(1)
    }
    fn from_i64(&self, n: i64) -> Self {
        let mut r = Ball::new_zero(self.prec);
        // SAFETY: the ball is initialised.
        unsafe { arb_set_si(&mut r.b, n) };
        r
    }
    fn from_f64(&self, x: f64) -> Self {
        Ball::exact(x, self.prec)
    }
    fn parse_like(&self, s: &str) -> Result<Self, NumError> {
        let t = s.trim();
        if !super::is_decimal(t) {
            return Err(NumError::Parse(s.to_string()));
        }
        let c = std::ffi::CString::new(t).map_err(|_| NumError::Parse(s.to_string()))?;
        let mut r = Ball::new_zero(self.prec);
        // SAFETY: the ball is initialised, the string NUL-terminated; arb_set_str
        // encloses the decimal (0 on success).
        let bad = unsafe { arb_set_str(&mut r.b, c.as_ptr(), slong(self.prec)) };
        if bad != 0 || !r.is_finite() {
            return Err(NumError::Parse(s.to_string()));
        }
        Ok(r)
    }
    fn precision(&self) -> Option<u32> {
        Some(self.prec)
    }
    fn is_zero(&self) -> bool {
        // SAFETY: the ball is initialised.
        let (zero, nonzero) =
            unsafe { (arb_is_zero(&self.b) != 0, arb_contains_zero(&self.b) == 0) };
        Ball::decide(zero, nonzero)
    }
    fn magnitude(&self) -> f64 {
        self.mid_f64().abs()
    }
    /// `|x|` needs no decision in balls: the ball of all `|x|`.
    fn stated_abs(&self) -> Result<Self, String> {
        Ok(Real::abs(self))
    }
    fn to_f64(&self) -> f64 {
        self.mid_f64()
    }
    fn is_finite(&self) -> bool {
        // SAFETY: the ball is initialised.
        unsafe { arb_is_finite(&self.b) != 0 }
    }
    fn try_sqrt(&self) -> Result<Self, NumError> {
        let r = self.un(arb_sqrt);
        if r.is_finite() {
            Ok(r)
        } else {
            Err(NumError::NegativeSqrt(self.show(10)))
        }
    }
    fn to_decimal(&self, digits: usize) -> String {
        self.show(digits.max(1) as i64)
    }
}

macro_rules! unary {
    ($($name:ident => $f:ident),* $(,)?) => {
        $(fn $name(&self) -> Self {
            self.un($f)
        })*
    };
}

impl Real for Ball {
    const FIXED: bool = false;
    // no numerical iteration may run on balls: the elliptic functions are Arb's
    // enclosures (module `ball_elliptic`)
    const BY_RULE: bool = true;
    const ENCLOSES: bool = true;
    fn sncndn_by_rule(u: &Self, k: &Self) -> Result<(Self, Self, Self), String> {
        super::ball_elliptic::sncndn(u, k)
    }
    fn quarter_period_by_rule(k: &Self, complementary: bool) -> Result<Self, String> {
        super::ball_elliptic::ellipk(k, complementary)
    }
    fn ellipf_by_rule(phi: &Self, k: &Self) -> Result<Self, String> {
        super::ball_elliptic::ellipf(phi, k)
    }
    fn jacobi_inverse_by_rule(sn: &Self, cn: &Self, dn: &Self, k: &Self) -> Result<Self, String> {
        super::ball_elliptic::jacobi_inverse(sn, cn, dn, k)
    }
    fn ellipe_by_rule(k: &Self, complementary: bool) -> Result<Self, String> {
        super::ball_elliptic::ellipe(k, complementary)
    }
    fn ellipeinc_by_rule(phi: &Self, k: &Self) -> Result<Self, String> {
        super::ball_elliptic::ellipeinc(phi, k)
    }
    fn as_ball(&self) -> Option<&Ball> {
        Some(self)
    }
    fn from_ball(x: Ball) -> Option<Self> {
        Some(x)
    }
    fn prec(&self) -> u32 {
        self.prec
    }
    fn with_prec(&self, bits: u32) -> Self {
        let mut r = self.clone();
        r.prec = bits;
        r
    }
    fn pi(&self) -> Self {
        let mut r = Ball::new_zero(self.prec);
        // SAFETY: the ball is initialised.
        unsafe { arb_const_pi(&mut r.b, slong(self.prec)) };
        r
    }
    fn mul_2si(&self, n: i32) -> Self {
        let mut r = Ball::new_zero(self.prec);
        // SAFETY: both balls are initialised; the scaling is exact.
        unsafe { arb_mul_2exp_si(&mut r.b, &self.b, i64::from(n)) };
        r
    }
    fn abs(&self) -> Self {
        let mut r = Ball::new_zero(self.prec);
        // SAFETY: both balls are initialised.
        unsafe { arb_abs(&mut r.b, &self.b) };
        r
    }
    unary!(
        sqrt => arb_sqrt,
        exp => arb_exp,
        exp_m1 => arb_expm1,
        ln => arb_log,
        sin => arb_sin,
        cos => arb_cos,
        atan => arb_atan,
        asin => arb_asin,
        sinh => arb_sinh,
        cosh => arb_cosh,
        tanh => arb_tanh,
        asinh => arb_asinh,
        atanh => arb_atanh,
    );
    fn floor(&self) -> Self {
        self.integer_part(arb_floor)
    }
    fn round(&self) -> Self {
        // ties away from zero as the trait says: sign · floor(|x| + 1/2)
        let half = self.from_f64(0.5);
        let a = Real::abs(self).add(half).integer_part(arb_floor);
        if *self < self.zero() { -a } else { a }
    }
    fn atan2(&self, x: &Self) -> Self {
        self.bin(x, arb_atan2)
    }
    fn powf(&self, y: &Self) -> Self {
        self.bin(y, arb_pow)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_encloses_and_comparisons_decide_or_record() {
        let third = Ball::exact(1.0, 128) / Ball::exact(3.0, 128);
        assert!(!third.is_exact() && third.rad_f64() < 1e-35);
        let back = third.clone() * Ball::exact(3.0, 128);
        assert!(back.contains_f64(1.0));
        let span = Decisions::start();
        assert!(third < Ball::exact(0.34, 128));
        assert!(span.all_decided());
        let greater = back > Ball::exact(1.0, 128);
        assert!(!greater);
        assert!(!span.all_decided(), "3 · (1/3) > 1 is undecided in balls");
    }

    #[test]
    fn floor_is_undecided_across_an_integer() {
        let span = Decisions::start();
        assert_eq!(Ball::with_radius(2.5, 0.25, 64).floor().mid_f64(), 2.0);
        assert!(span.all_decided());
        let _ = Ball::with_radius(2.0, 0.25, 64).floor();
        assert!(!span.all_decided());
    }
}
