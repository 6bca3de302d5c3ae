//! sn, cn, dn of linear combinations of symbols, expanded by the addition theorems.
//!
//! Per modulus `k` the ring keeps a table of *base arguments* `b₁…bₘ`.  Every argument
//! is split term by term into *directions* (a monomial over a primitive denominator)
//! with rational coefficients, plus multiples of `K/2` and `iK'/2` when the quarter
//! periods of this modulus occur; it must be an integer combination `Σ nⱼ bⱼ` of the
//! bases.  An argument outside their rational span becomes a new base; one inside the
//! span with non-integer coefficients (e.g. `φ/2` after `φ`) gets a provisional base and
//! asks for a restart with a refined base table (a lattice basis of all arguments seen,
//! module `lattice`).
//!
//! Each base gets a transcendental `s = sn bⱼ` and roots `c`, `d` with `c² = 1 − s²`,
//! `d² = 1 − k²s²` whose values at the points are `cn bⱼ`, `dn bⱼ` (computed by
//! [`crate::special`]).  Integer combinations follow from DLMF 22.8.1–3 (addition),
//! shifts by `K`, `iK'` from DLMF 22.4.3 (Table 22.4.3: `sn(z+K) = cd z`,
//! `sn(z+iK') = ns z / k`, …; poles as the reciprocal forms), and half periods from
//! DLMF 22.5.1 (`sn(K/2) = (1+k')^{-1/2}`, `sn(iK'/2) = i k^{-1/2}`, …).  Every result is
//! checked against a direct numeric evaluation at the domain points.

use super::base_table::{Base, Table};
pub use super::base_table::{BaseHint, DirKey, Terms};
use super::error::{AlgResult, AlgebraError};
use super::flint::Poly;
use super::lattice::{cost, lattice_basis, solve};
use super::node::{Node, Op};
use super::ring::{Origin, Prescription, Ring, VarKind};
use super::roots::Prescribed;
use super::shadow::Shadow;
use super::sym::Sym;
use super::val::Val;
use crate::special::{ellipk, ellipkp, sncndn, sncndn_complex};
use rug::{Complex, Float, Integer, Rational};

fn terms(p: &Poly) -> Terms {
    let mut t = Vec::new();
    p.for_each_term(|c, e| t.push((c.clone(), e.to_vec())));
    t
}

fn pad(v: &mut Vec<Rational>, n: usize) {
    while v.len() < n {
        v.push(Rational::new());
    }
}

/// The split of an argument: coefficients over directions, then multiples of K/2,
/// iK'/2 and K/3 (`third_k` in 0..3).
struct Split {
    vec: Vec<Rational>,
    half_k: i64,
    half_kp: i64,
    third_k: i64,
}

/// An argument as `(table, [(base, n)], half_k, half_kp)`: Σ n·base + half_k·K/2 +
/// half_kp·iK'/2 in the elliptic table `table`.
pub(crate) type Combination = (usize, Vec<(usize, i64)>, i64, i64);

impl Ring {
    /// The index of the table of modulus `k`, created if new.
    fn table_of(&self, k: &Sym) -> AlgResult<usize> {
        if !k.ring.same(self) {
            return Err(AlgebraError::RingMismatch);
        }
        let prec = self.precision();
        // k = 1 exactly: sn = tanh, cn = dn = sech (DLMF 22.5.ii); the addition theorems
        // hold, the quarter period does not exist
        let one = k.as_rational().is_some_and(|q| q == 1);
        for p in 0..self.points() {
            let z = &k.val.sh.v[p];
            let bad = z.real().is_sign_negative() || (*z.real() >= 1 && !one);
            if !k.val.sh.is_real_at(p, prec) || bad {
                return Err(AlgebraError::Domain(format!(
                    "modulus {} is not in [0, 1) at a domain point",
                    k.render_short(80)
                )));
            }
        }
        let found = self
            .state()
            .tables
            .iter()
            .position(|t| t.k.num == k.val.num && t.k.den == k.val.den);
        if let Some(i) = found {
            return Ok(i);
        }
        let k2 = k.try_mul(k)?;
        let mut t = Table::new((*k.val).clone(), k2.into_val());
        let mkey = (terms(&k.val.num), terms(&k.val.den));
        for h in &self.inner.opts.base_hints {
            if h.modulus == mkey {
                t.pending = h.bases.clone();
            }
        }
        let mut st = self.state();
        st.tables.push(t);
        let t = st.tables.len() - 1;
        drop(st);
        self.link_complementary(t)?;
        Ok(t)
    }

