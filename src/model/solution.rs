//! The explicit solution (sol) of (ET) and the discrete solution (discr sol).

use super::elliptic_coords::{EllCoords, m_to_phi, phi_to_m};
use super::{Inertia, ModelError};
use crate::linalg::Vec3;
use crate::numbers::Real;

/// The solution (sol) through `m0` at `t = 0`, evaluated at time `t`:
/// `M(t) = Φ(M², E, ν·(t − t₀))` with `t₀ = −φ₀/ν`, `φ₀ = Φ⁻¹(m0)`, `ν > 0` and the
/// sector signs of [`elliptic_coords`](super::elliptic_coords) (so `abcν > 0`).
/// Hyperbolic formulas on the separatrix.
pub fn continuous<R: Real>(
    inertia: &Inertia<R>,
    m0: &Vec3<R>,
    t: &R,
) -> Result<Vec3<R>, ModelError> {
    let c = m_to_phi(inertia, m0)?;
    continuous_from(&c, t)
}

/// (sol) exactly in the paper's form: `M(t) = Φ(M², E, ν·(t − t₀))` for given
/// parameters (from [`EllipticParams::new`](super::EllipticParams::new)), sector
/// signs and `t₀`; upper/lower expressions and the hyperbolic separatrix case by
/// `p.regime`.
pub fn sol<R: Real>(
    p: &super::EllipticParams<R>,
    sector: super::Sector,
    t: &R,
    t0: &R,
) -> Result<Vec3<R>, ModelError> {
    let phi = p.nu() * (t.clone() - t0.clone());
    phi_to_m(p, sector, &phi)
}

/// (sol) from already computed elliptic coordinates of the start point.
pub fn continuous_from<R: Real>(c: &EllCoords<R>, t: &R) -> Result<Vec3<R>, ModelError> {
    let phi = c.phi.clone() + c.params.nu() * t.clone();
    phi_to_m(&c.params, c.sector, &phi)
}

/// (discr sol): `M_m = Φ(M², E, 2mδ + φ₀)` for the start point's coordinates `c`
/// and a phase step `δ` (e.g. from [`phase`](super::phase)).
pub fn discrete_from<R: Real>(c: &EllCoords<R>, delta: &R, m: i64) -> Result<Vec3<R>, ModelError> {
    let phi = c.phi.clone() + delta.from_i64(2 * m) * delta.clone();
    phi_to_m(&c.params, c.sector, &phi)
}
