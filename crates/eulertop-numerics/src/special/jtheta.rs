//! The nome `q(k)` and the Jacobi theta functions `θ_j(z, q)`, `j = 1 … 4`, of a real
//! argument and real nome.

use super::agm::complementary;
use super::carlson::sqrt0;
use super::phase::residual;
use super::{GUARD, SpecialError, check_finite, check_modulus_below_one, refuse_by_rule, show};
use crate::numbers::Real;

/// Most terms summed by [`jtheta`] (a bound that is never reached: the direct series
/// runs for `q ≤ 1/4`, the transformed one converges faster as `q → 1`).
const MAX_TERMS: i64 = 1_000_000;

/// `q(k)` from Jacobi's series `q = ε + 2ε⁵ + 15ε⁹ + 150ε¹³ + 1707ε¹⁷ + 20910ε²¹ +
/// 268616ε²⁵` in `ε = (1 − √k')/(2(1 + √k')) = k²/(2(1 + k')(1 + √k')²)`
/// (Abramowitz–Stegun 17.3.21), after `N` descending Landen steps
/// `k ← k²/(1 + k')²`, `k' ← 2√k'/(1 + k')` (DLMF 19.8.12), each of which squares the
/// nome, so `q(k) = q(k_N)^(2^−N)`; the steps go on until the first omitted term is
/// below the working epsilon.
fn nome_landen<R: Real>(k: &R) -> R {
    let one = k.one();
    let limit = one.mul_2si(-(k.prec() as i32 + 52) / 28);
    let (mut kk, mut kp) = (k.clone(), complementary(k));
    let mut steps = 0;
    let eps = loop {
        let skp = kp.sqrt();
        let e =
            kk.sqr() / ((one.clone() + kp.clone()) * (one.clone() + skp.clone()).sqr()).mul_2si(1);
        if e <= limit || steps >= 64 {
            break e;
        }
        let den = one.clone() + kp.clone();
        kk = kk.sqr() / den.sqr();
        kp = skp.mul_2si(1) / den;
        steps += 1;
    };
    let e4 = eps.sqr().sqr();
    let mut poly = k.zero();
    for c in [268_616, 20_910, 1_707, 150, 15, 2, 1] {
        poly = poly * e4.clone() + k.from_i64(c);
    }
    let mut q = eps * poly;
    for _ in 0..steps {
        q = q.sqrt();
    }
    q
}

/// The nome `q(k) = exp(−π K'(k)/K(k))` (DLMF 22.2.1), **modulus** `k`, `0 ≤ k < 1`
/// (mpmath: `qfrom(m = k²)`).
///
/// Algorithm: Jacobi's series `q = ε + 2ε⁵ + 15ε⁹ + …` in
/// `ε = (1 − √k')/(2(1 + √k'))` (Abramowitz–Stegun 17.3.21), with `ε` formed as
/// `k²/(2(1 + k')(1 + √k')²)` without cancellation, after as many descending Landen
/// steps (DLMF 19.8.12; each squares the nome) as make the omitted terms negligible;
/// then `q` is the `2^N`-th root.  Relative accuracy for every `k`, also as `k → 0`
/// (`q ≈ k²/16`), where `exp(−πK'/K)` would amplify the error of `K'/K` by
/// `πK'/K ≈ ln(16/k²)`.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k < 1`.
///
/// ```
/// use eulertop_numerics::special::nome;
/// // mpmath: qfrom(m=0.25) = 0.0179723870089672399988196929490
/// let q = nome(&0.5_f64).unwrap();
/// assert!((q - 0.01797238700896724).abs() < 1e-17);
/// assert_eq!(nome(&0.0_f64).unwrap(), 0.0);
/// ```
pub fn nome<R: Real>(k: &R) -> Result<R, SpecialError> {
    refuse_by_rule::<R>("the nome")?;
    check_modulus_below_one(k)?;
    let n = k.prec();
    Ok(nome_landen(&k.with_prec(n + GUARD)).with_prec(n))
}

/// Checks the index and the nome of [`jtheta`].
fn check_theta<R: Real>(j: u32, q: &R) -> Result<(), SpecialError> {
    if !(1..=4).contains(&j) {
        return Err(SpecialError::Domain(format!(
            "theta function index j = {j} is not 1, 2, 3 or 4"
        )));
    }
    check_finite(q, "q")?;
    let lower = if j <= 2 { q.zero() } else { -q.one() };
    let closed = j <= 2;
    if (closed && *q < lower) || (!closed && *q <= lower) || *q >= q.one() {
        let range = if closed { "[0, 1)" } else { "(-1, 1)" };
        return Err(SpecialError::Domain(format!(
            "nome q = {} is outside {range} for theta_{j}",
            show(q)
        )));
    }
    Ok(())
}

/// Above this nome the theta functions are summed after Jacobi's imaginary
/// transformation (nome `exp(−π²/ln(1/q)) < 10⁻³`).
const TRANSFORM_ABOVE: f64 = 0.25;

