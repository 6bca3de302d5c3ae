//! The triple `(sn, cn, dn)` as exact values: the addition theorems (DLMF 22.8.1–3),
//! multiples by doubling, the quarter-period shifts (DLMF 22.4.3, poles as the
//! reciprocal forms), the half-period values (DLMF 22.5.1) and the values at `K/3`
//! (module `thirds`), for one modulus table.

use super::error::AlgResult;
use super::ring::{Origin, Ring};
use super::sym::Sym;
use super::val::Val;
use rug::Rational;

/// The triple arithmetic of DLMF 22.8 and 22.4.3 on values.
pub(crate) struct Triples<'a> {
    pub ring: &'a Ring,
    pub t: usize,
}

impl Triples<'_> {
    fn k2(&self) -> Val {
        self.ring.state().tables[self.t].k2.clone()
    }

    /// DLMF 22.8.1–3.
    fn add(&self, a: &[Val; 3], b: &[Val; 3]) -> AlgResult<[Val; 3]> {
        let i = &self.ring.inner;
        let k2 = self.k2();
        let [s1, c1, d1] = a;
        let [s2, c2, d2] = b;
        let s1s2 = i.v_mul(s1, s2)?;
        let den = i.v_add(
            &i.const_val(&Rational::from(1)),
            &i.v_mul(&k2, &i.v_mul(&s1s2, &s1s2)?)?,
            true,
        )?;
        let sn_n = i.v_add(
            &i.v_mul(s1, &i.v_mul(c2, d2)?)?,
            &i.v_mul(s2, &i.v_mul(c1, d1)?)?,
            false,
        )?;
        let cn_n = i.v_add(&i.v_mul(c1, c2)?, &i.v_mul(&s1s2, &i.v_mul(d1, d2)?)?, true)?;
        let dn_n = i.v_add(
            &i.v_mul(d1, d2)?,
            &i.v_mul(&k2, &i.v_mul(&s1s2, &i.v_mul(c1, c2)?)?)?,
            true,
        )?;
        Ok([
            i.v_div(&sn_n, &den)?,
            i.v_div(&cn_n, &den)?,
            i.v_div(&dn_n, &den)?,
        ])
    }

    fn neg(&self, a: &[Val; 3]) -> [Val; 3] {
        [self.ring.inner.v_neg(&a[0]), a[1].clone(), a[2].clone()]
    }

    fn base(&self, j: usize) -> [Val; 3] {
        let st = self.ring.state();
        let b = &st.tables[self.t].bases[j];
        [b.s.clone(), b.c.clone(), b.d.clone()]
    }

    /// `n·bⱼ` by doubling.
    fn multiple(&self, j: usize, n: i64, nb: usize) -> AlgResult<[Val; 3]> {
        let mut key = vec![0i64; nb];
        key[j] = n;
        if let Some(v) = self.ring.state().tables[self.t].triples.get(&key) {
            return Ok(v.clone());
        }
        let v = if n < 0 {
            self.neg(&self.multiple(j, -n, nb)?)
        } else if n == 1 {
            self.base(j)
        } else if n % 2 == 0 {
            let h = self.multiple(j, n / 2, nb)?;
            self.add(&h, &h)?
        } else {
            self.add(&self.multiple(j, n - 1, nb)?, &self.base(j))?
        };
        self.ring.state().tables[self.t]
            .triples
            .insert(key, v.clone());
        Ok(v)
    }

    /// `Σ nⱼ bⱼ`.
    fn combination(&self, n: &[i64]) -> AlgResult<[Val; 3]> {
        let i = &self.ring.inner;
        let mut acc = [
            i.const_val(&Rational::new()),
            i.const_val(&Rational::from(1)),
            i.const_val(&Rational::from(1)),
        ];
        let mut first = true;
        for (j, &m) in n.iter().enumerate() {
            if m != 0 {
                let t = self.multiple(j, m, n.len())?;
                acc = if first { t } else { self.add(&acc, &t)? };
                first = false;
            }
        }
        Ok(acc)
    }

    fn kp(&self) -> AlgResult<Val> {
        if let Some(v) = self.ring.state().tables[self.t].kp.clone() {
            return Ok(v);
        }
        let r = self.ring;
        let k2 = Sym::from_val(r, self.k2(), None);
        let kp = r.with_origin(Origin::Definition("k' = sqrt(1 - k^2) > 0".into()), || {
            r.integer(1).try_sub(&k2)?.sqrt()
        })?;
        r.state().tables[self.t].kp = Some((*kp.val).clone());
        Ok(kp.into_val())
    }

    /// DLMF 22.4.3: `z ↦ z + K`.
    fn shift_k(&self, a: &[Val; 3]) -> AlgResult<[Val; 3]> {
        let i = &self.ring.inner;
        let kp = self.kp()?;
        let [s, c, d] = a;
        Ok([
            i.v_div(c, d)?,
            i.v_neg(&i.v_div(&i.v_mul(&kp, s)?, d)?),
            i.v_div(&kp, d)?,
        ])
    }

    /// DLMF 22.4.3: `z ↦ z + iK'` (`sn = 1/(k s)`, `cn = −i d/(k s)`, `dn = −i c/s`).
    fn shift_ikp(&self, a: &[Val; 3]) -> AlgResult<[Val; 3]> {
        let i = &self.ring.inner;
        let k = self.ring.state().tables[self.t].k.clone();
        let iu = self.ring.i()?.val;
        let [s, c, d] = a;
        let ks = i.v_mul(&k, s)?;
        let one = i.const_val(&Rational::from(1));
        let sn = i.v_div(&one, &ks)?;
        let cn = i.v_neg(&i.v_div(&i.v_mul(&iu, d)?, &ks)?);
        let dn = i.v_neg(&i.v_div(&i.v_mul(&iu, c)?, s)?);
        Ok([sn, cn, dn])
    }

    /// DLMF 22.5.1 at `K/2` (`prime = false`) or `iK'/2`.
    fn half(&self, prime: bool) -> AlgResult<[Val; 3]> {
        let cached = {
            let st = self.ring.state();
            let t = &st.tables[self.t];
            if prime {
                t.half_kp.clone()
            } else {
                t.half_k.clone()
            }
        };
        if let Some(v) = cached {
            return Ok(v);
        }
        let r = self.ring;
        let one = r.integer(1);
        let v = r.with_origin(
            Origin::Definition("DLMF 22.5.1".into()),
            || -> AlgResult<[Val; 3]> {
                if prime {
                    let k = Sym::from_val(r, r.state().tables[self.t].k.clone(), None);
                    let rk = k.sqrt()?;
                    let r1k = one.try_add(&k)?.sqrt()?;
                    Ok([
                        r.i()?.try_div(&rk)?.into_val(),
                        r1k.try_div(&rk)?.into_val(),
                        r1k.into_val(),
                    ])
                } else {
                    let kp = Sym::from_val(r, self.kp()?, None);
                    let rkp = kp.sqrt()?;
                    let r1 = one.try_add(&kp)?.sqrt()?;
                    Ok([
                        one.try_div(&r1)?.into_val(),
                        rkp.try_div(&r1)?.into_val(),
                        rkp.into_val(),
                    ])
                }
            },
        )?;
        let mut st = r.state();
        if prime {
            st.tables[self.t].half_kp = Some(v.clone());
        } else {
            st.tables[self.t].half_k = Some(v.clone());
        }
        Ok(v)
    }

    /// `(sn, cn, dn)(K/3)` (module `thirds`).
    fn third(&self) -> AlgResult<[Val; 3]> {
        if let Some(v) = self.ring.state().tables[self.t].third_k.clone() {
            return Ok(v);
        }
        let v = self.ring.third_period_values(self.t, &self.kp()?)?;
        self.ring.state().tables[self.t].third_k = Some(v.clone());
        Ok(v)
    }

    /// The triple at `Σ nⱼ bⱼ + p·K/2 + q·iK'/2 + r·K/3`.
    pub fn at(&self, n: &[i64], p: i64, q: i64, r: i64) -> AlgResult<[Val; 3]> {
        let mut v = self.combination(n)?;
        for _ in 0..r.rem_euclid(12) {
            v = self.add(&v, &self.third()?)?;
        }
        if p.rem_euclid(2) == 1 {
            v = self.add(&v, &self.half(false)?)?;
        }
        for _ in 0..p.div_euclid(2).rem_euclid(4) {
            v = self.shift_k(&v)?;
        }
        if q.rem_euclid(2) == 1 {
            v = self.add(&v, &self.half(true)?)?;
        }
        for _ in 0..q.div_euclid(2).rem_euclid(4) {
            v = self.shift_ikp(&v)?;
        }
        Ok(v)
    }
}
