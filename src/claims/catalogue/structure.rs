//! The paper's structure in the catalogue: each claim names the environment of the paper
//! it belongs to (`environment`, one of the names the catalogue's `[paper]` table lists,
//! see [`super::paper`]), its role there (`role`) and the claims it rests on (`uses`).
//! [`check`] validates these fields after loading (the format is in
//! `identities/README.md`); the report writer and the per-claim tests read them through
//! [`place`].
//!
//! ```
//! use eulertop::claims::catalogue::load_sources;
//! use eulertop::claims::registry::Registry;
//! use eulertop::claims::structure::{place, Role};
//! let toml = r#"
//! [paper]
//! title = "T"
//! authors = []
//! year = 2000
//! environments = [{ name = "Section 2", section = true }, "Proposition 6"]
//!
//! [[claim]]
//! id = "one"
//! location = "l"
//! printed = 'p'
//! environment = "Proposition 6"
//! role = "statement"
//! kind = "identity"
//! expect = "holds"
//! lhs = "1"
//! rhs = "1"
//! "#;
//! let cat = load_sources(&[("t.toml".into(), toml.into())], Registry::new()).unwrap();
//! let e = cat.environment("Proposition 6").unwrap();
//! assert_eq!((e.rank, e.slug(), e.page()), (1, "proposition_6".to_string(), "proposition-6".to_string()));
//! assert!(cat.environment("Section 2").unwrap().section);
//! assert!(cat.environment("Proposition 7").is_none());
//! assert_eq!(place(&cat, &cat.claims[0]).unwrap().environment, e);
//! assert_eq!(Role::parse("proof-step"), Some(Role::ProofStep));
//! ```

use super::claim::{Body, Catalogue, Claim, PExpr};
use super::source::LoadError;
use crate::claims::ast::{Expr, ExprKind, Span};
use crate::claims::kind::{Form, Kind};
use std::collections::{BTreeMap, BTreeSet};

/// Where in the paper a claim belongs: one of the catalogue's environments.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Environment {
    /// Its rank in the catalogue's list (the paper's order).
    pub rank: usize,
    /// The name as written in the catalogue ("Proposition 6", "Section 2").
    pub name: String,
    /// Text of a section outside the theorem-like environments (no proof page of its own).
    pub section: bool,
}

impl Environment {
    /// The name as written in the catalogue.
    pub fn name(&self) -> String {
        self.name.clone()
    }

    /// The name as an identifier: `proposition_6`, `section_2` (test-name prefix); see
    /// [`super::paper::stem`].
    pub fn slug(&self) -> String {
        super::paper::stem(&self.name, '_')
    }

    /// The name as a file stem: `proposition-6`, `corollary`, `22-6` for "§22.6"; see
    /// [`super::paper::stem`].
    pub fn page(&self) -> String {
        super::paper::stem(&self.name, '-')
    }
}

impl Catalogue {
    /// The environment named `name` exactly as the catalogue lists it, if any.
    pub fn environment(&self, name: &str) -> Option<Environment> {
        let rank = self.environments.iter().position(|e| e.name == name)?;
        Some(self.environment_at(rank))
    }

    /// Every environment of the catalogue, in the paper's order, sections included.
    ///
    /// ```
    /// use eulertop::claims::catalogue::load_sources;
    /// use eulertop::claims::registry::Registry;
    /// let toml = "[paper]\ntitle = 'T'\nauthors = []\nyear = 1\nenvironments = ['Lemma 1', { name = 'Section 2', section = true }]\n";
    /// let cat = load_sources(&[("t.toml".into(), toml.into())], Registry::new()).unwrap();
    /// let envs = cat.all_environments();
    /// assert_eq!((envs[0].rank, envs[0].name.as_str(), envs[0].section), (0, "Lemma 1", false));
    /// assert_eq!((envs[1].rank, envs[1].page().as_str(), envs[1].section), (1, "section-2", true));
    /// ```
    pub fn all_environments(&self) -> Vec<Environment> {
        (0..self.environments.len())
            .map(|j| self.environment_at(j))
            .collect()
    }

