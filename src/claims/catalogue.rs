//! Loads the claim catalogue (`identities/*.toml`, format in `identities/README.md`).
//!
//! Every problem is a [`LoadError`] rendered as `file:line:column: message` followed by
//! the offending source line with the bad text underlined.  Nothing panics.

use super::ast::{Binding, Expr, ExprKind, Span};
use super::kind::{Form, Kind, Verdict};
use super::lexer::SyntaxError;
use super::parser::{parse_bindings, parse_expr};
use super::registry::Registry;
use super::structure::Located;
use serde::Deserialize;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use toml::Spanned;

/// A load error with its position.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadError {
    /// File name as given.
    pub file: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column (characters).
    pub col: usize,
    /// What is wrong.
    pub message: String,
    /// The source line.
    pub line_text: String,
    /// Number of characters to underline.
    pub width: usize,
}

impl std::fmt::Display for LoadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{}:{}: {}\n    {}\n    {}{}",
            self.file,
            self.line,
            self.col,
            self.message,
            self.line_text,
            " ".repeat(self.col.saturating_sub(1)),
            "^".repeat(self.width.max(1))
        )
    }
}

impl std::error::Error for LoadError {}

/// A source file's text, for positions.
#[derive(Debug)]
pub struct SourceFile {
    /// Path as displayed.
    pub name: String,
    /// Contents.
    pub text: String,
}

impl SourceFile {
    /// An error at byte range `[start, end)` of the file.
    pub fn error_at(&self, start: usize, end: usize, message: impl Into<String>) -> LoadError {
        let start = start.min(self.text.len());
        let mut s = start;
        while !self.text.is_char_boundary(s) {
            s -= 1;
        }
        let line_start = self.text[..s].rfind('\n').map_or(0, |j| j + 1);
        let line_end = self.text[s..].find('\n').map_or(self.text.len(), |j| s + j);
        let line = self.text[..s].matches('\n').count() + 1;
        let col = self.text[line_start..s].chars().count() + 1;
        let end = end.clamp(s, line_end.max(s));
        let mut e = end;
        while !self.text.is_char_boundary(e) {
            e -= 1;
        }
        LoadError {
            file: self.name.clone(),
            line,
            col,
            message: message.into(),
            line_text: self.text[line_start..line_end].to_string(),
            width: self.text[s..e].chars().count(),
        }
    }
}

/// Where an expression string sits in its file.
#[derive(Debug, Clone)]
pub struct Origin {
    /// The file.
    pub file: Arc<SourceFile>,
    /// Byte offset of the string's content in the file, when the content maps byte for
    /// byte (literal strings, or basic strings without escapes); else `None`.
    pub content_start: Option<usize>,
    /// The span of the whole TOML value (with quotes).
    pub value_span: (usize, usize),
}

impl Origin {
    /// An error at a span of the expression string.
    pub fn error(&self, span: Option<Span>, message: impl Into<String>) -> LoadError {
        match (self.content_start, span) {
            (Some(c), Some(sp)) => self.file.error_at(c + sp.start, c + sp.end, message),
            _ => self
                .file
                .error_at(self.value_span.0, self.value_span.1, message),
        }
    }
    /// `file:line` of the string.
    pub fn position(&self) -> String {
        let e = self.file.error_at(self.value_span.0, self.value_span.0, "");
        format!("{}:{}", e.file, e.line)
    }
}

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
    /// Total-degree bound of the numerator.
    pub degree: u32,
    /// Number of exact points.
    pub samples: usize,
}

