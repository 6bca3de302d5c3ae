//! Square roots: one root symbol per irreducible factor, shared by the whole ring.
//!
//! A radicand `x = N/D` of the field ℚ(x) is factored (FLINT) as
//! `±Π pᵢ^eᵢ · Π fⱼ^eⱼ` (primes, irreducible polynomials); its class modulo squares is
//! the vector over GF(2) of odd exponents (with a coordinate for −1).  Each root symbol
//! adjoined so far has such a vector, and the vectors are kept linearly independent
//! (Gaussian elimination over GF(2)), so ℚ(x)(r₁…rₘ) is a field of degree 2ᵐ and normal
//! forms are unique.  `√x` is written as `σ · q · Π_{i∈I} rᵢ` with `q ∈ ℚ(x)` and the set
//! `I` found by elimination; factors not yet covered get new roots (of `−f` rather than
//! `f` when `f < 0` at every domain point, so real claims stay real; of `−1` only when
//! the value is not real).  The sign `σ` comes from the shadows (the principal branch
//! at every point) and is recorded as an assumption.
//!
//! A radicand with roots in it is first stripped of its content (in the field) and then
//! tested for being a square in the tower by denesting `(a + b r)² = P + Q r`
//! (`a² = (P ± √(P² − a_r Q²))/2`); otherwise it gets a root of its own.

use super::decide::Decision;
use super::den_factors::Factors;
use super::error::{AlgResult, AlgebraError};
use super::flint::{Poly, factor_integer};
use super::node::Node;
use super::ring::Ring;
use super::shadow::Shadow;
use super::square_classes::{Bits, Factor};
use super::sym::Sym;
use super::val::Val;
use rug::Complex;
use std::sync::Arc;

/// Values a new root must take at the domain points (instead of the principal branch),
/// with its name and description.
pub(crate) struct Prescribed<'a> {
    pub values: &'a [Complex],
    pub name: &'a str,
    pub note: &'a str,
}

/// The class of a polynomial modulo squares: its GF(2) vector (over the ring's basis).
struct Class {
    t: Bits,
}

impl Ring {
    /// Divides out the irreducible factors met so far (cheap), then factors the rest
    /// with FLINT: `(rest, [(factor index, exponent)])`.
    fn known_factors(&self, p: &Poly) -> AlgResult<(Poly, Vec<(usize, u64)>)> {
        let known: Vec<(usize, Poly)> = {
            let st = self.state();
            st.basis
                .factors
                .iter()
                .enumerate()
                .filter_map(|(i, f)| match f {
                    Factor::Poly(q) => Some((i, q.clone())),
                    _ => None,
                })
                .collect()
        };
        let mut rest = p.clone();
        let mut found = Vec::new();
        for (i, f) in known {
            let used = rest.used_vars();
            if !f.used_vars().iter().all(|v| used.contains(v)) {
                continue;
            }
            let mut e = 0;
            while let Some(q) = rest.divides(&f)? {
                rest = q;
                e += 1;
            }
            if e > 0 {
                found.push((i, e));
            }
        }
        Ok((rest, found))
    }

    fn class_of(&self, p: &Poly) -> AlgResult<Class> {
        let (rest, known) = self.known_factors(p)?;
        let fac = match rest.as_constant() {
            Some(c) => super::flint::Factored {
                constant: c,
                factors: Vec::new(),
            },
            None => {
                // the ring's factorisation: remembered, or with the factors it has met
                // divided out first
                let f = self.inner.dens.of(&rest)?;
                super::flint::Factored {
                    constant: f.unit.clone(),
                    factors: f.list.clone(),
                }
            }
        };
        let (sign, primes) = factor_integer(&fac.constant)?;
        let mut st = self.state();
        let mut t = Bits::default();
        for (i, e) in known {
            if e % 2 == 1 {
                t.flip(i);
            }
        }
        if sign < 0 {
            let i = st.basis.index_of(Factor::MinusOne);
            t.flip(i);
        }
        for (q, e) in primes {
            if e % 2 == 1 {
                let i = st.basis.index_of(Factor::Prime(q));
                t.flip(i);
            }
        }
        for (f, e) in fac.factors {
            if e % 2 == 1 {
                let i = st.basis.index_of(Factor::Poly(f));
                t.flip(i);
            }
        }
        Ok(Class { t })
    }