    /// The tables of moduli `k`, `k'` with `k² + k'² = 1` exactly share their quarter
    /// periods crosswise: `K(k') = K'(k)` and `K'(k') = K(k)` (K depends on k² only), so
    /// that `K'(k)` inside sn, cn, dn of modulus `k'` is its quarter period (as in
    /// Jacobi's imaginary transformation of a complex argument).  A certificate's
    /// `period` lines then name one symbol in both tables, and the recheck verifies
    /// that their moduli are complementary.
    fn link_complementary(&self, t: usize) -> AlgResult<()> {
        let n = self.state().tables.len();
        for t0 in (0..n).filter(|&t0| t0 != t) {
            let (a, b) = {
                let st = self.state();
                (st.tables[t].k2.clone(), st.tables[t0].k2.clone())
            };
            let sum = self.inner.v_add(&a, &b, false)?;
            let one = self.inner.const_val(&Rational::from(1));
            if !self.inner.v_add(&sum, &one, true)?.num.is_zero() {
                continue;
            }
            let mut st = self.state();
            let (k0, kp0) = (st.tables[t0].k_var, st.tables[t0].kp_var);
            let tb = &mut st.tables[t];
            if tb.k_var.is_none() && kp0.is_some() {
                tb.k_var = kp0;
            }
            if tb.kp_var.is_none() && k0.is_some() {
                tb.kp_var = k0;
            }
        }
        Ok(())
    }

    /// The quarter period `K(k)` as a transcendental symbol.
    pub fn quarter_period(&self, k: &Sym) -> AlgResult<Sym> {
        self.period_symbol(k, false)
    }

    /// The complementary quarter period `K'(k)` as a transcendental symbol.
    pub fn quarter_period_prime(&self, k: &Sym) -> AlgResult<Sym> {
        self.period_symbol(k, true)
    }

    fn period_symbol(&self, k: &Sym, prime: bool) -> AlgResult<Sym> {
        let t = self.table_of(k)?;
        let existing = {
            let st = self.state();
            if prime {
                st.tables[t].kp_var
            } else {
                st.tables[t].k_var
            }
        };
        if let Some(j) = existing {
            return Ok(self.var_sym(j));
        }
        let prec = self.precision();
        let mut values = Vec::new();
        for z in k.shadows() {
            let kr = Float::with_val(prec, z.real());
            let v = if prime { ellipkp(&kr) } else { ellipk(&kr) };
            let v = v.map_err(|e| AlgebraError::Domain(format!("quarter period: {e}")))?;
            values.push(Complex::with_val(prec, (v, 0)));
        }
        let (name, kind) = if prime {
            (format!("Kp_{}", t + 1), VarKind::QuarterKp { table: t })
        } else {
            (format!("K_{}", t + 1), VarKind::QuarterK { table: t })
        };
        let j = self.inner.add_var(name, kind, values)?;
        let mut st = self.state();
        if prime {
            st.tables[t].kp_var = Some(j);
        } else {
            st.tables[t].k_var = Some(j);
        }
        let others: Vec<usize> = (0..st.tables.len()).filter(|&o| o != t).collect();
        drop(st);
        for o in others {
            self.link_complementary(o)?;
        }
        Ok(self.var_sym(j))
    }

    /// Splits an argument into directions and half-period multiples.
    fn split(&self, t: usize, arg: &Val) -> AlgResult<Split> {
        let inner = &self.inner;
        let content = arg.den.integer_content();
        let dp = arg.den.div_integer(&content)?;
        let dp_terms = terms(&dp);
        let (kv, kpv, iv) = {
            let st = self.state();
            (
                st.tables[t].k_var.map(|j| inner.kvar(j)),
                st.tables[t].kp_var.map(|j| inner.kvar(j)),
                st.i_root.map(|i| inner.root_var(i)),
            )
        };
        let unit = |idx: Option<usize>, e: &[u64]| {
            idx.is_some_and(|i| e[i] == 1 && e.iter().enumerate().all(|(j, &x)| j == i || x == 0))
        };
        let is_ikp = |e: &[u64]| match (kpv, iv) {
            (Some(a), Some(b)) => {
                e[a] == 1
                    && e[b] == 1
                    && e.iter()
                        .enumerate()
                        .all(|(j, &x)| j == a || j == b || x == 0)
            }
            _ => false,
        };
        let mut pairs: Vec<(Vec<u64>, Rational)> = Vec::new();
        let (mut hk, mut hkp) = (Rational::new(), Rational::new());
        arg.num.for_each_term(|c, e| {
            let q = Rational::from((c.clone(), content.clone()));
            if dp.is_one() && unit(kv, e) {
                hk += q * 2u32;
            } else if dp.is_one() && is_ikp(e) {
                hkp += q * 2u32;
            } else {
                pairs.push((e.to_vec(), q));
            }
        });
        let to_int = |q: &Rational, what: &str| {
            if *q.denom() == 1 {
                q.numer()
                    .to_i64()
                    .ok_or_else(|| AlgebraError::Domain(format!("{what}: multiple too large")))
            } else {
                Err(AlgebraError::Domain(format!(
                    "{what}: only multiples of a half period are supported"
                )))
            }
        };
        let (half_k, third_k) = halves_and_thirds(&hk, &to_int)?;
        let half_kp = to_int(&hkp, "iK'")?;
        let mut st = self.state();
        let table = &mut st.tables[t];
        let mut vec = Vec::new();
        for (e, q) in pairs {
            let ctx = &inner.ctx;
            let key: DirKey = (e.clone(), dp_terms.clone());
            let i = table.dir_index(key, || {
                let one = Integer::from(1);
                let m = Poly::from_terms(ctx, [(&one, e.as_slice())]);
                Val {
                    num: m,
                    den: dp.clone(),
                    sh: Shadow::leaf(Vec::new()),
                }
            });
            pad(&mut vec, i + 1);
            vec[i] += q;
        }
        Ok(Split {
            vec,
            half_k,
            half_kp,
            third_k,
        })
    }

