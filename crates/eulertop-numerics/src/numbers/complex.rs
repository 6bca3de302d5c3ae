//! Complex scalars: the generic [`Cplx<R>`] over any [`Real`] (so `Cplx<f64>` is the
//! f64 pair and `Cplx<rug::Float>` an MPFR pair), and [`rug::Complex`] (MPC).

use super::{ComplexScalar, NumError, Real, Scalar};
use rug::Complex;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A complex number `re + i·im` over a real scalar `R`.
#[derive(Clone, Debug, PartialEq)]
pub struct Cplx<R> {
    /// Real part.
    pub re: R,
    /// Imaginary part.
    pub im: R,
}

/// The double-precision complex type.
pub type C64 = Cplx<f64>;

impl<R: Scalar + PartialOrd> Cplx<R> {
    /// `re + i·im`.
    pub fn new(re: R, im: R) -> Self {
        Cplx { re, im }
    }
}

impl<R: Scalar + PartialOrd> Add for Cplx<R> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Cplx::new(self.re + o.re, self.im + o.im)
    }
}
impl<R: Scalar + PartialOrd> Sub for Cplx<R> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Cplx::new(self.re - o.re, self.im - o.im)
    }
}
impl<R: Scalar + PartialOrd> Mul for Cplx<R> {
    type Output = Self;
    /// `(ac − bd) + (ad + bc)i`, each part as one [`Scalar::det2`] (the same roundings as
    /// the products and the sum for numbers; one common denominator for the prover's
    /// values).
    fn mul(self, o: Self) -> Self {
        let re = R::det2(&self.re, &o.re, &self.im, &o.im);
        let im = R::det2(&self.re, &o.im, &-self.im.clone(), &o.re);
        Cplx::new(re, im)
    }
}
impl<R: Real> Div for Cplx<R> {
    type Output = Self;
    /// Smith's algorithm, avoiding overflow in `|o|²`.
    fn div(self, o: Self) -> Self {
        if o.im.abs() <= o.re.abs() {
            let r = o.im.clone() / o.re.clone();
            let d = o.re.clone() + o.im.clone() * r.clone();
            Cplx::new(
                (self.re.clone() + self.im.clone() * r.clone()) / d.clone(),
                (self.im - self.re * r) / d,
            )
        } else {
            let r = o.re.clone() / o.im.clone();
            let d = o.re * r.clone() + o.im;
            Cplx::new(
                (self.re.clone() * r.clone() + self.im.clone()) / d.clone(),
                (self.im * r - self.re) / d,
            )
        }
    }
}
impl<R: Scalar + PartialOrd> Neg for Cplx<R> {
    type Output = Self;
    fn neg(self) -> Self {
        Cplx::new(-self.re, -self.im)
    }
}

impl<R: Real> Scalar for Cplx<R> {
    fn zero(&self) -> Self {
        Cplx::new(self.re.zero(), self.re.zero())
    }
    fn one(&self) -> Self {
        Cplx::new(self.re.one(), self.re.zero())
    }
    fn from_i64(&self, n: i64) -> Self {
        Cplx::new(self.re.from_i64(n), self.re.zero())
    }
    fn from_f64(&self, x: f64) -> Self {
        Cplx::new(self.re.from_f64(x), self.re.zero())
    }
    fn from_ratio(&self, n: i64, d: i64) -> Self {
        Cplx::new(self.re.from_ratio(n, d), self.re.zero())
    }
    /// Parses `a`, `a+bi`, `a-bi`, `bi` or `a,b`.
    fn parse_like(&self, s: &str) -> Result<Self, NumError> {
        let (a, b) = split_complex(s).ok_or_else(|| NumError::Parse(s.to_string()))?;
        let re = if a.is_empty() {
            self.re.zero()
        } else {
            self.re.parse_like(a)?
        };
        let im = match b {
            None => self.re.zero(),
            Some(b) => self.re.parse_like(b)?,
        };
        Ok(Cplx::new(re, im))
    }
    fn precision(&self) -> Option<u32> {
        Some(self.re.prec())
    }
    fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }
    fn magnitude(&self) -> f64 {
        self.re.magnitude().hypot(self.im.magnitude())
    }
    fn to_f64(&self) -> f64 {
        self.re.to_f64()
    }
    fn is_finite(&self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }
    fn log2_abs(&self) -> f64 {
        log2_hypot(self.re.log2_abs(), self.im.log2_abs())
    }
    fn try_sqrt(&self) -> Result<Self, NumError> {
        Ok(ComplexScalar::sqrt(self))
    }
    fn to_decimal(&self, digits: usize) -> String {
        format!(
            "{} {}",
            self.re.to_decimal(digits),
            self.im.to_decimal(digits)
        )
    }
}

impl<R: Real> ComplexScalar for Cplx<R> {
    type R = R;
    fn from_parts(re: R, im: R) -> Self {
        Cplx::new(re, im)
    }
    fn re(&self) -> R {
        self.re.clone()
    }
    fn im(&self) -> R {
        self.im.clone()
    }
}

