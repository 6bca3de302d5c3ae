//! Shared style of the model figures: colours, γ labels, the level-set header line and
//! the error conversions of the drawing code.

use crate::model::experiments::INERTIA;
use crate::model::{EllipticParams, Gamma, ModelError, Regime};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::io;

/// Colours of the four γ (γ₀ red, then blue, green, purple for the components).
pub(super) const COLORS: [RGBColor; 4] = [
    RGBColor(214, 39, 40),
    RGBColor(31, 119, 180),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
];

/// Colour of the light grid lines.
pub(super) const LIGHT: RGBColor = RGBColor(238, 238, 238);

/// Colours of the step sizes in the `Δφ` figure.
pub(super) const H_COLORS: [RGBColor; 3] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
];

/// A drawing area of an SVG written into a string.
pub(super) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// The label of γ in legends and captions.
pub(super) fn label(g: Gamma) -> &'static str {
    match g {
        Gamma::G0 => "γ0",
        Gamma::G1 => "γ1",
        Gamma::G2 => "γ2",
        Gamma::Vm => "γVM",
    }
}

/// The regime as a caption fragment.
pub(super) fn regime_text(r: Regime) -> &'static str {
    match r {
        Regime::Upper => "upper regime E/M² > 1/B",
        Regime::Lower => "lower regime E/M² < 1/B",
        Regime::Separatrix => "separatrix E/M² = 1/B",
    }
}

/// The title line naming the inertia and the level set.
pub(super) fn header(p: &EllipticParams<f64>) -> String {
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

/// An I/O error naming the figure.
pub(super) fn io_err(what: &str, e: impl std::fmt::Display) -> io::Error {
    io::Error::other(format!("{what}: {e}"))
}

/// Converts a model error into an I/O error naming the figure.
pub(super) fn model_err(what: &'static str) -> impl Fn(ModelError) -> io::Error {
    move |e| io_err(what, e)
}

/// A short horizontal line of colour `c` for legends.
pub(super) fn legend_line(c: RGBColor) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2))
}
