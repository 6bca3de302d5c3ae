//! The small formatted pieces that every report page uses: the verdict badge, residuals,
//! a claim's anchor and a printed excerpt as Markdown.

use super::ReportInput;
use super::tex::{display_math, is_prose, prose};
use crate::claims::verdict::{ClaimResult, Rung, Verdict};

/// The verdict as a symbol and a word.
pub fn verdict_badge(v: Verdict) -> &'static str {
    match v {
        Verdict::Holds => "✓ holds",
        Verdict::Proved => "✓✓ proved (symbolic)",
        Verdict::Construction => "≡ by construction",
        Verdict::Refuted => "✗ refuted",
        Verdict::Inconclusive => "? inconclusive",
        Verdict::Defined => "≔ definition",
    }
}

/// A claim's verdict badge: as [`verdict_badge`], with a refutation certified at an
/// exact point (proof method `witness`) marked `✗✗` apart from a sampled one, and a
/// negation proved by such a point marked `proved (witness)`, a claim proved by exact
/// power series marked `proved (power series)`, one proved by the ODE method marked
/// `proved (ODE)`, and an existence claim whose sampled
/// solutions are certified by the Krawczyk test marked `holds (roots certified at the
/// samples)`.
pub fn result_badge(r: &ClaimResult) -> &'static str {
    use crate::claims::verdict::ProofMethod;
    let witness = r.proof.method == ProofMethod::Witness;
    match r.verdict {
        Verdict::Refuted if witness => return "✗✗ refuted (witness)",
        Verdict::Proved if witness => return "✓✓ proved (witness)",
        Verdict::Proved if r.proof.method == ProofMethod::Series => {
            return "✓✓ proved (power series)";
        }
        Verdict::Proved if r.proof.method == ProofMethod::Ode => return "✓✓ proved (ODE)",
        Verdict::Holds if r.proof.method == ProofMethod::Interval => {
            return "✓ holds (roots certified at the samples)";
        }
        _ => {}
    }
    verdict_badge(r.verdict)
}

/// A residual as `2^-n` (or `0`), with two significant digits of the mantissa.
pub fn fmt_residual(r: &Rung) -> String {
    if let Rung::Slope { slope, .. } = r {
        return format!("slope {slope:.3}");
    }
    match r.log2() {
        None => "0 (exact)".to_string(),
        Some(l) => format!("2^{:.1}", l),
    }
}

/// The smallest residual over the ladder (best agreement), formatted.
pub fn best_residual(r: &ClaimResult) -> String {
    if r.verdict == Verdict::Defined {
        return "—".to_string();
    }
    if r.residuals.iter().any(Rung::is_slope) {
        return r
            .residuals
            .last()
            .map(fmt_residual)
            .unwrap_or_else(|| "—".into());
    }
    let mut best: Option<&Rung> = None;
    for x in &r.residuals {
        let better = match (best, x.log2()) {
            (None, _) => true,
            (Some(b), Some(l)) => b.log2().is_some_and(|bl| l < bl),
            (Some(b), None) => b.log2().is_some(),
        };
        if better {
            best = Some(x);
        }
    }
    best.map(|x| format!("{} at {} bits", fmt_residual(x), x.bits()))
        .unwrap_or_else(|| "—".into())
}

/// A stable HTML anchor for a claim id.
pub fn anchor(id: &str) -> String {
    id.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .collect()
}

/// A printed excerpt as Markdown: prose as a quote with inline math, a formula as a `$$`
/// block (followed by a blank line).
pub fn printed_markdown(input: &ReportInput, printed: &str) -> String {
    if is_prose(printed) {
        format!("> {}\n\n", prose(printed, &input.macros))
    } else {
        format!("$$\n{}\n$$\n\n", display_math(printed, &input.macros))
    }
}
