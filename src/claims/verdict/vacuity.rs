//! Vacuous conditions.  A *counted condition* is an indicator `if G then 1 else 0` (any
//! two number literals as branches) that is an operand of an operator, as in
//! `(if abs(P[1]) > 0 then 1 else 0) + … >= 2`: the claim counts or combines
//! conditions, and says something only where they differ.  If some counted condition
//! has the same value at every sample of the claim's domain, the claim never meets the
//! case it is about: it cannot be judged, with the cause "vacuous on domain …".
//!
//! The guards are evaluated in f64 at the points of the ladder's sample stream (the
//! claim's sampled variables and `let` bindings are in scope).  A guard that cannot be
//! evaluated at a point (it names a function parameter, or the asymptotic variable)
//! is not counted there.

use super::context::Ctx;
use super::failure::Cause;
use crate::claims::ast::{Expr, ExprKind};
use crate::claims::catalogue::{Body, Claim, PExpr};
use crate::claims::sampler::Stream;

/// One counted condition: its guard and how it is shown.
pub struct Condition<'a> {
    /// The guard `G`.
    pub guard: &'a Expr,
    /// Its text (or where it is, for a guard inside a `let`).
    pub text: String,
}

/// How often a condition was true and false.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    /// Samples where the guard is true.
    pub true_at: usize,
    /// Samples where it is false.
    pub false_at: usize,
}

impl Tally {
    /// Vacuous: evaluated somewhere, and always with the same value.
    pub fn is_vacuous(&self) -> bool {
        self.true_at + self.false_at > 0 && (self.true_at == 0 || self.false_at == 0)
    }
}

fn is_indicator(e: &Expr) -> Option<&Expr> {
    match &e.kind {
        ExprKind::If(g, a, b)
            if matches!(a.kind, ExprKind::Num(_)) && matches!(b.kind, ExprKind::Num(_)) =>
        {
            Some(g)
        }
        _ => None,
    }
}

/// The guards of the counted conditions in `e`, in the order they are written.
pub fn counted_guards(e: &Expr) -> Vec<&Expr> {
    let mut out = Vec::new();
    collect(e, &mut out);
    out.sort_by_key(|g| g.span.start);
    out
}

fn collect<'e>(e: &'e Expr, out: &mut Vec<&'e Expr>) {
    let children: Vec<&Expr> = match &e.kind {
        ExprKind::Binary(_, a, b) => vec![a, b],
        ExprKind::Unary(_, a) => vec![a],
        _ => Vec::new(),
    };
    out.extend(children.iter().filter_map(|c| is_indicator(c)));
    match &e.kind {
        ExprKind::Num(_) | ExprKind::Name(_) => {}
        ExprKind::Call(_, a) | ExprKind::List(a) => a.iter().for_each(|x| collect(x, out)),
        ExprKind::Unary(_, a) => collect(a, out),
        ExprKind::Binary(_, a, b) => {
            collect(a, out);
            collect(b, out);
        }
        ExprKind::If(a, b, c) => [a, b, c].into_iter().for_each(|x| collect(x, out)),
        ExprKind::Index(a, ix) => {
            collect(a, out);
            ix.iter().for_each(|x| collect(x, out));
        }
        ExprKind::Sum { from, to, body, .. } => {
            [from, to, body].into_iter().for_each(|x| collect(x, out))
        }
        ExprKind::Deriv {
            body, component, ..
        } => {
            collect(body, out);
            if let Some(c) = component {
                collect(c, out);
            }
        }
        ExprKind::Grad { body, .. } => collect(body, out),
    }
}

fn of_pexpr<'a>(p: &'a PExpr, out: &mut Vec<Condition<'a>>) {
    for g in counted_guards(&p.expr) {
        let text = p.text.get(g.span.start..g.span.end).unwrap_or("?").trim();
        out.push(Condition {
            guard: g,
            text: format!("'{text}'"),
        });
    }
}

/// The counted conditions of a claim: in its `let` values, `scale` and the expressions
/// of its kind (a negation's inner claim is checked when it runs).
pub fn conditions(claim: &Claim) -> Vec<Condition<'_>> {
    let mut out = Vec::new();
    for b in claim.lets.iter().filter(|b| b.params.is_none()) {
        for g in counted_guards(&b.body) {
            out.push(Condition {
                guard: g,
                text: format!("in let {}", b.name),
            });
        }
    }
    if let Some(s) = &claim.scale {
        of_pexpr(s, &mut out);
    }
    match &claim.body {
        Body::Identity { lhs, rhs } => {
            of_pexpr(lhs, &mut out);
            of_pexpr(rhs, &mut out);
        }
        Body::Independence { expr, .. } | Body::Asymptotic { expr, .. } => of_pexpr(expr, &mut out),
        Body::Existence {
            equations, in_set, ..
        } => {
            equations.iter().for_each(|e| of_pexpr(e, &mut out));
            if let Some(s) = in_set {
                of_pexpr(s, &mut out);
            }
        }
        Body::Negation(_) | Body::Definition(_) => {}
    }
    out
}

