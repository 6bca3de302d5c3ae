//! Figures of the Euler-top model, drawn with plotters (SVG) from the f64 model layer:
//!
//! * `dphi-vs-phibar.svg` (upper regime) and `dphi-vs-phibar-lower.svg` (lower regime):
//!   the phase step `Δφ = (φ̂ − φ)/2` against `φ̄ = (φ + φ̂)/2` (phis) of one step of
//!   (impl spec) from start points covering a full period `4K` of `φ`, for γ₀, γ₁, γ₂
//!   and γ_VM (one panel each) at several `h`, normalized by `hν/2`.  For the Poisson
//!   maps γ₁, γ₂, γ_VM the curves are flat (φ-independence (phi indep)) and lie on the
//!   predicted `δ` of (master12) / (MV master) (dashed); γ₀ (Section 7) varies with `φ̄`.
//! * `orbits.svg`: the continuous solution (sol) `M₁(t), M₂(t), M₃(t)` (lines) against
//!   the iterates `M_m` of (discr eq) at `t = mh` (circles) and the discrete solution
//!   (discr sol) `Φ(M², E, 2mδ + φ₀)` (crosses), for γ_VM and γ₁ with a large `h`, so
//!   that the phase drift between continuous and discrete motion is visible.
//! * `error-vs-h.svg`: log–log plot of `‖M_N − M(T)‖∞` at `T = N h` fixed against `h`,
//!   for the four γ in both regimes, with the least-squares slope (the measured order)
//!   in the legend; [`fitted_orders`] returns the same fits for tests.
//!
//! All inputs are fixed (inertia `A, B, C = 3, 2, 1`, one start point per regime), all
//! arithmetic is f64, labels use fixed-width formatting and no time or randomness
//! enters, so the SVG bytes are identical across runs.  Model failures (Newton not
//! converging etc.) are returned as an `io::Error` whose message names the figure and
//! the model error.

use crate::linalg::Vec3;
use crate::model::discretization::{inf_norm, orbit, step};
use crate::model::elliptic_coords::{m_to_phi, phi_to_m, quarter_period};
use crate::model::phase::{delta, step_phases};
use crate::model::solution::{continuous_from, discrete_from};
use crate::model::{EllipticParams, Gamma, Inertia, ModelError, Regime, Sector};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::io;
use std::path::Path;

/// The figures [`write_all`] writes, with a one-line caption each (file, caption).
pub const FIGURES: [(&str, &str); 4] = [
    ("dphi-vs-phibar.svg", "Δφ against φ̄ for γ0, γ1, γ2 and γ_VM at several h (upper regime): flat for the Poisson maps γ1, γ2, γ_VM, on the predicted δ; varying for γ0 (Proposition 5)."),
    ("dphi-vs-phibar-lower.svg", "The same in the lower regime E/M² < 1/B."),
    ("orbits.svg", "The continuous solution (sol) against the discrete iterates and (discr sol)."),
    ("error-vs-h.svg", "Error of the discrete solution against h at fixed time, log–log, with the fitted order."),
];

/// The four γ of (impl spec), in the order drawn.
pub const GAMMAS: [Gamma; 4] = [Gamma::G0, Gamma::G1, Gamma::G2, Gamma::Vm];

/// The moments of inertia `(A, B, C)` used by every figure.
pub const INERTIA: (f64, f64, f64) = (3.0, 2.0, 1.0);

/// Step sizes of the `Δφ` figures.
pub const PHASE_H: [f64; 3] = [0.05, 0.1, 0.2];

/// Number of start points per period `4K` in the `Δφ` figures.
pub const PHASE_GRID: usize = 64;

/// The fixed time `T` of the error figure.
pub const ORDER_T: f64 = 2.0;

/// Step counts `N` of the error figure (`h = T/N`).
pub const ORDER_N: [usize; 7] = [10, 20, 40, 80, 160, 320, 640];

/// Step size of the orbit figure.
pub const ORBIT_H: f64 = 0.3;

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

/// The inertia [`INERTIA`] as a validated [`Inertia`].
pub fn inertia() -> Result<Inertia<f64>, ModelError> {
    Inertia::new(INERTIA.0, INERTIA.1, INERTIA.2)
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

fn min_max(it: impl Iterator<Item = f64>) -> (f64, f64) {
    it.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    })
}

