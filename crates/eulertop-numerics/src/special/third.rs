//! The incomplete elliptic integral of the third kind `Π(n, φ, k)` through Carlson's
//! `R_F` and `R_J`.

use super::agm::complementary_sqr;
use super::carlson::{rf, rj};
use super::dd::{Dd, with_fma};
use super::phase::{Amplitude, amplitude, fold};
use super::{SpecialError, check_finite, check_modulus_below_one, refuse_by_rule, show};
use crate::numbers::Real;

/// `Π(N, θ, k)` for `0 ≤ N`, `N sin²θ < 1`, `θ ∈ [−π/4, π/2]` given by `s = sin θ`,
/// `c² = cos² θ`, with `nc = 1 − N` given separately (no cancellation as `N → 1`):
/// `s (R_F(c², Δ², 1) + (N s²/3) R_J(c², Δ², 1, p))`, `p = 1 − N s²` or, where that
/// cancels, `c² + (1 − N) s²` (DLMF 19.25.14 in terms of `sin θ`).  `N`, `N s²`, `p`
/// and the combination are formed in double-double (fixed precision; see
/// [`Dd::value`]), so that the error is that of `s`, `R_F`, `R_J` and one rounding.
#[inline(always)]
fn positive<R: Real>(
    nn: &Dd<R>,
    nc: &R,
    s: &R,
    c2: &R,
    d2: &R,
    f: &R,
) -> Result<Dd<R>, SpecialError> {
    let t = Dd::from(s.clone()).sqr();
    let nt = nn.mul(&t);
    if nt.hi.is_zero() {
        return Ok(Dd::from(s.clone()).mul_r(f));
    }
    let one = s.one();
    let p = if nt.v() < 0.5 {
        Dd::from(one.clone()).add(&nt.neg())
    } else {
        Dd::from(c2.clone()).add(&t.mul_r(nc))
    };
    let j = rj(c2, d2, &one, &p.value())?;
    let three = Dd::from(s.from_i64(3));
    Ok(nt.mul_r(&j).div(&three).add_r(f).mul_r(s))
}

/// `Π(n, θ, k)` for `θ ∈ [−π/4, π/2]` (`s = sin θ`, `c² = cos² θ`), `n sin²θ < 1`,
/// `0 ≤ k < 1`, as a double-double (see [`Dd::value`]).  For `n < 0` the
/// transformation Abramowitz–Stegun 17.7.15 to `N = (k² − n)/(1 − n) ∈ (k², 1)` turns
/// the cancelling sum into one of positive terms:
/// `Π(n) = (−n)k'²/((1−n)(k²−n)) Π(N) + k²/(k²−n) F + √(−n/((k²−n)(1−n)))
/// atan(√(−nN) s c/Δ)`, every product and quotient in double-double.
#[inline(always)]
pub(crate) fn reduced_pi<R: Real>(n: &R, s: &R, c2: &R, k: &R) -> Result<Dd<R>, SpecialError> {
    let one = s.one();
    let k2 = Dd::from(k.clone()).sqr();
    let kp2 = complementary_sqr(k);
    let d2 = Dd::from(s.clone()).sqr().mul_r(&kp2).add_r(c2).value();
    let f = rf(c2, &d2, &one)?;
    if *n >= n.zero() {
        return positive(&Dd::from(n.clone()), &(one - n.clone()), s, c2, &d2, &f);
    }
    let m = -n.clone();
    let onem = Dd::from(one).add_r(&m);
    let k2m = k2.add_r(&m);
    let nn = k2m.div(&onem);
    let kp2d = Dd::from(kp2);
    let pi_n = positive(&nn, &kp2d.div(&onem).value(), s, c2, &d2, &f)?;
    let den = onem.mul(&k2m);
    let first = kp2d.mul_r(&m).mul(&pi_n).div(&den);
    let second = k2.mul_r(s).mul_r(&f).div(&k2m);
    // atan(√(m N s² c²/Δ²)), the argument in double-double: atan(x + e) = atan x + e/(1 + x²)
    let x2 = nn.mul_r(&m).mul(&Dd::from(s.clone()).sqr()).mul_r(c2);
    let x = if x2.hi.is_zero() {
        // θ = π/2 (c = 0): a zero angle, with finite derivative parts
        x2
    } else {
        x2.div(&Dd::from(d2)).sqrt()
    };
    let angle = Dd {
        hi: x.hi.atan(),
        lo: x.lo / (1.0 + x.v() * x.v()),
    };
    let angle = if R::FIXED { angle } else { Dd::from(angle.hi) };
    let angle = if *s < s.zero() { angle.neg() } else { angle };
    let third = Dd::from(m).div(&den).sqrt().mul(&angle);
    Ok(first.add(&second).add(&third))
}

