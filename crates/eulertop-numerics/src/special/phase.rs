//! The amplitude `φ` of the incomplete integrals split as `φ = Qπ/2 + r`, `|r| ≤ π/4`,
//! without losing the relative accuracy of `r` (Cody–Waite with a triple-double π for
//! `f64`, `log2|Q|` extra bits for MPFR), and the reduced sine and cosine.

use super::dd::{Dd, fast_two_sum, two_prod, with_value};
use super::reduce::reduce_dd2;
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
    if R::FIXED {
        let (r, lo) = residual_fixed(phi, q);
        return r + phi.from_f64(lo);
    }
    let half_pi = phi.pi().mul_2si(-1);
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

/// [`residual`] for the fixed-precision types as `(r, lo)`: `r + lo = φ − Qπ/2` to
/// about `2⁻¹⁰⁰·|φ|` (Cody–Waite with the triple-double π, [`reduce_dd2`]).
pub(crate) fn residual_fixed<R: Real>(phi: &R, q: i64) -> (R, f64) {
    if q == 0 {
        return (phi.clone(), 0.0);
    }
    let t = PI_TRIPLE;
    let half = [t[0] / 2.0, t[1] / 2.0, t[2] / 2.0];
    reduce_dd2(phi, &phi.pi().mul_2si(-1), q, half)
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

/// `x⁵`'s coefficients of `sin x = x − x³/6 + x⁵·P(x²)`: `P(z) = Σ (−z)ʲ/(2j + 5)!`.
const SIN_TAIL: [f64; 9] = [
    1.0 / 120.0,
    -1.0 / 5040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
    1.0 / 355_687_428_096_000.0,
    -1.0 / 121_645_100_408_832_000.0,
    1.0 / 51_090_942_171_709_440_000.0,
];

/// `x⁴`'s coefficients of `cos x = 1 − x²/2 + x⁴·Q(x²)`: `Q(z) = Σ (−z)ʲ/(2j + 4)!`.
const COS_TAIL: [f64; 9] = [
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40_320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
    1.0 / 20_922_789_888_000.0,
    -1.0 / 6_402_373_705_728_000.0,
    1.0 / 2_432_902_008_176_640_000.0,
];

/// `−(1/6 − fl(1/6))`: `−1/6 = −fl(1/6) + SIXTH_LO` exactly to `2⁻¹⁰⁸`.
const SIXTH_LO: f64 = -9.251_858_538_542_97e-18;

/// `Σ cⱼ zʲ` by Horner's rule.
#[inline(always)]
fn horner(z: f64, c: &[f64]) -> f64 {
    c.iter().rev().fold(0.0, |acc, &cj| acc.mul_add(z, cj))
}

/// `(sin x, cos x)` as double-doubles for `x = r + lo`, `|x| ≤ π/4 + 2⁻⁴⁰`, in the
/// fixed-precision types (the derivative parts of `r`'s sine and cosine ride along
/// in `hi`).  Taylor series: `sin x = x + x³·B`, `|x³B| ≤ 0.081|x|`, with `B` and
/// `x³` in `f64`; `cos x = (1 − x²/2) + x⁴·Q(x²)` with `x²/2` formed exactly and
/// `x⁴Q ≤ 0.016`; `lo` enters through the derivatives.  Error about `2⁻⁵⁷`
/// relative (sine: `0.25·2⁻⁵³` measured against mpmath, cosine `0.09·2⁻⁵³`), where the
/// `f64` sine and cosine are rounded to `2⁻⁵³` (and `r`'s own rounding adds as much
/// again to the sine of a reduced amplitude).
pub(crate) fn sin_cos_dd<R: Real>(r: &R, lo: f64) -> (Dd<R>, Dd<R>) {
    let (s, c) = r.sin_cos();
    let x = r.to_f64();
    let (x2, e2) = two_prod(x, x);
    // sine: x + lo·(1 − x²/2) + x³(−1/6 + x²P(x²)), x³ and −1/6 as double-doubles
    let b = x2.mul_add(horner(x2, &SIN_TAIL), -1.0 / 6.0);
    let (x3, e3) = two_prod(x, x2);
    let e3 = x.mul_add(e2, e3);
    let y = x3.mul_add(b, x3.mul_add(SIXTH_LO, e3 * b));
    let (h, e) = fast_two_sum(x, y);
    let (sh, sl) = fast_two_sum(h, e + lo * (1.0 - 0.5 * x2));
    // cosine: (1 − x²/2) + x⁴Q(x²), x²/2 exact
    let (h, e) = fast_two_sum(1.0, -0.5 * x2);
    let x2_lo = x.mul_add(2.0 * lo, e2);
    let (ch, cl) = fast_two_sum(h, (e - 0.5 * x2_lo) + x2 * x2 * horner(x2, &COS_TAIL));
    (
        Dd {
            hi: with_value(&s, sh),
            lo: sl,
        },
        Dd {
            hi: with_value(&c, ch),
            lo: cl,
        },
    )
}

/// `(sin φ, cos φ)` for `φ = Qπ/2 + r` as double-doubles: for the fixed-precision
/// types from `φ` reduced again as `r + lo` ([`residual_fixed`], [`sin_cos_dd`]),
/// else from `a.r` at the working precision (`lo` zero).  `phi` at precision `a.w`.
pub(crate) fn sin_cos_amplitude<R: Real>(phi: &R, a: &Amplitude<R>) -> (Dd<R>, Dd<R>) {
    let (s, c) = if R::FIXED {
        let (r, lo) = residual_fixed(phi, a.q);
        sin_cos_dd(&r, lo)
    } else {
        let (s, c) = a.r.sin_cos();
        (Dd::from(s), Dd::from(c))
    };
    match a.q.rem_euclid(4) {
        0 => (s, c),
        1 => (c, s.neg()),
        2 => (s.neg(), c.neg()),
        _ => (c.neg(), s),
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

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    /// [`sin_cos_dd`] within `0.3·2⁻⁵³` relative of MPFR at 200 bits on `|x| ≤ π/4`,
    /// with and without a low part.
    #[test]
    fn sin_cos_dd_against_mpfr() {
        for i in 0..=2000 {
            let r = -0.786 + 1.572 * f64::from(i) / 2000.0;
            for lo in [0.0, r * 1e-17, -3e-18] {
                let (s, c) = sin_cos_dd(&r, lo);
                let x = Float::with_val(200, r) + lo;
                for (got, want) in [(s, x.clone().sin()), (c, x.clone().cos())] {
                    let g = Float::with_val(200, got.hi) + got.lo;
                    let scale = want.clone().abs().max(&Float::with_val(200, 1e-300));
                    let e = Float::with_val(200, &g - &want).abs() / scale;
                    let e = e.to_f64() * 2f64.powi(53);
                    assert!(e <= 0.3, "x = {r} + {lo}: {e}");
                }
            }
        }
    }
}
