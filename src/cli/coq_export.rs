//! `eulertop prove ID --coq FILE`: a certificate (module
//! [`crate::algebra::certificate`]) written as a Coq script that the Coq kernel checks.
//!
//! The script declares, in one `Section` per certificate case:
//!
//! * every field symbol and root as a `Variable` of `R` (Coq's real numbers), and every
//!   root relation `r² = a` as a hypothesis `rel_r`;
//! * the value of `sn`, `cn`, `dn` at each combination of base arguments other than a
//!   base argument itself as a variable `ell_N` with the addition-theorem instance the
//!   prover used as a hypothesis `inst_N` (DLMF 22.8, 22.4, 22.5; the SymPy recheck
//!   recomputes these instances with its own addition formulae);
//! * every denominator of a normal form as nonzero (`nz_N`), every divisor as nonzero
//!   (`dz_N`), and the branch of every square root as a sign (`br_N : 0 <= value`).
//!
//! Then every node `tN` of the derivation is a `Definition t_N` of its operation, and a
//! lemma `e_N : t_N = num / den` proves its value without normalising a large term with
//! `field`: the arguments' values, as fractions, are combined into one fraction by the
//! preamble's lemmas on atoms (`eu_addq`, `eu_mulq`, … applied by the tactic `eu_comb`),
//! and the normal form follows by `ring` on the cross-multiplied numerators, with the
//! root relations `r² = a` as rewriting rules (`ring [rel_r …]`; the cofactors `qᵢ` with
//! `num·den' − num'·den = Σ qᵢ (rᵢ² − aᵢ)` name the relations a step uses).  A node
//! without a normal form is stated as `eu_comb` builds it, so that its value is expanded
//! once, where it is used.  The theorem
//! `claim_holds` states `lhs − rhs = 0` for every claim line, and `Print Assumptions`
//! lists what it rests on: the declared variables and hypotheses, and the axioms of
//! Coq's real numbers.  Derivatives are not exported (a claim whose derivation needs
//! one is refused); the symbols are real, so a root of a negative constant (the
//! imaginary unit) is refused too.

use super::coq_poly::Symbols;
use crate::algebra::flint::Poly;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt::Write;

/// The lemmas and tactics every script starts with (all proved in the script).
const PREAMBLE: &str = "From Coq Require Import Rbase Rfunctions R_sqrt Lra.
Open Scope R_scope.

Lemma eu_frac a b n e : b <> 0 -> e <> 0 -> a * e - n * b = 0 -> a / b = n / e.
Proof. intros hb he h. field_simplify_eq; [lra | auto..]. Qed.
Lemma eu_fracp a b n : b <> 0 -> a - n * b = 0 -> a / b = n.
Proof. intros hb h. field_simplify_eq; [lra | auto]. Qed.
Lemma eu_pfrac a n e : e <> 0 -> a * e - n = 0 -> a = n / e.
Proof. intros he h. field_simplify_eq; [lra | auto]. Qed.
Lemma eu_same a n e : a - n = 0 -> a / e = n / e.
Proof. intros h. replace a with n by lra. reflexivity. Qed.
Lemma eu_fracr a q n e r : q <> 0 -> e * r = q -> a - n * r = 0 -> a / q = n / e.
Proof.
  intros hq h ha. subst q.
  assert (e <> 0) by (intro z; apply hq; rewrite z; ring).
  assert (r <> 0) by (intro z; apply hq; rewrite z; ring).
  replace a with (n * r) by lra. field. auto.
Qed.
Lemma eu_num x p q : x = p / q -> x <> 0 -> p <> 0.
Proof. intros h hx hp. apply hx. rewrite h, hp. unfold Rdiv. ring. Qed.
Lemma eu_nump x p : x = p -> x <> 0 -> p <> 0.
Proof. intros h hx. rewrite <- h. exact hx. Qed.
Lemma eu_sqrt x y : 0 <= y -> y * y = x -> sqrt x = y.
Proof. intros hy h. apply sqrt_lem_1; [rewrite <- h; nra | exact hy | exact h]. Qed.
Lemma eu_nzl x y : x * y <> 0 -> x <> 0.
Proof. intros h e. apply h. rewrite e. ring. Qed.
Lemma eu_nzr x y : x * y <> 0 -> y <> 0.
Proof. intros h e. apply h. rewrite e. ring. Qed.
Lemma eu_nzpow x n : x ^ S n <> 0 -> x <> 0.
Proof. intros h e. apply h. rewrite e. simpl. ring. Qed.
(* a polynomial as a fraction, and the arithmetic of fractions on atoms: the steps
   combine fractions with these instead of normalising large terms with field *)
