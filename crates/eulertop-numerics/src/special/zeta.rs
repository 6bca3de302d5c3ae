//! Jacobi's zeta function `Z(φ, k)` and Heuman's lambda function `Λ₀(φ, k)`, through
//! Carlson's `R_J`.

use super::agm::{
    TWO_OVER_PI, agm, agm1_dd, complementary, complementary_sqr, inv_quarter_period_dd, modulus_dd,
};
use super::carlson::{rf, rj, rj_dd};
use super::dd::Dd;
use super::phase::{Amplitude, amplitude, fold, sin_cos_amplitude};
use super::{SpecialError, check_finite, check_modulus_below_one, refuse_by_rule};
use crate::numbers::Real;

/// `k² s c Δ R_J(0, k'², 1, Δ²)/3` with `Δ² = c² + k'² s² = 1 − k² s²` for the sine
/// `s` and cosine `c` of the amplitude and their product `sc`,
/// `k² = m` and `k'² = mc`: `Z(φ, k)·K(k)` (DLMF
/// 19.2.33; the form Boost uses).  Zero where `k s c = 0`.  The product and `Δ` are
/// formed in double-double (fixed precision; see [`Dd::value`]), and with `precise`
/// for `f64` also `R_J` ([`rj_dd`], with `Δ²` and `k'²` unrounded, about 2.4 times the
/// cost of Z), so that with `s`, `c` in double-double the result is rounded about once.
fn zeta_times_k<R: Real>(
    (s, c, sc): (&Dd<R>, &Dd<R>, &Dd<R>),
    m: &Dd<R>,
    mc: &Dd<R>,
    precise: bool,
) -> Result<Dd<R>, SpecialError> {
    let d2 = c.sqr().add(&s.sqr().mul(mc));
    let prod = m.mul(sc);
    if prod.hi.is_zero() {
        return Ok(prod);
    }
    let r = &mc.hi;
    let three = Dd::from(r.from_i64(3));
    // f64: R_J in double-double (a Dual's derivative parts need R_J in R itself)
    let j = if precise && R::PLAIN_F64 {
        rj_dd(&Dd::from(r.zero()), mc, &Dd::from(r.one()), &d2)?
    } else {
        Dd::from(rj(&r.zero(), &mc.value(), &r.one(), &d2.value())?)
    };
    Ok(prod.mul(&d2.sqrt()).mul(&j).div(&three))
}

/// Jacobi's zeta function `Z(φ, k) = E(φ, k) − E(k)F(φ, k)/K(k)` (DLMF 19.2.33), **modulus** `k` (Boost: `jacobi_zeta(k, φ)`), `0 ≤ k < 1`, any real
/// `φ`; odd and π-periodic in `φ`.
///
/// Algorithm: `Z(φ, k) = k² sin φ cos φ Δ R_J(0, k'², 1, Δ²)/(3K(k))`,
/// `Δ² = 1 − k² sin²φ` (the form Boost uses; the tests check it against the definition),
/// a product with no cancellation; `sin φ`, `cos φ` from the reduced amplitude
/// `φ = Qπ/2 + r`, `R_J` by duplication (DLMF 19.36.2), `1/K = 2 AGM(1, k')/π` (DLMF 19.8.5).  In `f64`
/// `sin φ`, `cos φ` (Taylor series of `r` in double-double), `R_J`, the product and
/// the AGM are formed in double-double and rounded once (within 0.5 ε on Boost's and
/// mpmath's tables).  Working precision `N + 40 + log2|Q|`.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k < 1`,
/// [`SpecialError::NotFinite`], [`SpecialError::ArgumentTooLarge`] for
/// `|φ|/(π/2) ≥ 2⁴⁰`.
///
/// ```
/// use eulertop_numerics::special::{ellipe, ellipeinc, ellipf, ellipk, jacobizeta};
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
    // sin φ, cos φ in double-double (f64: from φ − Qπ/2 in double-double, to about
    // 2⁻⁵⁷), and s·c from the same s, c as Δ (their errors partly cancel in s·Δ as k → 1)
    let (s, c) = sin_cos_amplitude(&phi.with_prec(a.w), &a);
    let sc = s.mul(&c);
    let k2 = Dd::from(kw.clone()).sqr();
    let kp2 = Dd::from(kw.one()).add(&k2.neg());
    let zk = zeta_times_k((&s, &c, &sc), &k2, &kp2, true)?;
    let inv_k = inv_quarter_period_dd(&kw)?;
    Ok(zk.mul(&inv_k).value().with_prec(n))
}

