//! A loaded catalogue: claims with their parsed expressions, domains, and the function
//! table.

use super::source::{Located, Origin};
use crate::claims::ast::{Binding, Expr};
use crate::claims::kind::{Form, Kind, Verdict};
use crate::claims::registry::Registry;
use std::collections::BTreeMap;

/// A parsed expression with its source text and origin.
#[derive(Debug, Clone)]
pub struct PExpr {
    /// The syntax tree.
    pub expr: Expr,
    /// The text as written.
    pub text: String,
    /// Where it is.
    pub origin: Origin,
}

/// The kind-specific part of a claim.
#[derive(Debug, Clone)]
pub enum Body {
    /// lhs == rhs.
    Identity {
        /// Left side.
        lhs: PExpr,
        /// Right side.
        rhs: PExpr,
    },
    /// expr independent of `wrt`.
    Independence {
        /// The expression.
        expr: PExpr,
        /// The redrawn variable.
        wrt: String,
        /// Number of redraws.
        redraws: usize,
    },
    /// expr = O(var^order).
    Asymptotic {
        /// The expression.
        expr: PExpr,
        /// The small variable (set by the engine).
        var: String,
        /// Claimed order.
        order: f64,
        /// Largest h.
        h0: f64,
        /// Number of halvings.
        steps: usize,
        /// Slope tolerance.
        slope_tol: f64,
    },
    /// The inner claim is refuted.
    Negation(Box<Claim>),
    /// A solution of the equations exists.
    Existence {
        /// Unknown names.
        unknowns: Vec<String>,
        /// Equations (= 0).
        equations: Vec<PExpr>,
        /// Start expressions (sampling context).
        start: Vec<PExpr>,
        /// Membership predicate.
        in_set: Option<PExpr>,
        /// Attempts per sample.
        tries: usize,
    },
    /// Function definitions.
    Definition(Vec<Binding>),
}

/// Exact-evaluation settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactSpec {
    /// Number of exact points.
    pub samples: usize,
}

/// A proof hint (identity claims): the paper's multipliers of the defining equations.
///
/// The `let` named `value` is a call of an implicit function (a step of a map).  With
/// the hint, the prover does not parametrize that call: its value becomes unknowns
/// `M̂`, `R` are the function's equations at `M̂`, and the claim is proved when every
/// component `(lhs − rhs)ⱼ − ⟨qⱼ, R⟩` has the normal form 0 (ideal membership with the
/// given multipliers `qⱼ`).  A wrong hint leaves a remainder: the claim is then not
/// proved, whatever other route might have served.
#[derive(Debug, Clone)]
pub struct Hint {
    /// The `let` that holds the implicit call.
    pub value: String,
    /// One multiplier per component of `lhs − rhs`, each with as many components as
    /// the equations.
    pub multipliers: Vec<PExpr>,
    /// Where the hint is.
    pub origin: Origin,
}

/// A hypothesis a proof may rest on (`[hypothesis.NAME]`): the paper states it, the
/// catalogue quotes it, and a claim that lists it in `hypotheses` states it.
#[derive(Debug, Clone)]
pub struct Hypothesis {
    /// The table's name.
    pub name: String,
    /// What it says.
    pub statement: String,
    /// The paper's words (where and how it says it).
    pub paper: String,
    /// What it fixes.
    pub kind: HypothesisKind,
    /// Where it is written.
    pub origin: Origin,
}

/// What a [`Hypothesis`] fixes.
#[derive(Debug, Clone)]
pub enum HypothesisKind {
    /// The solution branch of an implicit map (its name), which the solver selects.
    Branch(String),
    /// A condition `lhs > rhs` or `lhs < rhs`: the sign of `lhs − rhs`.
    Sign {
        /// The comparison as written.
        condition: PExpr,
        /// `1` for `>`, `−1` for `<`.
        sign: i32,
    },
}

/// A sampling domain.
#[derive(Debug, Clone)]
pub struct Domain {
    /// Name.
    pub name: String,
    /// Variables in order.
    pub vars: Vec<(String, PExpr)>,
    /// What a variable is, where the catalogue says so (the third string of its `vars`
    /// entry), by name.
    pub about: BTreeMap<String, String>,
    /// Constraints.
    pub wheres: Vec<PExpr>,
}

