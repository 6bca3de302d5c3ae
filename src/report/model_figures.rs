//! Figures of the Euler-top model (Δφ against φ̄, orbits, error against h).  Filled in
//! once the model layer is merged.

use std::path::Path;

/// Writes the model figures into `dir`.
pub fn write_all(_dir: &Path) -> std::io::Result<()> {
    Ok(())
}
