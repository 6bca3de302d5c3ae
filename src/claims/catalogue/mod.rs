//! Loads the claim catalogue (`identities/*.toml`, format in `identities/README.md`).
//!
//! The TOML is read into raw serde structs (module `raw`), each claim is built with its
//! defaults ([`defaults`]) and kind-specific fields ([`build`]), and the whole
//! catalogue is checked: names and arities ([`check`]), the paper's structure
//! ([`structure`]).  Every problem is a [`LoadError`] rendered as
//! `file:line:column: message` followed by the offending source line with the bad text
//! underlined (or `file: message` when it concerns a whole file).  Nothing panics.

pub mod build;
pub mod check;
pub mod claim;
pub mod defaults;
mod fields;
pub mod lookup;
pub mod paper;
mod raw;
pub mod source;
pub mod structure;

pub use claim::{Body, Catalogue, Claim, Domain, ExactSpec, Hint, LemmaMemo, PExpr};
pub use source::{LoadError, Located, Origin, SourceFile};

use crate::claims::ast::Binding;
use crate::claims::registry::Registry;
use build::build_claim;
use claim::Domain as Dom;
use fields::{pexprs, var_list};
use raw::{DomainToml, FileToml};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use toml::Spanned;

/// Loads a catalogue: every `*.toml` file of the directory `path` (sorted by name), or
/// the one file `path`.  A catalogue without claims is an error.
pub fn load_dir(path: &Path, registry: Registry) -> Result<Catalogue, LoadError> {
    let sources = read_sources(path)?;
    let cat = load_sources(&sources, registry)?;
    if cat.claims.is_empty() {
        return Err(LoadError::whole(
            path.display().to_string(),
            "the catalogue has no claims",
        ));
    }
    Ok(cat)
}

/// The `(file name, text)` of every `*.toml` file of the directory `path` (sorted by
/// name), or of the one file `path`, for [`load_sources`].
pub fn read_sources(path: &Path) -> Result<Vec<(String, String)>, LoadError> {
    let shown = path.display().to_string();
    let files: Vec<PathBuf> = if path.is_file() {
        vec![path.to_path_buf()]
    } else {
        let rd = std::fs::read_dir(path)
            .map_err(|e| LoadError::whole(&shown, format!("cannot read the catalogue: {e}")))?;
        let mut files: Vec<PathBuf> = rd
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        files
    };
    if files.is_empty() {
        return Err(LoadError::whole(shown, "no catalogue files (*.toml) here"));
    }
    let mut sources = Vec::new();
    for p in files {
        let name = p.display().to_string();
        let bytes = source::read_regular(&p, source::MAX_TEXT_FILE_BYTES)
            .map_err(|e| LoadError::whole(&name, e))?;
        let text = source::utf8(&name, bytes)?;
        sources.push((name, text));
    }
    Ok(sources)
}

/// The catalogue being assembled from its files.
#[derive(Default)]
struct Assembly {
    claims: Vec<claim::Claim>,
    domains: BTreeMap<String, Dom>,
    sections: Vec<(String, String, String)>,
    /// Claim id → `file:line`, for duplicates.
    ids: BTreeMap<String, String>,
    /// The `definition` functions with where they are written.
    defs: Vec<(Binding, Origin)>,
    hypotheses: BTreeMap<String, claim::Hypothesis>,
    /// The `[paper]` table, once read.
    paper: Option<(paper::Paper, Vec<paper::EnvironmentSpec>)>,
}

/// Loads a catalogue from `(file name, text)` pairs, with the host functions of
/// `registry` (the catalogue's `definition` functions are added to it).
///
/// ```
/// use eulertop::claims::catalogue::load_sources;
/// use eulertop::claims::registry::Registry;
/// let toml = r#"
/// [[claim]]
/// id = "double-angle"
/// location = "anywhere"
/// printed = 'sin 2x = 2 sin x cos x'
/// environment = "Section 2"
/// role = "statement"
/// kind = "identity"
/// expect = "holds"
/// vars = [["x", "uniform(-3, 3)"]]
/// lhs = "sin(2*x)"
/// rhs = "2*sin(x)*cos(x)"
/// "#;
/// let cat = load_sources(&[("t.toml".into(), toml.into())], Registry::new()).unwrap();
/// assert_eq!(cat.claims[0].id, "double-angle");
/// // an unknown name is an error with its position
/// let bad = toml.replace("rhs = \"2*sin(x)", "rhs = \"2*sin(y)");
/// let e = load_sources(&[("t.toml".into(), bad)], Registry::new()).unwrap_err();
/// assert_eq!(e.to_string().lines().next(), Some("t.toml:12:14: unknown variable 'y'"));
/// ```
pub fn load_sources(
    sources: &[(String, String)],
    mut registry: Registry,
) -> Result<Catalogue, LoadError> {
    let mut a = Assembly::default();
    for (name, text) in sources {
        let file = Arc::new(SourceFile::new(name.clone(), text.clone()));
        load_file(&file, &mut a)?;
    }
    for (b, origin) in &a.defs {
        if b.params.is_none() {
            return Err(origin.error(
                Some(b.span),
                format!(
                    "definition '{}' needs parameters: write {}(...) = ...",
                    b.name, b.name
                ),
            ));
        }
        registry
            .define(b.clone())
            .map_err(|m| origin.error(Some(b.span), m.to_string()))?;
    }
    let (paper, environments) = match a.paper {
        Some((p, envs)) => (Some(p), envs),
        None => {
            let names = a.claims.iter().filter_map(|c| c.environment.as_ref());
            (None, paper::implicit(names.map(|e| e.value.as_str())))
        }
    };
    let cat = Catalogue {
        claims: a.claims,
        domains: a.domains,
        registry,
        sections: a.sections,
        lemma_memo: LemmaMemo::default(),
        hypotheses: a.hypotheses,
        paper,
        environments,
    };
    check::check(&cat, &a.defs)?;
    structure::check(&cat)?;
    Ok(cat)
}