    fn factor_poly(&self, i: usize) -> (Factor, Poly) {
        let st = self.state();
        let f = st.basis.factors[i].clone();
        let ctx = &self.inner.ctx;
        let p = match &f {
            Factor::MinusOne => Poly::from_i64(ctx, -1),
            Factor::Prime(q) => Poly::from_integer(ctx, q),
            Factor::Poly(p) => p.clone(),
        };
        (f, p)
    }

    /// Adjoins roots for factors of the class `t` (irreducible polynomials first, then
    /// primes, then −1), each independent of the roots so far, until `t` is in their
    /// span (see the module doc).
    fn adjoin_factors(&self, t: &Bits) -> AlgResult<()> {
        let mut order = t.ones();
        {
            let st = self.state();
            order.sort_by_key(|&i| match st.basis.factors[i] {
                Factor::Poly(_) => 0,
                Factor::Prime(_) => 1,
                Factor::MinusOne => 2,
            });
        }
        for pick in order {
            if self.state().basis.reduce(t).0.is_zero() {
                break;
            }
            let (factor, p) = self.factor_poly(pick);
            let mut v = Bits::default();
            v.flip(pick);
            if !matches!(factor, Factor::MinusOne) && self.covered_up_to_sign(&v) {
                continue;
            }
            let (radicand, v) = if matches!(factor, Factor::Poly(_)) {
                self.prefer_positive(p, v)
            } else {
                (p, v)
            };
            if self.state().basis.reduce(&v).0.is_zero() {
                continue;
            }
            self.new_field_root(radicand, v, None, matches!(factor, Factor::MinusOne))?;
        }
        Ok(())
    }

    /// The vector (and radicand) of a single new root that, with the roots so far,
    /// covers the class `t`: its factors not covered up to sign if that works, else
    /// the residual of `t`, else `t` itself.
    fn special_vector(&self, t: &Bits) -> AlgResult<(Poly, Bits)> {
        let mut uncovered = Bits::default();
        for i in t.ones() {
            let mut e = Bits::default();
            e.flip(i);
            let minus = matches!(self.state().basis.factors[i], Factor::MinusOne);
            if !minus && !self.covered_up_to_sign(&e) {
                uncovered.flip(i);
            }
        }
        let residual = self.state().basis.reduce(t).0;
        for cand in [uncovered, residual, t.clone()] {
            if cand.is_zero() {
                continue;
            }
            let mut rad = Poly::from_i64(&self.inner.ctx, 1);
            for i in cand.ones() {
                rad = rad.mul(&self.factor_poly(i).1);
            }
            let (rad, v) = self.prefer_positive(rad, cand);
            let (mut trial, next) = {
                let st = self.state();
                (st.basis.clone(), st.roots.len())
            };
            if trial.add(&v, next) && trial.reduce(t).0.is_zero() {
                return Ok((rad, v));
            }
        }
        Err(AlgebraError::Internal(
            "no single root covers the class".into(),
        ))
    }

    /// Is `v` or `v + [−1]` in the span of the roots (the factor is covered up to a
    /// sign, which −1 settles)?
    fn covered_up_to_sign(&self, v: &Bits) -> bool {
        let mut st = self.state();
        if st.basis.reduce(v).0.is_zero() {
            return true;
        }
        let m1 = st.basis.index_of(Factor::MinusOne);
        let mut w = v.clone();
        w.flip(m1);
        st.basis.reduce(&w).0.is_zero()
    }

    /// `(−p, v + [−1])` instead of `(p, v)` when `p < 0` at every domain point and the
    /// flipped vector is still independent of the roots (so the new root is real).
    fn prefer_positive(&self, p: Poly, v: Bits) -> (Poly, Bits) {
        let vals = self.inner.var_values();
        let sv = Shadow::leaf(self.inner.eval_poly(&p, &vals));
        let prec = self.precision();
        let negative = (0..self.points()).all(|i| sv.real_sign(i, prec) == Some(-1));
        if negative {
            let mut flipped = v.clone();
            let m1 = self.state().basis.index_of(Factor::MinusOne);
            flipped.flip(m1);
            if !self.state().basis.reduce(&flipped).0.is_zero() {
                return (p.neg(), flipped);
            }
        }
        (p, v)
    }

