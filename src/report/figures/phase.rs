//! The `Δφ`-against-`φ̄` figure (one per regime): 2×2 panels, one per γ, each with one
//! curve per step size and the predicted `δ` dashed.

use super::style::{Area, H_COLORS, LIGHT, header, io_err, label, legend_line, model_err};
use crate::model::Gamma;
use crate::model::experiments::{Case, GAMMAS, PhaseCurve};
use crate::model::experiments::{case_params, inertia, min_max, phase_curves};
use plotters::prelude::*;
use std::io;

const W: &str = "dphi-vs-phibar.svg";

/// One panel of the `Δφ` figure.
fn phase_panel(
    area: &Area,
    gamma: Gamma,
    curves: &[&PhaseCurve],
    k: f64,
    yr: (f64, f64),
) -> io::Result<()> {
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
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 16))
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
        .label_font(("sans-serif", 15))
        .position(SeriesLabelPosition::UpperRight)
        .border_style(BLACK)
        .background_style(WHITE.mix(0.8))
        .draw()
        .map_err(|e| io_err(W, e))?;
    Ok(())
}

/// The `Δφ`-against-`φ̄` figure of one case (2×2 panels, one per γ).
pub fn dphi_vs_phibar_svg(case: &Case) -> io::Result<String> {
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
