//! The precision ladder of the model's Newton solvers: above [`LADDER_BITS`] bits a
//! solve starts at its own solution at about half the precision (computed the same way,
//! down to at most [`LADDER_BITS`] bits, where it starts at its usual predictor).
//! Newton's method doubles the number of correct bits with each step, so two or three
//! steps at full precision remain, where from the predictor there is about one per
//! doubling (for the phase steps nine at 4096 bits).

use super::{EllipticParams, Inertia, ModelError};
pub(crate) use crate::linalg::AtPrec;
use crate::numbers::Real;

/// The precision up to which the solvers start at their usual predictor; above it, at
/// the solution at `prec/2 + 32` bits.  Up to it every solve, and so every value, is the
/// same as without the ladder (the per-claim test runs at 53 and 256 bits).  At 1024 bits
/// the ladder does not pay: a Veselov–Moser step took 1.1 times as long with it.
pub const LADDER_BITS: u32 = 1024;

impl<R: Real> AtPrec for Inertia<R> {
    fn at_prec(&self, bits: u32) -> Self {
        self.map(|x| x.with_prec(bits))
    }
}

impl<R: Real> AtPrec for EllipticParams<R> {
    fn at_prec(&self, bits: u32) -> Self {
        self.map(|x| x.with_prec(bits))
    }
}

/// The solution `solve(q)` at `q = prec/2 + 32` bits, rounded back to `prec` bits, where
/// `prec` is the precision of `like`, when `prec` is above [`LADDER_BITS`] bits (and that
/// solve succeeds); otherwise none.  The caller iterates from there.
pub(crate) fn ladder<R: Real, T: AtPrec>(
    like: &R,
    solve: impl FnOnce(u32) -> Result<T, ModelError>,
) -> Option<T> {
    let prec = like.prec();
    if R::FIXED || prec <= LADDER_BITS {
        return None;
    }
    solve(prec / 2 + 32).ok().map(|x| x.at_prec(prec))
}
