//! Certificates: a plain-text derivation that a second system (SymPy, through
//! `scripts/recheck-certificates.py`) rechecks step by step.
//!
//! When a ring records certificates, every value keeps the operation that made it
//! (a DAG of nodes, module `node`).  The certificate lists, one statement a line:
//!
//! ```text
//! field A indeterminate            # a field variable and its kind (sn, zeta, K, Kp, named, …)
//! field delta param real           # an opaque symbol declared real (a real chart parameter)
//! call ln1 = ln (N)/(D)            # an opaque symbol for ln(N/D) (derivative (N/D)'/(N/D))
//! call am1 = am (u)/(1) (k)/(1)    # an opaque symbol for am(u, k) (derivative dn(u, k)·u')
//! root r_1 = A - C                 # a root symbol: r_1**2 = A - C
//! named k = (expression)           # a named quantity's definition (for derivatives)
//! base b_1 k=(…) s=sn_1 c=(…) d=(…) arg=(…)   # an elliptic base argument
//! period K k=(…) kp=(…) halfK=(s, c, d) halfiKp=(s, c, d) # quarter-period data
//! param t1_A positive              # a parameter of the domain's parametrization
//! image A = (t1_A)/(1)             # an indeterminate's image in the parameters
//! alt param t2_A positive          # the same for a second parametrization of the domain
//! posroot r_1                      # a root whose radicand the checker proves positive
//! sign t7 > 0                      # a sign the checker proves with a parametrization
//! sign t8 > 0 hypothesis hypothesis.H factor (1)/(2)   # t8 = (H's value)·(1/2): by H
//! sign t9 > 0 square (a)/(b) hypothesis hypothesis.H factor (F)/(G)  # t9 = (a/b)²
//! sign t10 > 0 hypothesis part:1 factor (F)/(G)   # t10 = (the first part's condition)·(F/G)
//! sign value (N)/(D) > 0           # a value without a derivation, written out
//! sign t11 > 0 parts               # decided from the signs of its parts in a square root
//! dominance (Q) > 0 constant 2 factor (G) ^ 1 factor (H) ^ 2   # Q = a² − b²·r² = 2·G·H²
//! signsym sgnx = sign (x)/(1)      # a sign symbol's definition: sgnx·x > 0
//! fact F0 dn base b_1_2 value (D)  # dn of a base of real argument, 0 < k² < 1: D > 0
//! fact F1 dn t14                   # dn node t14 of a real argument: its value > 0
//! sign t16 > 0 fact F1 factor (F)/(G)   # t16 = (t14's value)·(F/G), F/G of proved sign
//! node t3 = t1 * t2 -> (N)/(D)     # an operation and, where it reduces, its normal form
//! node t9 = sqrt t8 -> +1 (N)/(D)  # a square root: nf² = t8; the sign is an assumption
//! node t12 = sn b_1:2,b_2:-1 K:1 iKp:0 k=(…) -> …  # sn(2b₁ − b₂ + K/2) by DLMF 22.8, 22.4, 22.5
//! node t15 = d t14 x -> …          # derivative; `dvar x v = …` lines give d v/d x
//! inverse v k=(…) s=(…) c=(…) d=(…) z=Z_v   # an inverse of sn, cn, dn: sn v = s, …
//! coord h = t17                   # a claim's variable a chart replaces: its value there
//! claim t20 = t31
//! side t20 t31                     # a refutation: the sides of a component, not claimed equal
//! witness component 1              # … and the component that differs at the point:
//! at A = 3*2^-2                    # an indeterminate's or sn symbol's exact value there
//! at r_1 ~ 0.70710678 0            # a root's value there, to pick its branch
//! part "M3" > 0                    # a proof by parts: the condition of this part
//! assume branch step_gamma1 "…"    # a fact the derivation rests on (branch, lemma, hypothesis)
//! ```
//!
//! A proof by the uniqueness of the solution of an ODE (module [`super::ode`]) writes,
//! after its `field` and `root` lines, no nodes but these lines, which the checker
//! (`scripts/certcheck/ode.py`) recomputes from the claim's own formulas:
//!
//! ```text
//! jet jsn_1 jcn_1 jdn_1 arg=(u)/(k) k=(k)/(1)   # sn, cn, dn of (arg, k) as symbols S, C, D
//! ode var u at 0                                # the ODE's variable and initial point
//! ode equation y2 - (c1)/(1)*y0 - (c3)/(1)*y0**3   # P(y0, y1, y2) = 0, y_j the j-th derivative
//! ode side lhs y0=(…) y1=(…) y2=(…)             # a side and its derivatives
//! ode initial y0=(0)/(1) y1=(1)/(1) y2=(0)/(1)  # the common values at the initial point
//! ode nonsingular (1)/(1)                       # ∂P/∂y2 there, not 0
//! ```
//!
//! A proof by power series (an asymptotic claim, or an existence claim for small `h`)
//! writes, instead of `claim` lines, its `series`, `sseries`, `schart`, `sclaim` and
//! `ssolution` lines (module `series_trace`): every operation that made its
//! series, which the checker redoes from the leaves.  A refuted order writes, instead of
//! `sclaim` lines, `srefute sN component J coefficient E` and the witness point: the
//! coefficient of `t^E` is not 0 there.
//!
//! After the header and `# claim:` title, `claims N` states the number of `claim` lines.
//! `eulertop prove --certificate` adds the claim's `source` and `premise` lines
//! (`crate::cli::cert_source`), which bind the derivation to the catalogue.
//!
//! The checker recomputes every operation from its arguments, reduces modulo the root
//! relations, and compares with the stated normal form; elliptic nodes are recomputed
//! from the base symbols with its own addition formulae; the claim is checked last.