Lemma eu_f x p : x = p -> x = p / 1.
Proof. intros h. rewrite h. field. Qed.
Lemma eu_mulq a b c d : b <> 0 -> d <> 0 -> a / b * (c / d) = (a * c) / (b * d).
Proof. intros. field. auto. Qed.
Lemma eu_addq a b c d : b <> 0 -> d <> 0 -> a / b + c / d = (a * d + c * b) / (b * d).
Proof. intros. field. auto. Qed.
Lemma eu_subq a b c d : b <> 0 -> d <> 0 -> a / b - c / d = (a * d - c * b) / (b * d).
Proof. intros. field. auto. Qed.
Lemma eu_oppq a b : - (a / b) = (- a) / b.
Proof. unfold Rdiv. ring. Qed.
Lemma eu_zaddq a b : 0 + a / b = a / b.
Proof. ring. Qed.
Lemma eu_zsubq a b : 0 - a / b = (- a) / b.
Proof. unfold Rdiv. ring. Qed.
Lemma eu_divq a b c d : b <> 0 -> c <> 0 -> d <> 0 -> a / b / (c / d) = (a * d) / (b * c).
Proof. intros. field. auto. Qed.
Lemma eu_powq a b n : b <> 0 -> (a / b) ^ n = a ^ n / b ^ n.
Proof. intros. unfold Rdiv. rewrite Rpow_mult_distr, pow_inv. reflexivity. Qed.
Lemma eu_ipowq a b n : a <> 0 -> b <> 0 -> / ((a / b) ^ n) = b ^ n / a ^ n.
Proof. intros. rewrite eu_powq by auto. field. split; apply pow_nonzero; auto. Qed.
(* every factor of a nonzero product is nonzero *)
Ltac nzsat := repeat match goal with
  | H : ?x * ?y <> 0 |- _ =>
      lazymatch goal with _ : x <> 0, _ : y <> 0 |- _ => fail | _ => idtac end;
      pose proof (eu_nzl _ _ H); pose proof (eu_nzr _ _ H)
  | H : ?x ^ S ?n <> 0 |- _ =>
      lazymatch goal with _ : x <> 0 |- _ => fail | _ => pose proof (eu_nzpow _ _ H) end
  end.
Ltac nzp := nzsat;
  repeat first [apply Rmult_integral_contrapositive_currified | apply pow_nonzero];
  first [assumption | lra].
(* an operation on fractions as one fraction, innermost first *)
Ltac eu_comb := repeat match goal with
  | |- context [?a / ?b * (?c / ?d)] => rewrite (eu_mulq a b c d) by nzp
  | |- context [0 + ?a / ?b] => rewrite (eu_zaddq a b)
  | |- context [0 - ?a / ?b] => rewrite (eu_zsubq a b)
  | |- context [?a / ?b + ?c / ?d] => rewrite (eu_addq a b c d) by nzp
  | |- context [?a / ?b - ?c / ?d] => rewrite (eu_subq a b c d) by nzp
  | |- context [- (?a / ?b)] => rewrite (eu_oppq a b)
  | |- context [?a / ?b / (?c / ?d)] => rewrite (eu_divq a b c d) by nzp
  | |- context [/ ((?a / ?b) ^ ?n)] => rewrite (eu_ipowq a b n) by nzp
  | |- context [(?a / ?b) ^ ?n] => rewrite (eu_powq a b n) by nzp
  end.
";

/// The prefixes of the names the script gives; a symbol may not start with one.
const RESERVED: [&str; 11] = [
    "t_", "e_", "nz_", "dz_", "z_", "br_", "ell_", "inst_", "rel_", "eu_", "cl_",
];

