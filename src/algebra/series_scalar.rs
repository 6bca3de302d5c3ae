//! Operators and the numeric traits for [`Series`], so that the model's generic code
//! (the implicit maps' equations, the elliptic parameters) runs on power series in `h`.
//!
//! As for [`Sym`], operators cannot return errors: a failure poisons the ring and the
//! result is meaningless; a proof on a poisoned ring is never reported as proved.

use super::error::{AlgResult, AlgebraError};
use super::series::Series;
use super::sym::Sym;
use crate::numbers::{NumError, Real, Scalar};
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

impl Series {
    fn or_poison(&self, r: AlgResult<Series>) -> Series {
        match r {
            Ok(s) => s,
            Err(e) => self.poisoned(e),
        }
    }

    fn lift(&self, x: Sym) -> Series {
        Series::constant(&x)
    }

    fn unsupported(&self, what: &str) -> Series {
        self.poisoned(AlgebraError::NotAlgebraic(format!(
            "{what} of a power series in h"
        )))
    }

    fn on_const(&self, what: &str, f: impl FnOnce(&Sym) -> AlgResult<Sym>) -> Series {
        let r = self.on_constant(what, f);
        self.or_poison(r)
    }
}

macro_rules! binop {
    ($tr:ident, $m:ident, $body:expr) => {
        impl $tr for Series {
            type Output = Series;
            fn $m(self, o: Series) -> Series {
                if self.ring().is_poisoned() {
                    return self.poisoned(AlgebraError::Internal("poisoned".into()));
                }
                let f: fn(&Series, &Series) -> AlgResult<Series> = $body;
                let r = f(&self, &o);
                self.or_poison(r)
            }
        }
    };
}

binop!(Add, add, |a, b| a.try_add(b, false));
binop!(Sub, sub, |a, b| a.try_add(b, true));
binop!(Mul, mul, |a, b| a.try_mul(b));
binop!(Div, div, |a, b| a.try_div(b));

impl Neg for Series {
    type Output = Series;
    fn neg(self) -> Series {
        let zero = self.lift(self.ring().integer(0));
        zero - self
    }
}

/// Equal known coefficients and precision.
impl PartialEq for Series {
    fn eq(&self, o: &Series) -> bool {
        self.valuation() == o.valuation()
            && self.precision() == o.precision()
            && (self.valuation()..self.precision()).all(|e| self.coefficient(e) == o.coefficient(e))
    }
}

/// The order for small `h > 0` (see [`Series::sign`]); `None`, and an error in the
/// ring, when it is not decided.
impl PartialOrd for Series {
    fn partial_cmp(&self, o: &Series) -> Option<Ordering> {
        let d = self.try_add(o, true).and_then(|d| d.sign());
        match d {
            Ok(s) => Some(s.cmp(&0)),
            Err(e) => {
                self.poisoned(e);
                None
            }
        }
    }
}

impl Scalar for Series {
    fn zero(&self) -> Self {
        self.lift(self.ring().integer(0))
    }
    fn one(&self) -> Self {
        self.lift(self.ring().integer(1))
    }
    fn from_i64(&self, n: i64) -> Self {
        self.lift(self.ring().integer(n))
    }
    fn from_f64(&self, x: f64) -> Self {
        match rug::Rational::from_f64(x) {
            Some(q) => self.lift(self.ring().rational(&q)),
            None => self.unsupported("a non-finite number"),
        }
    }
    fn from_ratio(&self, n: i64, d: i64) -> Self {
        if d == 0 {
            return self.poisoned(AlgebraError::DivisionByZero);
        }
        self.lift(self.ring().rational(&rug::Rational::from((n, d))))
    }
    fn parse_like(&self, s: &str) -> Result<Self, NumError> {
        let c = self.as_constant().unwrap_or_else(|| self.ring().integer(0));
        c.parse_like(s).map(|x| self.lift(x))
    }
    fn precision(&self) -> Option<u32> {
        None
    }
    fn is_zero(&self) -> bool {
        self.valuation() >= self.precision()
    }
    fn magnitude(&self) -> f64 {
        self.to_f64().abs()
    }
    fn try_sqrt(&self) -> Result<Self, NumError> {
        Series::try_sqrt(self).map_err(|e| {
            self.poisoned(e);
            NumError::NotExact("a square root of a power series (the ring records why)")
        })
    }
    /// The value at `h = 0` at the first domain point (for messages only).
    fn to_f64(&self) -> f64 {
        match self.valuation() {
            0 => self.coefficient(0).map_or(f64::NAN, |c| c.to_f64()),
            v if v > 0 => 0.0,
            _ => f64::INFINITY,
        }
    }
    fn is_finite(&self) -> bool {
        !self.ring().is_poisoned()
    }
    /// `abs(x)` of the expression language: [`Real::abs`] (so `O(h^v)` where the sign
    /// of the leading coefficient is not decided).
    fn stated_abs(&self) -> Result<Self, String> {
        Ok(Real::abs(self))
    }
    fn to_decimal(&self, _digits: usize) -> String {
        self.render_short(60)
    }
}