/// Heuman's lambda function
/// `Λ₀(φ, k) = F(φ, k')/K(k') + (2/π) K(k) Z(φ, k')` (DLMF 19.2.32; Boost:
/// `heuman_lambda(k, φ)`), **modulus** `k`, `0 ≤ k < 1`, any real `φ`
/// (`Λ₀(φ + π) = Λ₀(φ) + 2`, `Λ₀(π/2, k) = 1`).
///
/// Algorithm: `Λ₀(φ) = c + σΛ₀(θ)` for `φ = Qπ/2 + r` folded to `θ ∈ [−π/4, π/2]`
/// (`Λ₀(φ + π) = Λ₀(φ) + 2`, `Λ₀` odd, `Λ₀(π/2) = 1`), and with `k'` never rounded
/// (the integrals of modulus `k'` take their complementary modulus `k` directly:
/// `F(θ, k') = sin θ R_F(cos²θ, Δ'², 1)`, `K(k') = π/(2 AGM(1, k))`),
/// `Λ₀(θ) = (F(θ, k') + k'² sin θ cos θ Δ' R_J(0, k², 1, Δ'²)/(3 AGM(1, k')))/K(k')`,
/// `Δ'² = cos²θ + k² sin²θ`, a sum of terms of one sign.  In `f64` the products, the
/// sums and both AGMs are formed in double-double and rounded once.  At `k = 0`,
/// `Λ₀(φ, 0) = 2j + sin(φ − jπ)` for `j` the integer nearest `φ/π`.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k < 1`,
/// [`SpecialError::NotFinite`], [`SpecialError::ArgumentTooLarge`] for
/// `|φ|/(π/2) ≥ 2⁴⁰`.
///
/// ```
/// use eulertop_numerics::special::heumanlambda;
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
    // k = 0, or in fixed precision k² below the smallest normal number, where
    // Λ₀(θ, k) = sin θ + O(k² ln(1/k)) is sin θ to the last bit (and k² would be lost)
    if kw.is_zero() || (R::FIXED && kw.to_f64() < 1e-154) {
        // Λ₀(·, 0) is odd, Λ₀(π/2, 0) = 1 and Λ₀(θ, 0) = sin θ on [−π/2, π/2]
        let (whole, sigma, st, _) = fold(q, &r);
        let lam = r.from_i64(whole) + r.from_i64(sigma) * st;
        return Ok(lam.with_prec(n));
    }
    // Λ₀(φ) = whole + σ Λ₀(θ), θ ∈ [−π/4, π/2], from Λ₀(φ + π) = Λ₀(φ) + 2, the
    // oddness and Λ₀(π/2) = 1: a sum formed in double-double, no 2K − F to cancel
    let (whole, sigma, st, ct) = fold_sin_cos(q, &r);
    let kp2 = complementary_sqr(&kw);
    let k2 = Dd::from(kw.clone()).sqr().value();
    let c2 = Dd::from(ct.clone()).sqr();
    let d2 = Dd::from(st.clone()).sqr().mul_r(&k2).add(&c2).value();
    // F(θ, k') = s R_F(c², Δ'², 1), Δ'² = c² + k² s² (k' is never rounded)
    let f = Dd::from(rf(&c2.value(), &d2, &kw.one())?).mul_r(&st);
    // sin θ cos θ = sin(2|r|)/2 for odd Q (θ = π/2 − |r|), sin(2r)/2 for even Q
    let sc = half_sin_double(&if q.rem_euclid(2) == 0 {
        r.clone()
    } else {
        r.abs()
    });
    let sc = Dd::from(sc);
    let (st, ct) = (Dd::from(st), Dd::from(ct));
    // R_J in f64: Λ₀ is within 2 ε so (its F(θ, k') is in f64 too), at a quarter of the
    // cost of the double-double R_J (small k: many duplication steps)
    let zk = zeta_times_k(
        (&st, &ct, &sc),
        &Dd::from(kp2),
        &Dd::from(k2.clone()),
        false,
    )?;
    let (a, a_c) = agm_pair(&kw)?;
    // (F + Z·K(k')/AGM(1, k')) / K(k'), 1/K(k') = 2 AGM(1, k)/π
    let two_pi = if R::FIXED {
        Dd {
            hi: kw.from_f64(TWO_OVER_PI.0),
            lo: TWO_OVER_PI.1,
        }
    } else {
        Dd::from(kw.pi().recip().mul_2si(1))
    };
    let lam = zk.div(&a).add(&f).mul(&a_c).mul(&two_pi);
    let lam = lam.mul_r(&r.from_i64(sigma)).add_r(&r.from_i64(whole));
    Ok(lam.value().with_prec(n))
}

/// `sin(2r)/2` (`2r` is exact), rounded once where `sin r · cos r` is rounded three times.
fn half_sin_double<R: Real>(r: &R) -> R {
    r.mul_2si(1).sin().mul_2si(-1)
}

/// As `phase::fold`, with `cos θ ≥ 0` itself instead of its square: `(c, σ, sin θ,
/// cos θ)` with `φ = Qπ/2 + r`, `G(φ) = c·G(π/2) + σ·G(θ)`, `θ ∈ [−π/4, π/2]`.
fn fold_sin_cos<R: Real>(q: i64, r: &R) -> (i64, i64, R, R) {
    let (s, c) = r.sin_cos();
    if q.rem_euclid(2) == 0 {
        return (q, 1, s, c);
    }
    let sigma = if *r < r.zero() { -1 } else { 1 };
    (q + sigma, -sigma, c, s.abs())
}

/// `(AGM(1, k'), AGM(1, k))` for `0 < k < 1`: in double-double for the fixed-precision
/// types ([`agm1_dd`] of the modulus and of its complement), else by [`agm`].
fn agm_pair<R: Real>(k: &R) -> Result<(Dd<R>, Dd<R>), SpecialError> {
    if !R::FIXED {
        let one = k.one();
        let a = agm(&one, &complementary(k))?;
        return Ok((Dd::from(a), Dd::from(agm(&one, k)?)));
    }
    let (m, mc) = modulus_dd(k);
    if m.v() < 1e-290 {
        // k² (nearly) underflows: AGM(1, k) plainly (the theta data need κ'² > 0)
        return Ok((agm1_dd(&m, &mc), Dd::from(agm(&k.one(), k)?)));
    }
    Ok((agm1_dd(&m, &mc), agm1_dd(&mc, &m)))
}
