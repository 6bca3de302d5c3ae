//! Finds claims as a reader names them: by claim id, by the paper's environment
//! ("Theorem 2": its statement claims), or by a paper label ("(gammaMV)" or "gammaMV":
//! the claims carrying it).  The environment names and labels are those of the loaded
//! catalogue; nothing here knows a particular paper.  A name that matches nothing gets
//! the closest ids, environments and labels by edit distance ([`NotFound`]).

use super::claim::{Catalogue, Claim};

/// Which claims of an environment a lookup by environment name selects.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scope {
    /// The claims of role `statement` (every claim of the environment when it has none).
    Statement,
    /// Every claim of the environment, proof steps and controls included.
    Whole,
}

/// Claims found for a name, in catalogue order.
#[derive(Debug)]
pub struct Selection<'a> {
    /// What the name was taken as: "claim ID", "Theorem 2 (statement)", "label (J)".
    pub what: String,
    /// The claims, in catalogue order.
    pub claims: Vec<&'a Claim>,
}

/// A name that is no claim id, environment or label, with the closest ones.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotFound {
    /// The name as given.
    pub query: String,
    /// The closest ids, environment names and labels (labels in parentheses).
    pub suggestions: Vec<String>,
}

impl std::fmt::Display for NotFound {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "no claim id, environment or label '{}' in the catalogue",
            self.query
        )?;
        if !self.suggestions.is_empty() {
            write!(f, "; did you mean {}?", self.suggestions.join(", "))?;
        }
        Ok(())
    }
}

impl std::error::Error for NotFound {}

/// The claims named by `query`: the claim with that id; else the environment of that
/// name (compared ignoring case and runs of spaces), its claims as `scope` says; else the
/// label, written with or without parentheses.  Otherwise [`NotFound`] with the closest
/// names.
///
/// ```
/// use eulertop::claims::catalogue::load_sources;
/// use eulertop::claims::catalogue::lookup::{find, Scope};
/// use eulertop::claims::registry::Registry;
/// let claim = |id: &str, role: &str| format!(r#"
/// [[claim]]
/// id = "{id}"
/// location = "anywhere"
/// printed = 'sin 2x = 2 sin x cos x'
/// environment = "Section 2"
/// role = "{role}"
/// labels = ["double"]
/// kind = "identity"
/// expect = "holds"
/// vars = [["x", "uniform(-3, 3)"]]
/// lhs = "sin(2*x)"
/// rhs = "2*sin(x)*cos(x)"
/// "#);
/// let toml = claim("sec2.double", "statement") + &claim("sec2.double.step", "proof-step");
/// let cat = load_sources(&[("t.toml".into(), toml)], Registry::new()).unwrap();
/// let ids = |q: &str, s: Scope| -> Vec<String> {
///     find(&cat, q, s).unwrap().claims.iter().map(|c| c.id.clone()).collect()
/// };
/// assert_eq!(ids("section 2", Scope::Statement), ["sec2.double"]);
/// assert_eq!(ids("Section 2", Scope::Whole), ["sec2.double", "sec2.double.step"]);
/// assert_eq!(ids("(double)", Scope::Statement).len(), 2);
/// let e = find(&cat, "sec2.dubble", Scope::Statement).unwrap_err();
/// assert_eq!(e.suggestions, ["sec2.double"]);
/// assert!(e.to_string().contains("did you mean sec2.double?"));
/// ```
pub fn find<'a>(cat: &'a Catalogue, query: &str, scope: Scope) -> Result<Selection<'a>, NotFound> {
    if let Some(c) = cat.claims.iter().find(|c| c.id == query) {
        return Ok(Selection {
            what: format!("claim {}", c.id),
            claims: vec![c],
        });
    }
    environment(cat, query, scope)
        .or_else(|| label(cat, query, false))
        .ok_or_else(|| not_found(cat, query))
}

