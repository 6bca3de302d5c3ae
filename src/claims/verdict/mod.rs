//! The verdict engine: evaluates each claim on a precision ladder (and exactly, for
//! rational claims) and decides holds / refuted / proved / inconclusive, with evidence.
//!
//! One module per kind ([`identity`], [`independence`], [`asymptotic`], [`existence`],
//! [`negation`], and [`exact`] for the rational evaluation of identities); each returns
//! its [`Evidence`] or a typed [`Failure`].  The ladder rule shared by the residual kinds
//! is in [`ladder`].  Before a kind runs, [`vacuity`] checks that the conditions the
//! claim counts are exercised on its domain.  This module runs the right kind and builds
//! the [`ClaimResult`] once.
//!
//! Samples that cannot be evaluated are reported as failures and replaced, never counted.

pub mod asymptotic;
pub mod ball_witness;
pub mod context;
pub mod exact;
pub mod existence;
pub mod failure;
pub mod hinted;
mod hypotheses;
pub mod identity;
pub mod independence;
pub mod ladder;
pub(crate) mod lemmas;
pub mod negation;
mod positivity;
pub mod proof_info;
pub mod result;
pub mod symbolic;
pub mod vacuity;

pub use crate::claims::kind::Verdict;
pub use proof_info::HypothesisUse;
pub use result::{
    Cause, ClaimResult, Counterexample, Evidence, ExactInfo, FailedSample, Failure, Named, Rung,
};
pub use symbolic::{ProofInfo, ProofMethod};

use crate::claims::catalogue::{Body, Catalogue, Claim};
use context::Ctx;
use rayon::prelude::*;

/// The default precision ladder.
pub const DEFAULT_BITS: [u32; 5] = [53, 128, 256, 512, 1024];

/// Verification options.
#[derive(Clone, Debug)]
pub struct Options {
    /// The precision ladder (53 = f64; others MPFR).
    pub bits: Vec<u32>,
    /// Exact work: symbolic proofs of identities, and the rational points of
    /// `exact = true` claims.
    pub exact: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            bits: DEFAULT_BITS.to_vec(),
            exact: true,
        }
    }
}

/// Verifies the claims selected by `select`, in parallel, calling `done` as each finishes.
/// Results are in catalogue order.  The claims run in parallel, and so do the samples
/// and rungs of each claim (see [`context::collect`]).  With the environment variable
/// `EULERTOP_TIMING` set, per-claim wall times are printed on standard error.
pub fn verify(
    cat: &Catalogue,
    opts: &Options,
    select: &(dyn Fn(&Claim) -> bool + Sync),
    done: &(dyn Fn(&ClaimResult) + Sync),
) -> Vec<ClaimResult> {
    let selected: Vec<&Claim> = cat.claims.iter().filter(|c| select(c)).collect();
    // results keep the catalogue's order
    let chosen: Vec<(usize, &Claim)> = run_order(cat, &selected)
        .into_iter()
        .map(|i| (i, selected[i]))
        .collect();
    // Opt-in per-claim timings on standard error (never part of the results).
    let timing = std::env::var_os("EULERTOP_TIMING").is_some();
    // One shared queue in that order: each worker takes the next claim when it is
    // free (a parallel iterator would start the second worker half-way down the list).
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(Vec::with_capacity(chosen.len()));
    (0..rayon::current_num_threads())
        .into_par_iter()
        .for_each(|_| {
            loop {
                let j = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some((i, c)) = chosen.get(j) else { break };
                let r = run_claim(cat, c, opts);
                if timing {
                    eprintln!("timing {:8.1} ms  {}", r.elapsed_ms, c.id);
                }
                done(&r);
                results
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .push((*i, r));
            }
        });
    let mut results = results.into_inner().unwrap_or_else(|e| e.into_inner());
    results.sort_by_key(|(i, _)| *i);
    results.into_iter().map(|(_, r)| r).collect()
}

