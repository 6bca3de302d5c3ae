//! Load-time checks of names.  Every variable an expression uses must be bound where the
//! engine evaluates it, every function must exist and get the right number of
//! arguments, random primitives appear only in sampler expressions, a claim's domain
//! exists, and no definition calls itself (directly or through others).  Each error
//! points at the offending text, so a catalogue that loads never fails on a name.

use super::claim::{Body, Catalogue, Claim, Domain, PExpr};
use super::source::{LoadError, Origin};
use crate::claims::ast::{Binding, Expr, ExprKind};
use crate::claims::builtins::{Arity, Builtin, Primitive};
use crate::claims::registry::Registry;
use std::collections::{BTreeMap, BTreeSet};

/// The names bound in the language itself.
const CONSTANTS: [&str; 4] = ["pi", "i", "I3", "I2"];

/// What an expression may use.
#[derive(Clone, Default)]
struct Scope {
    /// Bound variables.
    vars: Vec<String>,
    /// Local (`let`) functions and their arities.
    local: BTreeMap<String, usize>,
    /// May random primitives be drawn (domain `vars`, existence `start`)?
    sampling: bool,
}

impl Scope {
    fn with(&self, names: &[String]) -> Scope {
        let mut s = self.clone();
        s.vars.extend(names.iter().cloned());
        s
    }
    fn sampling(&self) -> Scope {
        Scope {
            sampling: true,
            ..self.clone()
        }
    }
    /// A function body: its parameters only.
    fn params(ps: &[String]) -> Scope {
        Scope {
            vars: ps.to_vec(),
            ..Scope::default()
        }
    }
}

struct Checker<'c> {
    reg: &'c Registry,
}

impl Checker<'_> {
    fn expr(&self, e: &Expr, scope: &Scope, at: &Origin) -> Result<(), LoadError> {
        let err = |m: String| Err(at.error(Some(e.span), m));
        match &e.kind {
            ExprKind::Num(_) => Ok(()),
            ExprKind::Name(n) => {
                if scope.vars.contains(n) || CONSTANTS.contains(&n.as_str()) {
                    Ok(())
                } else {
                    err(format!("unknown variable '{n}'"))
                }
            }
            ExprKind::Call(name, args) => {
                if let Some(m) = self.call_error(name, args.len(), scope) {
                    return err(m);
                }
                args.iter().try_for_each(|a| self.expr(a, scope, at))
            }
            ExprKind::Sum {
                var,
                from,
                to,
                body,
                ..
            } => {
                self.expr(from, scope, at)?;
                self.expr(to, scope, at)?;
                self.expr(body, &scope.with(std::slice::from_ref(var)), at)
            }
            ExprKind::Deriv {
                body,
                var,
                component,
            } => {
                if !scope.vars.contains(var) {
                    return err(format!("d(): '{var}' is not a variable in scope"));
                }
                if let Some(c) = component {
                    self.expr(c, scope, at)?;
                }
                self.expr(body, scope, at)
            }
            ExprKind::Grad { body, var } => {
                if !scope.vars.contains(var) {
                    return err(format!("grad(): '{var}' is not a variable in scope"));
                }
                self.expr(body, scope, at)
            }
            ExprKind::Unary(_, a) => self.expr(a, scope, at),
            ExprKind::Binary(_, a, b) => {
                self.expr(a, scope, at)?;
                self.expr(b, scope, at)
            }
            ExprKind::If(a, b, c) => [a, b, c].iter().try_for_each(|x| self.expr(x, scope, at)),
            ExprKind::Index(a, ix) => {
                self.expr(a, scope, at)?;
                ix.iter().try_for_each(|x| self.expr(x, scope, at))
            }
            ExprKind::List(items) => items.iter().try_for_each(|x| self.expr(x, scope, at)),
        }
    }

    /// Why a call of `name` with `n` arguments cannot work (resolved as the evaluator
    /// resolves it: random primitives in samplers, then local, built-in, registered and
    /// defined functions).
    fn call_error(&self, name: &str, n: usize, scope: &Scope) -> Option<String> {
        let arity_error = |arity: Arity| {
            (!arity.accepts(n))
                .then(|| format!("{name} takes {} argument(s), got {n}", arity.describe()))
        };
        if let Some(p) = Primitive::from_name(name).filter(|_| scope.sampling) {
            if p.spec().arity == Arity::Exact(0) && n > 0 {
                return Some(format!("{name}() takes no arguments in a sampler"));
            }
            return arity_error(p.spec().arity);
        }
        if let Some(k) = scope.local.get(name) {
            return arity_error(Arity::Exact(*k));
        }
        if let Some(b) = Builtin::from_name(name) {
            return arity_error(b.spec().arity);
        }
        if let Some(r) = self.reg.ext(name) {
            return arity_error(Arity::Exact(r.arity));
        }
        if let Some(u) = self.reg.user(name) {
            return arity_error(Arity::Exact(u.params.len()));
        }
        if Primitive::from_name(name).is_some() {
            return Some(format!(
                "the random primitive '{name}' is only available in sampler expressions (vars, start)"
            ));
        }
        Some(format!("unknown function '{name}'"))
    }

    fn pexpr(&self, p: &PExpr, scope: &Scope) -> Result<(), LoadError> {
        self.expr(&p.expr, scope, &p.origin)
    }

    /// `let` bindings in order; returns the scope after them.
    fn lets(
        &self,
        lets: &[Binding],
        at: Option<&Origin>,
        mut scope: Scope,
    ) -> Result<Scope, LoadError> {
        let Some(at) = at else {
            return Ok(scope);
        };
        for b in lets {
            match &b.params {
                Some(ps) => {
                    self.expr(&b.body, &Scope::params(ps), at)?;
                    scope.local.insert(b.name.clone(), ps.len());
                }
                None => {
                    self.expr(&b.body, &scope, at)?;
                    scope.vars.push(b.name.clone());
                }
            }
        }
        Ok(scope)
    }

    fn domain(&self, d: &Domain) -> Result<(), LoadError> {
        let mut scope = Scope::default().sampling();
        for (name, p) in &d.vars {
            self.pexpr(p, &scope)?;
            sampled_once(name, &scope, p)?;
            scope.vars.push(name.clone());
        }
        let wheres = Scope::default().with(&scope.vars);
        d.wheres.iter().try_for_each(|w| self.pexpr(w, &wheres))
    }

    fn claim(&self, cat: &Catalogue, c: &Claim) -> Result<(), LoadError> {
        let mut sampled = Scope::default();
        if let Some(d) = &c.domain {
            let dom = cat.domains.get(&d.value).ok_or_else(|| {
                d.error(format!("claim '{}': unknown domain '{}'", c.id, d.value))
            })?;
            sampled.vars.extend(dom.vars.iter().map(|(n, _)| n.clone()));
        }
        for (name, p) in &c.vars {
            self.pexpr(p, &sampled.sampling())?;
            sampled_once(name, &sampled, p)?;
            sampled.vars.push(name.clone());
        }
        c.wheres.iter().try_for_each(|w| self.pexpr(w, &sampled))?;
        self.body(cat, c, sampled)
    }

    fn body(&self, cat: &Catalogue, c: &Claim, sampled: Scope) -> Result<(), LoadError> {
        let lets = |s: Scope| self.lets(&c.lets, c.lets_origin.as_ref(), s);
        let scale = |s: &Scope| c.scale.iter().try_for_each(|p| self.pexpr(p, s));
        match &c.body {
            Body::Identity { lhs, rhs } => {
                let s = lets(sampled)?;
                scale(&s)?;
                for q in c.hint.iter().flat_map(|h| &h.multipliers) {
                    self.pexpr(q, &s)?;
                }
                self.pexpr(lhs, &s)?;
                self.pexpr(rhs, &s)
            }
            Body::Independence { expr, .. } => {
                let s = lets(sampled)?;
                scale(&s)?;
                self.pexpr(expr, &s)
            }
            Body::Asymptotic { expr, var, .. } => {
                let s = lets(sampled.with(std::slice::from_ref(var)))?;
                scale(&s)?;
                self.pexpr(expr, &s)
            }
            Body::Existence {
                unknowns,
                equations,
                start,
                in_set,
                ..
            } => {
                let s = lets(sampled)?;
                scale(&s)?;
                start
                    .iter()
                    .try_for_each(|p| self.pexpr(p, &s.sampling()))?;
                let with_x = s.with(unknowns);
                equations.iter().try_for_each(|p| self.pexpr(p, &with_x))?;
                in_set.iter().try_for_each(|p| self.pexpr(p, &with_x))
            }
            Body::Negation(inner) => self.claim(cat, inner),
            Body::Definition(_) => Ok(()),
        }
    }
}

