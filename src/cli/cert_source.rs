//! The claim a certificate proves, as the catalogue writes it: the `source` and
//! `premise` lines of a certificate (see `scripts/recheck-certificates.py`).
//!
//! A certificate's derivation is bound to its claim by these lines, written before the
//! derivation:
//!
//! ```text
//! source id "sec2.ET-v.corrected"           # the claim's id and its file
//! source file "02-euler-top.toml"
//! source claim.lhs "ETrhs(M, A, B, C)"      # every formula field, verbatim (JSON)
//! source domain.top {"vars": [...]}         # the domain table, the stated hypotheses,
//! source define.sec2.def.ET "ETrhs(M, ...   # the definitions the formulas call
//! premise branch hypothesis.branch-gamma1 "M^ = ..."   # what the theorem rests on
//! ```
//!
//! The recheck reads the same fields from the catalogue and rejects the certificate at
//! the first difference; it evaluates the formulas itself, from the certificate's
//! symbols, where its own evaluator covers them.

use super::CliError;
use crate::claims::verdict::proof_info::{HypothesisUse, SMALL_H_NOTE};
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The fields of a `[[claim]]` table that state what is claimed, in the order written.
pub const CLAIM_FIELDS: [&str; 17] = [
    "kind",
    "domain",
    "vars",
    "where",
    "let",
    "lhs",
    "rhs",
    "expr",
    "wrt",
    "var",
    "order",
    "unknowns",
    "equations",
    "start",
    "in",
    "hypotheses",
    "inner",
];

/// A catalogue read as TOML values: every claim by id (with its file name), every
/// definition's text by the names it defines, the domains and the hypotheses.
#[derive(Default)]
pub struct RawCatalogue {
    claims: BTreeMap<String, (String, toml::Table)>,
    defines: BTreeMap<String, (String, String)>,
    tables: BTreeMap<String, toml::Value>,
}

/// The names a `define` text defines: the name before `(` at the start of each line.
///
/// ```
/// use eulertop::cli::cert_source::defined_names;
/// assert_eq!(defined_names("f(x) = x^2\n# note\ng(a, b) = a"), ["f", "g"]);
/// ```
pub fn defined_names(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|l| {
            let l = l.trim_start();
            let end = l.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))?;
            (end > 0 && l[end..].trim_start().starts_with('(')).then(|| l[..end].to_string())
        })
        .collect()
}

/// The identifiers of a text (`[A-Za-z_][A-Za-z0-9_]*`), comments included.
///
/// ```
/// use eulertop::cli::cert_source::identifiers;
/// assert_eq!(identifiers("f(M[1]) + x2"), ["f", "M", "x2"]);
/// ```
pub fn identifiers(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    for c in text.chars().chain(std::iter::once(' ')) {
        if c.is_ascii_alphanumeric() || c == '_' {
            if !(cur.is_empty() && c.is_ascii_digit()) {
                cur.push(c);
            }
        } else if !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
    }
    out
}

impl RawCatalogue {
    /// Reads every `*.toml` file of `dir` (an error names the file that cannot be read
    /// or parsed).
    ///
    /// ```
    /// use eulertop::cli::cert_source::RawCatalogue;
    /// assert!(RawCatalogue::read("identities").is_ok());
    /// assert!(RawCatalogue::read("no-such-directory").is_err());
    /// ```
    pub fn read(dir: &str) -> Result<Self, CliError> {
        let mut files: Vec<_> = std::fs::read_dir(dir)
            .map_err(|e| CliError(format!("cannot read {dir}: {e}")))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        let mut cat = RawCatalogue::default();
        for path in files {
            let text = std::fs::read_to_string(&path)
                .map_err(|e| CliError(format!("cannot read {}: {e}", path.display())))?;
            cat.add_text(&path, &text)?;
        }
        Ok(cat)
    }

    /// Reads the `(file name, text)` pairs of a catalogue, as [`RawCatalogue::read`]
    /// reads its files.
    ///
    /// ```
    /// use eulertop::cli::cert_source::RawCatalogue;
    /// let cat = RawCatalogue::from_sources(&eulertop::bindings::catalogue::sources()).unwrap();
    /// assert!(cat.source_lines("sec2.def.M2").is_ok());
    /// ```
    pub fn from_sources(sources: &[(String, String)]) -> Result<Self, CliError> {
        let mut cat = RawCatalogue::default();
        for (name, text) in sources {
            cat.add_text(Path::new(name), text)?;
        }
        Ok(cat)
    }

    fn add_text(&mut self, path: &Path, text: &str) -> Result<(), CliError> {
        let shown = path.display();
        let table: toml::Table = text
            .parse()
            .map_err(|e| CliError(format!("{shown}: {e}")))?;
        let name = path
            .file_name()
            .map_or(String::new(), |n| n.to_string_lossy().into_owned());
        for (group, value) in &table {
            if let (true, Some(t)) = (group == "domain" || group == "hypothesis", value.as_table())
            {
                for (k, v) in t {
                    self.tables.insert(format!("{group}.{k}"), v.clone());
                }
            }
        }
        let claims = table.get("claim").and_then(|c| c.as_array());
        for c in claims.into_iter().flatten().filter_map(|c| c.as_table()) {
            let Some(id) = c.get("id").and_then(|v| v.as_str()) else {
                continue;
            };
            if let Some(d) = c.get("define").and_then(|v| v.as_str()) {
                for f in defined_names(d) {
                    self.defines.insert(f, (id.to_string(), d.to_string()));
                }
            }
            self.claims
                .insert(id.to_string(), (name.clone(), c.clone()));
        }
        Ok(())
    }

