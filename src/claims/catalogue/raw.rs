//! The TOML as written, before validation: serde structs that reject unknown fields
//! (typos must not be silently ignored), with serde enums for `kind`, `form` and
//! `expect` and spans on every value an error may point at.

use crate::claims::kind::{Form, Kind, Verdict};
use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

/// One catalogue file.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct FileToml {
    /// `[paper]`: the source and its environments (one file of the catalogue has it).
    pub paper: Option<Spanned<super::paper::PaperToml>>,
    /// `[section]`.
    pub section: Option<SectionToml>,
    /// `[[claim]]` tables.
    #[serde(default)]
    pub claim: Vec<Spanned<ClaimToml>>,
    /// `[domain.NAME]` tables.
    #[serde(default)]
    pub domain: BTreeMap<String, Spanned<DomainToml>>,
    /// `[hypothesis.NAME]` tables: hypotheses that claims may state.
    #[serde(default)]
    pub hypothesis: BTreeMap<String, Spanned<HypothesisToml>>,
    /// `[[convention]]` tables: free text, accepted and not evaluated.
    #[serde(default, rename = "convention")]
    pub _conventions: Vec<toml::Value>,
}

/// `[section]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SectionToml {
    /// Section number.
    pub number: String,
    /// Section title.
    pub title: String,
}

/// `[domain.NAME]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DomainToml {
    /// `[["name", "sampler expression"], ...]`.
    #[serde(default)]
    pub vars: Vec<Vec<Spanned<String>>>,
    /// Constraints.
    #[serde(default, rename = "where")]
    pub wheres: Vec<Spanned<String>>,
}

/// `[hypothesis.NAME]`: a hypothesis a proof may rest on, quoted from the paper.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HypothesisToml {
    /// What it says, for the reader.
    pub statement: Spanned<String>,
    /// Where and how the paper says it (a quotation).
    pub paper: Spanned<String>,
    /// The implicit map whose solution branch it fixes.
    pub branch: Option<Spanned<String>>,
    /// A sign condition, `a > b` or `a < b`, in the claim's names.
    pub when: Option<Spanned<String>>,
}

/// The verdicts a claim may expect (not `defined`).
#[derive(Deserialize, Clone, Copy, Debug, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum Expect {
    /// holds
    Holds,
    /// refuted
    Refuted,
    /// proved
    Proved,
    /// construction
    Construction,
    /// inconclusive
    Inconclusive,
}

impl From<Expect> for Verdict {
    fn from(e: Expect) -> Verdict {
        match e {
            Expect::Holds => Verdict::Holds,
            Expect::Refuted => Verdict::Refuted,
            Expect::Proved => Verdict::Proved,
            Expect::Construction => Verdict::Construction,
            Expect::Inconclusive => Verdict::Inconclusive,
        }
    }
}

/// `[[claim]]` (and `[claim.inner]`) as written.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct ClaimToml {
    pub id: Option<Spanned<String>>,
    #[serde(default)]
    pub labels: Vec<String>,
    pub location: Option<String>,
    pub printed: Option<String>,
    pub kind: Option<Spanned<Kind>>,
    pub form: Option<Spanned<Form>>,
    pub corrects: Option<String>,
    pub expect: Option<Spanned<Expect>>,
    pub note: Option<String>,
    pub domain: Option<Spanned<String>>,
    #[serde(default)]
    pub vars: Vec<Vec<Spanned<String>>>,
    #[serde(default, rename = "where")]
    pub wheres: Vec<Spanned<String>>,
    #[serde(rename = "let")]
    pub let_: Option<Spanned<String>>,
    pub lhs: Option<Spanned<String>>,
    pub rhs: Option<Spanned<String>>,
    pub scale: Option<Spanned<String>>,
    pub expr: Option<Spanned<String>>,
    pub wrt: Option<Spanned<String>>,
    pub redraws: Option<usize>,
    pub var: Option<Spanned<String>>,
    pub order: Option<f64>,
    pub h0: Option<f64>,
    pub steps: Option<usize>,
    pub slope_tol: Option<f64>,
    pub inner: Option<Box<Spanned<ClaimToml>>>,
    #[serde(default)]
    pub unknowns: Vec<String>,
    #[serde(default)]
    pub equations: Vec<Spanned<String>>,
    #[serde(default)]
    pub start: Vec<Spanned<String>>,
    #[serde(rename = "in")]
    pub in_set: Option<Spanned<String>>,
    pub tries: Option<usize>,
    pub define: Option<Spanned<String>>,
    pub samples: Option<usize>,
    pub exact: Option<bool>,
    pub exact_samples: Option<usize>,
    pub max_loss_bits: Option<f64>,
    pub refute_floor_bits: Option<f64>,
    pub seed: Option<u64>,
    pub environment: Option<Spanned<String>>,
    pub role: Option<Spanned<String>>,
    #[serde(default)]
    pub uses: Vec<Spanned<String>>,
    pub hint: Option<Spanned<HintToml>>,
    /// Names of the `[hypothesis.NAME]` tables whose hypotheses the claim states.
    #[serde(default)]
    pub hypotheses: Vec<Spanned<String>>,
    /// Why the claim holds by construction (the model defines its map by this equation).
    pub construction: Option<Spanned<String>>,
}

/// `hint = { value = "…", multipliers = [...] }`: a proof hint of an identity claim.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HintToml {
    /// The `let` whose body is the implicit call.
    pub value: Spanned<String>,
    /// One multiplier per component of `lhs − rhs`.
    pub multipliers: Vec<Spanned<String>>,
}