use super::base_table::Table;
use super::flint::Poly;
use super::node::{Node, Op};
use super::ring::{Assumption, AssumptionKind, Ring, State, VarKind, describe_kind};
use super::sym::Sym;
use super::val::Val;

use std::collections::HashMap;
use std::fmt::Write;
use std::sync::Arc;

/// Where a refutation's `lhs − rhs` is nonzero: the component (from 0) and the ring's
/// domain point (from 0).
#[derive(Clone, Copy, Debug)]
pub struct Refutation {
    /// The component whose difference is nonzero.
    pub component: usize,
    /// The domain point (an index into the ring's points).
    pub point: usize,
}

/// A string as a JSON literal (quoted, escaped), so that a statement is one line.
fn json(s: &str) -> String {
    serde_json::to_string(s).unwrap_or_default()
}

/// The `assume KIND NAME STATEMENT` line of a fact the derivation rests on: the branch
/// of an implicit map (named by the map), a lemma (by the claim's id) or a stated
/// hypothesis (by its label); the recheck requires a premise of the theorem for each.
fn assume_line(a: &Assumption) -> String {
    let (kind, name) = match &a.kind {
        AssumptionKind::Branch(m) => ("branch", m),
        AssumptionKind::Lemma(id) => ("lemma", id),
        AssumptionKind::Hypothesis(label) => ("hypothesis", label),
    };
    format!("assume {kind} {name} {}\n", json(&a.statement))
}

/// A machine-readable tag of a field variable's kind.
fn kind_tag(k: &VarKind) -> &'static str {
    use VarKind::*;
    match k {
        Indeterminate => "indeterminate",
        Named(_) => "named",
        Sn { .. } => "sn",
        Zeta { .. } => "zeta",
        QuarterK { .. } => "K",
        QuarterKp { .. } => "Kp",
        ThirdK { .. } => "snK3",
        Opaque { constant: true } => "constant",
        Opaque { constant: false } => "opaque",
        Jet { .. } => "jet",
    }
}

fn nf_text(num: &Poly, den: &Poly, names: &[String]) -> String {
    format!("({})/({})", num.render(names), den.render(names))
}