    /// The value of direction `i` of table `t` (with its shadow).
    fn dir_val(&self, t: usize, i: usize) -> Val {
        let v = self.state().tables[t].dirs[i].1.clone();
        let sh = self.shadow_of(&v.num, &v.den);
        Val { sh, ..v }
    }

    /// Integer coefficients of `vec` over the bases, activating pending hints and
    /// adding a base when `vec` is outside their span.
    fn coordinates(&self, t: usize, vec: &[Rational]) -> AlgResult<Vec<i64>> {
        self.activate_hints(t)?;
        self.prescribed_directions_first(t, vec)?;
        let bases: Vec<Vec<Rational>> = self.state().tables[t]
            .bases
            .iter()
            .map(|b| b.vec.clone())
            .collect();
        let mut x = solve(&bases, vec);
        if x.as_ref()
            .is_some_and(|x| x.iter().any(|q| *q.denom() != 1))
        {
            // finish this evaluation with a provisional base, then restart refined
            self.state().rebase_wanted = true;
            x = None;
        }
        let x = match x {
            Some(x) => x,
            None => {
                self.new_base(t, vec.to_vec())?;
                let n = self.state().tables[t].bases.len();
                let mut x = vec![Rational::new(); n];
                x[n - 1] = Rational::from(1);
                x
            }
        };
        x.iter()
            .map(|q| {
                q.numer()
                    .to_i64()
                    .ok_or_else(|| AlgebraError::Domain("argument multiple too large".into()))
            })
            .collect()
    }

    /// `val` with every symbol that has an equivalent argument (see
    /// [`Ring::seen_argument_with`]) replaced by it: valid inside sn, cn, dn, which have
    /// the period 4K.  The second value is the product of the signs `σ^q` that sn and cn
    /// take on for symbols equivalent up to a sign (`None` when there are none).
    fn with_equivalents(&self, t: usize, val: &Val) -> AlgResult<(Val, Option<Val>)> {
        type Equivalent = (usize, Val, Option<Val>);
        let eqs: Vec<Equivalent> = self
            .state()
            .prescribed
            .iter()
            .filter_map(|p| p.equiv.clone().map(|e| (p.var, e, p.equiv_sign.clone())))
            .collect();
        if eqs.is_empty() {
            return Ok((val.clone(), None));
        }
        let inner = &self.inner;
        let split = self.split(t, val)?;
        let mut out = val.clone();
        let mut factor: Option<Val> = None;
        for (var, e, sign) in eqs {
            let vs = self.var_sym(var).val;
            for (i, q) in split.vec.iter().enumerate() {
                if *q != 0 && inner.v_add(&self.dir_val(t, i), &vs, true)?.num.is_zero() {
                    let shift = inner.v_mul(&inner.const_val(q), &inner.v_add(&e, &vs, true)?)?;
                    out = inner.v_add(&out, &shift, false)?;
                    let Some(sigma) = &sign else { continue };
                    if !q.is_integer() {
                        return Err(AlgebraError::NotAlgebraic(
                            "a fractional multiple of a symbol equal to an argument up to a sign symbol".into(),
                        ));
                    }
                    if q.numer().is_odd() {
                        factor = Some(match factor {
                            Some(f) => inner.v_mul(&f, sigma)?,
                            None => sigma.clone(),
                        });
                    }
                }
            }
        }
        Ok((out, factor))
    }

