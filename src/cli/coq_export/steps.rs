//! The definitions and lemmas of a Coq export: one `Definition t_N` and one lemma
//! `e_N : t_N = num / den` per node, and the claims.

use super::{NodeLine, Section, Val, comment};
use crate::algebra::flint::Poly;
use rug::Integer;
use std::fmt::Write;

/// The most terms a value or a step's cofactors may have.
const MAX_TERMS: usize = 4000;

/// The most denominator factors a value may have.
const MAX_FACTORS: usize = 12;

/// The node number of an argument `tN`.
fn arg(t: &str) -> Result<usize, String> {
    t.strip_prefix('t')
        .and_then(|n| n.parse().ok())
        .ok_or_else(|| format!("malformed node argument '{t}'"))
}

/// The product of polynomials (1 for none).
fn product(ps: &[Poly], one: Poly) -> Poly {
    ps.iter().fold(one, |acc, p| acc.mul(p))
}

impl Section {
    /// The constant 1.
    fn one(&self) -> Poly {
        self.sym.constant(&Integer::from(1))
    }

    /// A value as a Coq term: `(num)` for a polynomial, else `(num) / den`.
    fn text(&self, v: &Val) -> String {
        if v.den.is_empty() {
            return self.ntext(v);
        }
        format!("{} / {}", self.ntext(v), v.dt)
    }

    /// The numerator of a value as its lemma states it.
    fn ntext(&self, v: &Val) -> String {
        v.nt.clone().unwrap_or_else(|| self.sym.coq(&v.num))
    }

    /// The numerator `eu_comb` makes of operation `b` on the arguments' fractions (the
    /// lemmas `eu_addq`, `eu_mulq`, … of the preamble), or `None` for an operation whose
    /// numerator is better written expanded.
    fn structural(&self, b: &[&str]) -> Option<String> {
        let v = |t: &str| arg(t).ok().and_then(|a| self.vals.get(&a));
        let nd = |t: &str| v(t).map(|x| (self.ntext(x), Self::dt(x).to_string()));
        match b {
            ["-", a] => Some(format!("(- {})", nd(a)?.0)),
            ["dot", rest @ ..] => {
                let mut acc: Option<(String, String)> = None;
                for t in rest.chunks(3) {
                    let [sg, a, c] = t else { return None };
                    let ((na, da), (nc, dc)) = (nd(a)?, nd(c)?);
                    let (n, d) = (format!("({na} * {nc})"), format!("({da} * {dc})"));
                    acc = Some(match acc {
                        None if *sg == "-" => (format!("(- {n})"), d),
                        None => (n, d),
                        Some((an, ad)) => (
                            format!("({an} * {d} {sg} {n} * {ad})"),
                            format!("({ad} * {d})"),
                        ),
                    });
                }
                acc.map(|(n, _)| n)
            }
            [a, "^", e] => {
                let (na, da) = nd(a)?;
                let n = e.trim_start_matches('-');
                Some(format!(
                    "({} ^ {n})",
                    if e.starts_with('-') { da } else { na }
                ))
            }
            [a, op, c] => {
                let ((na, da), (nc, dc)) = (nd(a)?, nd(c)?);
                match *op {
                    "+" | "-" => Some(format!("({na} * {dc} {op} {nc} * {da})")),
                    "*" => Some(format!("({na} * {nc})")),
                    "/" => Some(format!("({na} * {dc})")),
                    _ => None,
                }
            }
            _ => None,
        }
    }

    /// The denominator of a value as the steps write it (`1` for a polynomial, which
    /// the steps write as `p / 1`).
    fn dt(v: &Val) -> &str {
        if v.den.is_empty() { "1" } else { &v.dt }
    }

    /// The value of node `id` (an earlier node).
    fn val(&self, id: usize) -> Result<Val, String> {
        (self.vals.get(&id).cloned())
            .ok_or_else(|| format!("node t{id} is used before it is defined"))
    }

    /// A normal form `(N)/(D)` as a value; a denominator that is not constant gets the
    /// hypothesis `nz_id : D <> 0` (once per denominator).
    fn nf_val(&mut self, id: usize, text: &str) -> Result<Val, String> {
        let (num, den) = self.sym.parse_frac(text)?;
        if den.is_zero() {
            return Err(format!("node t{id} has the denominator 0"));
        }
        if den.as_constant().is_none() {
            let t = self.sym.coq(&den);
            if !self.facts.contains_key(&t) {
                let _ = writeln!(self.decls, "Hypothesis nz_{id} : {t} <> 0.");
                self.facts.insert(t, format!("nz_{id}"));
            }
        }
        let dt = self.sym.coq(&den);
        let den = if den.is_one() { vec![] } else { vec![den] };
        Ok(Val {
            num,
            den,
            dt,
            nt: None,
        })
    }

