//! The claims layer: the expression language, the catalogue loader, the sampler and the
//! verdict engine.  It knows nothing about the Euler top: other layers add functions
//! through [`registry::Registry`].  The language and the catalogue format are specified
//! in `identities/README.md`.

pub mod ast;
pub mod backend;
pub mod builtins;
pub mod catalogue;
pub mod eval;
pub mod latex;
pub mod lexer;
pub mod parser;
pub mod registry;
pub mod sampler;
pub mod structure;
pub mod value;
pub mod verdict;
