//! The Mermaid dependency diagrams of the environment pages, laid out to stay readable at
//! page width: short node labels (claim ids broken at their dots), top-down or left-right
//! whichever is narrower, and a large graph split into one diagram per claim that no
//! other drawn claim uses, with what it rests on.

use super::cells::result_badge;
use super::proofs::Structure;
use crate::claims::structure::{Environment, Role};
use crate::claims::verdict::{ClaimResult, Verdict};
use std::collections::BTreeSet;
use std::fmt::Write;

/// The most boxes side by side in a diagram (a row of the top-down layout, a column of
/// ranks in the left-right one) before it is split.
const MAX_ACROSS: usize = 5;
/// The longest line of a node label, in characters.
const LABEL_LINE: usize = 18;

/// A dependency graph: its nodes (claim, inside the environment) and its edges (user
/// index after used index).
struct Graph<'a> {
    nodes: Vec<(&'a ClaimResult, bool)>,
    edges: Vec<(usize, usize)>,
}

fn verdict_class(v: Verdict) -> &'static str {
    match v {
        Verdict::Holds => "holds",
        Verdict::Proved => "proved",
        Verdict::Construction => "construction",
        Verdict::Refuted => "refuted",
        Verdict::Inconclusive => "inconclusive",
        Verdict::Defined => "defined",
    }
}

/// Is a claim drawn: a statement, proof step or consequence?
fn drawn_role(s: &Structure, id: &str) -> bool {
    s.places.get(id).is_some_and(|p| {
        matches!(
            p.role,
            Role::Statement | Role::ProofStep | Role::Consequence
        )
    })
}

/// The environment's claims (definitions, background and controls left out) and the
/// statements and steps of other environments that they use.
fn graph<'a>(s: &'a Structure, env: &Environment) -> Graph<'a> {
    let own: Vec<&ClaimResult> = s
        .claims(env, None)
        .into_iter()
        .filter(|r| drawn_role(s, &r.id))
        .collect();
    let own_ids: BTreeSet<&str> = own.iter().map(|r| r.id.as_str()).collect();
    let mut nodes: Vec<(&ClaimResult, bool)> = own.iter().map(|r| (*r, true)).collect();
    let mut edges: Vec<(String, String)> = Vec::new();
    for r in &own {
        for u in s.uses(&r.id) {
            let Some(ur) = s.get(u) else { continue };
            if !own_ids.contains(u.as_str()) && !drawn_role(s, u) {
                continue;
            }
            if !nodes.iter().any(|(n, _)| n.id == *u) {
                nodes.push((ur, false));
            }
            edges.push((u.clone(), r.id.clone()));
        }
    }
    let key = |id: &str| nodes.iter().position(|(n, _)| n.id == id).unwrap_or(0);
    let edges = edges.iter().map(|(a, b)| (key(a), key(b))).collect();
    Graph { nodes, edges }
}