fn start(case: &Case) -> Vec3<f64> {
    Vec3::new(case.point[0], case.point[1], case.point[2])
}

/// The invariants and parameters of a case: `(params, sector, K)`.
fn case_params(
    i: &Inertia<f64>,
    case: &Case,
) -> Result<(EllipticParams<f64>, Sector, f64), ModelError> {
    let c = m_to_phi(i, &start(case))?;
    let k = quarter_period(&c.params)?.ok_or_else(|| {
        ModelError::Undefined(format!("case {}: start point on the separatrix", case.name))
    })?;
    Ok((c.params, c.sector, k))
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

/// The measured convergence order of one γ in one regime.
#[derive(Clone, Debug, PartialEq)]
pub struct OrderFit {
    /// The case (regime) name.
    pub case: &'static str,
    /// γ.
    pub gamma: Gamma,
    /// `(h, ‖M_N − M(T)‖∞)` for `h = T/N`, `N` in [`ORDER_N`].
    pub points: Vec<(f64, f64)>,
    /// Least-squares slope of `log err` against `log h`.
    pub order: f64,
}

/// Least-squares slope of `ln y` against `ln x`.
pub fn loglog_slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x.ln(), b + y.ln()));
    let (mx, my) = (sx / n, sy / n);
    let (num, den) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        let dx = x.ln() - mx;
        (a + dx * (y.ln() - my), b + dx * dx)
    });
    num / den
}

/// The error at `T = `[`ORDER_T`] of `N` steps of (impl spec) with `h = T/N` against
/// the solution (sol) through the same start point, for every case and γ, with the
/// fitted order ([`loglog_slope`]).
pub fn fitted_orders() -> Result<Vec<OrderFit>, ModelError> {
    let i = inertia()?;
    let mut out = Vec::new();
    for case in &CASES {
        let m0 = start(case);
        let c = m_to_phi(&i, &m0)?;
        let exact = continuous_from(&c, &ORDER_T)?;
        for gamma in GAMMAS {
            let mut points = Vec::with_capacity(ORDER_N.len());
            for n in ORDER_N {
                let h = ORDER_T / n as f64;
                let mut m = m0.clone();
                for _ in 0..n {
                    m = step(&i, gamma, &m, &h)?;
                }
                points.push((h, inf_norm(&(m - exact.clone()))));
            }
            let order = loglog_slope(&points);
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

// ---------------------------------------------------------------------------------
// drawing

const COLORS: [RGBColor; 4] = [
    RGBColor(214, 39, 40),
    RGBColor(31, 119, 180),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
];
const LIGHT: RGBColor = RGBColor(238, 238, 238);
const H_COLORS: [RGBColor; 3] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
];

fn label(g: Gamma) -> &'static str {
    match g {
        Gamma::G0 => "γ0",
        Gamma::G1 => "γ1",
        Gamma::G2 => "γ2",
        Gamma::Vm => "γVM",
    }
}

fn regime_text(r: Regime) -> &'static str {
    match r {
        Regime::Upper => "upper regime E/M² > 1/B",
        Regime::Lower => "lower regime E/M² < 1/B",
        Regime::Separatrix => "separatrix E/M² = 1/B",
    }
}

fn header(p: &EllipticParams<f64>) -> String {
    format!(
        "A,B,C = {}, {}, {};  M² = {:.4}, E = {:.4}, k = {:.4}, ν = {:.4};  {}",
        INERTIA.0,
        INERTIA.1,
        INERTIA.2,
        p.m2,
        p.e,
        p.k(),
        p.nu(),
        regime_text(p.regime)
    )
}

fn io_err(what: &str, e: impl std::fmt::Display) -> io::Error {
    io::Error::other(format!("{what}: {e}"))
}

fn model_err(what: &'static str) -> impl Fn(ModelError) -> io::Error {
    move |e| io_err(what, e)
}

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

fn legend_line(c: RGBColor) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2))
}

