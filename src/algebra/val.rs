//! [`Val`]: the exact part of a value (a normal form `N/D`) with its numeric shadow.
//!
//! A `Val` carries no ring handle, so the ring's symbol table can store values (the
//! definitions of named quantities, the base arguments of the elliptic tables) without
//! reference cycles; [`super::Sym`] is a `Val` with its ring.

use super::flint::Poly;
use super::shadow::Shadow;

/// The exact part of a value with its shadow, without the ring handle (so the symbol
/// table can store values without reference cycles).
#[derive(Clone, Debug)]
pub(crate) struct Val {
    /// The numerator: a polynomial in the field variables and the roots, reduced
    /// modulo the roots' relations.
    pub num: Poly,
    /// The denominator: a polynomial in the field variables only.
    pub den: Poly,
    /// The values at the domain points.
    pub sh: Shadow,
}
