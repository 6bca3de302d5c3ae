//! The one place where a proof decides a sign.  Every sign, comparison, `abs`,
//! square-root branch and regime that a proof takes is a [`Decision`]: proved on the
//! claim's domain, given by a hypothesis (one the catalogue states, or the condition of
//! the part of the domain a split proof is on), fixed by a definition (a sign symbol
//! `σ = sign(x)` has `σ·x > 0`), or undecided.  An undecided sign is never taken from
//! the values at domain points: the proof stops there (and may split the domain by it,
//! module [`super::split`]).
//!
//! **Proved signs.**  A value `N/D` has the sign of `N` times that of `D`.  The sign of
//! a polynomial is proved, in this order,
//! 1. by the parametrization of the domain by positive parameters (module
//!    [`super::positivity`]), where the positive square roots count as parameters, and
//!    `sn²` of a real base argument as a parameter in `[0, 1]`: all coefficients of one
//!    sign, at once or after multiplying by `(1 + Σ tᵢ)ᴺ` (Pólya); where that proves
//!    nothing, by the box of the sampled intervals (the parametrization's alternative);
//! 2. where the polynomial is `a + b·r` in its most significant square root `r` (the
//!    positive root of a radicand proved positive): from the signs of `a` and `b`, and,
//!    where they differ, from the sign of `a² − b²·r²` (the side that wins), each proved
//!    the same way;
//! 3. where it is `b·σ` for a sign symbol `σ = sign(x)` and `x` divides `b`: from the sign
//!    of `b/x`, since `σ·x > 0`.
//!
//! 4. a value `a²/b²` (squares of polynomials) is positive where the sign of `a/b` is
//!    decided and nonzero (decided as that sign is: proved, or by a hypothesis).
//!
//! A value is also proved of one sign when it is a fact's value (`dn u > 0` for a real
//! argument, module `elliptic_facts`) times a factor proved as above.
//!
//! ```
//! use eulertop::algebra::{Ring, RingOptions};
//! use eulertop::algebra::positivity::Parametrization;
//! use std::sync::Arc;
//! // A > B > C > 0 as C = t_C, B = C + t_B, A = B + t_A
//! let mut par = Parametrization::new();
//! let c = par.positive("t_C").unwrap();
//! let b = c.add(&par.positive("t_B").unwrap());
//! let a = b.add(&par.positive("t_A").unwrap());
//! par.bind("C", c, "C = t_C".into());
//! par.bind("B", b, "B = C + t_B".into());
//! par.bind("A", a, "A = B + t_A".into());
//! let ring = Ring::new(RingOptions { points: 1, positivity: Some(Arc::new(par)), ..Default::default() });
//! let a = ring.indeterminate_f64("A", &[3.0]).unwrap();
//! let b = ring.indeterminate_f64("B", &[2.0]).unwrap();
//! let c = ring.indeterminate_f64("C", &[1.0]).unwrap();
//! // √((A − B)(A − C)) < A: the roots are positive, and (A − B)(A − C) − A² < 0
//! let r = ((a.clone() - b) * (a.clone() - c)).sqrt().unwrap();
//! assert_eq!((r - a).sign().unwrap(), -1);
//! // a sign that is not proved is not decided: x is positive at the one point only
//! let x = ring.indeterminate_f64("x", &[0.5]).unwrap();
//! assert!(x.sign().is_err());
//! ```

use super::flint::Poly;
use super::positivity::Parametrization;
use super::ring::Ring;
use super::sym::Sym;

/// How a sign was decided.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Decision {
    /// Proved on the claim's domain (exact, or by the tests of this module).
    Proved(i32),
    /// By a hypothesis: the catalogue's statement (its label), or the condition of the
    /// part of the domain the proof is on.
    Hypothesis(i32, String),
    /// By the definition of a sign symbol (`σ·x > 0` for `σ = sign(x)`).
    Definition(i32),
    /// Not decided: neither proved nor given.
    Unknown,
}

