//! From a raw `[[claim]]` table to a [`Claim`]: the fields every claim has (with the
//! [`DEFAULTS`](super::defaults::DEFAULTS) and, for the inner claim of a negation, the
//! outer claim's values through [`inherit`]), then one function per kind for the
//! kind-specific fields.  Every missing-field error points at its table.

use super::claim::{Body, Claim, ExactSpec, Hint, PExpr};
use super::defaults::{of, pick, pick_count};
use super::fields::{bindings, name_field, pexpr, pexprs, var_list};
use super::raw::ClaimToml;
use super::source::{LoadError, Located, Origin, SourceFile};
use crate::claims::kind::{Form, Kind, Verdict};
use std::sync::Arc;
use toml::Spanned;

/// One `[[claim]]` (or `[claim.inner]`) table being read.
struct Table<'a> {
    file: &'a Arc<SourceFile>,
    t: &'a ClaimToml,
    /// The table's first byte, where missing-field errors point.
    at: (usize, usize),
    /// The outer claim of an inner claim.
    outer: Option<&'a Claim>,
}

impl Table<'_> {
    fn error(&self, message: impl Into<String>) -> LoadError {
        self.file.error_at(self.at.0, self.at.1, message)
    }
    fn missing(&self, what: &str) -> LoadError {
        self.error(format!("claim is missing required field '{what}'"))
    }
    fn needs(&self, kind: Kind, what: &str) -> LoadError {
        let article = if kind.name().starts_with(['a', 'e', 'i', 'o', 'u']) {
            "an"
        } else {
            "a"
        };
        self.error(format!("{article} {kind} claim needs field '{what}'"))
    }
    fn at<T>(&self, s: &Spanned<T>, message: impl Into<String>) -> LoadError {
        self.file.error_at(s.span().start, s.span().end, message)
    }
    /// A required expression field of a `kind` claim.
    fn expr(
        &self,
        f: &Option<Spanned<String>>,
        kind: Kind,
        what: &str,
    ) -> Result<PExpr, LoadError> {
        match f {
            Some(s) => pexpr(self.file, s),
            None => Err(self.needs(kind, what)),
        }
    }
    /// A required name field of a `kind` claim.
    fn name(
        &self,
        f: &Option<Spanned<String>>,
        kind: Kind,
        what: &str,
    ) -> Result<String, LoadError> {
        match f {
            Some(s) => name_field(self.file, s, what),
            None => Err(self.needs(kind, what)),
        }
    }
    /// A numeric field with its default and range.
    fn number(&self, field: &str, own: Option<f64>) -> Result<f64, LoadError> {
        pick(field, own).map_err(|m| self.field_error(field, m))
    }
    fn count(&self, field: &str, own: Option<usize>) -> Result<usize, LoadError> {
        pick_count(field, own).map_err(|m| self.field_error(field, m))
    }
    /// An error at the line `field = …` of this table (the value's text underlined),
    /// or at the table where the field is not written there (an inherited value).
    fn field_error(&self, field: &str, message: String) -> LoadError {
        let text = &self.file.text;
        let start = self.at.0.min(text.len());
        // the table ends where the next one starts
        let end = text[start + 1.min(text.len() - start)..]
            .find("\n[")
            .map_or(text.len(), |j| start + 1 + j);
        let mut at = start;
        for line in text[start..end].split_inclusive('\n') {
            let t = line.trim_start();
            if let Some(rest) = t.strip_prefix(field)
                && rest.trim_start().starts_with('=')
            {
                let eq = at + (line.len() - t.len()) + field.len();
                let value_start = eq + rest.find('=').map_or(0, |j| j + 1);
                let value = &text[value_start..at + line.trim_end().len()];
                let lead = value.len() - value.trim_start().len();
                let v0 = value_start + lead;
                let v1 = (v0 + value.trim().len()).max(v0 + 1).min(text.len());
                return self.file.error_at(v0, v1, message);
            }
            at += line.len();
        }
        self.error(message)
    }
}

/// The value of a field of an inner claim: its own if given, else the outer claim's.
pub fn inherit<T: Clone>(own: Option<T>, outer: Option<&T>) -> Option<T> {
    own.or_else(|| outer.cloned())
}

/// A list field given as a non-empty list.
fn given<T>(v: Vec<T>) -> Option<Vec<T>> {
    (!v.is_empty()).then_some(v)
}

/// Builds a claim from its table; `outer` is the negation around an inner claim.
pub fn build_claim(
    file: &Arc<SourceFile>,
    c: &Spanned<ClaimToml>,
    outer: Option<&Claim>,
) -> Result<Claim, LoadError> {
    let tb = Table {
        file,
        t: c.get_ref(),
        at: (c.span().start, c.span().start + 1),
        outer,
    };
    let mut claim = shell(&tb)?;
    claim.exact = exact(&tb, claim.kind)?;
    claim.body = body(&tb, &claim)?;
    claim.hint = hint(&tb, &claim)?;
    Ok(claim)
}

