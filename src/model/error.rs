//! The error type of the model layer.

/// Errors of the Euler-top model.  Every message is one line naming the quantity.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// Moments of inertia violating (ABC) `A > B > C > 0`.
    #[error("moments of inertia must satisfy A > B > C > 0 (ABC), got A={a}, B={b}, C={c}")]
    InvalidInertia {
        /// A as decimal text.
        a: String,
        /// B as decimal text.
        b: String,
        /// C as decimal text.
        c: String,
    },
    /// A quantity that is undefined at the given point (e.g. φ on a coordinate axis).
    #[error("{0}")]
    Undefined(String),
    /// Newton's method did not converge.
    #[error(
        "Newton iteration for {what} did not converge after {iterations} iterations (relative residual {residual:e}); step size h too large?"
    )]
    NewtonFailed {
        /// What was being solved.
        what: String,
        /// Iterations done.
        iterations: usize,
        /// Last relative residual (as f64).
        residual: f64,
    },
    /// The square root in γ_VM (gammaMV) is imaginary: `1 − ¼h²‖Ω(M+M̂)‖² < 0`.
    #[error("gamma_VM undefined: 1 - h^2 |Omega(M+M^)|^2 / 4 = {0:e} < 0 (h too large)")]
    ImaginarySqrt(f64),
    /// An error from the special-functions layer.
    #[error("special function: {0}")]
    Special(String),
}

impl From<crate::special::SpecialError> for ModelError {
    fn from(e: crate::special::SpecialError) -> Self {
        ModelError::Special(e.to_string())
    }
}
