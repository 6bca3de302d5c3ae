//! `f64` as a [`Scalar`] and [`Real`]: IEEE double precision, 53 bits.

use super::{NumError, Real, Scalar};

impl Scalar for f64 {
    fn zero(&self) -> Self {
        0.0
    }
    fn one(&self) -> Self {
        1.0
    }
    fn from_i64(&self, n: i64) -> Self {
        n as f64
    }
    fn from_f64(&self, x: f64) -> Self {
        x
    }
    fn parse_like(&self, s: &str) -> Result<Self, NumError> {
        let t = s.trim();
        match t.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(NumError::Parse(s.to_string())),
        }
    }
    fn precision(&self) -> Option<u32> {
        Some(53)
    }
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
    fn magnitude(&self) -> f64 {
        f64::abs(*self)
    }
    fn try_sqrt(&self) -> Result<Self, NumError> {
        if *self < 0.0 {
            Err(NumError::NegativeSqrt(format!("{self:e}")))
        } else {
            Ok(f64::sqrt(*self))
        }
    }
    fn to_decimal(&self, digits: usize) -> String {
        format!("{:.*e}", digits.saturating_sub(1), self)
    }
}

impl Real for f64 {
    fn prec(&self) -> u32 {
        53
    }
    fn with_prec(&self, _bits: u32) -> Self {
        *self
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn pi(&self) -> Self {
        std::f64::consts::PI
    }
    fn epsilon(&self) -> Self {
        f64::EPSILON
    }
    fn mul_2si(&self, n: i32) -> Self {
        self * f64::powi(2.0, n)
    }
    fn abs(&self) -> Self {
        f64::abs(*self)
    }
    fn sqrt(&self) -> Self {
        f64::sqrt(*self)
    }
    fn exp(&self) -> Self {
        f64::exp(*self)
    }
    fn ln(&self) -> Self {
        f64::ln(*self)
    }
    fn sin(&self) -> Self {
        f64::sin(*self)
    }
    fn cos(&self) -> Self {
        f64::cos(*self)
    }
    fn sin_cos(&self) -> (Self, Self) {
        f64::sin_cos(*self)
    }
    fn tan(&self) -> Self {
        f64::tan(*self)
    }
    fn atan(&self) -> Self {
        f64::atan(*self)
    }
    fn atan2(&self, x: &Self) -> Self {
        f64::atan2(*self, *x)
    }
    fn asin(&self) -> Self {
        f64::asin(*self)
    }
    fn sinh(&self) -> Self {
        f64::sinh(*self)
    }
    fn cosh(&self) -> Self {
        f64::cosh(*self)
    }
    fn tanh(&self) -> Self {
        f64::tanh(*self)
    }
    fn asinh(&self) -> Self {
        f64::asinh(*self)
    }
    fn atanh(&self) -> Self {
        f64::atanh(*self)
    }
    fn floor(&self) -> Self {
        f64::floor(*self)
    }
    fn round(&self) -> Self {
        f64::round(*self)
    }
    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }
    fn powf(&self, y: &Self) -> Self {
        f64::powf(*self, *y)
    }
}
