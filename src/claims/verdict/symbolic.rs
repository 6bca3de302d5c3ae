//! Symbolic proofs of identities: the claim's formulas evaluated exactly in the prover's
//! tower ([`crate::algebra`]), and `lhs − rhs` reduced to its normal form.  A claim is
//! `proved` when that normal form is 0, and only then.
//!
//! **Variables.**  A sampled variable whose definition draws a continuous primitive
//! (`uniform`, `randint`, `normal`) becomes an indeterminate (one per component of a
//! vec3): an identity proved for independent indeterminates holds in particular on the
//! sampled domain.  A variable drawn only by `sign()` or `choice(…)` takes finitely many
//! values: the proof enumerates them as cases and every case must be proved.  A variable
//! without primitives is evaluated symbolically from the earlier ones.
//!
//! **Decisions.**  Comparisons, `abs`, `sign`, `min`, `max`, the branch of a square
//! root, the condition of an `if` and the choice of a regime are decided as
//! [`crate::algebra::Decision`]s: proved on the domain (its parametrization by
//! positive parameters, module `positivity`), given by a hypothesis the claim states
//! (field `hypotheses`), fixed by the definition of a sign symbol, or by the part of a
//! split domain the proof is on.  The values at the domain points never decide one: a
//! sign that none of these decides splits the domain by it (module `split`), or leaves
//! the claim unproved with that sign as the reason.
//! A comparison yields a truth value, which only an `if` can use.
//!
//! ```
//! use eulertop::bindings::euler_top::registry;
//! use eulertop::claims::catalogue::load_sources;
//! use eulertop::claims::verdict::{run_claim, Options, ProofMethod, Verdict};
//! let toml = r#"
//! [[claim]]
//! id = "double-angle"
//! environment = "Section 2"
//! role = "statement"
//! labels = []
//! location = "a doc example"
//! printed = 'sn(2u)'
//! kind = "identity"
//! expect = "proved"
//! vars = [["u", "uniform(-1, 1)"], ["k", "uniform(0.1, 0.9)"]]
//! lhs = "sn(2*u, k)"
//! rhs = "2*sn(u, k)*cn(u, k)*dn(u, k) / (1 - k^2*sn(u, k)^4)"
//! "#;
//! let cat = load_sources(&[("doc.toml".into(), toml.into())], registry().unwrap()).unwrap();
//! let r = run_claim(&cat, &cat.claims[0], &Options::default());
//! assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
//! assert_eq!(r.proof.method, ProofMethod::Symbolic);
//! ```

use super::context::{Ctx, eval};
pub use super::proof_info::{ProofInfo, ProofMethod};
use super::result::Evidence;
use crate::algebra::{
    AlgResult, AlgebraError, AssumptionKind, BaseHint, Outcome, Proof, Ring, RingOptions, Sym,
    prove_components,
};
use crate::claims::ast::{Expr, ExprKind};
use crate::claims::builtins::Primitive;
use crate::claims::catalogue::{Hint, PExpr};
use crate::claims::eval::Evaluator;
use crate::claims::kind::Verdict;
use crate::claims::sampler::{Point, Stream};
use crate::claims::value::{Layout, Value};
use crate::linalg::Vec3;
use crate::numbers::Cplx;
use crate::numbers::Scalar;
use rug::Complex;
use std::collections::BTreeMap;
use std::time::Instant;

/// Domain points per case at which the symbols carry numeric values.  Signs, branches
/// and regimes are decided at these points, so a sign that changes on the domain is
/// taken for constant only when every point falls on one side (for an even split,
/// probability 2⁻⁴ with five points; with eight points no verdict of the catalogue
/// changes, and the run takes 10 % longer).
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
const MAX_RANDINT_CASES: i64 = 8;