/// `log2 √(2^(2a) + 2^(2b))` from `a = log2|x|`, `b = log2|y|`, without overflow.
fn log2_hypot(a: f64, b: f64) -> f64 {
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    if hi == f64::NEG_INFINITY || !hi.is_finite() {
        return hi;
    }
    hi + 0.5 * (2.0 * (lo - hi)).exp2().ln_1p() / std::f64::consts::LN_2
}

/// Splits `a+bi` / `a-bi` / `bi` / `a,b` / `a` into real and imaginary literal parts.
fn split_complex(s: &str) -> Option<(&str, Option<&str>)> {
    let t = s.trim();
    if t.is_empty() {
        return None;
    }
    if let Some((a, b)) = t.split_once(',') {
        return Some((a.trim(), Some(b.trim())));
    }
    let Some(body) = t.strip_suffix('i') else {
        return Some((t, None));
    };
    // find the sign that separates real and imaginary parts (not an exponent sign)
    let bytes = body.as_bytes();
    let mut cut = None;
    for j in (1..bytes.len()).rev() {
        let c = bytes[j];
        if (c == b'+' || c == b'-') && !matches!(bytes[j - 1], b'e' | b'E') {
            cut = Some(j);
            break;
        }
    }
    match cut {
        Some(j) => {
            let im = &body[j..];
            let im = if im == "+" || im == "-" {
                None
            } else {
                Some(im)
            };
            im.map(|im| (body[..j].trim(), Some(im.trim_start_matches('+'))))
        }
        None => {
            if body.is_empty() || body == "+" || body == "-" {
                None
            } else {
                Some(("", Some(body.trim_start_matches('+'))))
            }
        }
    }
}

// ---- rug::Complex (MPC) ----

impl Scalar for Complex {
    fn zero(&self) -> Self {
        Complex::new(self.prec())
    }
    fn one(&self) -> Self {
        Complex::with_val(self.prec(), 1)
    }
    fn from_i64(&self, n: i64) -> Self {
        Complex::with_val(self.prec(), n)
    }
    fn from_f64(&self, x: f64) -> Self {
        Complex::with_val(self.prec(), x)
    }
    fn parse_like(&self, s: &str) -> Result<Self, NumError> {
        let (a, b) = split_complex(s).ok_or_else(|| NumError::Parse(s.to_string()))?;
        let z = rug::Float::new(self.prec().0);
        let re = if a.is_empty() {
            z.zero()
        } else {
            z.parse_like(a)?
        };
        let im = match b {
            None => z.zero(),
            Some(b) => z.parse_like(b)?,
        };
        Ok(Complex::with_val(self.prec(), (re, im)))
    }
    fn precision(&self) -> Option<u32> {
        Some(self.prec().0)
    }
    fn is_zero(&self) -> bool {
        self.real().is_zero() && self.imag().is_zero()
    }
    fn magnitude(&self) -> f64 {
        self.real().to_f64().hypot(self.imag().to_f64())
    }
    fn to_f64(&self) -> f64 {
        self.real().to_f64()
    }
    fn is_finite(&self) -> bool {
        self.real().is_finite() && self.imag().is_finite()
    }
    fn log2_abs(&self) -> f64 {
        log2_hypot(self.real().log2_abs(), self.imag().log2_abs())
    }
    fn try_sqrt(&self) -> Result<Self, NumError> {
        Ok(Complex::with_val(self.prec(), self.sqrt_ref()))
    }
    fn to_decimal(&self, digits: usize) -> String {
        format!(
            "{} {}",
            self.real().to_decimal(digits),
            self.imag().to_decimal(digits)
        )
    }
}

impl ComplexScalar for Complex {
    type R = rug::Float;
    fn from_parts(re: rug::Float, im: rug::Float) -> Self {
        let p = re.prec().max(im.prec());
        Complex::with_val(p, (re, im))
    }
    fn re(&self) -> rug::Float {
        self.real().clone()
    }
    fn im(&self) -> rug::Float {
        self.imag().clone()
    }
    fn abs(&self) -> rug::Float {
        rug::Float::with_val(self.prec().0, self.abs_ref())
    }
    fn arg(&self) -> rug::Float {
        rug::Float::with_val(self.prec().0, self.arg_ref())
    }
    fn sqrt(&self) -> Self {
        Complex::with_val(self.prec(), self.sqrt_ref())
    }
    fn exp(&self) -> Self {
        Complex::with_val(self.prec(), self.exp_ref())
    }
    fn ln(&self) -> Self {
        Complex::with_val(self.prec(), self.ln_ref())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn parse_forms() {
        let z = C64::new(0.0, 0.0);
        assert_eq!(z.parse_like("1.5-2i").unwrap(), C64::new(1.5, -2.0));
        assert_eq!(z.parse_like("2.5i").unwrap(), C64::new(0.0, 2.5));
        assert_eq!(z.parse_like("1e-3+4e+2i").unwrap(), C64::new(1e-3, 400.0));
        assert_eq!(z.parse_like("3,4").unwrap(), C64::new(3.0, 4.0));
        assert!(z.parse_like("i").is_err());
        assert!(z.parse_like("1+xi").is_err());
    }
}