    /// The `source` lines of claim `id` (see the module doc).
    ///
    /// ```
    /// use eulertop::cli::cert_source::RawCatalogue;
    /// let cat = RawCatalogue::read("identities").unwrap();
    /// let lines = cat.source_lines("sec2.ET-v.corrected").unwrap();
    /// assert!(lines.starts_with("source id \"sec2.ET-v.corrected\"\n"));
    /// // the definition of ETrhs, which the lhs calls
    /// assert!(lines.contains("source define.sec2.def.ET \"ETrhs(M, A, B, C) = "));
    /// assert!(cat.source_lines("no.such.claim").is_err());
    /// ```
    pub fn source_lines(&self, id: &str) -> Result<String, CliError> {
        let (file, claim) = (self.claims.get(id))
            .ok_or_else(|| CliError(format!("no claim with id '{id}' in the catalogue files")))?;
        let json = |v: &toml::Value| serde_json::to_string(v).unwrap_or_default();
        // the text scanned for the names of definitions: a string as written
        let text = |v: &toml::Value| v.as_str().map_or_else(|| json(v), str::to_string);
        let mut out = format!(
            "source id {}\nsource file {}\n",
            json(&id.into()),
            json(&file.as_str().into())
        );
        let mut texts = Vec::new();
        for f in CLAIM_FIELDS {
            if let Some(v) = claim.get(f) {
                out.push_str(&format!("source claim.{f} {}\n", json(v)));
                texts.push(text(v));
            }
        }
        let mut tables = Vec::new();
        if let Some(d) = claim.get("domain").and_then(|v| v.as_str()) {
            tables.push(format!("domain.{d}"));
        }
        for h in claim
            .get("hypotheses")
            .and_then(|v| v.as_array())
            .into_iter()
            .flatten()
        {
            tables.extend(h.as_str().map(|h| format!("hypothesis.{h}")));
        }
        for t in tables {
            if let Some(v) = self.tables.get(&t) {
                out.push_str(&format!("source {t} {}\n", json(v)));
                texts.push(text(v));
            }
        }
        for (def_id, text) in self.definitions_used(&texts) {
            out.push_str(&format!("source define.{def_id} {}\n", json(&text.into())));
        }
        Ok(out)
    }

    /// The definitions (claim id, `define` text) that the texts call, transitively.
    fn definitions_used(&self, texts: &[String]) -> BTreeMap<String, String> {
        let mut out = BTreeMap::new();
        let mut seen = BTreeSet::new();
        let mut todo: Vec<String> = texts.iter().flat_map(|t| identifiers(t)).collect();
        while let Some(name) = todo.pop() {
            if !seen.insert(name.clone()) {
                continue;
            }
            if let Some((id, text)) = self.defines.get(&name)
                && out.insert(id.clone(), text.clone()).is_none()
            {
                todo.extend(identifiers(text));
            }
        }
        out
    }
}

/// The `premise` lines: every hypothesis the proof rests on, with its kind and source.
///
/// ```
/// use eulertop::claims::verdict::HypothesisUse;
/// use eulertop::cli::cert_source::premise_lines;
/// let h = HypothesisUse {
///     kind: "lemma",
///     statement: "the step's value".into(),
///     source: "sec7.master12.step.up".into(),
/// };
/// assert_eq!(
///     premise_lines(&[h]),
///     "premise lemma sec7.master12.step.up \"the step's value\"\n"
/// );
/// ```
///
/// A sign hypothesis that the prover finds to hold for every small enough `h` is still
/// the catalogue's sign hypothesis, with the catalogue's statement: the recheck takes it
/// as a premise as stated.
///
/// ```
/// use eulertop::claims::verdict::HypothesisUse;
/// use eulertop::claims::verdict::proof_info::SMALL_H_NOTE;
/// use eulertop::cli::cert_source::premise_lines;
/// let h = HypothesisUse {
///     kind: "small h",
///     statement: format!("tr omega > 1{SMALL_H_NOTE}"),
///     source: "hypothesis.omega-near-identity".into(),
/// };
/// assert_eq!(
///     premise_lines(&[h]),
///     "premise sign hypothesis.omega-near-identity \"tr omega > 1\"\n"
/// );
/// ```
pub fn premise_lines(hypotheses: &[HypothesisUse]) -> String {
    hypotheses
        .iter()
        .map(|h| {
            let (kind, text) = match h.kind {
                "small h" => ("sign", h.statement.trim_end_matches(SMALL_H_NOTE)),
                k => (k, h.statement.as_str()),
            };
            let statement = serde_json::to_string(text).unwrap_or_default();
            format!("premise {kind} {} {statement}\n", h.source)
        })
        .collect()
}

/// The certificate with the claim's `source` and `premise` lines after its first line
/// (the header of its first part).
///
/// ```
/// use eulertop::cli::cert_source::bind;
/// let cert = "# eulertop certificate 1\nnode t1 = 1\nclaim t1 = t1\n";
/// let bound = bind(cert, "source id \"x\"\n", "");
/// assert_eq!(bound, "# eulertop certificate 1\nsource id \"x\"\nnode t1 = 1\nclaim t1 = t1\n");
/// ```
pub fn bind(cert: &str, source: &str, premises: &str) -> String {
    let (head, rest) = cert.split_once('\n').unwrap_or((cert, ""));
    format!("{head}\n{source}{premises}{rest}")
}