    /// An argument already seen at modulus `k` whose sn, cn, dn are `s`, `c`, `d` (or
    /// that argument plus 2K, where sn and cn change sign), if there is one.
    pub(crate) fn seen_argument_with(
        &self,
        k: &Sym,
        s: &Sym,
        c: &Sym,
        d: &Sym,
    ) -> AlgResult<Option<(Sym, Option<Sym>)>> {
        let t = self.table_of(k)?;
        let mut seen: Vec<Vec<Rational>> = Vec::new();
        for v in self.state().tables[t].seen.iter().rev() {
            if !v.iter().all(|q| *q == 0) && !seen.contains(v) {
                seen.push(v.clone());
            }
            if seen.len() >= 32 {
                break;
            }
        }
        let signs = self.sign_products()?;
        let inner = &self.inner;
        for vec in seen {
            let mut arg = inner.const_val(&Rational::new());
            for (i, q) in vec.iter().enumerate() {
                if *q != 0 {
                    let term = inner.v_mul(&inner.const_val(q), &self.dir_val(t, i))?;
                    arg = inner.v_add(&arg, &term, false)?;
                }
            }
            let u = Sym::from_val(self, arg, None);
            let (su, cu, du) = u.sncndn(k)?;
            if !d.try_sub(&du)?.is_exact_zero() {
                continue;
            }
            if s.try_sub(&su)?.is_exact_zero() && c.try_sub(&cu)?.is_exact_zero() {
                return Ok(Some((u, None)));
            }
            if s.try_add(&su)?.is_exact_zero() && c.try_add(&cu)?.is_exact_zero() {
                let two_k = self.quarter_period(k)?.try_mul(&self.integer(2))?;
                return Ok(Some((u.try_add(&two_k)?, None)));
            }
            for sigma in &signs {
                let (ss, cs) = (su.try_mul(sigma)?, cu.try_mul(sigma)?);
                if s.try_sub(&ss)?.is_exact_zero() && c.try_sub(&cs)?.is_exact_zero() {
                    return Ok(Some((u, Some(sigma.clone()))));
                }
            }
        }
        Ok(None)
    }

    /// The table of modulus `k`, and `u` as a combination of its bases with half-period
    /// multiples (for certificates).
    pub(crate) fn combination(&self, k: &Val, u: &Val) -> AlgResult<Combination> {
        let t = self.table_of(&Sym::from_val(self, k.clone(), None))?;
        let split = self.split(t, u)?;
        if split.third_k != 0 {
            return Err(AlgebraError::NotAlgebraic(
                "a shift by a third of K in a certificate".into(),
            ));
        }
        let n = self.coordinates(t, &split.vec)?;
        let combo = n
            .iter()
            .enumerate()
            .filter(|(_, m)| **m != 0)
            .map(|(j, m)| (j, *m))
            .collect();
        Ok((t, combo, split.half_k, split.half_kp))
    }

    /// Records that the prescribed symbol `v` equals `u` modulo 4K.
    pub(crate) fn set_equivalent(&self, v: &Sym, u: &Sym, sign: Option<&Sym>) {
        if let Some(var) = v.as_field_var() {
            for p in self.state().prescribed.iter_mut().filter(|p| p.var == var) {
                p.equiv = Some((*u.val).clone());
                p.equiv_sign = sign.map(|s| (*s.val).clone());
            }
        }
    }

    /// Makes every direction of `vec` that is a symbol with prescribed sn, cn, dn a base
    /// by itself (so that `sn(v − w)` is expanded from the values of `v` and `w`, not
    /// given a symbol of its own).
    fn prescribed_directions_first(&self, t: usize, vec: &[Rational]) -> AlgResult<()> {
        let prescribed: Vec<usize> = self.state().prescribed.iter().map(|p| p.var).collect();
        if prescribed.is_empty() {
            return Ok(());
        }
        for (i, q) in vec.iter().enumerate() {
            if *q == 0 {
                continue;
            }
            let d = self.dir_val(t, i);
            let mut is_prescribed = false;
            for &j in &prescribed {
                is_prescribed |= self
                    .inner
                    .v_add(&d, &self.var_sym(j).val, true)?
                    .num
                    .is_zero();
            }
            if !is_prescribed {
                continue;
            }
            let mut unit = vec![Rational::new(); i + 1];
            unit[i] = Rational::from(1);
            let bases: Vec<Vec<Rational>> = self.state().tables[t]
                .bases
                .iter()
                .map(|b| b.vec.clone())
                .collect();
            if solve(&bases, &unit).is_none() {
                self.new_base(t, unit)?;
            }
        }
        Ok(())
    }