    /// Adjoins a root of a radicand in the field with GF(2) vector `v` and optional
    /// prescribed values (default: the principal square root at every point).
    fn new_field_root(
        &self,
        radicand: Poly,
        v: Bits,
        values: Option<Vec<Complex>>,
        is_i: bool,
    ) -> AlgResult<usize> {
        let names = self.inner.names();
        let note = format!("sqrt({})", radicand.render(&names));
        let values = match values {
            Some(v) => v,
            None => {
                let vals = self.inner.var_values();
                Shadow::leaf(self.inner.eval_poly(&radicand, &vals))
                    .sqrt()
                    .v
            }
        };
        let n = self.state().roots.len();
        let name = if is_i {
            "i_".to_string()
        } else {
            format!("r_{}", n + 1)
        };
        let i = self.inner.add_root(name, radicand, values, note)?;
        let mut st = self.state();
        if !st.basis.add(&v, i) {
            return Err(AlgebraError::Internal("dependent root vector".into()));
        }
        if is_i {
            st.i_root = Some(i);
        }
        Ok(i)
    }

    /// `√(nd)` for a polynomial `nd` of the field as `q · Π rᵢ` (up to sign), adjoining
    /// roots for uncovered factors when `adjoin` is set (else `None` if not a square in
    /// the tower).  With `prescribed`, uncovered factors get a single root whose values
    /// are fixed later.
    fn field_sqrt_poly(
        &self,
        nd: &Poly,
        adjoin: bool,
        special: Option<(&str, &str)>,
    ) -> AlgResult<Option<(Val, Option<usize>)>> {
        if nd.leading_coefficient() > 0
            && let Some(root) = nd.sqrt()
        {
            // a perfect square (of a polynomial) needs no factoring and no new root
            let one = Poly::from_i64(&self.inner.ctx, 1);
            let sh = self.shadow_of(&root, &one);
            let v = Val {
                num: root,
                den: one,
                sh,
            };
            return Ok(Some((v, None)));
        }
        let class = self.class_of(nd)?;
        let mut fresh = None;
        if !self.state().basis.reduce(&class.t).0.is_zero() {
            if !adjoin {
                return Ok(None);
            }
            match special {
                Some((name, note)) => {
                    // one root whose values can be set, for the uncovered factors
                    let (rad, v) = self.special_vector(&class.t)?;
                    let i = self.new_field_root(rad, v, None, false)?;
                    let mut st = self.state();
                    st.roots[i].note = note.to_string();
                    st.roots[i].name = name.to_string();
                    fresh = Some(i);
                }
                None => self.adjoin_factors(&class.t)?,
            }
        }
        let (res, combo) = self.state().basis.reduce(&class.t);
        if !res.is_zero() {
            return Err(AlgebraError::Internal(
                "a square root left its class uncovered".into(),
            ));
        }
        self.assemble(nd, &combo).map(|v| Some((v, fresh)))
    }

    /// `q · Π_{combo} rᵢ` with `q = √(nd / Π aᵢ)` exact in the field.
    fn assemble(&self, nd: &Poly, combo: &Bits) -> AlgResult<Val> {
        let ctx = self.inner.ctx.clone();
        let mut r = Poly::from_i64(&ctx, 1);
        let mut fr = Factors::integer(rug::Integer::from(1));
        let roots: Vec<usize> = combo.ones();
        for &i in &roots {
            let a = self.state().roots[i].radicand.clone();
            fr = fr.mul(&*self.inner.dens.of(&a)?);
            r = r.mul(&a);
        }
        self.inner.dens.record(&r, Arc::new(fr));
        let (yn, yd) = self.inner.normalise(nd.clone(), r)?;
        let (Some(sn), Some(sd)) = (yn.sqrt(), yd.sqrt()) else {
            return Err(AlgebraError::Internal(
                "square class mismatch in sqrt".into(),
            ));
        };
        if let Some(f) = self.inner.dens.of(&yd)?.half() {
            self.inner.dens.record(&sd, Arc::new(f));
        }
        let (num, den) = self.inner.normalise(sn, sd)?;
        let sh = self.shadow_of(&num, &den);
        let mut v = Val { num, den, sh };
        for &i in &roots {
            let rv = self.root_sym(i).val;
            v = self.inner.v_mul(&v, &rv)?;
        }
        Ok(v)
    }