impl Decision {
    /// The sign, where decided.
    pub fn sign(&self) -> Option<i32> {
        match self {
            Decision::Proved(s) | Decision::Hypothesis(s, _) | Decision::Definition(s) => Some(*s),
            Decision::Unknown => None,
        }
    }
}

/// How deep the test of rule 2 recurses (one square root per level).
const MAX_DEPTH: usize = 6;
/// The largest polynomial, in terms, whose sign rule 2 decomposes.
const MAX_TERMS: usize = 400;
/// The most polynomials one sign test of rules 1–3 examines.
const MAX_TESTS: usize = 48;

/// The largest polynomial, in terms, whose sign rule 2b decides.
const MAX_RULE_2B_TERMS: usize = 64;

/// The largest polynomial, in terms, that rule 2b factors.
const MAX_FACTOR_TERMS: usize = 120;

/// The most terms of a value and a hypothesis whose products `ratio_sign` forms.
const MAX_PRODUCT_TERMS: usize = 160;

impl Sym {
    /// The sign of a real value, decided as the module says; never from the points.
    pub fn decision(&self) -> Decision {
        if self.is_exact_zero() {
            return Decision::Proved(0);
        }
        if let Some(q) = self.as_rational() {
            return Decision::Proved(if q < 0 { -1 } else { 1 });
        }
        // the condition of the part of the domain itself: a split's value is never
        // proved of one sign on the domain (it would not have split it)
        if let Some((s, source)) = self.part_condition_sign() {
            return Decision::Hypothesis(s, source);
        }
        if let Some(s) = self.proved_sign().or_else(|| self.ring.fact_sign(self)) {
            return Decision::Proved(s);
        }
        if let Some(s) = self.defined_sign() {
            return Decision::Definition(s);
        }
        if let Some(d) = self.quick_root_decision() {
            return d;
        }
        match self.hypothesis_sign() {
            Some((s, source)) => Decision::Hypothesis(s, source),
            None => (self.square_decision())
                .or_else(|| self.root_decision())
                .unwrap_or(Decision::Unknown),
        }
    }

    /// Rule 4: a value `a²/b²` (numerator and denominator squares of polynomials) is
    /// positive where `a/b` has a decided nonzero sign, decided the way that sign is.
    fn square_decision(&self) -> Option<Decision> {
        let (n, d) = (&self.val.num, &self.val.den);
        if n.as_constant().is_some() && d.as_constant().is_some() {
            return None;
        }
        let (a, b) = (n.sqrt()?, d.sqrt()?);
        let base = self.ring.quotient_of_polys(a, b).ok()?;
        let decision = match base.decision() {
            Decision::Proved(s) if s != 0 => Decision::Proved(1),
            Decision::Hypothesis(s, source) if s != 0 => Decision::Hypothesis(1, source),
            Decision::Definition(s) if s != 0 => Decision::Definition(1),
            _ => return None,
        };
        if self.ring.certifying() {
            let recorded = match &decision {
                Decision::Hypothesis(_, label) => {
                    self.record_hypothesis_sign(1, label, Some(&base))
                }
                _ => false,
            };
            if !recorded {
                self.ring
                    .mark_uncertified("the sign of a square a²/b² from the sign of a/b");
            }
        }
        Some(decision)
    }

    /// [`Sym::decision`]'s sign, where decided.
    pub(crate) fn decided_sign(&self) -> Option<i32> {
        self.decision().sign()
    }
}

impl Ring {
    /// The sign of a polynomial of the ring's context on the domain, proved by rules 1–3
    /// of the module; `None` where they do not prove it.
    pub(crate) fn tower_sign(&self, par: &Parametrization, p: &Poly, depth: usize) -> Option<i32> {
        self.tower_sign_within(par, p, depth, &std::cell::Cell::new(MAX_TESTS))
    }

