//! The numerical experiments behind the model figures of the report, as data (drawing
//! is the report layer's business):
//!
//! * [`phase_curves`]: the phase step `Δφ = (φ̂ − φ)/2` against `φ̄ = (φ + φ̂)/2`
//!   (phis) of one step of (impl spec) from start points covering a full period `4K` of
//!   `φ`, for γ₀, γ₁, γ₂ and γ_VM at several `h`, with the predicted `δ` of (master12) /
//!   (MV master).  For the Poisson maps γ₁, γ₂, γ_VM the curves are flat
//!   (φ-independence (phi indep)); γ₀ (Section 7) varies with `φ̄`.
//! * [`orbit_comparison`]: the continuous solution (sol) against the iterates of
//!   (discr eq) and the discrete solution (discr sol) `Φ(M², E, 2mδ + φ₀)`, for γ_VM and
//!   γ₁ with a large `h`, so that the phase drift between continuous and discrete motion
//!   is visible.
//! * [`fitted_orders`]: `‖M_N − M(T)‖∞` at `T = N h` fixed against `h`, for the four γ in
//!   both regimes, with the least-squares log–log slope (the measured order).
//!
//! All inputs are fixed (inertia `A, B, C = 3, 2, 1`, one start point per regime) and all
//! arithmetic is f64, so the results are identical across runs.

use super::discretization::{inf_norm, step};
use super::elliptic_coords::{m_to_phi, phi_to_m, quarter_period};
use super::phase::{delta, step_phases};
use super::solution::{continuous_from, discrete_from};
use super::{EllipticParams, Gamma, Inertia, ModelError, Regime, Sector, orbit};
use crate::linalg::Vec3;

/// The four γ of (impl spec), in the order drawn.
pub const GAMMAS: [Gamma; 4] = [Gamma::G0, Gamma::G1, Gamma::G2, Gamma::Vm];

/// The moments of inertia `(A, B, C)` of every experiment.
pub const INERTIA: (f64, f64, f64) = (3.0, 2.0, 1.0);

/// Step sizes of the `Δφ` experiment.
pub const PHASE_H: [f64; 3] = [0.05, 0.1, 0.2];

/// Number of start points per period `4K` in the `Δφ` experiment.
pub const PHASE_GRID: usize = 64;

/// The fixed time `T` of the order experiment.
pub const ORDER_T: f64 = 2.0;

/// Step counts `N` of the order experiment (`h = T/N`).
pub const ORDER_N: [usize; 7] = [10, 20, 40, 80, 160, 320, 640];

/// Step size of the orbit comparison.
pub const ORBIT_H: f64 = 0.3;

/// Samples of the continuous solution in the orbit comparison (plus the end point).
pub const ORBIT_SAMPLES: usize = 600;

/// A start point, named by its regime.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Case {
    /// `"upper"` (`E/M² > 1/B`) or `"lower"` (`E/M² < 1/B`).
    pub name: &'static str,
    /// The regime the start point lies in.
    pub regime: Regime,
    /// The start point `M₀`.
    pub point: [f64; 3],
}

/// The two start points: `(0.3, −0.7, 1.1)` (upper regime, `E/M² ≈ 0.83 > 1/B`) and
/// `(1.1, −0.7, 0.3)` (lower regime, `E/M² ≈ 0.41 < 1/B`), for [`INERTIA`].
pub const CASES: [Case; 2] = [
    Case {
        name: "upper",
        regime: Regime::Upper,
        point: [0.3, -0.7, 1.1],
    },
    Case {
        name: "lower",
        regime: Regime::Lower,
        point: [1.1, -0.7, 0.3],
    },
];

impl Case {
    /// The start point as a vector.
    pub fn start(&self) -> Vec3<f64> {
        Vec3::new(self.point[0], self.point[1], self.point[2])
    }
}

/// The inertia [`INERTIA`] as a validated [`Inertia`].
pub fn inertia() -> Result<Inertia<f64>, ModelError> {
    Inertia::new(INERTIA.0, INERTIA.1, INERTIA.2)
}

