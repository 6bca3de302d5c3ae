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
        Some(l) => format!("$2^{{{l:.1}}}$"),
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

/// The exponent written after `^` at the start of `rest`: a parenthesized group, a signed
/// decimal number or one letter.  Returns (the exponent as LaTeX, bytes consumed).
fn exponent(rest: &str) -> Option<(String, usize)> {
    if let Some(inner) = rest.strip_prefix('(') {
        let end = inner.find(')')?;
        let body = &inner[..end];
        let plain = body
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "+-−.*/ ".contains(c));
        return plain.then(|| (body.replace('−', "-"), end + 2));
    }
    let mut n = 0;
    let mut chars = rest.char_indices().peekable();
    if let Some(&(_, c)) = chars.peek().filter(|(_, c)| *c == '-' || *c == '−') {
        n += c.len_utf8();
        chars.next();
    }
    let digits: usize = chars
        .take_while(|(_, c)| c.is_ascii_digit() || *c == '.')
        .map(|(_, c)| c.len_utf8())
        .sum();
    let digits = rest[n..n + digits].trim_end_matches('.').len();
    if digits > 0 {
        return Some((rest[..n + digits].replace('−', "-"), n + digits));
    }
    let tail = &rest[n..];
    tail.chars().next().filter(char::is_ascii_alphabetic)?;
    let after = tail[1..].chars().next();
    (!after.is_some_and(|c| c.is_ascii_alphanumeric()))
        .then(|| (rest[..n + 1].replace('−', "-"), n + 1))
}

/// Prose with its powers of 2 and of h (`2^-30`, `2^(−p+1.5)`, `h^e`) written as LaTeX
/// (`$2^{-30}$`), outside code spans and existing math.
pub fn tex_powers(s: &str) -> String {
    let mut out = String::new();
    let mut quoted: Option<char> = None;
    let mut j = 0;
    while j < s.len() {
        let c = s[j..].chars().next().unwrap_or(' ');
        if c == '`' || c == '$' {
            quoted = match quoted {
                Some(q) if q == c => None,
                None => Some(c),
                q => q,
            };
        }
        let base_ok = (c == '2' || c == 'h')
            && quoted.is_none()
            && s[j + 1..].starts_with('^')
            && !s[..j]
                .chars()
                .next_back()
                .is_some_and(|p| p.is_alphanumeric() || p == '.');
        if base_ok && let Some((e, used)) = exponent(&s[j + 2..]) {
            out.push_str(&format!("${c}^{{{e}}}$"));
            j += 2 + used;
            continue;
        }
        out.push(c);
        j += c.len_utf8();
    }
    out
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

#[cfg(test)]
mod tests {
    use super::tex_powers;

    #[test]
    fn powers_in_prose_become_latex() {
        assert_eq!(
            tex_powers("residual ≤ 2^(−p+1.5) at every rung, above 2^-30."),
            "residual ≤ $2^{-p+1.5}$ at every rung, above $2^{-30}$."
        );
        assert_eq!(
            tex_powers("the coefficient of h^1, h^e with e < 1.5; 2^−p"),
            "the coefficient of $h^{1}$, $h^{e}$ with e < 1.5; $2^{-p}$"
        );
        // code, math, other bases and names are left alone
        for s in [
            "`2^-30`",
            "$2^{-30}$",
            "M^2 and k^2",
            "x2^3",
            "h^ab",
            "2^(sqrt(x))",
        ] {
            assert_eq!(tex_powers(s), s);
        }
    }
}
