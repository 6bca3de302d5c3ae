//! The plain data of a sample that failed and of a claim that could not be judged:
//! [`Named`] values, [`FailedSample`] and [`Cause`].  A leaf of the verdict engine: it
//! imports nothing from the other verdict modules.

use serde::Serialize;

/// A named value.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Named {
    /// Name.
    pub name: String,
    /// Rendered value.
    pub value: String,
}

/// A sample that could not be evaluated.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct FailedSample {
    /// The point.
    pub point: Vec<Named>,
    /// Rung (bits) where it failed, 0 for sampling / exact.
    pub bits: u32,
    /// What went wrong.
    pub message: String,
}

/// Why a claim could not be judged.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Cause {
    /// The precision ladder is empty.
    #[error("empty precision ladder")]
    EmptyLadder,
    /// The domain cannot be sampled (the message names the variable or constraint).
    #[error("{0}")]
    Sampling(String),
    /// As many samples failed as were asked for.
    #[error("{count} samples could not be evaluated (first: {first})")]
    Unevaluable {
        /// How many failed.
        count: usize,
        /// The first failure's message.
        first: String,
    },
    /// An existence claim found no f64 solution at a sample.
    #[error("no solution found: {0}")]
    NoSolution(String),
    /// Another layer panicked (a bug there).
    #[error("internal error (panic) while evaluating: {0}")]
    Panic(String),
    /// A counted condition has the same value at every sample (see
    /// [`vacuity`](super::vacuity)).
    #[error(
        "vacuous on domain {domain}: the condition {condition} is {value} at all {samples} samples, so the claim never meets the case it is about"
    )]
    Vacuous {
        /// The domain's name.
        domain: String,
        /// The condition as written.
        condition: String,
        /// Its value at every sample.
        value: bool,
        /// How many samples evaluated it.
        samples: usize,
    },
}
