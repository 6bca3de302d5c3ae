//! `independence`: expr does not change when the sampled variable `wrt` is redrawn.
//! Residual of a sample: max over the redraws of |expr(wrt') − expr(wrt)| / scale.
//!
//! Proof: the symbolic normal form of `d(expr, wrt)` is 0 (then expr is constant in
//! `wrt` on every interval of the domain on which it is defined).

use super::context::{AtRung, Ctx, Sides, at_rung, collect, eval, render};
use super::ladder;
use super::result::{Cause, Evidence, Failure};
use crate::claims::catalogue::PExpr;
use crate::claims::eval::Backend;
use crate::claims::sampler::{MAX_DRAWS, Point, Sampler, Stream};

/// One sample (a base point and its redraws) at one rung.
struct At<'a> {
    ctx: Ctx<'a>,
    expr: &'a PExpr,
    base: &'a Point,
    alts: &'a [Point],
}

impl AtRung for At<'_> {
    type Output = Result<Sides, String>;
    fn run<T: Backend>(&self, like: T) -> Self::Output {
        let ev0 = self.ctx.setup(self.base, like.clone())?;
        let v0 = eval(&ev0, self.expr)?;
        let s = self.ctx.log2_scale(&ev0, self.base)?;
        let mut worst = (f64::NEG_INFINITY, render(&v0), render(&v0));
        for a in self.alts {
            let ev = self.ctx.setup(a, like.clone())?;
            let v = eval(&ev, self.expr)?;
            let d = v.sub(&v0)?;
            let r = d.log2_magnitude() - v0.log2_magnitude().max(v.log2_magnitude()).max(s);
            if r > worst.0 || worst.0 == f64::NEG_INFINITY {
                worst = (r.max(worst.0), render(&v0), render(&v));
            }
        }
        Ok(Sides {
            log2: worst.0,
            lhs: worst.1,
            rhs: worst.2,
        })
    }
}

/// A base point and `redraws` points that differ from it only in `wrt`, all inside the
/// domain.
pub(super) fn draw(
    sampler: &mut Sampler<'_>,
    alt_sampler: &mut Sampler<'_>,
    wrt: &str,
    redraws: usize,
) -> Result<(Point, Vec<Point>), Cause> {
    let base = sampler.draw().map_err(Cause::Sampling)?;
    if base.get(wrt).is_none() {
        return Err(Cause::Sampling(format!(
            "'{wrt}' is not a sampled variable of this claim"
        )));
    }
    let mut alts = Vec::new();
    let mut tries = 0;
    while alts.len() < redraws {
        tries += 1;
        if tries > MAX_DRAWS {
            return Err(Cause::Sampling(format!(
                "domain too thin to redraw '{wrt}'"
            )));
        }
        let other = alt_sampler.draw().map_err(Cause::Sampling)?;
        let mut p = base.clone();
        for (n, v) in p.vars.iter_mut() {
            if n == wrt
                && let Some(nv) = other.get(wrt)
            {
                *v = nv.clone();
            }
        }
        if sampler.accepts(&p).unwrap_or(false) {
            alts.push(p);
        }
    }
    Ok((base, alts))
}

/// The ladder of an independence claim.
pub fn run(
    ctx: Ctx<'_>,
    expr: &PExpr,
    wrt: &str,
    redraws: usize,
    bits: &[u32],
) -> Result<Evidence, Failure> {
    let mut sampler = ctx.sampler(Stream::Samples).map_err(Failure::bare)?;
    let mut alt_sampler = ctx.sampler(Stream::Redraws).map_err(Failure::bare)?;
    let mut failures = Vec::new();
    let draw = || {
        let (base, alts) = draw(&mut sampler, &mut alt_sampler, wrt, redraws)?;
        Ok(((base.clone(), alts), base))
    };
    let at = |(base, alts): &(Point, Vec<Point>), bits: u32| {
        let job = At {
            ctx,
            expr,
            base,
            alts,
        };
        at_rung(bits, &job)
    };
    match collect(ctx.claim, bits, &mut failures, draw, at) {
        Ok(samples) => Ok(ladder::finish(ctx.claim, bits, &samples, failures)),
        Err(cause) => Err(Failure::with_failures(cause, failures)),
    }
}

/// The identity whose proof proves independence: `d(expr, wrt) = 0`.
pub fn derivative_sides(expr: &PExpr, wrt: &str) -> (PExpr, PExpr) {
    use crate::claims::ast::{Expr, ExprKind};
    let span = expr.expr.span;
    let derivative = PExpr {
        expr: Expr {
            kind: ExprKind::Deriv {
                body: Box::new(expr.expr.clone()),
                var: wrt.to_string(),
                component: None,
            },
            span,
        },
        text: format!("d({}, {wrt})", expr.text.trim()),
        origin: expr.origin.clone(),
    };
    let zero = PExpr {
        expr: Expr {
            kind: ExprKind::Num("0".into()),
            span,
        },
        text: "0".into(),
        origin: expr.origin.clone(),
    };
    (derivative, zero)
}

/// Proves the claim when the numerical verdict holds and `d(expr, wrt)` has the
/// symbolic normal form 0.
pub fn judge_symbolically(ctx: Ctx<'_>, expr: &PExpr, wrt: &str, ev: &mut Evidence) {
    use super::symbolic::{prove, upgrade};
    let (derivative, zero) = derivative_sides(expr, wrt);
    // the same expression on the same domain (a statement the paper makes twice) is
    // proved once per catalogue
    let key = super::lemmas::content_key(ctx, &[&derivative]);
    upgrade(
        ev,
        || super::lemmas::memoised(ctx, &key, || prove(ctx, &derivative, &zero, false)),
        |info| {
            format!(
                "the symbolic normal form of d(expr, {wrt}) is 0 ({}): expr is constant in {wrt} on each interval of the domain; independent numerically",
                info.extent()
            )
        },
    );
}