    /// The refined bases for a restart: per table, a basis of the lattice of every
    /// argument seen (see [`super::lattice`]).
    pub(crate) fn rebase_hints(&self) -> Vec<BaseHint> {
        let st = self.state();
        let mut hints = Vec::new();
        for t in &st.tables {
            let n = t.dirs.len();
            let mut rows: Vec<Vec<Rational>> = t.seen.clone();
            for r in rows.iter_mut() {
                pad(r, n);
            }
            let basis = lattice_basis(&rows);
            let bases = basis
                .iter()
                .map(|row| {
                    row.iter()
                        .enumerate()
                        .filter(|(_, v)| **v != 0)
                        .map(|(i, v)| (t.dirs[i].0.clone(), v.clone()))
                        .collect()
                })
                .collect();
            hints.push(BaseHint {
                modulus: (terms(&t.k.num), terms(&t.k.den)),
                bases,
            });
        }
        hints
    }

    /// On a first attempt, whose bases are the arguments as they came: when an
    /// argument needs a multiple of a base (`|nⱼ| ≥ 2`, an expansion whose degree grows
    /// like `nⱼ²`) and a basis of the arguments seen so far writes them all at a lower
    /// [`cost`], the attempt stops here and asks for a restart on that basis (what
    /// [`Ring::rebase_hints`] gives), rather than expanding formulas it would then
    /// throw away.  With hinted bases it never stops (the hints are such a basis).
    fn better_bases_first(&self, t: usize, n: &[i64]) -> AlgResult<()> {
        if !self.options().base_hints.is_empty() || n.iter().all(|x| x.abs() < 2) {
            return Ok(());
        }
        let (seen, current) = {
            let st = self.state();
            let width = st.tables[t].dirs.len();
            let padded = |v: &Vec<Rational>| {
                let mut v = v.clone();
                pad(&mut v, width);
                v
            };
            let seen: Vec<Vec<Rational>> = st.tables[t].seen.iter().map(padded).collect();
            let current: Vec<Vec<Rational>> =
                st.tables[t].bases.iter().map(|b| padded(&b.vec)).collect();
            (seen, current)
        };
        let better = cost(&lattice_basis(&seen), &seen);
        let now = cost(&current, &seen);
        if better.is_some_and(|b| now.is_none_or(|c| b < c)) {
            self.state().rebase_wanted = true;
            return Err(AlgebraError::CannotDecide(
                "the arguments seen are written more simply over other bases: restart on them"
                    .into(),
            ));
        }
        Ok(())
    }

    /// Turns pending hinted bases into bases once every symbol they use exists.
    fn activate_hints(&self, t: usize) -> AlgResult<()> {
        let pending = std::mem::take(&mut self.state().tables[t].pending);
        let mut left = Vec::new();
        for hint in pending {
            let ready = {
                let st = self.state();
                let nv = st.vars.len();
                let nr = st.roots.len();
                let inner = &self.inner;
                hint.iter().all(|((e, d), _)| {
                    let ok = |ex: &[u64]| {
                        ex.iter().enumerate().all(|(i, &x)| {
                            x == 0
                                || match inner.root_of_var(i) {
                                    Some(r) => r < nr,
                                    None => i - inner.opts.max_roots < nv,
                                }
                        })
                    };
                    ok(e) && d.iter().all(|(_, de)| ok(de))
                })
            };
            if !ready {
                left.push(hint);
                continue;
            }
            let mut vec = Vec::new();
            for ((e, d), q) in &hint {
                let ctx = self.inner.ctx.clone();
                let den = Poly::from_terms(&ctx, d.iter().map(|(c, x)| (c, x.as_slice())));
                let one = Integer::from(1);
                let m = Poly::from_terms(&ctx, [(&one, e.as_slice())]);
                let key = (e.clone(), d.clone());
                let mut st = self.state();
                let i = st.tables[t].dir_index(key, || Val {
                    num: m,
                    den,
                    sh: Shadow::leaf(Vec::new()),
                });
                pad(&mut vec, i + 1);
                vec[i] += q;
            }
            self.new_base(t, vec)?;
        }
        self.state().tables[t].pending = left;
        Ok(())
    }

