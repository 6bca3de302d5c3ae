//! The amplitude `φ` of the incomplete integrals split as `φ = Qπ/2 + r`, `|r| ≤ π/4`,
//! without losing the relative accuracy of `r` (Cody–Waite with a triple-double π for
//! `f64`, `log2|Q|` extra bits for MPFR), and the reduced sine and cosine.

use super::reduce::reduce_dd;
use super::{GUARD, SpecialError, check_finite};
use crate::numbers::Real;

/// π as an unevaluated sum of three doubles.
pub(crate) const PI_TRIPLE: [f64; 3] = [
    std::f64::consts::PI,
    1.224_646_799_147_353_2e-16,
    -2.994_769_809_718_339_7e-33,
];

/// The quadrant `Q` of `φ` (nearest integer to `φ/(π/2)`) and the bits the reduction
/// needs beyond the working precision; an error for `|φ|/(π/2) ≥ 2⁴⁰` or a non-finite
/// `φ`.
pub(crate) fn quadrant<R: Real>(phi: &R) -> Result<(i64, u32), SpecialError> {
    check_finite(phi, "phi")?;
    let ratio = phi.to_f64() / std::f64::consts::FRAC_PI_2;
    if ratio.abs() >= 2f64.powi(40) {
        return Err(SpecialError::ArgumentTooLarge(format!(
            "|phi|/(pi/2) = {:e} >= 2^40",
            ratio.abs()
        )));
    }
    let q = ratio.round() as i64;
    Ok((q, 64 - q.unsigned_abs().leading_zeros()))
}

/// `r = φ − Qπ/2` at the precision of `phi` (raise it by the bits of [`quadrant`]
/// first), with full relative accuracy also when `φ` is close to a multiple of `π/2`:
/// for MPFR the subtraction is repeated with as many more bits as it cancelled.
pub(crate) fn residual<R: Real>(phi: &R, q: i64) -> R {
    if q == 0 {
        return phi.clone();
    }
    let half_pi = phi.pi().mul_2si(-1);
    if R::FIXED {
        let t = PI_TRIPLE;
        return reduce_dd(phi, &half_pi, q, [t[0] / 2.0, t[1] / 2.0, t[2] / 2.0]);
    }
    let r = phi.clone() - phi.from_i64(q) * half_pi;
    let lost = phi.log2_abs() - r.log2_abs();
    if lost.is_nan() || lost <= 4.0 {
        return r;
    }
    // a p-bit φ is not closer than about 2^(−2p) to a multiple of π/2 (r = 0: ∞)
    let extra = (lost.min(f64::from(2 * phi.prec() + 64)) as u32) + 16;
    let wide = phi.with_prec(phi.prec() + extra);
    let r = wide.clone() - wide.from_i64(q) * wide.pi().mul_2si(-1);
    r.with_prec(phi.prec())
}

/// An amplitude split as `φ = Qπ/2 + r` for an incomplete integral: the quadrant, the
/// residual and the working precision `w` it was formed at.
pub(crate) struct Amplitude<R> {
    /// The quadrant `Q` ([`quadrant`]).
    pub q: i64,
    /// `r = φ − Qπ/2` at precision `w` ([`residual`]).
    pub r: R,
    /// The working precision: the result's precision, the guard bits and the bits the
    /// reduction needs.
    pub w: u32,
}

/// Splits `phi` for a result of precision `prec` (see [`Amplitude`]); the errors of
/// [`quadrant`].
pub(crate) fn amplitude<R: Real>(phi: &R, prec: u32) -> Result<Amplitude<R>, SpecialError> {
    let (q, bits) = quadrant(phi)?;
    let w = prec + GUARD + bits;
    Ok(Amplitude {
        q,
        r: residual(&phi.with_prec(w), q),
        w,
    })
}

/// `(sin φ, cos φ)` for `φ = Qπ/2 + r`, from the sine and cosine of `r`.
pub(crate) fn sin_cos_quadrant<R: Real>(q: i64, r: &R) -> (R, R) {
    let (s, c) = r.sin_cos();
    match q.rem_euclid(4) {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// The reduction of an integral `G(φ) = ∫₀^φ g(sin²θ) dθ` (odd, with
/// `G(φ + π) = G(φ) + 2G(π/2)`) to an amplitude in `[0, π/2]`: for `φ = Qπ/2 + r`,
/// `G(φ) = c·G(π/2) + σ·G(θ)` with `(sin θ, cos² θ)` returned exactly from `r`.
/// Returns `(c, σ, sin θ, cos² θ)`, with `sin θ` carrying the sign of the reduced
/// amplitude (`θ ∈ [−π/4, π/2]`).
pub(crate) fn fold<R: Real>(q: i64, r: &R) -> (i64, i64, R, R) {
    let (s, c) = r.sin_cos();
    if q.rem_euclid(2) == 0 {
        return (q, 1, s, c.sqr());
    }
    // φ = Qπ/2 + r, Q odd: with σ = sign r, φ = (Q + σ)π/2 − σ(π/2 − |r|), and
    // G(φ) = (Q + σ)G(π/2) − σG(π/2 − |r|), where sin(π/2 − |r|) = cos r
    let sigma = if *r < r.zero() { -1 } else { 1 };
    (q + sigma, -sigma, c, s.sqr())
}
