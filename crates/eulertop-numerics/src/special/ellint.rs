//! The incomplete elliptic integral of the first kind `F(φ, k)` for any real `φ`.

use super::agm::complementary;
use super::reduce::reduce_dd;
use super::{GUARD, SpecialError, check_finite, check_modulus_below_one, show};
use crate::numbers::Real;

/// π as an unevaluated sum of three doubles.
const PI_TRIPLE: [f64; 3] = [
    std::f64::consts::PI,
    1.224_646_799_147_353_2e-16,
    -2.994_769_809_718_339_7e-33,
];

/// `F(Qπ/2 + r, k)` for an integer `Q` and `|r| ≲ π/4` by the AGM phase recursion
/// `φ_{n+1} = φ_n + atan((b_n/a_n) tan φ_n)` (branch nearest `φ_n`),
/// `F = φ_N/(2^N a_N)` (DLMF §19.8(i); Abramowitz–Stegun 17.6).  The phase is kept as
/// `Q_n π/2 + r_n`: for even `Q` the step is `r ← r + atan((b/a) tan r)`, for odd `Q`
/// (`tan φ = −cot r`) it is `r ← r + atan((a/b) tan r)`, and `Q ← 2Q` (± 1 when `r`
/// leaves `[−π/4, π/4]`).  So `π` never enters a subtraction with the small residual,
/// which matters for `k → 1`, where the recursion amplifies residual errors by `a/b`.
pub(crate) fn f_agm<R: Real>(q0: i64, r0: &R, kp: &R) -> Result<R, SpecialError> {
    if !R::FIXED {
        return f_agm_tangent(q0, r0, kp);
    }
    let one = r0.one();
    let half = r0.from_ratio(1, 2);
    let half_pi = r0.pi().mul_2si(-1);
    let quarter_pi = r0.pi().mul_2si(-2);
    let eps = r0.epsilon();
    let (mut a, mut b, mut r, mut q) = (one.clone(), kp.clone(), r0.clone(), q0);
    let mut scale = one;
    for _ in 0..200 {
        let c = (a.clone() - b.clone()) * half.clone();
        let rho = step_ratio(q, &a, &b);
        r = r.clone() + (rho * r.tan()).atan();
        q = q
            .checked_mul(2)
            .ok_or_else(|| SpecialError::ArgumentTooLarge("phase overflow in F".into()))?;
        if r > quarter_pi {
            r = r - half_pi.clone();
            q += 1;
        } else if r < -quarter_pi.clone() {
            r = r + half_pi.clone();
            q -= 1;
        }
        let an = (a.clone() + b.clone()) * half.clone();
        b = (a * b).sqrt();
        a = an;
        scale = scale.mul_2si(1);
        if c.abs() <= eps.clone() * a.clone() {
            let phi = half_pi * r.from_i64(q) + r;
            return Ok(phi / (scale * a));
        }
    }
    Err(SpecialError::NoConvergence(format!(
        "AGM phase recursion for F(φ = {}) did not converge",
        show(r0)
    )))
}

/// The ratio of the phase step: `b/a` for even `Q` (`tan φ = tan r`), `a/b` for odd `Q`
/// (`tan φ = −cot r`).
fn step_ratio<R: Real>(q: i64, a: &R, b: &R) -> R {
    if q.rem_euclid(2) == 0 {
        b.clone() / a.clone()
    } else {
        a.clone() / b.clone()
    }
}