/// How many values a finite primitive call can take: `None` for a continuous one.
fn finite_values(name: &str, args: &[Expr]) -> Option<usize> {
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
fn role_of(p: &PExpr) -> (Role, usize) {
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

/// Why the claim's own formulas state a condition rather than an identity, if they do.
fn states_condition(ctx: Ctx<'_>, sides: &[&PExpr]) -> Option<String> {
    let mut found: Option<String> = None;
    let mut look = |e: &Expr| {
        e.walk(&mut |x| {
            let what = match &x.kind {
                ExprKind::If(_, a, b) if is_literal(a) || is_literal(b) => Some("if".to_string()),
                ExprKind::Call(n, _) if ["min", "max", "floor"].contains(&n.as_str()) => {
                    Some(n.clone())
                }
                _ => None,
            };
            if found.is_none() {
                found = what;
            }
        })
    };
    for s in sides {
        look(&s.expr);
    }
    for b in &ctx.claim.lets {
        look(&b.body);
    }
    found.map(|w| {
        format!("the claim's own formulas use '{w}': it states a condition, which a normal form does not prove")
    })
}

/// Why the claim is not an analytic function of its complex variables, if it is not
/// (then an indeterminate does not stand for every complex value).
fn not_analytic(ctx: Ctx<'_>, vars: &[(String, &PExpr)], sides: &[&PExpr]) -> Option<String> {
    if !vars.iter().any(|(_, p)| p.text.contains("cplx(")) {
        return None;
    }
    let mut found = None;
    let mut look = |e: &Expr| {
        e.walk(&mut |x| {
            if let ExprKind::Call(n, _) = &x.kind
                && ["re", "im", "conj", "arg"].contains(&n.as_str())
                && found.is_none()
            {
                found = Some(n.clone());
            }
        })
    };
    for s in sides {
        look(&s.expr);
    }
    for b in &ctx.claim.lets {
        look(&b.body);
    }
    found.map(|n| format!("'{n}' of a complex variable is not analytic: an indeterminate does not stand for every complex value"))
}

/// Nested applications of one catalogue function to its own result, this deep or
/// deeper, are an iteration (such as Newton's method written out).
const ITERATION_DEPTH: usize = 3;

/// Why no proof is attempted when the claim evaluates an iteration: a catalogue
/// function applied to its own result [`ITERATION_DEPTH`] times, in the claim's
/// formulas or in a catalogue function they call.  Its exact value is a rational
/// function whose size multiplies with every step, far beyond the prover's bound.
fn iteration(ctx: Ctx<'_>, sides: &[&PExpr]) -> Option<String> {
    let reg = &ctx.cat.registry;
    let mut seen = std::collections::BTreeSet::new();
    let mut stack: Vec<(&Expr, Option<&str>)> = sides.iter().map(|s| (&s.expr, None)).collect();
    stack.extend(ctx.claim.lets.iter().map(|b| (&b.body, None)));
    while let Some((e, inside)) = stack.pop() {
        let mut found = None;
        e.walk(&mut |x| {
            let ExprKind::Call(name, _) = &x.kind else {
                return;
            };
            if found.is_none() && self_nesting(x, name) >= ITERATION_DEPTH {
                found = Some(name.clone());
            }
            if let Some(f) = reg.user(name)
                && seen.insert(name.clone())
            {
                stack.push((&f.def.body, Some(name.as_str())));
            }
        });
        if let Some(n) = found {
            let place = inside.map_or(String::new(), |f| format!(" in the catalogue function {f}"));
            return Some(format!(
                "the claim evaluates an iteration ({n} applied to its own result{place}): its exact value grows with every step beyond the prover's bound, so no proof is attempted"
            ));
        }
    }
    None
}

/// How many times `name` is applied in a chain `name(name(…))` starting at `e`
/// (through the first argument).
fn self_nesting(e: &Expr, name: &str) -> usize {
    match &e.kind {
        ExprKind::Call(n, args) if n == name => {
            1 + args.first().map_or(0, |a| self_nesting(a, name))
        }
        _ => 0,
    }
}

/// A numeric literal, possibly negated: the branch of an indicator `if c then 1 else 0`.
fn is_literal(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Num(_) => true,
        ExprKind::Unary(_, x) => is_literal(x),
        _ => false,
    }
}

/// The points of each case, keyed by the case values.
type Cases = BTreeMap<Vec<String>, Vec<Point>>;

/// Draws points until every case has [`POINTS`] of them (or the draws run out).
/// Every case must be drawn: a case that is never drawn would never be proved.
fn case_points(ctx: Ctx<'_>, roles: &[(String, (Role, usize))]) -> Result<Cases, String> {
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

/// The shadow values of one scalar component across the points.
fn shadows(points: &[Point], name: &str, comp: Option<usize>) -> Vec<Complex> {
    points
        .iter()
        .map(|p| {
            let x = match (p.get(name), comp) {
                (Some(Value::Real(x)), None) => *x,
                (Some(Value::Vec3(v)), Some(j)) => v.0[j],
                _ => f64::NAN,
            };
            Complex::with_val(256, x)
        })
        .collect()
}

/// The complex shadow values of a complex variable across the points.
fn complex_shadows(points: &[Point], name: &str) -> Vec<Complex> {
    points
        .iter()
        .map(|p| match p.get(name) {
            Some(Value::Complex(z)) => Complex::with_val(256, (z.re, z.im)),
            _ => Complex::with_val(256, f64::NAN),
        })
        .collect()
}

/// An implicit call whose eliminated arguments are free variables of the claim: the
/// prover replaces them by the function's parametrization.
struct Plan<'e> {
    name: String,
    args: &'e [Expr],
    vars: Vec<String>,
}

/// The implicit calls of the claim's own formulas that can be parametrized, in order;
/// each free variable is eliminated at most once.
fn plans<'e>(ctx: Ctx<'e>, roles: &[(String, Role, &PExpr)], exprs: &[&'e Expr]) -> Vec<Plan<'e>> {
    let free = |n: &str| roles.iter().any(|(v, r, _)| v == n && *r == Role::Free);
    let mut out: Vec<Plan<'e>> = Vec::new();
    for e in exprs {
        e.walk(&mut |x: &'e Expr| {
            let ExprKind::Call(name, args) = &x.kind else {
                return;
            };
            let Some(imp) = ctx.cat.registry.ext(name).and_then(|r| r.f.implicit()) else {
                return;
            };
            let vars: Option<Vec<String>> = imp
                .eliminates()
                .iter()
                .map(|&j| match args.get(j).map(|a| &a.kind) {
                    Some(ExprKind::Name(v)) if free(v) => Some(v.clone()),
                    _ => None,
                })
                .collect();
            let Some(vars) = vars else { return };
            let taken = out.iter().any(|p| p.vars.iter().any(|v| vars.contains(v)));
            if !taken {
                out.push(Plan {
                    name: name.clone(),
                    args,
                    vars,
                });
            }
        });
    }
    out
}

/// Binds the sampled variables as symbols in a fresh evaluator on `ring`; implicit
/// calls with free arguments are parametrized, and the equations the parametrization
/// must satisfy are returned with the evaluator.
fn bind_variables<'c>(
    ctx: Ctx<'c>,
    ring: &Ring,
    roles: &[(String, Role, &PExpr)],
    points: &[Point],
    (plans, lemmas): (&[Plan<'c>], &[super::lemmas::Lemma<'_>]),
    hint: Option<&Hint>,
) -> AlgResult<Bound<'c>> {
    let mut ev = Evaluator::new(&ctx.cat.registry, ring.integer(0));
    let fail = |m: String| AlgebraError::Domain(m);
    for (name, role, def) in roles {
        let value = bind_one(&ev, ring, name, role, def, points)?;
        ev.bind(name, value);
    }
    let mut checks = Vec::new();
    let mut params = Vec::new();
    for plan in plans {
        let (c, p) = parametrize(ctx, &mut ev, plan)?;
        checks.extend(c);
        params.extend(p);
        recompute(&mut ev, roles)?;
    }
    let mut replaced: Vec<String> = plans.iter().flat_map(|p| p.vars.clone()).collect();
    if let Some((vars, p)) = linear_change(ctx, &mut ev, ring, roles)? {
        replaced.extend(vars);
        params.extend(p);
    }
    if !replaced.is_empty() {
        recompute(&mut ev, roles)?;
        declare_coordinates(&ev, ring, roles, &replaced, params)?;
    }
    super::lemmas::apply(&ev, lemmas)?;
    let unknown = match hint {
        Some(h) => Some(super::hinted::unknown(ctx, ring, h, points)?),
        None => None,
    };
    for b in &ctx.claim.lets {
        match (hint, &unknown) {
            (Some(h), Some(v)) if h.value == b.name => ev.bind(&b.name, v.clone()),
            _ => ev
                .bind_let(b)
                .map_err(|e| fail(format!("let {}: {}", b.name, e.message)))?,
        }
    }
    Ok(Bound {
        ev,
        checks,
        unknown,
    })
}

