//! `sn`, `cn`, `dn` at a third of the quarter period, exactly.
//!
//! `s = sn(K/3)` is algebraic over ℚ(k): with `u = K/3`, `sn 2u = sn(K − u) = cd u`
//! (DLMF 22.4.3) and the double-argument formula (DLMF 22.6.5, from 22.8.1) give
//! `2 s c d² = c (1 − k² s⁴)`, and `c = cn(K/3) > 0` because `0 < K/3 < K`, so
//!
//! ```text
//! P(s) = k² s⁴ − 2 k² s³ + 2 s − 1 = 0.
//! ```
//!
//! The symbol `s` is a field variable with this relation (module `algebraic`): it is
//! adjoined only when `P` is irreducible over ℚ(the other variables), and then every
//! identity the zero test accepts holds at every root of `P`, so that no root needs to
//! be singled out (the value `s ∈ (0, 1)` is the symbol's meaning, never a choice made
//! at domain points).  `cn(K/3)` is a root symbol with `c² = 1 − s²` (defined as that
//! cosine, like `cn` of a base argument), and `dn(K/3)` follows rationally from
//! `cn 2u = cn(K − u) = k' sd u` (DLMF 22.4.3) and DLMF 22.6.6:
//!
//! ```text
//! dn(K/3) = k' s (1 − k² s⁴) / (1 − 2 s² + k² s⁴),
//! ```
//!
//! where the denominator is `cn(2K/3)(1 − k² s⁴) > 0`; its square is checked to be
//! `1 − k² s²` modulo `P`.  Shifts by `2K/3`, `4K/3`, `K/6`, … are integer
//! combinations of `K/3` and `K/2` (module `addition`).

use super::algebraic::pseudo_remainder;
use super::error::{AlgResult, AlgebraError};
use super::flint::Poly;
use super::ring::{Origin, Ring, VarKind};
use super::roots::Prescribed;
use super::shadow::Shadow;
use super::sym::Sym;
use super::val::Val;
use crate::special::{ellipk, sncndn};
use rug::{Complex, Float};
use std::sync::Arc;

impl Ring {
    /// `(sn, cn, dn)(K/3)` of table `t`, with `k'` its complementary modulus (see the
    /// module doc).
    pub(crate) fn third_period_values(&self, t: usize, kp: &Val) -> AlgResult<[Val; 3]> {
        let k2 = self.state().tables[t].k2.clone();
        let has_roots =
            |p: &Poly| (p.used_vars().iter()).any(|&i| self.inner.root_of_var(i).is_some());
        if has_roots(&k2.num) || has_roots(&k2.den) {
            return Err(AlgebraError::NotAlgebraic(
                "sn(K/3) of a modulus whose square has square roots in it".into(),
            ));
        }
        let [sv, cv, dv] = self.third_numeric(t)?;
        let name = self.fresh_name(&format!("snK3_{}", t + 1));
        let j = self
            .inner
            .add_var(name.clone(), VarKind::ThirdK { table: t }, sv)?;
        let var = self.inner.kvar(j);
        let rel = self.triplication_polynomial(&k2, var)?;
        self.state().algebraic.push((var, Arc::new(rel)));
        let s = self.var_sym(j);
        let one = self.integer(1);
        let c = self.with_origin(Origin::Definition("cn".into()), || {
            one.try_sub(&s.try_mul(&s)?)?.sqrt_with(Some(Prescribed {
                values: &cv,
                name: &self.fresh_name(&format!("cnK3_{}", t + 1)),
                note: "cn(K/3)",
            }))
        })?;
        let d = self.third_dn(&k2, kp, &s, &dv)?;
        self.note(format!(
            "{name} = sn(K/3), a root of k^2 s^4 - 2 k^2 s^3 + 2 s - 1 (sn(2K/3) = cd(K/3), DLMF 22.4.3, 22.6.5); dn(K/3) = k' s (1 - k^2 s^4)/(1 - 2 s^2 + k^2 s^4) (cn(2K/3) = k' sd(K/3))"
        ));
        self.mark_uncertified("sn(K/3) as a root of its triplication polynomial");
        Ok([s.into_val(), c.into_val(), d.into_val()])
    }

    /// `sn`, `cn`, `dn` of `K/3` at every domain point.
    fn third_numeric(&self, t: usize) -> AlgResult<[Vec<Complex>; 3]> {
        let prec = self.precision();
        let k = self.state().tables[t].k.sh.clone();
        let mut out: [Vec<Complex>; 3] = Default::default();
        for p in 0..self.points() {
            let kr = Float::with_val(prec, k.v[p].real());
            let err = |e: crate::special::SpecialError| {
                AlgebraError::Domain(format!("sn, cn, dn(K/3): {e}"))
            };
            let u = ellipk(&kr).map_err(err)? / 3u32;
            let (a, b, c) = sncndn(&u, &kr).map_err(err)?;
            for (o, x) in out.iter_mut().zip([a, b, c]) {
                o.push(Complex::with_val(prec, (x, 0)));
            }
        }
        Ok(out)
    }

    /// `k² s⁴ − 2 k² s³ + 2 s − 1` (times the denominator of `k²`) in FLINT variable
    /// `var`, checked irreducible.
    fn triplication_polynomial(&self, k2: &Val, var: usize) -> AlgResult<Poly> {
        let ctx = &self.inner.ctx;
        let s = Poly::var(ctx, var);
        let s3 = s.mul(&s).mul(&s);
        let two = Poly::from_i64(ctx, 2);
        let quartic = s3.mul(&s).sub(&two.mul(&s3));
        let linear = two.mul(&s).sub(&Poly::from_i64(ctx, 1));
        let rel = k2.num.mul(&quartic).add(&k2.den.mul(&linear));
        let f = rel
            .factor()
            .map_err(|e| AlgebraError::Internal(format!("factoring P(sn(K/3)): {e:?}")))?;
        let irreducible = f.factors.len() == 1 && f.factors[0].1 == 1;
        if !irreducible || f.factors[0].0.degree(var) != 4 {
            return Err(AlgebraError::NotAlgebraic(
                "sn(K/3): its triplication polynomial is reducible at this modulus".into(),
            ));
        }
        Ok(rel)
    }

