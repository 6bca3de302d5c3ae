//! Phase steps: `Δφ = (φ̂ − φ)/2`, `φ̄ = (φ + φ̂)/2` (phis) of a computed step, and
//! the predicted `δ` solving (master12) with (alphas) for γ₁, γ₂ and `δ_VM` solving
//! (MV master) with (MV alphabeta), at working precision.
//!
//! Both equations are solved in the denominator-free form
//! `sn(1 − α sn²) − (hν/2) cn dn = 0` (master12) and
//! `sn cn dn − (hν/2)(1 + α sn² − β sn⁴) = 0` (MV master) by Newton's method in
//! `Δφ` started at `hν/2`, with the derivative from [`Dual`] numbers; the iteration
//! stops when the update stalls and errors ([`ModelError::NewtonFailed`]) after 200
//! iterations or if the iterate leaves `(0, K)`.
//!
//! Above [`LADDER_BITS`](super::ladder::LADDER_BITS) bits the iteration starts instead
//! at the solution at about half the precision (module [`ladder`](super::ladder)): two
//! full-precision steps instead of nine at 4096 bits.

use super::discretization::Gamma;
use super::elliptic_coords::{EllCoords, phi_near, quarter_period, sncndn_params};
use super::ladder::{AtPrec, ladder};
use super::params::EllipticParams;
use super::{Inertia, ModelError};
use crate::linalg::Vec3;
use crate::numbers::{Dual, Real, Scalar};

/// `(φ̄, Δφ)` (phis) of a step `M ↦ M̂`, with `φ̂` unwrapped next to `φ`.
pub fn step_phases<R: Real>(
    inertia: &Inertia<R>,
    m: &Vec3<R>,
    mhat: &Vec3<R>,
) -> Result<(EllCoords<R>, R, R), ModelError> {
    let c = super::elliptic_coords::m_to_phi(inertia, m)?;
    let ch = phi_near(inertia, mhat, &c.phi)?;
    let half = c.phi.from_ratio(1, 2);
    let bar = (c.phi.clone() + ch.phi.clone()) * half.clone();
    let delta = (ch.phi - c.phi.clone()) * half;
    Ok((c, bar, delta))
}

fn solve_phase<R: Real, F>(
    p: &EllipticParams<R>,
    h: &R,
    start: Option<R>,
    what: &str,
    f: F,
) -> Result<R, ModelError>
where
    F: Fn(&Dual<R>, &Dual<R>, &Dual<R>) -> Dual<R>,
{
    if h.is_zero() {
        return Ok(h.zero());
    }
    let mut x = start.unwrap_or_else(|| h.clone() * p.nu() / h.from_i64(2));
    let kq = quarter_period(p)?;
    let eps = h.epsilon();
    let mut prev: Option<R> = None;
    for it in 0..200 {
        let (sn, cn, dn) = sncndn_var(&x, p)?;
        let v = f(&sn, &cn, &dn);
        if v.d.is_zero() || !v.d.is_finite() {
            break;
        }
        let dx = v.v / v.d;
        x = x - dx.clone();
        let bad = x <= x.zero() || kq.as_ref().is_some_and(|k| x >= *k) || !x.is_finite();
        if bad {
            return Err(ModelError::NewtonFailed {
                what: what.into(),
                iterations: it + 1,
                residual: f64::NAN,
            });
        }
        let dn_ = dx.abs();
        if dn_ <= eps.clone() * x.abs() {
            return Ok(x);
        }
        if let Some(pv) = &prev
            && dn_ >= *pv
            && dn_ <= eps.sqrt() * x.abs()
        {
            return Ok(x);
        }
        prev = Some(dn_);
    }
    Err(ModelError::NewtonFailed {
        what: what.into(),
        iterations: 200,
        residual: f64::NAN,
    })
}

/// `(sn, cn, dn)` as dual numbers.
type DualTriple<R> = (Dual<R>, Dual<R>, Dual<R>);

/// `(sn, cn, dn)` at the phase `x` as [`Dual`] numbers with derivative along `x`
/// (DLMF 22.13.1–3: `sn' = cn dn`, `cn' = −sn dn`, `dn' = −k² sn cn`; on the separatrix
/// `k = 1` and these are the derivatives of tanh and sech): the functions are
/// evaluated once, at the value, rather than through the dual numbers.
fn sncndn_var<R: Real>(x: &R, p: &EllipticParams<R>) -> Result<DualTriple<R>, ModelError> {
    let (sn, cn, dn) = sncndn_params(x, p)?;
    let k2 = match p.regime {
        super::Regime::Separatrix => x.one(),
        _ => p.k2.clone(),
    };
    let d_sn = cn.clone() * dn.clone();
    let d_cn = -(sn.clone() * dn.clone());
    let d_dn = -(k2 * sn.clone() * cn.clone());
    Ok((
        Dual::new(sn, d_sn),
        Dual::new(cn, d_cn),
        Dual::new(dn, d_dn),
    ))
}

