//! # eulertop-numerics
//!
//! The numbers layer of eulertop, usable on its own: one scalar abstraction over `f64`,
//! MPFR ([`rug::Float`]), MPC, exact rationals and dual numbers ([`numbers`]); the
//! Jacobi elliptic functions, elliptic integrals, nome and theta functions written once
//! over it ([`special`]); small dense linear algebra and Newton's method ([`linalg`]).
//! It depends on `rug` (GMP, MPFR, MPC) and the `num` crates only; the optional feature
//! `arb` adds FLINT's Arb ball arithmetic (`numbers::Ball`, `linalg::krawczyk`) and
//! Arb's `sin_cos` in the multi-precision Landen chain.
//!
//! ```
//! use eulertop_numerics::special::sncndn;
//! let (sn, cn, dn) = sncndn(&0.7_f64, &0.8).unwrap();
//! assert!((sn * sn + cn * cn - 1.0).abs() < 1e-15);
//! let u = rug::Float::with_val(256, 0.7);
//! let (s, c, _) = sncndn(&u, &rug::Float::with_val(256, 0.8)).unwrap();
//! assert!((s.clone() * &s + c.clone() * &c - 1u32).abs() < 1e-75);
//! assert!((s.to_f64() - sn).abs() < 1e-15 && dn > 0.0);
//! ```

#![warn(missing_docs)]
// `Scalar::from_i64(&self, ..)` takes `&self` on purpose: precision travels with values.
#![allow(clippy::wrong_self_convention)]

pub mod linalg;
pub mod numbers;
pub mod special;

/// The `rug` crate (GMP, MPFR, MPC), whose `Float` and `Complex` are the multi-precision
/// scalars, so that a program needs no dependency line of its own for it.
///
/// ```
/// use eulertop_numerics::rug::Float;
/// assert_eq!(Float::with_val(256, 0.5).prec(), 256);
/// ```
pub use rug;