    /// The `pose proof` of every lemma that states a denominator of `vals` nonzero (the
    /// hypotheses are in the context already).
    fn poses(&self, vals: &[&Val]) -> Result<String, String> {
        let mut out = String::new();
        let mut done = std::collections::BTreeSet::new();
        for d in vals.iter().flat_map(|v| v.den.iter()) {
            if d.as_constant().is_some() {
                continue;
            }
            let t = self.sym.coq(d);
            let fact =
                (self.facts.get(&t)).ok_or_else(|| format!("no hypothesis states {t} <> 0"))?;
            if fact.starts_with("z_") && done.insert(fact.clone()) {
                let _ = writeln!(out, "  pose proof {fact}.");
            }
        }
        Ok(out)
    }

    /// The proof of `from = to` (as [`Self::text`] writes them) for two values whose
    /// cross products differ by a combination of the root relations: `eu_frac` (or its
    /// forms for a polynomial side), then the cofactors.
    fn frac_steps(&self, from: &Val, to: &Val) -> Result<String, String> {
        let f = (from.num.mul(&product(&to.den, self.one())))
            .sub(&to.num.mul(&product(&from.den, self.one())));
        let apply = match (from.den.is_empty(), to.den.is_empty()) {
            (true, true) => "apply Rminus_diag_uniq.",
            (false, true) => "apply eu_fracp; [nzp | ].",
            (true, false) => "apply eu_pfrac; [nzp | ].",
            (false, false) => "apply eu_frac; [nzp | nzp | ].",
        };
        Ok(format!("  {apply}\n  {}\n", self.cofactor_proof(&f)?))
    }

    /// The proof of `P / Q = to` once `eu_comb` has made the operation on the
    /// arguments' values one fraction `P / Q` of value `from`: for a node without a
    /// normal form (`to` is `from`, written alike) the numerators agree by `ring`;
    /// when the product `Q` of `from`'s denominators is the denominator `D` of `to`
    /// times `R`, `P − N·R` is the combination of the relations (smaller than
    /// `P·D − N·Q`); otherwise [`Self::frac_steps`].
    fn reduce_steps(&self, from: &Val, to: &Val, raw: bool) -> Result<String, String> {
        if raw {
            return Ok("  apply eu_same.\n  ring.\n".into());
        }
        let q = product(&from.den, self.one());
        let d = product(&to.den, self.one());
        let r = match (to.den.is_empty(), q.divides(&d)) {
            (false, Ok(Some(r))) => r,
            _ => return self.frac_steps(from, to),
        };
        let f = from.num.sub(&to.num.mul(&r));
        Ok(format!(
            "  apply (eu_fracr _ _ _ _ {}); [nzp | ring | ].\n  {}\n",
            self.sym.coq(&r),
            self.cofactor_proof(&f)?
        ))
    }

    /// Refuses a value too large for a script that compiles in reasonable time.
    fn guard(id: usize, v: &Val) -> Result<(), String> {
        let terms = v.num.len() + v.den.iter().map(Poly::len).sum::<usize>();
        if terms > MAX_TERMS || v.den.len() > MAX_FACTORS {
            return Err(format!(
                "node t{id} is too large for the Coq export ({terms} terms over {} denominators)",
                v.den.len()
            ));
        }
        Ok(())
    }

    /// The proof of `f = 0` from the root relations: the cofactors `qᵢ` with
    /// `f = Σ qᵢ (rᵢ² − aᵢ)` show which relations it uses, and `ring [rel_i …]`
    /// normalises `f` with those relations as rewriting rules `rᵢ² → aᵢ` (much
    /// cheaper than proving the cofactor identity with `ring`).
    fn cofactor_proof(&self, f: &Poly) -> Result<String, String> {
        let qs = self.sym.cofactors(f)?;
        let rels: Vec<String> = (qs.iter().zip(&self.sym.roots))
            .filter(|(q, _)| !q.is_zero())
            .map(|(_, (v, _))| format!("rel_{}", self.sym.names[*v]))
            .collect();
        if rels.is_empty() {
            return Ok("ring.".into());
        }
        Ok(format!("ring [{}].", rels.join(" ")))
    }

