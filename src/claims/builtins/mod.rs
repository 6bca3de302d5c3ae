//! The names the language knows without a catalogue: built-in functions ([`Builtin`])
//! and the random primitives of samplers ([`Primitive`]).  Each is declared once, in
//! [`names`] and [`primitives`]; the evaluator ([`mod@apply`]), the load-time checker, the
//! LaTeX writer and the tables of `identities/README.md` read those declarations.
//!
//! ```
//! use eulertop::claims::builtins::{Arity, Builtin};
//! let b = Builtin::from_name("jacobi_inverse").unwrap();
//! assert_eq!(b.spec().arity, Arity::Exact(4));
//! assert_eq!(b.spec().signature(), "jacobi_inverse(s, c, d, k)");
//! ```

pub mod apply;
pub mod names;
pub mod primitives;
pub mod table;

pub use apply::apply;
pub use names::{Builtin, Group, Spec, Tex};
pub use primitives::{Primitive, PrimitiveSpec};
pub use table::Arity;
