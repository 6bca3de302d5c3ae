//! The record of a proof attempt, as the results and reports show it.

use serde::Serialize;

/// How a claim was proved.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ProofMethod {
    /// The symbolic normal form of lhs − rhs is 0.
    Symbolic,
    /// Refuted with a witness: a domain point at which lhs − rhs is certified nonzero
    /// (field `witness`).
    Witness,
    /// An asymptotic claim proved by exact power series: every coefficient below the
    /// claimed order has normal form 0.
    Series,
    /// An identity in one variable proved by the uniqueness of the solution of an
    /// algebraic ODE that both sides satisfy, with the same initial values
    /// ([`crate::algebra::ode`]).
    Ode,
    /// Existence certified at the sampled points by the Krawczyk test in ball arithmetic
    /// (one solution in a box around each sampled solution); not a proof on the whole
    /// domain, so the verdict stays `holds`.
    Interval,
    /// Not proved (the reason says why).
    None,
}

/// How the reason of an existence claim whose sampled solutions are not certified by
/// the Krawczyk test begins.
pub const NO_INTERVAL: &str = "no interval certificate: ";

/// What a `small h` hypothesis use adds to the catalogue's statement: the sign
/// condition holds for every small enough `h > 0`.
///
/// ```
/// use eulertop::claims::verdict::proof_info::SMALL_H_NOTE;
/// assert!(SMALL_H_NOTE.starts_with(" (holds for every small enough $h > 0$"));
/// ```
pub const SMALL_H_NOTE: &str = " (holds for every small enough $h > 0$: the leading coefficient of its power series in $h$ is proved positive on the domain)";

/// A fact a proof rests on besides algebra.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct HypothesisUse {
    /// `branch` (the solution branch of an implicit map), `sign` (a sign condition the
    /// claim states), `small h` (one that holds for every small enough `h > 0`, its
    /// statement followed by [`SMALL_H_NOTE`]) or `lemma` (a step's value proved by
    /// another claim).
    pub kind: &'static str,
    /// What it says.
    pub statement: String,
    /// Where it comes from: `hypothesis.NAME` of the catalogue, or the lemma's claim id.
    pub source: String,
}

impl HypothesisUse {
    /// One line for the reader: "statement (source)".
    pub fn line(&self) -> String {
        format!("{} [{}: {}]", self.statement, self.kind, self.source)
    }
}

/// The evidence of a proof attempt, as reported.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ProofInfo {
    /// Proved symbolically, or not.
    pub method: ProofMethod,
    /// Why not, when not proved.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    /// The symbols: "name: what it stands for".
    pub symbols: Vec<String>,
    /// The relations of the square-root symbols.
    pub relations: Vec<String>,
    /// What the proof rests on besides algebra: stated hypotheses and lemmas (never a
    /// decision taken at domain points).
    pub hypotheses: Vec<HypothesisUse>,
    /// Signs proved with the parametrization of the domain (not assumptions).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub proved_signs: Vec<String>,
    /// That parametrization, when a sign was proved with it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parametrization: Option<String>,
    /// The steps for the reader: addition-theorem instances, symbols introduced.
    pub notes: Vec<String>,
    /// The cases of the finitely-valued variables ("sa = 1, sc = -1"), if any.
    pub cases: Vec<String>,
    /// Terms of the numerators of both sides (the size of the identity).
    pub terms: usize,
    /// Wall time in milliseconds.
    pub ms: f64,
    /// The steps the certificate format does not record, when the proof has any (it then
    /// has no certificate).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub uncertified: Vec<String>,
    /// The certificate (SymPy-recheckable), when requested.
    #[serde(skip)]
    pub certificate: Option<String>,
    /// Where lhs − rhs is certified nonzero, when the attempt found such a point: the
    /// case, the domain point and the enclosure (`crate::algebra::witness`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub witness: Option<String>,
}

impl ProofInfo {
    /// No proof, for `reason`.
    pub fn none(reason: impl Into<String>) -> ProofInfo {
        ProofInfo {
            method: ProofMethod::None,
            reason: Some(reason.into()),
            symbols: Vec::new(),
            relations: Vec::new(),
            hypotheses: Vec::new(),
            proved_signs: Vec::new(),
            parametrization: None,
            notes: Vec::new(),
            cases: Vec::new(),
            terms: 0,
            ms: 0.0,
            uncertified: Vec::new(),
            certificate: None,
            witness: None,
        }
    }

    /// Was the claim proved?
    pub fn is_proved(&self) -> bool {
        matches!(
            self.method,
            ProofMethod::Symbolic | ProofMethod::Series | ProofMethod::Ode
        )
    }

    /// What the proof rests on, in a few words: "12 symbols, 4 relations, 3 assumptions"
    /// (and the number of cases, if any).
    pub fn extent(&self) -> String {
        let cases = if self.cases.is_empty() {
            String::new()
        } else {
            format!(", {} cases", self.cases.len())
        };
        format!(
            "{} symbols, {} relations, {} hypotheses{cases}",
            self.symbols.len(),
            self.relations.len(),
            self.hypotheses.len()
        )
    }
}
