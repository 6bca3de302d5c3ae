//! The paper's structure in the catalogue: each claim names the environment of the paper
//! it belongs to (`environment`), its role there (`role`) and the claims it rests on
//! (`uses`).  [`check`] validates these fields after loading (the format is in
//! `identities/README.md`); the report writer and the per-claim tests read them through
//! [`place`].
//!
//! ```
//! use eulertop::claims::structure::{Environment, Role};
//! let e = Environment::parse("Proposition 6").unwrap();
//! assert_eq!(e.slug(), "proposition_6");
//! assert_eq!(e.page(), "proposition-6");
//! assert_eq!(Environment::parse("Section 5").unwrap().name(), "Section 5");
//! assert!(Environment::parse("Proposition 7").is_none());
//! assert_eq!(Role::parse("proof-step"), Some(Role::ProofStep));
//! ```

use super::claim::{Body, Catalogue, Claim, PExpr};
use super::source::LoadError;
use crate::claims::ast::{Expr, ExprKind, Span};
use crate::claims::kind::{Form, Kind};
use std::collections::{BTreeMap, BTreeSet};

/// The theorem-like environments of the paper, in the order in which they are printed.
pub const ENVIRONMENTS: [&str; 13] = [
    "Definition 1",
    "Proposition 1",
    "Proposition 2",
    "Proposition 3",
    "Proposition 4",
    "Lemma 1",
    "Theorem 1",
    "Corollary",
    "Proposition 5",
    "Proposition 6",
    "Theorem 2",
    "Lemma 2",
    "Theorem 3",
];

/// The paper's sections ("A" is the appendix).
const SECTIONS: [&str; 10] = ["1", "2", "3", "4", "5", "6", "7", "8", "9", "A"];

/// Where in the paper a claim belongs.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Environment {
    /// One of [`ENVIRONMENTS`] (the index, i.e. its rank in the paper).
    Named(usize),
    /// The text of a section outside any environment ("Section 5"; "A" is the appendix).
    Section(String),
}

impl Environment {
    /// Parses "Proposition 6", "Corollary", "Section 2", …; `None` if not an environment of
    /// the paper.
    pub fn parse(s: &str) -> Option<Environment> {
        if let Some(j) = ENVIRONMENTS.iter().position(|e| *e == s) {
            return Some(Environment::Named(j));
        }
        let n = s.strip_prefix("Section ")?;
        SECTIONS
            .contains(&n)
            .then(|| Environment::Section(n.to_string()))
    }

    /// The name as written in the catalogue.
    pub fn name(&self) -> String {
        match self {
            Environment::Named(j) => ENVIRONMENTS[*j].to_string(),
            Environment::Section(n) => format!("Section {n}"),
        }
    }

    /// The name as an identifier: `proposition_6`, `section_2` (test-name prefix).
    pub fn slug(&self) -> String {
        self.name().to_ascii_lowercase().replace(' ', "_")
    }

    /// The name as a file stem: `proposition-6`, `corollary`.
    pub fn page(&self) -> String {
        self.name().to_ascii_lowercase().replace(' ', "-")
    }
}

/// What a claim does in its environment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Role {
    /// Encodes (part of) the environment's statement, or a displayed formula of the text.
    Statement,
    /// A step of the printed proof.
    ProofStep,
    /// Defines a quantity the environment uses (a `definition` claim).
    Definition,
    /// A statement the text derives from the environment.
    Consequence,
    /// A fact from outside the paper that the text invokes (DLMF, vector algebra).
    Background,
    /// A check of the tool or of the model, not a statement of the paper.
    Control,
}

/// The roles in the order of the catalogue format.
pub const ROLES: [Role; 6] = [
    Role::Statement,
    Role::ProofStep,
    Role::Definition,
    Role::Consequence,
    Role::Background,
    Role::Control,
];

impl Role {
    /// The role as written in the catalogue.
    pub fn name(self) -> &'static str {
        match self {
            Role::Statement => "statement",
            Role::ProofStep => "proof-step",
            Role::Definition => "definition",
            Role::Consequence => "consequence",
            Role::Background => "background",
            Role::Control => "control",
        }
    }

    /// Parses a role name.
    pub fn parse(s: &str) -> Option<Role> {
        ROLES.iter().copied().find(|r| r.name() == s)
    }
}

/// A claim's place in the paper's structure.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Place {
    /// Its environment.
    pub environment: Environment,
    /// Its role there.
    pub role: Role,
    /// The ids of the claims it uses.
    pub uses: Vec<String>,
}

