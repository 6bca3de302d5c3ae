//! The polynomials of a Coq export (module [`super::coq_export`]): read from a
//! certificate's text, written as Coq terms of `R`, and the cofactors that show a
//! polynomial lies in the ideal of the root relations `r² − a`.

use crate::algebra::flint::{Ctx, Poly};
use rug::Integer;
use std::collections::HashMap;
use std::sync::Arc;

/// The symbols of one certificate: field symbols and roots, in one polynomial context.
pub(crate) struct Symbols {
    pub ctx: Arc<Ctx>,
    pub names: Vec<String>,
    index: HashMap<String, usize>,
    /// `(variable, radicand)` of every root, in the certificate's order.
    pub roots: Vec<(usize, Poly)>,
}

impl Symbols {
    /// The symbols `names` (each once), in one context.
    pub fn new(names: Vec<String>) -> Result<Symbols, String> {
        let mut index = HashMap::new();
        for (i, n) in names.iter().enumerate() {
            if index.insert(n.clone(), i).is_some() {
                return Err(format!("the symbol {n} is declared twice"));
            }
        }
        Ok(Symbols {
            ctx: Ctx::new(names.len().max(1)),
            names,
            index,
            roots: Vec::new(),
        })
    }

    /// The variable of symbol `name`.
    pub fn var(&self, name: &str) -> Result<Poly, String> {
        let i = self
            .index
            .get(name)
            .ok_or_else(|| format!("unknown symbol {name}"))?;
        Ok(Poly::var(&self.ctx, *i))
    }

    /// The constant `n`.
    pub fn constant(&self, n: &Integer) -> Poly {
        Poly::from_integer(&self.ctx, n)
    }

    /// Parses a polynomial as the certificate writes it (`-3*x**2*y + z - 1`).
    pub fn parse(&self, text: &str) -> Result<Poly, String> {
        let text = text.trim().replace("**", "^");
        let mut terms: Vec<(Integer, Vec<u64>)> = Vec::new();
        let mut rest = text.as_str();
        let mut neg = false;
        if let Some(r) = rest.strip_prefix('-') {
            (neg, rest) = (true, r.trim_start());
        }
        loop {
            let cut = [" + ", " - "]
                .iter()
                .filter_map(|s| rest.find(s).map(|i| (i, s.starts_with(" -"))))
                .min();
            let (term, next) = match cut {
                Some((i, n)) => (&rest[..i], Some((n, &rest[i + 3..]))),
                None => (rest, None),
            };
            terms.push(self.parse_term(term, neg)?);
            let Some((n, r)) = next else { break };
            (neg, rest) = (n, r);
        }
        let refs = terms.iter().map(|(c, e)| (c, e.as_slice()));
        Ok(Poly::from_terms(&self.ctx, refs))
    }

    /// One term `c*x^2*y` (with its sign) as a coefficient and exponents.
    fn parse_term(&self, term: &str, neg: bool) -> Result<(Integer, Vec<u64>), String> {
        let mut coef = Integer::from(if neg { -1 } else { 1 });
        let mut exps = vec![0u64; self.ctx.nvars()];
        for f in term.split('*').map(str::trim) {
            if let Ok(n) = f.parse::<Integer>() {
                coef *= n;
                continue;
            }
            let (name, e) = match f.split_once('^') {
                Some((n, e)) => (n, e.parse::<u64>().map_err(|_| bad(term))?),
                None => (f, 1),
            };
            let i = *self.index.get(name).ok_or_else(|| bad(term))?;
            exps[i] += e;
        }
        Ok((coef, exps))
    }

    /// Parses `(N)/(D)` into its numerator and denominator.
    pub fn parse_frac(&self, text: &str) -> Result<(Poly, Poly), String> {
        let t = text.trim();
        let inner = t
            .strip_prefix('(')
            .and_then(|t| t.strip_suffix(')'))
            .ok_or_else(|| bad(t))?;
        let (n, d) = inner.split_once(")/(").ok_or_else(|| bad(t))?;
        Ok((self.parse(n)?, self.parse(d)?))
    }

    /// The polynomial as a Coq term of `R`, in parentheses (`(3 * x ^ 2 - y)`).
    pub fn coq(&self, p: &Poly) -> String {
        if p.is_zero() {
            return "0".into();
        }
        let mut out = String::from("(");
        p.for_each_term(|c, e| {
            let mono: Vec<String> = (e.iter().enumerate())
                .filter(|&(_, &k)| k > 0)
                .map(|(i, &k)| match k {
                    1 => self.names[i].clone(),
                    _ => format!("{} ^ {k}", self.names[i]),
                })
                .collect();
            let first = out.len() == 1;
            out.push_str(match (c.cmp0().is_lt(), first) {
                (true, true) => "- ",
                (true, false) => " - ",
                (false, true) => "",
                (false, false) => " + ",
            });
            let abs = c.clone().abs();
            match (mono.is_empty(), abs == 1) {
                (true, _) => out.push_str(&abs.to_string()),
                (false, true) => out.push_str(&mono.join(" * ")),
                (false, false) => out.push_str(&format!("{abs} * {}", mono.join(" * "))),
            }
        });
        out.push(')');
        out
    }

    /// The cofactors `qᵢ` with `f = Σ qᵢ (rᵢ² − aᵢ)` over the roots, or an error when
    /// `f` does not reduce to 0 modulo the root relations.
    pub fn cofactors(&self, f: &Poly) -> Result<Vec<Poly>, String> {
        let mut f = f.clone();
        let mut qs: Vec<Poly> = self.roots.iter().map(|_| Poly::zero(&self.ctx)).collect();
        // a radicand may hold earlier roots: repeat until no root has degree 2 or more
        for _ in 0..=self.roots.len() {
            let mut changed = false;
            for (j, (v, rad)) in self.roots.iter().enumerate() {
                let rel = Poly::var(&self.ctx, *v).pow(2).map_err(|e| e.to_string())?;
                let rel = rel.sub(rad);
                while f.degree(*v) >= 2 {
                    let e = f.degree(*v) as u64;
                    let x = Poly::var(&self.ctx, *v)
                        .pow(e - 2)
                        .map_err(|e| e.to_string())?;
                    let q = f.coefficient_in(*v, e).mul(&x);
                    f = f.sub(&q.mul(&rel));
                    qs[j] = qs[j].add(&q);
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        if !f.is_zero() {
            return Err("a step does not reduce to 0 modulo the root relations".into());
        }
        Ok(qs)
    }
}

fn bad(text: &str) -> String {
    format!("malformed polynomial '{text}'")
}
