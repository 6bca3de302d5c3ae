//! Signs that the theory of the Jacobi functions fixes: `dn u > 0` for real `u` and a
//! real modulus with `0 < k² < 1` (DLMF 22.2.4 and 22.4.1: `dn` is real, even, never 0
//! and 1 at `u = 0` on the real line).  A base argument of an elliptic table gets the
//! fact when its argument is real by construction and the modulus is proved in
//! `(0, 1)`: both are decided from the symbols' definitions, never from the points.
//!
//! **Real by construction.**  A value is real when every symbol it uses is: an
//! indeterminate of the claim (a real draw), a named quantity whose definition is real,
//! a sign symbol, the principal root of a radicand proved positive, `sn`, `cn`, `dn` of
//! a real base argument, `K`, `K'` of a modulus in `(0, 1)`, and an opaque symbol
//! declared real ([`Ring::declare_real`]: a real chart parameter).  No other opaque
//! symbol is.

use super::ring::{Ring, VarKind};
use super::sign_state::{Fact, FactEvidence, FactSource};
use super::sym::Sym;
use super::val::Val;

/// How deep the realness test follows definitions.
const MAX_DEPTH: usize = 6;

impl Ring {
    /// Declares an opaque symbol real: a chart parameter that ranges over real values
    /// (the phase step `δ` of a map's parametrization, with `h` solved from it).
    pub fn declare_real(&self, v: &Sym) {
        if let Some(j) = v.as_field_var() {
            self.state().signs.real_opaque.push(j);
        }
    }

    /// Records `dn > 0` for the new base `base` of table `t`, of argument `arg`, whose
    /// `dn` is `d`, when the argument is real and the modulus is proved in `(0, 1)`.
    /// Returns whether the base is real.
    pub(crate) fn note_dn_positive(
        &self,
        (t, base): (usize, usize),
        arg: &Val,
        d: &Val,
        what: &str,
    ) -> bool {
        let real_base = self.real_modulus(t) && self.is_real(arg, 0);
        if real_base {
            self.state().signs.facts.push(Fact {
                value: d.clone(),
                why: format!("dn({what}) > 0: a real argument, 0 < k² < 1 (DLMF 22.4.1)"),
                source: FactSource::Base(t, base),
            });
        }
        real_base
    }

    /// Records `dn u > 0` for `dn u = d` of an argument `u` of table `t` (expanded by
    /// the addition theorems), when `u` is real and the modulus is proved in `(0, 1)`;
    /// a certificate names the fact by the derivation of `d`, where it has one.
    pub(crate) fn note_dn_of_real_argument(
        &self,
        t: usize,
        u: &Val,
        d: &Sym,
        what: impl FnOnce() -> String,
    ) {
        let known = (self.state().signs.facts.iter())
            .any(|f| f.value.num == d.val.num && f.value.den == d.val.den);
        if known || d.val.num.len() > 64 || !self.real_modulus(t) || !self.is_real(u, 0) {
            return;
        }
        let why = format!(
            "dn({}) > 0: a real argument, 0 < k² < 1 (DLMF 22.4.1)",
            what()
        );
        let source = d
            .node
            .clone()
            .map_or(FactSource::Unrecorded, FactSource::Node);
        self.state().signs.facts.push(Fact {
            value: (*d.val).clone(),
            why,
            source,
        });
    }

    /// Is the modulus of table `t` real with `0 < k² < 1` (proved)?
    fn real_modulus(&self, t: usize) -> bool {
        self.real_quarter_period(t, true) && self.real_quarter_period(t, false)
    }

    /// Is `K(k)` (`K′(k)` when `complementary`) of table `t` real: `k` real with
    /// `k² < 1` (`k² > 0`) proved (DLMF 19.2.8, 19.7.2)?
    fn real_quarter_period(&self, t: usize, complementary: bool) -> bool {
        let (k, k2) = {
            let st = self.state();
            (st.tables[t].k.clone(), st.tables[t].k2.clone())
        };
        if !self.is_real(&k, 0) {
            return false;
        }
        let k2 = Sym::from_val(self, k2, None);
        if complementary {
            return positive(&k2);
        }
        self.integer(1)
            .try_sub(&k2)
            .is_ok_and(|rest| positive(&rest))
    }

