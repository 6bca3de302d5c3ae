//! The error-against-`h` figure: one log–log panel per regime with the error of each γ
//! at fixed time, its fitted order in the legend and a dashed reference slope 2.

use super::style::{Area, COLORS, LIGHT, io_err, label, legend_line, model_err, regime_text};
use crate::model::experiments::{CASES, Case, GAMMAS, INERTIA, ORDER_N, ORDER_T, OrderFit};
use crate::model::experiments::{case_params, fitted_orders, inertia, min_max};
use crate::model::{EllipticParams, Inertia};
use plotters::prelude::*;
use std::io;

const W: &str = "error-vs-h.svg";

/// The dashed reference slope 2 through the largest-h error of the first fit.
fn reference_slope<DB: DrawingBackend, CT>(
    chart: &mut ChartContext<DB, CT>,
    fs: &[&OrderFit],
    (hlo, hhi): (f64, f64),
) -> io::Result<()>
where
    CT: plotters::coord::CoordTranslate<From = (f64, f64)>,
    DB::ErrorType: 'static,
{
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
    Ok(())
}

/// One panel: the fits of one case.
fn order_panel(area: &Area, p: &EllipticParams<f64>, fs: &[&OrderFit]) -> io::Result<()> {
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
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 16))
        .x_desc("h")
        .y_desc("‖M_N − M(T)‖∞")
        .x_label_formatter(&|v| format!("{v:.5}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()
        .map_err(|e| io_err(W, e))?;
    for f in fs {
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
    reference_slope(&mut chart, fs, (hlo, hhi))?;
    chart
        .configure_series_labels()
        .label_font(("sans-serif", 15))
        .position(SeriesLabelPosition::LowerRight)
        .border_style(BLACK)
        .background_style(WHITE.mix(0.8))
        .draw()
        .map_err(|e| io_err(W, e))?;
    Ok(())
}

fn case_panel(area: &Area, i: &Inertia<f64>, case: &Case, fits: &[OrderFit]) -> io::Result<()> {
    let (p, _, _) = case_params(i, case).map_err(model_err(W))?;
    let fs: Vec<&OrderFit> = fits.iter().filter(|f| f.case == case.name).collect();
    order_panel(area, &p, &fs)
}

/// The error-against-`h` figure (one log–log panel per case) from [`fitted_orders`].
pub fn error_vs_h_svg() -> io::Result<String> {
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
            case_panel(area, &i, case, &fits)?;
        }
        root.present().map_err(|e| io_err(W, e))?;
    }
    Ok(svg)
}
