//! # eulertop
//!
//! Formula-by-formula verification of A. I. Bobenko, B. Lorbeer and Yu. B. Suris,
//! *Integrable discretizations of the Euler top* (1998).
//!
//! Layers, each depending only on the ones before it:
//! numbers and stats → special functions, linear algebra → symbolic algebra → model;
//! numbers → claims (the claim engine, which knows nothing of the Euler top) → bindings (the
//! model's functions in the catalogue) → outputs (cli, report).
//!
//! The numbers, special functions and linear algebra are the crate `eulertop-numerics`,
//! which depends on neither FLINT nor anything above it; they are re-exported here as
//! [`numbers`], [`special`] and [`linalg`].

#![warn(missing_docs)]
// `Scalar::from_i64(&self, ..)` takes `&self` on purpose: precision travels with values.
#![allow(clippy::wrong_self_convention)]

pub mod algebra;
pub mod allocator;
pub mod bindings;
pub mod claims;
pub mod cli;
pub mod model;
pub mod report;
pub mod stats;

pub use eulertop_numerics::{linalg, numbers, special};
