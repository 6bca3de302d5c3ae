//! # eulertop
//!
//! Formula-by-formula verification of A. I. Bobenko, B. Lorbeer and Yu. B. Suris,
//! *Integrable discretizations of the Euler top* (1998).
//!
//! Layers, each depending only on the ones before it:
//! numbers → special functions → model → claims → outputs.

#![warn(missing_docs)]

pub mod claims;
pub mod cli;
pub mod linalg;
pub mod numbers;
pub mod report;
