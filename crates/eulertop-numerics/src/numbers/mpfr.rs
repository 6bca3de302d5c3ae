//! [`rug::Float`] (MPFR) as a [`Scalar`] and [`Real`] at any precision.
//!
//! Every result is correctly rounded (round-to-nearest) by MPFR at the precision of
//! the receiver; binary operators keep the precision of the left operand.

use super::{NumError, Real, Scalar};
use rug::float::Constant;
use rug::ops::Pow;
use rug::{Assign, Float};

impl Scalar for Float {
    fn zero(&self) -> Self {
        Float::new(self.prec())
    }
    fn one(&self) -> Self {
        Float::with_val(self.prec(), 1)
    }
    fn from_i64(&self, n: i64) -> Self {
        Float::with_val(self.prec(), n)
    }
    fn from_f64(&self, x: f64) -> Self {
        Float::with_val(self.prec(), x)
    }
    fn from_ratio(&self, n: i64, d: i64) -> Self {
        Float::with_val(self.prec(), n) / d
    }
    fn parse_like(&self, s: &str) -> Result<Self, NumError> {
        let t = s.trim();
        if !super::is_decimal(t) {
            return Err(NumError::Parse(s.to_string()));
        }
        match Float::parse(t) {
            Ok(p) => {
                let v = Float::with_val(self.prec(), p);
                if v.is_finite() {
                    Ok(v)
                } else {
                    Err(NumError::Parse(s.to_string()))
                }
            }
            Err(_) => Err(NumError::Parse(s.to_string())),
        }
    }
    fn precision(&self) -> Option<u32> {
        Some(self.prec())
    }
    fn is_zero(&self) -> bool {
        Float::is_zero(self)
    }
    fn magnitude(&self) -> f64 {
        Float::to_f64(self).abs()
    }
    fn to_f64(&self) -> f64 {
        Float::to_f64(self)
    }
    fn is_finite(&self) -> bool {
        Float::is_finite(self)
    }
    fn log2_abs(&self) -> f64 {
        if Float::is_zero(self) {
            return f64::NEG_INFINITY;
        }
        let (m, e) = self.to_f64_exp();
        m.abs().log2() + f64::from(e)
    }
    fn try_sqrt(&self) -> Result<Self, NumError> {
        if self.is_sign_negative() && !Float::is_zero(self) {
            Err(NumError::NegativeSqrt(Scalar::to_decimal(self, 10)))
        } else {
            Ok(Float::with_val(self.prec(), self.sqrt_ref()))
        }
    }
    fn recip(&self) -> Self {
        Float::with_val(self.prec(), self.recip_ref())
    }
    fn sqr(&self) -> Self {
        Float::with_val(self.prec(), self.square_ref())
    }
    fn powi(&self, n: i32) -> Self {
        Float::with_val(self.prec(), self.pow(n))
    }
    fn to_decimal(&self, digits: usize) -> String {
        if Float::is_zero(self) {
            return "0".to_string();
        }
        self.to_string_radix(10, Some(digits.max(1)))
    }
}

macro_rules! unary {
    ($($name:ident => $ref_fn:ident),* $(,)?) => {
        $(fn $name(&self) -> Self {
            Float::with_val(self.prec(), self.$ref_fn())
        })*
    };
}

impl Real for Float {
    const FIXED: bool = false;
    fn as_mpfr(&self) -> Option<&Float> {
        Some(self)
    }
    fn from_mpfr(x: Float) -> Option<Self> {
        Some(x)
    }
    fn prec(&self) -> u32 {
        Float::prec(self)
    }
    fn with_prec(&self, bits: u32) -> Self {
        Float::with_val(bits, self)
    }
    fn pi(&self) -> Self {
        Float::with_val(self.prec(), Constant::Pi)
    }
    fn mul_2si(&self, n: i32) -> Self {
        let mut x = self.clone();
        x <<= n;
        x
    }
    unary!(
        abs => abs_ref,
        sqrt => sqrt_ref,
        exp => exp_ref,
        exp_m1 => exp_m1_ref,
        ln => ln_ref,
        sin => sin_ref,
        cos => cos_ref,
        tan => tan_ref,
        atan => atan_ref,
        asin => asin_ref,
        sinh => sinh_ref,
        cosh => cosh_ref,
        tanh => tanh_ref,
        asinh => asinh_ref,
        atanh => atanh_ref,
        floor => floor_ref,
        round => round_ref,
    );
    fn sin_cos(&self) -> (Self, Self) {
        let p = self.prec();
        let mut sc = (Float::new(p), Float::new(p));
        sc.assign(self.sin_cos_ref());
        sc
    }
    fn atan2(&self, x: &Self) -> Self {
        Float::with_val(self.prec(), self.atan2_ref(x))
    }
    fn powf(&self, y: &Self) -> Self {
        Float::with_val(self.prec(), self.pow(y))
    }
}