    /// [`Ring::tower_sign`] with a budget of polynomials to examine.
    fn tower_sign_within(
        &self,
        par: &Parametrization,
        p: &Poly,
        depth: usize,
        budget: &std::cell::Cell<usize>,
    ) -> Option<i32> {
        if p.is_zero() || budget.get() == 0 {
            return None;
        }
        budget.set(budget.get() - 1);
        if let Some(c) = p.as_constant() {
            return Some(if c < 0 { -1 } else { 1 });
        }
        let images = self.sign_images(par, p)?;
        if let Some((s, n)) = par.poly_sign_polya(p, &images) {
            self.note_polya(n);
            return Some(s);
        }
        if depth >= MAX_DEPTH || p.len() > MAX_TERMS {
            return None;
        }
        let inner = &self.inner;
        // the most significant root: the lowest variable index among the roots
        let rv = (p.used_vars().into_iter()).find(|&v| inner.root_of_var(v).is_some())?;
        let i = inner.root_of_var(rv)?;
        let (radicand, positive, sign_symbol) = {
            let st = self.state();
            let r = st.roots.get(i)?;
            (r.radicand.clone(), r.is_positive(), r.radicand.is_one())
        };
        let a = p.coefficient_in(rv, 0);
        let b = p.coefficient_in(rv, 1);
        if sign_symbol {
            return self.folded_product_sign(par, (&a, &b), i, depth, budget);
        }
        if !positive || self.tower_sign_within(par, &radicand, depth + 1, budget) != Some(1) {
            return None;
        }
        if a.is_zero() {
            return self.tower_sign_within(par, &b, depth + 1, budget);
        }
        let sa = self.tower_sign_within(par, &a, depth + 1, budget);
        let sb = self.tower_sign_within(par, &b, depth + 1, budget);
        let q = || inner.reduce(a.mul(&a).sub(&b.mul(&b).mul(&radicand)));
        match (sa, sb) {
            (Some(sa), Some(sb)) if sa == sb => Some(sa),
            (Some(sa), Some(_)) => Some(sa * self.tower_sign_within(par, &q(), depth + 1, budget)?),
            // rule 2b: one side of known sign that wins, the other of unknown sign
            (Some(sa), None) if p.len() <= MAX_RULE_2B_TERMS => {
                (self.factored_sign(par, &q(), depth + 1, budget)? == 1).then_some(sa)
            }
            (None, Some(sb)) if p.len() <= MAX_RULE_2B_TERMS => {
                (self.factored_sign(par, &q(), depth + 1, budget)? == -1).then_some(sb)
            }
            (Some(_), None) | (None, Some(_)) => None,
            (None, None) => None,
        }
    }

    /// The sign of `q = a² − b²·r²` in rule 2b: by rules 1–3, else as the product of
    /// the signs of its irreducible factors, each proved by rules 1–3 with the
    /// parametrization or with its alternative (the box of the sampled intervals).  Each
    /// factor's sign then holds on the sampled domain, which both parametrizations
    /// cover, and so does the product's.  A certificate records `q`, its sign and its
    /// factors (a `dominance` line), whose signs a recheck proves again.
    fn factored_sign(
        &self,
        par: &Parametrization,
        q: &Poly,
        depth: usize,
        budget: &std::cell::Cell<usize>,
    ) -> Option<i32> {
        let (s, f) = match self.tower_sign_within(par, q, depth, budget) {
            Some(s) => (s, None),
            None => {
                if q.len() > MAX_FACTOR_TERMS {
                    return None;
                }
                let f = q.factor().ok()?;
                let mut s = f.constant.cmp0() as i32;
                for (g, k) in &f.factors {
                    // a factor to an even power: g² > 0 suffices (g ≠ 0)
                    let g = if k % 2 == 1 { g.clone() } else { g.mul(g) };
                    let sg = self.tower_sign_within(par, &g, depth, budget).or_else(|| {
                        let alt = par.alternative()?;
                        self.tower_sign_within(alt, &g, depth, budget)
                    })?;
                    s *= sg;
                }
                (s, Some(f))
            }
        };
        if s != 0 && self.certifying() {
            let (constant, factors) = match f {
                Some(f) => (f.constant, f.factors),
                None => (rug::Integer::from(1), vec![(q.clone(), 1)]),
            };
            let mut st = self.state();
            if !(st.signs.dominance.iter()).any(|d| d.q == *q) {
                (st.signs.dominance).push(super::sign_state::Dominance {
                    q: q.clone(),
                    sign: s,
                    constant,
                    factors,
                });
            }
        }
        (s != 0).then_some(s)
    }