/// The claim's variables bound in the prover: the evaluator, the equations the
/// parametrizations must satisfy, and the unknown value of a hinted call.
struct Bound<'c> {
    ev: Evaluator<'c, Sym>,
    checks: Vec<Sym>,
    unknown: Option<Value<Sym>>,
}

/// Re-evaluates the computed variables after free ones were replaced.
fn recompute(ev: &mut Evaluator<'_, Sym>, roles: &[(String, Role, &PExpr)]) -> AlgResult<()> {
    for (name, role, def) in roles {
        if *role == Role::Computed {
            let v = eval(ev, def).map_err(AlgebraError::Domain)?;
            ev.bind(name, v);
        }
    }
    Ok(())
}

/// The `let` names the claim differentiates with respect to (`d(Q, x)` with `x` a
/// `let`), in the order of the lets.
fn differentiated_lets(ctx: Ctx<'_>) -> Vec<&crate::claims::ast::Binding> {
    let mut vars: Vec<String> = Vec::new();
    let mut look = |e: &Expr| {
        e.walk(&mut |x| {
            if let ExprKind::Deriv { var, .. } = &x.kind {
                vars.push(var.clone());
            }
        })
    };
    if let crate::claims::catalogue::Body::Identity { lhs, rhs } = &ctx.claim.body {
        look(&lhs.expr);
        look(&rhs.expr);
    }
    for b in &ctx.claim.lets {
        look(&b.body);
    }
    ctx.claim
        .lets
        .iter()
        .filter(|b| b.params.is_none() && vars.contains(&b.name))
        .collect()
}