/// The direct series (DLMF 20.2.1–4) after the factor `2q^{1/4}` (`odd`: θ₁, θ₂) or as
/// `Σ_{n≥1}` (θ₃, θ₄): `Σ_{n≥0} (∓1)ⁿ q^{n²+n} (sin, cos)((2n+1)θ)` or
/// `Σ_{n≥1} (∓1)ⁿ q^{n²} cos 2nθ`, the sign alternating when `alt`; angles by rotation,
/// powers of `q` by `q^{(n+1)²} = q^{n²} q^{2n+1}`.
fn series<R: Real>(
    theta: &R,
    q: &R,
    odd: bool,
    cosine: bool,
    alt: bool,
) -> Result<R, SpecialError> {
    let eps = theta.epsilon().mul_2si(-3);
    let (s1, c1) = theta.sin_cos();
    let (s2, c2) = theta.mul_2si(1).sin_cos();
    let (mut s, mut c) = if odd {
        (s1, c1)
    } else {
        (s2.clone(), c2.clone())
    };
    let q2 = q.sqr();
    let (mut w, mut step) = if odd {
        (q.one(), q2.clone())
    } else {
        (q.clone(), q.clone() * q2.clone())
    };
    let mut sum = q.zero();
    let flip = if alt { -q.one() } else { q.one() };
    let mut sign = if odd { q.one() } else { flip.clone() };
    for _ in 0..MAX_TERMS {
        let trig = if odd && !cosine { s.clone() } else { c.clone() };
        sum = sum + sign.clone() * w.clone() * trig;
        w = w * step.clone();
        step = step * q2.clone();
        if w.abs() <= eps {
            return Ok(sum);
        }
        (s, c) = (
            s.clone() * c2.clone() + c.clone() * s2.clone(),
            c * c2.clone() - s * s2.clone(),
        );
        sign = sign * flip.clone();
    }
    Err(SpecialError::NoConvergence(format!(
        "theta series: nome q = {} too close to 1",
        show(q)
    )))
}

/// `θ_j(θ, q)` for `|θ| ≤ π/2`, `1/4 < q < 1`, by Jacobi's imaginary transformation
/// (DLMF 20.7.30–33) written as Gaussian sums: with `t = ln(1/q)/π`, `c = πt` and
/// `g(x) = exp(−x²/c)`, `θ₃ = t^{−1/2} Σ_{n∈ℤ} g(θ + nπ)`,
/// `θ₂ = t^{−1/2} Σ (−1)ⁿ g(θ + nπ)`, `θ₄ = t^{−1/2} Σ g(θ + (n+½)π)`,
/// `θ₁ = t^{−1/2} Σ (−1)ⁿ (g((n+½)π − θ) − g((n+½)π + θ))` (`n ≥ 0`).  The pairs that
/// cancel at the zeros (θ₁ at 0, θ₂ at ±π/2) are formed with `expm1`, the distance
/// `π/2 − |θ|` from the accurate reduction.
fn transformed<R: Real>(j: u32, theta: &R, q: &R) -> Result<R, SpecialError> {
    let t = -q.ln() / q.pi();
    let c = q.pi() * t.clone();
    let g = |x: &R| (-(x.sqr()) / c.clone()).exp();
    let pi = q.pi();
    let half_pi = pi.mul_2si(-1);
    let x = theta.abs();
    let eps = q.epsilon().mul_2si(-4);
    let mut sum = match j {
        1 | 4 => q.zero(),
        2 => {
            // g(θ) − g(π − |θ|) = g(θ)(1 − exp(−π(π − 2|θ|)/c))
            let gap = -residual(&x, 1).mul_2si(1);
            -(g(&x) * (-(pi.clone() * gap) / c.clone()).exp_m1()) - g(&(pi.clone() + x.clone()))
        }
        _ => g(&x),
    };
    let first: i64 = if j == 2 {
        2
    } else if j == 3 {
        1
    } else {
        0
    };
    for n in first..MAX_TERMS {
        let centre = if j == 2 || j == 3 {
            pi.clone() * q.from_i64(n)
        } else {
            pi.clone() * q.from_i64(n) + half_pi.clone()
        };
        let near = g(&(centre.clone() - x.clone()));
        let term = if j == 1 {
            // g(a − x) − g(a + x) = g(a − x)(1 − exp(−4ax/c))
            -(near.clone() * (-(centre.clone() * x.clone()).mul_2si(2) / c.clone()).exp_m1())
        } else {
            near.clone() + g(&(centre + x.clone()))
        };
        let alternating = (j == 1 || j == 2) && n % 2 == 1;
        sum = if alternating { sum - term } else { sum + term };
        if near <= eps.clone() * sum.abs() || near.is_zero() {
            let v = sum / t.sqrt();
            return Ok(if j == 1 && *theta < theta.zero() {
                -v
            } else {
                v
            });
        }
    }
    Err(SpecialError::NoConvergence(format!(
        "theta series: nome q = {} too close to 1",
        show(q)
    )))
}

