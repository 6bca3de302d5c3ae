//! # eulertop
//!
//! Formula-by-formula verification of A. I. Bobenko, B. Lorbeer and Yu. B. Suris,
//! *Integrable discretizations of the Euler top* (1998).
//!
//! Layers, each depending only on the ones before it:
//! numbers → special functions → (symbolic algebra) → model → claims → outputs.

#![warn(missing_docs)]
// `Scalar::from_i64(&self, ..)` takes `&self` on purpose: precision travels with values.
#![allow(clippy::wrong_self_convention)]

pub mod algebra;
pub mod claims;
pub mod cli;
pub mod linalg;
pub mod model;
pub mod numbers;
pub mod report;
pub mod special;