fn id(tb: &Table<'_>) -> Result<String, LoadError> {
    match (&tb.t.id, tb.outer) {
        (Some(id), _) => {
            let s = id.get_ref();
            let ok = !s.is_empty()
                && s.chars()
                    .all(|ch| ch.is_ascii_alphanumeric() || "_.:-".contains(ch));
            if !ok {
                return Err(tb.at(id, format!("invalid claim id '{s}' (use [A-Za-z0-9_.:-])")));
            }
            Ok(s.clone())
        }
        (None, Some(o)) => Ok(format!("{}.inner", o.id)),
        (None, None) => Err(tb.missing("id")),
    }
}

fn expect(tb: &Table<'_>, kind: Kind) -> Result<Option<Verdict>, LoadError> {
    let Some(e) = &tb.t.expect else {
        if tb.outer.is_none() && kind != Kind::Definition {
            return Err(tb.missing("expect"));
        }
        return Ok(None);
    };
    if kind == Kind::Definition {
        return Err(tb.at(e, "a definition has no verdict: remove 'expect'"));
    }
    Ok(Some(Verdict::from(*e.get_ref())))
}

/// The fields a top-level claim must give.
fn required(tb: &Table<'_>, form: Form) -> Result<(), LoadError> {
    let t = tb.t;
    if tb.outer.is_some() {
        return Ok(());
    }
    let fields = [
        ("location", t.location.is_some()),
        ("printed", t.printed.is_some()),
        ("environment", t.environment.is_some()),
        ("role", t.role.is_some()),
        ("corrects", form == Form::Printed || t.corrects.is_some()),
    ];
    match fields.iter().find(|(_, given)| !given) {
        Some((what, _)) => Err(tb.missing(what)),
        None => Ok(()),
    }
}

/// Everything but the kind-specific body and the exact settings.
fn shell(tb: &Table<'_>) -> Result<Claim, LoadError> {
    let (t, o) = (tb.t, tb.outer);
    let id = id(tb)?;
    let kind = *t.kind.as_ref().ok_or_else(|| tb.missing("kind"))?.get_ref();
    let form =
        inherit(t.form.as_ref().map(|f| *f.get_ref()), o.map(|o| &o.form)).unwrap_or(Form::Printed);
    let expect = expect(tb, kind)?;
    required(tb, form)?;
    let vars = given(var_list(tb.file, &t.vars, tb.at)?);
    let wheres = given(pexprs(tb.file, &t.wheres)?);
    let lets = match &t.let_ {
        Some(l) => Some(bindings(tb.file, l)?),
        None => None,
    };
    let scale = match &t.scale {
        Some(s) => Some(pexpr(tb.file, s)?),
        None => None,
    };
    let samples = tb.count("samples", t.samples.or(o.map(|o| o.samples)))?;
    let max_loss_bits = tb.number(
        "max_loss_bits",
        t.max_loss_bits.or(o.map(|o| o.max_loss_bits)),
    )?;
    let refute_floor_bits = tb.number(
        "refute_floor_bits",
        t.refute_floor_bits.or(o.map(|o| o.refute_floor_bits)),
    )?;
    let (lets, lets_origin) = match lets {
        Some((b, origin)) => (b, Some(origin)),
        None => (
            o.map_or_else(Vec::new, |o| o.lets.clone()),
            o.and_then(|o| o.lets_origin.clone()),
        ),
    };
    Ok(Claim {
        id,
        labels: inherit(given(t.labels.clone()), o.map(|o| &o.labels)).unwrap_or_default(),
        location: inherit(t.location.clone(), o.map(|o| &o.location)).unwrap_or_default(),
        printed: inherit(t.printed.clone(), o.map(|o| &o.printed)).unwrap_or_default(),
        kind,
        form,
        corrects: t.corrects.clone(),
        expect,
        note: t.note.clone(),
        position: tb.file.position(tb.at.0),
        domain: inherit(
            t.domain.as_ref().map(|d| Located::of(tb.file, d)),
            o.and_then(|o| o.domain.as_ref()),
        ),
        vars: inherit(vars, o.map(|o| &o.vars)).unwrap_or_default(),
        // the descriptions go with the list they come from
        var_about: inherit(
            (!t.vars.is_empty()).then(|| super::fields::var_about(&t.vars)),
            o.map(|o| &o.var_about),
        )
        .unwrap_or_default(),
        wheres: inherit(wheres, o.map(|o| &o.wheres)).unwrap_or_default(),
        lets,
        lets_origin,
        body: Body::Definition(Vec::new()),
        scale: inherit(scale, o.and_then(|o| o.scale.as_ref())),
        samples,
        exact: None,
        max_loss_bits,
        refute_floor_bits,
        seed: t
            .seed
            .or(o.map(|o| o.seed))
            .unwrap_or(of("seed").value as u64),
        environment: t.environment.as_ref().map(|s| Located::of(tb.file, s)),
        role: t.role.as_ref().map(|s| Located::of(tb.file, s)),
        uses: t.uses.iter().map(|s| Located::of(tb.file, s)).collect(),
        hint: None,
        hypotheses: hypotheses(tb),
        construction: t.construction.as_ref().map(|s| s.get_ref().clone()),
    })
}