/// One panel of the `Δφ` figure.
fn phase_panel(
    area: &Area,
    gamma: Gamma,
    curves: &[&PhaseCurve],
    k: f64,
    yr: (f64, f64),
) -> io::Result<()> {
    const W: &str = "dphi-vs-phibar.svg";
    let caption = match gamma {
        Gamma::G0 => format!("{} (Section 7, not Poisson)", label(gamma)),
        Gamma::Vm => format!("{} (dashed: δ_VM of (MV master))", label(gamma)),
        _ => format!("{} (dashed: δ of (master12))", label(gamma)),
    };
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 15))
        .margin(8)
        .x_label_area_size(34)
        .y_label_area_size(64)
        .build_cartesian_2d(-2.1..2.1, yr.0..yr.1)
        .map_err(|e| io_err(W, e))?;
    chart
        .configure_mesh()
        .light_line_style(LIGHT)
        .x_desc("φ̄ / K(k)")
        .y_desc("Δφ / (hν/2)")
        .y_label_formatter(&|v| format!("{v:.4}"))
        .draw()
        .map_err(|e| io_err(W, e))?;
    for (ci, c) in curves.iter().enumerate() {
        let col = H_COLORS[ci % H_COLORS.len()];
        let pts: Vec<(f64, f64)> = c
            .points
            .iter()
            .map(|&(x, y)| (x / k, y / c.half_h_nu))
            .collect();
        chart
            .draw_series(LineSeries::new(pts.clone(), col.stroke_width(2)))
            .map_err(|e| io_err(W, e))?
            .label(format!("h = {}", c.h))
            .legend(legend_line(col));
        chart
            .draw_series(pts.iter().map(|&p| Circle::new(p, 2, col.filled())))
            .map_err(|e| io_err(W, e))?;
        if let Some(d) = c.predicted {
            let y = d / c.half_h_nu;
            chart
                .draw_series(DashedLineSeries::new(
                    vec![(-2.1, y), (2.1, y)],
                    6,
                    4,
                    BLACK.stroke_width(1),
                ))
                .map_err(|e| io_err(W, e))?;
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .border_style(BLACK)
        .background_style(WHITE.mix(0.8))
        .draw()
        .map_err(|e| io_err(W, e))?;
    Ok(())
}

/// The `Δφ`-against-`φ̄` figure of one case (2×2 panels, one per γ).
pub fn dphi_vs_phibar_svg(case: &Case) -> io::Result<String> {
    const W: &str = "dphi-vs-phibar.svg";
    let i = inertia().map_err(model_err(W))?;
    let (p, _, k) = case_params(&i, case).map_err(model_err(W))?;
    let curves = phase_curves(case).map_err(model_err(W))?;
    // one y-range for all panels, so that flat and varying curves compare directly
    let (lo, hi) = min_max(curves.iter().flat_map(|c| {
        c.points
            .iter()
            .map(move |p| p.1 / c.half_h_nu)
            .chain(c.predicted.map(|d| d / c.half_h_nu))
    }));
    let pad = (hi - lo).max(1e-3) * 0.12;
    let yr = (lo - pad, hi + 2.5 * pad);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1100, 820)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| io_err(W, e))?;
        let title = format!(
            "One step of (impl spec): Δφ against φ̄ over a period 4K  —  {}",
            header(&p)
        );
        let body = root
            .titled(&title, ("sans-serif", 17))
            .map_err(|e| io_err(W, e))?;
        let panels = body.split_evenly((2, 2));
        for (gamma, area) in GAMMAS.iter().zip(panels.iter()) {
            let cs: Vec<&PhaseCurve> = curves.iter().filter(|c| c.gamma == *gamma).collect();
            phase_panel(area, *gamma, &cs, k, yr)?;
        }
        root.present().map_err(|e| io_err(W, e))?;
    }
    Ok(svg)
}