    /// Writes `Definition t_id`, the lemma `e_id` and records the value.
    fn define(&mut self, id: usize, def: &str, target: Val, proof: &str) -> Result<(), String> {
        Self::guard(id, &target)?;
        let text = self.text(&target);
        // a value written as its definition (a symbol, a constant): nothing to prove
        let proof = if def.trim_matches(['(', ')']) == text.trim_matches(['(', ')']) {
            "  reflexivity.\n"
        } else {
            proof
        };
        let _ = writeln!(
            self.body,
            "Definition t_{id} := {def}.\nLemma e_{id} : t_{id} = {text}.\nProof.\n  unfold t_{id}.\n{proof}Qed."
        );
        self.vals.insert(id, target);
        Ok(())
    }

    /// The rewriting of the arguments by their values.
    fn rewrite_args(args: &[usize]) -> String {
        Self::rewrite_with(args, |a| format!("e_{a}"))
    }

    /// The rewriting of the arguments by their values as fractions (`p / 1` for a
    /// polynomial), for `eu_comb`.
    fn rewrite_fracs(&self, args: &[usize]) -> String {
        Self::rewrite_with(args, |a| match self.vals.get(&a) {
            Some(v) if v.den.is_empty() => format!("(eu_f _ _ e_{a})"),
            _ => format!("e_{a}"),
        })
    }

    /// `rewrite` with the equation `eq(a)` of every argument `a` (each once).
    fn rewrite_with(args: &[usize], eq: impl Fn(usize) -> String) -> String {
        let mut seen: Vec<usize> = Vec::new();
        for a in args {
            if !seen.contains(a) {
                seen.push(*a);
            }
        }
        if seen.is_empty() {
            return String::new();
        }
        let list: Vec<String> = seen.into_iter().map(eq).collect();
        format!("  rewrite {}.\n", list.join(", "))
    }

    /// Node `id`: its definition and the lemma of its value.
    pub(super) fn node(&mut self, id: usize, n: &NodeLine) -> Result<(), String> {
        let b: Vec<&str> = n.body.iter().map(String::as_str).collect();
        match b.as_slice() {
            ["d", ..] => Err(format!(
                "node t{id} is a derivative, which the Coq export does not cover"
            )),
            ["sqrt", a, ..] => self.sqrt(id, arg(a)?, n.nf.as_deref()),
            [f @ ("sn" | "cn" | "dn"), _, "table", _, "combo", rest @ ..] => {
                let nf = n.nf.as_deref().ok_or(format!("node t{id} has no value"))?;
                // an empty combination (the argument 0) leaves no word
                let (combo, rest) = match rest {
                    ["halfK", ..] => ("", rest),
                    [c, rest @ ..] => (*c, rest),
                    [] => ("", rest),
                };
                let ["halfK", hk, "halfiKp", hkp] = rest else {
                    return Err(format!("malformed elliptic node t{id}"));
                };
                self.elliptic(id, f, combo, (hk, hkp), nf)
            }
            _ => self.rational(id, &b, n.nf.as_deref()),
        }
    }

    /// A rational operation (or a symbol or constant): `ring` on the arguments' values
    /// when they are polynomials, else `eu_comb` on them as fractions; then the
    /// reduction to the normal form, if the node has one.
    fn rational(&mut self, id: usize, b: &[&str], nf: Option<&str>) -> Result<(), String> {
        let (def, args, val) = self.operation(id, b)?;
        Self::guard(id, &val)?;
        // a node without a normal form, not a divisor: its numerator as eu_comb makes it
        let nt = match nf.is_none() && !val.den.is_empty() && !self.divisors.contains(&id) {
            true => self.structural(b),
            false => None,
        };
        let target = match nf {
            Some(t) => self.nf_val(id, t)?,
            None => Val {
                nt: nt.clone(),
                ..val.clone()
            },
        };
        let arg_vals: Vec<Val> = args
            .iter()
            .map(|a| self.val(*a))
            .collect::<Result<_, _>>()?;
        let mut all: Vec<&Val> = arg_vals.iter().collect();
        all.extend([&val, &target]);
        // a polynomial value: the operation on the arguments is that polynomial (ring);
        // else the arguments as fractions, combined into one by eu_comb
        let proof = if val.den.is_empty() {
            Self::rewrite_args(&args) + &self.poses(&all)? + &self.frac_steps(&val, &target)?
        } else {
            let rewrite = self.rewrite_fracs(&args);
            let finish = match nt {
                Some(_) => "  reflexivity.\n".to_string(),
                None => self.reduce_steps(&val, &target, nf.is_none())?,
            };
            rewrite + &self.poses(&all)? + "  eu_comb.\n" + &finish
        };
        self.define(id, &def, target, &proof)
    }

