//! The exact derivative: a derivation of the tower.
//!
//! `d/dx` of a normal form `N/D`, with `D = c·Π fᵢ^eᵢ`, is `N'/D − (N/D)·Σ eᵢ fᵢ'/fᵢ`
//! (the quotient rule over the denominator `D·Π fᵢ`), with `P' = Σ_v ∂P/∂v · v'` over
//! the variables of `P`, and for each symbol `v`:
//!
//! * an indeterminate: `x' = 1`, others 0; a named quantity: the derivative of its
//!   definition; an opaque constant: 0;
//! * a root `r² = a`: `r' = a'/(2r) = a'·r/(2a)`;
//! * `s = sn b` of a base argument: `s' = c·d·b' + ∂s/∂k · k'(x)` (DLMF 22.13.1), and
//!   when the modulus depends on `x`, with `Z = E(am b, k) − k'²b` (one more symbol per
//!   base): `∂s/∂k = −c d Z/(k k'²) + k s c²/k'²`,
//!   `∂Z/∂k = k s c d/k'² − k c² Z/k'² + k b`, `Z' = k² c² b' + ∂Z/∂k · k'(x)`;
//! * `K`, `K'`: 0 when the modulus does not depend on `x` (otherwise an error).

use super::error::{AlgResult, AlgebraError};
use super::flint::Poly;
use super::node::{Node, Op};
use super::ring::{Ring, VarKind};
use super::shadow::Shadow;
use super::sym::Sym;
use super::val::Val;
use crate::numbers::Dual;
use crate::special::sncndn;
use rug::{Complex, Float, Rational};

impl Sym {
    /// The derivation with respect to the indeterminate `x` itself (all other symbols
    /// fixed), whether or not coordinates are declared.
    pub(crate) fn derivative_plain(&self, x: &Sym) -> AlgResult<Sym> {
        let ring = &self.ring;
        if !ring.same(&x.ring) {
            return Err(AlgebraError::RingMismatch);
        }
        let jx = x
            .as_field_var()
            .filter(|&j| matches!(ring.state().vars[j].kind, VarKind::Indeterminate))
            .ok_or_else(|| {
                AlgebraError::Derivative(format!("{} is not an indeterminate", x.render_short(60)))
            })?;
        let v = ring.val_derivative(&self.val, jx)?;
        let name = ring.state().vars[jx].name.clone();
        let node = self
            .node
            .as_ref()
            .map(|n| Node::with_nf(Op::Deriv(name), vec![n.clone()], &v));
        Ok(Sym::from_val(ring, v, node))
    }
}

impl Ring {
    fn poly_val(&self, p: &Poly) -> Val {
        let one = Poly::from_i64(&self.inner.ctx, 1);
        let sh = self.shadow_of(p, &one);
        Val {
            num: p.clone(),
            den: one,
            sh,
        }
    }

    /// `d/dx` of a polynomial (as a value).
    fn poly_derivative(&self, p: &Poly, jx: usize) -> AlgResult<Val> {
        let inner = &self.inner;
        let mut terms = Vec::new();
        for idx in p.used_vars() {
            let dv = self.var_derivative(idx, jx)?;
            if dv.num.is_zero() {
                continue;
            }
            terms.push((self.poly_val(&p.derivative(idx)), dv));
        }
        match terms.as_slice() {
            [] => Ok(inner.const_val(&Rational::new())),
            [(part, dv)] => inner.v_mul(part, dv),
            _ => {
                let refs: Vec<(&Val, &Val, bool)> =
                    terms.iter().map(|(a, b)| (a, b, false)).collect();
                inner.v_sum_of_products(&refs)
            }
        }
    }

    /// `(N/D)'` for `D = c·Π fᵢ^eᵢ` (its remembered factors): `N'/D − (N/D)·Σ eᵢ fᵢ'/fᵢ`,
    /// one sum of products over the common denominator `D·Π fᵢ` rather than `D²`, from
    /// the value's own shadow (`N` and `D` are not evaluated again).
    pub(crate) fn val_derivative(&self, v: &Val, jx: usize) -> AlgResult<Val> {
        let inner = &self.inner;
        let dn = self.poly_derivative(&v.num, jx)?;
        if v.den.is_one() {
            return Ok(dn);
        }
        let one = Poly::from_i64(&inner.ctx, 1);
        let reciprocal = |d: &Poly| Val {
            num: one.clone(),
            den: d.clone(),
            sh: self.shadow_of(&one, d),
        };
        let factors = inner.dens.of(&v.den)?;
        let mut logs = Vec::with_capacity(factors.list.len());
        for (f, e) in &factors.list {
            let df = self.poly_derivative(f, jx)?;
            if df.num.is_zero() {
                continue;
            }
            // f is irreducible, primitive, of positive leading coefficient
            let own = super::den_factors::Factors {
                unit: rug::Integer::from(1),
                list: vec![(f.clone(), 1)],
            };
            inner.dens.record(f, std::sync::Arc::new(own));
            let scaled = inner.v_mul(&df, &inner.const_val(&Rational::from(*e)))?;
            logs.push(inner.v_mul(&scaled, &reciprocal(f))?);
        }
        let inv_d = reciprocal(&v.den);
        let mut terms: Vec<(&Val, &Val, bool)> = vec![(&dn, &inv_d, false)];
        terms.extend(logs.iter().map(|g| (v, g, true)));
        if terms.len() == 1 {
            return inner.v_mul(&dn, &inv_d);
        }
        inner.v_sum_of_products(&terms)
    }

