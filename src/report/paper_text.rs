//! The printed statements and proofs of the paper's environments
//! (`identities/environments.tex`), rendered as Markdown with math.
//!
//! ```
//! use eulertop::report::paper_text::{parse, to_markdown};
//! use std::collections::BTreeMap;
//! let tex = "%% Lemma 1: statement\nThe set $S$ is\n\\[\nx=0\\;.\n\\]\n%% Lemma 1: proof\n{\\bf Proof.} Clear. \\qed\n";
//! let envs = parse(tex);
//! assert_eq!(envs["Lemma 1"].statement, "The set $S$ is\n\\[\nx=0\\;.\n\\]");
//! let md = to_markdown(&envs["Lemma 1"].statement, &BTreeMap::new());
//! assert_eq!(md, "The set $S$ is\n\n$$\nx=0\\;\n$$");
//! assert_eq!(to_markdown(envs["Lemma 1"].proof.as_deref().unwrap(), &BTreeMap::new()), "*Proof.* Clear. ∎");
//! ```

use super::tex::{display_math, prose};
use std::collections::BTreeMap;

/// One environment's printed text.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EnvironmentText {
    /// The statement, verbatim LaTeX.
    pub statement: String,
    /// The printed proof, if the paper prints one.
    pub proof: Option<String>,
}

/// Reads the parts `%% <environment>: statement` / `%% <environment>: proof`; lines before
/// the first part and other `%` comment lines are ignored.
pub fn parse(tex: &str) -> BTreeMap<String, EnvironmentText> {
    let mut out: BTreeMap<String, EnvironmentText> = BTreeMap::new();
    let mut current: Option<(String, bool)> = None;
    let mut buf: Vec<&str> = Vec::new();
    let mut flush = |cur: &Option<(String, bool)>, buf: &mut Vec<&str>| {
        if let Some((env, is_proof)) = cur {
            let text = buf.join("\n").trim().to_string();
            let e = out.entry(env.clone()).or_default();
            if *is_proof {
                e.proof = Some(text);
            } else {
                e.statement = text;
            }
        }
        buf.clear();
    };
    for line in tex.lines() {
        if let Some(head) = line.strip_prefix("%% ") {
            flush(&current, &mut buf);
            current = head
                .rsplit_once(": ")
                .and_then(|(env, part)| match part.trim() {
                    "statement" => Some((env.to_string(), false)),
                    "proof" => Some((env.to_string(), true)),
                    _ => None,
                });
            continue;
        }
        if current.is_some() && !line.starts_with('%') {
            buf.push(line);
        }
    }
    flush(&current, &mut buf);
    out
}

/// Display environments that become `$$ … $$` blocks: (opening, closing).
const DISPLAYS: [(&str, &str); 3] = [
    ("\\begin{equation}", "\\end{equation}"),
    ("\\begin{eqnarray}", "\\end{eqnarray}"),
    ("\\[", "\\]"),
];

/// Theorem-like wrappers and layout commands removed from the text.
fn strip_wrappers(src: &str) -> String {
    let mut s = src.to_string();
    for env in ["definition", "proposition", "lemma", "theorem", "appendix"] {
        s = s
            .replace(&format!("\\begin{{{env}}}"), "")
            .replace(&format!("\\end{{{env}}}"), "");
    }
    // `\vspace{..}` and a label directly after a removed `\begin{…}`
    let mut out = String::new();
    let mut rest = s.as_str();
    while let Some(p) = rest.find("\\vspace{") {
        out.push_str(&rest[..p]);
        rest = rest[p..].split_once('}').map_or("", |(_, r)| r);
    }
    out.push_str(rest);
    out.replace("{\\bf Proof.}", "*Proof.*")
        .replace("{\\bf Corollary.}", "*Corollary.*")
        .replace("\\qed", "∎")
}

/// Splits text into (is_display, text) pieces.
fn split_displays(src: &str) -> Vec<(bool, String)> {
    let mut out = Vec::new();
    let mut rest = src;
    loop {
        let next = DISPLAYS
            .iter()
            .filter_map(|(o, c)| rest.find(o).map(|p| (p, *o, *c)))
            .min_by_key(|(p, _, _)| *p);
        let Some((p, open, close)) = next else {
            out.push((false, rest.to_string()));
            return out;
        };
        let body_start = p + open.len();
        let Some(end) = rest[body_start..].find(close) else {
            out.push((false, rest.to_string()));
            return out;
        };
        out.push((false, rest[..p].to_string()));
        out.push((true, rest[p..body_start + end + close.len()].to_string()));
        rest = &rest[body_start + end + close.len()..];
    }
}

/// The printed LaTeX of a statement or proof as Markdown: prose paragraphs with inline
/// math, displays as `$$` blocks.
pub fn to_markdown(src: &str, macros: &BTreeMap<String, String>) -> String {
    let text = strip_wrappers(src);
    let mut blocks: Vec<String> = Vec::new();
    for (display, piece) in split_displays(&text) {
        if display {
            blocks.push(format!("$$\n{}\n$$", display_math(&piece, macros)));
            continue;
        }
        for para in piece.split("\n\n") {
            let p = prose(para, macros);
            if !p.is_empty() {
                blocks.push(p);
            }
        }
    }
    blocks.join("\n\n")
}