    /// The definition, the argument nodes and the (unreduced) value of an operation.
    fn operation(&mut self, id: usize, b: &[&str]) -> Result<(String, Vec<usize>, Val), String> {
        let one = self.one();
        match b {
            [x] => self.leaf(x).map(|(d, v)| (d, vec![], v)),
            ["-", a] => {
                let v = self.val(arg(a)?)?;
                let val = Val {
                    num: v.num.neg(),
                    den: v.den,
                    dt: v.dt,
                    nt: None,
                };
                Ok((format!("- t_{}", arg(a)?), vec![arg(a)?], val))
            }
            ["dot", rest @ ..] => self.dot(rest),
            [a, "^", e] => self.power(id, arg(a)?, e),
            [a, op, c] => {
                let (x, y) = (arg(a)?, arg(c)?);
                let def = format!("t_{x} {op} t_{y}");
                let (va, vc) = (self.val(x)?, self.val(y)?);
                let dt = format!("({} * {})", Self::dt(&va), Self::dt(&vc));
                let val = match *op {
                    "+" | "-" => {
                        let l = va.num.mul(&product(&vc.den, one.clone()));
                        let r = vc.num.mul(&product(&va.den, one));
                        let num = if *op == "+" { l.add(&r) } else { l.sub(&r) };
                        Val {
                            num,
                            den: [va.den, vc.den].concat(),
                            dt,
                            nt: None,
                        }
                    }
                    "*" => Val {
                        num: va.num.mul(&vc.num),
                        den: [va.den, vc.den].concat(),
                        dt,
                        nt: None,
                    },
                    "/" => self.divide(id, y, &va, &vc)?,
                    _ => return Err(format!("unknown operation '{op}' in node t{id}")),
                };
                Ok((def, vec![x, y], val))
            }
            _ => Err(format!(
                "node t{id}: an operation the Coq export does not cover"
            )),
        }
    }

    /// `a / c`: the divisor `t_c` nonzero is a hypothesis `dz_id`, and the lemma `z_id`
    /// states its value's numerator nonzero.
    fn divide(&mut self, id: usize, c: usize, va: &Val, vc: &Val) -> Result<Val, String> {
        self.nonzero_divisor(id, c, vc)?;
        let num = va.num.mul(&product(&vc.den, self.one()));
        Ok(Val {
            num,
            den: [va.den.clone(), vec![vc.num.clone()]].concat(),
            dt: format!("({} * {})", Self::dt(va), self.sym.coq(&vc.num)),
            nt: None,
        })
    }

    /// The hypothesis that node `c` (a divisor) is nonzero and the lemma `z_id` that
    /// its value's numerator is (none for a nonzero constant).
    fn nonzero_divisor(&mut self, id: usize, c: usize, vc: &Val) -> Result<(), String> {
        if vc.num.is_zero() {
            return Err(format!("node t{id} divides by 0"));
        }
        if vc.num.as_constant().is_some() {
            return Ok(());
        }
        let t = self.sym.coq(&vc.num);
        let _ = writeln!(
            self.body,
            "Hypothesis dz_{id} : t_{c} <> 0.\nLemma z_{id} : {t} <> 0.\nProof. exact ({} e_{c} dz_{id}). Qed.",
            if vc.den.is_empty() {
                "eu_nump _ _"
            } else {
                "eu_num _ _ _"
            }
        );
        self.facts.entry(t).or_insert(format!("z_{id}"));
        Ok(())
    }

    /// `a ^ e` (a negative power divides, with the hypothesis that `a` is nonzero).
    fn power(&mut self, id: usize, a: usize, e: &str) -> Result<(String, Vec<usize>, Val), String> {
        let e: i64 = e
            .parse()
            .map_err(|_| format!("malformed power in node t{id}"))?;
        let va = self.val(a)?;
        let n = e.unsigned_abs();
        let pow = |p: &Poly| p.pow(n).map_err(|e| e.to_string());
        let rep = |ps: &[Poly]| -> Vec<Poly> { (0..n).flat_map(|_| ps.iter().cloned()).collect() };
        if e >= 0 {
            let val = Val {
                num: pow(&va.num)?,
                den: rep(&va.den),
                dt: format!("({} ^ {n})", Self::dt(&va)),
                nt: None,
            };
            return Ok((format!("t_{a} ^ {n}"), vec![a], val));
        }
        self.nonzero_divisor(id, a, &va)?;
        let val = Val {
            num: pow(&product(&va.den, self.one()))?,
            dt: format!("({} ^ {n})", self.sym.coq(&va.num)),
            nt: None,
            den: rep(&[va.num]),
        };
        Ok((format!("/ (t_{a} ^ {n})"), vec![a], val))
    }