/// The orbit figure: (sol) against the iterates of (discr eq) and (discr sol), for
/// γ_VM and γ₁ at `h = `[`ORBIT_H`] over about 2.5 periods of the upper case.
pub fn orbits_svg() -> io::Result<String> {
    const W: &str = "orbits.svg";
    let case = &CASES[0];
    let i = inertia().map_err(model_err(W))?;
    let m0 = start(case);
    let c = m_to_phi(&i, &m0).map_err(model_err(W))?;
    let k = quarter_period(&c.params)
        .map_err(model_err(W))?
        .ok_or_else(|| io_err(W, "start point on the separatrix"))?;
    let nu = c.params.nu();
    let period = 4.0 * k / nu;
    let h = ORBIT_H;
    let steps = (2.5 * period / h).ceil() as usize;
    let t_end = steps as f64 * h;
    let samples = 600;
    let mut cont = Vec::with_capacity(samples + 1);
    for s in 0..=samples {
        let t = t_end * s as f64 / samples as f64;
        cont.push((t, continuous_from(&c, &t).map_err(model_err(W))?));
    }
    let amp = c.params.a2.max(c.params.b2).max(c.params.c2).sqrt();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1100, 820)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| io_err(W, e))?;
        let title = format!(
            "Continuous (sol) vs discrete, h = {h}, {steps} steps  —  {}",
            header(&c.params)
        );
        let body = root
            .titled(&title, ("sans-serif", 17))
            .map_err(|e| io_err(W, e))?;
        let panels = body.split_evenly((2, 1));
        for (gamma, area) in [Gamma::Vm, Gamma::G1].iter().zip(panels.iter()) {
            let gamma = *gamma;
            let iters = orbit(&i, gamma, &m0, &h, steps).map_err(model_err(W))?;
            let d = delta(&i, &c.params, gamma, &h).map_err(model_err(W))?;
            let mut disc = Vec::with_capacity(steps + 1);
            for m in 0..=steps as i64 {
                disc.push(discrete_from(&c, &d, m).map_err(model_err(W))?);
            }
            let caption = format!(
                "{}: lines (sol) M(t); circles iterates M_m at t = mh; crosses (discr sol) \
                 with δ = {:.6} (hν/2 = {:.6})",
                label(gamma),
                d,
                h * nu / 2.0
            );
            let mut chart = ChartBuilder::on(area)
                .caption(caption, ("sans-serif", 14))
                .margin(8)
                .x_label_area_size(34)
                .y_label_area_size(50)
                .build_cartesian_2d(0.0..t_end, -1.15 * amp..1.45 * amp)
                .map_err(|e| io_err(W, e))?;
            chart
                .configure_mesh()
                .light_line_style(LIGHT)
                .x_desc("t")
                .y_desc("M_j")
                .draw()
                .map_err(|e| io_err(W, e))?;
            for comp in 0..3 {
                let col = COLORS[comp + 1];
                chart
                    .draw_series(LineSeries::new(
                        cont.iter().map(|(t, m)| (*t, m.0[comp])),
                        col.stroke_width(1),
                    ))
                    .map_err(|e| io_err(W, e))?
                    .label(format!("M{} (sol)", comp + 1))
                    .legend(legend_line(col));
                let it_pts = std::iter::once(&m0)
                    .chain(iters.iter())
                    .enumerate()
                    .map(|(n, m)| (n as f64 * h, m.0[comp]));
                chart
                    .draw_series(it_pts.map(|p| Circle::new(p, 3, col.stroke_width(1))))
                    .map_err(|e| io_err(W, e))?;
                chart
                    .draw_series(
                        disc.iter()
                            .enumerate()
                            .map(|(n, m)| Cross::new((n as f64 * h, m.0[comp]), 2, col)),
                    )
                    .map_err(|e| io_err(W, e))?;
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .border_style(BLACK)
                .background_style(WHITE.mix(0.8))
                .draw()
                .map_err(|e| io_err(W, e))?;
        }
        root.present().map_err(|e| io_err(W, e))?;
    }
    Ok(svg)
}

