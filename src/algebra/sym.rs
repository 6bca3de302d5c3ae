//! [`Sym`]: an exact element of the tower with its numeric shadow.
//!
//! **Normal form.**  A value is `N/D` where `N` is a polynomial over ℤ in the field
//! variables and the root symbols, of degree < 2 in every root (reduced modulo the
//! relations `rᵢ² = aᵢ`, a Gröbner basis), and `D` is a polynomial in the field
//! variables only, with positive leading coefficient and `gcd(N, D) = 1`.  Division by
//! a value with roots multiplies by conjugates until the denominator is root-free.
//! Over the field ℚ(x) and roots of pairwise independent radicands the form is unique,
//! so a value is zero exactly when `N = 0`.

use super::den_factors::{self, Factors};
use super::error::{AlgResult, AlgebraError};
use super::flint::Poly;
use super::node::{Node, Op};
use super::ring::{Inner, Ring, Stored};
use super::shadow::Shadow;
use super::val::Val;
use rug::{Complex, Rational};
use std::sync::Arc;

/// An exact element of a [`Ring`]'s tower, with its numeric values at the domain points.
///
/// Arithmetic goes through the standard operators (also on references); operations
/// that can fail (`sqrt`, `sn`, derivatives, division by a zero divisor) have inherent
/// methods returning [`AlgResult`]; inside operators a failure is recorded in the
/// ring ([`Ring::error`]) and yields a meaningless value.
#[derive(Clone)]
pub struct Sym {
    pub(crate) ring: Ring,
    pub(crate) val: Arc<Val>,
    pub(crate) node: Option<Arc<Node>>,
}

impl std::fmt::Debug for Sym {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.render())
    }
}

impl Inner {
    /// Reduces a polynomial modulo the root relations (only if some root has degree ≥ 2).
    pub(crate) fn reduce(&self, p: Poly) -> Poly {
        self.reduce_changed(p).0
    }

    /// [`Self::reduce`], and whether the relations changed the polynomial: exactly when
    /// some root has degree ≥ 2 in it, since the result has none.
    pub(crate) fn reduce_changed(&self, p: Poly) -> (Poly, bool) {
        let degs = p.degrees();
        let needs = (0..self.opts.max_roots).any(|idx| degs[idx] >= 2);
        if !needs {
            return (p, false);
        }
        let rels = self.relations_for(&p);
        let refs: Vec<&Poly> = rels.iter().map(|r| r.as_ref()).collect();
        (p.rem_ideal(&refs), true)
    }

    /// Cancels the gcd and makes the denominator's leading coefficient positive.
    pub(crate) fn normalise(&self, num: Poly, den: Poly) -> AlgResult<(Poly, Poly)> {
        if den.is_zero() {
            return Err(AlgebraError::DivisionByZero);
        }
        let size = num.len() + den.len();
        if size > self.opts.max_terms {
            return Err(AlgebraError::TooLarge(size, self.opts.max_terms));
        }
        self.opts.budget.check()?;
        if num.is_zero() {
            return Ok((num, Poly::from_i64(&self.ctx, 1)));
        }
        let (n, d, fd) = if den.is_one() {
            (num, den, None)
        } else {
            let (n, d, fd) = self.cancel_den(&num, &den)?;
            (n, d, Some(fd))
        };
        Ok(self.positive_den(n, d, fd.as_deref()))
    }

    /// `(n, d)` or `(−n, −d)`, whichever has the denominator's leading coefficient
    /// positive; the factors `fd` of `d`, if known, are remembered for the result's.
    fn positive_den(&self, n: Poly, d: Poly, fd: Option<&Factors>) -> (Poly, Poly) {
        let (n, d, f) = if d.leading_coefficient() >= 0 {
            (n, d, fd.cloned())
        } else {
            (n.neg(), d.neg(), fd.map(Factors::neg))
        };
        if let Some(f) = f {
            self.dens.record(&d, Arc::new(f));
        }
        (n, d)
    }

    /// `(num/g, den/g)` for `g = gcd(num, den)`, found from the factors of `den`
    /// (see [`super::den_factors`]), with the factors of `den/g`.
    fn cancel_den(&self, num: &Poly, den: &Poly) -> AlgResult<(Poly, Poly, Arc<Factors>)> {
        let fd = self.dens.of(den)?;
        if num.is_zero() {
            return Ok((num.clone(), den.clone(), fd));
        }
        let (n, fg) = den_factors::cancel(num, &fd)?;
        if fg.list.is_empty() && fg.unit == 1 {
            return Ok((n, den.clone(), fd));
        }
        let fq = fd.div(&fg)?;
        let d = fq.expand(den)?;
        Ok((n, d, Arc::new(fq)))
    }