/// Coq keywords, which a symbol may not be.
const KEYWORDS: [&str; 20] = [
    "as", "at", "cofix", "else", "end", "exists", "fix", "for", "forall", "fun", "if", "in", "let",
    "match", "mod", "Prop", "return", "Set", "then", "Type",
];

/// The Coq script of a certificate (the text `eulertop prove ID --certificate` writes),
/// or why it cannot be written.
///
/// ```
/// use eulertop::cli::coq_export::coq_script;
/// let cert = "# eulertop certificate 1\nclaims 1\nfield s sn\nroot c = -s**2 + 1\n\
///             node t1 = c\nnode t2 = t1 * t1 -> (-s**2 + 1)/(1)\nnode t3 = s\n\
///             node t4 = t3 * t3 -> (s**2)/(1)\nnode t5 = t2 + t4\nnode t6 = 1\n\
///             claim t5 = t6\n";
/// let coq = coq_script(cert).unwrap();
/// assert!(coq.contains("Theorem claim_holds : t_5 - t_6 = 0."));
/// assert!(coq.contains("Hypothesis rel_c : c ^ 2 = (- s ^ 2 + 1)."));
/// assert!(!coq.contains("Admitted"));
/// assert!(coq_script("# eulertop certificate 1\nnode t1 = d t0 x\n").is_err());
/// ```
pub fn coq_script(certificate: &str) -> Result<String, String> {
    let blocks = split_blocks(certificate);
    if blocks.is_empty() {
        return Err("the certificate has no derivation".into());
    }
    let mut out = String::from("(* eulertop: a certificate as a Coq script (coqc checks it) *)\n");
    for line in blocks[0].iter().filter(|l| l.starts_with("source ")) {
        let _ = writeln!(out, "(* {} *)", comment(line));
    }
    out.push_str(PREAMBLE);
    let several = blocks.len() > 1;
    for (i, block) in blocks.iter().enumerate() {
        let name = if several {
            format!("Case{}", i + 1)
        } else {
            "Claim".into()
        };
        let theorem = if several {
            format!("claim_holds_case{}", i + 1)
        } else {
            "claim_holds".into()
        };
        out.push_str(&section(block, &name, &theorem)?);
    }
    Ok(out)
}

/// The certificate's lines, one list per case (a new case at each header line).
fn split_blocks(certificate: &str) -> Vec<Vec<&str>> {
    let mut blocks: Vec<Vec<&str>> = Vec::new();
    for line in certificate.lines() {
        if line.starts_with("# eulertop certificate") {
            blocks.push(Vec::new());
        } else if let Some(b) = blocks.last_mut() {
            b.push(line);
        }
    }
    blocks
}

/// A text as the inside of a Coq comment: no quotes (Coq reads strings in comments)
/// and no comment delimiters.
fn comment(text: &str) -> String {
    text.replace('"', "''")
        .replace("(*", "( *")
        .replace("*)", "* )")
}

/// A value as the script writes it: a numerator over a product of denominators (an
/// empty product is 1), the product written `dt` as the steps of [`PREAMBLE`] build it
/// (empty for a polynomial).  The numerator is written expanded, or, for a node
/// without a normal form, as the steps build it (`nt`), which spares expanding it
/// twice.
#[derive(Clone)]
struct Val {
    num: Poly,
    den: Vec<Poly>,
    dt: String,
    nt: Option<String>,
}

/// One parsed `node` line.
struct NodeLine {
    body: Vec<String>,
    nf: Option<String>,
}

/// The state of one section while it is written.
struct Section {
    sym: Symbols,
    /// `base` lines: the base's name → its `s`, `c`, `d` and argument texts.
    bases: HashMap<String, [String; 4]>,
    vals: HashMap<usize, Val>,
    /// A nonzero denominator (as written) → the hypothesis or lemma that states it.
    facts: HashMap<String, String>,
    /// The nodes that divide (a divisor or the base of a negative power): their
    /// numerator is written expanded, as the lemma of their nonzero numerator states it.
    divisors: BTreeSet<usize>,
    decls: String,
    body: String,
}