/// The place of a claim (`None` when `environment` or `role` is absent or invalid; a loaded
/// catalogue has passed [`check`]).
pub fn place(c: &Claim) -> Option<Place> {
    Some(Place {
        environment: Environment::parse(&c.environment.as_ref()?.value)?,
        role: Role::parse(&c.role.as_ref()?.value)?,
        uses: c.uses.iter().map(|u| u.value.clone()).collect(),
    })
}

fn parse_fields(c: &Claim) -> Result<(Option<Environment>, Option<Role>), LoadError> {
    let env = match &c.environment {
        None => None,
        Some(e) => Some(Environment::parse(&e.value).ok_or_else(|| {
            e.error(format!(
                "unknown environment '{}' (one of {}, or \"Section N\" with N in 1..9 or A)",
                e.value,
                ENVIRONMENTS.join(", ")
            ))
        })?),
    };
    let role = match &c.role {
        None => None,
        Some(r) => Some(Role::parse(&r.value).ok_or_else(|| {
            let names: Vec<&str> = ROLES.iter().map(|r| r.name()).collect();
            r.error(format!(
                "unknown role '{}' ({})",
                r.value,
                names.join(" | ")
            ))
        })?),
    };
    if let (Some(r), Some(role)) = (&c.role, role) {
        let def = c.kind == Kind::Definition;
        if role == Role::Definition && !def {
            return Err(r.error("role \"definition\" is for claims of kind \"definition\""));
        }
        if def && !matches!(role, Role::Definition | Role::Statement) {
            return Err(r.error(
                "a claim of kind \"definition\" has role \"definition\" (or \"statement\" for a definition of the paper)",
            ));
        }
    }
    if let Body::Negation(inner) = &c.body {
        let stray = inner
            .environment
            .iter()
            .chain(inner.role.iter())
            .chain(inner.uses.iter())
            .next();
        if let Some(f) = stray {
            return Err(f.error("environment, role and uses belong to the outer claim"));
        }
    }
    Ok((env, role))
}

fn check_uses(cat: &Catalogue, index: &BTreeMap<&str, usize>) -> Result<(), LoadError> {
    for c in &cat.claims {
        let mut seen = BTreeSet::new();
        for u in &c.uses {
            if !index.contains_key(u.value.as_str()) {
                return Err(u.error(format!("unknown claim id '{}' in uses", u.value)));
            }
            if u.value == c.id {
                return Err(u.error(format!("claim '{}' uses itself", c.id)));
            }
            if !seen.insert(u.value.as_str()) {
                return Err(u.error(format!("'{}' is listed twice in uses", u.value)));
            }
        }
        for h in &c.hypotheses {
            if !cat.hypotheses.contains_key(&h.value) {
                return Err(h.error(format!(
                    "unknown hypothesis '{}' (no [hypothesis.{}] table)",
                    h.value, h.value
                )));
            }
        }
    }
    Ok(())
}

/// Depth-first search for a cycle of `uses`; the error points at the entry that closes it.
fn check_cycles(cat: &Catalogue, index: &BTreeMap<&str, usize>) -> Result<(), LoadError> {
    // 0 = unvisited, 1 = on the current path, 2 = done
    let mut state = vec![0u8; cat.claims.len()];
    for root in 0..cat.claims.len() {
        if state[root] != 0 {
            continue;
        }
        let mut stack: Vec<(usize, usize)> = vec![(root, 0)];
        state[root] = 1;
        while let Some(&mut (node, ref mut next)) = stack.last_mut() {
            let uses = &cat.claims[node].uses;
            if *next == uses.len() {
                state[node] = 2;
                stack.pop();
                continue;
            }
            let entry = &uses[*next];
            *next += 1;
            let Some(&to) = index.get(entry.value.as_str()) else {
                continue;
            };
            match state[to] {
                0 => {
                    state[to] = 1;
                    stack.push((to, 0));
                }
                1 => {
                    let start = stack.iter().position(|(n, _)| *n == to).unwrap_or(0);
                    let mut path: Vec<&str> = stack[start..]
                        .iter()
                        .map(|(n, _)| cat.claims[*n].id.as_str())
                        .collect();
                    path.push(&cat.claims[to].id);
                    return Err(entry.error(format!("cycle in uses: {}", path.join(" → "))));
                }
                _ => {}
            }
        }
    }
    Ok(())
}

