//! The claims layer: the expression language, the catalogue loader, the sampler and the
//! verdict engine.  It knows nothing about the Euler top: other layers add functions
//! through [`registry::Registry`] (the model does, in [`crate::bindings`]).  The
//! language and the catalogue format are specified in `identities/README.md`; the
//! [`tutorial`] follows one claim from TOML to verdict.
//!
//! Modules, from the bottom: [`ast`], [`lexer`], [`parser`] (text → syntax);
//! [`backend`] (number systems), [`cmath`], [`value`] (values of the language);
//! [`builtins`] (the built-in functions and random primitives, declared once);
//! [`registry`] (host and catalogue functions); [`eval`] (the evaluator); [`latex`];
//! [`kind`] (kinds, forms, verdicts); [`catalogue`] (TOML → claims, with the paper's
//! [`structure`]); [`sampler`]; [`verdict`] (claims → results).

pub mod ast;
pub mod backend;
pub mod builtins;
pub mod catalogue;
pub mod cmath;
pub mod eval;
pub mod implicit;
pub mod kind;
pub mod latex;
pub mod lexer;
mod memo;
pub mod parser;
pub mod registry;
pub mod sampler;
pub mod tutorial;
pub mod value;
pub mod verdict;

pub use catalogue::structure;
