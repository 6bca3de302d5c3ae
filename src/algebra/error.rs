//! Errors of the algebra layer.

use super::flint::FlintError;

/// Why a symbolic computation could not go on.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AlgebraError {
    /// A function that is not algebraic over the tower (exp, ln, asin, F, am, …).
    #[error("{0} is not algebraic: the symbolic prover cannot expand it")]
    NotAlgebraic(String),
    /// A sign, branch or comparison on which the domain points disagree.
    #[error("cannot decide {0}")]
    CannotDecide(String),
    /// Division by an exact zero.
    #[error("division by zero")]
    DivisionByZero,
    /// Division by a non-zero element whose norm vanishes (the tower is not a field).
    #[error("division by a zero divisor ({0})")]
    ZeroDivisor(String),
    /// A pole of an elliptic function.
    #[error("pole: {0}")]
    Pole(String),
    /// More symbols than the ring was made for.
    #[error("too many symbols: {0}")]
    Capacity(String),
    /// Input outside what the layer accepts (a bad name, a wrong number of values, …).
    #[error("{0}")]
    Domain(String),
    /// An intermediate value exceeds the prover's size bound (a deterministic bound, so
    /// the outcome does not depend on the machine).
    #[error("an intermediate expression has {0} terms, above the prover's bound of {1}")]
    TooLarge(usize, usize),
    /// The attempt ran out of its budget of time or memory (see [`super::Budget`]).
    #[error("the proof exceeded its budget ({0})")]
    Budget(String),
    /// A derivative with respect to something that is not an indeterminate, or through
    /// a symbol whose derivative is unknown.
    #[error("derivative: {0}")]
    Derivative(String),
    /// An inconsistency between the exact normal form and its numeric shadow: a bug.
    #[error("internal inconsistency: {0}")]
    Internal(String),
    /// Values of two different rings were combined.
    #[error("values of different rings were combined")]
    RingMismatch,
    /// FLINT declined an operation.
    #[error("FLINT: {0}")]
    Flint(#[from] FlintError),
}

/// Result type of the algebra layer.
pub type AlgResult<T> = Result<T, AlgebraError>;