struct Emitter<'a> {
    names: &'a [String],
    ids: HashMap<*const Node, usize>,
    out: String,
}

impl Emitter<'_> {
    /// Emits `root` and everything it depends on (post-order, without recursion, so
    /// deep derivations cannot overflow the stack); returns its id.
    fn visit(&mut self, root: &Arc<Node>) -> usize {
        let mut stack: Vec<(Arc<Node>, bool)> = vec![(root.clone(), false)];
        while let Some((n, expanded)) = stack.pop() {
            if self.ids.contains_key(&Arc::as_ptr(&n)) {
                continue;
            }
            if expanded {
                self.emit(&n);
            } else {
                stack.push((n.clone(), true));
                for a in n.args.iter().rev() {
                    stack.push((a.clone(), false));
                }
            }
        }
        self.ids[&Arc::as_ptr(root)]
    }

    fn emit(&mut self, n: &Arc<Node>) {
        let args: Vec<usize> = n.args.iter().map(|a| self.ids[&Arc::as_ptr(a)]).collect();
        let id = self.ids.len() + 1;
        let t = |i: usize| format!("t{}", args[i]);
        let body = match &n.op {
            Op::Symbol(s) => s.clone(),
            Op::Const(q) => q.clone(),
            Op::Add => format!("{} + {}", t(0), t(1)),
            Op::Sub => format!("{} - {}", t(0), t(1)),
            Op::Mul => format!("{} * {}", t(0), t(1)),
            Op::SumOfProducts(signs) => {
                let terms: Vec<String> = signs
                    .iter()
                    .enumerate()
                    .map(|(i, neg)| {
                        format!(
                            "{} {} {}",
                            if *neg { "-" } else { "+" },
                            t(2 * i),
                            t(2 * i + 1)
                        )
                    })
                    .collect();
                format!("dot {}", terms.join(" "))
            }
            Op::Div => format!("{} / {}", t(0), t(1)),
            Op::Neg => format!("- {}", t(0)),
            Op::Pow(e) => format!("{} ^ {e}", t(0)),
            Op::Sqrt(s) => format!("sqrt {} sign {s}", t(0)),
            Op::Elliptic {
                f,
                table,
                combo,
                half_k,
                half_kp,
            } => {
                let c: Vec<String> = combo
                    .iter()
                    .map(|(b, m)| format!("b_{}_{}:{m}", table + 1, b + 1))
                    .collect();
                format!(
                    "{f} {} table {} combo {} halfK {half_k} halfiKp {half_kp}",
                    t(0),
                    table + 1,
                    c.join(",")
                )
            }
            Op::Deriv(x) => format!("d {} {x}", t(0)),
        };
        let nf =
            n.nf.as_ref()
                .map(|(a, b)| format!(" -> {}", nf_text(a, b, self.names)))
                .unwrap_or_default();
        let _ = writeln!(self.out, "node t{id} = {body}{nf}");
        self.ids.insert(Arc::as_ptr(n), id);
    }
}

/// The `sseries` lines of a proof by power series (module [`super::series_trace`]),
/// their leaves' nodes emitted first, and its `sclaim` lines (a refutation's: the
/// `srefute` line of the coefficient `refuted`, by its index among the coefficients the
/// proof tests); `None` when a leaf has no derivation.
fn series_lines(
    em: &mut Emitter<'_>,
    trace: &super::series_trace::SeriesTrace,
    refuted: Option<usize>,
) -> Option<String> {
    let mut claims = String::new();
    for (i, r) in trace.records.iter().enumerate() {
        let mut node = |x: &Sym| Some(em.visit(x.node.as_ref()?));
        let line = super::series_trace::record_line(i + 1, r, &mut node)?;
        em.out.push_str(&line);
    }
    for (name, args, value) in &trace.charts {
        let ids = |xs: &[u32]| xs.iter().map(|i| format!("s{i}")).collect::<Vec<_>>();
        let argv: Vec<String> = args.iter().map(|a| ids(a).join(", ")).collect();
        let _ = writeln!(
            em.out,
            "schart {name}({}) value={}",
            argv.join("; "),
            ids(value).join(",")
        );
    }
    if let Some(i) = refuted {
        // a refutation: the coefficient that is not 0 (at the witness point)
        let (id, j, e) = trace.coefficients.get(i)?;
        let _ = writeln!(claims, "srefute s{id} component {j} coefficient {e}");
        return Some(claims);
    }
    for (id, j, below) in &trace.claims {
        let _ = writeln!(claims, "sclaim s{id} component {j} below {below}");
    }
    if !trace.solution.is_empty() {
        let parts: Vec<String> = (trace.solution.iter())
            .map(|(u, id)| format!("{u} = s{id}"))
            .collect();
        let _ = writeln!(claims, "ssolution {}", parts.join("; "));
    }
    Some(claims)
}

