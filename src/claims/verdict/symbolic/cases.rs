//! The roles of the sampled variables (indeterminate, enumerated case, sign symbol,
//! computed) and the domain points drawn for each case.

use crate::claims::ast::{Expr, ExprKind};
use crate::claims::builtins::Primitive;
use crate::claims::catalogue::PExpr;
use crate::claims::sampler::{Point, Stream};
use crate::claims::value::Layout;
use crate::claims::verdict::context::Ctx;
use std::collections::BTreeMap;

/// Domain points per case at which the symbols carry numeric values: the shadows that
/// pick a solver's root among its conjugates and that the zero test evaluates.  No sign,
/// branch or regime is decided at them (module [`crate::algebra::decide`]).
pub(super) const POINTS: usize = 5;
/// Draws spent looking for points of every case.
pub(super) const MAX_DRAWS: usize = 256;

/// How a sampled variable enters the proof.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Role {
    /// An indeterminate (per component).
    Free,
    /// Finitely many values, enumerated as cases.
    Case,
    /// A case variable with the values ±1, bound to a sign symbol (σ² = 1) so that one
    /// proof covers every sign case.
    Sign,
    /// Evaluated from the earlier variables.
    Computed,
}

/// The most values of `randint(a, b)` enumerated as cases; a wider range is an
/// indeterminate (an identity in an indeterminate holds at every integer).
pub(super) const MAX_RANDINT_CASES: i64 = 8;

/// How many values a finite primitive call can take: `None` for a continuous one.
pub(super) fn finite_values(name: &str, args: &[Expr]) -> Option<usize> {
    match Primitive::from_name(name)? {
        Primitive::Sign => Some(2),
        Primitive::Choice => Some(args.len()),
        Primitive::Randint => {
            let int = |e: &Expr| match &e.kind {
                ExprKind::Num(t) => t.parse::<i64>().ok(),
                _ => None,
            };
            let (a, b) = (int(args.first()?)?, int(args.get(1)?)?);
            let n = b.checked_sub(a)?.checked_add(1)?;
            (1..=MAX_RANDINT_CASES).contains(&n).then_some(n as usize)
        }
        Primitive::Uniform | Primitive::Normal => None,
    }
}

/// The role of a sampled variable, and for a case variable an upper bound on the number
/// of its values (the product over its finite primitive calls).
pub(super) fn role_of(p: &PExpr) -> (Role, usize) {
    let (mut values, mut finite, mut continuous) = (1usize, false, false);
    p.expr.walk(&mut |e| {
        if let ExprKind::Call(name, args) = &e.kind
            && Primitive::from_name(name).is_some()
        {
            match finite_values(name, args) {
                Some(n) => {
                    finite = true;
                    values = values.saturating_mul(n);
                }
                None => continuous = true,
            }
        }
    });
    match (continuous, finite) {
        (true, _) => (Role::Free, 1),
        (false, true) => (Role::Case, values),
        _ => (Role::Computed, 1),
    }
}

/// The sampled variables of a proof's domain: each with its definition, its role (and
/// for a case variable the number of its values), and the domain's parametrization for
/// proving signs.
pub(super) struct Domain<'c> {
    /// Name and definition, in the sampler's order.
    pub(super) vars: Vec<(String, &'c PExpr)>,
    /// Name, role and the number of values of a case variable.
    pub(super) plain: Vec<(String, (Role, usize))>,
    /// Name, role and definition.
    pub(super) roles: Vec<(String, Role, &'c PExpr)>,
    /// The domain's parametrization by positive parameters, where there is one.
    pub(super) positivity: Option<std::sync::Arc<crate::algebra::positivity::Parametrization>>,
}

/// The claim's proof domain ([`Domain`]); `Err` when it cannot be sampled.
pub(super) fn domain<'c>(ctx: Ctx<'c>) -> Result<Domain<'c>, String> {
    let sampler = ctx.sampler(Stream::Proof).map_err(|c| c.to_string())?;
    let vars: Vec<(String, &'c PExpr)> = sampler.variables().to_vec();
    let plain: Vec<(String, (Role, usize))> =
        vars.iter().map(|(n, p)| (n.clone(), role_of(p))).collect();
    let roles = (vars.iter().zip(&plain))
        .map(|((n, p), (_, (r, _)))| (n.clone(), r.clone(), *p))
        .collect();
    let positivity = crate::claims::verdict::positivity::parametrization(&vars);
    Ok(Domain {
        vars,
        plain,
        roles,
        positivity,
    })
}

/// The points of each case, keyed by the case values.
pub(super) type Cases = BTreeMap<Vec<String>, Vec<Point>>;

/// Draws points until every case has [`POINTS`] of them (or the draws run out).
/// Every case must be drawn: a case that is never drawn would never be proved.
pub(super) fn case_points(
    ctx: Ctx<'_>,
    roles: &[(String, (Role, usize))],
) -> Result<Cases, String> {
    let mut sampler = ctx.sampler(Stream::Proof).map_err(|c| c.to_string())?;
    let case_vars: Vec<&String> = roles
        .iter()
        .filter(|(_, (r, _))| *r == Role::Case)
        .map(|(n, _)| n)
        .collect();
    let expected = roles
        .iter()
        .filter(|(_, (r, _))| *r == Role::Case)
        .fold(1usize, |a, (_, (_, n))| a.saturating_mul(*n));
    let mut cases = Cases::new();
    for _ in 0..MAX_DRAWS {
        let p = sampler.draw()?;
        let key = case_key(&p, &case_vars);
        let group = cases.entry(key).or_default();
        if group.len() < POINTS {
            group.push(p);
        }
        let full = cases.values().all(|g| g.len() >= POINTS);
        if full && cases.len() >= expected {
            break;
        }
    }
    cases.retain(|_, g| g.len() >= POINTS);
    if cases.len() < expected {
        return Err(format!(
            "{} of the {expected} cases of {} have {POINTS} domain points in {MAX_DRAWS} draws",
            cases.len(),
            case_vars
                .iter()
                .map(|n| n.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    Ok(cases)
}

/// The case of a point: the values of the case variables.
pub(super) fn case_key(p: &Point, case_vars: &[&String]) -> Vec<String> {
    (case_vars.iter())
        .map(|n| {
            let v = p
                .get(n)
                .map_or(String::new(), |v| v.render(17, Layout::Inline));
            format!("{n} = {v}")
        })
        .collect()
}