    pub(crate) fn shadow_of(&self, num: &Poly, den: &Poly) -> Shadow {
        let vals = self.inner.var_values();
        let n = Shadow::leaf(self.inner.eval_poly(num, &vals));
        let d = Shadow::leaf(self.inner.eval_poly(den, &vals));
        n.div(&d)
    }

    /// The value `num/den` of two polynomials of the ring's context, in lowest terms,
    /// with its values at the points (no derivation: it is not a step of the proof).
    pub(crate) fn quotient_of_polys(&self, num: Poly, den: Poly) -> AlgResult<Sym> {
        let (num, den) = self.inner.normalise(num, den)?;
        let sh = self.shadow_of(&num, &den);
        Ok(Sym::from_val(self, Val { num, den, sh }, None))
    }

    /// Negates the values of root `i` at the points where `sigma` is −1 (the table of
    /// the variables' values is built afresh on its next use).
    fn flip_root_values(&self, i: usize, sigma: &[i32]) {
        let mut st = self.state();
        for (p, s) in sigma.iter().enumerate() {
            if *s < 0 {
                let z = -st.roots[i].values[p].clone();
                st.roots[i].values[p] = z;
            }
        }
        st.values_table = None;
        st.signs.sign_memo.clear();
    }

    /// The shadow of `v` evaluated afresh from its normal form at the points' values,
    /// with the error scale of its terms ([`Inner::eval_poly_scaled`]).
    pub(crate) fn reevaluated(&self, v: &Val) -> Shadow {
        let vals = self.inner.var_values();
        let n = self.inner.eval_poly_scaled(&v.num, &vals);
        let d = self.inner.eval_poly_scaled(&v.den, &vals);
        n.div(&d)
    }

    /// The sign σ with `target = σ · candidate` at every point.
    fn decide_sign(&self, target: &Shadow, cand: &Shadow, what: &str) -> AlgResult<i32> {
        let prec = self.precision();
        let mut sigma = 0;
        for i in 0..self.points() {
            let ratio = Shadow::with_scale(vec![target.v[i].clone()], vec![target.lscale[i]]).div(
                &Shadow::with_scale(vec![cand.v[i].clone()], vec![cand.lscale[i]]),
            );
            if cand.is_small(i, prec) {
                return Err(AlgebraError::CannotDecide(format!(
                    "the branch of {what}: it vanishes at a domain point"
                )));
            }
            let s = ratio.real_sign(0, prec).ok_or_else(|| {
                AlgebraError::Internal(format!(
                    "the square of the root of {what} differs from its radicand"
                ))
            })?;
            if sigma != 0 && s != sigma {
                return Err(AlgebraError::CannotDecide(format!(
                    "the branch of {what}: the sign differs between domain points"
                )));
            }
            sigma = s;
        }
        Ok(sigma)
    }
}

