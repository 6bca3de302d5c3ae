//! Integration tests of the model of the Euler top: the discretizations, the elliptic
//! coordinates, the Lax matrices, the Poisson property and bad input.

mod model_discretization;
mod model_elliptic;
mod model_lax;
mod model_poisson;
mod model_robust;