    /// Rule 3: the sign of `a + b·σ` for the sign symbol of root `i`, where `a = 0`, `σ`
    /// is `sign(x)` for an indeterminate `x`, and `x` divides `b`.
    fn folded_product_sign(
        &self,
        par: &Parametrization,
        (a, b): (&Poly, &Poly),
        i: usize,
        depth: usize,
        budget: &std::cell::Cell<usize>,
    ) -> Option<i32> {
        if !a.is_zero() {
            return None;
        }
        let (var, s) =
            (self.state().signs.folded.iter()).find_map(|f| (f.root == i).then_some(f.var))??;
        let x = Poly::var(b.ctx(), var);
        let quotient = b.divides(&x).ok()??;
        // b·σ = (b/x)·(σ·x), and σ·x has the sign s by the definition of σ
        // a certificate states the definition (a `signsym` line), which a recheck uses
        let q = self.tower_sign_within(par, &quotient, depth + 1, budget)?;
        Some(s * q)
    }
}

impl Sym {
    /// `+1` for `σ·x` (or `−1` for its negative) where `σ` is the sign symbol of a folded
    /// value `x` ([`Sym::folded_sign`]): the definition of `σ`.
    pub(crate) fn defined_sign(&self) -> Option<i32> {
        let st = self.ring.state();
        if st.signs.folded.is_empty() {
            return None;
        }
        let defs: Vec<String> = st.signs.folded.iter().map(|f| f.positive.clone()).collect();
        drop(st);
        let text = self.render();
        if defs.contains(&text) {
            return Some(1);
        }
        defs.contains(&self.negate().render()).then_some(-1)
    }

    /// The sign of this value where it is the condition of the part of the domain the
    /// proof is on, or its negative (a cheap test, made before any proof).
    pub(crate) fn part_condition_sign(&self) -> Option<(i32, String)> {
        let parts = &self.ring.options().hypotheses;
        if parts.is_empty() {
            return None;
        }
        let (text, neg) = (self.render(), self.negate().render());
        parts.iter().find_map(|(h, s)| {
            let label = || format!("{} {} 0", h.what, if *s > 0 { ">" } else { "<" });
            (h.text == text)
                .then(|| (*s, label()))
                .or_else(|| (h.text == neg).then(|| (-*s, label())))
        })
    }

    /// The sign of this value by a hypothesis: the condition of the part of the domain
    /// the proof is on ([`super::RingOptions::hypotheses`]), or a hypothesis the claim
    /// states ([`Ring::state_hypothesis`]), with the hypothesis' label.  The value must
    /// be a hypothesis' value times a factor of proved sign (or the value itself, or its
    /// negative).
    pub(crate) fn hypothesis_sign(&self) -> Option<(i32, String)> {
        let parts = &self.ring.options().hypotheses;
        let stated = self.ring.state().signs.stated.clone();
        if parts.is_empty() && stated.is_empty() {
            return None;
        }
        let (text, neg) = (self.render(), self.negate().render());
        for (h, s) in parts {
            let label = format!("{} {} 0", h.what, if *s > 0 { ">" } else { "<" });
            if h.text == text {
                return Some((*s, label));
            }
            if h.text == neg {
                return Some((-*s, label));
            }
            if let Some(q) = h.in_ring(&self.ring).and_then(|v| self.ratio_sign(&v)) {
                return Some((q * s, label));
            }
        }
        for (val, s, label) in stated {
            let v = Sym::from_val(&self.ring, val, None);
            if let Some(q) = self.ratio_sign(&v) {
                self.ring.assume(
                    super::ring::AssumptionKind::Hypothesis(label.clone()),
                    label.clone(),
                );
                return Some((q * s, label));
            }
        }
        None
    }

