//! Jacobi's zeta function `Z(φ, k)` and Heuman's lambda function `Λ₀(φ, k)`, through
//! Carlson's `R_J`.

use super::agm::{agm, complementary};
use super::carlson::rj;
use super::ellint::f_agm;
use super::phase::{Amplitude, amplitude, fold, sin_cos_quadrant};
use super::{SpecialError, check_finite, check_modulus_below_one, refuse_by_rule};
use crate::numbers::Real;

/// `k² s c Δ R_J(0, k'², 1, Δ²)/3` with `Δ² = c² + k'² s² = 1 − k² s²` for the sine
/// `s` and cosine `c` of the amplitude: `Z(φ, k)·K(k)` (DLMF 19.2.33;
/// the form Boost uses).  Zero where `k s c = 0`.
fn zeta_times_k<R: Real>(s: &R, c: &R, k: &R, kp: &R) -> Result<R, SpecialError> {
    let kp2 = kp.sqr();
    let d2 = c.sqr() + kp2.clone() * s.sqr();
    let prod = k.sqr() * s.clone() * c.clone();
    if prod.is_zero() {
        return Ok(prod);
    }
    let j = rj(&s.zero(), &kp2, &s.one(), &d2)?;
    Ok(prod * d2.sqrt() * j / s.from_i64(3))
}

/// Jacobi's zeta function `Z(φ, k) = E(φ, k) − E(k)F(φ, k)/K(k)` (DLMF 19.2.33), **modulus** `k` (Boost: `jacobi_zeta(k, φ)`), `0 ≤ k < 1`, any real
/// `φ`; odd and π-periodic in `φ`.
///
/// Algorithm: `Z(φ, k) = k² sin φ cos φ Δ R_J(0, k'², 1, Δ²)/(3K(k))`,
/// `Δ² = 1 − k² sin²φ` (the form Boost uses; the tests check it against the definition),
/// a product with no cancellation; `sin φ`, `cos φ` from the reduced amplitude
/// `φ = Qπ/2 + r`, `R_J` by duplication (DLMF 19.36.2), `1/K = 2 AGM(1, k')/π`
/// (DLMF 19.8.5).  Working precision `N + 40 + log2|Q|`.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k < 1`,
/// [`SpecialError::NotFinite`], [`SpecialError::ArgumentTooLarge`] for
/// `|φ|/(π/2) ≥ 2⁴⁰`.
///
/// ```
/// use eulertop::special::{ellipe, ellipeinc, ellipf, ellipk, jacobizeta};
/// let (phi, k) = (0.8_f64, 0.6_f64);
/// let z = jacobizeta(&phi, &k).unwrap();
/// let direct = ellipeinc(&phi, &k).unwrap()
///     - ellipe(&k).unwrap() * ellipf(&phi, &k).unwrap() / ellipk(&k).unwrap();
/// assert!((z - direct).abs() < 1e-15);
/// // mpmath: ellipe(0.8, 0.36) - ellipe(0.36)*ellipf(0.8, 0.36)/ellipk(0.36)
/// assert!((z - 0.10012024322789093).abs() < 1e-15);
/// ```
pub fn jacobizeta<R: Real>(phi: &R, k: &R) -> Result<R, SpecialError> {
    refuse_by_rule::<R>("Z(phi, k)")?;
    check_modulus_below_one(k)?;
    check_finite(phi, "phi")?;
    let n = phi.prec().max(k.prec());
    let a = amplitude(phi, n)?;
    let kw = k.with_prec(a.w);
    let (s, c) = sin_cos_quadrant(a.q, &a.r);
    let kp = complementary(&kw);
    let zk = zeta_times_k(&s, &c, &kw, &kp)?;
    let inv_k = agm(&kw.one(), &kp)?.mul_2si(1) / kw.pi();
    Ok((zk * inv_k).with_prec(n))
}

/// Heuman's lambda function
/// `Λ₀(φ, k) = F(φ, k')/K(k') + (2/π) K(k) Z(φ, k')` (DLMF 19.2.32; Boost:
/// `heuman_lambda(k, φ)`), **modulus** `k`, `0 ≤ k < 1`, any real `φ`
/// (`Λ₀(φ + π) = Λ₀(φ) + 2`, `Λ₀(π/2, k) = 1`).
///
/// Algorithm: with `k'` never rounded (the integrals of modulus `k'` take their
/// complementary modulus `k` directly: `F(φ, k')` by the AGM phase recursion of
/// [`ellipf`](super::ellipf) started from `k`, `K(k') = π/(2 AGM(1, k))`),
/// `Λ₀ = (F(φ, k') + k'² sin φ cos φ Δ' R_J(0, k², 1, Δ'²)/(3 AGM(1, k')))/K(k')`,
/// `Δ'² = cos²φ + k² sin²φ`, a sum of terms of one sign on `[0, π/2]`.  At `k = 0`,
/// `Λ₀(φ, 0) = 2j + sin(φ − jπ)` for `j` the integer nearest `φ/π`.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k < 1`,
/// [`SpecialError::NotFinite`], [`SpecialError::ArgumentTooLarge`] for
/// `|φ|/(π/2) ≥ 2⁴⁰`.
///
/// ```
/// use eulertop::special::heumanlambda;
/// // mpmath, from the definition: Λ₀(1, 0.5) = 0.792745183008071035953588061453
/// let l = heumanlambda(&1.0_f64, &0.5).unwrap();
/// assert!((l - 0.792745183008071).abs() < 1e-15);
/// // Λ₀(π/2, k) = 1
/// let one = heumanlambda(&std::f64::consts::FRAC_PI_2, &0.3).unwrap();
/// assert!((one - 1.0).abs() < 1e-15);
/// ```
pub fn heumanlambda<R: Real>(phi: &R, k: &R) -> Result<R, SpecialError> {
    refuse_by_rule::<R>("Lambda0(phi, k)")?;
    check_modulus_below_one(k)?;
    check_finite(phi, "phi")?;
    let n = phi.prec().max(k.prec());
    let Amplitude { q, r, w } = amplitude(phi, n)?;
    let kw = k.with_prec(w);
    let (s, c) = sin_cos_quadrant(q, &r);
    if kw.is_zero() {
        // Λ₀(·, 0) is odd, Λ₀(π/2, 0) = 1 and Λ₀(θ, 0) = sin θ on [−π/2, π/2]
        let (whole, sigma, st, _) = fold(q, &r);
        let lam = r.from_i64(whole) + r.from_i64(sigma) * st;
        return Ok(lam.with_prec(n));
    }
    let one = kw.one();
    let kp = complementary(&kw);
    let f = f_agm(q, &r, &kw)?;
    let zk = zeta_times_k(&s, &c, &kp, &kw)?;
    let big_kp = kw.pi() / agm(&one, &kw)?.mul_2si(1);
    let lam = (f + zk / agm(&one, &kp)?) / big_kp;
    Ok(lam.with_prec(n))
}