    pub(crate) fn v_add(&self, a: &Val, b: &Val, sub: bool) -> AlgResult<Val> {
        let sh = if sub {
            a.sh.sub(&b.sh)
        } else {
            a.sh.add(&b.sh)
        };
        let combine = |l: Poly, r: Poly| if sub { l.sub(&r) } else { l.add(&r) };
        if a.den == b.den {
            let n = combine(a.num.clone(), b.num.clone());
            let (num, den) = self.normalise(n, a.den.clone())?;
            return Ok(Val { num, den, sh });
        }
        // Henrici: with g = gcd(D₁, D₂), the sum N/(D₁·D₂/g) can only cancel
        // factors of g, because N₁/D₁ and N₂/D₂ are in lowest terms.
        let (fa, fb) = (self.dens.of(&a.den)?, self.dens.of(&b.den)?);
        let fg = fa.gcd(&fb);
        // a.den/g and b.den/g, expanded from the factors (as they are where g is 1)
        let (qa, qb) = (fa.div(&fg)?, fb.div(&fg)?);
        let (ad, bd) = if fg.is_one() {
            (a.den.clone(), b.den.clone())
        } else {
            (qa.expand(&a.den)?, qb.expand(&b.den)?)
        };
        let n = combine(a.num.mul(&bd), b.num.mul(&ad));
        let d = a.den.mul(&bd);
        let fd = fa.mul(&qb);
        let (n, d, fd) = if fg.is_one() || n.is_zero() {
            (n, d, fd)
        } else {
            let (n, fc) = den_factors::cancel(&n, &fg)?;
            let fd = fd.div(&fc)?;
            let d = if fc.is_one() { d } else { fd.expand(&d)? };
            (n, d, fd)
        };
        let (num, den) = self.lowest_terms_factored(n, d, Some(&fd))?;
        Ok(Val { num, den, sh })
    }

    /// `num/den` already in lowest terms: checks the size bound and makes the
    /// denominator's leading coefficient positive, without a gcd.
    pub(crate) fn lowest_terms(&self, num: Poly, den: Poly) -> AlgResult<(Poly, Poly)> {
        self.lowest_terms_factored(num, den, None)
    }

    /// [`Self::lowest_terms`], remembering the factors `fd` of `den` (if given) for the
    /// result's denominator.
    fn lowest_terms_factored(
        &self,
        num: Poly,
        den: Poly,
        fd: Option<&Factors>,
    ) -> AlgResult<(Poly, Poly)> {
        let size = num.len() + den.len();
        if size > self.opts.max_terms {
            return Err(AlgebraError::TooLarge(size, self.opts.max_terms));
        }
        self.opts.budget.check()?;
        if num.is_zero() {
            return Ok((num, Poly::from_i64(&self.ctx, 1)));
        }
        Ok(self.positive_den(num, den, fd))
    }

    /// `(a/g, b/g)` for `g = gcd(a, b)`, where `b` is a denominator, with the factors
    /// of `b/g`; none where `b` is 1 or `a` is 0 (a product with `a` is then 0).
    fn cancel(&self, a: &Poly, b: &Poly) -> AlgResult<(Poly, Poly, Option<Arc<Factors>>)> {
        if b.is_one() || a.is_zero() {
            return Ok((a.clone(), b.clone(), None));
        }
        let (n, d, fd) = self.cancel_den(a, b)?;
        Ok((n, d, Some(fd)))
    }

    pub(crate) fn v_mul(&self, a: &Val, b: &Val) -> AlgResult<Val> {
        let sh = a.sh.mul(&b.sh);
        // cancel crosswise before multiplying
        let (an, bd, fbd) = self.cancel(&a.num, &b.den)?;
        let (bn, ad, fad) = self.cancel(&b.num, &a.den)?;
        let (reduced, changed) = self.reduce_changed(an.mul(&bn));
        let den = ad.mul(&bd);
        // Crosswise cancellation leaves the product in lowest terms unless the
        // root relations changed the numerator.
        let (num, den) = if den.is_one() && !changed {
            (reduced, den)
        } else if reduced.is_zero() {
            self.lowest_terms(reduced, den)?
        } else {
            // a non-zero product: both numerators are non-zero, so a missing
            // factorisation is that of 1
            let fden = match (fad, fbd) {
                (Some(x), Some(y)) => x.mul(&y),
                (Some(x), None) | (None, Some(x)) => (*x).clone(),
                (None, None) => Factors::integer(rug::Integer::from(1)),
            };
            if changed {
                self.dens.record(&den, Arc::new(fden));
                self.normalise(reduced, den)?
            } else {
                self.lowest_terms_factored(reduced, den, Some(&fden))?
            }
        };
        Ok(Val { num, den, sh })
    }