/// The hypotheses a claim states; an inner claim rests on those its negation states.
fn hypotheses(tb: &Table<'_>) -> Vec<Located> {
    match (tb.t.hypotheses.is_empty(), tb.outer) {
        (true, Some(o)) => o.hypotheses.clone(),
        _ => (tb.t.hypotheses.iter())
            .map(|s| Located::of(tb.file, s))
            .collect(),
    }
}

/// `hint`: identity claims only, naming one of the claim's own `let`s.
fn hint(tb: &Table<'_>, claim: &Claim) -> Result<Option<Hint>, LoadError> {
    let Some(h) = &tb.t.hint else {
        return Ok(None);
    };
    if claim.kind != Kind::Identity {
        return Err(tb.at(h, "a proof hint is only read for identity claims"));
    }
    let value = h.get_ref().value.get_ref();
    if !claim
        .lets
        .iter()
        .any(|b| &b.name == value && b.params.is_none())
    {
        return Err(tb.at(
            &h.get_ref().value,
            format!("the hint's value '{value}' is not a let of this claim"),
        ));
    }
    let multipliers = pexprs(tb.file, &h.get_ref().multipliers)?;
    if multipliers.is_empty() {
        return Err(tb.at(h, "a proof hint needs at least one multiplier"));
    }
    Ok(Some(Hint {
        value: value.clone(),
        multipliers,
        origin: Origin::of(tb.file, &h.get_ref().value),
    }))
}

/// `exact = true`: identities only.
fn exact(tb: &Table<'_>, kind: Kind) -> Result<Option<ExactSpec>, LoadError> {
    if tb.t.exact != Some(true) {
        return Ok(None);
    }
    if kind != Kind::Identity {
        return Err(tb.error("exact = true is only supported for identity claims"));
    }
    Ok(Some(ExactSpec {
        samples: tb.count("exact_samples", tb.t.exact_samples)?,
    }))
}

/// The kind-specific fields.
fn body(tb: &Table<'_>, shell: &Claim) -> Result<Body, LoadError> {
    let t = tb.t;
    let k = shell.kind;
    match k {
        Kind::Identity => Ok(Body::Identity {
            lhs: tb.expr(&t.lhs, k, "lhs")?,
            rhs: tb.expr(&t.rhs, k, "rhs")?,
        }),
        Kind::Independence => Ok(Body::Independence {
            expr: tb.expr(&t.expr, k, "expr")?,
            wrt: tb.name(&t.wrt, k, "wrt")?,
            redraws: tb.count("redraws", t.redraws)?,
        }),
        Kind::Asymptotic => asymptotic(tb),
        Kind::Negation => negation(tb, shell),
        Kind::Existence => existence(tb),
        Kind::Definition => {
            let d = t.define.as_ref().ok_or_else(|| tb.needs(k, "define"))?;
            Ok(Body::Definition(bindings(tb.file, d)?.0))
        }
    }
}

fn asymptotic(tb: &Table<'_>) -> Result<Body, LoadError> {
    let (t, k) = (tb.t, Kind::Asymptotic);
    let steps = tb.count("steps", t.steps)?;
    let h0 = tb.number("h0", t.h0)?;
    Ok(Body::Asymptotic {
        expr: tb.expr(&t.expr, k, "expr")?,
        var: tb.name(&t.var, k, "var")?,
        order: t
            .order
            .filter(|o| o.is_finite())
            .ok_or_else(|| tb.needs(k, "order"))?,
        h0,
        steps,
        slope_tol: tb.number("slope_tol", t.slope_tol)?,
    })
}

fn negation(tb: &Table<'_>, shell: &Claim) -> Result<Body, LoadError> {
    let inner =
        tb.t.inner
            .as_ref()
            .ok_or_else(|| tb.error("a negation claim needs a [claim.inner] table"))?;
    let ic = build_claim(tb.file, inner, Some(shell))?;
    if matches!(ic.kind, Kind::Definition | Kind::Negation) {
        let at = inner.span().start;
        return Err(tb.file.error_at(
            at,
            at + 1,
            "the inner claim of a negation must be an identity, independence, asymptotic or existence claim",
        ));
    }
    Ok(Body::Negation(Box::new(ic)))
}

fn existence(tb: &Table<'_>) -> Result<Body, LoadError> {
    let t = tb.t;
    let equations = pexprs(tb.file, &t.equations)?;
    let start = pexprs(tb.file, &t.start)?;
    let n = t.unknowns.len();
    if n == 0 || equations.len() != n || start.len() != n {
        return Err(tb.error(
            "an existence claim needs as many 'equations' and 'start' entries as 'unknowns' (at least one)",
        ));
    }
    Ok(Body::Existence {
        unknowns: t.unknowns.clone(),
        equations,
        start,
        in_set: match &t.in_set {
            Some(s) => Some(pexpr(tb.file, s)?),
            None => None,
        },
        tries: tb.count("tries", t.tries)?,
    })
}