    /// Adds a sign's evidence to the certificate's, once per value and hypothesis.
    fn push_evidence(
        &self,
        node: std::sync::Arc<super::node::Node>,
        sign: i32,
        square: Option<(Poly, Poly)>,
        label: &str,
        factor: super::val::Val,
    ) {
        let mut st = self.ring.state();
        let known = (st.signs.evidence.iter())
            .any(|e| std::sync::Arc::ptr_eq(&e.node, &node) && e.label == label);
        if !known {
            st.signs.evidence.push(super::sign_state::SignEvidence {
                node,
                sign,
                square,
                label: label.to_string(),
                factor,
            });
        }
    }

    /// Records, for a certificate, the evidence that the stated hypothesis `label`
    /// decides this value's sign `sign`: the value (or `base`, whose square the value
    /// is) is the hypothesis' value times a factor of proved sign.  False where it cannot
    /// (a value without a derivation, a hypothesis of a part of the domain, a factor of
    /// no proved sign): the proof then has no certificate.
    pub(crate) fn record_hypothesis_sign(
        &self,
        sign: i32,
        label: &str,
        base: Option<&Sym>,
    ) -> bool {
        let Some(node) = self.node.clone() else {
            return false;
        };
        let base_or_self = base.unwrap_or(self);
        let (factor, label) = match base_or_self.hypothesis_factor(label) {
            Some(f) => (f, label.to_string()),
            None => match base_or_self.part_factor(label) {
                Some(found) => found,
                None => return false,
            },
        };
        let square = base.map(|b| (b.val.num.clone(), b.val.den.clone()));
        self.push_evidence(node, sign, square, &label, factor);
        true
    }

    /// `self / p` for the value `p` of the condition of the part of the domain the
    /// proof is on whose label is `label` (the `K`-th `part` line of a certificate,
    /// labelled `part:K`), where that factor is a nonzero rational number or has a sign
    /// proved with the parametrization of the domain (which a recheck proves again).
    fn part_factor(&self, label: &str) -> Option<(super::val::Val, String)> {
        let parts = self.ring.options().hypotheses.clone();
        let k = parts.iter().position(|(h, s)| {
            format!("{} {} 0", h.what, if *s > 0 { ">" } else { "<" }) == label
        })?;
        let p = parts[k].0.in_ring(&self.ring)?;
        if p.is_exact_zero() {
            return None;
        }
        let q = self.try_div(&p).ok()?;
        let signed = match q.as_rational() {
            Some(r) => r != 0,
            None => q.sign_of_recorded_factor().is_some(),
        };
        signed.then(|| ((*q.val).clone(), format!("part:{}", k + 1)))
    }

    /// `self / h` for the value `h` of the stated hypothesis `label`, where that factor
    /// is a nonzero rational number or has a sign proved with the parametrization of the
    /// domain (which a recheck proves again).
    fn hypothesis_factor(&self, label: &str) -> Option<super::val::Val> {
        let stated = self.ring.state().signs.stated.clone();
        let (val, _, _) = stated.into_iter().find(|(_, _, l)| l == label)?;
        let h = Sym::from_val(&self.ring, val, None);
        if h.is_exact_zero() {
            return None;
        }
        let q = self.try_div(&h).ok()?;
        let signed = match q.as_rational() {
            Some(r) => r != 0,
            None => q.sign_of_recorded_factor().is_some(),
        };
        signed.then(|| (*q.val).clone())
    }