/// A derivative with respect to a `let` that is an affine function of free variables
/// (such as `x = (φ + φ̂)/2`, `y = (φ̂ − φ)/2`) holds the other such lets fixed.  When the
/// differentiated lets are as many as the free variables they involve and independent,
/// they become the new indeterminates and those variables affine functions of them.
fn linear_change(
    ctx: Ctx<'_>,
    ev: &mut Evaluator<'_, Sym>,
    ring: &Ring,
    roles: &[(String, Role, &PExpr)],
) -> AlgResult<Option<(Vec<String>, Vec<Sym>)>> {
    let lets = differentiated_lets(ctx);
    if lets.is_empty() {
        return Ok(None);
    }
    let free: Vec<(String, Sym)> = roles
        .iter()
        .filter(|(_, r, _)| *r == Role::Free)
        .filter_map(|(n, _, _)| match ev.lookup(n) {
            Some(Value::Real(x)) if x.as_rational().is_none() => Some((n.clone(), x.clone())),
            _ => None,
        })
        .collect();
    let (lets, rows) = match affine_lets(ctx, ev, ring, &free, &lets)? {
        Some(x) => x,
        None => return Ok(None),
    };
    let involved: Vec<usize> = (0..free.len())
        .filter(|&j| rows.iter().any(|r| r.0[j] != 0))
        .collect();
    if involved.len() != rows.len() {
        return Ok(None);
    }
    let m: Vec<Vec<rug::Rational>> = rows
        .iter()
        .map(|r| involved.iter().map(|&j| r.0[j].clone()).collect())
        .collect();
    let Some(inv) = rational_inverse(&m) else {
        return Ok(None);
    };
    let mut params = Vec::new();
    for (b, (_, c0, l)) in lets.iter().zip(&rows) {
        let p = ring.indeterminate(&ring.fresh_name(&b.name), l.shadows())?;
        params.push(p.try_sub(&ring.rational(c0))?);
    }
    let mut names = Vec::new();
    for (i, &j) in involved.iter().enumerate() {
        let mut v = ring.integer(0);
        for (k, p) in params.iter().enumerate() {
            v = v.try_add(&p.try_mul(&ring.rational(&inv[i][k]))?)?;
        }
        ev.bind(&free[j].0, Value::Real(v));
        names.push(free[j].0.clone());
    }
    ring.note(format!(
        "the differentiated lets {} are new indeterminates, and {} affine functions of them",
        lets.iter()
            .map(|b| b.name.as_str())
            .collect::<Vec<_>>()
            .join(", "),
        names.join(", ")
    ));
    let originals = params
        .iter()
        .zip(&rows)
        .map(|(p, (_, c0, _))| p.try_add(&ring.rational(c0)))
        .collect::<AlgResult<Vec<_>>>()?;
    Ok(Some((names, originals)))
}

/// One affine `let`: coefficients over the free variables, constant, value.
type AffineRow = (Vec<rug::Rational>, rug::Rational, Sym);

/// The `let` as an affine function of the free variables, if it is one.
fn affine(
    ring: &Ring,
    free: &[(String, Sym)],
    l: &Sym,
) -> AlgResult<Option<(Vec<rug::Rational>, rug::Rational)>> {
    let mut coef = Vec::new();
    let mut rest = l.clone();
    for (_, f) in free {
        let Some(c) = l.derivative(f)?.as_rational() else {
            return Ok(None);
        };
        rest = rest.try_sub(&f.try_mul(&ring.rational(&c))?)?;
        coef.push(c);
    }
    Ok(rest.as_rational().map(|c0| (coef, c0)))
}

/// The differentiated lets with the other affine lets of the same variables, when every
/// differentiated let is affine and the variables they involve are used by the sides
/// and later lets only through these lets (so that holding the others fixed is what
/// the derivative means).
fn affine_lets<'c>(
    ctx: Ctx<'c>,
    ev: &Evaluator<'_, Sym>,
    ring: &Ring,
    free: &[(String, Sym)],
    wanted: &[&'c crate::claims::ast::Binding],
) -> AlgResult<Option<(Vec<&'c crate::claims::ast::Binding>, Vec<AffineRow>)>> {
    let mut chosen = Vec::new();
    let mut rows: Vec<AffineRow> = Vec::new();
    for b in ctx.claim.lets.iter().filter(|b| b.params.is_none()) {
        let Ok(Value::Real(l)) = ev.eval(&b.body) else {
            continue;
        };
        match affine(ring, free, &l)? {
            Some((c, c0)) if c.iter().any(|q| *q != 0) => {
                chosen.push(b);
                rows.push((c, c0, l));
            }
            _ => {}
        }
    }
    if wanted
        .iter()
        .any(|w| !chosen.iter().any(|b| b.name == w.name))
    {
        return Ok(None);
    }
    let involved: Vec<&String> = free
        .iter()
        .enumerate()
        .filter(|(j, _)| rows.iter().any(|r| r.0[*j] != 0))
        .map(|(_, (n, _))| n)
        .collect();
    let mut direct = false;
    let mut look = |e: &Expr| {
        e.walk(&mut |x| {
            if let ExprKind::Name(n) = &x.kind {
                direct |= involved.contains(&n);
            }
        })
    };
    if let crate::claims::catalogue::Body::Identity { lhs, rhs } = &ctx.claim.body {
        look(&lhs.expr);
        look(&rhs.expr);
    }
    for b in ctx
        .claim
        .lets
        .iter()
        .filter(|b| !chosen.iter().any(|c| c.name == b.name))
    {
        look(&b.body);
    }
    Ok((!direct).then_some((chosen, rows)))
}

