//! The symbolic algebra layer: exact proofs of identities by normal forms in a tower of
//! quadratic extensions of ℚ(x₁…xₙ), on FLINT 3.
//!
//! It sits between `special`/`linalg` and `claims` and imports neither claims, nor
//! report, nor cli.
//!
//! # Design
//!
//! * **Field.**  The claim's indeterminates and transcendental symbols (`sn` of base
//!   arguments, quarter periods, opaque symbols) generate K = ℚ(x₁…xₙ); polynomials are
//!   FLINT `fmpz_mpoly` in one context (module [`flint`], the only `unsafe` code).
//! * **Tower.**  Square roots adjoin symbols `rᵢ` with relations `rᵢ² = aᵢ`, `aᵢ` a
//!   polynomial in K's variables and earlier roots.  In the lexicographic order with
//!   later roots first, the leading terms `rᵢ²` are pairwise coprime, so the relations
//!   are a Gröbner basis and the normal form (degree < 2 in every root, a root-free
//!   denominator, gcd 1) is unique.  Radicands in K are factored and each irreducible
//!   factor gets one root shared by the ring, with GF(2)-independent classes modulo
//!   squares, so the tower over K is a field (module [`roots`]).
//! * **Shadows.**  Every value carries its value at a few domain points (complex MPFR,
//!   256 bits by default), computed alongside.  Signs, branches of square roots and
//!   comparisons are proved where [`positivity`] proves them (with
//!   [`RingOptions::positivity`], a parametrization of the domain); otherwise they are
//!   decided from the shadows and recorded as [`Assumption`]s; disagreeing points give
//!   [`AlgebraError::CannotDecide`]; an exact 0 with a non-zero shadow is an internal
//!   error.
//! * **Elliptic functions.**  `sn`, `cn`, `dn` of arguments that are integer
//!   combinations of base arguments and of `K/2`, `iK'/2` are expanded by DLMF 22.8,
//!   22.4.3 and 22.5.1 (module [`elliptic`]); each base has symbols `s`, `c`, `d` with
//!   `c² = 1 − s²`, `d² = 1 − k²s²`.
//! * **Derivatives** are a derivation of the tower (module [`derive`]), including the
//!   derivative in the modulus through one more symbol `Z = E(am u, k) − k'²u`.
//! * **Proofs** ([`prove_identity`], [`Ring::prove`]): the normal form of `lhs − rhs`
//!   is 0.  A non-zero normal form proves nothing.  Named quantities (such as `k`, `ν`)
//!   are free symbols first and replaced by their definitions only if needed.
//!   Certificates (module [`certificate`]) are rechecked by SymPy with
//!   `scripts/recheck-certificates.py`.
//!
//! # Layers
//!
//! The files import one another one way, bottom to top: [`flint`], [`shadow`] and the
//! errors; the value `Val` (a normal form with its shadow), the classes modulo squares,
//! the lattice of arguments; the derivation DAG of certificates and the elliptic
//! tables' data; the ring's state (`ring`: options, symbol table, assumptions and its
//! plumbing); [`Sym`] and its arithmetic; then square roots ([`roots`]), comparisons,
//! the claim's symbols, the addition theorems, [`elliptic`], the jet symbols of the ODE
//! method (module `jets`), derivatives and the change of variables, opaque functions,
//! [`certificate`], the scalar traits; and proofs on top: normal forms (module `proof`)
//! and the uniqueness of the solution of an ODE ([`ode`]).
//! `Ring` has `impl` blocks in the module of each concept ([`Ring::i`] in [`roots`],
//! [`Ring::quarter_period`] in [`elliptic`], …), so no lower file needs a higher one.
//!
//! # Using it from an expression evaluator
//!
//! 1. Per claim, [`prove_components`] with a closure that builds both sides on the ring
//!    it is given (the closure may run more than once: after a refinement of the
//!    elliptic base arguments, and with named quantities expanded).
//! 2. Each variable of the claim: [`Ring::indeterminate`] with its values at the
//!    domain points (the sampler's points); numbers: [`Ring::rational`]; `i`:
//!    [`Ring::i`]; definitions such as `k`, `nu`: [`Ring::named`] (free symbol first);
//!    quarter periods: [`Ring::quarter_period`], [`Ring::quarter_period_prime`]; values
//!    the prover cannot expand (`u0`): [`Ring::opaque`].
//! 3. Operators `+ − × ÷`, [`Sym::try_powi`], [`Sym::sqrt`], [`Sym::sncndn`],
//!    [`Sym::derivative`], [`Sym::abs`], [`Sym::sign`], comparisons
//!    ([`Sym::compare`] or `PartialOrd`), and [`Sym::function`] for functions by name
//!    (which refuses exp, ln, asin, am, F, … with [`AlgebraError::NotAlgebraic`]).
//!    Wrap the evaluation of a definition in [`Ring::with_origin`] so its decisions are
//!    recorded as coming from that definition.
//! 4. Generic model code over [`crate::numbers::Real`] runs on [`Sym`] unchanged;
//!    transcendental functions then record an error in the ring ([`Ring::error`]) and
//!    the proof reports it.
//! 5. The [`Proof`] carries the outcome, symbols, relations, assumptions, notes,
//!    size, time and (with [`RingOptions::certificate`]) the certificate.
//!
//! # Limits
//!
//! * Radicands with roots in them are tested for being squares by denesting; otherwise
//!   they get a root of their own, and such towers may have zero divisors (a non-zero
//!   normal form then proves nothing, as always).
//! * Half periods: multiples of `K/2` and `iK'/2` only; the derivative of `K(k)` in a
//!   varying modulus is refused (it would need `E(k)`).  The derivative of an inverse of
//!   sn, cn, dn in a varying modulus takes one more symbol `Z = E(am v, k) − k'²v` per
//!   inverse (certificates give it in the inverse's `inverse` line).
//! * Signs, branches and comparisons are decided in one place (module `decide`, with
//!   [`Decision`]): exact, proved on a parametrization of the domain by positive
//!   parameters ([`positivity`]) and through square roots, given by a hypothesis, or
//!   fixed by the definition of a sign symbol.  The values at the domain points never
//!   decide one: an undecided sign stops the proof (and may split the domain,
//!   [`split`]).
//!
//! # Example
//!
//! The addition formula for `sn` (DLMF 22.8.1):
//!
//! ```
//! use eulertop::algebra::{prove_identity, RingOptions};
//! let proof = prove_identity(RingOptions::default(), "DLMF 22.8.1", |r| {
//!     let u = r.indeterminate_f64("u", &[0.3, -0.8, 1.2])?;
//!     let v = r.indeterminate_f64("v", &[0.5, 0.4, -1.7])?;
//!     let k = r.indeterminate_f64("k", &[0.5, 0.9, 0.1])?;
//!     let (su, cu, du) = u.sncndn(&k)?;
//!     let (sv, cv, dv) = v.sncndn(&k)?;
//!     let lhs = (&u + &v).sn(&k)?;
//!     let num = &(&su * &cv) * &dv + &(&sv * &cu) * &du;
//!     let den = r.integer(1) - &(&(&k * &k) * &(&su * &su)) * &(&sv * &sv);
//!     Ok((lhs, num / den))
//! });
//! assert!(proof.is_proved(), "{:?}", proof.outcome);
//! ```

mod addition;
mod algebraic;
mod base_table;
mod budget;
pub mod certificate;
mod coordinates;
mod decide;
mod den_factors;
mod derive;
pub mod elliptic;
mod elliptic_facts;
mod error;
pub mod flint;
mod jets;
mod lattice;
mod node;
pub mod ode;
mod opaque;
mod order;
pub mod parametrization;
pub mod positivity;
mod proof;
mod ring;
mod root_signs;
pub mod roots;
mod scalar;
pub mod series;
mod series_modulus;
mod series_scalar;
pub mod series_solve;
mod series_trace;
pub mod shadow;
pub mod sign_state;
pub mod split;
mod square_classes;
mod sym;
mod symbols;
mod thirds;
mod val;
pub mod witness;

pub use budget::{BUDGET_MESSAGE, Budget, DEFAULT_MEMORY_MB, DEFAULT_TIME_MS, set_default_budget};
pub use decide::Decision;
pub use elliptic::BaseHint;
pub use error::{AlgResult, AlgebraError};
pub use proof::{Outcome, Proof, prove_components, prove_identity};
pub use ring::{Assumption, AssumptionKind, Origin, Ring, RingOptions};
pub use sym::Sym;