impl Ring {
    /// The certificate of `lhs = rhs` (see the module doc), or `None` when the ring does
    /// not record derivations.  With `refute`, the certificate of a refutation instead:
    /// the pairs as `side` lines, and the point at which the component's `lhs − rhs` is
    /// nonzero ([`Refutation`], module `witness`).
    pub fn certificate(
        &self,
        pairs: &[(Sym, Sym)],
        title: &str,
        refute: Option<Refutation>,
    ) -> Option<String> {
        if !self.state().uncertified.is_empty() {
            return None;
        }
        let mut nodes = Vec::new();
        for (l, r) in pairs {
            nodes.push((l.node.clone()?, r.node.clone()?));
        }
        let names = self.inner.names();
        let mut out = String::new();
        let _ = writeln!(out, "# eulertop certificate 1");
        let _ = writeln!(out, "# claim: {}", title.replace('\n', " "));
        // the number of claim lines: a deleted one is noticed
        let series_claims = {
            let st = self.state();
            st.series.claims.len() + usize::from(!st.series.solution.is_empty())
        };
        let count = if series_claims > 0 && refute.is_some() {
            1
        } else if series_claims > 0 {
            series_claims
        } else {
            pairs.len()
        };
        let _ = writeln!(out, "claims {count}");
        out.push_str(&self.symbol_lines(&names));
        let mut em = Emitter {
            names: &names,
            ids: HashMap::new(),
            out: String::new(),
        };
        self.equivalence_lines(&mut em, &names);
        self.chart_lines(&mut em);
        self.coordinate_lines(&mut em);
        let trace = self.state().series.clone();
        let series = if trace.claims.is_empty() && trace.solution.is_empty() {
            None
        } else {
            Some(series_lines(&mut em, &trace, refute.map(|r| r.component))?)
        };
        let mut claims = Vec::new();
        if series.is_none() {
            for (ln, rn) in &nodes {
                let a = em.visit(ln);
                let b = em.visit(rn);
                claims.push((a, b));
            }
        }
        let signs = self.sign_lines(&mut em);
        out.push_str(&em.out);
        out.push_str(&signs);
        for (a, b) in claims {
            let _ = match refute {
                None => writeln!(out, "claim t{a} = t{b}"),
                Some(_) => writeln!(out, "side t{a} t{b}"),
            };
        }
        if let Some(r) = refute {
            // a series refutation has one claim, its `srefute` line
            let component = if series.is_some() { 0 } else { r.component };
            let _ = writeln!(out, "witness component {}", component + 1);
            out.push_str(&self.point_lines(r.point));
        }
        if let Some(s) = series {
            out.push_str(&s);
        }
        for (h, s) in &self.inner.opts.hypotheses {
            let rel = if *s > 0 { ">" } else { "<" };
            let _ = writeln!(out, "part {} {rel} 0", json(&h.text));
        }
        for a in self.assumptions() {
            out.push_str(&assume_line(&a));
        }
        Some(out)
    }