/// The invariants and parameters of a case: `(params, sector, K)`.
pub fn case_params(
    i: &Inertia<f64>,
    case: &Case,
) -> Result<(EllipticParams<f64>, Sector, f64), ModelError> {
    let c = m_to_phi(i, &case.start())?;
    let k = quarter_period(&c.params)?.ok_or_else(|| {
        ModelError::Undefined(format!("case {}: start point on the separatrix", case.name))
    })?;
    Ok((c.params, c.sector, k))
}

/// `(min, max)` of the values (`(∞, −∞)` when empty).
pub fn min_max(it: impl Iterator<Item = f64>) -> (f64, f64) {
    it.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    })
}

/// `Δφ` against `φ̄` for one γ and one `h` over a full period.
#[derive(Clone, Debug, PartialEq)]
pub struct PhaseCurve {
    /// γ.
    pub gamma: Gamma,
    /// Step size.
    pub h: f64,
    /// `hν/2`, the leading-order phase step (the normalization of the figure).
    pub half_h_nu: f64,
    /// `(φ̄, Δφ)` (phis) for start points `φ = −2K + 4K(j + ½)/N`, sorted by `φ̄`.
    pub points: Vec<(f64, f64)>,
    /// The predicted `δ` of (master12) / (MV master); `None` for γ₀.
    pub predicted: Option<f64>,
}

impl PhaseCurve {
    /// `max Δφ − min Δφ` over the curve.
    pub fn spread(&self) -> f64 {
        let (lo, hi) = min_max(self.points.iter().map(|p| p.1));
        hi - lo
    }
}

/// The `Δφ`-against-`φ̄` curves of a case: for each γ in [`GAMMAS`] and `h` in
/// [`PHASE_H`], one step of (impl spec) from each of [`PHASE_GRID`] points
/// `Φ(M², E, φ)` of the case's level set, `φ = −2K + 4K(j + ½)/N`, then (phis) by
/// [`step_phases`].
pub fn phase_curves(case: &Case) -> Result<Vec<PhaseCurve>, ModelError> {
    let i = inertia()?;
    let (p, sector, k) = case_params(&i, case)?;
    let nu = p.nu();
    let mut out = Vec::new();
    for gamma in GAMMAS {
        for h in PHASE_H {
            let mut points = Vec::with_capacity(PHASE_GRID);
            for j in 0..PHASE_GRID {
                let phi = -2.0 * k + 4.0 * k * (j as f64 + 0.5) / PHASE_GRID as f64;
                let m = phi_to_m(&p, sector, &phi)?;
                let mh = step(&i, gamma, &m, &h)?;
                let (_, bar, dphi) = step_phases(&i, &m, &mh)?;
                points.push((bar, dphi));
            }
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            let predicted = match gamma {
                Gamma::G0 => None,
                _ => Some(delta(&i, &p, gamma, &h)?),
            };
            out.push(PhaseCurve {
                gamma,
                h,
                half_h_nu: h * nu / 2.0,
                points,
                predicted,
            });
        }
    }
    Ok(out)
}

/// `‖M_n − exact‖∞` after `n` steps of `gamma` with step size `h` from `m0`.
fn error_after(
    i: &Inertia<f64>,
    gamma: Gamma,
    m0: &Vec3<f64>,
    h: f64,
    n: usize,
    exact: &Vec3<f64>,
) -> Result<f64, ModelError> {
    let mut m = m0.clone();
    for p in orbit(i, gamma, m0, &h).take(n) {
        m = p?;
    }
    Ok(inf_norm(&(m - exact.clone())))
}

/// One discrete motion of the orbit comparison.
#[derive(Clone, Debug, PartialEq)]
pub struct DiscreteRun {
    /// γ.
    pub gamma: Gamma,
    /// The phase step `δ` of (master12) / (MV master).
    pub delta: f64,
    /// The iterates `M₀, M₁, …, M_N` of (discr eq) (`M_m` at `t = mh`).
    pub iterates: Vec<Vec3<f64>>,
    /// The discrete solution (discr sol) `Φ(M², E, 2mδ + φ₀)`, `m = 0, …, N`.
    pub discrete: Vec<Vec3<f64>>,
}