    /// `d v/d x` for FLINT variable `idx` (cached).
    fn var_derivative(&self, idx: usize, jx: usize) -> AlgResult<Val> {
        if let Some(v) = self.state().dcache.get(&(idx, jx)) {
            return Ok(v.clone());
        }
        let inner = &self.inner;
        let v = match inner.root_of_var(idx) {
            Some(i) => self.root_derivative(i, jx)?,
            None => self.field_var_derivative(idx - inner.opts.max_roots, jx)?,
        };
        let names = inner.names();
        let line = format!(
            "dvar {} {} = ({})/({})",
            names[inner.kvar(jx)],
            names[idx],
            v.num.render(&names),
            v.den.render(&names)
        );
        let mut st = self.state();
        st.dcache.insert((idx, jx), v.clone());
        st.derivation_lines.push(line);
        Ok(v)
    }

    fn root_derivative(&self, i: usize, jx: usize) -> AlgResult<Val> {
        let inner = &self.inner;
        let a = self.state().roots[i].radicand.clone();
        let da = self.poly_derivative(&a, jx)?;
        if da.num.is_zero() {
            return Ok(da);
        }
        let r = self.root_sym(i).val;
        let two_a = inner.v_mul(&inner.const_val(&Rational::from(2)), &self.poly_val(&a))?;
        inner.v_div(&inner.v_mul(&da, &r)?, &two_a)
    }

    fn field_var_derivative(&self, j: usize, jx: usize) -> AlgResult<Val> {
        let kind = self.state().vars[j].kind.clone();
        let zero = self.inner.const_val(&Rational::new());
        match kind {
            VarKind::Indeterminate => Ok(self.inner.const_val(&Rational::from(i64::from(j == jx)))),
            VarKind::Named(def) => self.val_derivative(&def, jx),
            VarKind::Opaque { constant: true } => Ok(zero),
            VarKind::Opaque { constant: false } => self.opaque_derivative(j, jx),
            VarKind::QuarterK { table }
            | VarKind::QuarterKp { table }
            | VarKind::ThirdK { table } => {
                let k = self.state().tables[table].k.clone();
                if self.val_derivative(&k, jx)?.num.is_zero() {
                    Ok(zero)
                } else {
                    Err(AlgebraError::Derivative(
                        "of a quarter period (or sn(K/3)) whose modulus varies (needs E(k))".into(),
                    ))
                }
            }
            VarKind::Sn { table, base } => self.sn_derivative(table, base, jx, false),
            VarKind::Zeta { table, base } => self.sn_derivative(table, base, jx, true),
            VarKind::Jet { f, s, arg, k } => self.jet_derivative(f, s, (&arg, &k), jx),
        }
    }

    /// `S' = C·D·a'`, `C' = −S·D·a'`, `D' = −κ²·S·C·a'` of a jet trio (module `jets`,
    /// DLMF 22.13.1–3), for a modulus `κ` that does not depend on `x`.
    fn jet_derivative(&self, f: u8, s: usize, (arg, k): (&Val, &Val), jx: usize) -> AlgResult<Val> {
        let inner = &self.inner;
        if !self.val_derivative(k, jx)?.num.is_zero() {
            return Err(AlgebraError::Derivative(
                "of a jet symbol whose modulus varies".into(),
            ));
        }
        let da = self.val_derivative(arg, jx)?;
        let v = |i: usize| self.var_sym(s + i).into_val();
        let (a, b, sign) = match f {
            0 => (v(1), v(2), 1),
            1 => (v(0), v(2), -1),
            _ => (v(0), v(1), -1),
        };
        let mut t = inner.v_mul(&inner.v_mul(&a, &b)?, &da)?;
        if f == 2 {
            t = inner.v_mul(&t, &inner.v_mul(k, k)?)?;
        }
        if sign < 0 {
            t = inner.v_neg(&t);
        }
        Ok(t)
    }