    /// `Σ ±aᵢbᵢ` with the products over the least common multiple of their
    /// denominators, reduced by the relations and brought to lowest terms once.
    pub(crate) fn v_sum_of_products(&self, terms: &[(&Val, &Val, bool)]) -> AlgResult<Val> {
        let mut sh: Option<Shadow> = None;
        // each non-zero product's numerator and the factors of its denominator
        let mut prods: Vec<(Poly, Factors)> = Vec::with_capacity(terms.len());
        for (a, b, neg) in terms {
            let p = a.sh.mul(&b.sh);
            sh = Some(match sh {
                None if *neg => p.neg(),
                None => p,
                Some(s) if *neg => s.sub(&p),
                Some(s) => s.add(&p),
            });
            if a.num.is_zero() || b.num.is_zero() {
                // a product that is 0 adds nothing, and its denominator is not needed
                continue;
            }
            let num = a.num.mul(&b.num);
            let f = self.dens.of(&a.den)?.mul(&*self.dens.of(&b.den)?);
            prods.push((if *neg { num.neg() } else { num }, f));
        }
        let sh = sh.ok_or_else(|| AlgebraError::Internal("an empty sum of products".into()))?;
        let Some((first, rest)) = prods.split_first() else {
            let zero = Poly::zero(&self.ctx);
            return Ok(Val {
                num: zero,
                den: Poly::from_i64(&self.ctx, 1),
                sh,
            });
        };
        let flcm = rest.iter().fold(first.1.clone(), |l, (_, f)| l.lcm(f));
        let lcm = flcm.expand(&first.0)?;
        // A sum (or a partial sum) more than twice the bound before cancelling is an
        // intermediate expression too large, like any other; one just beyond the
        // bound is taken one product at a time, since cancelling may bring it within.
        let far = |n: &Poly| n.len() + lcm.len() > 2 * self.opts.max_terms;
        let mut num = Poly::zero(&self.ctx);
        for (p, f) in &prods {
            // lcm / (the product's denominator), from the factors
            num = num.add(&p.mul(&flcm.div(f)?.expand(&lcm)?));
            self.opts.budget.check()?;
            if far(&num) {
                return Err(AlgebraError::TooLarge(
                    num.len() + lcm.len(),
                    self.opts.max_terms,
                ));
            }
        }
        let size = num.len() + lcm.len();
        if size > self.opts.max_terms {
            // before cancelling, the sum may exceed the bound that its lowest terms
            // meet: then the products and sums one at a time
            return self.sum_stepwise(terms);
        }
        self.dens.record(&lcm, Arc::new(flcm));
        let (num, den) = self.normalise(self.reduce(num), lcm)?;
        Ok(Val { num, den, sh })
    }

    fn sum_stepwise(&self, terms: &[(&Val, &Val, bool)]) -> AlgResult<Val> {
        let mut acc: Option<Val> = None;
        for (a, b, neg) in terms {
            let p = self.v_mul(a, b)?;
            acc = Some(match acc {
                None if *neg => self.v_neg(&p),
                None => p,
                Some(s) => self.v_add(&s, &p, *neg)?,
            });
        }
        acc.ok_or_else(|| AlgebraError::Internal("an empty sum of products".into()))
    }

    pub(crate) fn v_neg(&self, a: &Val) -> Val {
        Val {
            num: a.num.neg(),
            den: a.den.clone(),
            sh: a.sh.neg(),
        }
    }

    /// `1/a`: conjugates until the denominator is free of roots.
    pub(crate) fn v_inv(&self, a: &Val) -> AlgResult<Val> {
        if a.num.is_zero() {
            return Err(AlgebraError::DivisionByZero);
        }
        let one = Poly::from_i64(&self.ctx, 1);
        let sh = Shadow::leaf(vec![
            Complex::with_val(self.opts.precision, 1);
            self.opts.points
        ])
        .div(&a.sh);
        let (conj, norm) = self.rationalise(&a.num)?;
        self.check_algebraic_divisor(&norm)?;
        // 1/(N/D) = D·conj/norm
        let num = self.reduce(a.den.mul(&conj));
        let (num, den) = self.normalise(num, norm)?;
        let _ = one;
        Ok(Val { num, den, sh })
    }