/// The inverse of a square rational matrix, if it is invertible.
fn rational_inverse(m: &[Vec<rug::Rational>]) -> Option<Vec<Vec<rug::Rational>>> {
    let n = m.len();
    let mut a: Vec<Vec<rug::Rational>> = m
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let mut row = r.clone();
            row.extend((0..n).map(|j| rug::Rational::from(i32::from(i == j))));
            row
        })
        .collect();
    for col in 0..n {
        let piv = (col..n).find(|&r| a[r][col] != 0)?;
        a.swap(col, piv);
        let p = a[col][col].clone();
        for x in a[col].iter_mut() {
            *x /= &p;
        }
        for r in 0..n {
            if r != col && a[r][col] != 0 {
                let f = a[r][col].clone();
                let prow = a[col].clone();
                for (x, y) in a[r].iter_mut().zip(&prow) {
                    *x -= rug::Rational::from(&f * y);
                }
            }
        }
    }
    Some(a.into_iter().map(|r| r[n..].to_vec()).collect())
}

/// After parametrizations, the claim's free variables as functions of the remaining
/// indeterminates and the new parameters (for derivatives by the chain rule).
fn declare_coordinates(
    ev: &Evaluator<'_, Sym>,
    ring: &Ring,
    roles: &[(String, Role, &PExpr)],
    replaced: &[String],
    new_params: Vec<Sym>,
) -> AlgResult<()> {
    let symbolic = |v: &Value<Sym>| -> Vec<Sym> {
        v.components()
            .into_iter()
            .filter(|c| c.as_rational().is_none())
            .collect()
    };
    let (mut coords, mut params) = (Vec::new(), Vec::new());
    for (name, role, _) in roles {
        if *role != Role::Free {
            continue;
        }
        let Some(v) = ev.lookup(name) else { continue };
        coords.extend(symbolic(v));
        if !replaced.contains(name) {
            params.extend(symbolic(v));
        }
    }
    params.extend(new_params);
    ring.set_coordinates(coords, params)
}

/// The symbolic value of one sampled variable.
fn bind_one(
    ev: &Evaluator<'_, Sym>,
    ring: &Ring,
    name: &str,
    role: &Role,
    def: &PExpr,
    points: &[Point],
) -> AlgResult<Value<Sym>> {
    let fail = |m: String| AlgebraError::Domain(m);
    let first = points[0].get(name).cloned();
    Ok(match (role, first) {
        (Role::Free, Some(Value::Real(_))) => {
            Value::Real(ring.indeterminate(name, &shadows(points, name, None))?)
        }
        (Role::Free, Some(Value::Complex(_))) => {
            // an analytic identity in a complex variable holds for all complex values
            // once it holds for an indeterminate (the claim may not use re/im/conj)
            let z = ring.indeterminate(name, &complex_shadows(points, name))?;
            Value::Complex(Cplx::new(z, ring.integer(0)))
        }
        (Role::Free, Some(Value::Vec3(_))) => {
            let c = |j: usize| {
                ring.indeterminate(&format!("{name}{}", j + 1), &shadows(points, name, Some(j)))
            };
            Value::Vec3(Vec3::new(c(0)?, c(1)?, c(2)?))
        }
        (Role::Sign, Some(Value::Real(_))) => {
            Value::Real(ring.sign_symbol(name, &shadows(points, name, None))?)
        }
        (Role::Case, Some(v)) => v.map(&mut |x: &f64| {
            let q = rug::Rational::from_f64(*x).unwrap_or_default();
            ring.rational(&q)
        }),
        (Role::Computed, _) => eval(ev, def).map_err(fail)?,
        (_, other) => {
            return Err(fail(format!(
                "variable '{name}' of type {:?} cannot be a symbol",
                other.map(|v| v.type_name())
            )));
        }
    })
}