    /// `dot ± a b ± c d …`: `Σ ± a·b` over one common denominator.
    fn dot(&mut self, rest: &[&str]) -> Result<(String, Vec<usize>, Val), String> {
        let mut terms = Vec::new();
        for t in rest.chunks(3) {
            let [s, a, b] = t else {
                return Err("malformed dot node".into());
            };
            terms.push((*s == "-", arg(a)?, arg(b)?));
        }
        let vals: Vec<Val> = (terms.iter())
            .map(|&(_, a, b)| {
                let (va, vb) = (self.val(a)?, self.val(b)?);
                let dt = format!("({} * {})", Self::dt(&va), Self::dt(&vb));
                Ok(Val {
                    num: va.num.mul(&vb.num),
                    den: [va.den, vb.den].concat(),
                    dt,
                    nt: None,
                })
            })
            .collect::<Result<_, String>>()?;
        let den: Vec<Poly> = vals.iter().flat_map(|v| v.den.clone()).collect();
        let mut num = Poly::zero(&self.sym.ctx);
        for (i, ((neg, _, _), v)) in terms.iter().zip(&vals).enumerate() {
            let others: Vec<Poly> = (vals.iter().enumerate())
                .filter(|(j, _)| *j != i)
                .flat_map(|(_, w)| w.den.clone())
                .collect();
            let t = v.num.mul(&product(&others, self.one()));
            num = if *neg { num.sub(&t) } else { num.add(&t) };
        }
        let def: Vec<String> = (terms.iter())
            .map(|(neg, a, b)| format!("{} t_{a} * t_{b}", if *neg { "-" } else { "+" }))
            .collect();
        let def = format!("0 {}", def.join(" "));
        let args = terms.iter().flat_map(|&(_, a, b)| [a, b]).collect();
        // eu_comb: 0 ± F₁ is F₁'s denominator, then each further term multiplies it
        let first = vals.first().ok_or("a dot node without terms")?.dt.clone();
        let dt = (vals.iter().skip(1)).fold(first, |acc, v| format!("({acc} * {})", v.dt));
        let val = Val {
            num,
            den,
            dt,
            nt: None,
        };
        Ok((def, args, val))
    }

    /// A symbol or a rational constant.
    fn leaf(&self, x: &str) -> Result<(String, Val), String> {
        let (n, d) = x.split_once('/').unwrap_or((x, "1"));
        if let (Ok(n), Ok(d)) = (n.parse::<Integer>(), d.parse::<Integer>()) {
            if d == 0 {
                return Err(format!("the constant {x} divides by 0"));
            }
            let den = if d == 1 {
                vec![]
            } else {
                vec![self.sym.constant(&d)]
            };
            let dt = self.sym.coq(&self.sym.constant(&d));
            let num = self.sym.coq(&self.sym.constant(&n));
            let def = if d == 1 {
                num
            } else {
                format!("({num} / {d})")
            };
            return Ok((
                def,
                Val {
                    num: self.sym.constant(&n),
                    den,
                    dt,
                    nt: None,
                },
            ));
        }
        let v = self.sym.var(x)?;
        Ok((
            x.to_string(),
            Val {
                num: v,
                den: vec![],
                dt: String::new(),
                nt: None,
            },
        ))
    }

    /// `sqrt a`: the nonnegative root, whose value is the normal form `y` by `y ≥ 0` (the
    /// branch, a hypothesis `br_id`) and `y² = a`.
    fn sqrt(&mut self, id: usize, a: usize, nf: Option<&str>) -> Result<(), String> {
        let nf = nf.ok_or(format!("node t{id} has no value"))?;
        let target = self.nf_val(id, nf)?;
        let va = self.val(a)?;
        let _ = writeln!(
            self.decls,
            "(* the branch of the square root t{id}: its value is the nonnegative root *)\nHypothesis br_{id} : 0 <= {}.",
            self.text(&target)
        );
        let square = Val {
            num: target.num.mul(&target.num),
            den: [target.den.clone(), target.den.clone()].concat(),
            dt: String::new(),
            nt: None,
        };
        let mut proof = Self::rewrite_args(&[a]) + &self.poses(&[&va, &target, &square])?;
        let _ = writeln!(proof, "  apply eu_sqrt; [exact br_{id} | ].");
        if !square.den.is_empty() {
            // y·y for the fraction y = n/d: the fraction (n·n)/(d·d)
            proof.push_str("  eu_comb.\n");
        }
        proof.push_str(&self.frac_steps(&square, &va)?);
        self.define(id, &format!("sqrt t_{a}"), target, &proof)
    }