    /// `dn(K/3) = k' s (1 − k² s⁴)/(1 − 2 s² + k² s⁴)`, checked against
    /// `dn² = 1 − k² s²` modulo the triplication polynomial and against the values.
    fn third_dn(&self, k2: &Val, kp: &Val, s: &Sym, values: &[Complex]) -> AlgResult<Sym> {
        let k2 = Sym::from_val(self, k2.clone(), None);
        let kp = Sym::from_val(self, kp.clone(), None);
        let one = self.integer(1);
        let s2 = s.try_mul(s)?;
        let ks4 = k2.try_mul(&s2)?.try_mul(&s2)?;
        let num = kp.try_mul(s)?.try_mul(&one.try_sub(&ks4)?)?;
        let den = one.try_sub(&self.integer(2).try_mul(&s2)?)?.try_add(&ks4)?;
        let d = num.try_div(&den)?;
        let check = d.try_mul(&d)?.try_sub(&one.try_sub(&k2.try_mul(&s2)?)?)?;
        let (var, rel) = self
            .inner
            .algebraic_relations()
            .last()
            .cloned()
            .ok_or_else(|| AlgebraError::Internal("no relation for sn(K/3)".into()))?;
        let prec = self.precision();
        let agrees = d.val.sh.agrees(&Shadow::leaf(values.to_vec()), prec);
        if !pseudo_remainder(&check.val.num, &rel, var).is_zero() || !agrees {
            return Err(AlgebraError::Internal(
                "dn(K/3) from the triplication polynomial does not check".into(),
            ));
        }
        Ok(d)
    }
}

#[cfg(test)]
mod tests {
    use crate::algebra::parametrization::Parametrization;
    use crate::algebra::{RingOptions, prove_identity};
    use rug::Rational;

    /// The domain 0 < k < 1 as k = t/(1 + t), t > 0, so that signs such as k' > 0 are
    /// proved.
    fn opts() -> RingOptions {
        let mut par = Parametrization::new();
        let t = par.positive("t_k").expect("a parameter");
        let one = par.constant(&Rational::from(1));
        let k = t.div(&one.add(&t)).expect("1 + t is not 0");
        par.bind("k", k, "k = t/(1 + t)".into());
        RingOptions {
            positivity: Some(std::sync::Arc::new(par)),
            ..Default::default()
        }
    }

    /// sn(K/3) at k = 0.3, 0.8 and 0.5 (mpmath: `ellipfun('sn', ellipk(m)/3, m=m)`).
    const K_POINTS: [f64; 3] = [0.3, 0.8, 0.5];
    const SN_K3_03: f64 = 0.508_840_602_379_084_5;
    const SN_K3_08: f64 = 0.594_501_694_227_53;

    /// `k² s⁴ − 2 k² s³ + 2 s − 1` at `s = sn(K/3)`, minus `extra`.
    fn triplication(extra: i64) -> crate::algebra::Proof {
        prove_identity(opts(), "sn(K/3)", |r| {
            let k = r.indeterminate_f64("k", &K_POINTS)?;
            let kk = r.quarter_period(&k)?;
            let s = kk.try_div(&r.integer(3))?.sn(&k)?;
            let v0 = s.shadow(0).real().to_f64();
            let v1 = s.shadow(1).real().to_f64();
            assert!((v0 - SN_K3_03).abs() < 1e-14 && (v1 - SN_K3_08).abs() < 1e-14);
            let k2 = k.try_mul(&k)?;
            let s3 = s.try_powi(3)?;
            let lhs = k2.try_mul(&s3)?.try_mul(&s.try_sub(&r.integer(2))?)?;
            let lhs = lhs.try_add(&s.try_mul(&r.integer(2))?)?;
            Ok((lhs, r.integer(1 + extra)))
        })
    }

    #[test]
    fn sn_of_a_third_of_k_is_a_root_of_its_triplication_polynomial() {
        let p = triplication(0);
        assert!(p.is_proved(), "{:?}", p.outcome);
        assert!(!triplication(1).is_proved());
    }

    #[test]
    fn sn_two_thirds_of_k_is_cd_of_a_third() {
        // DLMF 22.4.3: sn(K − u) = cd u, at u = K/3; and sn(K/6) from K/2 − K/3
        let p = prove_identity(opts(), "sn(2K/3)", |r| {
            let k = r.indeterminate_f64("k", &K_POINTS)?;
            let kk = r.quarter_period(&k)?;
            let third = kk.try_div(&r.integer(3))?;
            let (_, c, d) = third.sncndn(&k)?;
            Ok((third.try_mul(&r.integer(2))?.sn(&k)?, c.try_div(&d)?))
        });
        assert!(p.is_proved(), "{:?}", p.outcome);
        let wrong = prove_identity(opts(), "sn(2K/3) wrong", |r| {
            let k = r.indeterminate_f64("k", &K_POINTS)?;
            let kk = r.quarter_period(&k)?;
            let third = kk.try_div(&r.integer(3))?;
            let (_, c, _) = third.sncndn(&k)?;
            Ok((third.try_mul(&r.integer(2))?.sn(&k)?, c))
        });
        assert!(!wrong.is_proved());
    }
}
