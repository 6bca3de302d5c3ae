//! The figures of the Euler-top model, drawn with plotters (SVG) from the data of
//! [`experiments`](crate::model::experiments):
//!
//! * `dphi-vs-phibar.svg` (upper regime) and `dphi-vs-phibar-lower.svg` (lower regime):
//!   `Δφ` against `φ̄` ([`phase_curves`](crate::model::experiments::phase_curves)), one
//!   panel per γ, normalized by `hν/2`, with the predicted `δ` dashed;
//! * `orbits.svg`: (sol) against the iterates and (discr sol)
//!   ([`orbit_comparison`](crate::model::experiments::orbit_comparison));
//! * `error-vs-h.svg`: log–log error against `h` with the fitted orders
//!   ([`fitted_orders`](crate::model::experiments::fitted_orders)).
//!
//! Labels use fixed-width formatting and no time or randomness enters, so the SVG bytes
//! are identical across runs.  Model failures are returned as an `io::Error` whose
//! message names the figure and the model error.

use crate::model::Regime;
use crate::model::experiments::CASES;
use std::io;
use std::path::Path;

/// The figures [`write_all`] writes, with a one-line caption each (file, caption).
pub const FIGURES: [(&str, &str); 4] = [
    (
        "dphi-vs-phibar.svg",
        "Δφ against φ̄ for γ0, γ1, γ2 and γ_VM at several h (upper regime): flat for the Poisson maps γ1, γ2, γ_VM, on the predicted δ; varying for γ0 (Proposition 5).",
    ),
    (
        "dphi-vs-phibar-lower.svg",
        "The same in the lower regime E/M² < 1/B.",
    ),
    (
        "orbits.svg",
        "The continuous solution (sol) against the discrete iterates and (discr sol).",
    ),
    (
        "error-vs-h.svg",
        "Error of the discrete solution against h at fixed time, log–log, with the fitted order.",
    ),
];

/// Every model figure as `(file name, SVG text)`, in a fixed order.
pub fn render_all() -> io::Result<Vec<(String, String)>> {
    let mut out = Vec::new();
    for case in &CASES {
        let name = match case.regime {
            Regime::Upper => "dphi-vs-phibar.svg".to_string(),
            _ => format!("dphi-vs-phibar-{}.svg", case.name),
        };
        out.push((name, super::phase::dphi_vs_phibar_svg(case)?));
    }
    out.push(("orbits.svg".to_string(), super::orbits::orbits_svg()?));
    out.push((
        "error-vs-h.svg".to_string(),
        super::order::error_vs_h_svg()?,
    ));
    Ok(out)
}

/// Writes the model figures ([`render_all`]) into `dir` (created if missing).
/// Errors name the figure and the failing model computation or file operation.
pub fn write_all(dir: &Path) -> io::Result<()> {
    let figs = render_all()?;
    std::fs::create_dir_all(dir)?;
    for (name, svg) in figs {
        let p = dir.join(&name);
        std::fs::write(&p, svg).map_err(|e| super::style::io_err(&p.display().to_string(), e))?;
    }
    Ok(())
}
