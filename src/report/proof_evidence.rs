//! The symbolic proof of a claim as shown in the reports: its steps and what it rests on
//! (symbols, relations, hypotheses, cases), or why there is none.  Times are left out, so the
//! reports stay byte-identical from run to run.

use crate::claims::verdict::ProofInfo;
use std::fmt::Write;

/// The proof paragraph of one claim (empty for claims that are not identities).
/// `prose` renders the catalogue's prose (a hypothesis' statement, its mathematics as
/// LaTeX in `$…$`) as Markdown.
pub fn proof_block(p: &ProofInfo, prose: &dyn Fn(&str) -> String) -> String {
    let mut s = String::new();
    if p.method == crate::claims::verdict::ProofMethod::Interval {
        let why = p.reason.as_deref().unwrap_or_default();
        let _ = writeln!(s, "Interval certificate: {}.\n", why.trim_end_matches('.'));
        if !p.notes.is_empty() {
            let shown: Vec<String> = p.notes.iter().map(|x| format!("`{x}`")).collect();
            let _ = writeln!(s, "- certified enclosures: {}\n", shown.join("; "));
        }
        return s;
    }
    if let Some(r) = &p.reason {
        if let Some(why) = r.strip_prefix(crate::claims::verdict::proof_info::NO_INTERVAL) {
            let _ = writeln!(
                s,
                "Interval certificate: none — {}.\n",
                why.trim_end_matches('.')
            );
            return s;
        }
        if r != "a definition"
            && r != "only identities and independence claims are proved symbolically"
        {
            let _ = writeln!(s, "Symbolic proof: none — {}.\n", r.trim_end_matches('.'));
        }
        return s;
    }
    let size = if p.terms > 0 {
        format!(" (numerators of {} terms)", p.terms)
    } else {
        String::new()
    };
    let _ = writeln!(
        s,
        "Symbolic proof: the normal form of lhs − rhs is 0{size}.\n"
    );
    let items = |s: &mut String, title: &str, xs: &[String]| {
        if !xs.is_empty() {
            let shown: Vec<String> = xs.iter().map(|x| format!("`{x}`")).collect();
            let _ = writeln!(s, "- {title}: {}", shown.join("; "));
        }
    };
    if !p.notes.is_empty() {
        let _ = writeln!(s, "- steps: {}", p.notes.join("; "));
    }
    items(&mut s, "cases", &p.cases);
    items(&mut s, "symbols", &p.symbols);
    items(&mut s, "relations", &p.relations);
    if let Some(par) = &p.parametrization {
        let _ = writeln!(s, "- domain parametrized by positive parameters: `{par}`");
    }
    items(
        &mut s,
        "signs proved (every coefficient of one sign after substituting the parametrization; a root of a radicand proved positive is its positive root)",
        &p.proved_signs,
    );
    if !p.hypotheses.is_empty() {
        // a hypothesis of the catalogue is prose; a lemma's statement is an expression
        let shown: Vec<String> = (p.hypotheses.iter())
            .map(|h| match h.kind {
                "lemma" => format!("`{}`", h.line()),
                kind => format!("{} [{kind}: `{}`]", prose(&h.statement), h.source),
            })
            .collect();
        let _ = writeln!(
            s,
            "- hypotheses (stated by the claim, quoted from the paper; lemmas proved separately): {}",
            shown.join("; ")
        );
    }
    s.push('\n');
    s
}