    /// The proved sign of `self / h`, or of `self · h` or `self · h³` (the same sign
    /// where `h ≠ 0`, as on a part of the domain where `h` has a strict sign): `2/p` by
    /// the hypothesis `p/2 > 0`, whose quotient `4/p²` would need the sign of `2/p`
    /// itself, and `q/p³` by `p > 0`.
    fn ratio_sign(&self, h: &Sym) -> Option<i32> {
        if h.is_exact_zero() {
            return None;
        }
        let exact = |q: &Sym| q.as_rational().map(|r| r.cmp0() as i32).filter(|&s| s != 0);
        let q = self.try_div(h).ok()?;
        if let Some(s) = exact(&q) {
            return Some(s);
        }
        if let Some(s) = q.proved_sign_of_quotient() {
            return Some(s);
        }
        // self·h, then self·h³ (a cube of h in a denominator): the sign of self·h^odd;
        // only for small values, as a product beyond the term bound fails the proof
        let size = |v: &Sym| v.val.num.len() + v.val.den.len();
        if size(self) + size(h) > MAX_PRODUCT_TERMS {
            return None;
        }
        let h2 = h.clone() * h.clone();
        let mut p = self.clone() * h.clone();
        for _ in 0..2 {
            if crate::numbers::Real::failure(&p).is_some() {
                return None;
            }
            if let Some(s) = exact(&p).or_else(|| p.proved_sign_of_quotient()) {
                return Some(s);
            }
            p = p * h2.clone();
        }
        None
    }

    /// The context variable of the one indeterminate of which this value is a constant
    /// multiple, and the sign of that constant.
    pub(crate) fn single_indeterminate(&self) -> Option<(usize, i32)> {
        let (num, den) = (&self.val.num, &self.val.den);
        let den = den.as_constant()?;
        if num.len() != 1 {
            return None;
        }
        let mut out = None;
        num.for_each_term(|c, e| {
            let ones: Vec<usize> = (0..e.len()).filter(|&i| e[i] != 0).collect();
            if let [i] = ones[..]
                && e[i] == 1
            {
                out = Some((i, (c.cmp0() as i32) * (den.cmp0() as i32)));
            }
        });
        let (i, s) = out?;
        let j = i.checked_sub(self.ring.inner.opts.max_roots)?;
        let st = self.ring.state();
        matches!(st.vars.get(j)?.kind, super::ring::VarKind::Indeterminate).then_some((i, s))
    }
}

impl Ring {
    /// States a hypothesis of the claim: `value` has the sign `sign` on the domain (the
    /// catalogue says so, quoting the paper; `label` names it).  A sign decided by it is
    /// recorded as an assumption of the proof.
    pub fn state_hypothesis(&self, value: &Sym, sign: i32, label: String) {
        let val = (*value.val).clone();
        let mut st = self.state();
        st.signs.stated.push((val, sign, label));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::RingOptions;

    /// Constants in a tower of square roots have their signs decided exactly (rule 2
    /// recurses to rational numbers), with no parametrization and at no point.
    #[test]
    fn signs_of_constant_algebraic_numbers_are_exact() {
        let ring = Ring::new(RingOptions {
            points: 1,
            ..Default::default()
        });
        let root = |n: i64| ring.integer(n).sqrt().unwrap();
        // √2 + √3 − √10 ≈ −0.0161
        let x = root(2) + root(3) - root(10);
        assert_eq!(x.decision(), Decision::Proved(-1));
        // √11 − √(10 + √(2/5)) ≈ 0.0559, and its negative
        let y = root(11)
            - (ring.integer(10) + (ring.integer(2) / ring.integer(5)).sqrt().unwrap())
                .sqrt()
                .unwrap();
        assert_eq!(y.decision(), Decision::Proved(1));
        assert_eq!(y.negate().decision(), Decision::Proved(-1));
        // √2 + √3 − √(5 + 2√6) is exactly 0
        let z = root(2) + root(3)
            - (ring.integer(5) + ring.integer(2) * root(6))
                .sqrt()
                .unwrap();
        assert_eq!(z.decision(), Decision::Proved(0));
    }
}
