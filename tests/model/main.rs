//! Integration tests of the model of the Euler top: the discretizations, the elliptic
//! coordinates, the Lax matrices, the Poisson property and bad input.

/// The allocator of the `eulertop` binary (mimalloc, serving GMP and FLINT too), so that
/// the tests run the product's configuration.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

mod model_discretization;
mod model_elliptic;
mod model_ladder;
mod model_lax;
mod model_poisson;
mod model_robust;