/// [`f_agm`] with the residual phase kept as its tangent `t = tan r`: the step
/// `r ← r + atan(ρ tan r)` is `t ← t(1 + ρ)/(1 − ρt²)` (the tangent addition formula),
/// and leaving `[−π/4, π/4]` is `t ← −(1 − ρt²)/(t(1 + ρ))` with `Q ← Q ± 1`.  The new
/// phase lies on the side of `r` (ρ > 0), within `3π/4` of 0, so the two cases are told
/// apart by the signs and sizes of numerator and denominator.  One tangent at the start
/// and one arctangent at the end replace one of each per step, which dominate at high
/// precision (MPFR's arctangent costs about three sin–cos pairs).  Used where the
/// precision is not fixed; `f64` keeps the per-step form.
fn f_agm_tangent<R: Real>(q0: i64, r0: &R, kp: &R) -> Result<R, SpecialError> {
    let one = r0.one();
    let half = r0.from_ratio(1, 2);
    let eps = r0.epsilon();
    let (mut a, mut b, mut t, mut q) = (one.clone(), kp.clone(), r0.tan(), q0);
    let mut scale = one.clone();
    for _ in 0..200 {
        let c = (a.clone() - b.clone()) * half.clone();
        let rho = step_ratio(q, &a, &b);
        let num = t.clone() * (one.clone() + rho.clone());
        let den = one.clone() - rho * t.sqr();
        q = q
            .checked_mul(2)
            .ok_or_else(|| SpecialError::ArgumentTooLarge("phase overflow in F".into()))?;
        // the new phase θ has the sign of t: within [−π/4, π/4] iff den > 0, |num| ≤ den
        if den > num.zero() && num.abs() <= den {
            t = num / den;
        } else {
            // θ − π/2 (θ > 0) or θ + π/2 (θ < 0): tangent −cot θ
            q += if num > num.zero() { 1 } else { -1 };
            t = -(den / num);
        }
        let an = (a.clone() + b.clone()) * half.clone();
        b = (a * b).sqrt();
        a = an;
        scale = scale.mul_2si(1);
        if c.abs() <= eps.clone() * a.clone() {
            let phi = t.pi().mul_2si(-1) * t.from_i64(q) + t.atan();
            return Ok(phi / (scale * a));
        }
    }
    Err(SpecialError::NoConvergence(format!(
        "AGM phase recursion for F(φ = {}) did not converge",
        show(r0)
    )))
}

/// The incomplete elliptic integral of the first kind
/// `F(φ, k) = ∫₀^φ dθ/√(1 − k² sin²θ)` for any real `φ`, **modulus** `k`
/// (mpmath: `ellipf(φ, m=k²)`), `0 ≤ k < 1`.
///
/// Algorithm: `φ = Qπ/2 + r`, `|r| ≤ π/4` (done with `log2|Q|` extra bits; a
/// triple-double π for `f64`), then the quadratically convergent AGM phase recursion
/// (DLMF §19.8(i), Abramowitz–Stegun 17.6) run on the pair `(Q, r)`, so that
/// quasi-periodicity `F(φ + π) = F(φ) + 2K` (DLMF 19.2.10) and the conditioning near
/// `φ = π/2` as `k → 1` are handled without cancellation.
/// Working precision `N + 40 + log2|m|`, one rounding at the end; relative error a
/// few ulp.
///
/// Errors: [`SpecialError::ModulusOutOfRange`], [`SpecialError::NotFinite`],
/// [`SpecialError::ArgumentTooLarge`] for `|φ|/(π/2) ≥ 2⁴⁰`.
///
/// ```
/// use eulertop_numerics::special::{ellipf, ellipk};
/// // mpmath: ellipf(1, m=0.25) = 1.03735612000217729162882159570
/// let f = ellipf(&1.0_f64, &0.5).unwrap();
/// assert!((f - 1.0373561200021773).abs() < 1e-15);
/// // F(π/2 + π) = 3K
/// let kk = ellipk(&0.5_f64).unwrap();
/// let f3 = ellipf(&(1.5 * std::f64::consts::PI), &0.5).unwrap();
/// assert!((f3 - 3.0 * kk).abs() < 1e-14);
/// ```
pub fn ellipf<R: Real>(phi: &R, k: &R) -> Result<R, SpecialError> {
    if R::BY_RULE {
        return R::ellipf_by_rule(phi, k).map_err(SpecialError::Rule);
    }
    check_modulus_below_one(k)?;
    check_finite(phi, "phi")?;
    let n = phi.prec().max(k.prec());
    let ratio = phi.to_f64() / std::f64::consts::FRAC_PI_2;
    if ratio.abs() >= 2f64.powi(40) {
        return Err(SpecialError::ArgumentTooLarge(format!(
            "|phi|/(pi/2) = {:e} >= 2^40",
            ratio.abs()
        )));
    }
    let q = ratio.round() as i64;
    let w = n + GUARD + (64 - q.unsigned_abs().leading_zeros());
    let pw = phi.with_prec(w);
    let kw = k.with_prec(w);
    let kp = complementary(&kw);
    let half_pi = pw.pi().mul_2si(-1);
    let r = if q == 0 {
        pw.clone()
    } else if R::FIXED {
        let t = PI_TRIPLE;
        reduce_dd(&pw, &half_pi, q, [t[0] / 2.0, t[1] / 2.0, t[2] / 2.0])
    } else {
        pw.clone() - pw.from_i64(q) * half_pi
    };
    let f = f_agm(q, &r, &kp)?;
    Ok(f.with_prec(n))
}
