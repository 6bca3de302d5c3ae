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

    /// A value as a Coq term: `(num)` for a polynomial, else `(num) / (den)`.
    fn text(&self, v: &Val) -> String {
        if v.den.is_empty() {
            return self.sym.coq(&v.num);
        }
        self.frac_text(v)
    }

    /// A value as a Coq term `(num) / (den)` (`/ 1` for a polynomial).
    fn frac_text(&self, v: &Val) -> String {
        let den: Vec<String> = v.den.iter().map(|d| self.sym.coq(d)).collect();
        let den = match den.len() {
            0 => "1".to_string(),
            1 => den[0].clone(),
            _ => format!("({})", den.join(" * ")),
        };
        format!("{} / {den}", self.sym.coq(&v.num))
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
        let den = if den.is_one() { vec![] } else { vec![den] };
        Ok(Val { num, den })
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

    /// The proof of `op(arguments) = to` through the value `from` with denominators: by
    /// `field`, `from` is `P / (D·R)` when the product `Q` of its denominators is the
    /// denominator `D` of `to` times `R`, and then `P − N·R` is the combination of the
    /// relations (smaller than `P·D − N·Q`); otherwise `P / Q` and [`Self::frac_steps`].
    fn reduce_steps(&self, from: &Val, to: &Val) -> Result<String, String> {
        let q = product(&from.den, self.one());
        let d = product(&to.den, self.one());
        let r = match (to.den.is_empty(), q.divides(&d)) {
            (false, Ok(Some(r))) => r,
            _ => {
                let t = format!(
                    "  transitivity ({}); [field; nzs | ].\n",
                    self.frac_text(from)
                );
                return Ok(t + &self.frac_steps(from, to)?);
            }
        };
        let p = self.sym.coq(&from.num);
        let dt = self.sym.coq(&d);
        if r.is_one() {
            let f = from.num.sub(&to.num);
            return Ok(format!(
                "  transitivity ({p} / {dt}); [field; nzs | ].\n  apply eu_same.\n  {}\n",
                self.cofactor_proof(&f)?
            ));
        }
        let rt = self.sym.coq(&r);
        let qt: Vec<String> = from.den.iter().map(|f| self.sym.coq(f)).collect();
        let f = from.num.sub(&to.num.mul(&r));
        Ok(format!(
            "  assert ({rt} <> 0) by (apply (eu_nzq ({}) {dt}); [nzp | ring]).\n  transitivity ({p} / ({dt} * {rt})); [field; nzs | ].\n  apply eu_fracq; [nzp | nzp | ].\n  {}\n",
            qt.join(" * "),
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

    /// The proof of `f = 0` from the root relations: `ring` on `f = Σ qᵢ (rᵢ² − aᵢ)`,
    /// then each relation.
    fn cofactor_proof(&self, f: &Poly) -> Result<String, String> {
        let qs = self.sym.cofactors(f)?;
        let terms: usize = qs.iter().map(Poly::len).sum();
        if terms > MAX_TERMS {
            return Err(format!(
                "a step's cofactors have {terms} terms, too many for the Coq export"
            ));
        }
        let mut terms = Vec::new();
        let mut rewrites = Vec::new();
        for (q, (v, rad)) in qs.iter().zip(&self.sym.roots) {
            if q.is_zero() {
                continue;
            }
            let name = &self.sym.names[*v];
            let rel = format!("({name} ^ 2 - {})", self.sym.coq(rad));
            terms.push(format!("{} * {rel}", self.sym.coq(q)));
            rewrites.push(format!("(Rminus_diag_eq _ _ rel_{name})"));
        }
        if terms.is_empty() {
            return Ok("ring.".into());
        }
        Ok(format!(
            "transitivity ({}); [ring | rewrite {}; ring].",
            terms.join(" + "),
            rewrites.join(", ")
        ))
    }

    /// Writes `Definition t_id`, the lemma `e_id` and records the value.
    fn define(&mut self, id: usize, def: &str, target: Val, proof: &str) -> Result<(), String> {
        Self::guard(id, &target)?;
        let _ = writeln!(
            self.body,
            "Definition t_{id} := {def}.\nLemma e_{id} : t_{id} = {}.\nProof.\n  unfold t_{id}.\n{proof}Qed.",
            self.text(&target)
        );
        self.vals.insert(id, target);
        Ok(())
    }

    /// The rewriting of the arguments by their values.
    fn rewrite_args(args: &[usize]) -> String {
        let mut seen: Vec<usize> = Vec::new();
        for a in args {
            if !seen.contains(a) {
                seen.push(*a);
            }
        }
        if seen.is_empty() {
            return String::new();
        }
        let list: Vec<String> = seen.iter().map(|a| format!("e_{a}")).collect();
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

    /// A rational operation (or a symbol or constant): `field` from the arguments'
    /// values, then the reduction to the normal form, if the node has one.
    fn rational(&mut self, id: usize, b: &[&str], nf: Option<&str>) -> Result<(), String> {
        let (def, args, val) = self.operation(id, b)?;
        Self::guard(id, &val)?;
        let target = match nf {
            Some(t) => self.nf_val(id, t)?,
            None => val.clone(),
        };
        let arg_vals: Vec<Val> = args
            .iter()
            .map(|a| self.val(*a))
            .collect::<Result<_, _>>()?;
        let mut all: Vec<&Val> = arg_vals.iter().collect();
        all.extend([&val, &target]);
        let mut proof = Self::rewrite_args(&args) + &self.poses(&all)?;
        // a polynomial value: the operation on the arguments is that polynomial (ring)
        if val.den.is_empty() {
            proof.push_str(&self.frac_steps(&val, &target)?);
        } else if nf.is_some() {
            proof.push_str(&self.reduce_steps(&val, &target)?);
        } else {
            proof.push_str("  field; nzs.\n");
        }
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
                };
                Ok((format!("- t_{}", arg(a)?), vec![arg(a)?], val))
            }
            ["dot", rest @ ..] => self.dot(rest),
            [a, "^", e] => self.power(id, arg(a)?, e),
            [a, op, c] => {
                let (x, y) = (arg(a)?, arg(c)?);
                let def = format!("t_{x} {op} t_{y}");
                let (va, vc) = (self.val(x)?, self.val(y)?);
                let val = match *op {
                    "+" | "-" => {
                        let l = va.num.mul(&product(&vc.den, one.clone()));
                        let r = vc.num.mul(&product(&va.den, one));
                        let num = if *op == "+" { l.add(&r) } else { l.sub(&r) };
                        Val {
                            num,
                            den: [va.den, vc.den].concat(),
                        }
                    }
                    "*" => Val {
                        num: va.num.mul(&vc.num),
                        den: [va.den, vc.den].concat(),
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
            };
            return Ok((format!("t_{a} ^ {n}"), vec![a], val));
        }
        self.nonzero_divisor(id, a, &va)?;
        let val = Val {
            num: pow(&product(&va.den, self.one()))?,
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
                Ok(Val {
                    num: va.num.mul(&vb.num),
                    den: [va.den, vb.den].concat(),
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
        Ok((def, args, Val { num, den }))
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
                },
            ));
        }
        let v = self.sym.var(x)?;
        Ok((
            x.to_string(),
            Val {
                num: v,
                den: vec![],
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
        };
        let mut proof = Self::rewrite_args(&[a]) + &self.poses(&[&va, &target, &square])?;
        let _ = writeln!(proof, "  apply eu_sqrt; [exact br_{id} | ].");
        if square.den.is_empty() {
            proof.push_str(&self.frac_steps(&square, &va)?);
        } else {
            let _ = writeln!(
                proof,
                "  transitivity ({}); [field; nzs | ].",
                self.frac_text(&square)
            );
            proof.push_str(&self.frac_steps(&square, &va)?);
        }
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
