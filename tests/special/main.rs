//! Integration tests of the special functions and the number kernels: accuracy against
//! the reference tables of tests/data (mpmath, python-flint), properties, and sweeps.

/// The allocator of the `eulertop` binary (mimalloc, serving GMP and FLINT too), so that
/// the tests run the product's configuration.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[path = "../common/mod.rs"]
mod common;

mod ellint;
mod ellint2;
mod jacobi_builtins;
mod jacobi_complex;
mod jacobi_dual;
mod jacobi_inverse;
mod jacobi_pole;
mod jacobi_props;
mod jacobi_real;
mod jacobi_sweep;
mod jacobi_twelve;
mod numbers_kernel;