/// The orbit comparison: (sol) against (discr eq) and (discr sol).
#[derive(Clone, Debug, PartialEq)]
pub struct OrbitComparison {
    /// The parameters of the level set of the start point.
    pub params: EllipticParams<f64>,
    /// Step size ([`ORBIT_H`]).
    pub h: f64,
    /// Number of steps `N` (about 2.5 periods).
    pub steps: usize,
    /// `N h`.
    pub t_end: f64,
    /// `(t, M(t))` of (sol) at [`ORBIT_SAMPLES`]` + 1` equally spaced times in `[0, Nh]`.
    pub continuous: Vec<(f64, Vec3<f64>)>,
    /// The discrete motions for γ_VM and γ₁, in this order.
    pub runs: Vec<DiscreteRun>,
}

/// The orbit comparison for the upper case at `h = `[`ORBIT_H`] over about 2.5 periods.
pub fn orbit_comparison() -> Result<OrbitComparison, ModelError> {
    let i = inertia()?;
    let m0 = CASES[0].start();
    let c = m_to_phi(&i, &m0)?;
    let k = quarter_period(&c.params)?
        .ok_or_else(|| ModelError::Undefined("start point on the separatrix".into()))?;
    let period = 4.0 * k / c.params.nu();
    let h = ORBIT_H;
    let steps = (2.5 * period / h).ceil() as usize;
    let t_end = steps as f64 * h;
    let continuous = (0..=ORBIT_SAMPLES)
        .map(|s| {
            let t = t_end * s as f64 / ORBIT_SAMPLES as f64;
            Ok((t, continuous_from(&c, &t)?))
        })
        .collect::<Result<Vec<_>, ModelError>>()?;
    let mut runs = Vec::new();
    for gamma in [Gamma::Vm, Gamma::G1] {
        let iterates = std::iter::once(Ok(m0.clone()))
            .chain(orbit(&i, gamma, &m0, &h).take(steps))
            .collect::<Result<Vec<_>, _>>()?;
        let d = delta(&i, &c.params, gamma, &h)?;
        let discrete = (0..=steps as i64)
            .map(|m| discrete_from(&c, &d, m))
            .collect::<Result<Vec<_>, _>>()?;
        runs.push(DiscreteRun {
            gamma,
            delta: d,
            iterates,
            discrete,
        });
    }
    Ok(OrbitComparison {
        params: c.params,
        h,
        steps,
        t_end,
        continuous,
        runs,
    })
}

/// The measured convergence order of one γ in one regime.
#[derive(Clone, Debug, PartialEq)]
pub struct OrderFit {
    /// The case (regime) name.
    pub case: &'static str,
    /// γ.
    pub gamma: Gamma,
    /// `(h, ‖M_N − M(T)‖∞)` for `h = T/N`, `N` in [`ORDER_N`].
    pub points: Vec<(f64, f64)>,
    /// Least-squares slope of `log err` against `log h`
    /// ([`loglog_slope`](crate::stats::loglog_slope)).
    pub order: f64,
}

/// The error at `T = `[`ORDER_T`] of `N` steps of (impl spec) with `h = T/N` against
/// the solution (sol) through the same start point, for every case and γ, with the
/// fitted order.
pub fn fitted_orders() -> Result<Vec<OrderFit>, ModelError> {
    let i = inertia()?;
    let mut out = Vec::new();
    for case in &CASES {
        let m0 = case.start();
        let c = m_to_phi(&i, &m0)?;
        let exact = continuous_from(&c, &ORDER_T)?;
        for gamma in GAMMAS {
            let points = ORDER_N
                .iter()
                .map(|&n| {
                    let h = ORDER_T / n as f64;
                    Ok((h, error_after(&i, gamma, &m0, h, n, &exact)?))
                })
                .collect::<Result<Vec<_>, ModelError>>()?;
            let order = crate::stats::loglog_slope(&points).ok_or_else(|| {
                ModelError::Undefined(format!(
                    "case {}, {}: no order can be fitted to {points:?}",
                    case.name,
                    gamma.name()
                ))
            })?;
            out.push(OrderFit {
                case: case.name,
                gamma,
                points,
                order,
            });
        }
    }
    Ok(out)
}
