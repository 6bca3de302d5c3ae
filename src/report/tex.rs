//! Makes the paper's LaTeX fit for Markdown math (GitHub's MathJax, KaTeX): expands the
//! paper's own zero-argument macros (a table that the catalogue supplies), turns
//! `eqnarray` into `array`, drops `\label`, `\nonumber` and `\raisebox`, and renders prose
//! statements (text with `$…$`) as Markdown with inline math.

use std::collections::BTreeMap;

/// Expands zero-argument macros `\name` (not followed by a letter) using `macros`
/// (name without backslash → replacement), repeatedly, so replacements may use others.
pub fn expand_macros(src: &str, macros: &BTreeMap<String, String>) -> String {
    let mut s = src.to_string();
    for _ in 0..4 {
        let mut out = String::with_capacity(s.len());
        let b = s.as_bytes();
        let mut i = 0;
        let mut changed = false;
        while i < b.len() {
            if b[i] == b'\\' {
                let mut j = i + 1;
                while j < b.len() && b[j].is_ascii_alphabetic() {
                    j += 1;
                }
                if j > i + 1
                    && let Some(rep) = macros.get(&s[i + 1..j])
                {
                    out.push_str(rep);
                    changed = true;
                    i = j;
                    continue;
                }
                // copy the backslash and the following char (keeps `\\` intact)
                out.push('\\');
                if i + 1 < b.len() {
                    let ch = s[i + 1..].chars().next().unwrap_or(' ');
                    out.push(ch);
                    i += 1 + ch.len_utf8();
                } else {
                    i += 1;
                }
                continue;
            }
            let ch = s[i..].chars().next().unwrap_or(' ');
            out.push(ch);
            i += ch.len_utf8();
        }
        s = out;
        if !changed {
            break;
        }
    }
    s
}

/// Removes `\cmd{…}` (with balanced braces) entirely.
fn drop_command(s: &str, cmd: &str) -> String {
    let pat = format!("\\{cmd}{{");
    let mut out = String::new();
    let mut rest = s;
    while let Some(p) = rest.find(&pat) {
        out.push_str(&rest[..p]);
        let after = &rest[p + pat.len()..];
        match balanced_end(after) {
            Some(e) => rest = &after[e + 1..],
            None => {
                out.push_str(&rest[p..]);
                rest = "";
            }
        }
    }
    out.push_str(rest);
    out
}

/// Index of the `}` closing an already-opened group at the start of `s`.
fn balanced_end(s: &str) -> Option<usize> {
    let mut depth = 1;
    for (k, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(k);
                }
            }
            _ => {}
        }
    }
    None
}

/// `\raisebox{len}{$X$}` → `X`.
fn strip_raisebox(s: &str) -> String {
    let pat = "\\raisebox{";
    let mut out = String::new();
    let mut rest = s;
    while let Some(p) = rest.find(pat) {
        out.push_str(&rest[..p]);
        let after = &rest[p + pat.len()..];
        let Some(e1) = balanced_end(after) else {
            out.push_str(&rest[p..]);
            rest = "";
            break;
        };
        let tail = after[e1 + 1..].trim_start();
        let Some(body) = tail.strip_prefix('{') else {
            rest = tail;
            continue;
        };
        let Some(e2) = balanced_end(body) else {
            out.push_str(tail);
            rest = "";
            break;
        };
        let inner = body[..e2].trim().trim_matches('$');
        out.push_str(inner);
        rest = &body[e2 + 1..];
    }
    out.push_str(rest);
    out
}