/// `δ` solving (master12) `sn/(cn dn) = (hν/2)/(1 − α sn²)` for a given `α`
/// (use [`EllipticParams::alpha1`] or [`EllipticParams::alpha2`], (alphas)); for
/// `h ≥ 0` (negative `h` → [`ModelError::NewtonFailed`]; use [`delta`]).
pub fn delta_master12<R: Real>(p: &EllipticParams<R>, alpha: &R, h: &R) -> Result<R, ModelError> {
    let start = ladder(h, |q| {
        delta_master12(&p.at_prec(q), &alpha.at_prec(q), &h.at_prec(q))
    });
    let hn = Dual::constant(h.clone() * p.nu() / h.from_i64(2));
    let al = Dual::constant(alpha.clone());
    solve_phase(p, h, start, "(master12)", |sn, cn, dn| {
        master12_equation(&al, &hn, sn, cn, dn)
    })
}

/// (master12) in the denominator-free form `sn(1 − α sn²) − (hν/2) cn dn`, with
/// `hnu2 = hν/2` and `sn`, `cn`, `dn` of the phase step: the equation that
/// [`delta_master12`] solves, and that the prover uses as the definition of `δ`.
pub fn master12_equation<S: Scalar>(alpha: &S, hnu2: &S, sn: &S, cn: &S, dn: &S) -> S {
    sn.clone() * (sn.one() - alpha.clone() * sn.sqr()) - hnu2.clone() * cn.clone() * dn.clone()
}

/// (MV master) in the form `sn cn dn − (hν/2)(1 + α sn² − β sn⁴)`, with `hnu2 = hν/2`
/// and (α, β) from (MV alphabeta): the equation that [`delta_vm`] solves.
pub fn mv_master_equation<S: Scalar>(alpha: &S, beta: &S, hnu2: &S, sn: &S, cn: &S, dn: &S) -> S {
    let s2 = sn.sqr();
    sn.clone() * cn.clone() * dn.clone()
        - hnu2.clone() * (sn.one() + alpha.clone() * s2.clone() - beta.clone() * s2.sqr())
}

/// `δ_VM` solving (MV master) `sn cn dn = (hν/2)(1 + α sn² − β sn⁴)` with (α, β)
/// from (MV alphabeta), for `h ≥ 0`.  Errors on the separatrix (no printed α, β).
pub fn delta_vm<R: Real>(
    inertia: &Inertia<R>,
    p: &EllipticParams<R>,
    h: &R,
) -> Result<R, ModelError> {
    let (a, b) = p.alpha_beta_vm(inertia).ok_or_else(|| {
        ModelError::Undefined("(MV alphabeta) is not given on the separatrix E/M^2 = 1/B".into())
    })?;
    let start = ladder(h, |q| {
        delta_vm(&inertia.at_prec(q), &p.at_prec(q), &h.at_prec(q))
    });
    let hn = Dual::constant(h.clone() * p.nu() / h.from_i64(2));
    let (a, b) = (Dual::constant(a), Dual::constant(b));
    solve_phase(p, h, start, "(MV master)", |sn, cn, dn| {
        mv_master_equation(&a, &b, &hn, sn, cn, dn)
    })
}

/// The predicted `φ̄`-independent phase step `δ(M², E, h)` of (phi indep) for γ₁, γ₂
/// (master12) and γ_VM (MV master); γ₀ has none (it is not Poisson) → error.
///
/// For `h < 0` the equations are odd in `(Δφ, h)`, and `δ(−h) = −δ(h)` is returned.
pub fn delta<R: Real>(
    inertia: &Inertia<R>,
    p: &EllipticParams<R>,
    gamma: Gamma,
    h: &R,
) -> Result<R, ModelError> {
    if *h < h.zero() {
        return Ok(-delta(inertia, p, gamma, &-h.clone())?);
    }
    match gamma {
        Gamma::G0 => Err(ModelError::Undefined(
            "gamma0 has no phi-independent phase step delta".into(),
        )),
        Gamma::G1 => delta_master12(p, &p.alpha1(), h),
        Gamma::G2 => delta_master12(p, &p.alpha2(inertia), h),
        Gamma::Vm => delta_vm(inertia, p, h),
    }
}