/// Replaces the free arguments of one implicit call by its parametrization, and
/// remembers the call's value at the new arguments.
fn parametrize(
    ctx: Ctx<'_>,
    ev: &mut Evaluator<'_, Sym>,
    plan: &Plan<'_>,
) -> AlgResult<(Vec<Sym>, Vec<Sym>)> {
    let fail = |m: String| AlgebraError::Domain(format!("{}: {m}", plan.name));
    let imp = ctx
        .cat
        .registry
        .ext(&plan.name)
        .and_then(|r| r.f.implicit())
        .ok_or_else(|| fail("not an implicit function".into()))?;
    let args_now = |ev: &Evaluator<'_, Sym>| -> AlgResult<Vec<Value<Sym>>> {
        plan.args
            .iter()
            .map(|a| ev.eval(a).map_err(|e| fail(e.message)))
            .collect()
    };
    let p = imp.parametrize(&args_now(ev)?).map_err(fail)?;
    for (var, v) in plan.vars.iter().zip(p.replace) {
        ev.bind(var, v);
    }
    let args = args_now(ev)?;
    crate::claims::implicit::remember(&plan.name, &args, &p.value).map_err(fail)?;
    for (name, v) in &p.also {
        crate::claims::implicit::remember(name, &args, v).map_err(fail)?;
    }
    let ring = ev.like().ring().clone();
    ring.note(p.note);
    ring.note(format!(
        "the equations {} at the parametrization are proved to vanish together with the claim",
        imp.equations()
    ));
    ring.assume(
        AssumptionKind::Branch(plan.name.clone()),
        format!("{}: {}", plan.name, imp.branch()),
    );
    Ok((p.checks, p.params))
}

/// Both sides as pairs of scalar components (every component of lhs − rhs against 0).
/// When one side is an implicit call the parametrizations did not cover, the other side
/// is its stated value and is substituted into the function's equations instead.
fn sides(ev: &Evaluator<'_, Sym>, lhs: &PExpr, rhs: &PExpr) -> AlgResult<Vec<(Sym, Sym)>> {
    let fail = AlgebraError::Domain;
    let zero = ev.like().zero();
    for (call, other) in [(lhs, rhs), (rhs, lhs)] {
        if let Some(comps) = stated_value(ev, call, other)? {
            return Ok(comps.into_iter().map(|c| (c, zero.clone())).collect());
        }
    }
    let l = eval(ev, lhs).map_err(fail)?;
    let r = eval(ev, rhs).map_err(fail)?;
    let d = l
        .sub(&r)
        .map_err(|m| fail(format!("lhs and rhs have different types: {m}")))?;
    Ok(d.components()
        .into_iter()
        .map(|c| (c, zero.clone()))
        .collect())
}

/// If `call` is a call of an implicit function whose value is not known, the
/// components of its equations with `other` as the value.
fn stated_value(
    ev: &Evaluator<'_, Sym>,
    call: &PExpr,
    other: &PExpr,
) -> AlgResult<Option<Vec<Sym>>> {
    let ExprKind::Call(name, args) = &call.expr.kind else {
        return Ok(None);
    };
    let Some(imp) = ev.registry().ext(name).and_then(|r| r.f.implicit()) else {
        return Ok(None);
    };
    let fail = |m: String| AlgebraError::Domain(format!("{name}: {m}"));
    let vals: Vec<Value<Sym>> = args
        .iter()
        .map(|a| ev.eval(a).map_err(|e| fail(e.message)))
        .collect::<AlgResult<_>>()?;
    if crate::claims::implicit::recall(name, &vals).is_some() {
        return Ok(None);
    }
    let value = eval(ev, other).map_err(AlgebraError::Domain)?;
    let (comps, factor) = imp.stated_residual(&vals, &value).map_err(fail)?;
    let ring = ev.like().ring().clone();
    if let Some(d) = factor {
        // the equations were multiplied by d: they hold where d ≠ 0, decided on the domain
        if d.sign()? == 0 {
            return Err(fail("the equations' factor vanishes".into()));
        }
        ring.note(format!(
            "the equations of {name} are multiplied through by the denominator of γ, which is nonzero on the domain"
        ));
    }
    ring.note(format!(
        "the claim states the value of {name}: the other side is substituted into {}, and every component vanishes",
        imp.stated_equations()
    ));
    ring.assume(
        AssumptionKind::Branch(name.to_string()),
        format!("{name}: {}", imp.branch()),
    );
    Ok(Some(comps))
}

/// One case: the zero test of every component (the prover restarts when the elliptic
/// bases must be refined, and expands named quantities if the first test is not 0).
pub(super) fn prove_case(
    ctx: Ctx<'_>,
    roles: &[(String, Role, &PExpr)],
    points: &[Point],
    sides_of: (&PExpr, &PExpr),
    (certificate, signs): (bool, &Signs),
    base_hints: Vec<BaseHint>,
    region: &super::split::Region,
) -> Proof {
    let opts = RingOptions {
        points: points.len(),
        certificate,
        base_hints,
        positivity: signs.positivity.clone(),
        hypotheses: region.signs.clone(),
        sign_folds: region.folds.clone(),
        ..RingOptions::default()
    };
    let hint = ctx.claim.hint.as_ref();
    let mut exprs: Vec<&Expr> = vec![&sides_of.0.expr, &sides_of.1.expr];
    // a hinted call stays unknown: it is not parametrized
    exprs.extend(
        ctx.claim
            .lets
            .iter()
            .filter(|b| hint.is_none_or(|h| h.value != b.name))
            .map(|b| &b.body),
    );
    let lemmas = super::lemmas::lemmas(ctx);
    exprs.extend(lemmas.iter().map(|l| &l.rhs.expr));
    let plans = plans(ctx, roles, &exprs);
    prove_components(opts, &ctx.claim.id, |ring| {
        let Bound {
            ev,
            checks,
            unknown,
        } = bind_variables(ctx, ring, roles, points, (&plans, &lemmas), hint)?;
        super::hypotheses::state_signs(ctx, &ev)?;
        let mut pairs = match (hint, &unknown) {
            (Some(h), Some(v)) => super::hinted::sides(ctx, &ev, h, v, sides_of)?,
            _ => sides(&ev, sides_of.0, sides_of.1)?,
        };
        let zero = ev.like().zero();
        pairs.extend(checks.into_iter().map(|c| (c, zero.clone())));
        Ok(pairs)
    })
}