    /// Adds a base argument with its symbols `s`, `c`, `d`.
    fn new_base(&self, t: usize, mut vec: Vec<Rational>) -> AlgResult<()> {
        let inner = &self.inner;
        let ndirs = self.state().tables[t].dirs.len();
        pad(&mut vec, ndirs);
        let mut arg = inner.const_val(&Rational::new());
        for (i, q) in vec.iter().enumerate() {
            if *q != 0 {
                let term = inner.v_mul(&inner.const_val(q), &self.dir_val(t, i))?;
                arg = inner.v_add(&arg, &term, false)?;
            }
        }
        let k = self.state().tables[t].k.clone();
        if self.prescribed_base(t, vec.clone(), &arg, &k)? {
            return Ok(());
        }
        let (sv, cv, dv) = self.numeric_sncndn(&arg.sh, &k.sh)?;
        let nb: usize = self
            .state()
            .tables
            .iter()
            .map(|tb| tb.bases.len())
            .sum::<usize>()
            + 1;
        let argtext = Sym::from_val(self, arg.clone(), None).render_short(60);
        let base = self.state().tables[t].bases.len();
        let j = inner.add_var(format!("sn_{nb}"), VarKind::Sn { table: t, base }, sv)?;
        let s = self.var_sym(j);
        let one = self.integer(1);
        let k2 = Sym::from_val(self, self.state().tables[t].k2.clone(), None);
        let c = self.with_origin(Origin::Definition("cn".into()), || {
            one.try_sub(&s.try_mul(&s)?)?.sqrt_with(Some(Prescribed {
                values: &cv,
                name: &format!("cn_{nb}"),
                note: &format!("cn({argtext})"),
            }))
        })?;
        let d = self.with_origin(Origin::Definition("dn".into()), || {
            one.try_sub(&k2.try_mul(&s)?.try_mul(&s)?)?
                .sqrt_with(Some(Prescribed {
                    values: &dv,
                    name: &format!("dn_{nb}"),
                    note: &format!("dn({argtext})"),
                }))
        })?;
        self.note(format!("sn_{nb} = sn({argtext})"));
        let real = self.note_dn_positive((t, base), &arg, &d.val, &argtext);
        let mut st = self.state();
        if real {
            for r in st.roots.iter_mut() {
                if r.name == format!("cn_{nb}") || r.name == format!("dn_{nb}") {
                    r.real = true;
                }
            }
        }
        st.tables[t].bases.push(Base {
            vec,
            arg,
            s: (*s.val).clone(),
            s_name: format!("sn_{nb}"),
            c: c.into_val(),
            d: d.into_val(),
            z_var: None,
            real,
        });
        Ok(())
    }

    /// Declares that the symbol `v` (a field variable, such as an opaque `F(asin x, k)`)
    /// has `sn v = s`, `cn v = c`, `dn v = d` at modulus `k`: a base argument `±v` of
    /// that modulus then takes these values instead of new symbols.
    pub fn prescribe_sncndn(
        &self,
        v: &Sym,
        k: &Sym,
        s: &Sym,
        c: &Sym,
        d: &Sym,
        why: &str,
    ) -> AlgResult<()> {
        let var = v
            .as_field_var()
            .ok_or_else(|| AlgebraError::Internal("prescribed sn of a non-symbol".into()))?;
        let what = v.render_short(40);
        self.state().prescribed.push(Prescription {
            var,
            k: (*k.val).clone(),
            s: (*s.val).clone(),
            c: (*c.val).clone(),
            d: (*d.val).clone(),
            what,
            why: why.to_string(),
            equiv: None,
            equiv_sign: None,
            nodes: match (&s.node, &c.node, &d.node) {
                (Some(a), Some(b), Some(e)) => Some([a.clone(), b.clone(), e.clone()]),
                _ => None,
            },
        });
        Ok(())
    }

    /// A base argument `±v` whose sn, cn, dn are prescribed (see
    /// [`Ring::prescribe_sncndn`]) at this table's modulus: added with those values
    /// instead of new symbols.
    fn prescribed_base(&self, t: usize, vec: Vec<Rational>, arg: &Val, k: &Val) -> AlgResult<bool> {
        let inner = &self.inner;
        let prescribed = self.state().prescribed.clone();
        let found = {
            prescribed.iter().find_map(|p| {
                let v = self.var_sym(p.var).val;
                let same_k = inner.v_add(k, &p.k, true).ok()?.num.is_zero();
                let plus = inner.v_add(arg, &v, true).ok()?.num.is_zero();
                let minus = inner.v_add(arg, &v, false).ok()?.num.is_zero();
                (same_k && (plus || minus)).then(|| (p.clone(), if plus { 1 } else { -1 }))
            })
        };
        let Some((p, sign)) = found else {
            return Ok(false);
        };
        let s = if sign > 0 {
            p.s.clone()
        } else {
            inner.v_neg(&p.s)
        };
        let name = format!("sn({})", p.what);
        self.note(format!(
            "{} is a base argument with sn, cn, dn given by its definition: {}",
            if sign > 0 {
                p.what.clone()
            } else {
                format!("-{}", p.what)
            },
            p.why
        ));
        let mut st = self.state();
        st.tables[t].bases.push(Base {
            vec,
            arg: arg.clone(),
            s,
            s_name: name,
            c: p.c,
            d: p.d,
            z_var: None,
            real: false,
        });
        Ok(true)
    }