    /// For `n` with roots, returns `(c, m)` with `n·c = m` free of roots.
    pub(crate) fn rationalise(&self, n: &Poly) -> AlgResult<(Poly, Poly)> {
        let mut conj = Poly::from_i64(&self.ctx, 1);
        let mut cur = n.clone();
        loop {
            let top = cur
                .used_vars()
                .into_iter()
                .find(|&idx| self.root_of_var(idx).is_some());
            let Some(idx) = top else { break };
            let r = Poly::var(&self.ctx, idx);
            let p0 = cur.coefficient_in(idx, 0);
            let p1 = cur.coefficient_in(idx, 1);
            let c = p0.sub(&p1.mul(&r));
            cur = self.reduce(cur.mul(&c));
            if cur.is_zero() {
                return Err(AlgebraError::ZeroDivisor(
                    "a non-zero value has norm 0 (the tower is not a field here)".into(),
                ));
            }
            conj = self.reduce(conj.mul(&c));
        }
        Ok((conj, cur))
    }

    pub(crate) fn v_div(&self, a: &Val, b: &Val) -> AlgResult<Val> {
        if b.num.is_zero() {
            return Err(AlgebraError::DivisionByZero);
        }
        let sh = a.sh.div(&b.sh);
        let has_roots = b
            .num
            .used_vars()
            .iter()
            .any(|&i| self.root_of_var(i).is_some());
        let mut v = if has_roots {
            let inv = self.v_inv(b)?;
            self.v_mul(a, &inv)?
        } else {
            self.check_algebraic_divisor(&b.num)?;
            // (an/ad) / (bn/bd) = an·bd / (ad·bn)
            let flipped = Val {
                num: b.den.clone(),
                den: b.num.clone(),
                sh: b.sh.clone(),
            };
            let (n, d) = self.lowest_terms(flipped.num, flipped.den)?;
            self.v_mul(
                a,
                &Val {
                    num: n,
                    den: d,
                    sh: flipped.sh,
                },
            )?
        };
        v.sh = sh;
        Ok(v)
    }

    pub(crate) fn v_powi(&self, a: &Val, n: i32) -> AlgResult<Val> {
        let base = if n < 0 { self.v_inv(a)? } else { a.clone() };
        let mut e = n.unsigned_abs();
        let mut acc: Option<Val> = None;
        let mut b = base;
        while e > 0 {
            if e & 1 == 1 {
                acc = Some(match acc {
                    None => b.clone(),
                    Some(x) => self.v_mul(&x, &b)?,
                });
            }
            e >>= 1;
            if e > 0 {
                b = self.v_mul(&b, &b)?;
            }
        }
        Ok(match acc {
            Some(x) => x,
            None => self.const_val(&rug::Rational::from(1)),
        })
    }
}

impl Sym {
    pub(crate) fn from_val(ring: &Ring, val: Val, node: Option<Arc<Node>>) -> Sym {
        let node = if ring.inner.opts.certificate {
            node
        } else {
            None
        };
        Sym {
            ring: ring.clone(),
            val: Arc::new(val),
            node,
        }
    }

    /// The normal form and shadow, taken out of the symbol (copied only if shared).
    pub(crate) fn into_val(self) -> Val {
        Arc::unwrap_or_clone(self.val)
    }

    /// The value as the ring stores it (without the ring handle).
    pub(crate) fn stored(&self) -> Stored {
        ((*self.val).clone(), self.node.clone())
    }

    /// A stored value back on its ring.
    pub(crate) fn restored(ring: &Ring, (val, node): Stored) -> Sym {
        Sym::from_val(ring, val, node)
    }

    /// The ring of this value.
    pub fn ring(&self) -> &Ring {
        &self.ring
    }

    fn same_ring(&self, o: &Sym) -> AlgResult<()> {
        if self.ring.same(&o.ring) {
            Ok(())
        } else {
            Err(AlgebraError::RingMismatch)
        }
    }

    fn node2(&self, op: Op, o: &Sym, v: &Val) -> Option<Arc<Node>> {
        let with_nf = matches!(op, Op::Mul | Op::Div);
        match (&self.node, &o.node) {
            (Some(a), Some(b)) if with_nf => Some(Node::with_nf(op, vec![a.clone(), b.clone()], v)),
            (Some(a), Some(b)) => Some(Node::new(op, vec![a.clone(), b.clone()])),
            _ => None,
        }
    }