/// The claims of the environment named `name` (ignoring case and runs of spaces), as
/// `scope` says, or `None` when no claim is in such an environment.
pub fn environment<'a>(cat: &'a Catalogue, name: &str, scope: Scope) -> Option<Selection<'a>> {
    let want = normalize(name);
    let all: Vec<&Claim> = cat
        .claims
        .iter()
        .filter(|c| {
            c.environment
                .as_ref()
                .is_some_and(|e| normalize(&e.value) == want)
        })
        .collect();
    let env = all.first()?.environment.as_ref()?.value.clone();
    let statements: Vec<&Claim> = all
        .iter()
        .copied()
        .filter(|c| c.role.as_ref().is_some_and(|r| r.value == "statement"))
        .collect();
    Some(match scope {
        Scope::Statement if !statements.is_empty() => Selection {
            what: format!("{env} (statement)"),
            claims: statements,
        },
        _ => Selection {
            what: env,
            claims: all,
        },
    })
}

/// The claims carrying the paper label `text`, written "(label)" or, unless
/// `parenthesized` is set, also "label"; `None` when no claim carries it.
pub fn label<'a>(cat: &'a Catalogue, text: &str, parenthesized: bool) -> Option<Selection<'a>> {
    let t = text.trim();
    let inner = match t.strip_prefix('(').and_then(|r| r.strip_suffix(')')) {
        Some(i) => i.trim(),
        None if parenthesized => return None,
        None => t,
    };
    let claims: Vec<&Claim> = cat
        .claims
        .iter()
        .filter(|c| c.labels.iter().any(|l| l == inner))
        .collect();
    (!claims.is_empty()).then(|| Selection {
        what: format!("label ({inner})"),
        claims,
    })
}

/// The error for `query`, with the closest claim ids, environment names and labels.
pub fn not_found(cat: &Catalogue, query: &str) -> NotFound {
    NotFound {
        query: query.to_string(),
        suggestions: suggestions(cat, query),
    }
}

/// At most three names closest to `query` by edit distance (ignoring case): claim ids,
/// environment names and labels (shown in parentheses), within a distance of a third of
/// the name's length (at least 2).
pub fn suggestions(cat: &Catalogue, query: &str) -> Vec<String> {
    let q = query.trim();
    let q_label = q
        .strip_prefix('(')
        .and_then(|r| r.strip_suffix(')'))
        .unwrap_or(q);
    let mut scored: Vec<(usize, String)> = Vec::new();
    let mut consider = |name: &str, shown: String, against: &str| {
        if scored.iter().any(|(_, s)| *s == shown) {
            return;
        }
        let d = distance(&against.to_lowercase(), &name.to_lowercase());
        if d <= (name.chars().count() / 3).max(2) {
            scored.push((d, shown));
        }
    };
    for c in &cat.claims {
        consider(&c.id, c.id.clone(), q);
        if let Some(e) = &c.environment {
            consider(&e.value, e.value.clone(), q);
        }
        for l in &c.labels {
            consider(l, format!("({l})"), q_label);
        }
    }
    scored.sort();
    scored.into_iter().take(3).map(|(_, s)| s).collect()
}

/// At most `n` of `names` closest to `query` by edit distance (ignoring case), within a
/// distance of a third of the name's length (at least 2), closest first.
///
/// ```
/// use eulertop::claims::catalogue::lookup::closest;
/// let names = ["Lemma 1", "Lemma 2", "Theorem 1"];
/// assert_eq!(closest("Lemma 3", names, 3), ["Lemma 1", "Lemma 2"]);
/// assert!(closest("Corollary", names, 3).is_empty());
/// ```
pub fn closest<'a>(query: &str, names: impl IntoIterator<Item = &'a str>, n: usize) -> Vec<String> {
    let q = query.trim().to_lowercase();
    let mut scored: Vec<(usize, &str)> = names
        .into_iter()
        .map(|name| (distance(&q, &name.to_lowercase()), name))
        .filter(|(d, name)| *d <= (name.chars().count() / 3).max(2))
        .collect();
    scored.sort();
    scored.dedup();
    scored
        .into_iter()
        .take(n)
        .map(|(_, s)| s.to_string())
        .collect()
}

/// Lower case with runs of white space as one space, for comparing environment names.
fn normalize(s: &str) -> String {
    s.split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .to_lowercase()
}

/// Levenshtein distance in characters.
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::distance;

    #[test]
    fn edit_distance() {
        assert_eq!(distance("gammaMW", "gammaMV"), 1);
        assert_eq!(distance("", "abc"), 3);
        assert_eq!(distance("kitten", "sitting"), 3);
        assert_eq!(distance("Théorème", "Theoreme"), 2);
    }
}
