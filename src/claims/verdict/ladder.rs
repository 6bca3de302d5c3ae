//! The precision-ladder rule.
//!
//! Residual of a sample at precision p: |lhs − rhs| / max(|lhs|, |rhs|, S), kept as
//! log2.  r_p = max over samples; g = max_p (p + log2 r_p) is the number of bits lost to
//! conditioning.
//! * holds: g ≤ max_loss_bits;
//! * refuted: r_p ≥ 2^(−refute_floor_bits) at every [judged] rung;
//! * inconclusive: otherwise.
//!
//! The judged rungs — those of at least 128 bits, or all when there are none — are the
//! same for every kind (asymptotic claims judge their slopes on them too).

use super::context::{Sample, Sides, named};
use super::result::{Counterexample, Evidence, FailedSample, Rung};
use crate::claims::catalogue::Claim;
use crate::claims::kind::Verdict;

/// The rung from which residuals are trusted to show whether a claim is false.
pub const JUDGED_FROM_BITS: u32 = 128;

/// The rungs a verdict is judged on: those of at least [`JUDGED_FROM_BITS`] bits, or all
/// of them when there are none.
pub fn judged<R>(rungs: &[R], bits: impl Fn(&R) -> u32) -> Vec<&R> {
    if rungs.iter().any(|r| bits(r) >= JUDGED_FROM_BITS) {
        rungs
            .iter()
            .filter(|r| bits(r) >= JUDGED_FROM_BITS)
            .collect()
    } else {
        rungs.iter().collect()
    }
}

/// The worst sample at one rung.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Worst {
    /// Precision in bits.
    pub bits: u32,
    /// Its value (log2 residual, or slope).
    pub value: f64,
    /// Index of the sample.
    pub sample: usize,
}

/// Per rung, the sample with the largest log2 residual.
pub fn worst_residuals<P>(bits: &[u32], samples: &[Sample<P, Sides>]) -> Vec<Worst> {
    bits.iter()
        .enumerate()
        .map(|(j, &b)| {
            let mut best = (f64::NEG_INFINITY, 0usize);
            for (i, s) in samples.iter().enumerate() {
                if i == 0 || s.rungs[j].log2 > best.0 {
                    best = (s.rungs[j].log2, i);
                }
            }
            Worst {
                bits: b,
                value: best.0,
                sample: best.1,
            }
        })
        .collect()
}

/// Which rungs were judged, in words: "at every rung ≥ 128 bits", or, when none of them
/// reaches [`JUDGED_FROM_BITS`], the rungs that were run.
fn judged_phrase(judged: &[&Worst]) -> String {
    if judged.iter().any(|w| w.bits >= JUDGED_FROM_BITS) {
        return format!("at every rung ≥ {JUDGED_FROM_BITS} bits");
    }
    let list: Vec<String> = judged.iter().map(|w| w.bits.to_string()).collect();
    format!(
        "at every rung run ({} bits; none of {JUDGED_FROM_BITS} bits or more)",
        list.join(", ")
    )
}

/// The ladder verdict from the worst residual per rung: (verdict, g, reason).
pub fn verdict(
    worst: &[Worst],
    max_loss_bits: f64,
    refute_floor_bits: f64,
) -> (Verdict, f64, String) {
    let g = worst
        .iter()
        .map(|w| f64::from(w.bits) + w.value)
        .fold(f64::NEG_INFINITY, f64::max);
    let g_rep = if g.is_finite() { g.max(0.0) } else { 0.0 };
    if g <= max_loss_bits {
        let reason = format!("residual ≤ 2^(−p+{g_rep:.1}) at every rung (bound {max_loss_bits})");
        return (Verdict::Holds, g_rep, reason);
    }
    let judged = judged(worst, |w| w.bits);
    if !judged.is_empty() && judged.iter().all(|w| w.value >= -refute_floor_bits) {
        let reason = format!(
            "residual ≥ 2^-{refute_floor_bits} {}: it does not shrink with precision",
            judged_phrase(&judged)
        );
        return (Verdict::Refuted, g_rep, reason);
    }
    let reason = format!(
        "residual neither within 2^(−p+{max_loss_bits}) at every rung nor above 2^-{refute_floor_bits} {} (g = {g_rep:.1})",
        judged_phrase(&judged)
    );
    (Verdict::Inconclusive, g_rep, reason)
}