    fn node1(&self, op: Op) -> Option<Arc<Node>> {
        self.node.as_ref().map(|a| Node::new(op, vec![a.clone()]))
    }

    /// `self + o`, or an error.
    pub fn try_add(&self, o: &Sym) -> AlgResult<Sym> {
        self.same_ring(o)?;
        let v = self.ring.inner.v_add(&self.val, &o.val, false)?;
        let node = self.node2(Op::Add, o, &v);
        Ok(Sym::from_val(&self.ring, v, node))
    }

    /// `self − o`, or an error.
    pub fn try_sub(&self, o: &Sym) -> AlgResult<Sym> {
        self.same_ring(o)?;
        let v = self.ring.inner.v_add(&self.val, &o.val, true)?;
        let node = self.node2(Op::Sub, o, &v);
        Ok(Sym::from_val(&self.ring, v, node))
    }

    /// `Σ ±aᵢbᵢ` (minus where the flag is set) over one common denominator, brought
    /// to lowest terms once (no derivation node: used without certificates only).
    pub fn try_sum_of_products(terms: &[(&Sym, &Sym, bool)]) -> AlgResult<Sym> {
        let ring = &terms
            .first()
            .ok_or_else(|| AlgebraError::Internal("an empty sum of products".into()))?
            .0
            .ring;
        let mut vals = Vec::with_capacity(terms.len());
        let mut args = Vec::with_capacity(2 * terms.len());
        for (x, y, neg) in terms {
            terms[0].0.same_ring(x)?;
            terms[0].0.same_ring(y)?;
            vals.push((&*x.val, &*y.val, *neg));
            if let (Some(a), Some(b)) = (&x.node, &y.node) {
                args.push(a.clone());
                args.push(b.clone());
            }
        }
        let v = ring.inner.v_sum_of_products(&vals)?;
        let node = (args.len() == 2 * terms.len()).then(|| {
            let signs = terms.iter().map(|t| t.2).collect();
            Node::with_nf(Op::SumOfProducts(signs), args, &v)
        });
        Ok(Sym::from_val(ring, v, node))
    }

    /// `self · o`, or an error.
    pub fn try_mul(&self, o: &Sym) -> AlgResult<Sym> {
        self.same_ring(o)?;
        let v = self.ring.inner.v_mul(&self.val, &o.val)?;
        let node = self.node2(Op::Mul, o, &v);
        Ok(Sym::from_val(&self.ring, v, node))
    }

    /// `self / o`, or an error (division by zero or by a zero divisor).
    pub fn try_div(&self, o: &Sym) -> AlgResult<Sym> {
        self.same_ring(o)?;
        let v = self.ring.inner.v_div(&self.val, &o.val)?;
        let node = self.node2(Op::Div, o, &v);
        Ok(Sym::from_val(&self.ring, v, node))
    }

    /// `self^n` for any integer `n` (negative powers invert), or an error.
    pub fn try_powi(&self, n: i32) -> AlgResult<Sym> {
        let v = self.ring.inner.v_powi(&self.val, n)?;
        let node = self
            .node
            .as_ref()
            .map(|a| Node::with_nf(Op::Pow(n), vec![a.clone()], &v));
        Ok(Sym::from_val(&self.ring, v, node))
    }

    /// `−self`.
    pub fn negate(&self) -> Sym {
        let v = self.ring.inner.v_neg(&self.val);
        Sym::from_val(&self.ring, v, self.node1(Op::Neg))
    }

    /// Is the normal form exactly zero?
    pub fn is_exact_zero(&self) -> bool {
        self.val.num.is_zero()
    }

    /// The value if it is an exact rational number.
    pub fn as_rational(&self) -> Option<rug::Rational> {
        let n = self.val.num.as_constant()?;
        let d = self.val.den.as_constant()?;
        Some(rug::Rational::from((n, d)))
    }

    /// Number of terms of the numerator of the normal form.
    pub fn terms(&self) -> usize {
        self.val.num.len()
    }

    /// The shadow value at domain point `i`.
    pub fn shadow(&self, i: usize) -> &Complex {
        &self.val.sh.v[i]
    }

    /// The shadow values at all domain points.
    pub fn shadows(&self) -> &[Complex] {
        &self.val.sh.v
    }

