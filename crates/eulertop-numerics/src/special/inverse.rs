//! Inverse of the Jacobi functions: the argument from `(sn, cn, dn)`.

use super::ellint::ellipf;
use super::{SpecialError, check_finite, check_modulus_below_one, show};
use crate::numbers::Real;

/// The real argument `u ∈ (−2K, 2K]` with `sn(u,k) = sn` and `cn(u,k) = cn`
/// (the quadrant is taken from the signs of `sn` and `cn`); **modulus** `k`.
///
/// Algorithm: `am = atan2(sn, cn) ∈ (−π, π]`, `u = F(am, k)` (DLMF 22.15.11–12,
/// 22.16.1), with [`ellipf`].  The condition number is `1/dn`: near `u = ±K` with
/// `k → 1` small errors in the input move `u` a lot (the forward values still agree).
///
/// `dn` is only checked: the input must satisfy `sn² + cn² = 1` and
/// `dn² + k² sn² = 1` to within `2^(10−N)` and `dn > 0`, otherwise
/// [`SpecialError::Inconsistent`].  Other errors: [`SpecialError::ModulusOutOfRange`],
/// [`SpecialError::NotFinite`].
///
/// ```
/// use eulertop_numerics::special::{jacobi_inverse, sncndn};
/// let (s, c, d) = sncndn(&-2.5_f64, &0.8).unwrap();   // K(0.8) ≈ 1.995, so -2.5 is in (-2K, -K)
/// let u = jacobi_inverse(&s, &c, &d, &0.8).unwrap();
/// assert!((u + 2.5).abs() < 1e-14);
/// assert!(jacobi_inverse(&0.6_f64, &0.6, &0.9, &0.8).is_err()); // sn² + cn² ≠ 1
/// ```
pub fn jacobi_inverse<R: Real>(sn: &R, cn: &R, dn: &R, k: &R) -> Result<R, SpecialError> {
    if R::BY_RULE {
        return R::jacobi_inverse_by_rule(sn, cn, dn, k).map_err(SpecialError::Rule);
    }
    check_modulus_below_one(k)?;
    check_finite(sn, "sn")?;
    check_finite(cn, "cn")?;
    check_finite(dn, "dn")?;
    let n = sn.prec().max(cn.prec()).max(dn.prec()).max(k.prec());
    let one = sn.one();
    let tol = one.mul_2si(10 - n as i32);
    let r1 = sn.sqr() + cn.sqr() - one.clone();
    let r2 = dn.sqr() + k.sqr() * sn.sqr() - one;
    if r1.abs() > tol || r2.abs() > tol || *dn <= dn.zero() {
        return Err(SpecialError::Inconsistent(format!(
            "sn = {}, cn = {}, dn = {} are not sn, cn, dn of one real argument for k = {}",
            show(sn),
            show(cn),
            show(dn),
            show(k)
        )));
    }
    let phi = sn.atan2(cn);
    ellipf(&phi, k)
}
