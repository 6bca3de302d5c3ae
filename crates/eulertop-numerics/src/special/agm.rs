//! Complete elliptic integrals of the first kind by the arithmetic–geometric mean.

use super::dd::{Dd, two_sum, with_value};
use super::theta::{SERIES_MAX_M, Theta};
use super::{GUARD, SpecialError, check_modulus_below_one};
use crate::numbers::Real;

/// `AGM(a, b)` for `a, b > 0` at the precision of `a` (DLMF 19.8.1).  Quadratic
/// convergence; once `|a−b| ≤ ε·a` one more step is taken: the values have converged
/// then, but derivative parts carried along (e.g. by `Dual` numbers) lag behind — with
/// `|a−b| = δ` their difference is only `O(√δ)` relative — and the extra step squares
/// that (without it, d/dk of `K(k)` near `k = 0` was good to only about 1e-9).
pub(crate) fn agm<R: Real>(a: &R, b: &R) -> Result<R, SpecialError> {
    let (mut a, mut b) = (a.clone(), b.clone());
    let eps = a.epsilon();
    let half = a.from_ratio(1, 2);
    let mut converged = false;
    for _ in 0..200 {
        if converged {
            return Ok(a);
        }
        converged = (a.clone() - b.clone()).abs() <= eps.clone() * a.clone();
        let an = (a.clone() + b.clone()) * half.clone();
        b = (a * b).sqrt();
        a = an;
    }
    Err(SpecialError::NoConvergence(
        "AGM did not converge in 200 steps".into(),
    ))
}

/// `k' = √((1−k)(1+k))` (no cancellation as `k → 1`).
pub(crate) fn complementary<R: Real>(k: &R) -> R {
    let one = k.one();
    ((one.clone() - k.clone()) * (one + k.clone())).sqrt()
}

/// `k'² = 1 − k²`: for the fixed-precision types (`Real::FIXED`, no guard bits) from
/// `k²` as a double-double, so that the result is rounded once; otherwise
/// `(1 − k)(1 + k)` (two roundings at the working precision, which has guard bits).
pub(crate) fn complementary_sqr<R: Real>(k: &R) -> R {
    let one = k.one();
    if !R::FIXED {
        return (one.clone() - k.clone()) * (one + k.clone());
    }
    let k2 = Dd::from(k.clone()).sqr();
    let (s, e) = two_sum(1.0, -k2.v());
    with_value(&(one - k2.hi.clone()), s) + k.from_f64(e - k2.lo)
}

/// `2/π` as a double-double.
pub(crate) const TWO_OVER_PI: (f64, f64) =
    (std::f64::consts::FRAC_2_PI, -3.935_735_335_036_497e-17);

/// `AGM(1, κ')` for the modulus `κ` given by `m = κ²` and `mc = κ'²` (normalised
/// double-doubles, `0 ≤ m`, `0 < mc`), to about `2⁻⁸⁵` relative, for the
/// fixed-precision types: the scale `π/(2K)` of the theta data of the Jacobi
/// functions (module `theta`; DLMF 19.8.5), or above `κ² = 0.81` the scale `π/(2K')`
/// and period `πK/(2K')` at imaginary argument, whose quotient times `π/2` is
/// `π/(2K)`.  A plain `f64` AGM is good to about one ulp, which alone used up half of
/// the 2 ε aimed at for Z and Λ₀.
pub(crate) fn agm1_dd<R: Real>(m: &Dd<R>, mc: &Dd<R>) -> Dd<R> {
    let imaginary = m.v() > SERIES_MAX_M;
    let th = Theta::with_bottom(m, mc, imaginary, true);
    if !imaginary {
        return th.scale;
    }
    let half_pi = Dd {
        hi: m.hi.from_f64(std::f64::consts::FRAC_PI_2),
        lo: 6.123_233_995_736_766e-17,
    };
    th.scale.mul(&half_pi).div(&th.period)
}

