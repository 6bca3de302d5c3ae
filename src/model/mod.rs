//! The model layer: the Euler top (Section 2 of the paper), its elliptic
//! coordinates (Section 4), the special discretizations (Sections 5–7) and the
//! Veselov–Moser discretization (Section 8), generic over [`Real`](crate::numbers::Real)
//! scalars (`f64`, `rug::Float` at any precision, `Dual<R>` for derivatives).
//!
//! # Sign conventions (read this first)
//!
//! The paper prints the Euler equations twice:
//!
//! * in components, (ET): `Ṁ₁ = (1/B − 1/C) M₂M₃` and cyclic;
//! * in vector form, (ET v): `Ṁ = M × Ω(M)`.
//!
//! With the standard right-handed cross product `(a×b)₁ = a₂b₃ − a₃b₂`,
//! `(M × Ω)₁ = (1/C − 1/B) M₂M₃`, i.e. **(ET v) read with the standard `×` is the
//! negative of (ET)**: (ET) is `Ṁ = Ω × M`.  Everything else in the paper follows the
//! component form (ET):
//!
//! * the explicit solution (sol) with `abcν > 0` satisfies (ET) (and hence violates
//!   `Ṁ = M ×_std Ω`);
//! * the Poisson bracket (PB) `{M₁,M₂} = M₃` (i.e. `{F,G} = ⟨M, ∇F ×_std ∇G⟩`) with
//!   `H = E/2` and `Ṁ = {M, H}` gives (ET);
//! * (impl spec 1–3) in components is `M̂ − M = ¼hγ · (S ×_std Ω(S))` with the
//!   *opposite* sign, i.e. `¼hγ · Ω(S) ×_std S`, `S = M + M̂` — again the (ET) form;
//! * the hat map (M m) `M ↦ [[0, M₃, −M₂], [−M₃, 0, M₁], [M₂, −M₁, 0]]` is minus the
//!   usual hat map, so `[M̌, Ω̌] = (Ω ×_std M)ˇ`, and (ET m) `Ṁ = [M, Ω]` is (ET).
//!
//! So the paper's `×` is the left-handed product `a × b := b ×_std a` throughout.
//! This crate implements every discretization in the (ET) / (impl spec 1–3)
//! component convention; [`euler::Inertia::field_et`] is (ET) and
//! [`euler::Inertia::field_cross_std`] is the printed `M × Ω` with the standard cross
//! product, kept separately so that the mismatch can be recorded as a claim.

pub mod discretization;
pub mod elliptic_coords;
pub mod error;
pub mod euler;
pub mod experiments;
pub mod ladder;
pub mod lax;
pub mod orbit;
pub mod params;
pub mod phase;
pub mod solution;
pub mod veselov_moser;

pub use discretization::{Gamma, NewtonOptions, StepReport};
pub use elliptic_coords::{EllCoords, Sector};
pub use error::ModelError;
pub use euler::Inertia;
pub use orbit::{Orbit, Stepper, orbit};
pub use params::{EllipticParams, Regime};