/// How the proof decides signs: the domain's parametrization.
pub(super) struct Signs {
    positivity: Option<std::sync::Arc<crate::algebra::positivity::Parametrization>>,
}

/// Attempts a symbolic proof of `lhs = rhs` on the claim's domain.
pub fn prove(ctx: Ctx<'_>, lhs: &PExpr, rhs: &PExpr, certificate: bool) -> ProofInfo {
    let t0 = Instant::now();
    let condition = states_condition(ctx, &[lhs, rhs]);
    let sampler = match ctx.sampler(Stream::Proof) {
        Ok(s) => s,
        Err(c) => return ProofInfo::none(c.to_string()),
    };
    if let Some(why) = not_analytic(ctx, sampler.variables(), &[lhs, rhs]) {
        return ProofInfo::none(why);
    }
    if let Some(why) = iteration(ctx, &[lhs, rhs]) {
        return ProofInfo::none(why);
    }
    let signs = Signs {
        positivity: super::positivity::parametrization(sampler.variables()),
    };
    if let (Some(why), None) = (&condition, &signs.positivity) {
        return ProofInfo::none(format!(
            "{why} (no variable of its domain can be parametrized to prove signs)"
        ));
    }
    let plain: Vec<(String, (Role, usize))> = sampler
        .variables()
        .iter()
        .map(|(n, p)| (n.clone(), role_of(p)))
        .collect();
    let roles: Vec<(String, Role, &PExpr)> = sampler
        .variables()
        .iter()
        .zip(&plain)
        .map(|((n, p), (_, (r, _)))| (n.clone(), r.clone(), *p))
        .collect();
    let cases = match case_points(ctx, &plain) {
        Ok(c) if !c.is_empty() => c,
        Ok(_) => return ProofInfo::none("no case of the domain has enough points"),
        Err(m) => return ProofInfo::none(m),
    };
    if let Some(mut joint) =
        prove_signs_jointly(ctx, &roles, &cases, (lhs, rhs), (certificate, &signs))
    {
        joint.ms = t0.elapsed().as_secs_f64() * 1e3;
        return with_lemmas(ctx, joint);
    }
    let mut info = ProofInfo::none("");
    info.reason = None;
    info.method = ProofMethod::Symbolic;
    let mut hints = Vec::new();
    let input = super::split::CaseInput {
        ctx,
        roles: &roles,
        sides: (lhs, rhs),
        certificate,
        signs: &signs,
    };
    for (key, points) in &cases {
        // the cases differ in signs only: the bases that served one serve the next
        match super::split::prove_parts(&input, key, points.clone(), hints.clone()) {
            Ok(parts) => {
                for (label, p) in parts {
                    hints = p.base_hints.clone();
                    merge(ctx, &mut info, &label, p);
                }
            }
            Err(part) => {
                let (label, p) = *part;
                merge(ctx, &mut info, &label, p);
                break;
            }
        }
    }
    info.ms = t0.elapsed().as_secs_f64() * 1e3;
    with_lemmas(ctx, info)
}

/// A proof that rests on lemmas stands only when they are proved.
fn with_lemmas(ctx: Ctx<'_>, info: ProofInfo) -> ProofInfo {
    let lemmas = super::lemmas::lemmas(ctx);
    if !info.is_proved() || lemmas.is_empty() {
        return info;
    }
    match super::lemmas::check(ctx, &lemmas, prove) {
        Ok(()) => info,
        Err(why) => ProofInfo {
            ms: info.ms,
            ..ProofInfo::none(why)
        },
    }
}