/// `(κ², κ'²)` of the modulus `k` (`0 ≤ k < 1`) as normalised double-doubles; `κ'²`
/// is `1 − k²` with the rounding error of `k²` carried along.  Fixed precision only.
pub(crate) fn modulus_dd<R: Real>(k: &R) -> (Dd<R>, Dd<R>) {
    let k2 = Dd::from(k.clone()).sqr().norm();
    let (s, e) = two_sum(1.0, -k2.v());
    let mc = Dd {
        hi: with_value(&(k.one() - k2.hi.clone()), s),
        lo: e - k2.lo,
    }
    .norm();
    (k2, mc)
}

/// `1/K(k) = 2 AGM(1, k')/π` (DLMF 19.8.5), `0 ≤ k < 1`: in double-double from
/// [`agm1_dd`] for the fixed-precision types, else by [`agm`] at the precision of `k`
/// (only `hi` is meaningful then, see [`Dd::value`]).
pub(crate) fn inv_quarter_period_dd<R: Real>(k: &R) -> Result<Dd<R>, SpecialError> {
    if !R::FIXED {
        let a = agm(&k.one(), &complementary(k))?;
        return Ok(Dd::from(a.mul_2si(1) / k.pi()));
    }
    let (m, mc) = modulus_dd(k);
    let two_pi = Dd {
        hi: k.from_f64(TWO_OVER_PI.0),
        lo: TWO_OVER_PI.1,
    };
    Ok(agm1_dd(&m, &mc).mul(&two_pi))
}

/// The complete elliptic integral of the first kind `K(k)`, modulus `k` (not `m = k²`).
///
/// Algorithm: `K(k) = π / (2·AGM(1, k'))` (DLMF 19.8.5) with `k' = √((1−k)(1+k))`,
/// evaluated at `N + 40` bits and rounded to the precision `N` of `k`.  Relative error
/// below a few ulp in `f64`, below `2^(4−N)` at `N` bits.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k < 1` (NaN included).
///
/// ```
/// use eulertop_numerics::special::ellipk;
/// // mpmath: ellipk(0.25) = 1.68575035481259604287120365780
/// let kk = ellipk(&0.5_f64).unwrap();
/// assert!((kk - 1.685750354812596).abs() < 1e-15);
/// assert!(ellipk(&1.0_f64).is_err());
/// ```
pub fn ellipk<R: Real>(k: &R) -> Result<R, SpecialError> {
    if R::BY_RULE {
        return R::quarter_period_by_rule(k, false).map_err(SpecialError::Rule);
    }
    check_modulus_below_one(k)?;
    let n = k.prec();
    let kw = k.with_prec(n + GUARD);
    let m = agm(&kw.one(), &complementary(&kw))?;
    Ok((kw.pi() / (m * kw.from_i64(2))).with_prec(n))
}

/// The complementary complete integral `K'(k) = K(√(1−k²))`, modulus `k`.
///
/// Algorithm: `K'(k) = π / (2·AGM(1, k))` (DLMF 19.8.5 applied to `k'`, whose
/// complementary modulus is `k` itself, so no rounding of `k'` enters), at `N + 40`
/// bits.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k < 1`;
/// [`SpecialError::Pole`] for `k = 0` (`K'(0) = ∞`).
///
/// ```
/// use eulertop_numerics::special::ellipkp;
/// // mpmath: ellipk(1 - 0.25) = 2.15651564749964323262...
/// let kp = ellipkp(&0.5_f64).unwrap();
/// assert!((kp - 2.1565156474996432).abs() < 1e-15);
/// assert!(ellipkp(&0.0_f64).is_err());
/// ```
pub fn ellipkp<R: Real>(k: &R) -> Result<R, SpecialError> {
    if R::BY_RULE {
        return R::quarter_period_by_rule(k, true).map_err(SpecialError::Rule);
    }
    check_modulus_below_one(k)?;
    if k.is_zero() {
        return Err(SpecialError::Pole("K'(k) is infinite at k = 0".into()));
    }
    let n = k.prec();
    let kw = k.with_prec(n + GUARD);
    let m = agm(&kw.one(), &kw)?;
    Ok((kw.pi() / (m * kw.from_i64(2))).with_prec(n))
}