/// The incomplete elliptic integral of the third kind
/// `Π(n, φ, k) = ∫₀^φ dθ / ((1 − n sin²θ) √(1 − k² sin²θ))` (DLMF 19.2.7 with
/// `α² = n`), characteristic `n`, **modulus** `k` (mpmath: `ellippi(n, φ, m = k²)`),
/// `0 ≤ k < 1`, any real `φ` when `n < 1`, and `n sin²φ < 1` (so `|φ| < π/2`) when
/// `n ≥ 1`.
///
/// Algorithm: the amplitude is reduced as for [`ellipeinc`](super::ellipeinc)
/// (`Π(φ + π) = Π(φ) + 2Π(n, k)`, DLMF 19.2.10); then
/// `Π(n, θ, k) = sin θ (R_F(c², Δ², 1) + (n sin²θ/3) R_J(c², Δ², 1, 1 − n sin²θ))`,
/// `c = cos θ`, `Δ² = 1 − k² sin²θ` (DLMF 19.25.14), with `1 − n sin²θ` formed as
/// `c² + (1 − n) sin²θ` where that is more accurate, and for `n < 0` the transformation
/// Abramowitz–Stegun 17.7.15 to a characteristic in `(k², 1)`, which replaces a
/// cancelling difference by a sum of positive terms (as Boost does).  Carlson's `R_F`,
/// `R_J` by duplication (DLMF 19.36.1–2); working precision `N + 40 + log2|Q|`, one
/// rounding at the end.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k < 1`;
/// [`SpecialError::Pole`] where `n sin²φ = 1` or for `n = 1`, `|φ| ≥ π/2`;
/// [`SpecialError::Domain`] where `n sin²φ > 1` (the integral is not real) or for
/// `n > 1`, `|φ| > π/2`; [`SpecialError::NotFinite`],
/// [`SpecialError::ArgumentTooLarge`] as [`ellipf`](super::ellipf).
///
/// ```
/// use eulertop_numerics::special::{ellipf, ellippi};
/// // mpmath: ellippi(0.5, 1, m=0.25) = 1.22801441431622064261129894629
/// let p = ellippi(&0.5_f64, &1.0, &0.5).unwrap();
/// assert!((p - 1.2280144143162206).abs() < 1e-15);
/// // n = 0 is F(φ, k)
/// let f = ellipf(&1.0_f64, &0.5).unwrap();
/// assert!((ellippi(&0.0_f64, &1.0, &0.5).unwrap() - f).abs() < 1e-15);
/// assert!(ellippi(&2.0_f64, &1.0, &0.5).is_err()); // 2 sin²1 > 1
/// ```
pub fn ellippi<R: Real>(n: &R, phi: &R, k: &R) -> Result<R, SpecialError> {
    refuse_by_rule::<R>("Pi(n, phi, k)")?;
    check_modulus_below_one(k)?;
    check_finite(n, "n")?;
    check_finite(phi, "phi")?;
    let prec = n.prec().max(phi.prec()).max(k.prec());
    let Amplitude { q, r, w } = amplitude(phi, prec)?;
    let (nw, kw) = (n.with_prec(w), k.with_prec(w));
    let (c, sigma, s, c2) = fold(q, &r);
    let one = kw.one();
    if c != 0 && nw >= one {
        let at = format!("n = {}, phi = {}", show(n), show(phi));
        return Err(if nw == one {
            SpecialError::Pole(format!("Pi(n, phi, k) is infinite at {at}"))
        } else {
            SpecialError::Domain(format!("Pi(n, phi, k) is not real at {at} (|phi| > pi/2)"))
        });
    }
    let nt = nw.clone() * s.sqr();
    if nt >= one {
        let at = format!("n = {}, phi = {}", show(n), show(phi));
        return Err(if nt == one {
            SpecialError::Pole(format!(
                "Pi(n, phi, k) is infinite at {at} (n sin^2(phi) = 1)"
            ))
        } else {
            SpecialError::Domain(format!(
                "Pi(n, phi, k) is not real at {at}: n sin^2(phi) = {} > 1",
                show(&nt)
            ))
        });
    }
    // Π(φ) = σ Π(θ) + c Π(π/2), in double-double; in fixed precision compiled for the
    // fused multiply-add (the two-products of the double-double steps)
    let sum = || -> Result<R, SpecialError> {
        let mut p = reduced_pi(&nw, &s, &c2, &kw)?.mul_r(&r.from_i64(sigma));
        if c != 0 {
            let whole = reduced_pi(&nw, &one, &kw.zero(), &kw)?;
            p = p.add(&whole.mul_r(&r.from_i64(c)));
        }
        Ok(p.value())
    };
    let p = if R::FIXED { with_fma(sum)? } else { sum()? };
    Ok(p.with_prec(prec))
}