/// Reads one file into the assembly.
fn load_file(file: &Arc<SourceFile>, a: &mut Assembly) -> Result<(), LoadError> {
    let parsed: FileToml = toml::from_str(&file.text).map_err(|e| {
        let (s, t) = e.span().map_or((0, 0), |r| (r.start, r.end));
        file.error_at(s, t, e.message().trim().replace('\n', " "))
    })?;
    if let Some(t) = &parsed.paper {
        if let Some((p, _)) = &a.paper {
            let at = t.span().start;
            return Err(file.error_at(
                at,
                at + 1,
                format!("a second [paper] table (the first is at {})", p.position),
            ));
        }
        a.paper = Some(paper::read(file, t)?);
    }
    if let Some(s) = &parsed.section {
        a.sections
            .push((file.name.clone(), s.number.clone(), s.title.clone()));
    }
    for (dname, d) in &parsed.domain {
        let dom = domain(file, dname, d)?;
        if a.domains.contains_key(dname) {
            let at = d.span().start;
            return Err(file.error_at(at, at + 1, format!("domain '{dname}' defined twice")));
        }
        a.domains.insert(dname.clone(), dom);
    }
    for (hname, h) in &parsed.hypothesis {
        let hyp = hypothesis(file, hname, h)?;
        if a.hypotheses.insert(hname.clone(), hyp).is_some() {
            let at = h.span().start;
            return Err(file.error_at(at, at + 1, format!("hypothesis '{hname}' defined twice")));
        }
    }
    for c in &parsed.claim {
        let claim = build_claim(file, c, None)?;
        if let Some(prev) = a.ids.insert(claim.id.clone(), claim.position.clone()) {
            let (s, t) = c
                .get_ref()
                .id
                .as_ref()
                .map_or((c.span().start, c.span().start + 1), |s| {
                    (s.span().start, s.span().end)
                });
            return Err(file.error_at(
                s,
                t,
                format!("duplicate claim id '{}' (first at {prev})", claim.id),
            ));
        }
        if let (Body::Definition(bs), Some(d)) = (&claim.body, &c.get_ref().define) {
            let origin = Origin::of(file, d);
            a.defs
                .extend(bs.iter().map(|b| (b.clone(), origin.clone())));
        }
        a.claims.push(claim);
    }
    Ok(())
}

/// A `[hypothesis.NAME]` table: exactly one of `branch` and `when`; a `when` is a
/// comparison `a > b` or `a < b`.
fn hypothesis(
    file: &Arc<SourceFile>,
    name: &str,
    h: &Spanned<raw::HypothesisToml>,
) -> Result<claim::Hypothesis, LoadError> {
    use crate::claims::ast::{BinOp, ExprKind};
    let t = h.get_ref();
    let at = |s: &Spanned<String>, m: String| file.error_at(s.span().start, s.span().end, m);
    let kind = match (&t.branch, &t.when) {
        (Some(b), None) => claim::HypothesisKind::Branch(b.get_ref().clone()),
        (None, Some(w)) => {
            let p = fields::pexpr(file, w)?;
            let sign = match &p.expr.kind {
                ExprKind::Binary(BinOp::Gt, _, _) => 1,
                ExprKind::Binary(BinOp::Lt, _, _) => -1,
                _ => {
                    return Err(at(
                        w,
                        format!("hypothesis '{name}': 'when' must be a comparison a > b or a < b"),
                    ));
                }
            };
            claim::HypothesisKind::Sign { condition: p, sign }
        }
        _ => {
            let at0 = h.span().start;
            return Err(file.error_at(
                at0,
                at0 + 1,
                format!("hypothesis '{name}' needs exactly one of 'branch' and 'when'"),
            ));
        }
    };
    Ok(claim::Hypothesis {
        name: name.to_string(),
        statement: t.statement.get_ref().clone(),
        paper: t.paper.get_ref().clone(),
        kind,
        origin: Origin::of(file, &t.statement),
    })
}

fn domain(file: &Arc<SourceFile>, name: &str, d: &Spanned<DomainToml>) -> Result<Dom, LoadError> {
    let sp = (d.span().start, d.span().end);
    Ok(Dom {
        name: name.to_string(),
        vars: var_list(file, &d.get_ref().vars, sp)?,
        about: fields::var_about(&d.get_ref().vars),
        wheres: pexprs(file, &d.get_ref().wheres)?,
    })
}

/// Labels → claim ids (the coverage table's backbone).
pub fn coverage(cat: &Catalogue) -> BTreeMap<String, Vec<String>> {
    let mut m: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for c in &cat.claims {
        for l in &c.labels {
            m.entry(l.clone()).or_default().push(c.id.clone());
        }
    }
    m
}

/// Reads the `\label{...}` names of a LaTeX source, in order of appearance, without
/// duplicates.
pub fn latex_labels(tex: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut rest = tex;
    while let Some(j) = rest.find("\\label{") {
        rest = &rest[j + 7..];
        if let Some(e) = rest.find('}') {
            let l = rest[..e].to_string();
            if !out.contains(&l) {
                out.push(l);
            }
            rest = &rest[e..];
        }
    }
    out
}
