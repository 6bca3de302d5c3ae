//! `negation`: holds when the inner claim is refuted (its counterexample is the
//! evidence), and is proved when that refutation is certified by a witness (a domain
//! point at which the inner identity's lhs − rhs is provably nonzero: the negation of
//! "lhs = rhs on the whole domain" is exactly the existence of such a point); refuted
//! when the inner claim holds or is proved, inconclusive otherwise.

use super::proof_info::ProofMethod;
use super::result::{ClaimResult, Evidence};
use crate::claims::kind::Verdict;

/// The evidence of a negation from the result of its inner claim.
pub fn judge(inner: &ClaimResult) -> Evidence {
    let witnessed = inner.proof.method == ProofMethod::Witness;
    let verdict = match inner.verdict {
        Verdict::Refuted if witnessed => Verdict::Proved,
        Verdict::Refuted => Verdict::Holds,
        Verdict::Holds | Verdict::Proved => Verdict::Refuted,
        _ => Verdict::Inconclusive,
    };
    Evidence {
        proof: (verdict == Verdict::Proved).then(|| inner.proof.clone()),
        residuals: inner.residuals.clone(),
        loss_bits: inner.loss_bits,
        samples: inner.samples,
        failures: inner.failures.clone(),
        counterexample: inner.counterexample.clone(),
        exact: inner.exact.clone(),
        ..Evidence::new(
            verdict,
            if verdict == Verdict::Proved {
                format!(
                    "proved by a witness: the inner claim fails at a domain point where its lhs − rhs is certified nonzero ({})",
                    inner.reason
                )
            } else {
                let why = match (&inner.proof.reason, verdict) {
                    (Some(r), Verdict::Holds) => format!("; no witness: {r}"),
                    _ => String::new(),
                };
                format!(
                    "inner claim {}: {}{why}",
                    inner.verdict.name(),
                    inner.reason
                )
            },
        )
    }
}
