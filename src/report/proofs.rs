//! One page per environment of the paper (`reports/proofs/*.md`): the printed statement and
//! the claims that encode it, the printed proof step by step, the rolled-up status and a
//! dependency diagram.
//!
//! The rollup rule (also written in `reports/README.md`, see [`RULE`]):
//! * **statement**: the environment's `statement` claims in printed form.  If one is
//!   refuted, the statement *fails as printed*, and the corrected statement (the other
//!   printed statement claims with the claims that correct the refuted ones) is rolled up
//!   in the same way; else *inconclusive* if one is inconclusive; else *proved* if every
//!   one is proved (definitions aside); else *holds*.
//! * **proof**: the `proof-step` claims in printed form, with every claim that a step or a
//!   statement claim `uses` outside the statement.  *Every step verified* when all hold, are
//!   proved or are definitions; *complete after corrections* when the only failures are
//!   refuted printed claims that each have a correction that holds (the errata are named);
//!   else it *has a gap* (the inconclusive claims, or refuted ones without a correction
//!   that holds, are named).  An environment without proof steps: *no proof printed*.

use super::cells::{anchor, best_residual, printed_markdown, result_badge};
use super::decimal::round_numbers;
use super::diagram::mermaid;
use super::paper_text::to_markdown;
use super::variables::VarDef;
use super::{ReportInput, stem_of};
use crate::claims::kind::Form;
use crate::claims::structure::{Environment, Place, Role};
use crate::claims::verdict::{ClaimResult, Counterexample, Verdict};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;

/// The rollup rule, as written in the report's README.
pub const RULE: &str = "\
- **Statement.** The environment's claims with role `statement`, in printed form. If one of them is refuted, the statement **fails as printed**; the corrected statement (the other printed statement claims together with the claims that correct the refuted ones) is then rolled up by the same rule and shown after it. Otherwise the statement is **inconclusive** if one claim is inconclusive, **proved** if every claim is proved (definitions aside), and else it **holds**.
- **Proof.** The claims with role `proof-step`, in printed form, together with every claim that a step or a statement claim `uses` (outside the statement itself). **Every step verified**: all of them hold, are proved or are definitions. **Complete after corrections**: the only failures are refuted printed claims, each with a corrected claim that holds or is proved; the errata are named. **Has a gap**: a claim is inconclusive, or refuted without a correction that holds; the claim is named. An environment without proof steps has **no proof printed** (the paper gives none).";

/// Status of an environment's statement.
#[derive(Clone, Debug, PartialEq)]
pub enum StatementStatus {
    /// Every statement claim is proved.
    Proved,
    /// Every statement claim holds or is proved.
    Holds,
    /// Only definitions.
    Definition,
    /// Some statement claim is inconclusive (named).
    Inconclusive(Vec<String>),
    /// Some printed statement claim is refuted (named); the corrected statement's status.
    FailsAsPrinted {
        /// The refuted printed claims.
        refuted: Vec<String>,
        /// Status of the corrected statement.
        corrected: Box<StatementStatus>,
    },
    /// No statement claim.
    Missing,
}

/// Status of an environment's proof.
#[derive(Clone, Debug, PartialEq)]
pub enum ProofStatus {
    /// The paper prints no proof.
    NoProof,
    /// Every step verified (the number of claims).
    Verified(usize),
    /// Complete after the named errata.
    AfterCorrections(Vec<String>),
    /// Gaps: (claim id, why).
    Gap(Vec<(String, String)>),
}

/// The rolled-up status of one environment.
#[derive(Clone, Debug, PartialEq)]
pub struct Rollup {
    /// The statement.
    pub statement: StatementStatus,
    /// The proof.
    pub proof: ProofStatus,
}

/// Claims of the catalogue with their places, for the rollup and the pages.
pub struct Structure<'a> {
    /// Results in catalogue order.
    pub results: &'a [ClaimResult],
    /// Place of each claim id.
    pub places: &'a BTreeMap<String, Place>,
    by_id: BTreeMap<&'a str, &'a ClaimResult>,
}

impl<'a> Structure<'a> {
    /// Indexes the results.
    pub fn new(results: &'a [ClaimResult], places: &'a BTreeMap<String, Place>) -> Self {
        let by_id = results.iter().map(|r| (r.id.as_str(), r)).collect();
        Structure {
            results,
            places,
            by_id,
        }
    }