/// The evidence of a residual ladder: rungs, g, verdict, and for a refutation the sample
/// with the largest residual at the highest rung.
pub fn finish<P>(
    claim: &Claim,
    bits: &[u32],
    samples: &[Sample<P, Sides>],
    failures: Vec<FailedSample>,
) -> Evidence {
    let worst = worst_residuals(bits, samples);
    let (v, g, reason) = verdict(&worst, claim.max_loss_bits, claim.refute_floor_bits);
    let counterexample = if v == Verdict::Refuted {
        counterexample(&worst, samples)
    } else {
        None
    };
    Evidence {
        residuals: worst
            .iter()
            .map(|w| Rung::Residual {
                bits: w.bits,
                log2: w.value,
            })
            .collect(),
        loss_bits: Some(g),
        samples: samples.len(),
        failures,
        counterexample,
        ..Evidence::new(v, reason)
    }
}

fn counterexample<P>(worst: &[Worst], samples: &[Sample<P, Sides>]) -> Option<Counterexample> {
    let j = worst.len().checked_sub(1)?;
    let w = worst[j];
    let s = samples.get(w.sample)?;
    Some(Counterexample {
        bits: w.bits,
        point: named(&s.point),
        lhs: s.rungs[j].lhs.clone(),
        rhs: s.rungs[j].rhs.clone(),
        log2_residual: if w.value.is_finite() {
            Some(w.value)
        } else {
            None
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rungs(values: &[(u32, f64)]) -> Vec<Worst> {
        values
            .iter()
            .map(|&(bits, value)| Worst {
                bits,
                value,
                sample: 0,
            })
            .collect()
    }

    #[test]
    fn judged_rungs_are_those_from_128_bits_or_all() {
        let w = rungs(&[(53, 0.0), (128, 0.0), (256, 0.0)]);
        let j: Vec<u32> = judged(&w, |w| w.bits).iter().map(|w| w.bits).collect();
        assert_eq!(j, vec![128, 256]);
        let w = rungs(&[(53, 0.0), (64, 0.0)]);
        assert_eq!(judged(&w, |w| w.bits).len(), 2);
        assert!(judged(&rungs(&[]), |w| w.bits).is_empty());
    }

    #[test]
    fn a_residual_tracking_the_precision_holds() {
        // r_p = 2^(−p+3): g = 3
        let w = rungs(&[(53, -50.0), (128, -125.0), (256, -253.0)]);
        let (v, g, _) = verdict(&w, 24.0, 30.0);
        assert_eq!((v, g), (Verdict::Holds, 3.0));
    }

    #[test]
    fn a_residual_that_does_not_shrink_is_refuted() {
        // 2^-10 at every rung: the 53-bit rung is not judged, so its value is irrelevant
        let w = rungs(&[(53, -60.0), (128, -10.0), (256, -10.0)]);
        assert_eq!(verdict(&w, 24.0, 30.0).0, Verdict::Refuted);
        let (v, _, reason) = verdict(&rungs(&[(53, -10.0), (64, -10.0)]), 24.0, 30.0);
        assert_eq!(v, Verdict::Refuted);
        assert!(
            reason.contains("(53, 64 bits; none of 128 bits or more)"),
            "{reason}"
        );
        assert!(!reason.contains("≥ 128"), "{reason}");
    }

    #[test]
    fn a_small_constant_discrepancy_is_inconclusive() {
        // 2^-80 from 128 bits on: above 2^(−p+24), below the floor 2^-30
        let w = rungs(&[(53, -53.0), (128, -80.0), (256, -80.0)]);
        let (v, g, _) = verdict(&w, 24.0, 30.0);
        assert_eq!((v, g), (Verdict::Inconclusive, 176.0));
    }

    #[test]
    fn exact_zeros_hold_with_no_loss() {
        let w = rungs(&[(53, f64::NEG_INFINITY), (128, f64::NEG_INFINITY)]);
        assert_eq!(
            verdict(&w, 24.0, 30.0),
            (
                Verdict::Holds,
                0.0,
                "residual ≤ 2^(−p+0.0) at every rung (bound 24)".into()
            )
        );
    }
}