    /// The signs proved with the parametrization of the domain (module
    /// [`super::positivity`]): the parametrization, the roots taken as positive, and one
    /// `sign tN > 0` (or `< 0`) line per proved sign of a derived value.
    fn sign_lines(&self, em: &mut Emitter<'_>) -> String {
        let (signs, vars, roots) = {
            let st = self.state();
            let vars: Vec<String> = (st.vars.iter())
                .filter(|v| matches!(v.kind, VarKind::Indeterminate))
                .map(|v| v.name.clone())
                .collect();
            let roots: Vec<String> = (st.roots.iter())
                .filter(|r| r.is_positive())
                .map(|r| r.name.clone())
                .collect();
            (st.signs.proved_signs.clone(), vars, roots)
        };
        let evidence = self.state().signs.evidence.clone();
        let (facts, valued, by_parts, dominance) = {
            let st = self.state();
            (
                st.signs.fact_evidence.clone(),
                st.signs.valued.clone(),
                st.signs.root_signs.clone(),
                st.signs.dominance.clone(),
            )
        };
        // a factor of a hypothesis' value that is no constant has its sign proved with
        // the parametrization too
        let factors = (evidence.iter())
            .any(|e| e.factor.num.as_constant().is_none() || e.factor.den.as_constant().is_none());
        let Some(par) = (self.inner.opts.positivity.as_ref()).filter(|_| {
            !signs.is_empty()
                || factors
                || !facts.is_empty()
                || !valued.is_empty()
                || !by_parts.is_empty()
                || !dominance.is_empty()
        }) else {
            let mut out = dominance_lines(&dominance, em.names);
            out.push_str(&hypothesis_sign_lines(&evidence, em));
            out.push_str(&self.fact_sign_lines(&facts, em));
            out.push_str(&root_sign_lines(&by_parts, em));
            return out;
        };
        let mut out = par.certificate_lines(&vars);
        for r in roots {
            let _ = writeln!(out, "posroot {r}");
        }
        // before the sign lines, whose recheck may use them
        out.push_str(&dominance_lines(&dominance, em.names));
        for (node, s, _) in signs {
            if let Some(n) = node {
                let id = em.visit(&n);
                let _ = writeln!(out, "sign t{id} {} 0", if s > 0 { ">" } else { "<" });
            }
        }
        for (v, s) in valued {
            let _ = writeln!(
                out,
                "sign value {} {} 0",
                nf_text(&v.num, &v.den, em.names),
                if s > 0 { ">" } else { "<" }
            );
        }
        out.push_str(&hypothesis_sign_lines(&evidence, em));
        out.push_str(&self.fact_sign_lines(&facts, em));
        out.push_str(&root_sign_lines(&by_parts, em));
        out
    }

    /// The facts of the Jacobi functions that decide signs (`fact Fi dn base b_T_B value
    /// (D)` or `fact Fi dn tN`: `dn` of a base, or the `dn` node of a derivation, whose
    /// argument and modulus a recheck proves real, with `0 < k² < 1`), then the signs
    /// they decide: `sign tN > 0 fact Fi factor (F)/(G)` (or `sign value (X) > 0 …`
    /// for a value without a derivation), the value being the fact's times the factor.
    fn fact_sign_lines(
        &self,
        evidence: &[super::sign_state::FactEvidence],
        em: &mut Emitter<'_>,
    ) -> String {
        use super::sign_state::FactSource;
        let facts = self.state().signs.facts.clone();
        let mut used: Vec<usize> = evidence.iter().map(|e| e.fact).collect();
        used.sort_unstable();
        used.dedup();
        let mut out = String::new();
        for i in used {
            let line = match &facts[i].source {
                FactSource::Base(t, b) => format!(
                    "fact F{i} dn base b_{}_{} value {}",
                    t + 1,
                    b + 1,
                    nf_text(&facts[i].value.num, &facts[i].value.den, em.names)
                ),
                FactSource::Node(n) => format!("fact F{i} dn t{}", em.visit(n)),
                FactSource::Unrecorded => continue,
            };
            let _ = writeln!(out, "{line}");
        }
        for e in evidence {
            let what = match &e.node {
                Some(n) => format!("t{}", em.visit(n)),
                None => format!("value {}", nf_text(&e.value.num, &e.value.den, em.names)),
            };
            let _ = writeln!(
                out,
                "sign {what} {} 0 fact F{} factor {}",
                if e.sign > 0 { ">" } else { "<" },
                e.fact,
                nf_text(&e.factor.num, &e.factor.den, em.names)
            );
        }
        out
    }

