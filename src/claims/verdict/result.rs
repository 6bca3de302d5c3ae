//! What verification produces: [`ClaimResult`] (everything the report writer needs),
//! the [`Evidence`] each kind returns, and the typed [`Failure`] of a kind that could not
//! reach a verdict.

pub use super::failure::{Cause, FailedSample, Named};
use super::proof_info::ProofInfo;
use crate::claims::catalogue::{Body, Claim};
use crate::claims::kind::{Form, Kind, Verdict};
use crate::claims::latex::{binding_to_latex, to_latex};
use serde::ser::SerializeStruct;
use serde::{Serialize, Serializer};

/// The result at one rung of the precision ladder.
#[derive(Clone, Debug, PartialEq)]
pub enum Rung {
    /// The worst scaled residual over the samples (identity, independence, existence).
    Residual {
        /// Precision in bits.
        bits: u32,
        /// log2 of the residual (−∞: exactly zero).
        log2: f64,
    },
    /// The smallest fitted slope over the samples (asymptotic claims).
    Slope {
        /// Precision in bits.
        bits: u32,
        /// The slope of log2 |expr| against log2 h.
        slope: f64,
    },
}

impl Rung {
    /// Precision in bits.
    pub fn bits(&self) -> u32 {
        match self {
            Rung::Residual { bits, .. } | Rung::Slope { bits, .. } => *bits,
        }
    }
    /// log2 of the residual; `None` for an exact zero and for slopes.
    pub fn log2(&self) -> Option<f64> {
        match self {
            Rung::Residual { log2, .. } if log2.is_finite() => Some(*log2),
            _ => None,
        }
    }
    /// The fitted slope of an asymptotic claim.
    pub fn slope(&self) -> Option<f64> {
        match self {
            Rung::Slope { slope, .. } => Some(*slope),
            Rung::Residual { .. } => None,
        }
    }
    /// Is this the fitted slope of an asymptotic claim?
    pub fn is_slope(&self) -> bool {
        matches!(self, Rung::Slope { .. })
    }
    /// The residual `2^log2` (may underflow to 0 in f64: use [`Rung::log2`]), or the
    /// slope.
    pub fn value(&self) -> f64 {
        match self {
            Rung::Residual { log2, .. } => log2.exp2(),
            Rung::Slope { slope, .. } => *slope,
        }
    }
}

/// Serialised as `{"bits", "residual", "log2"}`: for a slope, `residual` is the slope
/// and `log2` is null.
impl Serialize for Rung {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut st = s.serialize_struct("Rung", 3)?;
        st.serialize_field("bits", &self.bits())?;
        st.serialize_field("residual", &self.value())?;
        st.serialize_field("log2", &self.log2())?;
        st.end()
    }
}

/// A counterexample.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Counterexample {
    /// Precision of the values shown ("exact" = 0).
    pub bits: u32,
    /// The sample point.
    pub point: Vec<Named>,
    /// Left side (or the expression) there.
    pub lhs: String,
    /// Right side (or the comparison value) there.
    pub rhs: String,
    /// Residual (log2).
    pub log2_residual: Option<f64>,
}

/// Evidence of an exact evaluation.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct ExactInfo {
    /// Rational points evaluated.
    pub points: usize,
    /// Smallest primitive set size |S| (None: a non-uniform primitive was used).
    pub set_size: Option<u64>,
    /// Fraction of candidate points accepted by the constraints.
    pub acceptance: f64,
    /// Was lhs − rhs exactly zero at every point?
    pub all_zero: bool,
    /// Explanation.
    pub note: String,
}

/// What a kind found about a claim.
#[derive(Clone, Debug, PartialEq)]
pub struct Evidence {
    /// The verdict.
    pub verdict: Verdict,
    /// Why, in one line.
    pub reason: String,
    /// Per rung.
    pub residuals: Vec<Rung>,
    /// Bits lost to conditioning g, when the ladder rule applies.
    pub loss_bits: Option<f64>,
    /// Samples evaluated at every rung.
    pub samples: usize,
    /// Samples that could not be evaluated.
    pub failures: Vec<FailedSample>,
    /// The counterexample of a refutation.
    pub counterexample: Option<Counterexample>,
    /// Exact evaluation.
    pub exact: Option<ExactInfo>,
    /// The symbolic proof attempt (identities).
    pub proof: Option<ProofInfo>,
}

impl Evidence {
    /// A verdict with a reason and no data yet.
    pub fn new(verdict: Verdict, reason: impl Into<String>) -> Self {
        Evidence {
            verdict,
            reason: reason.into(),
            residuals: Vec::new(),
            loss_bits: None,
            samples: 0,
            failures: Vec::new(),
            counterexample: None,
            exact: None,
            proof: None,
        }
    }
}

/// A kind that stopped without a verdict: the cause, and what it had gathered (failed
/// samples, the float ladder of an identity whose exact evaluation failed, ...).
#[derive(Clone, Debug, PartialEq)]
pub struct Failure {
    /// Why.
    pub cause: Cause,
    /// The evidence gathered before; its verdict and reason are replaced.
    pub partial: Box<Evidence>,
}