    /// A result by id.
    pub fn get(&self, id: &str) -> Option<&'a ClaimResult> {
        self.by_id.get(id).copied()
    }

    /// The claims of one environment with a role, in catalogue order.
    pub fn claims(&self, env: &Environment, role: Option<Role>) -> Vec<&'a ClaimResult> {
        self.results
            .iter()
            .filter(|r| {
                self.places
                    .get(&r.id)
                    .is_some_and(|p| p.environment == *env && role.is_none_or(|x| p.role == x))
            })
            .collect()
    }

    /// The claims that correct `id`.
    pub fn corrections(&self, id: &str) -> Vec<&'a ClaimResult> {
        self.results
            .iter()
            .filter(|r| r.corrects.as_deref() == Some(id))
            .collect()
    }

    pub(super) fn uses(&self, id: &str) -> &'a [String] {
        self.places.get(id).map_or(&[], |p| p.uses.as_slice())
    }
}

fn simple_status(claims: &[&ClaimResult]) -> StatementStatus {
    if claims.is_empty() {
        return StatementStatus::Missing;
    }
    let inconclusive: Vec<String> = claims
        .iter()
        .filter(|r| r.verdict == Verdict::Inconclusive)
        .map(|r| r.id.clone())
        .collect();
    if !inconclusive.is_empty() {
        return StatementStatus::Inconclusive(inconclusive);
    }
    // a claim that holds by construction restates the model's own equation: the
    // statement rests on the claims with content
    let content = |r: &&&ClaimResult| r.verdict != Verdict::Construction;
    if claims
        .iter()
        .filter(content)
        .all(|r| r.verdict == Verdict::Defined)
    {
        StatementStatus::Definition
    } else if claims
        .iter()
        .filter(content)
        .all(|r| matches!(r.verdict, Verdict::Proved | Verdict::Defined))
    {
        StatementStatus::Proved
    } else {
        StatementStatus::Holds
    }
}

/// The statement rule.
pub fn statement_status(s: &Structure, env: &Environment) -> StatementStatus {
    let printed: Vec<&ClaimResult> = s
        .claims(env, Some(Role::Statement))
        .into_iter()
        .filter(|r| r.form == Form::Printed)
        .collect();
    let refuted: Vec<&ClaimResult> = printed
        .iter()
        .copied()
        .filter(|r| r.verdict == Verdict::Refuted)
        .collect();
    if refuted.is_empty() {
        return simple_status(&printed);
    }
    let mut corrected: Vec<&ClaimResult> = printed
        .iter()
        .copied()
        .filter(|r| r.verdict != Verdict::Refuted)
        .collect();
    let mut fixes_all = true;
    for r in &refuted {
        let fixes = s.corrections(&r.id);
        fixes_all &= !fixes.is_empty();
        corrected.extend(fixes);
    }
    let corrected = if fixes_all {
        simple_status(&corrected)
    } else {
        StatementStatus::Missing
    };
    StatementStatus::FailsAsPrinted {
        refuted: refuted.iter().map(|r| r.id.clone()).collect(),
        corrected: Box::new(corrected),
    }
}

/// The claims the proof rests on: printed proof steps, and what steps and statement claims
/// use outside the statement, in catalogue order.
pub fn proof_claims<'a>(s: &Structure<'a>, env: &Environment) -> Vec<&'a ClaimResult> {
    let statement: BTreeSet<&str> = s
        .claims(env, Some(Role::Statement))
        .iter()
        .map(|r| r.id.as_str())
        .collect();
    let steps: Vec<&ClaimResult> = s
        .claims(env, Some(Role::ProofStep))
        .into_iter()
        .filter(|r| r.form == Form::Printed)
        .collect();
    let mut ids: BTreeSet<&str> = steps.iter().map(|r| r.id.as_str()).collect();
    for r in steps.iter().copied().chain(
        s.claims(env, Some(Role::Statement))
            .into_iter()
            .filter(|r| r.form == Form::Printed),
    ) {
        for u in s.uses(&r.id) {
            if !statement.contains(u.as_str()) && s.get(u).is_some_and(|x| x.form == Form::Printed)
            {
                ids.insert(u);
            }
        }
    }
    s.results
        .iter()
        .filter(|r| ids.contains(r.id.as_str()))
        .collect()
}