/// The order in which to run `claims` (indices into it): the likely slowest first, so
/// that no core idles at the end, and a statement stated again (whose proof is then
/// recalled) after its first statement; otherwise the catalogue's order.
pub fn run_order(cat: &Catalogue, claims: &[&Claim]) -> Vec<usize> {
    let mut seen = std::collections::BTreeSet::new();
    let costs: Vec<u8> = claims
        .iter()
        .map(|c| {
            let again = statement_key(cat, c).is_some_and(|k| !seen.insert(k));
            if again { 0 } else { expected_cost(cat, c) }
        })
        .collect();
    let mut order: Vec<usize> = (0..claims.len()).collect();
    order.sort_by_key(|&i| (std::cmp::Reverse(costs[i]), i));
    order
}

/// The key under which an independence claim's proof is remembered (the same
/// statement on the same domain has the same key); `None` for other claims.
fn statement_key(cat: &Catalogue, claim: &Claim) -> Option<String> {
    let Body::Independence { expr, wrt, .. } = &claim.body else {
        return None;
    };
    let (derivative, _) = independence::derivative_sides(expr, wrt);
    Some(lemmas::content_key(Ctx { cat, claim }, &[&derivative]))
}

/// A rough rank of a claim's cost, for scheduling only: independence proofs through
/// implicit maps, then identities with implicit calls, then the rest.
fn expected_cost(cat: &Catalogue, claim: &Claim) -> u8 {
    let implicit = lemmas::calls_where(claim, |n| {
        cat.registry
            .ext(n)
            .is_some_and(|r| r.f.implicit().is_some())
    });
    match (&claim.body, implicit) {
        (Body::Independence { .. }, true) => 2,
        (Body::Identity { .. }, true) => 1,
        _ => 0,
    }
}

/// Verifies one claim.  A panic in another layer (a bug there) does not take the run
/// down: the claim is inconclusive with the panic message as the reason.
///
/// ```
/// use eulertop::claims::catalogue::load_sources;
/// use eulertop::claims::registry::Registry;
/// use eulertop::claims::verdict::{run_claim, Options, Verdict};
///
/// let toml = r#"
/// [[claim]]
/// id = "pythagoras"
/// environment = "Section 2"
/// role = "statement"
/// location = "anywhere"
/// printed = 'sin^2 x + cos^2 x = 1'
/// kind = "identity"
/// expect = "proved"
/// vars = [["x", "uniform(-3, 3)"]]
/// lhs = "sin(x)^2 + cos(x)^2"
/// rhs = "1"
/// "#;
/// let cat = load_sources(&[("t.toml".into(), toml.into())], Registry::new()).unwrap();
/// let opts = Options { bits: vec![53, 128], exact: true };
/// let r = run_claim(&cat, &cat.claims[0], &opts);
/// assert_eq!(r.verdict, Verdict::Proved); // holds on the ladder, and sin, cos are sn, cn at k = 0
/// assert!(r.as_expected && r.samples == 8);
/// ```
pub fn run_claim(cat: &Catalogue, claim: &Claim, opts: &Options) -> ClaimResult {
    let t0 = std::time::Instant::now();
    let ctx = Ctx { cat, claim };
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| judge(ctx, opts)))
        .unwrap_or_else(|p| {
            let msg = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            Err(Failure::bare(Cause::Panic(msg)))
        });
    let mut evidence = outcome.unwrap_or_else(Failure::into_evidence);
    if let (Verdict::Proved, Some(why)) = (evidence.verdict, &claim.construction) {
        evidence.verdict = Verdict::Construction;
        evidence.reason = format!("holds by construction: {why} ({})", evidence.reason);
    }
    ClaimResult {
        elapsed_ms: t0.elapsed().as_secs_f64() * 1e3,
        ..ClaimResult::new(claim, evidence)
    }
}