    /// sn, cn, dn at every point of an argument and modulus shadow.
    pub(crate) fn numeric_sncndn(
        &self,
        u: &Shadow,
        k: &Shadow,
    ) -> AlgResult<(Vec<Complex>, Vec<Complex>, Vec<Complex>)> {
        let prec = self.precision();
        let (mut s, mut c, mut d) = (Vec::new(), Vec::new(), Vec::new());
        for p in 0..self.points() {
            let kr = Float::with_val(prec, k.v[p].real());
            let err = |e: crate::special::SpecialError| {
                AlgebraError::Pole(format!("numeric sn, cn, dn: {e}"))
            };
            if u.is_real_at(p, prec) {
                let ur = Float::with_val(prec, u.v[p].real());
                let (a, b, e) = sncndn(&ur, &kr).map_err(err)?;
                s.push(Complex::with_val(prec, (a, 0)));
                c.push(Complex::with_val(prec, (b, 0)));
                d.push(Complex::with_val(prec, (e, 0)));
            } else {
                let (a, b, e) = sncndn_complex(&u.v[p], &kr).map_err(err)?;
                s.push(a);
                c.push(b);
                d.push(e);
            }
        }
        Ok((s, c, d))
    }
}

/// `h·K/2` (with `h` in halves of K, from an argument's split) as `a·K/2 + b·K/3` with
/// `b` in 0..3: `h = m/3` with `m = 3a + 2b`; an error unless `3h` is an integer.
fn halves_and_thirds(
    h: &Rational,
    to_int: &dyn Fn(&Rational, &str) -> AlgResult<i64>,
) -> AlgResult<(i64, i64)> {
    if *h.denom() == 1 {
        return Ok((to_int(h, "K")?, 0));
    }
    let m = to_int(&(h.clone() * 3u32), "K (a multiple of K/6)")?;
    let b = (2 * m).rem_euclid(3);
    Ok(((m - 2 * b) / 3, b))
}

/// Notes one expansion (see [`instance_note`]); a shift by a third of K leaves the proof
/// without a certificate (the format records multiples of K/2 and iK'/2 only).
fn note_expansion(ring: &Ring, t: usize, combo: &[(usize, i64)], split: &Split, arg: &Sym) {
    let shifts = (split.half_k, split.half_kp, split.third_k);
    ring.note(instance_note(ring, t, combo, shifts, arg));
    if split.third_k != 0 {
        ring.mark_uncertified("a shift by a third of K");
    }
}

/// The reader's note for one expansion: which bases, shifts and half periods.
fn instance_note(
    ring: &Ring,
    t: usize,
    combo: &[(usize, i64)],
    (hk, hkp, tk): (i64, i64, i64),
    arg: &Sym,
) -> String {
    let st = ring.state();
    let bases: Vec<String> = combo
        .iter()
        .map(|(j, m)| format!("{m}*{}", st.tables[t].bases[*j].s_name.replace("sn_", "b_")))
        .collect();
    let mut used = vec!["DLMF 22.8.1-3"];
    if hk / 2 != 0 || hkp / 2 != 0 {
        used.push("22.4.3");
    }
    if hk % 2 != 0 || hkp % 2 != 0 {
        used.push("22.5.1");
    }
    let third = if tk != 0 {
        used.push("sn(K/3) by triplication");
        format!(" + {tk}*K/3")
    } else {
        String::new()
    };
    drop(st);
    format!(
        "sn, cn, dn({}) with argument {} + {hk}*K/2 + {hkp}*iK'/2{third} by {}",
        arg.render_short(60),
        if bases.is_empty() {
            "0".to_string()
        } else {
            bases.join(" + ")
        },
        used.join(", ")
    )
}

