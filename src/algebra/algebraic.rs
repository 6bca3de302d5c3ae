//! Field variables that are algebraic over the others: a symbol `s` with a defining
//! polynomial `P(s) = 0` whose coefficients are free of `s` and of roots (such as
//! `sn(K/3)`, a root of its triplication polynomial, module `thirds`).
//!
//! The normal forms of the ring treat such a symbol as an indeterminate; two facts make
//! that sound:
//!
//! * **Zero test.**  A numerator `N` whose pseudo-remainder by `P` in `s` is 0 satisfies
//!   `lc(P)^m · N = Q · P`, so `N` vanishes at the symbol's value (`lc(P) ≠ 0` there).
//!   A non-zero remainder proves nothing.
//! * **Division.**  Before dividing by a value whose root-free norm involves `s`, its
//!   pseudo-remainder by `P` must be non-zero.  `P` is checked to be irreducible over
//!   ℚ(the other variables) when it is adjoined (FLINT factorisation and Gauss's lemma),
//!   so a polynomial of degree < deg P in `s` that is not 0 does not vanish at the
//!   symbol's value, with the other field variables algebraically independent of it
//!   (indeterminates and transcendental symbols); a remainder 0 is a division by zero.

use super::error::{AlgResult, AlgebraError};
use super::flint::Poly;
use super::ring::Inner;
use std::sync::Arc;

/// The pseudo-remainder of `p` by `rel` in the variable `var`: `lc(rel)^m · p` reduced
/// to degree < deg(rel) in `var` by multiples of `rel`.
pub(crate) fn pseudo_remainder(p: &Poly, rel: &Poly, var: usize) -> Poly {
    let n = rel.degree(var);
    let lc = rel.coefficient_in(var, n as u64);
    let x = Poly::var(p.ctx(), var);
    let mut r = p.clone();
    loop {
        let e = r.degree(var);
        if r.is_zero() || e < n {
            return r;
        }
        let c = r.coefficient_in(var, e as u64);
        let mut shift = c;
        for _ in 0..(e - n) {
            shift = shift.mul(&x);
        }
        r = r.mul(&lc).sub(&shift.mul(rel));
    }
}

impl Inner {
    /// The algebraic relations `(FLINT variable, P)` adjoined so far.
    pub(crate) fn algebraic_relations(&self) -> Vec<(usize, Arc<Poly>)> {
        self.state().algebraic.clone()
    }

    /// `p` reduced by the pseudo-remainder of every algebraic relation whose variable
    /// it uses (0 only if `p` vanishes at the symbols' values).
    pub(crate) fn algebraic_rem(&self, p: &Poly) -> AlgResult<Poly> {
        let mut r = p.clone();
        for (var, rel) in self.algebraic_relations() {
            if r.degree(var) >= rel.degree(var) {
                r = pseudo_remainder(&r, &rel, var);
                self.opts.budget.check()?;
            }
        }
        Ok(r)
    }

    /// An error if the root-free polynomial `p`, a divisor, vanishes at the values of
    /// the algebraic symbols it uses (see the module doc).
    pub(crate) fn check_algebraic_divisor(&self, p: &Poly) -> AlgResult<()> {
        let rels = self.algebraic_relations();
        if rels.is_empty() {
            return Ok(());
        }
        let used = p.used_vars();
        if !rels.iter().any(|(v, _)| used.contains(v)) {
            return Ok(());
        }
        if self.algebraic_rem(p)?.is_zero() {
            return Err(AlgebraError::DivisionByZero);
        }
        Ok(())
    }
}