impl Real for Series {
    const FIXED: bool = false;
    const BY_RULE: bool = true;
    fn failure(&self) -> Option<String> {
        self.ring().error().map(|e| e.to_string())
    }
    fn sncndn_by_rule(u: &Self, k: &Self) -> Result<(Self, Self, Self), String> {
        u.sncndn(k).map_err(|e| e.to_string())
    }
    fn sncndn_dual_by_rule(
        u: &crate::numbers::Dual<Self>,
        k: &crate::numbers::Dual<Self>,
    ) -> Result<crate::numbers::DualTriple<Self>, String> {
        Series::sncndn_dual(u, k).map_err(|e| e.to_string())
    }
    fn quarter_period_by_rule(k: &Self, complementary: bool) -> Result<Self, String> {
        if k.as_constant().is_none() {
            return Series::quarter_period_moving(k, complementary).map_err(|e| e.to_string());
        }
        let ring = k.ring().clone();
        k.on_constant("K", |k0| {
            if complementary {
                ring.quarter_period_prime(k0)
            } else {
                ring.quarter_period(k0)
            }
        })
        .map_err(|e| e.to_string())
    }
    fn prec(&self) -> u32 {
        self.ring().precision()
    }
    fn with_prec(&self, _bits: u32) -> Self {
        self.clone()
    }
    fn pi(&self) -> Self {
        self.unsupported("pi")
    }
    fn mul_2si(&self, n: i32) -> Self {
        let mut q = rug::Rational::from(1);
        if n >= 0 {
            q <<= n.unsigned_abs();
        } else {
            q >>= n.unsigned_abs();
        }
        self.clone() * self.lift(self.ring().rational(&q))
    }
    /// `|x|`: `±x` where the leading coefficient's sign is proved; otherwise only
    /// `|x| = O(h^v)` for `x` of valuation `v` is known, and that is the value (no
    /// coefficient of it is known).
    fn abs(&self) -> Self {
        match self.sign() {
            Ok(s) if s < 0 => -self.clone(),
            Ok(_) => self.clone(),
            Err(AlgebraError::CannotDecide(_)) => self.bound(),
            Err(e) => self.poisoned(e),
        }
    }
    fn sqrt(&self) -> Self {
        let r = Series::try_sqrt(self);
        self.or_poison(r)
    }
    fn exp(&self) -> Self {
        self.unsupported("exp")
    }
    fn ln(&self) -> Self {
        self.unsupported("ln")
    }
    fn sin(&self) -> Self {
        self.elementary(0, |s, _| Ok(s.clone()))
    }
    fn cos(&self) -> Self {
        self.elementary(0, |_, c| Ok(c.clone()))
    }
    fn atan(&self) -> Self {
        self.unsupported("atan")
    }
    fn atan2(&self, _x: &Self) -> Self {
        self.unsupported("atan2")
    }
    fn asin(&self) -> Self {
        self.on_const("asin", |x| Ok(Real::asin(x)))
    }
    fn sinh(&self) -> Self {
        self.elementary(1, |s, c| s.try_div(c))
    }
    fn cosh(&self) -> Self {
        self.elementary(1, |_, c| c.one().try_div(c))
    }
    fn tanh(&self) -> Self {
        self.elementary(1, |s, _| Ok(s.clone()))
    }
    fn asinh(&self) -> Self {
        self.unsupported("asinh")
    }
    fn atanh(&self) -> Self {
        self.unsupported("atanh")
    }
    fn floor(&self) -> Self {
        self.on_const("floor", |x| Ok(Real::floor(x)))
    }
    fn round(&self) -> Self {
        self.on_const("round", |x| Ok(Real::round(x)))
    }
}

impl Series {
    /// A circular (`k = 0`) or hyperbolic (`k = 1`) function from `sn` and `cn` at that
    /// modulus (DLMF 22.5.ii).
    fn elementary(&self, k: i64, f: impl Fn(&Series, &Series) -> AlgResult<Series>) -> Series {
        let k = self.lift(self.ring().integer(k));
        let r = self.sncndn(&k).and_then(|(s, c, _)| f(&s, &c));
        self.or_poison(r)
    }
}
