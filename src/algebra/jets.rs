//! Jacobi functions as jet symbols, for the ODE method ([`super::ode`]).
//!
//! With [`RingOptions::jets`](super::RingOptions::jets), `sn`, `cn`, `dn` of an argument
//! `a` at a modulus `κ` are three independent field variables `S`, `C`, `D` (one trio per
//! distinct pair `(a, κ)`, at any moduli, with no addition theorem), whose values at the
//! domain points are the numeric `sn a`, `cn a`, `dn a`.  The derivation of the tower
//! knows them (module `derive`, DLMF 22.13.1–3): `S' = C·D·a'`, `C' = −S·D·a'`,
//! `D' = −κ²·S·C·a'` when `κ` does not depend on the variable.  The relations
//! `C² = 1 − S²` and `D² = 1 − κ²S²` (DLMF 22.6.1) are not reduced by the ring:
//! [`Ring::reduce_jets`] reduces a value modulo them.  The relations' leading terms
//! `C²`, `D²` are coprime to each other and to the tower's `rᵢ²`, so together they are a
//! Gröbner basis: the reduction is a normal form, and it is 0 exactly when the value is
//! in the ideal of the relations — then it vanishes at the true values of the functions.

use super::error::{AlgResult, AlgebraError};
use super::flint::Poly;
use super::ring::{JET_NAMES, Ring, VarKind};
use super::sym::Sym;
use super::val::Val;

/// One trio of jet symbols: the field variable of its sn (cn and dn follow), the
/// argument and the modulus.
#[derive(Clone, Debug)]
pub(crate) struct Jet {
    pub s: usize,
    pub arg: Val,
    pub k: Val,
}

impl Ring {
    /// The ring's jet trios, in the order they were made.
    pub(crate) fn jets(&self) -> Vec<Jet> {
        let st = self.state();
        (st.vars.iter())
            .filter_map(|v| match &v.kind {
                VarKind::Jet { f: 0, s, arg, k } => Some(Jet {
                    s: *s,
                    arg: (**arg).clone(),
                    k: (**k).clone(),
                }),
                _ => None,
            })
            .collect()
    }

    /// The jet trio `(S, C, D)` of `sn`, `cn`, `dn` at `arg` and modulus `k`: the trio
    /// made before for the same pair, or a new one with the numeric values.  The
    /// derivation knows them; their relations are reduced by the ODE method only.
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// let ring = Ring::new(RingOptions { points: 2, jets: true, ..Default::default() });
    /// let u = ring.indeterminate_f64("u", &[0.3, 0.7]).unwrap();
    /// let k = ring.indeterminate_f64("k", &[0.5, 0.8]).unwrap();
    /// let (s, c, d) = ring.jet_sncndn(&(ring.integer(2) * u.clone()), &k).unwrap();
    /// // d/du sn(2u) = 2 cn(2u) dn(2u)
    /// let ds = s.derivative(&u).unwrap();
    /// assert!(ring.prove(&ds, &(ring.integer(2) * c * d)).is_proved());
    /// ```
    pub fn jet_sncndn(&self, arg: &Sym, k: &Sym) -> AlgResult<(Sym, Sym, Sym)> {
        if !arg.ring.same(self) || !k.ring.same(self) {
            return Err(AlgebraError::RingMismatch);
        }
        let inner = &self.inner;
        let same = |a: &Val, b: &Val| inner.v_add(a, b, true).map(|d| d.num.is_zero());
        for jet in self.jets() {
            if same(&jet.arg, &arg.val)? && same(&jet.k, &k.val)? {
                return Ok(self.jet_trio(jet.s));
            }
        }
        let (s, c, d) = self.numeric_sncndn(&arg.val.sh, &k.val.sh)?;
        let n = self.jets().len() + 1;
        let first = self.state().vars.len();
        for (f, values) in [s, c, d].into_iter().enumerate() {
            let kind = VarKind::Jet {
                f: f as u8,
                s: first,
                arg: Box::new((*arg.val).clone()),
                k: Box::new((*k.val).clone()),
            };
            let j = inner.add_var(format!("j{}_{n}", JET_NAMES[f]), kind, values)?;
            if j != first + f {
                return Err(AlgebraError::Internal("jet symbols out of order".into()));
            }
        }
        self.note(format!(
            "jsn_{n}, jcn_{n}, jdn_{n}: sn, cn, dn({}, {}) as jet symbols",
            arg.render_short(60),
            k.render_short(60)
        ));
        Ok(self.jet_trio(first))
    }

    fn jet_trio(&self, s: usize) -> (Sym, Sym, Sym) {
        (self.var_sym(s), self.var_sym(s + 1), self.var_sym(s + 2))
    }

    /// A polynomial of the ring as a value (denominator 1).
    pub(crate) fn poly_sym(&self, p: &Poly) -> Sym {
        let one = Poly::from_i64(&self.inner.ctx, 1);
        let sh = self.shadow_of(p, &one);
        let val = Val {
            num: p.clone(),
            den: one,
            sh,
        };
        Sym::from_val(self, val, None)
    }

    /// The numerator of `v` reduced modulo every trio's `C² = 1 − S²`,
    /// `D² = 1 − κ²S²`: 0 exactly when `v` vanishes wherever the relations hold and its
    /// denominator does not vanish (see the module doc).
    pub(crate) fn reduce_jets(&self, v: &Sym) -> AlgResult<Sym> {
        let mut n = self.poly_sym(&v.val.num);
        for jet in self.jets() {
            let s = self.var_sym(jet.s);
            let one = self.integer(1);
            let s2 = s.try_mul(&s)?;
            let k2 = Sym::from_val(self, jet.k.clone(), None);
            let c2 = one.try_sub(&s2)?;
            let d2 = one.try_sub(&k2.try_mul(&k2)?.try_mul(&s2)?)?;
            n = self.reduce_square(&n, jet.s + 1, &c2)?;
            n = self.reduce_square(&n, jet.s + 2, &d2)?;
            // a denominator (from κ²) is nonzero: the numerator carries the zero test
            n = self.poly_sym(&n.val.num);
        }
        Ok(n)
    }

    /// `n` with `x² ↦ square` for field variable `j` = `x`: `Σ x^(e mod 2) square^(e div 2) nₑ`.
    fn reduce_square(&self, n: &Sym, j: usize, square: &Sym) -> AlgResult<Sym> {
        let idx = self.inner.kvar(j);
        let x = self.var_sym(j);
        let deg = n.val.num.degree(idx);
        let mut out = self.integer(0);
        for e in 0..=deg.max(0) as u64 {
            let ne = n.val.num.coefficient_in(idx, e);
            if ne.is_zero() {
                continue;
            }
            let mut t = self
                .poly_sym(&ne)
                .try_mul(&square.try_powi((e / 2) as i32)?)?;
            if e % 2 == 1 {
                t = t.try_mul(&x)?;
            }
            out = out.try_add(&t)?;
        }
        Ok(out)
    }
}