    /// Is the value real by construction (see the module)?
    pub(crate) fn is_real(&self, v: &Val, depth: usize) -> bool {
        if depth > MAX_DEPTH {
            return false;
        }
        let inner = &self.inner;
        let used: Vec<usize> = (v.num.used_vars().into_iter())
            .chain(v.den.used_vars())
            .collect();
        used.into_iter().all(|idx| match inner.root_of_var(idx) {
            Some(i) => self.root_is_real(i, depth),
            None => self.var_is_real(idx - inner.opts.max_roots, depth),
        })
    }

    fn root_is_real(&self, i: usize, depth: usize) -> bool {
        let (radicand, principal, real) = {
            let st = self.state();
            let r = &st.roots[i];
            (r.radicand.clone(), r.principal, r.real)
        };
        if real || radicand.is_one() {
            return true;
        }
        let one = super::flint::Poly::from_i64(&self.inner.ctx, 1);
        let sh = self.shadow_of(&radicand, &one);
        let rad = Val {
            num: radicand,
            den: one,
            sh,
        };
        principal && self.is_real(&rad, depth + 1) && positive(&Sym::from_val(self, rad, None))
    }

    fn var_is_real(&self, j: usize, depth: usize) -> bool {
        let kind = self.state().vars[j].kind.clone();
        match kind {
            VarKind::Indeterminate => true,
            VarKind::Named(def) => self.is_real(&def, depth + 1),
            VarKind::Sn { table, base } | VarKind::Zeta { table, base } => {
                (self.state().tables[table].bases.get(base)).is_some_and(|b| b.real)
            }
            VarKind::QuarterK { table } => self.real_quarter_period(table, false),
            VarKind::QuarterKp { table } => self.real_quarter_period(table, true),
            VarKind::ThirdK { table } => self.real_modulus(table),
            VarKind::Opaque { .. } => self.state().signs.real_opaque.contains(&j),
            VarKind::Jet { ref arg, ref k, .. } => {
                self.is_real(arg, depth + 1) && self.is_real(k, depth + 1)
            }
        }
    }

    /// The sign of `x` by a fact of the theory: `x` is a fact's value times a factor of
    /// proved sign.  A certificate records the evidence (the fact by its derivation and
    /// the factor), which a recheck proves again.
    pub(crate) fn fact_sign(&self, x: &Sym) -> Option<i32> {
        let facts = self.state().signs.facts.clone();
        for (i, fact) in facts.into_iter().enumerate() {
            let f = Sym::from_val(self, fact.value, None);
            let Ok(q) = x.try_div(&f) else { continue };
            let s = match q.as_rational() {
                Some(r) if r != 0 => Some(if r < 0 { -1 } else { 1 }),
                Some(_) => None,
                None => q.proved_sign_of_quotient(),
            };
            if let Some(s) = s {
                self.note(fact.why);
                self.record_fact_sign(x, s, i, &fact.source, &q);
                return Some(s);
            }
        }
        None
    }

    /// Records, for a certificate, that fact `i` decides the sign `s` of `x = fact · q`.
    fn record_fact_sign(&self, x: &Sym, s: i32, i: usize, source: &FactSource, q: &Sym) {
        if !self.certifying() {
            return;
        }
        if matches!(source, FactSource::Unrecorded) {
            self.mark_uncertified(
                "a sign proved by a fact of the Jacobi functions whose value has no derivation",
            );
            return;
        }
        let mut st = self.state();
        let known = (st.signs.fact_evidence.iter())
            .any(|e| e.fact == i && e.value.num == x.val.num && e.value.den == x.val.den);
        if !known {
            st.signs.fact_evidence.push(FactEvidence {
                node: x.node.clone(),
                value: (*x.val).clone(),
                sign: s,
                fact: i,
                factor: (*q.val).clone(),
            });
        }
    }
}

/// Is the value proved positive?  The test leaves no trace: a fact it admits enters a
/// proof only through [`Ring::fact_sign`], which records itself.
fn positive(x: &Sym) -> bool {
    match x.as_rational() {
        Some(q) => q > 0,
        None => x.proved_sign_unrecorded() == Some(1),
    }
}

impl Sym {
    /// Is the value real by construction: built from indeterminates, real sn/cn/dn
    /// symbols and principal roots of proved-positive radicands only?
    pub(crate) fn is_real_by_construction(&self) -> bool {
        self.ring.is_real(&self.val, 0)
    }
}
