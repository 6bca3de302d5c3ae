//! One row of the orbit table: what `eulertop orbit` writes (orbit.rs) and draws
//! (orbit_svg.rs).

use crate::linalg::Vec3;

/// One row of the orbit table.
#[derive(Clone, Debug)]
pub struct Row<R> {
    /// Step index n.
    pub n: usize,
    /// `t = n·h`.
    pub t: R,
    /// The iterate `M_n`.
    pub m: Vec3<R>,
    /// The continuous solution `M(t)` through `M_0`.
    pub sol: Vec3<R>,
    /// `(φ̄, Δφ)` of the step `n−1 → n`.
    pub phase: Option<(R, R)>,
}