/// Runs the claim's kind.
fn judge(ctx: Ctx<'_>, opts: &Options) -> Result<Evidence, Failure> {
    let bits = &opts.bits;
    if bits.is_empty() {
        return Err(Failure::bare(Cause::EmptyLadder));
    }
    if !matches!(ctx.claim.body, Body::Definition(_)) {
        vacuity::check(ctx).map_err(Failure::bare)?;
    }
    match &ctx.claim.body {
        Body::Definition(_) => Ok(Evidence::new(Verdict::Defined, "definition: no verdict")),
        Body::Identity { lhs, rhs } => {
            let ladder = identity::ladder(ctx, lhs, rhs, bits)?;
            let mut ev = match (ctx.claim.exact, opts.exact) {
                (Some(spec), true) => exact::refine(ctx, lhs, rhs, spec, ladder)?,
                _ => ladder,
            };
            if opts.exact {
                match hypotheses::check_at_samples(ctx) {
                    Ok(()) => symbolic::judge(ctx, lhs, rhs, &mut ev),
                    Err(why) => ev.reason = format!("{}; not proved: {why}", ev.reason),
                }
                ball_witness::refine(ctx, lhs, rhs, &mut ev);
            }
            Ok(ev)
        }
        Body::Independence { expr, wrt, redraws } => {
            let mut ev = independence::run(ctx, expr, wrt, *redraws, bits)?;
            if opts.exact {
                independence::judge_symbolically(ctx, expr, wrt, &mut ev);
                ball_witness::refine_independence(ctx, expr, (wrt, *redraws), &mut ev);
            }
            Ok(ev)
        }
        Body::Asymptotic {
            expr,
            var,
            order,
            h0,
            steps,
            slope_tol,
        } => asymptotic_verdict(
            ctx,
            opts,
            asymptotic::Spec {
                expr,
                var,
                order: *order,
                h0: *h0,
                steps: *steps,
                slope_tol: *slope_tol,
            },
        ),
        Body::Existence {
            unknowns,
            equations,
            start,
            in_set,
            tries,
        } => existence_verdict(
            ctx,
            opts,
            existence::Spec {
                unknowns,
                equations,
                start,
                in_set: in_set.as_ref(),
                tries: *tries,
            },
        ),
        Body::Negation(inner) => Ok(negation::judge(&run_claim(ctx.cat, inner, opts))),
    }
}

/// An asymptotic claim: the slopes, then the power series ([`symbolic::judge_order`]).
fn asymptotic_verdict(
    ctx: Ctx<'_>,
    opts: &Options,
    spec: asymptotic::Spec<'_>,
) -> Result<Evidence, Failure> {
    let mut ev = asymptotic::run(ctx, spec, &opts.bits)?;
    if opts.exact {
        let order = symbolic::Order {
            expr: spec.expr,
            var: spec.var,
            order: spec.order,
            certificate: false,
        };
        symbolic::judge_order(ctx, order, &mut ev);
    }
    Ok(ev)
}

/// An existence claim: Newton's method at the samples, then the implicit function
/// theorem for small h ([`symbolic::judge_existence`]).
fn existence_verdict(
    ctx: Ctx<'_>,
    opts: &Options,
    spec: existence::Spec<'_>,
) -> Result<Evidence, Failure> {
    let mut ev = existence::run(ctx, spec, &opts.bits)?;
    if opts.exact {
        let sys = symbolic::System {
            unknowns: spec.unknowns,
            equations: spec.equations,
            start: spec.start,
            in_set: spec.in_set,
            certificate: false,
        };
        symbolic::judge_existence(ctx, sys, &mut ev);
    }
    Ok(ev)
}

/// Labels → claim ids with verdicts, for `--coverage`.
pub fn coverage_table(
    labels: &[String],
    results: &[ClaimResult],
) -> Vec<(String, Vec<(String, Verdict)>)> {
    labels
        .iter()
        .map(|l| {
            let ids = results
                .iter()
                .filter(|r| r.labels.contains(l))
                .map(|r| (r.id.clone(), r.verdict))
                .collect();
            (l.clone(), ids)
        })
        .collect()
}