    /// `v'` of an opaque symbol: known when its sn, cn, dn are prescribed at a modulus
    /// that does not depend on `x` (then `s' = c·d·v'`, DLMF 22.13.1).
    fn opaque_derivative(&self, j: usize, jx: usize) -> AlgResult<Val> {
        let name = self.state().vars[j].name.clone();
        let p = self.state().prescribed.iter().find(|p| p.var == j).cloned();
        let unknown = |why: &str| {
            AlgebraError::Derivative(format!("the derivative of {name} is unknown{why}"))
        };
        if let Some(d) = self.opaque_call_derivative(j, jx)? {
            return Ok(d);
        }
        let Some(p) = p else {
            // a parameter of declared coordinates (a phase step δ) is independent of the
            // other parameters
            if self.is_coordinate_parameter(j)? {
                return Ok(self.inner.const_val(&Rational::new()));
            }
            return Err(unknown(""));
        };
        let ds = self.val_derivative(&p.s, jx)?;
        let cd = self.inner.v_mul(&p.c, &p.d)?;
        if cd.num.is_zero() {
            return Err(unknown(": cn dn vanishes"));
        }
        let dk = self.val_derivative(&p.k, jx)?;
        if dk.num.is_zero() {
            return self.inner.v_div(&ds, &cd);
        }
        // sn(v, k) = s: c d v' + (∂sn/∂k)(v, k) k' = s', with
        // ∂sn/∂k = −c d Z/(k k'²) + k s c²/k'² and Z = E(am v, k) − k'² v
        let z = self.opaque_zeta(j, &p)?;
        let inner = &self.inner;
        let m = |a: &Val, b: &Val| inner.v_mul(a, b);
        let one = inner.const_val(&Rational::from(1));
        let k2 = m(&p.k, &p.k)?;
        let kp2 = inner.v_add(&one, &k2, true)?;
        let t1 = inner.v_div(&m(&cd, &z)?, &m(&p.k, &kp2)?)?;
        let t2 = inner.v_div(&m(&m(&p.k, &p.s)?, &m(&p.c, &p.c)?)?, &kp2)?;
        let dsdk = inner.v_add(&t2, &t1, true)?;
        let rhs = inner.v_add(&ds, &m(&dsdk, &dk)?, true)?;

        inner.v_div(&rhs, &cd)
    }

    /// The derivative of the opaque symbol `j` of a call with a rule: `ln x` has `x'/x`,
    /// `am(u, k)` has `dn(u, k)·u'` for a modulus that does not depend on the variable
    /// (DLMF 22.16.3); `None` for other symbols.
    fn opaque_call_derivative(&self, j: usize, jx: usize) -> AlgResult<Option<Val>> {
        let call = self.state().opaque_args.get(&j).cloned();
        let Some((f, args)) = call else {
            return Ok(None);
        };
        let inner = &self.inner;
        match (f.as_str(), args.as_slice()) {
            ("ln", [x]) => {
                let dx = self.val_derivative(&x.0, jx)?;
                Ok(Some(inner.v_div(&dx, &x.0)?))
            }
            ("am", [u, k]) if !self.options().jets => {
                if !self.val_derivative(&k.0, jx)?.num.is_zero() {
                    return Err(AlgebraError::Derivative(
                        "of am whose modulus varies (needs E(am u, k))".into(),
                    ));
                }
                let du = self.val_derivative(&u.0, jx)?;
                let us = Sym::restored(self, u.clone());
                let ks = Sym::restored(self, k.clone());
                let d = us.dn(&ks)?;
                Ok(Some(inner.v_mul(&d.val, &du)?))
            }
            _ => Ok(None),
        }
    }

    /// The symbol `Z = E(am v, k) − k'² v` of opaque symbol `j` (its values from the
    /// k-derivative of sn at the symbol's values, as for a base argument).
    fn opaque_zeta(&self, j: usize, p: &super::ring::Prescription) -> AlgResult<Val> {
        let known = self.state().opaque_zeta.get(&j).copied();
        if let Some(z) = known {
            return Ok(self.var_sym(z).into_val());
        }
        let v = self.var_sym(j).val;
        let prec = self.precision();
        let mut values = Vec::new();
        for i in 0..self.points() {
            if !v.sh.is_real_at(i, prec) || !p.k.sh.is_real_at(i, prec) {
                return Err(AlgebraError::Derivative(
                    "in the modulus at a complex argument".into(),
                ));
            }
            values.push(zeta_value(&v.sh, &p.k.sh, i, prec)?);
        }
        let name = format!("Z_{}", self.state().vars[j].name);
        let z = self
            .inner
            .add_var(name, VarKind::Opaque { constant: false }, values)?;
        self.state().opaque_zeta.insert(j, z);
        Ok(self.var_sym(z).into_val())
    }