fn correction_holds(s: &Structure, id: &str) -> bool {
    s.corrections(id).iter().any(|f| {
        matches!(
            f.verdict,
            Verdict::Holds | Verdict::Proved | Verdict::Construction | Verdict::Defined
        )
    })
}

/// The proof rule.
pub fn proof_status(s: &Structure, env: &Environment) -> ProofStatus {
    if s.claims(env, Some(Role::ProofStep)).is_empty() {
        return ProofStatus::NoProof;
    }
    let claims = proof_claims(s, env);
    let mut gaps = Vec::new();
    let mut errata = Vec::new();
    for r in &claims {
        match r.verdict {
            Verdict::Inconclusive => gaps.push((r.id.clone(), "inconclusive".to_string())),
            Verdict::Refuted if correction_holds(s, &r.id) => errata.push(r.id.clone()),
            Verdict::Refuted => {
                gaps.push((r.id.clone(), "refuted, no correction holds".to_string()))
            }
            _ => {}
        }
    }
    if !gaps.is_empty() {
        ProofStatus::Gap(gaps)
    } else if !errata.is_empty() {
        ProofStatus::AfterCorrections(errata)
    } else {
        ProofStatus::Verified(claims.len())
    }
}

/// Both rules for one environment.
pub fn rollup(s: &Structure, env: &Environment) -> Rollup {
    Rollup {
        statement: statement_status(s, env),
        proof: proof_status(s, env),
    }
}

/// The environments that get a proof page (those that are not sections), in the paper's
/// order.
pub fn environments(input: &ReportInput) -> Vec<Environment> {
    let all = input.paper_environments.iter();
    all.filter(|e| !e.section).cloned().collect()
}

/// Link to a claim on its environment page (`prefix` leads to `reports/`), or to its section
/// page when its environment has no page.
pub fn claim_link(s: &Structure, id: &str, prefix: &str) -> String {
    match s.places.get(id).map(|p| &p.environment) {
        Some(env) if !env.section => {
            format!("{prefix}proofs/{}.md#{}", env.page(), anchor(id))
        }
        _ => s
            .get(id)
            .map(|r| format!("{prefix}{}.md#{}", stem_of(r), anchor(id)))
            .unwrap_or_default(),
    }
}

