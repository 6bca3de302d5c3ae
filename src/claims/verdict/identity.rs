//! `identity`: lhs == rhs at every sample, on the precision ladder (and exactly, see
//! [`super::exact`]).

use super::context::{AtRung, Ctx, Sides, at_rung, collect, eval, render};
use super::ladder;
use super::result::{Cause, Evidence, Failure};
use crate::claims::catalogue::PExpr;
use crate::claims::eval::Backend;
use crate::claims::sampler::{Point, Stream};

/// One sample of an identity at one rung.
struct At<'a> {
    ctx: Ctx<'a>,
    lhs: &'a PExpr,
    rhs: &'a PExpr,
    point: &'a Point,
}

impl AtRung for At<'_> {
    type Output = Result<Sides, String>;
    fn run<T: Backend>(&self, like: T) -> Self::Output {
        let ev = self.ctx.setup(self.point, like)?;
        let l = eval(&ev, self.lhs)?;
        let r = eval(&ev, self.rhs)?;
        let diff = l
            .sub(&r)
            .map_err(|m| format!("lhs and rhs have different types: {m}"))?;
        let s = self.ctx.log2_scale(&ev, self.point)?;
        let den = l.log2_magnitude().max(r.log2_magnitude()).max(s);
        Ok(Sides {
            log2: diff.log2_magnitude() - den,
            lhs: render(&l),
            rhs: render(&r),
        })
    }
}

/// The float ladder of an identity.
pub fn ladder(ctx: Ctx<'_>, lhs: &PExpr, rhs: &PExpr, bits: &[u32]) -> Result<Evidence, Failure> {
    let mut sampler = ctx.sampler(Stream::Samples).map_err(Failure::bare)?;
    let mut failures = Vec::new();
    let draw = || {
        let p = sampler.draw().map_err(Cause::Sampling)?;
        Ok((p.clone(), p))
    };
    let at = |point: &Point, bits: u32| {
        let job = At {
            ctx,
            lhs,
            rhs,
            point,
        };
        at_rung(bits, &job)
    };
    match collect(ctx.claim, bits, &mut failures, draw, at) {
        Ok(samples) => Ok(ladder::finish(ctx.claim, bits, &samples, failures)),
        Err(cause) => Err(Failure::with_failures(cause, failures)),
    }
}