    /// Is field variable `j` one of the parameters of the declared coordinates?
    pub(crate) fn is_coordinate_parameter(&self, j: usize) -> AlgResult<bool> {
        let params: Vec<Val> = match &self.state().coordinates {
            Some(c) => c.params.iter().map(|(v, _)| v.clone()).collect(),
            None => return Ok(false),
        };
        let v = self.var_sym(j).val;
        for p in params {
            if self.inner.v_add(&p, &v, true)?.num.is_zero() {
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// `s'` (or `Z'` when `zeta`) of base `base` of table `table`.
    fn sn_derivative(&self, table: usize, base: usize, jx: usize, zeta: bool) -> AlgResult<Val> {
        let inner = &self.inner;
        let (k, arg, c, d, sj) = {
            let st = self.state();
            let b = &st.tables[table].bases[base];
            (
                st.tables[table].k.clone(),
                b.arg.clone(),
                b.c.clone(),
                b.d.clone(),
                b.s.clone(),
            )
        };
        let s = sj;
        let du = self.val_derivative(&arg, jx)?;
        let dk = self.val_derivative(&k, jx)?;
        let m = |a: &Val, b: &Val| inner.v_mul(a, b);
        let cd = m(&c, &d)?;
        let k2 = m(&k, &k)?;
        let along = if zeta {
            m(&m(&k2, &m(&c, &c)?)?, &du)?
        } else {
            m(&cd, &du)?
        };
        if dk.num.is_zero() {
            return Ok(along);
        }
        let z = self.zeta_symbol(table, base)?;
        let one = inner.const_val(&Rational::from(1));
        let kp2 = inner.v_add(&one, &k2, true)?;
        let c2 = m(&c, &c)?;
        let partial = if zeta {
            // k s c d/k'² − k c² Z/k'² + k u
            let t1 = m(&m(&k, &s)?, &cd)?;
            let t2 = m(&m(&k, &c2)?, &z)?;
            let t = inner.v_div(&inner.v_add(&t1, &t2, true)?, &kp2)?;
            inner.v_add(&t, &m(&k, &arg)?, false)?
        } else {
            // −c d Z/(k k'²) + k s c²/k'²
            let t1 = inner.v_div(&m(&cd, &z)?, &m(&k, &kp2)?)?;
            let t2 = inner.v_div(&m(&m(&k, &s)?, &c2)?, &kp2)?;
            inner.v_add(&t2, &t1, true)?
        };
        inner.v_add(&along, &m(&partial, &dk)?, false)
    }

    /// The symbol `Z = E(am b, k) − k'² b` of a base (values from the k-derivative of sn
    /// by automatic differentiation).
    fn zeta_symbol(&self, table: usize, base: usize) -> AlgResult<Val> {
        let existing = self.state().tables[table].bases[base].z_var;
        if let Some(j) = existing {
            return Ok(self.var_sym(j).into_val());
        }
        let (k, arg) = {
            let st = self.state();
            (
                st.tables[table].k.clone(),
                st.tables[table].bases[base].arg.clone(),
            )
        };
        let prec = self.precision();
        let mut values = Vec::new();
        for p in 0..self.points() {
            if !arg.sh.is_real_at(p, prec) {
                return Err(AlgebraError::Derivative(
                    "in the modulus at a complex argument".into(),
                ));
            }
            values.push(zeta_value(&arg.sh, &k.sh, p, prec)?);
        }
        let n = self.state().vars.len();
        let j = self.inner.add_var(
            format!("Z_{}", n + 1),
            VarKind::Zeta { table, base },
            values,
        )?;
        self.state().tables[table].bases[base].z_var = Some(j);
        Ok(self.var_sym(j).into_val())
    }
}

/// `Z = E(am u, k) − k'²u` at point `p`, from `∂am/∂k` (dual numbers in `k`):
/// `Z = (k s c/k'² − ∂am/∂k)·k k'²/d`.
fn zeta_value(u: &Shadow, k: &Shadow, p: usize, prec: u32) -> AlgResult<Complex> {
    let uf = Float::with_val(prec, u.v[p].real());
    let kf = Float::with_val(prec, k.v[p].real());
    let ud = Dual::constant(uf);
    let kd = Dual::var(kf.clone());
    let (s, c, d) =
        sncndn(&ud, &kd).map_err(|e| AlgebraError::Derivative(format!("numeric sn: {e}")))?;
    let damk = if Float::with_val(prec, c.v.abs_ref()) >= Float::with_val(prec, s.v.abs_ref()) {
        Float::with_val(prec, &s.d / &c.v)
    } else {
        -Float::with_val(prec, &c.d / &s.v)
    };
    let kp2 = Float::with_val(prec, 1) - Float::with_val(prec, &kf * &kf);
    let first = Float::with_val(prec, &kf * &s.v) * &c.v / &kp2;
    let z = (first - damk) * &kf * &kp2 / &d.v;
    Ok(Complex::with_val(prec, (z, 0)))
}