impl Sym {
    /// `(sn, cn, dn)` of this argument with modulus `k`, expanded exactly by the
    /// addition theorems over the ring's base arguments (see the module doc).
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
    /// let u = ring.indeterminate_f64("u", &[0.3, 0.7]).unwrap();
    /// let v = ring.indeterminate_f64("v", &[0.2, -0.4]).unwrap();
    /// let k = ring.indeterminate_f64("k", &[0.5, 0.8]).unwrap();
    /// let (s, c, d) = u.sncndn(&k).unwrap();
    /// let (s2, _, _) = (u.clone() + u.clone()).sncndn(&k).unwrap();
    /// // sn 2u = 2 s c d / (1 − k² s⁴)
    /// let two = ring.integer(2);
    /// let one = ring.integer(1);
    /// let rhs = two * s.clone() * c * d / (one - k.clone() * k * s.clone() * s.clone() * s.clone() * s);
    /// assert!(ring.prove(&s2, &rhs).is_proved());
    /// # let _ = v;
    /// ```
    pub fn sncndn(&self, k: &Sym) -> AlgResult<(Sym, Sym, Sym)> {
        let ring = &self.ring;
        if !self.ring.same(&k.ring) {
            return Err(AlgebraError::RingMismatch);
        }
        if k.is_negative_modulus() {
            // sn, cn, dn depend on k² only (DLMF 22.17.1): an identity of functions, so
            // the points only choose which of the equal forms to expand
            ring.note("sn, cn, dn at the modulus -k are those at k (DLMF 22.17.1)".into());
            return self.sncndn(&k.negate());
        }
        let t = ring.table_of(k)?;
        let (arg, sign) = ring.with_equivalents(t, &self.val)?;
        let split = ring.split(t, &arg)?;
        {
            let mut st = ring.state();
            let v = split.vec.clone();
            st.tables[t].seen.push(v);
        }
        let n = ring.coordinates(t, &split.vec)?;
        ring.better_bases_first(t, &n)?;
        let tr = super::addition::Triples { ring, t };
        let mut v = tr
            .at(&n, split.half_k, split.half_kp, split.third_k)
            .map_err(|e| match e {
                AlgebraError::DivisionByZero => {
                    AlgebraError::Pole(format!("sn, cn, dn at {}", self.render_short(80)))
                }
                e => e,
            })?;
        if let Some(sigma) = &sign {
            // a symbol equal to an argument up to the sign σ: sn, cn carry σ^q
            v[0] = ring.inner.v_mul(&v[0], sigma)?;
            v[1] = ring.inner.v_mul(&v[1], sigma)?;
        }
        let (ns, nc, nd) = ring.numeric_sncndn(&self.val.sh, &k.val.sh)?;
        let prec = ring.precision();
        for (val, num) in v.iter().zip([&ns, &nc, &nd]) {
            if !val.sh.agrees(&Shadow::leaf(num.clone()), prec) {
                return Err(AlgebraError::Internal(format!(
                    "the expansion of sn, cn, dn at {} disagrees with its numeric value",
                    self.render_short(80)
                )));
            }
        }
        let combo: Vec<(usize, i64)> = n
            .iter()
            .enumerate()
            .filter(|(_, m)| **m != 0)
            .map(|(j, m)| (j, *m))
            .collect();
        note_expansion(ring, t, &combo, &split, self);
        let mk = |f: &'static str, val: &Val| {
            let node = self.node.as_ref().map(|a| {
                Node::with_nf(
                    Op::Elliptic {
                        f,
                        table: t,
                        combo: combo.clone(),
                        half_k: split.half_k,
                        half_kp: split.half_kp,
                    },
                    vec![a.clone()],
                    val,
                )
            });
            Sym::from_val(ring, val.clone(), node)
        };
        let [s, c, d] = &v;
        let (s, c, d) = (mk("sn", s), mk("cn", c), mk("dn", d));
        ring.note_dn_of_real_argument(t, &self.val, &d, || self.render_short(60));
        Ok((s, c, d))
    }

    /// Whether this modulus is real and negative at every domain point (then sn, cn,
    /// dn are expanded at its negative, DLMF 22.17.1).
    fn is_negative_modulus(&self) -> bool {
        let prec = self.ring.precision();
        (0..self.ring.points())
            .all(|p| self.val.sh.is_real_at(p, prec) && self.val.sh.v[p].real().is_sign_negative())
            && !self.is_exact_zero()
    }

    /// `sn(self, k)`, see [`Sym::sncndn`].
    pub fn sn(&self, k: &Sym) -> AlgResult<Sym> {
        Ok(self.sncndn(k)?.0)
    }

    /// `cn(self, k)`, see [`Sym::sncndn`].
    pub fn cn(&self, k: &Sym) -> AlgResult<Sym> {
        Ok(self.sncndn(k)?.1)
    }

    /// `dn(self, k)`, see [`Sym::sncndn`].
    pub fn dn(&self, k: &Sym) -> AlgResult<Sym> {
        Ok(self.sncndn(k)?.2)
    }
}