/// Display math for a printed formula: macros expanded, `eqnarray`/`equation` environments
/// turned into `array`, labels and `\nonumber` removed, no blank lines.
pub fn display_math(src: &str, macros: &BTreeMap<String, String>) -> String {
    // `\qed` first: the paper's macro would expand it to a `\rule`
    let mut s = expand_macros(&src.replace("\\qed", ""), macros);
    s = drop_command(&s, "label");
    s = strip_raisebox(&s);
    s = s.replace("\\nonumber", "");
    s = s.replace("\\begin{eqnarray}", "\\begin{array}{rcl}");
    s = s.replace("\\end{eqnarray}", "\\end{array}");
    s = s
        .replace("\\begin{equation}", "")
        .replace("\\end{equation}", "");
    s = s.replace("\\[", "").replace("\\]", "");
    // no blank lines inside a math block; collapse "\\ \\" produced by removed \nonumber
    let lines: Vec<&str> = s
        .lines()
        .map(str::trim_end)
        .filter(|l| !l.trim().is_empty())
        .collect();
    let mut joined = lines.join("\n");
    while joined.contains("\\\\ \\\\") {
        joined = joined.replace("\\\\ \\\\", "\\\\");
    }
    while joined.contains("\\\\\n\\\\") {
        joined = joined.replace("\\\\\n\\\\", "\\\\");
    }
    let body = joined.trim().trim_end_matches('.').to_string();
    // rows of an eqnarray printed without their environment: give them one
    if body.contains('&') && !body.contains("\\begin{") {
        return format!("\\begin{{array}}{{rcl}}\n{body}\n\\end{{array}}");
    }
    body
}

/// Is this printed text prose (a statement with inline `$…$`) rather than a formula?
pub fn is_prose(src: &str) -> bool {
    // a `$` inside `\raisebox{..}{$…$}` belongs to a formula, not to prose
    strip_raisebox(src).contains('$')
}

/// Split prose into (is_math, text) segments; the delimiters `$`, `$$`, `\[`, `\]` stay with
/// their math segment.
fn split_math(src: &str) -> Vec<(bool, String)> {
    let mut segs: Vec<(bool, String)> = Vec::new();
    let mut cur = String::new();
    let mut close: Option<&str> = None; // the delimiter that ends the current math segment
    let mut i = 0;
    while i < src.len() {
        let rest = &src[i..];
        let opener = ["$$", "$", "\\["]
            .into_iter()
            .find(|d| close.is_none() && rest.starts_with(d));
        if let Some(d) = opener {
            if !cur.is_empty() {
                segs.push((false, std::mem::take(&mut cur)));
            }
            cur.push_str(d);
            close = Some(if d == "\\[" { "\\]" } else { d });
            i += d.len();
            continue;
        }
        if let Some(d) = close.filter(|d| rest.starts_with(d)) {
            cur.push_str(d);
            segs.push((true, std::mem::take(&mut cur)));
            close = None;
            i += d.len();
            continue;
        }
        let c = rest.chars().next().unwrap_or(' ');
        cur.push(c);
        i += c.len_utf8();
    }
    if !cur.is_empty() {
        segs.push((close.is_some(), cur));
    }
    segs
}