impl Sym {
    /// The square root (the principal branch), exact in the tower: `σ · q · Π rᵢ` with
    /// root symbols shared across the ring.  The values at the domain points suggest
    /// the sign σ; the proof must prove it (the result positive, or `i` times a positive
    /// value where the radicand is proved negative), or the branch is undecided
    /// ([`AlgebraError::CannotDecide`]).
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// use eulertop::algebra::positivity::Parametrization;
    /// use std::sync::Arc;
    /// // the domain: a, b > 0
    /// let mut par = Parametrization::new();
    /// for v in ["a", "b"] {
    ///     let t = par.positive(&format!("t_{v}")).unwrap();
    ///     par.bind(v, t, String::new());
    /// }
    /// let ring = Ring::new(RingOptions { points: 2, positivity: Some(Arc::new(par)), ..Default::default() });
    /// let a = ring.indeterminate_f64("a", &[2.0, 3.0]).unwrap();
    /// let b = ring.indeterminate_f64("b", &[0.5, 0.25]).unwrap();
    /// let r = (a.clone() * b.clone() * b.clone()).sqrt().unwrap(); // b·√a, b > 0
    /// let back = r.clone() * r;
    /// assert!(ring.prove(&back, &(a * b.clone() * b)).is_proved());
    /// ```
    pub fn sqrt(&self) -> AlgResult<Sym> {
        self.sqrt_with(None)
    }

    /// A square root whose values at the points are prescribed (e.g. `cn u` for
    /// `√(1 − sn²u)`): new roots take those values instead of the principal branch.
    pub(crate) fn sqrt_with(&self, prescribed: Option<Prescribed<'_>>) -> AlgResult<Sym> {
        let ring = &self.ring;
        if self.is_exact_zero() {
            return Ok(self.clone());
        }
        let what = format!("sqrt({})", self.render_short(160));
        let target = match &prescribed {
            Some(p) => Shadow::leaf(p.values.to_vec()),
            None => self.val.sh.sqrt(),
        };
        let inner = &ring.inner;
        let (mut cand, fresh) = match self.root_of_squares()? {
            Some(v) => (v, None),
            None => self.root_of_product(prescribed.as_ref())?,
        };
        if let (Some(i), Some(_)) = (fresh, &prescribed) {
            // fix the new root's values so that the product equals the prescribed values
            let sigma = ring.pointwise_signs(&target, &cand.sh, &what)?;
            ring.state().roots[i].principal = false;
            ring.flip_root_values(i, &sigma);
            cand.sh = cand.sh.scale_by(
                &sigma
                    .iter()
                    .map(|&s| Complex::with_val(ring.precision(), s))
                    .collect::<Vec<_>>(),
            );
            let node = self.node.as_ref().map(|n| Node::sqrt(n, &cand, 1));
            return Ok(Sym::from_val(ring, cand, node));
        }
        // the values at the points suggest the branch; the proof must then prove it
        let guess = match ring.decide_sign(&target, &cand.sh, &what) {
            Ok(s) => Ok(s),
            Err(_) if prescribed.is_none() => {
                let target = ring.reevaluated(&self.val).sqrt();
                ring.decide_sign(&target, &ring.reevaluated(&cand), &what)
            }
            Err(e) => Err(e),
        };
        let sigma = match guess {
            Ok(s) => s,
            Err(e) => {
                ring.note_undecided(&Sym::from_val(ring, cand, None));
                ring.note_undecided(self);
                return Err(e);
            }
        };
        if sigma < 0 {
            cand = inner.v_neg(&cand);
        }
        let result = Sym::from_val(ring, cand, None);
        let node = self
            .node
            .as_ref()
            .map(|n| Node::sqrt(n, &result.val, sigma));
        let result = result.with_node(node);
        if !(sigma > 0 && fresh.is_none() && result.is_single_root_of(self)) {
            result.principal_branch_proved(self, &what)?;
        }
        Ok(result)
    }