/// The global definitions a body calls.
/// A sampled variable is named once: a second `vars` entry of the same name (in the
/// claim's or its domain's list) would silently replace the first.
fn sampled_once(name: &str, scope: &Scope, p: &PExpr) -> Result<(), LoadError> {
    if scope.vars.iter().any(|v| v == name) {
        return Err(p.origin.error(
            None,
            format!("variable '{name}' is sampled twice (a second vars entry of that name)"),
        ));
    }
    Ok(())
}

fn calls_of(body: &Expr, defs: &BTreeMap<&str, usize>) -> Vec<usize> {
    let mut out = Vec::new();
    body.walk(&mut |x| {
        if let ExprKind::Call(n, _) = &x.kind
            && let Some(&j) = defs.get(n.as_str())
        {
            out.push(j);
        }
    });
    out
}

/// No definition calls itself, directly or through others.
fn check_recursion(defs: &[(Binding, Origin)]) -> Result<(), LoadError> {
    let index: BTreeMap<&str, usize> = defs
        .iter()
        .enumerate()
        .map(|(j, (b, _))| (b.name.as_str(), j))
        .collect();
    let calls: Vec<Vec<usize>> = defs
        .iter()
        .map(|(b, _)| calls_of(&b.body, &index))
        .collect();
    for root in 0..defs.len() {
        // depth-first search for a path root → … → root
        let mut seen = BTreeSet::new();
        let mut stack = vec![(root, vec![root])];
        while let Some((node, path)) = stack.pop() {
            for &next in &calls[node] {
                if next == root {
                    let mut names: Vec<&str> =
                        path.iter().map(|&j| defs[j].0.name.as_str()).collect();
                    names.push(&defs[root].0.name);
                    let (b, at) = &defs[root];
                    return Err(at.error(
                        Some(b.span),
                        format!(
                            "recursive definition: {} (definitions may not call themselves)",
                            names.join(" → ")
                        ),
                    ));
                }
                if seen.insert(next) {
                    let mut p = path.clone();
                    p.push(next);
                    stack.push((next, p));
                }
            }
        }
    }
    Ok(())
}

/// Checks every name of the catalogue; `defs` are the `definition` functions with their
/// origins.
pub fn check(cat: &Catalogue, defs: &[(Binding, Origin)]) -> Result<(), LoadError> {
    let ck = Checker { reg: &cat.registry };
    for (b, at) in defs {
        let ps = b.params.clone().unwrap_or_default();
        ck.expr(&b.body, &Scope::params(&ps), at)?;
    }
    check_recursion(defs)?;
    for d in cat.domains.values() {
        ck.domain(d)?;
    }
    cat.claims.iter().try_for_each(|c| ck.claim(cat, c))
}
