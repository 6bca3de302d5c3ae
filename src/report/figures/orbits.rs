//! The orbit figure: the continuous solution (sol) against the iterates of (discr eq)
//! and the discrete solution (discr sol), one panel per γ.

use super::style::{Area, COLORS, LIGHT, header, io_err, label, legend_line, model_err};
use crate::model::experiments::{DiscreteRun, OrbitComparison, orbit_comparison};
use plotters::prelude::*;
use std::io;

const W: &str = "orbits.svg";

/// One panel: lines (sol), circles the iterates at `t = mh`, crosses (discr sol).
fn orbit_panel(area: &Area, data: &OrbitComparison, run: &DiscreteRun) -> io::Result<()> {
    let (p, h) = (&data.params, data.h);
    let amp = p.a2.max(p.b2).max(p.c2).sqrt();
    let caption = format!(
        "{}: lines (sol) M(t); circles iterates M_m at t = mh; crosses (discr sol) \
         with δ = {:.6} (hν/2 = {:.6})",
        label(run.gamma),
        run.delta,
        h * p.nu() / 2.0
    );
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 14))
        .margin(8)
        .x_label_area_size(34)
        .y_label_area_size(50)
        .build_cartesian_2d(0.0..data.t_end, -1.15 * amp..1.45 * amp)
        .map_err(|e| io_err(W, e))?;
    chart
        .configure_mesh()
        .light_line_style(LIGHT)
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 16))
        .x_desc("t")
        .y_desc("M_j")
        .draw()
        .map_err(|e| io_err(W, e))?;
    for comp in 0..3 {
        let col = COLORS[comp + 1];
        chart
            .draw_series(LineSeries::new(
                data.continuous.iter().map(|(t, m)| (*t, m.0[comp])),
                col.stroke_width(1),
            ))
            .map_err(|e| io_err(W, e))?
            .label(format!("M{} (sol)", comp + 1))
            .legend(legend_line(col));
        let it_pts = run
            .iterates
            .iter()
            .enumerate()
            .map(|(n, m)| (n as f64 * h, m.0[comp]));
        chart
            .draw_series(it_pts.map(|p| Circle::new(p, 3, col.stroke_width(1))))
            .map_err(|e| io_err(W, e))?;
        chart
            .draw_series(
                run.discrete
                    .iter()
                    .enumerate()
                    .map(|(n, m)| Cross::new((n as f64 * h, m.0[comp]), 2, col)),
            )
            .map_err(|e| io_err(W, e))?;
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

/// The orbit figure of [`orbit_comparison`]: one panel for γ_VM, one for γ₁.
pub fn orbits_svg() -> io::Result<String> {
    let data = orbit_comparison().map_err(model_err(W))?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1100, 820)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| io_err(W, e))?;
        let title = format!(
            "Continuous (sol) vs discrete, h = {}, {} steps  —  {}",
            data.h,
            data.steps,
            header(&data.params)
        );
        let body = root
            .titled(&title, ("sans-serif", 17))
            .map_err(|e| io_err(W, e))?;
        let panels = body.split_evenly((2, 1));
        for (run, area) in data.runs.iter().zip(panels.iter()) {
            orbit_panel(area, &data, run)?;
        }
        root.present().map_err(|e| io_err(W, e))?;
    }
    Ok(svg)
}