    /// Proves that `self`, a square root of `radicand`, is its principal root on the
    /// whole domain: positive, or `i` times a positive value where the radicand is
    /// proved negative.  Otherwise the branch is undecided (an error; the ring
    /// remembers the value, so that the domain may be split by its sign).
    fn principal_branch_proved(&self, radicand: &Sym, what: &str) -> AlgResult<()> {
        let ring = &self.ring;
        match self.decision() {
            Decision::Proved(1) | Decision::Definition(1) => return Ok(()),
            Decision::Hypothesis(1, label) => {
                if ring.certifying() && !self.record_hypothesis_sign(1, &label, None) {
                    ring.mark_uncertified(
                        "a square-root branch decided by a stated hypothesis, which a certificate records only as a premise",
                    );
                }
                return Ok(());
            }
            _ => {}
        }
        if let Some(c) = self.positive_multiple_of_principal_root() {
            // √(c²a) = c·√a for c > 0, whatever the sign of a: a recheck finds its own
            // evidence of the branch (c of a sign it proves, √a a positive or free root),
            // which a sign of c by a hypothesis or a part's condition is not
            if matches!(c, Decision::Hypothesis(..)) {
                ring.mark_uncertified(
                    "a square root c·√a with √a principal and c > 0 by a hypothesis or a part's condition",
                );
            }
            return Ok(());
        }
        if radicand.decided_sign() == Some(-1) {
            let over_i = self.try_mul(&ring.i()?)?.negate();
            if over_i.decided_sign() == Some(1) {
                return Ok(());
            }
        }
        ring.note_undecided(self);
        ring.note_undecided(radicand);
        Err(AlgebraError::CannotDecide(format!(
            "the branch of {what} is not proved on the domain: {} > 0 is neither proved nor a hypothesis",
            self.render_short(160)
        )))
    }

    /// `√(N/D) = √N/√D`, up to sign, when `N` and `D` are squares of polynomials with
    /// positive leading coefficients (and no roots): the same value as
    /// [`Sym::root_of_product`]'s, as `N/D` is in lowest terms, without forming `N·D`.
    fn root_of_squares(&self) -> AlgResult<Option<Val>> {
        let (n, d) = (&self.val.num, &self.val.den);
        if self.has_roots() || n.leading_coefficient() <= 0 || d.leading_coefficient() <= 0 {
            return Ok(None);
        }
        let Some(sn) = n.sqrt() else {
            return Ok(None);
        };
        let Some(sd) = d.sqrt() else {
            return Ok(None);
        };
        let ring = &self.ring;
        let inner = &ring.inner;
        if !d.is_one()
            && let Some(f) = inner.dens.of(d)?.half()
        {
            inner.dens.record(&sd, Arc::new(f));
        }
        let (num, den) = inner.normalise(sn, sd)?;
        let sh = ring.shadow_of(&num, &den);
        Ok(Some(Val { num, den, sh }))
    }

    /// `√(N/D) = √(N·D)/D`, up to sign: the square root of the polynomial `N·D` in the
    /// field (new roots adjoined as needed; the index of a root made for prescribed
    /// values is returned) or in the tower of roots, divided by `D`.
    fn root_of_product(
        &self,
        prescribed: Option<&Prescribed<'_>>,
    ) -> AlgResult<(Val, Option<usize>)> {
        let ring = &self.ring;
        let inner = &ring.inner;
        let nd = inner.reduce(self.val.num.mul(&self.val.den));
        let (cand, fresh) = if self.has_roots() {
            (self.tower_sqrt(&nd)?, None)
        } else {
            let special = prescribed.map(|p| (p.name, p.note));
            ring.field_sqrt_poly(&nd, true, special)?
                .ok_or_else(|| AlgebraError::Internal("sqrt adjoined no root".into()))?
        };
        let one = Poly::from_i64(&inner.ctx, 1);
        let dval = Val {
            num: self.val.den.clone(),
            den: one.clone(),
            sh: ring.shadow_of(&self.val.den, &one),
        };
        Ok((inner.v_div(&cand, &dval)?, fresh))
    }

    /// Where this value is `c·r` for a root `r` that is the principal root of its
    /// radicand by definition (adjoined with its principal values) and a factor `c`
    /// free of `r` with a decided positive sign, the decision of that sign: then, as the
    /// value's square is `c²·r²`, the value is the principal root of its square,
    /// whatever the sign of `r²`.
    fn positive_multiple_of_principal_root(&self) -> Option<Decision> {
        let ring = &self.ring;
        self.val.num.used_vars().into_iter().find_map(|v| {
            let i = ring.inner.root_of_var(v)?;
            if !ring.state().roots[i].principal {
                return None;
            }
            let c = self.try_div(&ring.root_sym(i)).ok()?;
            let free = |p: &Poly| !p.used_vars().contains(&v);
            if !(free(&c.val.num) && free(&c.val.den)) {
                return None;
            }
            let d = c.decision();
            (d.sign() == Some(1)).then_some(d)
        })
    }

