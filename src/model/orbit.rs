//! Orbits of the discrete maps: the iterates `M₁, M₂, …` of (discr eq) from a start point
//! `M₀`, for one [`Stepper`] — the implicit map (impl spec) with one of the four γ, or the
//! Veselov–Moser matrix algorithm (M thru omega), (VM).
//!
//! [`orbit`] is a lazy iterator: it computes one step per item and holds only the current
//! point, so an orbit of any length runs in constant memory.  The first failing step
//! yields its error and ends the orbit.
//!
//! ```
//! use eulertop::linalg::Vec3;
//! use eulertop::model::{orbit, Gamma, Inertia};
//! let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
//! let m0 = Vec3::new(0.3, -0.7, 1.1);
//! let pts: Vec<Vec3<f64>> = orbit(&i, Gamma::G1, &m0, &0.1)
//!     .take(5)
//!     .collect::<Result<_, _>>()
//!     .unwrap();
//! assert_eq!(pts.len(), 5);
//! // γ₁ preserves the Casimir M²
//! assert!((pts[4].norm2() - m0.norm2()).abs() < 1e-14);
//! ```

use super::discretization::{Gamma, step};
use super::veselov_moser::vm_step;
use super::{Inertia, ModelError};
use crate::linalg::Vec3;
use crate::numbers::Real;

/// One step `M ↦ M̂` of a discretization.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stepper {
    /// The implicit map (impl spec) with this γ, solved by Newton's method
    /// ([`super::discretization::step`]).
    Implicit(Gamma),
    /// The Veselov–Moser matrix algorithm: (M thru omega) solved for `ω`, then (VM)
    /// `M̂ = ωᵀMω` ([`super::veselov_moser::vm_step`]).
    Matrix,
}

impl From<Gamma> for Stepper {
    fn from(g: Gamma) -> Self {
        Stepper::Implicit(g)
    }
}

impl Stepper {
    /// One step from `m` with step size `h`.
    pub fn step<R: Real>(
        &self,
        inertia: &Inertia<R>,
        m: &Vec3<R>,
        h: &R,
    ) -> Result<Vec3<R>, ModelError> {
        match self {
            Stepper::Implicit(g) => step(inertia, *g, m, h),
            Stepper::Matrix => Ok(vm_step(inertia, m, h)?.m_hat),
        }
    }
}

/// The iterator returned by [`orbit`].
#[derive(Clone, Debug)]
pub struct Orbit<'a, R> {
    inertia: &'a Inertia<R>,
    stepper: Stepper,
    h: R,
    current: Option<Vec3<R>>,
}

impl<R: Real> Iterator for Orbit<'_, R> {
    type Item = Result<Vec3<R>, ModelError>;

    fn next(&mut self) -> Option<Self::Item> {
        let cur = self.current.take()?;
        match self.stepper.step(self.inertia, &cur, &self.h) {
            Ok(next) => {
                self.current = Some(next.clone());
                Some(Ok(next))
            }
            Err(e) => Some(Err(e)),
        }
    }
}

impl<R: Real> std::iter::FusedIterator for Orbit<'_, R> {}

/// The iterates `M₁, M₂, …` of `stepper` from `M₀ = m0` with step size `h`, one step
/// per item (endless unless a step fails; use [`Iterator::take`]).  A [`Gamma`] converts
/// into [`Stepper::Implicit`].
pub fn orbit<'a, R: Real>(
    inertia: &'a Inertia<R>,
    stepper: impl Into<Stepper>,
    m0: &Vec3<R>,
    h: &R,
) -> Orbit<'a, R> {
    Orbit {
        inertia,
        stepper: stepper.into(),
        h: h.clone(),
        current: Some(m0.clone()),
    }
}
