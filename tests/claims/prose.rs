//! The catalogue's prose writes its mathematics as LaTeX inside `$…$`, in the paper's
//! notation, since the reports render it as Markdown with math: every claim's `location`
//! and `note`, every description of a sampled variable (the third string of a `vars`
//! entry, a claim's or a domain's), every `construction` after the map's name that
//! begins it, and every hypothesis' `statement` and `paper` quotation; and every sampled
//! variable has a description.  Outside `$…$` and code
//! spans (`` `step_gamma1` ``), after the paper's equation labels in parentheses
//! (`(ET v)`, `(impl spec 1-3)`), a field may not contain ASCII
//! mathematics: no `^ _ = < > | * + \` or `->`, no Greek letter or elliptic function
//! spelt out (`phi`, `sn`), no single-letter variable (`h`; the article `a`, `A` aside), no
//! name with an index (`M1`, `u0`), no short function call (`O(h)`, `det(`) and no
//! fraction of numbers (`1/B`).  The failing test lists every field that still does, with
//! the count.

use eulertop::bindings::euler_top::registry;
use eulertop::claims::catalogue::{Catalogue, load_dir};
use std::path::Path;

const GREEK: &[&str] = &[
    "alpha", "beta", "gamma", "delta", "epsilon", "eps", "kappa", "lambda", "lam", "mu", "nu",
    "rho", "sigma", "phi", "psi", "omega", "theta", "pi", "Delta", "Gamma", "Phi", "Psi", "Omega",
    "Pi",
];
const FUNCTIONS: &[&str] = &[
    "sn", "cn", "dn", "det", "tr", "sqrt", "sin", "cos", "tanh", "sech", "cosh", "am",
];
/// Catalogue names of the paper's quantities, which prose quotes as code.
const NAMES: &[&str] = &["Mh", "Msq", "kK"];

/// The text outside `$…$` and code spans (each replaced by a space), or `None` when a `$`
/// or a backtick is left open.
fn outside_math(s: &str) -> Option<String> {
    let mut out = String::new();
    let mut open: Option<char> = None;
    for c in s.chars() {
        match open {
            None if c == '$' || c == '`' => {
                open = Some(c);
                out.push(' ');
            }
            None => out.push(c),
            Some(o) if o == c => open = None,
            Some(_) => {}
        }
    }
    open.is_none().then_some(out)
}

/// Removes what is prose although it looks like mathematics: the paper's labels in
/// parentheses (and ranges `(impl spec 1-3)` of numbered ones) and abbreviations.
fn without_labels(mut t: String, labels: &[String]) -> String {
    for l in labels {
        t = t.replace(&format!("({l})"), " ");
        if let Some(base) = l.strip_suffix(" 1") {
            t = t.replace(&format!("({base} 1-3)"), " ");
        }
    }
    for a in ["i.e.", "e.g.", "w.r.t."] {
        t = t.replace(a, " ");
    }
    t
}

/// Is the word `w`, found at `at` in `t`, mathematics?
fn math_word(t: &str, w: &str, at: usize) -> bool {
    let after = &t[at + w.len()..];
    let letters = w.chars().all(|c| c.is_ascii_alphabetic());
    let article = w == "a"
        || (w == "A"
            && (t[..at].trim_end().is_empty()
                || t[..at].ends_with(". ")
                || after.starts_with(' ')
                    && after[1..].starts_with(|c: char| c.is_ascii_lowercase())));
    let digits_at = w.find(|c: char| c.is_ascii_digit());
    let indexed = match digits_at {
        // letters then digits (`M1`, `u0`)
        Some(j) if j > 0 => w[j..].chars().all(|c| c.is_ascii_digit()),
        // digits then letters (`2K`), a matrix size (`3x3`) aside
        Some(0) => {
            let k = w.find(|c: char| !c.is_ascii_digit()).unwrap_or(w.len());
            k < w.len() && !(w[k..].starts_with('x') && w[k + 1..].parse::<u32>().is_ok())
        }
        _ => false,
    };
    GREEK.contains(&w)
        || FUNCTIONS.contains(&w)
        || NAMES.contains(&w)
        || (w.len() == 1 && letters && !article)
        || indexed
        || (letters && w.len() <= 3 && after.starts_with('('))
}

