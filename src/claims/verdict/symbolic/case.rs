//! One case of a symbolic proof: its ring, its bound variables and the zero test of every
//! component of `lhs − rhs`.

use super::binding::{Bound, bind_variables, plans, sides};
use super::cases::Role;
use crate::algebra::split::SignSplit;
use crate::algebra::{BaseHint, Proof, RingOptions, prove_components};
use crate::claims::ast::Expr;
use crate::claims::catalogue::PExpr;
use crate::claims::sampler::Point;
use crate::claims::verdict::context::Ctx;
use crate::numbers::Scalar;

/// The conditions of a part of the domain: the signs that hold on it, and the
/// indeterminates whose signs the proof carries as sign symbols instead of splitting by
/// them ([`crate::algebra::RingOptions::sign_folds`]).
#[derive(Clone, Default)]
pub(super) struct Region {
    pub signs: Vec<(SignSplit, i32)>,
    pub folds: Vec<SignSplit>,
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
    region: &Region,
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
    let lemmas = crate::claims::verdict::lemmas::lemmas(ctx);
    exprs.extend(lemmas.iter().map(|l| &l.rhs.expr));
    let plans = plans(ctx, roles, &exprs);
    prove_components(opts, &ctx.claim.id, |ring| {
        let Bound {
            ev,
            checks,
            unknown,
        } = bind_variables(ctx, ring, roles, points, (&plans, &lemmas), hint)?;
        let mut pairs = match (hint, &unknown) {
            (Some(h), Some(v)) => crate::claims::verdict::hinted::sides(ctx, &ev, h, v, sides_of)?,
            _ => sides(&ev, sides_of.0, sides_of.1)?,
        };
        let zero = ev.like().zero();
        pairs.extend(checks.into_iter().map(|c| (c, zero.clone())));
        Ok(pairs)
    })
}

/// How the proof decides signs: the domain's parametrization.
pub(super) struct Signs {
    pub(super) positivity: Option<std::sync::Arc<crate::algebra::positivity::Parametrization>>,
}