    /// The chart of each implicit map the proof parametrizes: `chart NAME(ARGS) value=…`
    /// with the arguments as rendered (components `, `, arguments `; `) and the nodes of
    /// the map's value there, so that a recheck substitutes the chart into the map's
    /// equations as the catalogue states them.
    fn chart_lines(&self, em: &mut Emitter<'_>) {
        let charts = self.state().implicit_values.clone();
        for (key, (_, vals)) in charts {
            let Some(nodes) = vals
                .iter()
                .map(|(_, n)| n.clone())
                .collect::<Option<Vec<_>>>()
            else {
                continue;
            };
            let ids: Vec<String> = nodes.iter().map(|n| format!("t{}", em.visit(n))).collect();
            let _ = writeln!(em.out, "chart {key} value={}", ids.join(","));
        }
    }

    /// The claim's variables that a chart replaces, with their values in the chart's
    /// parameters: `coord NAME = tN`.  A recheck takes a derivative of a parameter that
    /// is no claim variable (a phase step `δ`) in a claim's variable `x` as stated, and
    /// then requires that every such coordinate has the derivative `[NAME = x]`: the
    /// parameter moves so that the claim's other variables stay fixed, as the chart
    /// implies.
    fn coordinate_lines(&self, em: &mut Emitter<'_>) {
        let Some(c) = self.state().coordinates.clone() else {
            return;
        };
        for (i, (val, node)) in c.coords.iter().enumerate() {
            let is_param = (c.params.iter())
                .any(|(p, _)| (self.inner.v_add(p, val, true)).is_ok_and(|d| d.num.is_zero()));
            let (Some(name), Some(node), false) = (c.names.get(i), node, is_param) else {
                continue;
            };
            let id = em.visit(node);
            let _ = writeln!(em.out, "coord {name} = t{id}");
        }
    }

    /// For each symbol with prescribed sn, cn, dn that an argument replaces inside sn,
    /// cn, dn: its values (as derived) and that argument as a combination of the bases,
    /// so that a recheck recomputes sn, cn, dn of the argument and compares.
    fn equivalence_lines(&self, em: &mut Emitter<'_>, names: &[String]) {
        let prescribed = self.state().prescribed.clone();
        for p in prescribed {
            let (Some(u), Some([s, c, d])) = (&p.equiv, &p.nodes) else {
                continue;
            };
            let Ok((t, combo, hk, hkp)) = self.combination(&p.k, u) else {
                continue;
            };
            let (a, b, e) = (em.visit(s), em.visit(c), em.visit(d));
            let combo: Vec<String> = combo
                .iter()
                .map(|(i, n)| format!("b_{}_{}:{n}", t + 1, i + 1))
                .collect();
            let name = names[self.inner.opts.max_roots + p.var].clone();
            let sign = p
                .equiv_sign
                .as_ref()
                .map(|g| format!(" sign={}", nf_text(&g.num, &g.den, names)))
                .unwrap_or_default();
            let _ = writeln!(
                em.out,
                "equiv {name} s=t{a} c=t{b} d=t{e} table {} combo {} halfK {hk} halfiKp {hkp}{sign} arg={}",
                t + 1,
                combo.join(","),
                nf_text(&u.num, &u.den, names)
            );
        }
    }