/// Every environment has a statement claim, and the statements of the paper's
/// environments come in the order in which the paper prints them.
fn check_statements(
    cat: &Catalogue,
    fields: &[(Option<Environment>, Option<Role>)],
) -> Result<(), LoadError> {
    let mut first: BTreeMap<&Environment, usize> = BTreeMap::new();
    let mut stated: BTreeSet<&Environment> = BTreeSet::new();
    let mut last_named: Option<(usize, usize)> = None;
    for (j, (env, role)) in fields.iter().enumerate() {
        let Some(env) = env else { continue };
        first.entry(env).or_insert(j);
        if *role != Some(Role::Statement) || !stated.insert(env) {
            continue;
        }
        if let Environment::Named(rank) = env {
            if let Some((prev_rank, _)) = last_named.filter(|(r, _)| r > rank) {
                let at = cat.claims[j].environment.as_ref().expect("parsed");
                return Err(at.error(format!(
                    "the first statement of {} comes after that of {} in the catalogue, but the paper prints {} first (claims keep the paper's order)",
                    ENVIRONMENTS[*rank], ENVIRONMENTS[prev_rank], ENVIRONMENTS[*rank]
                )));
            }
            last_named = Some((*rank, j));
        }
    }
    for (env, j) in first {
        if !stated.contains(env) {
            let at = cat.claims[j].environment.as_ref().expect("parsed");
            return Err(at.error(format!(
                "{} has no claim with role = \"statement\"",
                env.name()
            )));
        }
    }
    Ok(())
}

/// Validates `environment`, `role` and `uses` of every claim: known names, known ids in
/// `uses`, no cycle, a statement claim in every environment, statements in the paper's
/// order.  Errors point at the offending value (`file:line:col`).
pub fn check(cat: &Catalogue) -> Result<(), LoadError> {
    let fields: Vec<(Option<Environment>, Option<Role>)> = cat
        .claims
        .iter()
        .map(parse_fields)
        .collect::<Result<_, _>>()?;
    let index: BTreeMap<&str, usize> = cat
        .claims
        .iter()
        .enumerate()
        .map(|(j, c)| (c.id.as_str(), j))
        .collect();
    check_uses(cat, &index)?;
    check_cycles(cat, &index)?;
    check_statements(cat, &fields)?;
    check_printed(cat)
}

/// The calls in an expression: (function name, span of the call).
fn calls(e: &Expr) -> Vec<(String, Span)> {
    let mut out = Vec::new();
    e.walk(&mut |x| {
        if let ExprKind::Call(n, _) = &x.kind {
            out.push((n.clone(), x.span));
        }
    });
    out
}

/// Functions that rest on a definition marked as corrected: name → id of that definition
/// (directly, or through the definitions they call).
pub fn corrected_functions(cat: &Catalogue) -> BTreeMap<String, String> {
    let mut out: BTreeMap<String, String> = BTreeMap::new();
    for c in &cat.claims {
        if let (Body::Definition(bs), Form::Corrected) = (&c.body, c.form) {
            for b in bs {
                out.insert(b.name.clone(), c.id.clone());
            }
        }
    }
    loop {
        let mut added = false;
        for c in &cat.claims {
            let Body::Definition(bs) = &c.body else {
                continue;
            };
            for b in bs {
                if out.contains_key(&b.name) {
                    continue;
                }
                let via = calls(&b.body)
                    .into_iter()
                    .find_map(|(n, _)| out.get(&n).cloned());
                if let Some(id) = via {
                    out.insert(b.name.clone(), id);
                    added = true;
                }
            }
        }
        if !added {
            return out;
        }
    }
}

/// The expressions of a claim that carry positions (not its `let` and `define` blocks).
fn located_exprs(c: &Claim) -> Vec<&PExpr> {
    let mut all: Vec<&PExpr> = c.vars.iter().map(|v| &v.1).collect();
    all.extend(c.wheres.iter());
    all.extend(c.scale.iter());
    match &c.body {
        Body::Identity { lhs, rhs } => all.extend([lhs, rhs]),
        Body::Independence { expr, .. } | Body::Asymptotic { expr, .. } => all.push(expr),
        Body::Existence {
            equations,
            start,
            in_set,
            ..
        } => {
            all.extend(equations.iter());
            all.extend(start.iter());
            all.extend(in_set.iter());
        }
        Body::Negation(inner) => all.extend(located_exprs(inner)),
        Body::Definition(_) => {}
    }
    all
}

/// An error at a claim's `file:line` (for text without positions of its own).
fn claim_error(c: &Claim, message: String) -> LoadError {
    let (file, line) = c.position.rsplit_once(':').unwrap_or((&c.position, "0"));
    LoadError {
        file: file.to_string(),
        line: line.parse().unwrap_or(0),
        col: 1,
        message,
        line_text: "[[claim]]".to_string(),
        width: 9,
    }
}

