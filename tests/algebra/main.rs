//! Integration tests of the symbolic algebra: the paper's identities written against the
//! algebra API, properties of the normal form, and the tower of square roots.

#[path = "../algebra_identities/mod.rs"]
mod algebra_identities;

mod algebra_paper;
mod algebra_props;
mod algebra_tower;