    fn symbol_lines(&self, names: &[String]) -> String {
        let nvars = self.state().vars.len();
        let params: Vec<bool> = (0..nvars)
            .map(|j| self.is_coordinate_parameter(j).unwrap_or(false))
            .collect();
        let st = self.state();
        let mut out = String::new();
        for (j, v) in st.vars.iter().enumerate() {
            let what = describe_kind(&v.kind);
            // an opaque parameter of the declared coordinates (a phase step δ) is a
            // coordinate of the chart: the other parameters do not depend on it
            let tag = match v.kind {
                VarKind::Opaque { constant: false } if params[j] => "param",
                _ => kind_tag(&v.kind),
            };
            // an opaque symbol declared real (a real chart parameter) says so
            let real = if st.signs.real_opaque.contains(&j) {
                " real"
            } else {
                ""
            };
            let _ = writeln!(out, "field {} {tag}{real}  # {what}", v.name);
            if let VarKind::Named(def) = &v.kind {
                let _ = writeln!(
                    out,
                    "named {} = {}",
                    v.name,
                    nf_text(&def.num, &def.den, names)
                );
            }
        }
        out.push_str(&call_lines(&st, names));
        for r in &st.roots {
            let _ = writeln!(
                out,
                "root {} = {}  # {}",
                r.name,
                r.radicand.render(names),
                r.note
            );
        }
        // the sign symbols' definitions: σ = sign(x), so σ·x > 0
        for f in &st.signs.folded {
            let _ = writeln!(
                out,
                "signsym {} = sign {}  # {} > 0",
                f.name,
                nf_text(&f.x.num, &f.x.den, names),
                f.positive
            );
        }
        out.push_str(&inverse_lines(&st, names));
        let i_name = st
            .i_root
            .map_or("none".to_string(), |i| st.roots[i].name.clone());
        for (ti, t) in st.tables.iter().enumerate() {
            out.push_str(&table_lines(t, ti, names, |j| self.inner.kvar(j), &i_name));
        }
        for line in &st.derivation_lines {
            out.push_str(line);
            out.push('\n');
        }
        out
    }
}

/// The `call` lines: the calls with a derivative rule, `ln x` (x'/x) and `am(u, k)`
/// (dn(u, k)·u').
fn call_lines(st: &State, names: &[String]) -> String {
    let mut out = String::new();
    for (j, (f, args)) in &st.opaque_args {
        if f == "ln" || f == "am" {
            let args: Vec<String> = (args.iter())
                .map(|(v, _)| nf_text(&v.num, &v.den, names))
                .collect();
            let _ = writeln!(out, "call {} = {f} {}", st.vars[*j].name, args.join(" "));
        }
    }
    out
}

/// The `inverse` lines: the inverses of sn, cn, dn, their values and, where the
/// modulus varies, the symbol Z of their derivative in the modulus.
fn inverse_lines(st: &State, names: &[String]) -> String {
    let mut out = String::new();
    for p in &st.prescribed {
        let z =
            (st.opaque_zeta.get(&p.var)).map_or("none".to_string(), |&j| st.vars[j].name.clone());
        let _ = writeln!(
            out,
            "inverse {} k={} s={} c={} d={} z={z}",
            st.vars[p.var].name,
            nf_text(&p.k.num, &p.k.den, names),
            nf_text(&p.s.num, &p.s.den, names),
            nf_text(&p.c.num, &p.c.den, names),
            nf_text(&p.d.num, &p.d.den, names)
        );
    }
    out
}

/// The `sign tN > 0 [square (A)/(B)] hypothesis LABEL factor (F)/(G)` lines: a sign a
/// stated hypothesis decides, with its evidence (the value, or the quotient `A/B` whose
/// square it is, equals the hypothesis' value times `F/G`, whose sign is proved).
fn hypothesis_sign_lines(
    evidence: &[super::sign_state::SignEvidence],
    em: &mut Emitter<'_>,
) -> String {
    let mut out = String::new();
    for e in evidence {
        let id = em.visit(&e.node);
        let square = (e.square.as_ref())
            .map(|(a, b)| format!(" square {}", nf_text(a, b, em.names)))
            .unwrap_or_default();
        let _ = writeln!(
            out,
            "sign t{id} {} 0{square} hypothesis {} factor {}",
            if e.sign > 0 { ">" } else { "<" },
            e.label,
            nf_text(&e.factor.num, &e.factor.den, em.names)
        );
    }
    out
}

