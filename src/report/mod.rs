//! The outputs layer's report writer: Markdown verification reports and SVG figures.
//!
//! [`write_reports`] turns verified claims ([`ClaimResult`]s) into `reports/`:
//! `README.md` (the paper's environments with their rolled-up statuses, verdict counts, a
//! table of every claim), `proofs/<environment>.md` (one page per environment of the paper:
//! statement, proof steps, status, dependency diagram), one file per catalogue section with
//! one block per claim (printed formula, the formula as evaluated, residual ladder,
//! verdict, counterexample), `errata.md`, `conventions.md` and `figures/residuals-*.svg`.  Output is deterministic: no timestamps, catalogue order,
//! fixed number formatting.

pub mod cells;
pub mod decimal;
pub mod diagram;
pub mod figures;
pub mod markdown;
pub mod paper_text;
pub mod proof_evidence;
pub mod proofs;
pub mod tex;
pub mod variables;

use crate::claims::structure::{Environment, Place};
use crate::claims::verdict::ClaimResult;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One section of the catalogue (one TOML file).
#[derive(Clone, Debug)]
pub struct Section {
    /// File stem, e.g. `02-euler-top`; the report is `<stem>.md`.
    pub stem: String,
    /// Section number as printed ("2", "A", …).
    pub number: String,
    /// Title.
    pub title: String,
}

/// A convention the catalogue fixes.
#[derive(Clone, Debug)]
pub struct Convention {
    /// Short name.
    pub name: String,
    /// The choice made.
    pub choice: String,
    /// Why.
    pub why: String,
}

/// Everything the report writer needs.
pub struct ReportInput<'a> {
    /// Sections in catalogue order.
    pub sections: Vec<Section>,
    /// Verified claims in catalogue order.
    pub results: &'a [ClaimResult],
    /// Conventions.
    pub conventions: Vec<Convention>,
    /// LaTeX macros of the paper (name without backslash → replacement).
    pub macros: BTreeMap<String, String>,
    /// The precision ladder used.
    pub bits: Vec<u32>,
    /// The command line that regenerates the reports (shown in them).
    pub command: String,
    /// Further figures in `figures/` to show in the index: (file, caption).
    pub extra_figures: Vec<(String, String)>,
    /// Each claim's place in the paper (environment, role, uses), by id.
    pub places: BTreeMap<String, Place>,
    /// The catalogue's environments in the paper's order, sections included (those that
    /// are not sections get a page in `proofs/`).
    pub paper_environments: Vec<Environment>,
    /// The source, from the catalogue's `[paper]` table (for the title of the index).
    pub paper: Option<crate::claims::catalogue::paper::Paper>,
    /// The printed statements and proofs of the environments, by environment name.
    pub environments: BTreeMap<String, paper_text::EnvironmentText>,
    /// Each claim's sampled variables with the catalogue's definitions, by claim id (to
    /// say what the variables of a counterexample are).
    pub variables: BTreeMap<String, Vec<variables::VarDef>>,
}

impl ReportInput<'_> {
    /// The sampled variables of claim `id` with their definitions (none when unknown).
    pub fn variables_of(&self, id: &str) -> &[variables::VarDef] {
        self.variables.get(id).map_or(&[], Vec::as_slice)
    }

    /// The catalogue's prose (a location, a note) as Markdown, the paper's macros
    /// expanded in its `$…$` math.
    pub fn prose(&self, text: &str) -> String {
        tex::inline_math(text, &self.macros)
    }
}

/// Section stem of a claim, from its `file:line` position.
pub fn stem_of(r: &ClaimResult) -> String {
    let file = r.position.split(':').next().unwrap_or("");
    let base = Path::new(file)
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("other");
    base.to_string()
}

/// Writes every Markdown file and the residual figures into `out`; returns the paths
/// written (sorted).  Model-specific figures are written separately by the caller.
pub fn write_reports(input: &ReportInput, out: &Path) -> std::io::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(out.join("figures"))?;
    std::fs::create_dir_all(out.join("proofs"))?;
    let mut written = Vec::new();
    let mut put = |name: &str, text: String| -> std::io::Result<()> {
        let p = out.join(name);
        std::fs::write(&p, text)?;
        written.push(p);
        Ok(())
    };
    for sec in &input.sections {
        let claims: Vec<&ClaimResult> = input
            .results
            .iter()
            .filter(|r| stem_of(r) == sec.stem)
            .collect();
        if claims.is_empty() {
            continue;
        }
        put(
            &format!("{}.md", sec.stem),
            markdown::section_file(input, sec, &claims),
        )?;
        let svg = figures::residual_plot(sec, &claims, &input.bits);
        put(&format!("figures/residuals-{}.svg", sec.stem), svg)?;
    }
    let structure = proofs::Structure::new(input.results, &input.places);
    for env in proofs::environments(input) {
        put(
            &format!("proofs/{}.md", env.page()),
            proofs::page(input, &structure, &env),
        )?;
    }
    put("README.md", markdown::readme(input))?;
    put("errata.md", markdown::errata(input))?;
    put("conventions.md", markdown::conventions(input))?;
    written.sort();
    Ok(written)
}
