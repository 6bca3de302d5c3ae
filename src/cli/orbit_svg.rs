//! The figure of `eulertop orbit --svg`: the components of the continuous solution
//! (lines) and the iterates (dots) against `t`, and the deviation of `Δφ` from the
//! predicted `δ` against `φ̄` (with `δ` as the horizontal line at 0).

use super::orbit_row::Row;
use plotters::coord::Shift;
use plotters::prelude::*;

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

fn range(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for x in v {
        lo = lo.min(x);
        hi = hi.max(x);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = ((hi - lo) * 0.05).max(1e-12 * hi.abs().max(1.0));
    (lo - pad, hi + pad)
}

fn text(e: impl std::fmt::Display) -> String {
    e.to_string()
}

fn solution_panel(area: &Area, rows: &[Row<f64>]) -> Result<(), String> {
    let (t0, t1) = range(rows.iter().map(|r| r.t));
    let (y0, y1) = range(
        rows.iter()
            .flat_map(|r| r.m.0.iter().chain(r.sol.0.iter()))
            .copied(),
    );
    let mut ch = ChartBuilder::on(area)
        .margin(20)
        .x_label_area_size(30)
        .y_label_area_size(50)
        .build_cartesian_2d(t0..t1, y0..y1)
        .map_err(text)?;
    ch.configure_mesh()
        .x_desc("t")
        .y_desc("M1 (red), M2 (green), M3 (blue): sol lines, iterates dots")
        .draw()
        .map_err(text)?;
    for (k, col) in [RED, GREEN, BLUE].iter().enumerate() {
        ch.draw_series(LineSeries::new(rows.iter().map(|r| (r.t, r.sol.0[k])), col))
            .map_err(text)?;
        ch.draw_series(
            rows.iter()
                .map(|r| Circle::new((r.t, r.m.0[k]), 2, col.filled())),
        )
        .map_err(text)?;
    }
    Ok(())
}

/// A tick label with enough digits to tell the ticks of an axis spanning `span` apart:
/// scientific notation for a span below 10⁻³, else fixed decimals.
fn tick_label(v: f64, span: f64) -> String {
    // a tick within rounding of 0 is 0
    if v.abs() <= span * 1e-9 {
        return "0".to_string();
    }
    if span < 1e-3 {
        return format!("{v:.2e}");
    }
    let decimals = (1.0 - (span / 5.0).log10().floor()).clamp(0.0, 6.0) as usize;
    format!("{v:.decimals$}")
}

/// The lower panel: `Δφ` against `φ̄`, drawn as the deviation from the predicted `δ` (or,
/// without a prediction, from the mean of `Δφ`) so that its ticks stay distinct when `Δφ`
/// is constant to many digits.
fn phase_panel(area: &Area, rows: &[Row<f64>], pred: Option<f64>) -> Result<(), String> {
    let ph: Vec<(f64, f64)> = rows.iter().filter_map(|r| r.phase).collect();
    let mean = ph.iter().map(|p| p.1).sum::<f64>() / ph.len().max(1) as f64;
    let offset = pred.unwrap_or(mean);
    let dev: Vec<(f64, f64)> = ph.iter().map(|p| (p.0, p.1 - offset)).collect();
    let (x0, x1) = range(dev.iter().map(|p| p.0));
    let (d0, d1) = range(dev.iter().map(|p| p.1).chain(pred.map(|_| 0.0)));
    let mut ch = ChartBuilder::on(area)
        .margin(20)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d(x0..x1, d0..d1)
        .map_err(text)?;
    let y_desc = match pred {
        Some(d) => format!("dphi - delta (dots), delta = {d:.10} predicted (red line)"),
        None => format!("dphi - {offset:.10} (dots; the mean of dphi)"),
    };
    ch.configure_mesh()
        .x_desc("phibar")
        .y_desc(y_desc)
        .x_label_formatter(&|v| tick_label(*v, x1 - x0))
        .y_label_formatter(&|v| tick_label(*v, d1 - d0))
        .label_style(("sans-serif", 13))
        .draw()
        .map_err(text)?;
    ch.draw_series(dev.iter().map(|p| Circle::new(*p, 2, BLACK.filled())))
        .map_err(text)?;
    if pred.is_some() {
        ch.draw_series(LineSeries::new(vec![(x0, 0.0), (x1, 0.0)], &RED))
            .map_err(text)?;
    }
    Ok(())
}

/// The SVG text of the figure for the rows of an orbit and the predicted `δ`.
pub fn render(rows: &[Row<f64>], pred: Option<f64>) -> Result<String, String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 900)).into_drawing_area();
        root.fill(&WHITE).map_err(text)?;
        let (top, bottom) = root.split_vertically(450);
        solution_panel(&top, rows)?;
        phase_panel(&bottom, rows, pred)?;
        root.present().map_err(text)?;
    }
    Ok(svg)
}