    /// Is this value a single root symbol whose radicand is exactly `x` (the
    /// definitional case, which needs no assumption)?
    fn is_single_root_of(&self, x: &Sym) -> bool {
        let used = self.val.num.used_vars();
        if used.len() != 1 || !self.val.den.is_one() || self.val.num.len() != 1 {
            return false;
        }
        let Some(i) = self.ring.inner.root_of_var(used[0]) else {
            return false;
        };
        let st = self.ring.state();
        x.val.den.is_one()
            && st.roots[i].radicand == x.val.num
            && self.val.num.leading_coefficient() == 1
    }

    /// √ of a polynomial with roots (see the module doc), up to sign.
    fn tower_sqrt(&self, nd: &Poly) -> AlgResult<Val> {
        let ring = &self.ring;
        let inner = &ring.inner;
        let root_vars: Vec<usize> = (0..ring.state().roots.len())
            .map(|i| inner.root_var(i))
            .collect();
        let g = nd.content_in(&root_vars)?;
        let g = if nd.leading_coefficient() < 0 {
            g.neg()
        } else {
            g
        };
        let rest = nd
            .divides(&g)?
            .ok_or_else(|| AlgebraError::Internal("content does not divide".into()))?;
        let (gv, _) = ring
            .field_sqrt_poly(&g, true, None)?
            .ok_or_else(|| AlgebraError::Internal("sqrt adjoined no root".into()))?;
        let rv = match ring.exact_tower_sqrt(&rest, 0)? {
            Some(v) => v,
            None => ring.tower_root(&rest)?,
        };
        inner.v_mul(&gv, &rv)
    }
}

impl Ring {
    /// The imaginary unit, a root symbol with `i² = −1` (shared by the whole ring).
    pub fn i(&self) -> AlgResult<Sym> {
        let m1 = self.integer(-1);
        m1.sqrt()
    }

    /// Signs σₚ with `target = σₚ · cand` at each point.
    fn pointwise_signs(&self, target: &Shadow, cand: &Shadow, what: &str) -> AlgResult<Vec<i32>> {
        let prec = self.precision();
        (0..self.points())
            .map(|i| {
                let t = Shadow::with_scale(vec![target.v[i].clone()], vec![target.lscale[i]]);
                let c = Shadow::with_scale(vec![cand.v[i].clone()], vec![cand.lscale[i]]);
                t.div(&c).real_sign(0, prec).ok_or_else(|| {
                    AlgebraError::Internal(format!(
                        "prescribed values do not square to the radicand of {what}"
                    ))
                })
            })
            .collect()
    }

    /// A root of a radicand with roots (existing one reused, else adjoined).
    fn tower_root(&self, rad: &Poly) -> AlgResult<Val> {
        let existing = self.state().roots.iter().position(|r| r.radicand == *rad);
        let i = match existing {
            Some(i) => i,
            None => {
                let vals = self.inner.var_values();
                let values = Shadow::leaf(self.inner.eval_poly(rad, &vals)).sqrt().v;
                let names = self.inner.names();
                let note = format!("sqrt({})", rad.render(&names));
                let n = self.state().roots.len();
                let i = self
                    .inner
                    .add_root(format!("r_{}", n + 1), rad.clone(), values, note)?;
                self.state().tower_roots = true;
                i
            }
        };
        Ok(self.root_sym(i).into_val())
    }

