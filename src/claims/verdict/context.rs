//! What every kind needs to evaluate a claim at a sample: the evaluator set up with the
//! point and the `let` bindings, the residual scale, the dispatch of one computation to
//! the backend of a rung, and the loop that draws samples and records failures.

use super::failure::{Cause, FailedSample, Named};
use crate::claims::catalogue::{Catalogue, Claim, PExpr};
use crate::claims::eval::{Backend, Evaluator};
use crate::claims::sampler::{Point, Sampler, Stream};
use crate::claims::value::{Layout, Value};
use rayon::prelude::*;
use rug::Float;

/// One claim of one catalogue.
#[derive(Clone, Copy)]
pub struct Ctx<'c> {
    /// The catalogue (functions, domains).
    pub cat: &'c Catalogue,
    /// The claim.
    pub claim: &'c Claim,
}

impl<'c> Ctx<'c> {
    /// A sampler of the claim's domain on `stream`.
    pub fn sampler(&self, stream: Stream) -> Result<Sampler<'c>, Cause> {
        Sampler::new(self.cat, self.claim, stream).map_err(Cause::Sampling)
    }

    /// An evaluator with the point bound (f64 values, exactly) and the claim's `let`
    /// bindings evaluated.
    pub fn setup<T: Backend>(&self, point: &Point, like: T) -> Result<Evaluator<'c, T>, String> {
        let mut ev = Evaluator::new(&self.cat.registry, like.clone());
        for (n, v) in &point.vars {
            ev.bind(n, v.map(&mut |x: &f64| like.from_f64(*x)));
        }
        for b in &self.claim.lets {
            ev.bind_let(b)
                .map_err(|e| format!("let {}: {}", b.name, e.message))?;
        }
        Ok(ev)
    }

    /// log2 of the residual scale S at this point: the claim's `scale`, else the size of
    /// the sampled inputs.
    pub fn log2_scale<T: Backend>(
        &self,
        ev: &Evaluator<'_, T>,
        point: &Point,
    ) -> Result<f64, String> {
        match &self.claim.scale {
            Some(s) => {
                let l = eval(ev, s)?.log2_magnitude();
                if l.is_finite() {
                    Ok(l)
                } else {
                    Err("scale evaluates to zero".into())
                }
            }
            None => Ok(point.size().log2()),
        }
    }
}

/// Evaluates a catalogue expression; the error quotes the failing sub-expression.
pub fn eval<T: Backend>(ev: &Evaluator<'_, T>, p: &PExpr) -> Result<Value<T>, String> {
    ev.eval(&p.expr).map_err(|e| {
        let at = e
            .span
            .and_then(|s| p.text.get(s.start..s.end))
            .map(|t| format!(" at '{t}'"))
            .unwrap_or_default();
        format!("{}{at}", e.message)
    })
}

/// A value as shown in evidence: 20 digits, one line.
pub fn render<T: Backend>(v: &Value<T>) -> String {
    v.render(20, Layout::Inline)
}

/// The point as name/value pairs with round-trip f64 digits.
pub fn named(p: &Point) -> Vec<Named> {
    p.render()
        .into_iter()
        .map(|(name, value)| Named { name, value })
        .collect()
}

/// A computation at one rung, written once for every backend.
pub trait AtRung {
    /// What it computes.
    type Output;
    /// Runs it with scalars like `like`.
    fn run<T: Backend>(&self, like: T) -> Self::Output;
}

/// Runs `job` at `bits` of precision: IEEE f64 at 53 bits, MPFR otherwise.
pub fn at_rung<J: AtRung>(bits: u32, job: &J) -> J::Output {
    if bits == 53 {
        job.run(0.0f64)
    } else {
        job.run(Float::new(bits))
    }
}

/// A sample evaluated at every rung: what was drawn, the point shown as evidence, and
/// the value per rung.
pub struct Sample<P, V> {
    /// What the kind drew (a point, a point with redraws, a point with a start).
    pub drawn: P,
    /// The point.
    pub point: Point,
    /// Per rung, in ladder order.
    pub rungs: Vec<V>,
}

/// One rung of an identity-like sample: log2 of the scaled residual and both sides.
#[derive(Clone, Debug, PartialEq)]
pub struct Sides {
    /// log2 residual.
    pub log2: f64,
    /// The left side (or the expression).
    pub lhs: String,
    /// The right side (or the comparison value).
    pub rhs: String,
}

/// Draws `claim.samples` samples and evaluates `at(sample, bits)` at every rung.  A
/// sample that fails at some rung is recorded in `failures` (with the lowest failing
/// rung) and replaced; after `claim.samples` failures the claim cannot be judged.
///
/// The draws are sequential (the streams are), in batches of as many samples as are still
/// missing; the evaluations of a batch, one job per sample and rung, run in parallel on
/// the current rayon pool, so one slow claim keeps every core busy.  The result is the
/// same as drawing and evaluating one sample at a time: a batch never draws more than
/// that loop would (at most the missing samples, and at most the failures still
/// allowed), and its results are taken in draw order.
pub fn collect<P: Sync, V: Send>(
    claim: &Claim,
    bits: &[u32],
    failures: &mut Vec<FailedSample>,
    mut draw: impl FnMut() -> Result<(P, Point), Cause>,
    at: impl Fn(&P, u32) -> Result<V, String> + Sync,
) -> Result<Vec<Sample<P, V>>, Cause> {
    let mut good = Vec::new();
    while good.len() < claim.samples {
        if failures.len() >= claim.samples {
            return Err(Cause::Unevaluable {
                count: failures.len(),
                first: failures.first().map_or("", |f| f.message.as_str()).into(),
            });
        }
        let batch = (claim.samples - good.len()).min(claim.samples - failures.len());
        let mut drawn = Vec::with_capacity(batch);
        let mut stopped = None;
        for _ in 0..batch {
            match draw() {
                Ok(d) => drawn.push(d),
                Err(cause) => {
                    stopped = Some(cause);
                    break;
                }
            }
        }
        let rows = evaluate(&drawn, bits, &at);
        for ((drawn, point), row) in drawn.into_iter().zip(rows) {
            match row {
                Ok(rungs) => good.push(Sample {
                    drawn,
                    point,
                    rungs,
                }),
                Err((b, message)) => failures.push(FailedSample {
                    point: named(&point),
                    bits: b,
                    message,
                }),
            }
        }
        if let Some(cause) = stopped {
            return Err(cause);
        }
    }
    Ok(good)
}

/// Evaluates every drawn sample at every rung in parallel; per sample, its values in
/// ladder order or its lowest failing rung with the message.
fn evaluate<P: Sync, V: Send>(
    drawn: &[(P, Point)],
    bits: &[u32],
    at: &(impl Fn(&P, u32) -> Result<V, String> + Sync),
) -> Vec<Result<Vec<V>, (u32, String)>> {
    let jobs: Vec<(usize, u32)> = (0..drawn.len())
        .flat_map(|i| bits.iter().map(move |&b| (i, b)))
        .collect();
    let values: Vec<Result<V, String>> =
        jobs.par_iter().map(|&(i, b)| at(&drawn[i].0, b)).collect();
    let mut values = values.into_iter();
    (0..drawn.len())
        .map(|_| {
            let mut row = Vec::with_capacity(bits.len());
            let mut failed = None;
            for (&b, v) in bits.iter().zip(values.by_ref()) {
                match v {
                    Ok(x) if failed.is_none() => row.push(x),
                    Ok(_) => {}
                    Err(m) => {
                        failed.get_or_insert((b, m));
                    }
                }
            }
            failed.map_or(Ok(row), Err)
        })
        .collect()
}