/// The rank of each node of `part`: the longest chain of uses from it to a claim that
/// nothing in `part` uses (as the layout ranks a graph: a claim sits just above its
/// nearest user), by node index.
fn ranks(g: &Graph, part: &[usize]) -> Vec<usize> {
    let mut rank = vec![0usize; g.nodes.len()];
    // a chain is at most |part| long; relax that often (a cycle cannot raise it further)
    for _ in 0..part.len() {
        let mut changed = false;
        for &(a, b) in &g.edges {
            if part.contains(&a)
                && part.contains(&b)
                && rank[a] < rank[b] + 1
                && rank[b] < part.len()
            {
                rank[a] = rank[b] + 1;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    rank
}

/// The widest row of the top-down layout of `part` and its number of ranks.
fn extent(g: &Graph, part: &[usize]) -> (usize, usize) {
    let rank = ranks(g, part);
    let depth = part.iter().map(|&n| rank[n]).max().map_or(0, |r| r + 1);
    let widest = (0..depth)
        .map(|r| part.iter().filter(|&&n| rank[n] == r).count())
        .max()
        .unwrap_or(0);
    (widest, depth)
}

/// `n` with everything it rests on, in node order.
fn closure(g: &Graph, n: usize) -> Vec<usize> {
    let mut part = BTreeSet::from([n]);
    let mut todo = vec![n];
    while let Some(x) = todo.pop() {
        for &(a, b) in &g.edges {
            if b == x && part.insert(a) {
                todo.push(a);
            }
        }
    }
    part.into_iter().collect()
}

/// The parts that draw what `n` rests on: all of it when that fits the page; else `n`
/// with the claims it uses directly, then the parts of each of those.
fn parts_below(g: &Graph, n: usize, out: &mut Vec<(Option<usize>, Vec<usize>)>) {
    let all = closure(g, n);
    if direction(g, &all).is_some() || out.len() > g.nodes.len() {
        out.push((Some(n), all));
        return;
    }
    let direct: BTreeSet<usize> = g.edges.iter().filter(|e| e.1 == n).map(|e| e.0).collect();
    let mut star = direct.clone();
    star.insert(n);
    out.push((Some(n), star.into_iter().collect()));
    for d in direct {
        if g.edges.iter().any(|e| e.1 == d) && !out.iter().any(|(top, _)| *top == Some(d)) {
            parts_below(g, d, out);
        }
    }
}

/// The parts a large graph is drawn in: for each node that no other node uses (in node
/// order), what it rests on ([`parts_below`]); the nodes that use nothing and that
/// nothing uses go together into one part (without a node of its own).
fn parts(g: &Graph) -> Vec<(Option<usize>, Vec<usize>)> {
    let mut out = Vec::new();
    let mut alone = Vec::new();
    for n in 0..g.nodes.len() {
        if g.edges.iter().any(|&(a, _)| a == n) {
            continue;
        }
        if g.edges.iter().any(|&(_, b)| b == n) {
            parts_below(g, n, &mut out);
        } else {
            alone.push(n);
        }
    }
    if !alone.is_empty() {
        out.push((None, alone));
    }
    out
}

/// A claim id broken after its dots into lines of at most [`LABEL_LINE`] characters
/// (a longer piece stays whole).
fn label_id(id: &str) -> String {
    let mut lines: Vec<String> = vec![String::new()];
    for piece in id.split_inclusive('.') {
        let cur = lines.last_mut().expect("one line");
        if !cur.is_empty() && cur.chars().count() + piece.chars().count() > LABEL_LINE {
            lines.push(piece.to_string());
        } else {
            cur.push_str(piece);
        }
    }
    lines.join("<br/>")
}

/// The label of a node: the claim id (broken at its dots), its verdict and, for a claim
/// of another environment, that environment.
fn label(s: &Structure, r: &ClaimResult, inside: bool) -> String {
    let badge = result_badge(r).replacen(" (", "<br/>(", 1);
    let env_note = if inside {
        String::new()
    } else {
        s.places
            .get(&r.id)
            .map(|p| format!(" · {}", p.environment.name()))
            .unwrap_or_default()
    };
    format!("{}<br/>{badge}{env_note}", label_id(&r.id))
}

/// Does `part` fit across the page top-down (`Some("TD")`) or left-right (`Some("LR")`)?
fn direction(g: &Graph, part: &[usize]) -> Option<&'static str> {
    let (widest, depth) = extent(g, part);
    if widest <= MAX_ACROSS {
        Some("TD")
    } else if depth <= MAX_ACROSS {
        Some("LR")
    } else {
        None
    }
}

/// One Mermaid block drawing the nodes of `part` and the edges between them.
fn block(s: &Structure, env: &Environment, g: &Graph, part: &[usize]) -> String {
    let dir = direction(g, part).unwrap_or_else(|| {
        let (widest, depth) = extent(g, part);
        if widest <= depth { "TD" } else { "LR" }
    });
    let mut m = format!("```mermaid\nflowchart {dir}\n");
    for &j in part {
        let (r, inside) = g.nodes[j];
        let statement = s
            .places
            .get(&r.id)
            .is_some_and(|p| p.role == Role::Statement && p.environment == *env);
        let (open, close) = if statement { ("([", "])") } else { ("[", "]") };
        let _ = writeln!(
            m,
            "  n{j}{open}\"{}\"{close}:::{}{}",
            label(s, r, inside),
            verdict_class(r.verdict),
            if inside { "" } else { "_ext" }
        );
    }
    for &(a, b) in &g.edges {
        if part.contains(&a) && part.contains(&b) {
            let _ = writeln!(m, "  n{a} --> n{b}");
        }
    }
    m.push_str(MERMAID_CLASSES);
    m.push_str("```\n");
    m
}

/// The Mermaid dependency diagram of an environment: the environment's claims
/// (definitions, background and controls left out) and the statements and steps of other
/// environments that they use; a graph too wide for the page is drawn in parts, one per
/// claim that no other drawn claim uses, each with what that claim rests on.
pub fn mermaid(s: &Structure, env: &Environment) -> String {
    let g = graph(s, env);
    let all: Vec<usize> = (0..g.nodes.len()).collect();
    if all.is_empty() || direction(&g, &all).is_some() {
        return block(s, env, &g, &all);
    }
    let parts = parts(&g);
    let mut m = format!(
        "The {} claims are drawn in {} diagrams, so that each fits the page: one per claim that no other drawn claim uses, with everything it rests on (a claim that rests on too much for one diagram is drawn with the claims it uses directly, each of which gets its own diagram).\n\n",
        g.nodes.len(),
        parts.len()
    );
    for (top, part) in &parts {
        let title = match top {
            Some(n) => format!("What `{}` rests on:", g.nodes[*n].0.id),
            None => "Claims that use no drawn claim and that no drawn claim uses:".to_string(),
        };
        let _ = writeln!(m, "{title}\n\n{}", block(s, env, &g, part));
    }
    m
}

/// The styles of the nodes, by verdict (`_ext`: a claim of another environment).
const MERMAID_CLASSES: &str = concat!(
    "  classDef proved fill:#1a7f37,stroke:#116329,color:#ffffff\n",
    "  classDef holds fill:#dafbe1,stroke:#1a7f37,color:#000000\n",
    "  classDef refuted fill:#ffebe9,stroke:#cf222e,color:#000000\n",
    "  classDef inconclusive fill:#fff8c5,stroke:#9a6700,color:#000000\n",
    "  classDef defined fill:#f6f8fa,stroke:#57606a,color:#000000\n",
    "  classDef construction fill:#ddf4ff,stroke:#0969da,color:#000000\n",
    "  classDef proved_ext fill:#1a7f37,stroke:#116329,color:#ffffff,stroke-dasharray:4 3\n",
    "  classDef holds_ext fill:#dafbe1,stroke:#1a7f37,color:#000000,stroke-dasharray:4 3\n",
    "  classDef refuted_ext fill:#ffebe9,stroke:#cf222e,color:#000000,stroke-dasharray:4 3\n",
    "  classDef inconclusive_ext fill:#fff8c5,stroke:#9a6700,color:#000000,stroke-dasharray:4 3\n",
    "  classDef defined_ext fill:#f6f8fa,stroke:#57606a,color:#000000,stroke-dasharray:4 3\n",
    "  classDef construction_ext fill:#ddf4ff,stroke:#0969da,color:#000000,stroke-dasharray:4 3\n",
);