/// One loaded claim.
#[derive(Debug, Clone)]
pub struct Claim {
    /// Unique id.
    pub id: String,
    /// Paper labels.
    pub labels: Vec<String>,
    /// Human location.
    pub location: String,
    /// Verbatim LaTeX.
    pub printed: String,
    /// Kind.
    pub kind: Kind,
    /// Printed or corrected.
    pub form: Form,
    /// Fixed printed claim id.
    pub corrects: Option<String>,
    /// Expected verdict (`None` for definitions and inner claims).
    pub expect: Option<Verdict>,
    /// Note.
    pub note: Option<String>,
    /// `file:line` of the claim.
    pub position: String,
    /// The sampling domain, by name.
    pub domain: Option<Located>,
    /// Extra sampled variables.
    pub vars: Vec<(String, PExpr)>,
    /// What an extra sampled variable is, where the catalogue says so, by name.
    pub var_about: BTreeMap<String, String>,
    /// Extra constraints.
    pub wheres: Vec<PExpr>,
    /// Let bindings.
    pub lets: Vec<Binding>,
    /// Where the let block is.
    pub lets_origin: Option<Origin>,
    /// Kind-specific data.
    pub body: Body,
    /// Residual scale expression.
    pub scale: Option<PExpr>,
    /// Number of samples.
    pub samples: usize,
    /// Exact settings.
    pub exact: Option<ExactSpec>,
    /// Bound g on bits lost.
    pub max_loss_bits: f64,
    /// Refutation floor 2^-bits.
    pub refute_floor_bits: f64,
    /// Seed.
    pub seed: u64,
    /// The paper's environment ("Proposition 6", "Section 2", …); see `structure`.
    pub environment: Option<Located>,
    /// The claim's role in its environment (statement, proof-step, …).
    pub role: Option<Located>,
    /// Ids of the claims this one uses.
    pub uses: Vec<Located>,
    /// A proof hint (identity claims only).
    pub hint: Option<Hint>,
    /// The hypotheses the claim states (names of [`Hypothesis`] tables).
    pub hypotheses: Vec<Located>,
    /// Why the claim holds by construction: its equation is the one by which the model
    /// defines its map (`None` for a claim with content).
    pub construction: Option<String>,
}

/// The whole catalogue.
#[derive(Clone, Debug)]
pub struct Catalogue {
    /// Claims in file order (files sorted by name).
    pub claims: Vec<Claim>,
    /// Domains by name.
    pub domains: BTreeMap<String, Domain>,
    /// Functions: registered + defined by `definition` claims.
    pub registry: Registry,
    /// Sections: (file, number, title).
    pub sections: Vec<(String, String, String)>,
    /// Whether the lemmas that proofs rest on are proved (filled as they are checked).
    pub lemma_memo: LemmaMemo,
    /// The source, from the `[paper]` table (`None` when no file has one).
    pub paper: Option<super::paper::Paper>,
    /// The environments claims may name, in the paper's order: the `[paper]` table's
    /// list, or, without one, the names the claims use.
    pub environments: Vec<super::paper::EnvironmentSpec>,
    /// The hypotheses claims may state, by name.
    pub hypotheses: BTreeMap<String, Hypothesis>,
}

impl Catalogue {
    /// Combines every claim's seed (and its inner claim's) with `seed`; 0 keeps them.
    ///
    /// ```
    /// use eulertop::claims::catalogue::load_sources;
    /// use eulertop::claims::registry::Registry;
    /// let toml = r#"
    /// [[claim]]
    /// id = "c"
    /// location = "anywhere"
    /// printed = 'x = x'
    /// environment = "Section 2"
    /// role = "statement"
    /// kind = "identity"
    /// expect = "holds"
    /// vars = [["x", "uniform(-3, 3)"]]
    /// lhs = "x"
    /// rhs = "x"
    /// "#;
    /// let mut cat = load_sources(&[("t.toml".into(), toml.into())], Registry::new()).unwrap();
    /// let own = cat.claims[0].seed;
    /// cat.reseed(0);
    /// assert_eq!(cat.claims[0].seed, own);
    /// cat.reseed(3);
    /// assert_ne!(cat.claims[0].seed, own);
    /// ```
    pub fn reseed(&mut self, seed: u64) {
        if seed == 0 {
            return;
        }
        let mix = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15).rotate_left(17);
        for c in &mut self.claims {
            c.seed ^= mix;
            if let Body::Negation(inner) = &mut c.body {
                inner.seed ^= mix;
            }
        }
    }

    /// The hypotheses a claim states.
    pub fn hypotheses_of<'a>(&'a self, claim: &Claim) -> Vec<&'a Hypothesis> {
        (claim.hypotheses.iter())
            .filter_map(|h| self.hypotheses.get(&h.value))
            .collect()
    }
}

/// Memo of symbolic proofs: key → the proof record (of the verdict layer's type), so
/// that a lemma, or a statement the paper makes twice, is proved once per catalogue
/// whichever claim asks first.  Shared by the clones of a catalogue, which have the same
/// claims.
#[derive(Clone, Default)]
pub struct LemmaMemo(
    pub std::sync::Arc<std::sync::Mutex<BTreeMap<String, std::sync::Arc<MemoSlot>>>>,
);

/// A memoised proof record.
pub type LemmaRecord = std::sync::Arc<dyn std::any::Any + Send + Sync>;

/// One entry of a [`LemmaMemo`]: whether its computation has started, and its record.
#[derive(Default)]
pub struct MemoSlot {
    /// Set by the one caller that computes the record.
    pub started: std::sync::atomic::AtomicBool,
    /// The record, once computed.
    pub value: std::sync::OnceLock<LemmaRecord>,
}

impl std::fmt::Debug for LemmaMemo {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("LemmaMemo")
    }
}

impl LemmaMemo {
    /// The slot of `key` (created empty).
    pub fn slot(&self, key: &str) -> std::sync::Arc<MemoSlot> {
        match self.0.lock() {
            Ok(mut m) => m.entry(key.to_string()).or_default().clone(),
            Err(_) => std::sync::Arc::new(MemoSlot::default()),
        }
    }
}