fn ids_text(ids: &[String], s: &Structure, prefix: &str) -> String {
    ids.iter()
        .map(|i| format!("[`{i}`]({})", claim_link(s, i, prefix)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The statement status as text (links relative to `prefix`).
pub fn statement_text(st: &StatementStatus, s: &Structure, prefix: &str) -> String {
    match st {
        StatementStatus::Proved => "✓✓ proved".into(),
        StatementStatus::Holds => "✓ holds".into(),
        StatementStatus::Definition => "≔ definition".into(),
        StatementStatus::Missing => "— no claim".into(),
        StatementStatus::Inconclusive(ids) => {
            format!("? inconclusive ({})", ids_text(ids, s, prefix))
        }
        StatementStatus::FailsAsPrinted { refuted, corrected } => format!(
            "✗ fails as printed (refuted: {}); corrected statement: {}",
            ids_text(refuted, s, prefix),
            statement_text(corrected, s, prefix)
        ),
    }
}

/// The proof status as text.
pub fn proof_text(p: &ProofStatus, s: &Structure, prefix: &str) -> String {
    match p {
        ProofStatus::NoProof => "no proof printed in the paper".into(),
        ProofStatus::Verified(n) => format!("✓ every step verified ({n} claims)"),
        ProofStatus::AfterCorrections(ids) => format!(
            "✓ complete after corrections (errata: {})",
            ids_text(ids, s, prefix)
        ),
        ProofStatus::Gap(g) => {
            let parts: Vec<String> = g
                .iter()
                .map(|(i, why)| format!("[`{i}`]({}) {why}", claim_link(s, i, prefix)))
                .collect();
            format!("? has a gap: {}", parts.join("; "))
        }
    }
}

/// The table of the paper's environments that opens `reports/README.md`.
pub fn index_table(input: &ReportInput, s: &Structure) -> String {
    let mut t = String::from("| environment | statement | proof | claims |\n|---|---|---|---|\n");
    for env in environments(input) {
        let r = rollup(s, &env);
        let n = s.claims(&env, None).len();
        let _ = writeln!(
            t,
            "| [{}](proofs/{}.md) | {} | {} | {} |",
            env.name(),
            env.page(),
            statement_text(&r.statement, s, ""),
            proof_text(&r.proof, s, ""),
            n
        );
    }
    t
}

/// A counterexample as decimals (12 significant digits), each variable with what it is
/// (from `vars`, the claim's variables with their definitions), with the exact values in
/// a collapsed block when rounding changed any of them.
pub fn counterexample_block(c: &Counterexample, vars: &[VarDef]) -> String {
    let mut s = String::new();
    let mut exact = String::new();
    let mut changed = false;
    let mut row = |name: &str, value: &str, note: Option<String>, s: &mut String| {
        let (d, ch) = round_numbers(value);
        changed |= ch;
        match note {
            Some(n) => {
                let _ = writeln!(s, "- {name} = `{d}`, {n}");
            }
            None => {
                let _ = writeln!(s, "- {name} = `{d}`");
            }
        }
        let _ = writeln!(exact, "- {name} = `{value}`");
    };
    for p in &c.point {
        let note = vars.iter().find(|v| v.name == p.name).map(VarDef::note);
        row(&format!("`{}`", p.name), &p.value, note, &mut s);
    }
    row("left side", &c.lhs, None, &mut s);
    row("right side", &c.rhs, None, &mut s);
    if changed {
        let _ = write!(
            s,
            "\n<details><summary>Exact values</summary>\n\n{exact}\n</details>\n"
        );
    }
    s
}

/// One claim on an environment page: anchor, verdict, evidence link, printed excerpt,
/// uses, corrections and counterexample.
fn claim_entry(input: &ReportInput, s: &Structure, r: &ClaimResult, n: usize) -> String {
    let mut t = String::new();
    let _ = writeln!(t, "<a id=\"{}\"></a>\n", anchor(&r.id));
    let _ = writeln!(
        t,
        "**{n}. `{}`** — {} · {} · [evidence](../{}.md#{})\n",
        r.id,
        result_badge(r),
        r.form,
        stem_of(r),
        anchor(&r.id)
    );
    let _ = writeln!(t, "{}\n", input.prose(&r.location));
    t.push_str(&printed_markdown(input, &r.printed));
    if r.verdict != Verdict::Defined {
        let _ = writeln!(
            t,
            "Best residual: {}; {}.\n",
            best_residual(r),
            input.prose(&super::cells::tex_powers(&r.reason))
        );
    }
    let uses = s.uses(&r.id);
    if !uses.is_empty() {
        let links: Vec<String> = uses
            .iter()
            .map(|u| {
                let v = s.get(u).map_or("", |x| result_badge(x));
                format!("[`{u}`]({}) ({v})", claim_link(s, u, "../"))
            })
            .collect();
        let _ = writeln!(t, "Uses: {}.\n", links.join(", "));
    }
    if let Some(c) = &r.corrects {
        let _ = writeln!(t, "Corrects [`{c}`]({}).\n", claim_link(s, c, "../"));
    }
    for f in s.corrections(&r.id) {
        let _ = writeln!(
            t,
            "Corrected by [`{}`]({}) — {}.\n",
            f.id,
            claim_link(s, &f.id, "../"),
            result_badge(f)
        );
    }
    if let Some(c) = &r.counterexample {
        let _ = writeln!(
            t,
            "Counterexample:\n\n{}",
            counterexample_block(c, input.variables_of(&r.id))
        );
    }
    t
}

fn statement_section(input: &ReportInput, s: &Structure, env: &Environment) -> String {
    let mut t = String::from("## Statement\n\n");
    if let Some(text) = input.environments.get(&env.name()) {
        let _ = writeln!(t, "{}\n", to_markdown(&text.statement, &input.macros));
    }
    let claims = s.claims(env, Some(Role::Statement));
    let _ = writeln!(t, "Encoded by {} claims:\n", claims.len());
    let _ = writeln!(
        t,
        "| claim | what it checks | form | verdict | best residual (evidence) |"
    );
    let _ = writeln!(t, "|---|---|---|---|---|");
    for r in &claims {
        let _ = writeln!(
            t,
            "| <a id=\"{}\"></a>`{}` | {} | {} | {} | [{}](../{}.md#{}) |",
            anchor(&r.id),
            r.id,
            input.prose(&r.location).replace('|', "\\|"),
            r.form,
            result_badge(r),
            best_residual(r),
            stem_of(r),
            anchor(&r.id)
        );
    }
    t.push('\n');
    for r in claims.iter().filter(|r| r.verdict == Verdict::Refuted) {
        let fixes: Vec<String> = s
            .corrections(&r.id)
            .iter()
            .map(|f| {
                format!(
                    "[`{}`]({}) ({})",
                    f.id,
                    claim_link(s, &f.id, "../"),
                    result_badge(f)
                )
            })
            .collect();
        let _ = writeln!(
            t,
            "`{}` is refuted; corrected by {}.\n",
            r.id,
            if fixes.is_empty() {
                "no claim".to_string()
            } else {
                fixes.join(", ")
            }
        );
        if let Some(n) = &r.note {
            let _ = writeln!(t, "{}\n", input.prose(n));
        }
        if let Some(c) = &r.counterexample {
            let _ = writeln!(
                t,
                "Counterexample:\n\n{}",
                counterexample_block(c, input.variables_of(&r.id))
            );
        }
    }
    t
}

fn proof_section(input: &ReportInput, s: &Structure, env: &Environment) -> String {
    let mut t = String::from("## Proof\n\n");
    let printed = input
        .environments
        .get(&env.name())
        .and_then(|e| e.proof.as_ref());
    if let Some(p) = printed {
        let _ = writeln!(
            t,
            "<details><summary>The printed proof</summary>\n\n{}\n\n</details>\n",
            to_markdown(p, &input.macros)
        );
    }
    let steps = s.claims(env, Some(Role::ProofStep));
    if steps.is_empty() {
        let _ = writeln!(
            t,
            "The paper prints no proof; the statement claims above are checked directly.\n"
        );
        return t;
    }
    let _ = writeln!(t, "The steps, in the paper's order:\n");
    for (j, r) in steps.iter().enumerate() {
        t.push_str(&claim_entry(input, s, r, j + 1));
    }
    t
}

fn other_section(input: &ReportInput, s: &Structure, env: &Environment) -> String {
    let mut t = String::new();
    for (role, title) in [
        (Role::Definition, "Definitions"),
        (Role::Consequence, "Consequences"),
        (Role::Background, "Background facts"),
        (Role::Control, "Controls"),
    ] {
        let claims = s.claims(env, Some(role));
        if claims.is_empty() {
            continue;
        }
        let _ = writeln!(t, "## {title}\n");
        for (j, r) in claims.iter().enumerate() {
            t.push_str(&claim_entry(input, s, r, j + 1));
        }
    }
    t
}

/// The page `reports/proofs/<environment>.md`.
pub fn page(input: &ReportInput, s: &Structure, env: &Environment) -> String {
    let mut t = String::new();
    let r = rollup(s, env);
    let _ = writeln!(t, "# {}\n", env.name());
    let _ = writeln!(
        t,
        "[← report index](../README.md) · [errata](../errata.md) · generated by `{}`\n",
        input.command
    );
    let _ = writeln!(
        t,
        "**Status:** statement {} · proof: {}\n",
        statement_text(&r.statement, s, "../"),
        proof_text(&r.proof, s, "../")
    );
    t.push_str(&statement_section(input, s, env));
    t.push_str(&proof_section(input, s, env));
    t.push_str(&other_section(input, s, env));
    let _ = writeln!(t, "## Dependencies\n");
    t.push_str(&mermaid(s, env));
    let _ = writeln!(
        t,
        "\n*An arrow runs from a claim to a claim that uses it; rounded boxes are the statement, dashed boxes belong to other environments. Definitions and background facts are listed above, not drawn.*"
    );
    t
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claims::verdict::Named;

    fn result(id: &str, verdict: Verdict, form: &str, corrects: Option<&str>) -> ClaimResult {
        ClaimResult {
            id: id.into(),
            labels: vec![],
            location: "l".into(),
            position: "identities/x.toml:1".into(),
            printed: "x".into(),
            rendered: vec![],
            kind: crate::claims::kind::Kind::Identity,
            form: if form == "printed" {
                Form::Printed
            } else {
                Form::Corrected
            },
            corrects: corrects.map(str::to_string),
            expect: None,
            verdict,
            as_expected: true,
            residuals: vec![],
            loss_bits: None,
            max_loss_bits: 24.0,
            samples: 1,
            failures: vec![],
            counterexample: None,
            exact: None,
            proof: crate::claims::verdict::ProofInfo::none("not attempted"),
            note: None,
            reason: String::new(),
            elapsed_ms: 0.0,
        }
    }

    /// The environment of rank 5 (Lemma 1) or 6 (Theorem 1) of the fixture.
    fn env_at(rank: usize) -> Environment {
        let name = if rank == 5 { "Lemma 1" } else { "Theorem 1" };
        Environment {
            rank,
            name: name.to_string(),
            section: false,
        }
    }

    fn place(env: usize, role: Role, uses: &[&str]) -> Place {
        Place {
            environment: env_at(env),
            role,
            uses: uses.iter().map(|u| u.to_string()).collect(),
        }
    }

    /// Lemma 1 (index 5): statement s, steps p1, p2 (p2 uses x of Theorem 1).
    fn fixture(
        vs: [Verdict; 4],
        fix: Option<Verdict>,
    ) -> (Vec<ClaimResult>, BTreeMap<String, Place>) {
        let mut rs = vec![
            result("s", vs[0], "printed", None),
            result("p1", vs[1], "printed", None),
            result("p2", vs[2], "printed", None),
            result("x", vs[3], "printed", None),
        ];
        let mut pl = BTreeMap::from([
            ("s".to_string(), place(5, Role::Statement, &["p2"])),
            ("p1".to_string(), place(5, Role::ProofStep, &[])),
            ("p2".to_string(), place(5, Role::ProofStep, &["p1", "x"])),
            ("x".to_string(), place(6, Role::Statement, &[])),
        ]);
        if let Some(v) = fix {
            let target = if vs[0] == Verdict::Refuted { "s" } else { "x" };
            rs.push(result("fix", v, "corrected", Some(target)));
            let env = if target == "s" { 5 } else { 6 };
            pl.insert("fix".into(), place(env, Role::Statement, &[]));
        }
        (rs, pl)
    }

    fn roll(vs: [Verdict; 4], fix: Option<Verdict>) -> Rollup {
        let (rs, pl) = fixture(vs, fix);
        let s = Structure::new(&rs, &pl);
        rollup(&s, &env_at(5))
    }

    use Verdict::{Holds as H, Inconclusive as I, Proved as P, Refuted as R};

    #[test]
    fn statement_rule() {
        assert_eq!(roll([P, P, P, P], None).statement, StatementStatus::Proved);
        assert_eq!(roll([H, P, P, P], None).statement, StatementStatus::Holds);
        assert_eq!(
            roll([I, P, P, P], None).statement,
            StatementStatus::Inconclusive(vec!["s".into()])
        );
        assert_eq!(
            roll([R, P, P, P], Some(P)).statement,
            StatementStatus::FailsAsPrinted {
                refuted: vec!["s".into()],
                corrected: Box::new(StatementStatus::Proved)
            }
        );
        assert_eq!(
            roll([R, P, P, P], None).statement,
            StatementStatus::FailsAsPrinted {
                refuted: vec!["s".into()],
                corrected: Box::new(StatementStatus::Missing)
            }
        );
    }

    #[test]
    fn proof_rule() {
        assert_eq!(roll([P, H, P, P], None).proof, ProofStatus::Verified(3));
        // a refuted claim used by a step, with a correction that holds
        assert_eq!(
            roll([P, P, P, R], Some(H)).proof,
            ProofStatus::AfterCorrections(vec!["x".into()])
        );
        // ... and without one
        assert_eq!(
            roll([P, P, P, R], Some(R)).proof,
            ProofStatus::Gap(vec![("x".into(), "refuted, no correction holds".into())])
        );
        assert_eq!(
            roll([P, I, P, P], None).proof,
            ProofStatus::Gap(vec![("p1".into(), "inconclusive".into())])
        );
        let (rs, mut pl) = fixture([P, P, P, P], None);
        pl.get_mut("p1").unwrap().role = Role::Consequence;
        pl.get_mut("p2").unwrap().role = Role::Consequence;
        let s = Structure::new(&rs, &pl);
        assert_eq!(proof_status(&s, &env_at(5)), ProofStatus::NoProof);
    }

    #[test]
    fn diagram_draws_uses_and_other_environments() {
        let (rs, pl) = fixture([H, H, H, R], Some(H));
        let s = Structure::new(&rs, &pl);
        let m = mermaid(&s, &env_at(5));
        assert!(m.starts_with("```mermaid\nflowchart TD\n"), "{m}");
        assert!(m.contains("n0([\"s<br/>✓ holds\"]):::holds"), "{m}");
        assert!(
            m.contains("n3[\"x<br/>✗ refuted · Theorem 1\"]:::refuted_ext"),
            "{m}"
        );
        for e in ["n2 --> n0", "n1 --> n2", "n3 --> n2"] {
            assert!(m.contains(e), "{e} in {m}");
        }
        assert_eq!(m, mermaid(&s, &env_at(5)));
    }

    #[test]
    fn a_graph_too_wide_and_too_deep_is_drawn_in_parts_that_fit() {
        // s uses six chains c{i}.1 -> c{i}.2 -> ... -> c{i}.6
        let mut rs = vec![result("s", H, "printed", None)];
        let mut pl = BTreeMap::new();
        let heads: Vec<String> = (1..=6).map(|i| format!("c{i}.1")).collect();
        let head_refs: Vec<&str> = heads.iter().map(String::as_str).collect();
        pl.insert("s".to_string(), place(5, Role::Statement, &head_refs));
        for i in 1..=6 {
            for j in 1..=6 {
                let id = format!("c{i}.{j}");
                let next = format!("c{i}.{}", j + 1);
                let uses: Vec<&str> = if j < 6 { vec![next.as_str()] } else { vec![] };
                rs.push(result(&id, H, "printed", None));
                pl.insert(id, place(5, Role::ProofStep, &uses));
            }
        }
        let st = Structure::new(&rs, &pl);
        let m = mermaid(&st, &env_at(5));
        // s with its six direct uses (left to right), then one diagram per chain
        assert!(m.contains("drawn in 7 diagrams"), "{m}");
        assert_eq!(m.matches("flowchart LR").count(), 1, "{m}");
        assert_eq!(m.matches("flowchart TD").count(), 6, "{m}");
        assert!(m.contains("What `c3.1` rests on:"), "{m}");
        assert_eq!(m, mermaid(&st, &env_at(5)));
    }

    #[test]
    fn counterexamples_in_decimals_with_exact_values_folded() {
        let c = Counterexample {
            bits: 0,
            point: vec![Named {
                name: "A".into(),
                value: "1/3".into(),
            }],
            lhs: "2".into(),
            rhs: "5e-1".into(),
            log2_residual: None,
        };
        let b = counterexample_block(&c, &[]);
        assert!(
            b.starts_with("- `A` = `0.333333333333`\n- left side = `2`\n- right side = `0.5`\n"),
            "{b}"
        );
        assert!(
            b.contains("<details><summary>Exact values</summary>\n\n- `A` = `1/3`"),
            "{b}"
        );
        let c = Counterexample { point: vec![], ..c };
        assert!(!counterexample_block(&c, &[]).contains("<details>"));
    }

    #[test]
    fn counterexample_variables_say_what_they_are() {
        let named = |name: &str, value: &str| Named {
            name: name.into(),
            value: value.into(),
        };
        let c = Counterexample {
            bits: 53,
            point: vec![named("kK", "1.5"), named("x", "0.25")],
            lhs: "1".into(),
            rhs: "2".into(),
            log2_residual: None,
        };
        let def = |name: &str, sampled: bool, text: &str, latex: &str| VarDef {
            name: name.into(),
            sampled,
            text: text.into(),
            latex: latex.into(),
            about: None,
        };
        let mut kk = def("kK", false, "K(k)", "K(k)");
        let vars = [kk.clone(), def("x", true, "uniform(0, 1)", "-")];
        let b = counterexample_block(&c, &vars);
        assert!(
            b.contains("- `kK` = `1.5`, where $\\mathrm{kK} = K(k)$\n"),
            "{b}"
        );
        assert!(
            b.contains("- `x` = `0.25`, drawn as `uniform(0, 1)`\n"),
            "{b}"
        );
        // with a description, the description first
        kk.about = Some("$K$, the quarter period".into());
        let b = counterexample_block(&c, &[kk]);
        assert!(
            b.contains("- `kK` = `1.5`, $K$, the quarter period, where $\\mathrm{kK} = K(k)$\n"),
            "{b}"
        );
    }
}