    /// `sn`, `cn` or `dn` of a combination of base arguments: the base's symbol or value
    /// when the combination is one base argument, else a variable `ell_id` whose value
    /// (the prover's addition-theorem instance) is the hypothesis `inst_id`.
    fn elliptic(
        &mut self,
        id: usize,
        f: &str,
        combo: &str,
        (hk, hkp): (&str, &str),
        nf: &str,
    ) -> Result<(), String> {
        let parts: Vec<(&str, &str)> = combo.split(',').filter_map(|c| c.split_once(':')).collect();
        let which = ["sn", "cn", "dn"].iter().position(|g| *g == f).unwrap_or(0);
        if let ([(b, "1")], "0", "0") = (parts.as_slice(), hk, hkp) {
            let value = (self.bases.get(*b).map(|v| v[which].clone()))
                .ok_or_else(|| format!("node t{id}: no base {b}"))?;
            return self.base_value(id, &value, nf);
        }
        let target = self.nf_val(id, nf)?;
        let args: Vec<String> = (parts.iter())
            .map(|(b, _)| {
                format!(
                    "{b} = {}",
                    self.bases.get(*b).map_or("?", |v| v[3].as_str())
                )
            })
            .collect();
        let _ = writeln!(
            self.decls,
            "Variable ell_{id} : R.\n(* {f} at {combo} + {hk} K/2 + {hkp} iK'/2 ({}): an addition-theorem instance *)\nHypothesis inst_{id} : ell_{id} = {}.",
            comment(&args.join(", ")),
            self.text(&target)
        );
        let proof = format!("  exact inst_{id}.\n");
        self.define(id, &format!("ell_{id}"), target, &proof)
    }

    /// `sn`, `cn` or `dn` of one base argument: its symbol or its value.
    fn base_value(&mut self, id: usize, value: &str, nf: &str) -> Result<(), String> {
        let val = if value.starts_with('(') {
            self.nf_val(id, value)?
        } else {
            Val {
                num: self.sym.var(value)?,
                den: vec![],
                dt: String::new(),
                nt: None,
            }
        };
        let target = self.nf_val(id, nf)?;
        let proof = self.poses(&[&val, &target])? + &self.frac_steps(&val, &target)?;
        let def = self.text(&val);
        self.define(id, &def, target, &proof)
    }

    /// The lemmas `cl_i : t_a - t_b = 0` of the claims and the theorem, their conjunction.
    pub(super) fn claims(
        &mut self,
        claims: &[(usize, usize)],
        theorem: &str,
    ) -> Result<String, String> {
        let mut out = String::new();
        for (i, &(a, b)) in claims.iter().enumerate() {
            let (va, vb) = (self.val(a)?, self.val(b)?);
            let proof = if a == b {
                "  ring.\n".to_string()
            } else if va.den.is_empty() && vb.den.is_empty() {
                let f = va.num.sub(&vb.num);
                let rw = Self::rewrite_args(&[a, b]);
                format!("{rw}  {}\n", self.cofactor_proof(&f)?)
            } else {
                format!(
                    "{}{}  apply Rminus_diag_eq.\n{}",
                    Self::rewrite_args(&[a, b]),
                    self.poses(&[&va, &vb])?,
                    self.frac_steps(&va, &vb)?
                )
            };
            let _ = writeln!(
                out,
                "Lemma cl_{} : t_{a} - t_{b} = 0.\nProof.\n{proof}Qed.",
                i + 1
            );
        }
        let statement: Vec<String> = claims
            .iter()
            .map(|(a, b)| format!("t_{a} - t_{b} = 0"))
            .collect();
        let mut proof = format!("cl_{}", claims.len());
        for i in (1..claims.len()).rev() {
            proof = format!("(conj cl_{i} {proof})");
        }
        let _ = writeln!(
            out,
            "(* the claim: lhs - rhs = 0 for every claim line of the certificate *)\nTheorem {theorem} : {}.\nProof. exact {proof}. Qed.",
            statement.join(" /\\ ")
        );
        Ok(out)
    }
}