    /// `√p` in the tower if `p` is a square there (no new roots), up to sign.
    fn exact_tower_sqrt(&self, p: &Poly, depth: usize) -> AlgResult<Option<Val>> {
        let inner = &self.inner;
        if p.is_zero() {
            return Ok(Some(Val {
                num: p.clone(),
                den: Poly::from_i64(&inner.ctx, 1),
                sh: self.shadow_of(p, &Poly::from_i64(&inner.ctx, 1)),
            }));
        }
        let top = p
            .used_vars()
            .into_iter()
            .find(|&i| inner.root_of_var(i).is_some());
        let Some(idx) = top else {
            return Ok(self.field_sqrt_poly(p, false, None)?.map(|(v, _)| v));
        };
        if depth > 2 * self.options().max_roots {
            return Ok(None);
        }
        let root = inner
            .root_of_var(idx)
            .ok_or_else(|| AlgebraError::Internal("root index".into()))?;
        let f = self.state().roots[root].radicand.clone();
        let one = Poly::from_i64(&inner.ctx, 1);
        let pp = p.coefficient_in(idx, 0);
        let qq = p.coefficient_in(idx, 1);
        inner.opts.budget.check()?;
        let norm = inner.reduce(pp.mul(&pp).sub(&f.mul(&qq).mul(&qq)));
        // the norms of nested roots grow geometrically: bounded like every value
        if norm.len() > inner.opts.max_terms {
            return Err(AlgebraError::TooLarge(norm.len(), inner.opts.max_terms));
        }
        let Some(m) = self.exact_tower_sqrt(&norm, depth + 1)? else {
            return Ok(None);
        };
        let pv = Val {
            num: pp.clone(),
            den: one.clone(),
            sh: self.shadow_of(&pp, &one),
        };
        let qv = Val {
            num: qq.clone(),
            den: one.clone(),
            sh: self.shadow_of(&qq, &one),
        };
        let two = inner.const_val(&rug::Rational::from(2));
        let rv = self.root_sym(root).val;
        for sign in [1, -1] {
            let ms = if sign > 0 { m.clone() } else { inner.v_neg(&m) };
            let a2 = inner.v_div(&inner.v_add(&pv, &ms, false)?, &two)?;
            if a2.num.is_zero() {
                continue;
            }
            let a2nd = inner.reduce(a2.num.mul(&a2.den));
            let Some(a) = self.exact_tower_sqrt(&a2nd, depth + 1)? else {
                continue;
            };
            let dv = Val {
                num: a2.den.clone(),
                den: one.clone(),
                sh: self.shadow_of(&a2.den, &one),
            };
            let a = inner.v_div(&a, &dv)?;
            let b = inner.v_div(&qv, &inner.v_mul(&two, &a)?)?;
            let cand = inner.v_add(&a, &inner.v_mul(&b, &rv)?, false)?;
            let sq = inner.v_mul(&cand, &cand)?;
            if sq.den.is_one() && sq.num == *p {
                return Ok(Some(cand));
            }
        }
        Ok(None)
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Ring, RingOptions};

    /// `√(N/D)` of squares `N`, `D` is `√N/√D`, the value of the route through `N·D`,
    /// and adjoins no root.
    #[test]
    fn the_root_of_a_quotient_of_squares_is_the_root_of_the_product() {
        // x, y > 0, so that x + y > 0 is proved
        let mut par = super::super::positivity::Parametrization::new();
        for v in ["x", "y"] {
            let t = par.positive(&format!("t_{v}")).unwrap();
            par.bind(v, t, String::new());
        }
        let ring = Ring::new(RingOptions {
            points: 3,
            positivity: Some(std::sync::Arc::new(par)),
            ..Default::default()
        });
        let x = ring.indeterminate_f64("x", &[1.5, 2.0, 3.5]).unwrap();
        let y = ring.indeterminate_f64("y", &[0.5, 1.25, 0.75]).unwrap();
        let n = &(&x + &y) * &(&x + &y);
        let d = &(&(&x * &x) + &ring.integer(3)) * &(&(&x * &x) + &ring.integer(3));
        let q = &n / &d;
        let fast = q.root_of_squares().unwrap().expect("squares");
        let (slow, fresh) = q.root_of_product(None).unwrap();
        assert_eq!((&fast.num, &fast.den), (&slow.num, &slow.den));
        assert!(fresh.is_none());
        let r = q.sqrt().unwrap();
        assert_eq!(r, &(&x + &y) / &(&(&x * &x) + &ring.integer(3)));
        assert!(ring.state().roots.is_empty());
        // not a square: the route through N·D
        assert!((&x / &d).root_of_squares().unwrap().is_none());
    }
}
