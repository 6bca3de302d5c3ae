//! Dual numbers `v + d·ε` (ε² = 0) over any scalar: forward-mode automatic
//! differentiation.  `Dual<R>` is a [`Real`] when `R` is, so generic code (the Jacobi
//! functions, the Euler-top model) differentiates itself exactly, without finite
//! differences.
//!
//! ```
//! use eulertop_numerics::numbers::{Dual, Real, Scalar};
//! let x = Dual::var(0.5_f64);          // seed dx/dx = 1
//! let y = x.sin() * x.clone();           // y = x sin x
//! assert!((y.d - (0.5f64.sin() + 0.5 * 0.5f64.cos())).abs() < 1e-15);
//! ```

use super::{NumError, Real, Scalar};
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A first-order dual number: value `v` and derivative `d`.
#[derive(Clone, Debug)]
pub struct Dual<S> {
    /// The value.
    pub v: S,
    /// The derivative along the seeded direction.
    pub d: S,
}

impl<S: Scalar> Dual<S> {
    /// A value with derivative `d`.
    pub fn new(v: S, d: S) -> Self {
        Dual { v, d }
    }
    /// The independent variable: derivative one.
    pub fn var(v: S) -> Self {
        let d = v.one();
        Dual { v, d }
    }
    /// A constant: derivative zero.
    pub fn constant(v: S) -> Self {
        let d = v.zero();
        Dual { v, d }
    }
    fn chain(&self, f: S, df: S) -> Self {
        Dual::new(f, df * self.d.clone())
    }
}

impl<S: Scalar> PartialEq for Dual<S> {
    fn eq(&self, o: &Self) -> bool {
        self.v == o.v
    }
}
impl<S: Scalar + PartialOrd> PartialOrd for Dual<S> {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        self.v.partial_cmp(&o.v)
    }
}

impl<S: Scalar> Add for Dual<S> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Dual::new(self.v + o.v, self.d + o.d)
    }
}
impl<S: Scalar> Sub for Dual<S> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Dual::new(self.v - o.v, self.d - o.d)
    }
}
impl<S: Scalar> Mul for Dual<S> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        let d = self.d * o.v.clone() + self.v.clone() * o.d;
        Dual::new(self.v * o.v, d)
    }
}
impl<S: Scalar> Div for Dual<S> {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        let q = self.v / o.v.clone();
        let d = (self.d - q.clone() * o.d) / o.v;
        Dual::new(q, d)
    }
}
impl<S: Scalar> Neg for Dual<S> {
    type Output = Self;
    fn neg(self) -> Self {
        Dual::new(-self.v, -self.d)
    }
}

impl<S: Scalar> Scalar for Dual<S> {
    fn zero(&self) -> Self {
        Dual::constant(self.v.zero())
    }
    fn one(&self) -> Self {
        Dual::constant(self.v.one())
    }
    fn from_i64(&self, n: i64) -> Self {
        Dual::constant(self.v.from_i64(n))
    }
    fn from_f64(&self, x: f64) -> Self {
        Dual::constant(self.v.from_f64(x))
    }
    fn from_ratio(&self, n: i64, d: i64) -> Self {
        Dual::constant(self.v.from_ratio(n, d))
    }
    fn parse_like(&self, s: &str) -> Result<Self, NumError> {
        Ok(Dual::constant(self.v.parse_like(s)?))
    }
    fn precision(&self) -> Option<u32> {
        self.v.precision()
    }
    fn is_zero(&self) -> bool {
        self.v.is_zero()
    }
    fn magnitude(&self) -> f64 {
        self.v.magnitude()
    }
    fn to_f64(&self) -> f64 {
        self.v.to_f64()
    }
    /// Both the value and the derivative are finite.
    fn is_finite(&self) -> bool {
        self.v.is_finite() && self.d.is_finite()
    }
    fn log2_abs(&self) -> f64 {
        self.v.log2_abs()
    }
    fn try_sqrt(&self) -> Result<Self, NumError> {
        let r = self.v.try_sqrt()?;
        let two = r.from_i64(2);
        let d = self.d.clone() / (two * r.clone());
        Ok(Dual::new(r, d))
    }
    fn to_decimal(&self, digits: usize) -> String {
        format!(
            "{} + {}ε",
            self.v.to_decimal(digits),
            self.d.to_decimal(digits)
        )
    }
}

/// Refuses an elliptic rule of dual numbers over a type that does not enclose.
fn enclosing<R: Real>(what: &str) -> Result<(), String> {
    match R::ENCLOSES {
        true => Ok(()),
        false => Err(format!("{what} have no rule for this type")),
    }
}

