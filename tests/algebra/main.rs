//! Integration tests of the symbolic algebra: the paper's identities written against the
//! algebra API, properties of the normal form, and the tower of square roots.

/// The allocator of the `eulertop` binary (mimalloc, serving GMP and FLINT too), so that
/// the tests run the product's configuration.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[path = "../algebra_identities/mod.rs"]
mod algebra_identities;

mod algebra_paper;
mod algebra_props;
mod algebra_tower;