/// The Coq section of one certificate case.
fn section(lines: &[&str], name: &str, theorem: &str) -> Result<String, String> {
    let mut s = Section::declare(lines)?;
    let nodes = parse_nodes(lines)?;
    let claims = parse_claims(lines)?;
    let needed = reachable(&nodes, &claims);
    s.divisors = divisors(&nodes);
    for (id, node) in &nodes {
        if needed.contains(id) {
            s.node(*id, node)?;
        }
    }
    let statement = s.claims(&claims, theorem)?;
    // a module of its own per case: the definitions outlive the section
    let mut out = format!("\nModule {name}.\nSection {name}.\n");
    for line in lines.iter().filter(|l| l.starts_with("assume ")) {
        let _ = writeln!(out, "(* rests on: {} *)", comment(&l_tail(line)));
    }
    out.push_str(&s.decls);
    out.push_str(&s.body);
    out.push_str(&statement);
    let _ = writeln!(
        out,
        "Print Assumptions {theorem}.\nEnd {name}.\nEnd {name}."
    );
    Ok(out)
}

/// A line without its first word.
fn l_tail(line: &str) -> String {
    line.split_once(' ').map_or("", |(_, t)| t).to_string()
}

/// The `node` lines by number.
fn parse_nodes(lines: &[&str]) -> Result<BTreeMap<usize, NodeLine>, String> {
    let mut nodes = BTreeMap::new();
    for line in lines.iter().filter_map(|l| l.strip_prefix("node t")) {
        let (id, rest) = line
            .split_once(" = ")
            .ok_or_else(|| format!("malformed node line 'node t{line}'"))?;
        let id: usize = id.parse().map_err(|_| format!("malformed node id t{id}"))?;
        let (body, nf) = match rest.split_once(" -> ") {
            Some((b, nf)) => (b, Some(nf.trim_start_matches("+1 ").to_string())),
            None => (rest, None),
        };
        let body = body.split_whitespace().map(str::to_string).collect();
        nodes.insert(id, NodeLine { body, nf });
    }
    Ok(nodes)
}

/// The `claim tA = tB` lines as node numbers.
fn parse_claims(lines: &[&str]) -> Result<Vec<(usize, usize)>, String> {
    let node = |t: &str| t.trim().strip_prefix('t').and_then(|n| n.parse().ok());
    let claims: Vec<(usize, usize)> = (lines.iter())
        .filter_map(|l| l.strip_prefix("claim "))
        .map(|c| {
            c.split_once(" = ")
                .and_then(|(a, b)| Some((node(a)?, node(b)?)))
                .ok_or_else(|| format!("malformed claim line 'claim {c}'"))
        })
        .collect::<Result<_, _>>()?;
    if claims.is_empty() {
        return Err("the certificate states no claim".into());
    }
    Ok(claims)
}

/// The node numbers of an operation's arguments (none for a symbol, a constant, or an
/// elliptic function, whose value the script takes from the bases).
fn node_args(body: &[String]) -> Vec<usize> {
    if body.len() == 1 || ["sn", "cn", "dn"].contains(&body[0].as_str()) {
        return Vec::new();
    }
    (body.iter())
        .filter_map(|t| t.strip_prefix('t').and_then(|n| n.parse().ok()))
        .collect()
}

/// The nodes that divide: a divisor of `/` or the base of a negative power.
fn divisors(nodes: &BTreeMap<usize, NodeLine>) -> BTreeSet<usize> {
    let arg = |t: &String| t.strip_prefix('t').and_then(|n| n.parse().ok());
    (nodes.values())
        .filter_map(|n| match n.body.as_slice() {
            [_, op, c] if op == "/" => arg(c),
            [a, op, e] if op == "^" && e.starts_with('-') => arg(a),
            _ => None,
        })
        .collect()
}

/// The nodes the claims depend on, in the script's definitions.
fn reachable(nodes: &BTreeMap<usize, NodeLine>, claims: &[(usize, usize)]) -> BTreeSet<usize> {
    let mut seen = BTreeSet::new();
    let mut stack: Vec<usize> = claims.iter().flat_map(|&(a, b)| [a, b]).collect();
    while let Some(id) = stack.pop() {
        if seen.insert(id)
            && let Some(n) = nodes.get(&id)
        {
            stack.extend(node_args(&n.body));
        }
    }
    seen
}