/// A sampling domain.
#[derive(Debug, Clone)]
pub struct Domain {
    /// Name.
    pub name: String,
    /// Variables in order.
    pub vars: Vec<(String, PExpr)>,
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
    /// Expected verdict (`None` for definitions).
    pub expect: Option<Verdict>,
    /// Note.
    pub note: Option<String>,
    /// `file:line` of the claim.
    pub position: String,
    /// Domain name.
    pub domain: Option<String>,
    /// Extra sampled variables.
    pub vars: Vec<(String, PExpr)>,
    /// Extra constraints.
    pub wheres: Vec<PExpr>,
    /// Let bindings.
    pub lets: Vec<Binding>,
    /// The let block text (for reports).
    pub let_text: Option<String>,
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
    /// Section titles by file.
    pub sections: Vec<(String, String, String)>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct FileToml {
    section: Option<SectionToml>,
    #[serde(default)]
    claim: Vec<Spanned<ClaimToml>>,
    #[serde(default)]
    domain: BTreeMap<String, Spanned<DomainToml>>,
    #[serde(default)]
    convention: Vec<toml::Value>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SectionToml {
    number: String,
    title: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct DomainToml {
    #[serde(default)]
    vars: Vec<Vec<Spanned<String>>>,
    #[serde(default, rename = "where")]
    wheres: Vec<Spanned<String>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct ClaimToml {
    id: Option<Spanned<String>>,
    #[serde(default)]
    labels: Vec<String>,
    location: Option<String>,
    printed: Option<String>,
    kind: Option<Spanned<String>>,
    form: Option<Spanned<String>>,
    corrects: Option<String>,
    expect: Option<Spanned<String>>,
    note: Option<String>,
    domain: Option<Spanned<String>>,
    #[serde(default)]
    vars: Vec<Vec<Spanned<String>>>,
    #[serde(default, rename = "where")]
    wheres: Vec<Spanned<String>>,
    #[serde(rename = "let")]
    let_: Option<Spanned<String>>,
    lhs: Option<Spanned<String>>,
    rhs: Option<Spanned<String>>,
    scale: Option<Spanned<String>>,
    expr: Option<Spanned<String>>,
    wrt: Option<Spanned<String>>,
    redraws: Option<usize>,
    var: Option<Spanned<String>>,
    order: Option<f64>,
    h0: Option<f64>,
    steps: Option<usize>,
    slope_tol: Option<f64>,
    inner: Option<Box<Spanned<ClaimToml>>>,
    #[serde(default)]
    unknowns: Vec<String>,
    #[serde(default)]
    equations: Vec<Spanned<String>>,
    #[serde(default)]
    start: Vec<Spanned<String>>,
    #[serde(rename = "in")]
    in_set: Option<Spanned<String>>,
    tries: Option<usize>,
    define: Option<Spanned<String>>,
    samples: Option<usize>,
    exact: Option<bool>,
    degree: Option<u32>,
    exact_samples: Option<usize>,
    max_loss_bits: Option<f64>,
    refute_floor_bits: Option<f64>,
    seed: Option<u64>,
    environment: Option<Spanned<String>>,
    role: Option<Spanned<String>>,
    #[serde(default)]
    uses: Vec<Spanned<String>>,
}

fn origin_of(file: &Arc<SourceFile>, s: &Spanned<String>) -> Origin {
    let (a, b) = (s.span().start, s.span().end);
    let raw = file.text.get(a..b).unwrap_or("");
    let value = s.get_ref();
    let mut content_start = None;
    for (delim, literal) in [("'''", true), ("\"\"\"", false), ("'", true), ("\"", false)] {
        if raw.starts_with(delim) && raw.len() >= 2 * delim.len() {
            let mut c = a + delim.len();
            let mut inner = &raw[delim.len()..raw.len() - delim.len()];
            if delim.len() == 3 {
                if let Some(rest) = inner.strip_prefix('\n') {
                    inner = rest;
                    c += 1;
                } else if let Some(rest) = inner.strip_prefix("\r\n") {
                    inner = rest;
                    c += 2;
                }
            }
            if inner == value && (literal || !inner.contains('\\')) {
                content_start = Some(c);
            }
            break;
        }
    }
    Origin {
        file: file.clone(),
        content_start,
        value_span: (a, b),
    }
}

fn pexpr(file: &Arc<SourceFile>, s: &Spanned<String>) -> Result<PExpr, LoadError> {
    let origin = origin_of(file, s);
    let expr = parse_expr(s.get_ref()).map_err(|e| syntax(&origin, e))?;
    Ok(PExpr {
        expr,
        text: s.get_ref().clone(),
        origin,
    })
}

fn syntax(origin: &Origin, e: SyntaxError) -> LoadError {
    origin.error(Some(e.span), format!("syntax error: {}", e.message))
}

fn bindings(
    file: &Arc<SourceFile>,
    s: &Spanned<String>,
) -> Result<(Vec<Binding>, Origin), LoadError> {
    let origin = origin_of(file, s);
    let b = parse_bindings(s.get_ref()).map_err(|e| syntax(&origin, e))?;
    Ok((b, origin))
}

fn var_list(
    file: &Arc<SourceFile>,
    vars: &[Vec<Spanned<String>>],
    at: (usize, usize),
) -> Result<Vec<(String, PExpr)>, LoadError> {
    let mut out = Vec::new();
    for v in vars {
        if v.len() != 2 {
            let (a, b) = v.first().map_or(at, |x| (x.span().start, x.span().end));
            return Err(file.error_at(
                a,
                b,
                "a variable must be [\"name\", \"sampler expression\"]",
            ));
        }
        let name = v[0].get_ref();
        if parse_expr(name).map(|e| matches!(e.kind, ExprKind::Name(_))) != Ok(true) {
            return Err(file.error_at(
                v[0].span().start,
                v[0].span().end,
                format!("'{name}' is not a valid variable name"),
            ));
        }
        out.push((name.clone(), pexpr(file, &v[1])?));
    }
    Ok(out)
}

/// Loads every `*.toml` file of `dir` (sorted by name).
pub fn load_dir(dir: &Path, registry: Registry) -> Result<Catalogue, LoadError> {
    let rd = std::fs::read_dir(dir).map_err(|e| LoadError {
        file: dir.display().to_string(),
        line: 0,
        col: 0,
        message: format!("cannot read catalogue directory: {e}"),
        line_text: String::new(),
        width: 0,
    })?;
    let mut files: Vec<PathBuf> = rd
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    let mut sources = Vec::new();
    for p in files {
        let text = std::fs::read_to_string(&p).map_err(|e| LoadError {
            file: p.display().to_string(),
            line: 0,
            col: 0,
            message: format!("cannot read: {e}"),
            line_text: String::new(),
            width: 0,
        })?;
        sources.push((p.display().to_string(), text));
    }
    load_sources(&sources, registry)
}

/// Loads a catalogue from `(file name, text)` pairs.
pub fn load_sources(
    sources: &[(String, String)],
    mut registry: Registry,
) -> Result<Catalogue, LoadError> {
    let mut claims = Vec::new();
    let mut domains = BTreeMap::new();
    let mut sections = Vec::new();
    let mut ids: BTreeMap<String, String> = BTreeMap::new();
    let mut defs: Vec<(Binding, Origin)> = Vec::new();
    for (name, text) in sources {
        let file = Arc::new(SourceFile {
            name: name.clone(),
            text: text.clone(),
        });
        let parsed: FileToml = toml::from_str(text).map_err(|e| {
            let (a, b) = e.span().map_or((0, 0), |r| (r.start, r.end));
            file.error_at(a, b, e.message().trim().replace('\n', " "))
        })?;
        if let Some(s) = &parsed.section {
            sections.push((name.clone(), s.number.clone(), s.title.clone()));
        }
        let _ = &parsed.convention;
        for (dname, d) in &parsed.domain {
            let sp = (d.span().start, d.span().end);
            let dom = d.get_ref();
            let vars = var_list(&file, &dom.vars, sp)?;
            let wheres = dom
                .wheres
                .iter()
                .map(|w| pexpr(&file, w))
                .collect::<Result<_, _>>()?;
            if domains.contains_key(dname) {
                return Err(file.error_at(
                    sp.0,
                    sp.0 + 1,
                    format!("domain '{dname}' defined twice"),
                ));
            }
            domains.insert(
                dname.clone(),
                Domain {
                    name: dname.clone(),
                    vars,
                    wheres,
                },
            );
        }
        for c in &parsed.claim {
            let claim = build_claim(&file, c, None)?;
            if let Some(prev) = ids.insert(claim.id.clone(), claim.position.clone()) {
                let id = c.get_ref().id.as_ref();
                let (a, b) = id.map_or((c.span().start, c.span().start + 1), |s| {
                    (s.span().start, s.span().end)
                });
                return Err(file.error_at(
                    a,
                    b,
                    format!("duplicate claim id '{}' (first at {prev})", claim.id),
                ));
            }
            if let Body::Definition(bs) = &claim.body {
                let d = c.get_ref().define.as_ref();
                for b in bs {
                    let origin = d.map(|d| origin_of(&file, d)).unwrap_or_else(|| Origin {
                        file: file.clone(),
                        content_start: None,
                        value_span: (c.span().start, c.span().start + 1),
                    });
                    defs.push((b.clone(), origin));
                }
            }
            claims.push(claim);
        }
    }
    for (b, origin) in &defs {
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
    let cat = Catalogue {
        claims,
        domains,
        registry,
        sections,
    };
    check_names(&cat, &defs)?;
    super::structure::check(&cat)?;
    Ok(cat)
}

fn check_expr_calls(
    reg: &Registry,
    local: &BTreeSet<String>,
    e: &Expr,
    origin: &Origin,
) -> Result<(), LoadError> {
    let mut err = None;
    e.walk(&mut |x| {
        if err.is_some() {
            return;
        }
        if let ExprKind::Call(n, _) = &x.kind {
            let primitive = matches!(
                n.as_str(),
                "uniform" | "normal" | "randint" | "sign" | "choice"
            );
            if !reg.knows(n) && !local.contains(n) && !primitive {
                err = Some(origin.error(Some(x.span), format!("unknown function '{n}'")));
            }
        }
    });
    err.map_or(Ok(()), Err)
}

fn check_names(cat: &Catalogue, defs: &[(Binding, Origin)]) -> Result<(), LoadError> {
    let reg = &cat.registry;
    let none = BTreeSet::new();
    for (b, o) in defs {
        check_expr_calls(reg, &none, &b.body, o)?;
    }
    for d in cat.domains.values() {
        for (_, p) in &d.vars {
            check_expr_calls(reg, &none, &p.expr, &p.origin)?;
        }
        for p in &d.wheres {
            check_expr_calls(reg, &none, &p.expr, &p.origin)?;
        }
    }
    for c in &cat.claims {
        check_claim_names(cat, c)?;
    }
    Ok(())
}

fn check_claim_names(cat: &Catalogue, c: &Claim) -> Result<(), LoadError> {
    let reg = &cat.registry;
    if let Some(d) = &c.domain {
        if !cat.domains.contains_key(d) {
            return Err(LoadError {
                file: c.position.clone(),
                line: 0,
                col: 0,
                message: format!("claim '{}': unknown domain '{d}'", c.id),
                line_text: String::new(),
                width: 0,
            });
        }
    }
    let local: BTreeSet<String> = c
        .lets
        .iter()
        .filter(|b| b.params.is_some())
        .map(|b| b.name.clone())
        .collect();
    let mut all: Vec<&PExpr> = Vec::new();
    all.extend(c.vars.iter().map(|v| &v.1));
    all.extend(c.wheres.iter());
    all.extend(c.scale.iter());
    match &c.body {
        Body::Identity { lhs, rhs } => {
            all.push(lhs);
            all.push(rhs);
        }
        Body::Independence { expr, .. } | Body::Asymptotic { expr, .. } => all.push(expr),
        Body::Existence {
            equations,
            start,
            in_set,
            ..
        } => {
            all.extend(equations.iter());
            all.extend(start.iter());
            all.extend(in_set.iter());
        }
        Body::Negation(inner) => check_claim_names(cat, inner)?,
        Body::Definition(_) => {}
    }
    for p in all {
        check_expr_calls(reg, &local, &p.expr, &p.origin)?;
    }
    Ok(())
}

fn build_claim(
    file: &Arc<SourceFile>,
    c: &Spanned<ClaimToml>,
    outer: Option<&Claim>,
) -> Result<Claim, LoadError> {
    let t = c.get_ref();
    let at = (c.span().start, c.span().start + 1);
    let need = |what: &str| {
        file.error_at(
            at.0,
            at.1,
            format!("claim is missing required field '{what}'"),
        )
    };
    let id = match (&t.id, outer) {
        (Some(id), _) => {
            let s = id.get_ref();
            if s.is_empty()
                || !s
                    .chars()
                    .all(|ch| ch.is_ascii_alphanumeric() || "_.:-".contains(ch))
            {
                return Err(file.error_at(
                    id.span().start,
                    id.span().end,
                    format!("invalid claim id '{s}' (use [A-Za-z0-9_.:-])"),
                ));
            }
            s.clone()
        }
        (None, Some(o)) => format!("{}.inner", o.id),
        (None, None) => return Err(need("id")),
    };
    let kind_s = t.kind.as_ref().ok_or_else(|| need("kind"))?;
    let kind = match kind_s.get_ref().as_str() {
        "identity" => Kind::Identity,
        "independence" => Kind::Independence,
        "asymptotic" => Kind::Asymptotic,
        "negation" => Kind::Negation,
        "existence" => Kind::Existence,
        "definition" => Kind::Definition,
        k => {
            return Err(file.error_at(
                kind_s.span().start,
                kind_s.span().end,
                format!("unknown kind '{k}' (identity | independence | asymptotic | negation | existence | definition)"),
            ))
        }
    };
    let form = match &t.form {
        None => outer.map_or(Form::Printed, |o| o.form),
        Some(f) => match Form::ALL.iter().find(|x| x.name() == f.get_ref()) {
            Some(x) => *x,
            None => {
                return Err(file.error_at(
                    f.span().start,
                    f.span().end,
                    format!(
                        "form must be 'printed' or 'corrected', not '{}'",
                        f.get_ref()
                    ),
                ))
            }
        },
    };
    let expect = match &t.expect {
        None => None,
        Some(e) => {
            let v = e.get_ref();
            let Some(verdict) = Verdict::ALL
                .iter()
                .find(|x| x.name() == v && **x != Verdict::Defined)
            else {
                return Err(file.error_at(
                    e.span().start,
                    e.span().end,
                    format!("expect must be holds | refuted | proved | inconclusive, not '{v}'"),
                ));
            };
            if kind == Kind::Definition {
                return Err(file.error_at(
                    e.span().start,
                    e.span().end,
                    "a definition has no verdict: remove 'expect'",
                ));
            }
            Some(*verdict)
        }
    };
    if outer.is_none() && kind != Kind::Definition && expect.is_none() {
        return Err(need("expect"));
    }
    if outer.is_none() {
        if t.location.is_none() {
            return Err(need("location"));
        }
        if t.printed.is_none() {
            return Err(need("printed"));
        }
    }
    if form == Form::Corrected && t.corrects.is_none() && outer.is_none() {
        return Err(need("corrects"));
    }
    let vars = var_list(file, &t.vars, at)?;
    let wheres: Vec<PExpr> = t
        .wheres
        .iter()
        .map(|w| pexpr(file, w))
        .collect::<Result<_, _>>()?;
    let (lets, let_text) = match &t.let_ {
        Some(l) => (bindings(file, l)?.0, Some(l.get_ref().clone())),
        None => (Vec::new(), None),
    };
    let req = |f: &Option<Spanned<String>>, what: &str| -> Result<PExpr, LoadError> {
        match f {
            Some(s) => pexpr(file, s),
            None => Err(file.error_at(
                at.0,
                at.1,
                format!("a {} claim needs field '{what}'", kind.name()),
            )),
        }
    };
    let name_field = |f: &Option<Spanned<String>>, what: &str| -> Result<String, LoadError> {
        match f {
            Some(s) => match parse_expr(s.get_ref()).map(|e| e.kind) {
                Ok(ExprKind::Name(n)) => Ok(n),
                _ => Err(file.error_at(
                    s.span().start,
                    s.span().end,
                    format!("'{what}' must be a variable name"),
                )),
            },
            None => Err(file.error_at(
                at.0,
                at.1,
                format!("a {} claim needs field '{what}'", kind.name()),
            )),
        }
    };
    let mut shell = Claim {
        id: id.clone(),
        labels: if t.labels.is_empty() {
            outer.map_or_else(Vec::new, |o| o.labels.clone())
        } else {
            t.labels.clone()
        },
        location: t
            .location
            .clone()
            .or_else(|| outer.map(|o| o.location.clone()))
            .unwrap_or_default(),
        printed: t
            .printed
            .clone()
            .or_else(|| outer.map(|o| o.printed.clone()))
            .unwrap_or_default(),
        kind,
        form,
        corrects: t.corrects.clone(),
        expect,
        note: t.note.clone(),
        position: file.error_at(at.0, at.0, "").file.clone()
            + ":"
            + &file.error_at(at.0, at.0, "").line.to_string(),
        domain: t
            .domain
            .as_ref()
            .map(|d| d.get_ref().clone())
            .or_else(|| outer.and_then(|o| o.domain.clone())),
        vars: if t.vars.is_empty() {
            outer.map_or_else(Vec::new, |o| o.vars.clone())
        } else {
            vars
        },
        wheres: if t.wheres.is_empty() {
            outer.map_or_else(Vec::new, |o| o.wheres.clone())
        } else {
            wheres
        },
        lets: if t.let_.is_none() {
            outer.map_or_else(Vec::new, |o| o.lets.clone())
        } else {
            lets
        },
        let_text: if t.let_.is_none() {
            outer.and_then(|o| o.let_text.clone())
        } else {
            let_text
        },
        body: Body::Definition(Vec::new()),
        scale: match &t.scale {
            Some(s) => Some(pexpr(file, s)?),
            None => outer.and_then(|o| o.scale.clone()),
        },
        samples: t.samples.or(outer.map(|o| o.samples)).unwrap_or(8).max(1),
        exact: None,
        max_loss_bits: t
            .max_loss_bits
            .or(outer.map(|o| o.max_loss_bits))
            .unwrap_or(24.0),
        refute_floor_bits: t
            .refute_floor_bits
            .or(outer.map(|o| o.refute_floor_bits))
            .unwrap_or(30.0),
        seed: t.seed.or(outer.map(|o| o.seed)).unwrap_or(0),
        environment: t
            .environment
            .as_ref()
            .map(|s| Located::new(s, origin_of(file, s))),
        role: t.role.as_ref().map(|s| Located::new(s, origin_of(file, s))),
        uses: t
            .uses
            .iter()
            .map(|s| Located::new(s, origin_of(file, s)))
            .collect(),
    };
    if t.samples == Some(0) || t.samples.is_some_and(|s| s > 10_000) {
        return Err(file.error_at(at.0, at.1, "samples must be between 1 and 10000"));
    }
    if t.exact == Some(true) {
        let degree = t.degree.ok_or_else(|| {
            file.error_at(
                at.0,
                at.1,
                "exact = true needs 'degree' (Schwartz–Zippel bound)",
            )
        })?;
        if kind != Kind::Identity {
            return Err(file.error_at(
                at.0,
                at.1,
                "exact = true is only supported for identity claims",
            ));
        }
        shell.exact = Some(ExactSpec {
            degree,
            samples: t.exact_samples.unwrap_or(4).max(1),
        });
    }
    shell.body = match kind {
        Kind::Identity => Body::Identity {
            lhs: req(&t.lhs, "lhs")?,
            rhs: req(&t.rhs, "rhs")?,
        },
        Kind::Independence => Body::Independence {
            expr: req(&t.expr, "expr")?,
            wrt: name_field(&t.wrt, "wrt")?,
            redraws: t.redraws.unwrap_or(3).clamp(1, 100),
        },
        Kind::Asymptotic => {
            let steps = t.steps.unwrap_or(6);
            if !(3..=60).contains(&steps) {
                return Err(file.error_at(at.0, at.1, "steps must be between 3 and 60"));
            }
            let h0 = t.h0.unwrap_or(0.1);
            if !(h0 > 0.0 && h0.is_finite()) {
                return Err(file.error_at(at.0, at.1, "h0 must be positive"));
            }
            Body::Asymptotic {
                expr: req(&t.expr, "expr")?,
                var: name_field(&t.var, "var")?,
                order: t.order.ok_or_else(|| {
                    file.error_at(at.0, at.1, "an asymptotic claim needs 'order'")
                })?,
                h0,
                steps,
                slope_tol: t.slope_tol.unwrap_or(0.25),
            }
        }
        Kind::Negation => {
            let inner = t.inner.as_ref().ok_or_else(|| {
                file.error_at(at.0, at.1, "a negation claim needs a [claim.inner] table")
            })?;
            let ic = build_claim(file, inner, Some(&shell))?;
            if ic.kind == Kind::Definition || ic.kind == Kind::Negation {
                return Err(file.error_at(inner.span().start, inner.span().start + 1, "the inner claim of a negation must be an identity, independence, asymptotic or existence claim"));
            }
            Body::Negation(Box::new(ic))
        }
        Kind::Existence => {
            let equations: Vec<PExpr> = t
                .equations
                .iter()
                .map(|e| pexpr(file, e))
                .collect::<Result<_, _>>()?;
            let start: Vec<PExpr> = t
                .start
                .iter()
                .map(|e| pexpr(file, e))
                .collect::<Result<_, _>>()?;
            if t.unknowns.is_empty()
                || equations.len() != t.unknowns.len()
                || start.len() != t.unknowns.len()
            {
                return Err(file.error_at(at.0, at.1, "an existence claim needs as many 'equations' and 'start' entries as 'unknowns' (at least one)"));
            }
            Body::Existence {
                unknowns: t.unknowns.clone(),
                equations,
                start,
                in_set: match &t.in_set {
                    Some(s) => Some(pexpr(file, s)?),
                    None => None,
                },
                tries: t.tries.unwrap_or(4).clamp(1, 100),
            }
        }
        Kind::Definition => {
            let d = t.define.as_ref().ok_or_else(|| {
                file.error_at(at.0, at.1, "a definition claim needs field 'define'")
            })?;
            Body::Definition(bindings(file, d)?.0)
        }
    };
    Ok(shell)
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
