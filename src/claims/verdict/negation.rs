//! `negation`: holds when the inner claim is refuted (its counterexample is the
//! evidence), refuted when the inner claim holds or is proved, inconclusive otherwise.

use super::result::{ClaimResult, Evidence};
use crate::claims::kind::Verdict;

/// The evidence of a negation from the result of its inner claim.
pub fn judge(inner: &ClaimResult) -> Evidence {
    let verdict = match inner.verdict {
        Verdict::Refuted => Verdict::Holds,
        Verdict::Holds | Verdict::Proved => Verdict::Refuted,
        _ => Verdict::Inconclusive,
    };
    Evidence {
        residuals: inner.residuals.clone(),
        loss_bits: inner.loss_bits,
        samples: inner.samples,
        failures: inner.failures.clone(),
        counterexample: inner.counterexample.clone(),
        exact: inner.exact.clone(),
        ..Evidence::new(
            verdict,
            format!("inner claim {}: {}", inner.verdict.name(), inner.reason),
        )
    }
}
