//! SVG figures drawn with plotters: residual against precision per section (here) and
//! the figures of the Euler-top model ([`model`]).

pub mod model;
mod orbits;
mod order;
mod phase;
mod style;

use super::Section;
use crate::claims::verdict::{ClaimResult, Rung, Verdict};
use plotters::prelude::*;

/// Residual (log2) against working precision for each claim of a section: one line per
/// claim, the dashed reference 2^−p, true identities blue, refuted red, others grey.
/// Exact zeros are drawn at the bottom edge of the plot.
pub fn residual_plot(sec: &Section, claims: &[&ClaimResult], bits: &[u32]) -> String {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (760, 460)).into_drawing_area();
        let _ = root.fill(&WHITE);
        let pmax = bits.iter().copied().max().unwrap_or(1024) as f64;
        let pmin = bits.iter().copied().min().unwrap_or(53) as f64;
        let floor = -(pmax + 40.0);
        let caption = format!("Section {}: residual vs precision", sec.number);
        let chart = ChartBuilder::on(&root)
            .caption(caption, ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(pmin..pmax, floor..20.0);
        let Ok(mut chart) = chart else {
            return svg_fallback();
        };
        let _ = chart
            .configure_mesh()
            .x_desc("working precision p (bits)")
            .y_desc("log2 residual")
            .draw();
        let _ = chart
            .draw_series(
                LineSeries::new(
                    vec![(pmin, -pmin), (pmax, -pmax)],
                    ShapeStyle::from(&BLACK).stroke_width(1),
                )
                .point_size(0),
            )
            .map(|s| {
                s.label("2^-p")
                    .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], BLACK))
            });
        for r in claims {
            if r.verdict == Verdict::Defined
                || r.residuals.iter().any(Rung::is_slope)
                || r.residuals.is_empty()
            {
                continue;
            }
            let color = match r.verdict {
                Verdict::Holds | Verdict::Proved | Verdict::Construction => RGBColor(31, 119, 180),
                Verdict::Refuted => RGBColor(214, 39, 40),
                _ => RGBColor(140, 140, 140),
            };
            let pts: Vec<(f64, f64)> = r
                .residuals
                .iter()
                .map(|x| (x.bits() as f64, x.log2().unwrap_or(floor).max(floor)))
                .collect();
            let _ = chart.draw_series(LineSeries::new(pts.clone(), color.stroke_width(1)));
            let _ = chart.draw_series(pts.into_iter().map(|p| Circle::new(p, 2, color.filled())));
        }
        let _ = chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE)
            .draw();
        let _ = root.present();
    }
    svg
}

fn svg_fallback() -> String {
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\"></svg>".to_string()
}