/// No claim in printed form calls a function that rests on a definition marked as
/// corrected: a printed statement is judged with the paper's own definitions.
fn check_printed(cat: &Catalogue) -> Result<(), LoadError> {
    let tainted = corrected_functions(cat);
    let say = |c: &Claim, f: &str| {
        format!(
            "printed claim '{}' uses '{f}', which rests on the corrected definition '{}': use the paper's definitions, or make the claim corrected",
            c.id, tainted[f]
        )
    };
    for c in cat.claims.iter().filter(|c| c.form == Form::Printed) {
        for p in located_exprs(c) {
            if let Some((n, span)) = calls(&p.expr)
                .into_iter()
                .find(|(n, _)| tainted.contains_key(n))
            {
                return Err(p.origin.error(Some(span), say(c, &n)));
            }
        }
        let mut blocks: Vec<&Expr> = c.lets.iter().map(|b| &b.body).collect();
        if let Body::Negation(inner) = &c.body {
            blocks.extend(inner.lets.iter().map(|b| &b.body));
        }
        if let Body::Definition(bs) = &c.body {
            blocks.extend(bs.iter().map(|b| &b.body));
        }
        for e in blocks {
            if let Some((n, _)) = calls(e).into_iter().find(|(n, _)| tainted.contains_key(n)) {
                return Err(claim_error(c, say(c, &n)));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claims::catalogue::load_sources;
    use crate::claims::registry::Registry;

    fn claim(id: &str, fields: &str) -> String {
        format!(
            "[[claim]]\nid = \"{id}\"\nlocation = \"l\"\nprinted = 'p'\nkind = \"identity\"\nexpect = \"holds\"\nlhs = \"1\"\nrhs = \"1\"\n{fields}\n"
        )
    }

    fn load(src: &str) -> Result<Catalogue, LoadError> {
        load_sources(&[("t.toml".to_string(), src.to_string())], Registry::new())
    }

    fn err(src: &str) -> LoadError {
        match load(src) {
            Ok(_) => panic!("loaded:\n{src}"),
            Err(e) => e,
        }
    }

    #[test]
    fn fields_are_read_in_catalogue_order() {
        let src = claim("a", "environment = \"Lemma 1\"\nrole = \"statement\"")
            + &claim(
                "b",
                "environment = \"Lemma 1\"\nrole = \"proof-step\"\nuses = [\"a\"]",
            )
            + &claim("c", "environment = \"Section 4\"\nrole = \"statement\"");
        let cat = load(&src).unwrap();
        let p: Vec<Place> = cat.claims.iter().map(|c| place(c).unwrap()).collect();
        assert_eq!(p[0].environment, Environment::Named(5));
        assert_eq!(p[1].role, Role::ProofStep);
        assert_eq!(p[1].uses, vec!["a".to_string()]);
        assert_eq!(p[2].environment, Environment::Section("4".into()));
    }

    #[test]
    fn unknown_names_are_errors_at_their_position() {
        let e = err(&claim(
            "a",
            "environment = \"Proposition 7\"\nrole = \"statement\"",
        ));
        assert_eq!((e.file.as_str(), e.line, e.col), ("t.toml", 9, 15));
        assert!(e.message.contains("unknown environment"), "{e}");
        let e = err(&claim("a", "environment = \"Section 2\"\nrole = \"lemma\""));
        assert_eq!((e.line, e.col), (10, 8));
        assert!(e.message.contains("unknown role 'lemma'"), "{e}");
    }

    #[test]
    fn uses_must_name_known_claims() {
        let src = claim(
            "a",
            "environment = \"Section 2\"\nrole = \"statement\"\nuses = [\"b\"]",
        );
        let e = err(&src);
        assert_eq!((e.line, e.col), (11, 9));
        assert!(e.message.contains("unknown claim id 'b'"), "{e}");
        let e = err(&claim(
            "a",
            "environment = \"Section 2\"\nrole = \"statement\"\nuses = [\"a\"]",
        ));
        assert!(e.message.contains("uses itself"), "{e}");
    }

    #[test]
    fn cycles_are_rejected() {
        let src = claim(
            "a",
            "environment = \"Section 2\"\nrole = \"statement\"\nuses = [\"c\"]",
        ) + &claim(
            "b",
            "environment = \"Section 2\"\nrole = \"statement\"\nuses = [\"a\"]",
        ) + &claim(
            "c",
            "environment = \"Section 2\"\nrole = \"statement\"\nuses = [\"b\"]",
        );
        let e = err(&src);
        assert!(e.message.contains("cycle in uses: a → c → b → a"), "{e}");
        assert_eq!((e.line, e.col), (22, 9), "{e}");
    }

    #[test]
    fn every_environment_needs_a_statement() {
        let src = claim("a", "environment = \"Theorem 1\"\nrole = \"proof-step\"");
        let e = err(&src);
        assert!(
            e.message.contains("Theorem 1 has no claim with role"),
            "{e}"
        );
    }

    #[test]
    fn statements_keep_the_papers_order() {
        let src = claim("a", "environment = \"Theorem 1\"\nrole = \"statement\"")
            + &claim("b", "environment = \"Lemma 1\"\nrole = \"statement\"");
        let e = err(&src);
        assert!(e.message.contains("the paper prints Lemma 1 first"), "{e}");
        // proof steps may come later (a lemma proved in the appendix)
        let src = claim("a", "environment = \"Lemma 1\"\nrole = \"statement\"")
            + &claim("b", "environment = \"Theorem 1\"\nrole = \"statement\"")
            + &claim("c", "environment = \"Lemma 1\"\nrole = \"proof-step\"");
        assert!(load(&src).is_ok());
    }

    #[test]
    fn roles_fit_kinds() {
        let e = err(&claim(
            "a",
            "environment = \"Section 2\"\nrole = \"definition\"",
        ));
        assert!(e.message.contains("kind \"definition\""), "{e}");
        let src = "[[claim]]\nid = \"d\"\nlocation = \"l\"\nprinted = 'p'\nkind = \"definition\"\ndefine = '''\nf(x) = x\n'''\nenvironment = \"Section 2\"\nrole = \"proof-step\"\n";
        assert!(err(src).message.contains("has role \"definition\""));
    }

    #[test]
    fn inner_claims_carry_no_structure() {
        let src = "[[claim]]\nid = \"n\"\nlocation = \"l\"\nprinted = 'p'\nkind = \"negation\"\nexpect = \"holds\"\nenvironment = \"Section 2\"\nrole = \"statement\"\n[claim.inner]\nkind = \"identity\"\nlhs = \"1\"\nrhs = \"2\"\nrole = \"statement\"\n";
        let e = err(src);
        assert!(e.message.contains("belong to the outer claim"), "{e}");
    }

    fn def(id: &str, form: &str, body: &str) -> String {
        let fix = if form == "corrected" {
            "corrects = \"a\"\n"
        } else {
            ""
        };
        format!(
            "[[claim]]\nid = \"{id}\"\nlocation = \"l\"\nprinted = 'p'\nkind = \"definition\"\nform = \"{form}\"\n{fix}environment = \"Section 2\"\nrole = \"definition\"\ndefine = '''\n{body}\n'''\n"
        )
    }

    fn stated(id: &str, extra: &str, lhs: &str) -> String {
        claim(
            id,
            &format!("environment = \"Section 2\"\nrole = \"statement\"\n{extra}"),
        )
        .replace("lhs = \"1\"", &format!("lhs = \"{lhs}\""))
    }

    #[test]
    fn printed_claims_use_no_corrected_definition() {
        let base = stated("a", "", "1")
            + &def("good", "printed", "f(x) = x")
            + &def("fix", "corrected", "g(x) = 2 * x");
        // a printed claim calling g: the error points at the call
        let e = err(&(base.clone() + &stated("b", "", "f(1) + g(1)")));
        assert!(
            e.message.contains("printed claim 'b' uses 'g'") && e.message.contains("'fix'"),
            "{e}"
        );
        assert_eq!(e.col, 15, "{e}");
        // through a let binding, and through a printed definition that calls g
        let e = err(&(base.clone() + &stated("b", "let = '''\ny = g(2)\n'''", "y")));
        assert!(e.message.contains("printed claim 'b' uses 'g'"), "{e}");
        let e = err(&(base.clone() + &def("via", "printed", "k(x) = g(x) + 1")));
        assert!(e.message.contains("printed claim 'via' uses 'g'"), "{e}");
        // corrected claims may use it, also through a corrected definition
        let ok = base
            + &def("via", "corrected", "k(x) = g(x) + 1")
            + &stated("c", "form = \"corrected\"\ncorrects = \"a\"", "k(1) - 2");
        assert!(load(&ok).is_ok());
    }
}