/// The ASCII mathematics of one prose field (empty when there is none).
fn ascii_math(s: &str, labels: &[String]) -> Vec<String> {
    let Some(t) = outside_math(s) else {
        return vec!["an unclosed $ or `".into()];
    };
    let t = without_labels(t, labels);
    let mut found: Vec<String> = Vec::new();
    for c in "^_=<>|*+\\".chars().filter(|&c| t.contains(c)) {
        found.push(c.to_string());
    }
    if t.contains("->") {
        found.push("->".into());
    }
    let b = t.as_bytes();
    for (j, _) in t.match_indices('/') {
        let digit = |k: Option<usize>| k.and_then(|k| b.get(k)).is_some_and(u8::is_ascii_digit);
        if digit(j.checked_sub(1)) || digit(Some(j + 1)) {
            found.push("a fraction".into());
        }
    }
    let is_word = |c: char| c.is_ascii_alphanumeric() || c == '\'';
    let mut start: Option<usize> = None;
    for (j, c) in t.char_indices().chain([(t.len(), ' ')]) {
        match (start, is_word(c)) {
            (None, true) => start = Some(j),
            (Some(s0), false) => {
                start = None;
                let piece = t[s0..j].trim_start_matches('\'');
                let at = s0 + (t[s0..j].len() - piece.len());
                let w = piece
                    .strip_suffix("'s")
                    .unwrap_or(piece)
                    .trim_end_matches('\'');
                if !w.is_empty() && math_word(&t, w, at) {
                    found.push(w.to_string());
                }
            }
            _ => {}
        }
    }
    found.sort();
    found.dedup();
    found
}

/// Every prose field of the catalogue: (where, text).
fn prose_fields(cat: &Catalogue) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for c in &cat.claims {
        out.push((format!("{} location", c.id), c.location.clone()));
        if let Some(n) = &c.note {
            out.push((format!("{} note", c.id), n.clone()));
        }
        if let Some(why) = &c.construction {
            // the first word names the map (the certificate recheck reads it)
            let prose = why.split_once(' ').map_or("", |(_, rest)| rest);
            out.push((format!("{} construction", c.id), prose.to_string()));
        }
        for (name, about) in &c.var_about {
            out.push((format!("{} variable {name}", c.id), about.clone()));
        }
    }
    for (d, dom) in &cat.domains {
        for (name, about) in &dom.about {
            out.push((format!("domain {d} variable {name}"), about.clone()));
        }
    }
    for (name, h) in &cat.hypotheses {
        out.push((format!("hypothesis {name} statement"), h.statement.clone()));
        out.push((format!("hypothesis {name} paper"), h.paper.clone()));
    }
    out
}

#[test]
fn the_catalogue_prose_writes_its_mathematics_in_latex() {
    let cat = load_dir(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("identities"),
        registry().unwrap(),
    )
    .unwrap_or_else(|e| panic!("catalogue does not load:\n{e}"));
    let labels = cat.paper.as_ref().expect("a [paper] table").labels.clone();
    let fields = prose_fields(&cat);
    let bad: Vec<String> = fields
        .iter()
        .filter_map(|(at, text)| {
            let found = ascii_math(text, &labels);
            (!found.is_empty()).then(|| format!("{at}: {found:?}: {text}"))
        })
        .collect();
    assert!(
        bad.is_empty(),
        "{} of {} prose fields write mathematics in ASCII:\n{}",
        bad.len(),
        fields.len(),
        bad.join("\n")
    );
}

#[test]
fn every_sampled_variable_says_what_it_is() {
    let cat = load_dir(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("identities"),
        registry().unwrap(),
    )
    .unwrap_or_else(|e| panic!("catalogue does not load:\n{e}"));
    let mut bare: Vec<String> = Vec::new();
    let mut all = 0;
    for c in &cat.claims {
        for (name, _) in &c.vars {
            all += 1;
            if !c.var_about.contains_key(name) {
                bare.push(format!("{} variable {name}", c.id));
            }
        }
    }
    for (d, dom) in &cat.domains {
        for (name, _) in &dom.vars {
            all += 1;
            if !dom.about.contains_key(name) {
                bare.push(format!("domain {d} variable {name}"));
            }
        }
    }
    assert!(
        bare.is_empty(),
        "{} of {all} sampled variables have no description (the third string of their `vars` entry):\n{}",
        bare.len(),
        bare.join("\n")
    );
}

#[test]
fn ascii_mathematics_is_found_and_latex_is_not() {
    let labels = vec!["ET v".to_string(), "impl spec 1".to_string()];
    for ascii in [
        "Section 2: M^2 is a Casimir",
        "the separatrix E/M^2 = 1/B",
        "with rho of (rokappa)",
        "for h small",
        "the point u0",
        "so it is O(h)",
        "Mh x Omega(Mh)",
        "a shift by 2K",
        "an unclosed $M^2",
    ] {
        assert!(!ascii_math(ascii, &labels).is_empty(), "{ascii}");
    }
    for latex in [
        "Section 2: $M^2$ is a Casimir",
        "A map (ET v) of (impl spec 1-3) with `step_gamma1`, i.e. Euler's",
        "Section 8, (Lax 3x3): $\\wM\\times\\bOm(\\wM)$, the model's $\\omega$",
        "DLMF 22.8.1-3 and sum/difference formulas, where $A > B$",
    ] {
        assert_eq!(ascii_math(latex, &labels), Vec::<String>::new(), "{latex}");
    }
}