impl<R: Real> Real for Dual<R> {
    // a dual over a type that evaluates by rules must not run numerical iterations either
    const BY_RULE: bool = R::BY_RULE;
    const FIXED: bool = R::FIXED;
    const ENCLOSES: bool = R::ENCLOSES;
    const DEFERS_DOMAIN_CHECKS: bool = R::DEFERS_DOMAIN_CHECKS;
    // the elliptic rules of duals over enclosures (module `dual_elliptic`); the prover
    // differentiates its symbols by its own rules
    fn sncndn_by_rule(u: &Self, k: &Self) -> Result<(Self, Self, Self), String> {
        if !R::ENCLOSES {
            return R::sncndn_dual_by_rule(u, k);
        }
        super::dual_elliptic::sncndn(u, k)
    }
    fn quarter_period_by_rule(k: &Self, complementary: bool) -> Result<Self, String> {
        enclosing::<R>("K")?;
        super::dual_elliptic::quarter_period(k, complementary)
    }
    fn ellipf_by_rule(phi: &Self, k: &Self) -> Result<Self, String> {
        enclosing::<R>("F")?;
        super::dual_elliptic::ellipf(phi, k)
    }
    fn jacobi_inverse_by_rule(sn: &Self, cn: &Self, dn: &Self, k: &Self) -> Result<Self, String> {
        enclosing::<R>("the inverse of sn, cn, dn")?;
        super::dual_elliptic::jacobi_inverse(sn, cn, dn, k)
    }
    fn prec(&self) -> u32 {
        self.v.prec()
    }
    fn with_prec(&self, bits: u32) -> Self {
        Dual::new(self.v.with_prec(bits), self.d.with_prec(bits))
    }
    fn pi(&self) -> Self {
        Dual::constant(self.v.pi())
    }
    fn epsilon(&self) -> Self {
        Dual::constant(self.v.epsilon())
    }
    fn mul_2si(&self, n: i32) -> Self {
        Dual::new(self.v.mul_2si(n), self.d.mul_2si(n))
    }
    fn abs(&self) -> Self {
        if self.v < self.v.zero() {
            -self.clone()
        } else {
            self.clone()
        }
    }
    fn sqrt(&self) -> Self {
        let r = self.v.sqrt();
        let df = (r.clone() * r.from_i64(2)).recip();
        self.chain(r, df)
    }
    fn exp(&self) -> Self {
        let e = self.v.exp();
        self.chain(e.clone(), e)
    }
    fn exp_m1(&self) -> Self {
        self.chain(self.v.exp_m1(), self.v.exp())
    }
    fn ln(&self) -> Self {
        self.chain(self.v.ln(), self.v.recip())
    }
    fn sin(&self) -> Self {
        let (s, c) = self.v.sin_cos();
        self.chain(s, c)
    }
    fn cos(&self) -> Self {
        let (s, c) = self.v.sin_cos();
        self.chain(c, -s)
    }
    fn sin_cos(&self) -> (Self, Self) {
        let (s, c) = self.v.sin_cos();
        (
            Dual::new(s.clone(), c.clone() * self.d.clone()),
            Dual::new(c, -s * self.d.clone()),
        )
    }
    fn atan(&self) -> Self {
        let df = (self.v.one() + self.v.sqr()).recip();
        self.chain(self.v.atan(), df)
    }
    fn atan2(&self, x: &Self) -> Self {
        // d atan2(y, x) = (x dy - y dx) / (x² + y²)
        let r2 = self.v.sqr() + x.v.sqr();
        let d = (x.v.clone() * self.d.clone() - self.v.clone() * x.d.clone()) / r2;
        Dual::new(self.v.atan2(&x.v), d)
    }
    fn asin(&self) -> Self {
        let df = (self.v.one() - self.v.sqr()).sqrt().recip();
        self.chain(self.v.asin(), df)
    }
    fn sinh(&self) -> Self {
        self.chain(self.v.sinh(), self.v.cosh())
    }
    fn cosh(&self) -> Self {
        self.chain(self.v.cosh(), self.v.sinh())
    }
    fn tanh(&self) -> Self {
        let t = self.v.tanh();
        let df = self.v.one() - t.sqr();
        self.chain(t, df)
    }
    fn asinh(&self) -> Self {
        let df = (self.v.one() + self.v.sqr()).sqrt().recip();
        self.chain(self.v.asinh(), df)
    }
    fn atanh(&self) -> Self {
        let df = (self.v.one() - self.v.sqr()).recip();
        self.chain(self.v.atanh(), df)
    }
    fn signum_value(&self) -> Self {
        Dual::constant(self.v.signum_value())
    }
    fn floor(&self) -> Self {
        Dual::constant(self.v.floor())
    }
    fn round(&self) -> Self {
        Dual::constant(self.v.round())
    }
}