/// Counts, over `claim.samples` points of the sample stream, where each condition is
/// true and where it is false.
pub fn tally(ctx: Ctx<'_>, conds: &[Condition<'_>]) -> Result<Vec<Tally>, Cause> {
    let mut sampler = ctx.sampler(Stream::Samples)?;
    let mut tallies = vec![Tally::default(); conds.len()];
    for _ in 0..ctx.claim.samples {
        let point = sampler.draw().map_err(Cause::Sampling)?;
        let Ok(ev) = ctx.setup(&point, 0.0f64) else {
            continue;
        };
        for (c, t) in conds.iter().zip(tallies.iter_mut()) {
            match ev.eval(c.guard).ok().and_then(|v| v.as_bool().ok()) {
                Some(true) => t.true_at += 1,
                Some(false) => t.false_at += 1,
                None => {}
            }
        }
    }
    Ok(tallies)
}

/// `Err(Cause::Vacuous)` if a counted condition of the claim has the same value at every
/// sample.
pub fn check(ctx: Ctx<'_>) -> Result<(), Cause> {
    let conds = conditions(ctx.claim);
    if conds.is_empty() {
        return Ok(());
    }
    let tallies = tally(ctx, &conds)?;
    match conds.iter().zip(&tallies).find(|(_, t)| t.is_vacuous()) {
        None => Ok(()),
        Some((c, t)) => Err(Cause::Vacuous {
            domain: domain_name(ctx.claim),
            condition: c.text.clone(),
            value: t.false_at == 0,
            samples: t.true_at + t.false_at,
        }),
    }
}

fn domain_name(claim: &Claim) -> String {
    match &claim.domain {
        Some(d) => format!("'{}'", d.value),
        None => "of the claim's vars".into(),
    }
}

#[cfg(test)]
mod tests {
    use crate::claims::catalogue::load_sources;
    use crate::claims::registry::Registry;
    use crate::claims::verdict::{ClaimResult, Options, Verdict, run_claim};

    fn run(vars: &str, lhs: &str) -> ClaimResult {
        let toml = format!(
            r#"
[domain.d]
vars = {vars}

[[claim]]
id = "t"
environment = "Section 2"
role = "statement"
location = "here"
printed = "at least one of x, y does not vanish"
kind = "identity"
expect = "holds"
domain = "d"
samples = 16
lhs = "{lhs}"
rhs = "1"
scale = "1"
"#
        );
        let cat = load_sources(&[("t.toml".into(), toml)], Registry::new()).unwrap();
        let opts = Options {
            bits: vec![53, 128],
            exact: false,
        };
        run_claim(&cat, &cat.claims[0], &opts)
    }

    const COUNT: &str =
        "if (if abs(x) > 0 then 1 else 0) + (if abs(y) > 0 then 1 else 0) >= 1 then 1 else 0";

    #[test]
    fn a_count_of_conditions_that_never_change_is_vacuous() {
        let r = run(
            r#"[["x", "uniform(0.5, 1)"], ["y", "uniform(0.5, 1)"]]"#,
            COUNT,
        );
        assert_eq!(r.verdict, Verdict::Inconclusive);
        assert!(!r.as_expected);
        assert!(
            r.reason.starts_with(
                "vacuous on domain 'd': the condition 'abs(x) > 0' is true at all 16 samples"
            ),
            "{}",
            r.reason
        );
    }

    #[test]
    fn a_count_whose_conditions_change_is_judged() {
        let vars = r#"[["x", "choice(0, 1) * uniform(0.5, 1)"], ["y", "1 - choice(0, 1) * uniform(0, 0.5)"]]"#;
        // y never vanishes: the second condition is still vacuous
        let r = run(vars, COUNT);
        assert!(r.reason.contains("'abs(y) > 0' is true"), "{}", r.reason);
        let vars = r#"[["x", "choice(0, 1) * uniform(0.5, 1)"], ["y", "if x == 0 then uniform(0.5, 1) else choice(0, 1) * uniform(0.5, 1)"]]"#;
        let r = run(vars, COUNT);
        assert_eq!(r.verdict, Verdict::Holds, "{}", r.reason);
    }

    #[test]
    fn an_indicator_that_is_the_assertion_is_not_a_counted_condition() {
        let r = run(
            r#"[["x", "uniform(0.5, 1)"], ["y", "uniform(0.5, 1)"]]"#,
            "if x > 0 then 1 else 0",
        );
        assert_eq!(r.verdict, Verdict::Holds, "{}", r.reason);
    }
}
