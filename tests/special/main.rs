//! Integration tests of the special functions and the number kernels: accuracy against
//! the reference tables of tests/data (mpmath, python-flint), properties, and sweeps.

#[path = "../common/mod.rs"]
mod common;

mod ellint;
mod jacobi_builtins;
mod jacobi_complex;
mod jacobi_dual;
mod jacobi_inverse;
mod jacobi_props;
mod jacobi_real;
mod jacobi_sweep;
mod jacobi_twelve;
mod numbers_kernel;