impl Section {
    /// The symbols, roots and bases of a case, and their declarations.
    fn declare(lines: &[&str]) -> Result<Section, String> {
        if lines.iter().any(|l| l.starts_with("named ")) {
            return Err("the Coq export does not cover named quantities".into());
        }
        let field = |l: &&str| l.strip_prefix("field ").map(|t| word(t, 0));
        let root = |l: &&str| l.strip_prefix("root ").map(|t| word(t, 0));
        let names: Vec<String> = lines.iter().filter_map(field).collect();
        let roots: Vec<String> = lines.iter().filter_map(root).collect();
        for n in names.iter().chain(&roots) {
            check_name(n)?;
        }
        let all: Vec<String> = names.iter().chain(&roots).cloned().collect();
        let mut s = Section {
            sym: Symbols::new(all.clone())?,
            bases: HashMap::new(),
            vals: HashMap::new(),
            facts: HashMap::new(),
            divisors: BTreeSet::new(),
            decls: String::new(),
            body: String::new(),
        };
        if !all.is_empty() {
            let _ = writeln!(s.decls, "Variables {} : R.", all.join(" "));
        }
        for l in lines.iter().filter_map(|l| l.strip_prefix("root ")) {
            s.root(l)?;
        }
        for l in lines.iter().filter_map(|l| l.strip_prefix("base ")) {
            s.base(l);
        }
        Ok(s)
    }

    /// A `root r = a  # note` line: the relation `r² = a` as a hypothesis.
    fn root(&mut self, line: &str) -> Result<(), String> {
        let (def, note) = line.split_once("  # ").unwrap_or((line, ""));
        let (name, rad) = def
            .split_once(" = ")
            .ok_or_else(|| format!("malformed root line 'root {line}'"))?;
        let rad = self.sym.parse(rad)?;
        if rad.as_constant().is_some_and(|c| c < 0) {
            return Err(format!(
                "the root {name} of a negative constant is not real, and the Coq export declares real symbols"
            ));
        }
        let v = self.sym.var(name)?;
        let _ = writeln!(
            self.decls,
            "(* {} *)\nHypothesis rel_{name} : {name} ^ 2 = {}.",
            comment(note),
            self.sym.coq(&rad)
        );
        let idx = self.sym.names.iter().position(|n| n == name).unwrap_or(0);
        debug_assert!(!v.is_zero());
        self.sym.roots.push((idx, rad));
        Ok(())
    }

    /// A `base b k=… s=… c=… d=… arg=…` line.
    fn base(&mut self, line: &str) {
        let field = |key: &str| {
            line.split_once(&format!(" {key}="))
                .map_or(String::new(), |(_, r)| value_text(r).to_string())
        };
        let name = word(line, 0);
        let vals = [field("s"), field("c"), field("d"), field("arg")];
        self.bases.insert(name, vals);
    }
}

/// The value at the start of `text`: a fraction `(N)/(D)` (whose parts may hold
/// spaces) or one word.
fn value_text(text: &str) -> &str {
    if !text.starts_with('(') {
        return text.split(' ').next().unwrap_or("");
    }
    let mut depth = 0;
    let mut groups = 0;
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    groups += 1;
                    if groups == 2 || !text[i + 1..].starts_with("/(") {
                        return &text[..=i];
                    }
                }
            }
            _ => {}
        }
    }
    text
}

/// Word `i` of a line.
fn word(line: &str, i: usize) -> String {
    line.split_whitespace().nth(i).unwrap_or("").to_string()
}

/// A symbol name the script can declare: an identifier that is no Coq keyword and does
/// not start like a name the script gives.
fn check_name(n: &str) -> Result<(), String> {
    let ident = n.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
        && n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !ident || KEYWORDS.contains(&n) || RESERVED.iter().any(|p| n.starts_with(p)) {
        return Err(format!(
            "the symbol {n} cannot be declared in the Coq script"
        ));
    }
    Ok(())
}

mod steps;
