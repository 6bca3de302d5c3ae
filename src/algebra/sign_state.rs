//! The sign-only state of a ring: the signs its proof has proved (with the derivation
//! of each value, for certificates), the signs the claim states, the facts of the
//! theory (`dn > 0` of a real argument), the sign symbols of folded values, the first
//! sign left undecided, and the memo of the sign test.  Module `decide` reads
//! and writes it; the rest of the ring state knows nothing of signs.
//!
//! ```
//! use eulertop::algebra::{Ring, RingOptions};
//! let ring = Ring::new(RingOptions { points: 1, ..Default::default() });
//! assert!(ring.proved_signs().is_empty());
//! ```

use super::flint::Poly;
use super::node::Node;
use super::val::Val;
use std::sync::Arc;

/// A rational function of the claim's indeterminates whose sign is not constant on the
/// domain (module [`super::split`]).
#[derive(Clone, Debug)]
pub struct SignSplit {
    /// The value as the prover renders it (cut to a readable length).
    pub what: String,
    /// The whole rendering, by which a later ring recognises the value.
    pub(crate) text: String,
    pub(crate) num: Poly,
    pub(crate) den: Poly,
    /// The names of the context's variables (indeterminates by name, others empty).
    pub(crate) names: Vec<String>,
}

/// A sign symbol `σ = sign(x)` made for a folded value `x` (see
/// [`RingOptions::sign_folds`](super::RingOptions::sign_folds)).
#[derive(Clone, Debug)]
pub(crate) struct Folded {
    /// `x`, rendered.
    pub value: String,
    /// The symbol's name (`sgnx`).
    pub name: String,
    /// The symbol's root index.
    pub root: usize,
    /// `σ·x`, rendered: positive at every point, by the definition of `σ`.
    pub positive: String,
    /// The indeterminate of `x` (its context variable) and the sign of `σ` times it,
    /// by the definition of `σ` (`x` is a constant multiple of the indeterminate).
    pub var: Option<(usize, i32)>,
    /// `x` itself, which a certificate states as the symbol's definition.
    pub x: Val,
}

/// What a certificate names a fact of the theory by: the base of an elliptic table
/// whose `dn` the value is, or the derivation of `dn u` by the addition theorems.
#[derive(Clone, Debug)]
pub(crate) enum FactSource {
    /// `dn` of base `.1` of table `.0`.
    Base(usize, usize),
    /// The `dn` node of the derivation.
    Node(Arc<Node>),
    /// No derivation: a sign by this fact leaves the proof without a certificate.
    Unrecorded,
}

/// A value positive by a theorem of the Jacobi functions: `dn u > 0` for real `u` and
/// a real modulus with `0 < k² < 1` (DLMF 22.4.1).
#[derive(Clone, Debug)]
pub(crate) struct Fact {
    pub value: Val,
    pub why: String,
    pub source: FactSource,
}

/// The evidence of a sign a fact decides, as a certificate records it: the value (by its
/// derivation, or written out where it has none) is the fact's value times `factor`,
/// whose sign is proved with the parametrization of the domain.
#[derive(Clone, Debug)]
pub(crate) struct FactEvidence {
    pub node: Option<Arc<Node>>,
    pub value: Val,
    pub sign: i32,
    pub fact: usize,
    pub factor: Val,
}

/// The evidence of a sign a stated hypothesis decides, as a certificate records it: the
/// value (by its derivation), its sign, where the value is a square `(a/b)²` the quotient
/// `a/b` whose sign the hypothesis decides, and the hypothesis' label with the factor
/// `f` such that the value (or `a/b`) is the hypothesis' value times `f`.
#[derive(Clone, Debug)]
pub(crate) struct SignEvidence {
    pub node: Arc<Node>,
    pub sign: i32,
    pub square: Option<(Poly, Poly)>,
    pub label: String,
    pub factor: Val,
}

/// A sign of a value in a square root decided from the signs of its root-free parts
/// (module [`super::root_signs`]), some by the condition of the part of the domain the
/// proof is on or by a sign symbol's definition: a certificate states the value (by its
/// derivation, or written out) and its sign, which a recheck decides again from the parts.
#[derive(Clone, Debug)]
pub(crate) struct RootSignEvidence {
    pub node: Option<Arc<Node>>,
    pub value: Val,
    pub sign: i32,
}

/// The sign of `q = a² − b²·r²` that decided the sign of `a + b·r` by the side that
/// wins (rule 2b of module `decide`), with its evidence, for certificates: `q` is
/// `constant · Π gᵢ^kᵢ` and each factor `gᵢ` (`gᵢ²` for an even `kᵢ`) has a proved
/// sign, whose product with the constant's is `sign`.
#[derive(Clone, Debug)]
pub(crate) struct Dominance {
    pub q: Poly,
    pub sign: i32,
    pub constant: rug::Integer,
    pub factors: Vec<(Poly, u64)>,
}

/// The sign-only state of a ring (see the module).
#[derive(Default)]
pub(crate) struct SignState {
    /// Signs proved with the parametrization of the domain, with the derivation of each
    /// value (for certificates).
    pub proved_signs: Vec<(Option<Arc<Node>>, i32, String)>,
    /// The first sign that differed between domain points (module [`super::split`]).
    pub undecided: Option<SignSplit>,
    /// The sign symbols made for [`RingOptions::sign_folds`](super::RingOptions::sign_folds): the folded value (rendered),
    /// the symbol's name and root index, and `σ·x` rendered (positive by definition).
    pub folded: Vec<Folded>,
    /// The outcome of the sign test with the parametrization of the domain, by value
    /// (numerator, denominator); emptied when a root's values change.
    pub sign_memo: std::collections::HashMap<(Poly, Poly), Option<i32>>,
    /// The hypotheses the claim states: a value, its sign, and the hypothesis' label
    /// (see [`Ring::state_hypothesis`](super::Ring::state_hypothesis)).
    pub stated: Vec<(Val, i32, String)>,
    /// Values positive by a theorem (`dn` of a real argument), with the reason.
    pub facts: Vec<Fact>,
    /// The signs decided by a fact, with their evidence (for certificates).
    pub fact_evidence: Vec<FactEvidence>,
    /// Signs proved with the parametrization of values without a derivation of their
    /// own (made only for a decision): a certificate writes the value out.
    pub valued: Vec<(Val, i32)>,
    /// Opaque symbols declared real (by field-variable index).
    pub real_opaque: Vec<usize>,
    /// The signs decided by a stated hypothesis, with their evidence (for certificates).
    pub evidence: Vec<SignEvidence>,
    /// The signs decided from the signs of their parts in a square root (for
    /// certificates), in the order decided (a part's before its value's).
    pub root_signs: Vec<RootSignEvidence>,
    /// The signs of `a² − b²·r²` that decided signs of `a + b·r` by the side that wins
    /// (for certificates), in the order proved (a factor's before the value's).
    pub dominance: Vec<Dominance>,
}
