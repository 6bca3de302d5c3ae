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

/// Width of a residual figure in pixels.
const RES_WIDTH: u32 = 1000;
/// Height of its plot; the key below it grows with the number of claims.
const RES_PLOT_HEIGHT: u32 = 460;
/// Columns of the key and the height of one of its rows.
const KEY_COLUMNS: usize = 3;
const KEY_ROW: u32 = 17;

/// Distinct colours of the claims (Tableau 10), cycled, with [`MARKERS`] shapes.
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];
/// Number of marker shapes: filled circle, triangle, cross, open circle.
const MARKERS: usize = 4;

/// The colour and marker shape of the `j`-th claim of a figure: every pair differs for
/// the first 40 claims.
fn claim_style(j: usize) -> (RGBColor, usize) {
    (PALETTE[j % PALETTE.len()], (j / PALETTE.len()) % MARKERS)
}

/// Draws a marker of shape `shape` at `at` on `area` (any coordinate system).
fn draw_marker<DB, CT>(area: &DrawingArea<DB, CT>, at: CT::From, shape: usize, color: RGBColor)
where
    DB: DrawingBackend,
    CT: plotters::coord::CoordTranslate,
    CT::From: Clone,
{
    let _ = match shape {
        0 => area.draw(&Circle::new(at, 3, color.filled())),
        1 => area.draw(&TriangleMarker::new(at, 4, color.filled())),
        2 => area.draw(&Cross::new(at, 3, color.stroke_width(2))),
        _ => area.draw(&Circle::new(at, 3, color.stroke_width(1))),
    };
}

/// The claims of a section that have a residual ladder to draw (not definitions, not
/// asymptotic claims).
fn ladder_claims<'a>(claims: &[&'a ClaimResult]) -> Vec<&'a ClaimResult> {
    claims
        .iter()
        .copied()
        .filter(|r| {
            r.verdict != Verdict::Defined
                && !r.residuals.iter().any(Rung::is_slope)
                && !r.residuals.is_empty()
        })
        .collect()
}

/// Residual (log2) against working precision for each claim of a section: one line per
/// claim in its own colour and marker, named in the key below the plot (refuted claims
/// marked ✗, inconclusive ones ?), with the dashed reference 2^−p.  Exact zeros are
/// drawn at the bottom edge of the plot.
pub fn residual_plot(sec: &Section, claims: &[&ClaimResult], bits: &[u32]) -> String {
    let drawn = ladder_claims(claims);
    let rows = drawn.len().div_ceil(KEY_COLUMNS) as u32;
    let height = RES_PLOT_HEIGHT + 16 + rows * KEY_ROW;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (RES_WIDTH, height)).into_drawing_area();
        let _ = root.fill(&WHITE);
        let (plot, key) = root.split_vertically(RES_PLOT_HEIGHT);
        if !draw_ladders(&plot, sec, &drawn, bits) {
            return svg_fallback();
        }
        draw_key(&key, &drawn);
        let _ = root.present();
    }
    svg
}

/// The plot of a residual figure; false when the chart cannot be built.
fn draw_ladders<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    sec: &Section,
    drawn: &[&ClaimResult],
    bits: &[u32],
) -> bool {
    let pmax = bits.iter().copied().max().unwrap_or(1024) as f64;
    let pmin = bits.iter().copied().min().unwrap_or(53) as f64;
    let floor = -(pmax + 40.0);
    let caption = format!("Section {}: residual vs precision", sec.number);
    let chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(pmin..pmax, floor..20.0);
    let Ok(mut chart) = chart else {
        return false;
    };
    let _ = chart
        .configure_mesh()
        .x_desc("working precision p (bits)")
        .y_desc("log2 residual")
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 15))
        .draw();
    let dashed = ShapeStyle::from(&BLACK).stroke_width(1);
    let _ = chart.draw_series(DashedLineSeries::new(
        vec![(pmin, -pmin), (pmax, -pmax)],
        6,
        4,
        dashed,
    ));
    let plotting = chart.plotting_area();
    for (j, r) in drawn.iter().enumerate() {
        let (color, shape) = claim_style(j);
        let pts: Vec<(f64, f64)> = r
            .residuals
            .iter()
            .map(|x| (x.bits() as f64, x.log2().unwrap_or(floor).max(floor)))
            .collect();
        let _ = plotting.draw(&PathElement::new(pts.clone(), color.stroke_width(1)));
        for p in pts {
            draw_marker(plotting, p, shape, color);
        }
    }
    true
}

/// The key below a residual plot: the reference line, then each claim's marker and id,
/// in columns.
fn draw_key<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    drawn: &[&ClaimResult],
) {
    let font = ("sans-serif", 14).into_font().color(&BLACK);
    let col_w = (RES_WIDTH as i32 - 40) / KEY_COLUMNS as i32;
    for x in [20, 30, 40] {
        let _ = area.draw(&PathElement::new(
            vec![(x, 6), (x + 6, 6)],
            BLACK.stroke_width(1),
        ));
    }
    let _ = area.draw(&Text::new(
        "dashed: the reference 2^-p, which a true identity tracks; exact zeros sit on the bottom edge; (✗) refuted, (?) inconclusive",
        (52, 0),
        font.clone(),
    ));
    let rows = drawn.len().div_ceil(KEY_COLUMNS);
    for (j, r) in drawn.iter().enumerate() {
        let (color, shape) = claim_style(j);
        let x = 20 + (j / rows.max(1)) as i32 * col_w;
        let y = 16 + (j % rows.max(1)) as i32 * KEY_ROW as i32;
        let _ = area.draw(&PathElement::new(
            vec![(x, y + 6), (x + 24, y + 6)],
            color.stroke_width(1),
        ));
        draw_marker(area, (x + 12, y + 6), shape, color);
        let what = match r.verdict {
            Verdict::Refuted => " (✗)",
            Verdict::Inconclusive => " (?)",
            _ => "",
        };
        let _ = area.draw(&Text::new(
            format!("{}{what}", r.id),
            (x + 30, y),
            font.clone(),
        ));
    }
}

fn svg_fallback() -> String {
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\"></svg>".to_string()
}