/// The `dominance (Q) > 0 constant C factor (G) ^ K …` lines of rule 2b (module
/// `decide`): `Q = a² − b²·r²` has the stated sign, as `C · Π G^K` whose factors' signs
/// a recheck proves; a sign of `a + b·r` is then that of `a` (`Q > 0`) or of `b`
/// (`Q < 0`), which the recheck proves in turn.
fn dominance_lines(evidence: &[super::sign_state::Dominance], names: &[String]) -> String {
    let mut out = String::new();
    for d in evidence {
        let factors: Vec<String> = (d.factors.iter())
            .map(|(g, k)| format!(" factor ({}) ^ {k}", g.render(names)))
            .collect();
        let _ = writeln!(
            out,
            "dominance ({}) {} 0 constant {}{}",
            d.q.render(names),
            if d.sign > 0 { ">" } else { "<" },
            d.constant,
            factors.concat()
        );
    }
    out
}

/// The `sign tN > 0 parts` (or `sign value (N)/(D) > 0 parts`) lines: a sign of a value
/// in a square root decided from the signs of its root-free parts, each proved, the
/// condition of the part of the domain or a sign symbol's definition, which a recheck
/// decides again (module [`super::root_signs`]).
fn root_sign_lines(
    evidence: &[super::sign_state::RootSignEvidence],
    em: &mut Emitter<'_>,
) -> String {
    let mut out = String::new();
    for e in evidence {
        let what = match &e.node {
            Some(n) => format!("t{}", em.visit(n)),
            None => format!("value {}", nf_text(&e.value.num, &e.value.den, em.names)),
        };
        let rel = if e.sign > 0 { ">" } else { "<" };
        let _ = writeln!(out, "sign {what} {rel} 0 parts");
    }
    out
}

/// The lines of elliptic table `ti`: its bases and, where used, its quarter-period data.
fn table_lines(
    table: &Table,
    ti: usize,
    names: &[String],
    kvar: impl Fn(usize) -> usize,
    i_name: &str,
) -> String {
    let nf = |v: &Val| format!("({})/({})", v.num.render(names), v.den.render(names));
    let mut out = String::new();
    for (bi, b) in table.bases.iter().enumerate() {
        let z = b
            .z_var
            .map_or(String::new(), |j| format!(" z={}", names[kvar(j)]));
        // a prescribed sn is written as its value, a symbol by its name
        let s = if b.is_prescribed() {
            nf(&b.s)
        } else {
            b.s_name.clone()
        };
        let _ = writeln!(
            out,
            "base b_{}_{} k={} s={s} c={} d={} arg={}{z}",
            ti + 1,
            bi + 1,
            nf(&table.k),
            nf(&b.c),
            nf(&b.d),
            nf(&b.arg)
        );
    }
    let triple = |t: &Option<[Val; 3]>| {
        t.as_ref().map_or("none".to_string(), |[s, c, d]| {
            format!("[{}, {}, {}]", nf(s), nf(c), nf(d))
        })
    };
    // a shift by a multiple of 4K needs no k' but still names K
    let periods = [table.k_var, table.kp_var].iter().any(Option::is_some);
    if table.kp.is_some() || table.half_kp.is_some() || periods {
        let kp = table.kp.as_ref().map_or("none".to_string(), nf);
        let name = |v: Option<usize>| v.map_or("none".to_string(), |j| names[kvar(j)].clone());
        let _ = writeln!(
            out,
            "period table {} k={} kp={kp} K={} Kp={} i={i_name} halfK={} halfiKp={}",
            ti + 1,
            nf(&table.k),
            name(table.k_var),
            name(table.kp_var),
            triple(&table.half_k),
            triple(&table.half_kp)
        );
    }
    out
}