/// The error-against-`h` figure (one log–log panel per case) from [`fitted_orders`].
pub fn error_vs_h_svg() -> io::Result<String> {
    const W: &str = "error-vs-h.svg";
    let fits = fitted_orders().map_err(model_err(W))?;
    let i = inertia().map_err(model_err(W))?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1100, 520)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| io_err(W, e))?;
        let title = format!(
            "Error ‖M_N − M(T)‖∞ at T = {ORDER_T} (h = T/N, N = {}…{}) for A,B,C = {}, {}, {}; \
             order = least-squares log–log slope",
            ORDER_N[0],
            ORDER_N[ORDER_N.len() - 1],
            INERTIA.0,
            INERTIA.1,
            INERTIA.2
        );
        let body = root
            .titled(&title, ("sans-serif", 16))
            .map_err(|e| io_err(W, e))?;
        let panels = body.split_evenly((1, CASES.len()));
        for (case, area) in CASES.iter().zip(panels.iter()) {
            let (p, _, _) = case_params(&i, case).map_err(model_err(W))?;
            let fs: Vec<&OrderFit> = fits.iter().filter(|f| f.case == case.name).collect();
            let (hlo, hhi) = min_max(fs.iter().flat_map(|f| f.points.iter().map(|p| p.0)));
            let hs: Vec<f64> = ORDER_N.iter().map(|n| ORDER_T / *n as f64).collect();
            let (elo, ehi) = min_max(fs.iter().flat_map(|f| f.points.iter().map(|p| p.1)));
            let caption = format!(
                "M² = {:.4}, E = {:.4}, {}",
                p.m2,
                p.e,
                regime_text(p.regime)
            );
            let mut chart = ChartBuilder::on(area)
                .caption(caption, ("sans-serif", 14))
                .margin(10)
                .x_label_area_size(36)
                .y_label_area_size(64)
                .build_cartesian_2d(
                    (hlo * 0.8..hhi * 1.25).log_scale().with_key_points(hs),
                    (elo * 0.3..ehi * 4.0).log_scale(),
                )
                .map_err(|e| io_err(W, e))?;
            chart
                .configure_mesh()
                .light_line_style(LIGHT)
                .x_desc("h")
                .y_desc("‖M_N − M(T)‖∞")
                .x_label_formatter(&|v| format!("{v:.5}"))
                .y_label_formatter(&|v| format!("{v:.0e}"))
                .draw()
                .map_err(|e| io_err(W, e))?;
            for f in &fs {
                let col = COLORS[GAMMAS.iter().position(|g| *g == f.gamma).unwrap_or(0)];
                chart
                    .draw_series(LineSeries::new(f.points.clone(), col.stroke_width(2)))
                    .map_err(|e| io_err(W, e))?
                    .label(format!("{}: order {:.3}", label(f.gamma), f.order))
                    .legend(legend_line(col));
                chart
                    .draw_series(f.points.iter().map(|&q| Circle::new(q, 3, col.filled())))
                    .map_err(|e| io_err(W, e))?;
            }
            // reference slope 2 through the largest-h error of the first fit
            if let Some(&(h0, e0)) = fs.first().and_then(|f| f.points.first()) {
                let r = |h: f64| e0 * 2.0 * (h / h0).powi(2);
                chart
                    .draw_series(DashedLineSeries::new(
                        vec![(hlo, r(hlo)), (hhi, r(hhi))],
                        6,
                        4,
                        BLACK.stroke_width(1),
                    ))
                    .map_err(|e| io_err(W, e))?
                    .label("slope 2")
                    .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], BLACK));
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::LowerRight)
                .border_style(BLACK)
                .background_style(WHITE.mix(0.8))
                .draw()
                .map_err(|e| io_err(W, e))?;
        }
        root.present().map_err(|e| io_err(W, e))?;
    }
    Ok(svg)
}

/// Every model figure as `(file name, SVG text)`, in a fixed order.
pub fn render_all() -> io::Result<Vec<(String, String)>> {
    let mut out = Vec::new();
    for case in &CASES {
        let name = match case.regime {
            Regime::Upper => "dphi-vs-phibar.svg".to_string(),
            _ => format!("dphi-vs-phibar-{}.svg", case.name),
        };
        out.push((name, dphi_vs_phibar_svg(case)?));
    }
    out.push(("orbits.svg".to_string(), orbits_svg()?));
    out.push(("error-vs-h.svg".to_string(), error_vs_h_svg()?));
    Ok(out)
}

/// Writes the model figures ([`render_all`]) into `dir` (created if missing).
/// Errors name the figure and the failing model computation or file operation.
pub fn write_all(dir: &Path) -> io::Result<()> {
    let figs = render_all()?;
    std::fs::create_dir_all(dir)?;
    for (name, svg) in figs {
        let p = dir.join(&name);
        std::fs::write(&p, svg).map_err(|e| io_err(&p.display().to_string(), e))?;
    }
    Ok(())
}