/// Prose statement → Markdown: inline math kept as `$…$` (macros expanded), `\ref{x}` →
/// `(x)`, `{\rm …}`/`{\it …}` unwrapped, LaTeX line breaks and spacing normalised.
pub fn prose(src: &str, macros: &BTreeMap<String, String>) -> String {
    // `\qed` first: the paper's macro would expand it to a `\rule`
    let mut s = expand_macros(&src.replace("\\qed", ""), macros);
    s = drop_command(&s, "label");
    s = strip_raisebox(&s);
    // \ref{x} → (x)
    let mut out = String::new();
    let mut rest = s.as_str();
    while let Some(p) = rest.find("\\ref{") {
        out.push_str(&rest[..p]);
        let after = &rest[p + 5..];
        match after.find('}') {
            Some(e) => {
                out.push_str(&after[..e]);
                rest = &after[e + 1..];
            }
            None => {
                rest = after;
            }
        }
    }
    out.push_str(rest);
    // text between the math segments: unwrap `{\rm …}` etc., drop the now-unbalanced braces;
    // math (`$…$`, `$$…$$`, `\[…\]`) is kept verbatim (`{\rm I}` is valid there)
    let mut res = String::new();
    for (is_math, seg) in split_math(&out) {
        if is_math {
            res.push_str(&seg);
            continue;
        }
        let mut t = seg;
        for (a, b) in [
            ("{\\rm(", "("),
            ("{\\rm (", "("),
            ("{\\it ", ""),
            ("{\\rm ", ""),
            ("{\\bf ", ""),
            ("{\\em ", ""),
            ("\\\\", " "),
            ("~", " "),
            ("--", "–"),
        ] {
            t = t.replace(a, b);
        }
        t.retain(|c| c != '{' && c != '}');
        res.push_str(&t);
    }
    // display math inside prose (`$$…$$` or `\[…\]`) stays; collapse whitespace
    res.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The catalogue's own prose (a claim's `location` and `note`, a variable's description)
/// → Markdown: the paper's macros expanded inside its `$…$` math only (the text around
/// it, code spans included, stays as written), whitespace collapsed to single spaces.
pub fn inline_math(src: &str, macros: &BTreeMap<String, String>) -> String {
    let mut res = String::new();
    for (is_math, seg) in split_math(src) {
        if is_math {
            res.push_str(&expand_macros(&seg, macros));
        } else {
            res.push_str(&seg);
        }
    }
    res.split_whitespace().collect::<Vec<_>>().join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;
    fn m() -> BTreeMap<String, String> {
        let mut m = BTreeMap::new();
        m.insert("bM".into(), "{\\bf M}".into());
        m.insert("wM".into(), "\\widehat{\\bM}".into());
        m
    }
    #[test]
    fn expands_nested_macros_only_on_word_boundary() {
        assert_eq!(
            expand_macros("\\wM-\\bM\\bMx", &m()),
            "\\widehat{{\\bf M}}-{\\bf M}\\bMx"
        );
    }
    #[test]
    fn eqnarray_becomes_array() {
        let d = display_math(
            "\\begin{eqnarray}\\label{x}\na & = & b\\;,\\nonumber\\\\\nc&=&d\n\\end{eqnarray}",
            &m(),
        );
        assert!(d.starts_with("\\begin{array}{rcl}"));
        assert!(!d.contains("label") && !d.contains("nonumber"));
    }
    #[test]
    fn bare_alignment_rows_get_an_array() {
        let d = display_math("a & = & b", &m());
        assert_eq!(d, "\\begin{array}{rcl}\na & = & b\n\\end{array}");
    }
    #[test]
    fn raisebox_is_stripped() {
        assert_eq!(
            strip_raisebox("\\frac{\\raisebox{2mm}{$x+y$}}{z}"),
            "\\frac{x+y}{z}"
        );
    }
    #[test]
    fn inline_math_expands_macros_in_math_only() {
        assert_eq!(
            inline_math("the map\n  $\\wM = F(\\bM, h)$ of `\\bM`", &m()),
            "the map $\\widehat{{\\bf M}} = F({\\bf M}, h)$ of `\\bM`"
        );
    }
    #[test]
    fn prose_refs() {
        let p = prose(
            "Maps defined by {\\rm(\\ref{impl spec})} possess $M^2(\\bM)$.",
            &m(),
        );
        assert_eq!(p, "Maps defined by (impl spec) possess $M^2({\\bf M})$.");
    }
    #[test]
    fn prose_keeps_math_verbatim() {
        let mut mac = m();
        mac.insert("rW".into(), "{\\rm W}".into());
        let p = prose(
            "a unique {\\it matrix} $\\rW\\in{\\rm so}(3)$, and\n\\[\n\\omega=\\frac{\\gamma}{2}\\rW^2\n\\]",
            &mac,
        );
        assert_eq!(
            p,
            "a unique matrix ${\\rm W}\\in{\\rm so}(3)$, and \\[ \\omega=\\frac{\\gamma}{2}{\\rm W}^2 \\]"
        );
        mac.insert("qed".into(), "\\rule{3mm}{3mm}".into());
        assert!(!is_prose("\\sqrt{\\raisebox{-1mm}{$1-h^2$}}"));
        let q = prose("{\\bf Proof.} Follows for $h$ small. \\qed", &mac);
        assert_eq!(q, "Proof. Follows for $h$ small.");
    }
}