    fn environment_at(&self, rank: usize) -> Environment {
        let e = &self.environments[rank];
        Environment {
            rank,
            name: e.name.clone(),
            section: e.section,
        }
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

/// The place of a claim of `cat` (`None` when `environment` or `role` is absent or
/// invalid; a loaded catalogue has passed [`check`]).
pub fn place(cat: &Catalogue, c: &Claim) -> Option<Place> {
    Some(Place {
        environment: cat.environment(&c.environment.as_ref()?.value)?,
        role: Role::parse(&c.role.as_ref()?.value)?,
        uses: c.uses.iter().map(|u| u.value.clone()).collect(),
    })
}

/// The error for an environment name the `[paper]` table does not list.
fn unknown_environment(cat: &Catalogue, e: &super::source::Located) -> LoadError {
    let names: Vec<&str> = cat.environments.iter().map(|x| x.name.as_str()).collect();
    let at = cat
        .paper
        .as_ref()
        .map_or(String::new(), |p| format!(" ({})", p.position));
    let mut m = format!(
        "unknown environment '{}': the [paper] table{at} lists {}",
        e.value,
        names.join(", ")
    );
    let near = super::lookup::closest(&e.value, names.iter().copied(), 3);
    if !near.is_empty() {
        m.push_str(&format!("; did you mean {}?", near.join(", ")));
    }
    e.error(m)
}

fn parse_fields(
    cat: &Catalogue,
    c: &Claim,
) -> Result<(Option<Environment>, Option<Role>), LoadError> {
    let env = match &c.environment {
        None => None,
        Some(e) => Some(
            cat.environment(&e.value)
                .ok_or_else(|| unknown_environment(cat, e))?,
        ),
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

/// Every environment with claims has a statement claim (unless the `[paper]` table says
/// why not, `no_statement`), and the first statements of the environments that are not
/// sections come in the order of the catalogue's list.
fn check_statements(
    cat: &Catalogue,
    fields: &[(Option<Environment>, Option<Role>)],
) -> Result<(), LoadError> {
    let mut first: BTreeMap<&Environment, usize> = BTreeMap::new();
    let mut stated: BTreeSet<&Environment> = BTreeSet::new();
    let mut last: Option<&Environment> = None;
    for (j, (env, role)) in fields.iter().enumerate() {
        let Some(env) = env else { continue };
        first.entry(env).or_insert(j);
        if *role != Some(Role::Statement) || !stated.insert(env) || env.section {
            continue;
        }
        if let Some(prev) = last.filter(|p| p.rank > env.rank) {
            let at = cat.claims[j].environment.as_ref().expect("parsed");
            return Err(at.error(format!(
                "the first statement of {} comes after that of {} in the catalogue, but the paper prints {} first (claims keep the order of the [paper] table's environments)",
                env.name, prev.name, env.name
            )));
        }
        last = Some(env);
    }
    for (env, j) in first {
        let excused = cat.environments[env.rank].no_statement.is_some();
        if !stated.contains(env) && !excused {
            let at = cat.claims[j].environment.as_ref().expect("parsed");
            return Err(at.error(format!(
                "{} has no claim with role = \"statement\" (or give the reason in the [paper] table: {{ name = \"{}\", no_statement = \"why\" }})",
                env.name, env.name
            )));
        }
    }
    Ok(())
}

/// Validates `environment`, `role` and `uses` of every claim: environments the catalogue
/// lists, known roles and ids in `uses`, no cycle, a statement claim in every environment
/// (or the reason why not), statements in the paper's order.  Errors point at the offending value (`file:line:col`).
pub fn check(cat: &Catalogue) -> Result<(), LoadError> {
    let fields: Vec<(Option<Environment>, Option<Role>)> = cat
        .claims
        .iter()
        .map(|c| parse_fields(cat, c))
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

    /// The `[paper]` table of the tests, after the claims (their lines stay put).
    const PAPER: &str = "[paper]\ntitle = \"T\"\nauthors = [\"A\"]\nyear = 2000\nenvironments = [{ name = \"Section 2\", section = true }, { name = \"Section 4\", section = true }, \"Lemma 1\", \"Theorem 1\", { name = \"Remark\", no_statement = \"a remark states nothing\" }]\n";

    fn load(src: &str) -> Result<Catalogue, LoadError> {
        load_plain(&format!("{src}{PAPER}"))
    }

    /// Without a `[paper]` table.
    fn load_plain(src: &str) -> Result<Catalogue, LoadError> {
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
        let p: Vec<Place> = cat.claims.iter().map(|c| place(&cat, c).unwrap()).collect();
        assert_eq!(p[0].environment, cat.environment("Lemma 1").unwrap());
        assert_eq!(p[0].environment.rank, 2);
        assert_eq!(p[1].role, Role::ProofStep);
        assert_eq!(p[1].uses, vec!["a".to_string()]);
        assert_eq!(p[2].environment.name, "Section 4");
        assert!(p[2].environment.section);
    }

    #[test]
    fn unknown_names_are_errors_at_their_position() {
        let e = err(&claim(
            "a",
            "environment = \"Proposition 7\"\nrole = \"statement\"",
        ));
        assert_eq!((e.file.as_str(), e.line, e.col), ("t.toml", 9, 15));
        assert!(
            e.message.contains("unknown environment 'Proposition 7'"),
            "{e}"
        );
        assert!(e.message.contains("the [paper] table (t.toml:"), "{e}");
        assert!(
            e.message.contains("lists Section 2, Section 4, Lemma 1"),
            "{e}"
        );
        let e = err(&claim(
            "a",
            "environment = \"Lemma 2\"\nrole = \"statement\"",
        ));
        assert!(e.message.ends_with("; did you mean Lemma 1?"), "{e}");
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
    fn a_reason_stands_for_the_statement() {
        // "Remark" says why it has no statement claim; "Theorem 1" does not
        assert!(
            load(&claim(
                "a",
                "environment = \"Remark\"\nrole = \"proof-step\""
            ))
            .is_ok()
        );
        let e = err(&claim(
            "a",
            "environment = \"Theorem 1\"\nrole = \"consequence\"",
        ));
        assert!(e.message.contains("no_statement = \"why\""), "{e}");
    }

    #[test]
    fn without_a_paper_table_any_name_goes() {
        let src = claim("a", "environment = \"Théorème B\"\nrole = \"statement\"")
            + &claim("b", "environment = \"Lemma 9\"\nrole = \"statement\"");
        let cat = load_plain(&src).unwrap();
        assert!(cat.paper.is_none());
        let names: Vec<String> = cat.all_environments().iter().map(|e| e.name()).collect();
        assert_eq!(names, ["Théorème B", "Lemma 9"]);
        assert_eq!(cat.environment("Théorème B").unwrap().slug(), "théorème_b");
        // still, every environment needs a statement
        let e = load_plain(&claim("a", "environment = \"X\"\nrole = \"proof-step\"")).unwrap_err();
        assert!(e.message.contains("X has no claim with role"), "{e}");
    }

    #[test]
    fn the_paper_table_is_checked() {
        let src = claim("a", "environment = \"Lemma 1\"\nrole = \"statement\"");
        let files = [
            ("a.toml".to_string(), format!("{src}{PAPER}")),
            ("b.toml".to_string(), PAPER.to_string()),
        ];
        let e = load_sources(&files, Registry::new()).unwrap_err();
        assert!(
            e.message
                .contains("a second [paper] table (the first is at a.toml:"),
            "{e}"
        );
        for (bad, says) in [
            ("environments = []", "at least one name"),
            ("environments = [\"Lemma 1\", \"Lemma 1\"]", "listed twice"),
            (
                "environments = [\"Lemma 1\", \"lemma-1\"]",
                "share the report page 'lemma-1'",
            ),
            (
                "environments = [{ name = \"L\", sections = true }]",
                "unknown field 'sections'",
            ),
            ("environments = [3]", "is a name or a table"),
            ("environments = [\" \"]", "empty name"),
        ] {
            let paper = format!("[paper]\ntitle = \"T\"\nauthors = []\nyear = 1\n{bad}\n");
            let e = load_plain(&format!("{src}{paper}")).unwrap_err();
            assert!(e.message.contains(says), "{bad}: {e}");
        }
        let e = load_plain(&format!(
            "{src}[paper]\ntitle = \"T\"\nyear = 1\nenvironments = [\"Lemma 1\"]\n"
        ))
        .unwrap_err();
        assert!(e.message.contains("authors"), "{e}");
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