/// One proof for every sign case at once, where the case variables take the values ±1
/// only: they become sign symbols (σ² = 1), and the points of all cases serve as the
/// domain points.  `None` when this does not apply or does not prove the claim (the
/// cases are then enumerated).
fn prove_signs_jointly(
    ctx: Ctx<'_>,
    roles: &[(String, Role, &PExpr)],
    cases: &Cases,
    sides: (&PExpr, &PExpr),
    certificate: (bool, &Signs),
) -> Option<ProofInfo> {
    let points: Vec<Point> = cases.values().flatten().cloned().collect();
    let is_sign = |name: &str| {
        points.iter().all(|p| match p.get(name) {
            Some(Value::Real(x)) => *x == 1.0 || *x == -1.0,
            _ => false,
        })
    };
    let signs: Vec<&str> = roles
        .iter()
        .filter(|(_, r, _)| *r == Role::Case)
        .map(|(n, _, _)| n.as_str())
        .collect();
    if cases.len() < 2 || !signs.iter().all(|n| is_sign(n)) {
        return None;
    }
    let joint: Vec<(String, Role, &PExpr)> = roles
        .iter()
        .map(|(n, r, p)| {
            let r = if *r == Role::Case {
                Role::Sign
            } else {
                r.clone()
            };
            (n.clone(), r, *p)
        })
        .collect();
    let region = super::split::Region::default();
    let p = prove_case(
        ctx,
        &joint,
        &points,
        sides,
        certificate,
        Vec::new(),
        &region,
    );
    if !matches!(p.outcome, Outcome::Proved) {
        return None;
    }
    let mut info = ProofInfo::none("");
    info.reason = None;
    info.method = ProofMethod::Symbolic;
    merge(ctx, &mut info, &[], p);
    info.notes.push(format!(
        "{} {} sign symbols: one normal form covers all {} sign cases",
        signs.join(", "),
        if signs.len() == 1 { "is a" } else { "are" },
        cases.len()
    ));
    Some(info)
}

/// Adds one case's proof to the record; a case that is not proved ends the proof.
fn merge(ctx: Ctx<'_>, info: &mut ProofInfo, key: &[String], p: Proof) {
    let label = key.join(", ");
    if let Outcome::NotProved(r) = &p.outcome {
        info.method = ProofMethod::None;
        info.reason = Some(if label.is_empty() {
            r.clone()
        } else {
            format!("case {label}: {r}")
        });
    }
    if !label.is_empty() {
        info.cases.push(label.clone());
    }
    let add = |dst: &mut Vec<String>, src: Vec<String>| {
        for s in src {
            if !dst.contains(&s) {
                dst.push(s);
            }
        }
    };
    add(
        &mut info.symbols,
        p.symbols.iter().map(|(n, w)| format!("{n}: {w}")).collect(),
    );
    add(&mut info.relations, p.relations.clone());
    add(&mut info.notes, p.notes.clone());
    add(&mut info.proved_signs, p.proved_signs.clone());
    add(&mut info.uncertified, p.uncertified.clone());
    if info.parametrization.is_none() {
        info.parametrization = p.parametrization.clone();
    }
    match super::hypotheses::uses(ctx, &p.assumptions) {
        Ok(uses) => {
            for u in uses {
                if !info.hypotheses.contains(&u) {
                    info.hypotheses.push(u);
                }
            }
        }
        Err(why) if info.is_proved() => {
            info.method = ProofMethod::None;
            info.reason = Some(if label.is_empty() {
                why
            } else {
                format!("case {label}: {why}")
            });
        }
        Err(_) => {}
    }
    info.terms = info.terms.max(p.terms);
    if let Some(c) = p.certificate {
        let prev = info.certificate.take().unwrap_or_default();
        info.certificate = Some(prev + &c);
    }
}

/// Turns a numerical `holds` into `proved` when the symbolic proof succeeds.  A claim
/// the ladder refutes (or cannot judge) is never passed to the prover as true.
pub fn judge(ctx: Ctx<'_>, lhs: &PExpr, rhs: &PExpr, ev: &mut Evidence) {
    upgrade(
        ev,
        || {
            if super::lemmas::is_lemma(ctx) {
                super::lemmas::proof_of(ctx, lhs, rhs, prove)
            } else {
                prove(ctx, lhs, rhs, false)
            }
        },
        |info| {
            format!(
                "the symbolic normal form of lhs − rhs is 0 ({}); holds numerically",
                info.extent()
            )
        },
    );
}

/// Runs `attempt` only when the numerical verdict holds (a claim the ladder refutes or
/// cannot judge is never passed to the prover as true), and makes the verdict `proved`,
/// with the reason `why`, when the attempt proves; the attempt is the claim's evidence.
pub(super) fn upgrade(
    ev: &mut Evidence,
    attempt: impl FnOnce() -> ProofInfo,
    why: impl FnOnce(&ProofInfo) -> String,
) {
    if ev.verdict != Verdict::Holds {
        ev.proof = Some(ProofInfo::none(format!(
            "not attempted: the numerical verdict is {}",
            ev.verdict.name()
        )));
        return;
    }
    let info = attempt();
    if info.is_proved() {
        ev.verdict = Verdict::Proved;
        ev.reason = why(&info);
    }
    ev.proof = Some(info);
}