impl Failure {
    /// A failure with the evidence gathered so far.
    pub fn new(cause: Cause, partial: Evidence) -> Self {
        Failure {
            cause,
            partial: Box::new(partial),
        }
    }
    /// A failure while collecting samples: only the failed samples are kept.
    pub fn with_failures(cause: Cause, failures: Vec<FailedSample>) -> Self {
        let partial = Evidence {
            failures,
            ..Evidence::new(Verdict::Inconclusive, "")
        };
        Failure::new(cause, partial)
    }
    /// A failure before anything was gathered.
    pub fn bare(cause: Cause) -> Self {
        Failure::new(cause, Evidence::new(Verdict::Inconclusive, ""))
    }
    /// The evidence with verdict inconclusive and the cause as the reason.
    pub fn into_evidence(self) -> Evidence {
        Evidence {
            verdict: Verdict::Inconclusive,
            reason: self.cause.to_string(),
            ..*self.partial
        }
    }
}

/// Everything known about one claim after verification (consumed by the report writer).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct ClaimResult {
    /// Claim id.
    pub id: String,
    /// Paper labels.
    pub labels: Vec<String>,
    /// Location in the paper.
    pub location: String,
    /// `file:line` in the catalogue.
    pub position: String,
    /// Verbatim LaTeX from the paper.
    pub printed: String,
    /// LaTeX of the evaluated expressions (let bindings, then the claim).
    pub rendered: Vec<String>,
    /// Kind.
    pub kind: Kind,
    /// Printed or corrected.
    pub form: Form,
    /// The printed claim this one corrects.
    pub corrects: Option<String>,
    /// Expected verdict.
    pub expect: Option<Verdict>,
    /// The verdict.
    pub verdict: Verdict,
    /// verdict == expect (definitions: true).
    pub as_expected: bool,
    /// Residual (or slope) per rung.
    pub residuals: Vec<Rung>,
    /// Bits lost to conditioning g (None when not applicable).
    pub loss_bits: Option<f64>,
    /// The bound on g.
    pub max_loss_bits: f64,
    /// Samples evaluated successfully.
    pub samples: usize,
    /// Samples that could not be evaluated.
    pub failures: Vec<FailedSample>,
    /// Counterexample (refuted claims).
    pub counterexample: Option<Counterexample>,
    /// Exact evaluation evidence.
    pub exact: Option<ExactInfo>,
    /// The symbolic proof, or why there is none.
    pub proof: ProofInfo,
    /// Catalogue note.
    pub note: Option<String>,
    /// Why this verdict, in one line.
    pub reason: String,
    /// Wall time of the claim's verification in milliseconds, set by
    /// [`run_claim`](super::run_claim).  It varies from run to run, so the report never
    /// shows it; `verify --format json` gives it to find the slow claims.
    pub elapsed_ms: f64,
}

impl ClaimResult {
    /// The result of `claim` with the evidence `ev`.
    pub fn new(claim: &Claim, ev: Evidence) -> Self {
        let as_expected = match (claim.expect, ev.verdict) {
            (None, Verdict::Defined) => true,
            (Some(e), v) => e == v,
            _ => false,
        };
        ClaimResult {
            id: claim.id.clone(),
            labels: claim.labels.clone(),
            location: claim.location.clone(),
            position: claim.position.clone(),
            printed: claim.printed.clone(),
            rendered: rendered(claim),
            kind: claim.kind,
            form: claim.form,
            corrects: claim.corrects.clone(),
            expect: claim.expect,
            verdict: ev.verdict,
            as_expected,
            residuals: ev.residuals,
            loss_bits: ev.loss_bits,
            max_loss_bits: claim.max_loss_bits,
            samples: ev.samples,
            failures: ev.failures,
            counterexample: ev.counterexample,
            exact: ev.exact,
            proof: ev
                .proof
                .unwrap_or_else(|| ProofInfo::none(not_attempted(claim.kind))),
            note: claim.note.clone(),
            reason: ev.reason,
            elapsed_ms: 0.0,
        }
    }
}

/// Why a claim of this kind has no symbolic proof attempt.
fn not_attempted(kind: Kind) -> &'static str {
    match kind {
        Kind::Definition => "a definition",
        Kind::Identity => "not attempted",
        _ => "only identities and independence claims are proved symbolically",
    }
}

/// LaTeX of what is evaluated: the `let` bindings, then the claim itself.
fn rendered(claim: &Claim) -> Vec<String> {
    let mut out: Vec<String> = claim.lets.iter().map(binding_to_latex).collect();
    match &claim.body {
        Body::Identity { lhs, rhs } => {
            out.push(format!("{} = {}", to_latex(&lhs.expr), to_latex(&rhs.expr)))
        }
        Body::Independence { expr, wrt, .. } => out.push(format!(
            "\\frac{{\\partial}}{{\\partial {wrt}}}\\left({}\\right) = 0",
            to_latex(&expr.expr)
        )),
        Body::Asymptotic {
            expr, var, order, ..
        } => out.push(format!("{} = O({var}^{{{order}}})", to_latex(&expr.expr))),
        Body::Existence { equations, .. } => out.extend(
            equations
                .iter()
                .map(|e| format!("{} = 0", to_latex(&e.expr))),
        ),
        Body::Negation(inner) => out.extend(
            rendered(inner)
                .into_iter()
                .map(|s| format!("\\neg\\left({s}\\right)")),
        ),
        Body::Definition(bs) => out.extend(bs.iter().map(binding_to_latex)),
    }
    out
}