/// The Jacobi theta function `θ_j(z, q)`, `j = 1, 2, 3, 4`, of real `z` and real nome
/// `q` (DLMF 20.2.1–4; mpmath: `jtheta(j, z, q)`):
/// `θ₁ = 2Σ_{n≥0} (−1)ⁿ q^{(n+½)²} sin(2n+1)z`, `θ₂ = 2Σ_{n≥0} q^{(n+½)²} cos(2n+1)z`,
/// `θ₃ = 1 + 2Σ_{n≥1} q^{n²} cos 2nz`, `θ₄ = 1 + 2Σ_{n≥1} (−1)ⁿ q^{n²} cos 2nz`;
/// `0 ≤ q < 1` for `j = 1, 2` (`q^{1/4}` real), `−1 < q < 1` for `j = 3, 4`.
///
/// Algorithm: `z = mπ + θ`, `|θ| ≤ π/2` (DLMF 20.2.6–8: `θ₁`, `θ₂` change sign with
/// odd `m`), reduced as the elliptic integrals' amplitude; a negative nome by
/// `θ₃(z, −q) = θ₄(z, q)`.  For `q ≤ 1/4` the series, with the angles `(2n+1)θ`, `2nθ`
/// by rotation and the powers of `q` by products, until the weight is below the working
/// epsilon (about `√(N ln 2/ln(1/q))` terms); above, Jacobi's imaginary transformation
/// (DLMF 20.7.30–33) as Gaussian sums `t^{−1/2} Σ ± exp(−(θ + nπ/2)²/(πt))`,
/// `t = ln(1/q)/π`, whose terms are positive or paired without cancellation (`expm1`)
/// at the zeros, and which converge the faster the closer `q` is to 1.  Working
/// precision `N + 40 + log2|m|`.  In `f64` the error grows with the size of the
/// exponents `(θ + nπ/2)²/(πt)` as `q → 1` (about 15 ε at `q = 0.9`, where the values
/// are `10⁻⁸`; see `reports/accuracy.md`).
///
/// Errors: [`SpecialError::Domain`] for `j ∉ {1, 2, 3, 4}` or `q` outside the ranges
/// above; [`SpecialError::NotFinite`]; [`SpecialError::ArgumentTooLarge`] for
/// `|z|/π ≥ 2³⁹`.
///
/// ```
/// use eulertop_numerics::special::jtheta;
/// // mpmath: jtheta(3, 0.5, 0.1) = 1.10797722982633339705325175845
/// let t3 = jtheta(3, &0.5_f64, &0.1).unwrap();
/// assert!((t3 - 1.1079772298263334).abs() < 1e-15);
/// // θ₁(z + π) = −θ₁(z)
/// let a = jtheta(1, &0.5_f64, &0.3).unwrap();
/// let b = jtheta(1, &(0.5 + std::f64::consts::PI), &0.3).unwrap();
/// assert!((a + b).abs() < 1e-15);
/// assert!(jtheta(5, &0.5_f64, &0.1).is_err());
/// ```
pub fn jtheta<R: Real>(j: u32, z: &R, q: &R) -> Result<R, SpecialError> {
    refuse_by_rule::<R>("theta functions")?;
    check_theta(j, q)?;
    check_finite(z, "z")?;
    let ratio = z.to_f64() / std::f64::consts::PI;
    if ratio.abs() >= 2f64.powi(39) {
        return Err(SpecialError::ArgumentTooLarge(format!(
            "|z|/pi = {:e} >= 2^39",
            ratio.abs()
        )));
    }
    let m = ratio.round() as i64;
    let n = z.prec().max(q.prec());
    let w = n + GUARD + (64 - m.unsigned_abs().leading_zeros());
    let (zw, qw) = (z.with_prec(w), q.with_prec(w));
    let theta = residual(&zw, 2 * m);
    let one = qw.one();
    // θ₃(z, −q) = θ₄(z, q) and θ₄(z, −q) = θ₃(z, q) ((−1)^{n²} = (−1)ⁿ)
    let (j, qw) = if qw < qw.zero() {
        (7 - j, -qw)
    } else {
        (j, qw)
    };
    let flip = j <= 2 && m.rem_euclid(2) == 1;
    let v = if qw.to_f64() > TRANSFORM_ABOVE {
        transformed(j, &theta, &qw)?
    } else if j <= 2 {
        sqrt0(&sqrt0(&qw)).mul_2si(1) * series(&theta, &qw, true, j == 2, j == 1)?
    } else {
        one + series(&theta, &qw, false, true, j == 4)?.mul_2si(1)
    };
    let v = if flip { -v } else { v };
    Ok(v.with_prec(n))
}
