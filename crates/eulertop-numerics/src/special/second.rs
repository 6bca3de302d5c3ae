//! The elliptic integrals of the second kind: the complete `E(k)` and the incomplete
//! `E(φ, k)` for any real `φ`, through Carlson's `R_F` and `R_D`.

use super::agm::complementary_sqr;
use super::carlson::{rd, rf, sqrt0};
use super::phase::{Amplitude, amplitude, fold};
use super::{GUARD, SpecialError, check_finite, modulus_error, refuse_by_rule};
use crate::numbers::Real;

/// Checks `0 ≤ k ≤ 1` and finiteness (the integrals of the second kind are finite at
/// `k = 1`).
pub(crate) fn check_modulus_closed<R: Real>(k: &R) -> Result<(), SpecialError> {
    if !k.is_finite() || *k < k.zero() || *k > k.one() {
        return Err(modulus_error(k, "[0, 1]"));
    }
    Ok(())
}

/// `E(k)` at the precision of `k` for `0 ≤ k < 1`, `k'² = (1−k)(1+k)`:
/// `E = (k'²/3)(R_D(0, k'², 1) + R_D(0, 1, k'²))` (DLMF 19.25.1), a sum of positive
/// terms.
pub(crate) fn complete_e<R: Real>(k: &R) -> Result<R, SpecialError> {
    let kp2 = complementary_sqr(k);
    let (z, one) = (k.zero(), k.one());
    let sum = rd(&z, &kp2, &one)? + rd(&z, &one, &kp2)?;
    Ok(kp2 * sum / k.from_i64(3))
}

/// The complete elliptic integral of the second kind
/// `E(k) = ∫₀^{π/2} √(1 − k² sin²θ) dθ` (DLMF 19.2.8), **modulus** `k`
/// (mpmath: `ellipe(m = k²)`), `0 ≤ k ≤ 1` (`E(1) = 1`).
///
/// Algorithm: `E(k) = (k'²/3)(R_D(0, k'², 1) + R_D(0, 1, k'²))` (DLMF 19.25.1), a sum
/// of positive terms, with Carlson's `R_D` by the duplication algorithm (DLMF 19.36.2)
/// at `N + 40` bits, rounded once to the precision `N` of `k`.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k ≤ 1` (NaN included).
///
/// ```
/// use eulertop_numerics::special::ellipe;
/// // mpmath: ellipe(0.25) = 1.46746220933942715545979526699
/// let e = ellipe(&0.5_f64).unwrap();
/// assert!((e - 1.4674622093394272).abs() < 1e-15);
/// assert_eq!(ellipe(&1.0_f64).unwrap(), 1.0);
/// assert!(ellipe(&1.5_f64).is_err());
/// ```
pub fn ellipe<R: Real>(k: &R) -> Result<R, SpecialError> {
    refuse_by_rule::<R>("E(k)")?;
    check_modulus_closed(k)?;
    if *k == k.one() {
        return Ok(k.one());
    }
    let n = k.prec();
    Ok(complete_e(&k.with_prec(n + GUARD))?.with_prec(n))
}

/// `E(θ, k)` for `θ ∈ [−π/4, π/2]` given by `s = sin θ`, `c² = cos² θ`, `0 ≤ k < 1`:
/// `k'² s R_F(c², Δ², 1) + (k²k'²/3) s³ R_D(c², 1, Δ²) + k² s √(c²)/Δ` with
/// `Δ² = c² + k'² s² = 1 − k² s²` (DLMF 19.25.10 in terms of `sin θ`), three terms of
/// the sign of `s`: no cancellation, also as `k → 1`.
pub(crate) fn reduced_e<R: Real>(s: &R, c2: &R, k: &R) -> Result<R, SpecialError> {
    if s.is_zero() {
        return Ok(s.clone());
    }
    let one = s.one();
    let k2 = k.sqr();
    let kp2 = complementary_sqr(k);
    let d2 = c2.clone() + kp2.clone() * s.sqr();
    let f = rf(c2, &d2, &one)?;
    let d = rd(c2, &one, &d2)?;
    let third = s.from_ratio(1, 3);
    let tail = k2.clone() * s.clone() * sqrt0(c2) / d2.sqrt();
    Ok(kp2.clone() * s.clone() * f + k2 * kp2 * third * s.sqr() * s.clone() * d + tail)
}

/// The incomplete elliptic integral of the second kind
/// `E(φ, k) = ∫₀^φ √(1 − k² sin²θ) dθ` (DLMF 19.2.5) for any real `φ`, **modulus** `k`
/// (mpmath: `ellipe(φ, m = k²)`), `0 ≤ k ≤ 1`.
///
/// Algorithm: `φ = Qπ/2 + r`, `|r| ≤ π/4` (as in [`ellipf`](super::ellipf)); the
/// quasi-periodicity `E(φ + π) = E(φ) + 2E(k)` (DLMF 19.2.10) and the symmetry about
/// `π/2` bring the amplitude to `θ ∈ [−π/4, π/2]` with `sin θ`, `cos² θ` taken from
/// `r` without cancellation; then
/// `E(θ, k) = k'² sin θ R_F(cos²θ, Δ², 1) + (k²k'²/3) sin³θ R_D(cos²θ, 1, Δ²) +
/// k² sin θ |cos θ|/Δ` with `Δ² = 1 − k² sin²θ` (DLMF 19.25.10), three terms of
/// one sign.  At `k = 1`, `E(θ, 1) = sin θ`.  Working precision `N + 40 + log2|Q|`,
/// one rounding at the end.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k ≤ 1`,
/// [`SpecialError::NotFinite`], [`SpecialError::ArgumentTooLarge`] for
/// `|φ|/(π/2) ≥ 2⁴⁰`.
///
/// ```
/// use eulertop_numerics::special::{ellipe, ellipeinc};
/// // mpmath: ellipe(1, m=0.25) = 0.964876454268627485458878625679
/// let e = ellipeinc(&1.0_f64, &0.5).unwrap();
/// assert!((e - 0.9648764542686275).abs() < 1e-15);
/// // E(φ + π) = E(φ) + 2E(k)
/// let shifted = ellipeinc(&(1.0 + std::f64::consts::PI), &0.5).unwrap();
/// assert!((shifted - e - 2.0 * ellipe(&0.5_f64).unwrap()).abs() < 1e-14);
/// ```
pub fn ellipeinc<R: Real>(phi: &R, k: &R) -> Result<R, SpecialError> {
    refuse_by_rule::<R>("E(phi, k)")?;
    check_modulus_closed(k)?;
    check_finite(phi, "phi")?;
    let n = phi.prec().max(k.prec());
    let Amplitude { q, r, w } = amplitude(phi, n)?;
    let kw = k.with_prec(w);
    let (c, sigma, s, c2) = fold(q, &r);
    let unit = kw == kw.one();
    let part = if unit { s } else { reduced_e(&s, &c2, &kw)? };
    let mut e = r.from_i64(sigma) * part;
    if c != 0 {
        let whole = if unit { kw.one() } else { complete_e(&kw)? };
        e = e + r.from_i64(c) * whole;
    }
    Ok(e.with_prec(n))
}
