//! Exact rationals ([`num_rational::BigRational`]) as a [`Scalar`]: field operations
//! only.  `try_sqrt` is exact when numerator and denominator are perfect squares and an
//! error otherwise; nothing is ever approximated.

use super::{NumError, Scalar};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// The exact rational type.
pub type Rational = BigRational;

/// Parses `p/q`, an integer, or a finite decimal (`-1.25e-3`) exactly.
pub fn parse_rational(s: &str) -> Result<BigRational, NumError> {
    let t = s.trim();
    let err = || NumError::Parse(s.to_string());
    if let Some((p, q)) = t.split_once('/') {
        let p: BigInt = p.trim().parse().map_err(|_| err())?;
        let q: BigInt = q.trim().parse().map_err(|_| err())?;
        if q.is_zero() {
            return Err(err());
        }
        return Ok(BigRational::new(p, q));
    }
    let (mant, exp) = match t.find(['e', 'E']) {
        Some(j) => (&t[..j], t[j + 1..].parse::<i64>().map_err(|_| err())?),
        None => (t, 0),
    };
    let (neg, mant) = match mant.strip_prefix('-') {
        Some(m) => (true, m),
        None => (false, mant.strip_prefix('+').unwrap_or(mant)),
    };
    let (ip, fp) = mant.split_once('.').unwrap_or((mant, ""));
    if ip.is_empty() && fp.is_empty() {
        return Err(err());
    }
    if !ip.chars().chain(fp.chars()).all(|c| c.is_ascii_digit()) {
        return Err(err());
    }
    if exp.abs() > 100_000 {
        return Err(err());
    }
    let digits: BigInt = format!("{ip}{fp}0").parse().map_err(|_| err())?;
    let scale = exp - fp.len() as i64 - 1;
    let ten = BigInt::from(10);
    let mut r = BigRational::from_integer(digits);
    if scale >= 0 {
        r *= BigRational::from_integer(num_traits::pow(ten, scale as usize));
    } else {
        r /= BigRational::from_integer(num_traits::pow(ten, (-scale) as usize));
    }
    Ok(if neg { -r } else { r })
}

fn exact_isqrt(n: &BigInt) -> Option<BigInt> {
    if n.is_negative() {
        return None;
    }
    let r = n.sqrt();
    if &(&r * &r) == n { Some(r) } else { None }
}

/// `Σ nᵢ/dᵢ` over the product of the denominators, reduced once (a sum and product
/// of ratios one at a time would reduce each, with a gcd per step).
fn sum_of_ratios(terms: &[(BigInt, BigInt)]) -> BigRational {
    let mut num = BigInt::from(0);
    let mut den = BigInt::from(1);
    for (n, d) in terms {
        num = num * d + n * &den;
        den *= d;
    }
    BigRational::new(num, den)
}

impl Scalar for BigRational {
    /// Over one denominator, reduced once.
    fn dot3(a: [&Self; 3], b: [&Self; 3]) -> Self {
        let terms = [0, 1, 2].map(|i| (a[i].numer() * b[i].numer(), a[i].denom() * b[i].denom()));
        sum_of_ratios(&terms)
    }
    /// Over one denominator, reduced once.
    fn det2(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
        sum_of_ratios(&[
            (a.numer() * b.numer(), a.denom() * b.denom()),
            (-(c.numer() * d.numer()), c.denom() * d.denom()),
        ])
    }
    fn zero(&self) -> Self {
        <BigRational as Zero>::zero()
    }
    fn one(&self) -> Self {
        <BigRational as One>::one()
    }
    fn from_i64(&self, n: i64) -> Self {
        BigRational::from_integer(BigInt::from(n))
    }
    /// Exact: every finite f64 is a dyadic rational.  Non-finite input gives zero's
    /// error-free counterpart is impossible, so NaN/∞ map to 0 only through
    /// `parse_like`, which rejects them; here they are converted as 0 with no panic.
    fn from_f64(&self, x: f64) -> Self {
        BigRational::from_float(x).unwrap_or_else(<BigRational as Zero>::zero)
    }
    fn from_ratio(&self, n: i64, d: i64) -> Self {
        if d == 0 {
            return <BigRational as Zero>::zero();
        }
        BigRational::new(BigInt::from(n), BigInt::from(d))
    }
    fn parse_like(&self, s: &str) -> Result<Self, NumError> {
        parse_rational(s)
    }
    fn precision(&self) -> Option<u32> {
        None
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn magnitude(&self) -> f64 {
        ToPrimitive::to_f64(&self.abs()).unwrap_or(f64::INFINITY)
    }
    fn to_f64(&self) -> f64 {
        ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }
    fn is_finite(&self) -> bool {
        true
    }
    /// From the leading 60 bits of numerator and denominator: no overflow for any size.
    fn log2_abs(&self) -> f64 {
        if Zero::is_zero(self) {
            return f64::NEG_INFINITY;
        }
        let top = |x: &BigInt| -> (f64, i64) {
            let x = x.abs();
            let shift = (x.bits() as i64 - 60).max(0);
            let t: BigInt = x >> (shift as usize);
            (ToPrimitive::to_f64(&t).unwrap_or(1.0), shift)
        };
        let (nf, ns) = top(self.numer());
        let (df, ds) = top(self.denom());
        nf.log2() - df.log2() + (ns - ds) as f64
    }
    fn try_sqrt(&self) -> Result<Self, NumError> {
        match (exact_isqrt(self.numer()), exact_isqrt(self.denom())) {
            (Some(p), Some(q)) => Ok(BigRational::new(p, q)),
            _ => Err(NumError::NotPerfectSquare(self.to_string())),
        }
    }
    fn to_decimal(&self, _digits: usize) -> String {
        self.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dot3_and_det2_are_the_plain_formulas() {
        let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
        let (a, b, c) = (q(3, 4), q(-5, 6), q(7, 10));
        let (x, y, z) = (q(2, 9), q(4, 15), q(-1, 14));
        let plain = &a * &x + &b * &y + &c * &z;
        assert_eq!(BigRational::dot3([&a, &b, &c], [&x, &y, &z]), plain);
        assert_eq!(BigRational::det2(&a, &x, &b, &y), &a * &x - &b * &y);
        // a sum that cancels to 0 is 0/1
        let zero = BigRational::det2(&a, &x, &x, &a);
        assert_eq!(zero, q(0, 1));
        assert_eq!(*zero.denom(), BigInt::from(1));
    }

    #[test]
    fn parse_exact() {
        assert_eq!(
            parse_rational("3/4").unwrap(),
            BigRational::new(3.into(), 4.into())
        );
        assert_eq!(
            parse_rational("-1.25e-1").unwrap(),
            BigRational::new((-1).into(), 8.into())
        );
        assert_eq!(
            parse_rational("2e3").unwrap(),
            BigRational::from_integer(2000.into())
        );
        assert!(parse_rational("1/0").is_err());
        assert!(parse_rational("1.2.3").is_err());
        assert!(parse_rational("").is_err());
    }
    #[test]
    fn sqrt_exact_or_error() {
        let q = parse_rational("9/16").unwrap();
        assert_eq!(q.try_sqrt().unwrap(), parse_rational("3/4").unwrap());
        assert!(parse_rational("2").unwrap().try_sqrt().is_err());
        assert!(parse_rational("-4").unwrap().try_sqrt().is_err());
    }
}