    /// Evaluates the normal form (not the shadow) at every domain point from the
    /// symbols' values: an independent check of the exact arithmetic.
    pub fn eval_normal_form(&self) -> Vec<Complex> {
        let inner = &self.ring.inner;
        let vals = inner.var_values();
        let n = inner.eval_poly(&self.val.num, &vals);
        let d = inner.eval_poly(&self.val.den, &vals);
        n.iter()
            .zip(&d)
            .map(|(a, b)| Complex::with_val(inner.opts.precision, a / b))
            .collect()
    }

    /// The normal form as `(numerator) / (denominator)` in SymPy syntax.
    pub fn render(&self) -> String {
        let names = self.ring.inner.names();
        let n = self.val.num.render(&names);
        if self.val.den.is_one() {
            n
        } else {
            format!("({n})/({})", self.val.den.render(&names))
        }
    }

    /// A rendering cut to about `max` characters, for messages and assumptions.
    pub fn render_short(&self, max: usize) -> String {
        let s = self.render();
        if s.chars().count() <= max {
            s
        } else {
            let cut: String = s.chars().take(max).collect();
            format!("{cut}… ({} terms)", self.terms())
        }
    }

    /// Does the normal form contain root symbols?
    pub fn has_roots(&self) -> bool {
        self.val
            .num
            .used_vars()
            .iter()
            .any(|&i| self.ring.inner.root_of_var(i).is_some())
    }

    /// If the value is exactly one field variable, its index.
    pub(crate) fn as_field_var(&self) -> Option<usize> {
        if !self.val.den.is_one() || self.val.num.len() != 1 {
            return None;
        }
        let used = self.val.num.used_vars();
        if used.len() != 1 || self.ring.inner.root_of_var(used[0]).is_some() {
            return None;
        }
        let p = Poly::var(&self.ring.inner.ctx, used[0]);
        (p == self.val.num).then(|| used[0] - self.ring.inner.opts.max_roots)
    }

    /// A value with a new shadow (used where a value is known more accurately).
    pub(crate) fn with_node(mut self, node: Option<Arc<Node>>) -> Sym {
        if self.ring.inner.opts.certificate {
            self.node = node;
        }
        self
    }

    /// Unwraps an operator result: on error, record it in the ring and return a NaN
    /// value.
    pub(crate) fn or_poison(ring: &Ring, r: AlgResult<Sym>) -> Sym {
        match r {
            Ok(s) => s,
            Err(e) => {
                ring.poison(e);
                ring.nan()
            }
        }
    }
}

impl Ring {
    /// The exact integer `n`.
    pub fn integer(&self, n: i64) -> Sym {
        self.rational(&Rational::from(n))
    }

    /// The exact rational `q`.
    pub fn rational(&self, q: &Rational) -> Sym {
        Sym::from_val(self, self.inner.const_val(q), Some(Node::constant(q)))
    }

    pub(crate) fn var_sym(&self, j: usize) -> Sym {
        let (values, name) = {
            let st = self.state();
            (st.vars[j].values.clone(), st.vars[j].name.clone())
        };
        self.leaf_sym(self.inner.kvar(j), values, &name)
    }

    pub(crate) fn root_sym(&self, i: usize) -> Sym {
        let (values, name) = {
            let st = self.state();
            (st.roots[i].values.clone(), st.roots[i].name.clone())
        };
        self.leaf_sym(self.inner.root_var(i), values, &name)
    }

    /// The symbol of polynomial variable `idx` with its values.
    fn leaf_sym(&self, idx: usize, values: Vec<Complex>, name: &str) -> Sym {
        let val = Val {
            num: Poly::var(&self.inner.ctx, idx),
            den: Poly::from_i64(&self.inner.ctx, 1),
            sh: Shadow::leaf(values),
        };
        Sym::from_val(self, val, Some(Node::symbol(name)))
    }

    /// A meaningless value (exact 0 with NaN shadows), returned after an error.
    pub(crate) fn nan(&self) -> Sym {
        let prec = self.precision();
        let mut z = Complex::new(prec);
        z.mut_real().assign_nan();
        let sh = Shadow::leaf(vec![z; self.points()]);
        let ctx = &self.inner.ctx;
        Sym::from_val(
            self,
            Val {
                num: Poly::zero(ctx),
                den: Poly::from_i64(ctx, 1),
                sh,
            },
            None,
        )
    }
}

trait AssignNan {
    fn assign_nan(&mut self);
}
impl AssignNan for rug::Float {
    fn assign_nan(&mut self) {
        use rug::Assign;
        self.assign(rug::float::Special::Nan);
    }
}
