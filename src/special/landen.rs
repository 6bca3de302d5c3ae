//! The descending Landen (Gauss) chain of moduli and the evaluation of sn, cn, dn of a
//! reduced argument by climbing it (DLMF 22.7.1–3, 22.10.4–6, 19.8.12).

use super::agm::agm;
use super::fourier::{nome, terms, Fourier, Q_IMAG, Q_MAX, Q_MAX_DEEP};
use super::SpecialError;
use crate::numbers::Real;
use rug::Float;

/// The chain `k = k₀ > k₁ > … > k_N` with `k_{n+1} = k_n²/(1+k_n')²`,
/// `k'_{n+1} = 2√k'_n/(1+k'_n)`, `1 − k_{n+1} = 2k'_n/(1+k'_n)`.
pub(crate) struct Chain<R> {
    /// One entry per level n = 1..N: `(k_n, 1 − k_n, 1 + k_n)`, `1 − k_n` computed
    /// without cancellation.
    levels: Vec<[R; 3]>,
    /// `1 / Π (1 + k_n)`, n = 1..N.
    inv_prod: R,
    /// `k_N²/4` and `k_N²/2`.
    k2q: R,
    k2h: R,
    /// One half.
    half: R,
    /// `k²` and `k'²` of the top modulus.
    k2: R,
    kp2: R,
    /// `k'² < ε/8`: the `tanh`/`sech` form applies (fixed precision only).
    tiny_kp: bool,
    /// Fixed precision: the nome series at the bottom (see [`Fourier`]) and
    /// `π/(2K) = AGM(1, k')` of the top modulus, which maps `t` to `v`.
    fourier: Option<(Fourier<R>, R)>,
    /// Fixed precision, `k` near 1: the series of `k'` at imaginary argument and
    /// `π/(2K') = AGM(1, k)` (see [`Chain::imaginary`]).
    imaginary: Option<(Fourier<R>, R)>,
    /// The quarter period `K(k) = (π/2)·Π(1+k_n)·(1 + k_N²/4)`.
    pub kq: R,
}

impl<R: Real> Chain<R> {
    /// Builds the chain for modulus `k` with complementary modulus `kp` (both given,
    /// so that the caller can pass an exactly known pair, e.g. `(k', k)`).
    ///
    /// Multi-precision (`reference = None`): descend until `k_N⁴ < ε/4` and use
    /// DLMF 22.10.4–6 at the bottom.  Fixed precision (`reference` = the same pair at
    /// 192 bits): descend only until the nome is at most [`Q_MAX`] ([`Q_MAX_DEEP`] after two
    /// levels; each step squares
    /// it) and use the nome series ([`Fourier`]) at the bottom, unless `k` is so small
    /// that DLMF 22.10.4–6 needs no level at all.
    pub(crate) fn new(
        k: &R,
        kp: &R,
        reference: Option<(&Float, &Float)>,
    ) -> Result<Self, SpecialError> {
        let one = k.one();
        // stop when k_N^4 < eps/4: the neglected O(k_N^4) terms are below the rounding
        let tol = k.epsilon().mul_2si(-2);
        let small = |x: &R| x.sqr().sqr() <= tol;
        let kp2 = kp.sqr();
        let tiny_kp = kp2 < k.epsilon().mul_2si(-3);
        // no series where DLMF 22.10.4–6 (tiny k) or 22.10.7–9 (tiny k') apply directly
        let reference = reference.filter(|_| !small(k) && !tiny_kp);
        let mut q = match reference {
            Some(_) => nome(k, kp)?.to_f64(),
            None => 0.0,
        };
        if let (Some((rk, rkp)), true) = (reference, q > Q_IMAG) {
            return Self::imaginary(k, kp, (rk, rkp));
        }
        let mut rpair = reference.map(|(a, b)| (a.clone(), b.clone()));
        let mut levels = Vec::new();
        let (mut kc, mut kpc) = (k.clone(), kp.clone());
        let mut prod = one.clone();
        loop {
            let done = match reference {
                Some(_) => q <= if levels.len() >= 2 { Q_MAX_DEEP } else { Q_MAX },
                None => small(&kc),
            };
            if done {
                break;
            }
            if levels.len() >= 64 {
                return Err(SpecialError::NoConvergence(
                    "Landen chain of moduli did not converge in 64 steps".into(),
                ));
            }
            let (k1, kp1, level) = landen_step(&kc, &kpc);
            prod = prod * level[2].clone();
            levels.push(level);
            (kc, kpc) = (k1, kp1);
            q = q * q;
            if let Some((rk, rkp)) = rpair.as_mut() {
                let (a, b, _) = landen_step(rk, rkp);
                (*rk, *rkp) = (a, b);
            }
        }
        let (kq, fourier) = match (reference, rpair) {
            (Some((_, top_kp)), Some((rk, rkp))) => {
                // K = Π(1+k_n)·K(k_N), K(k_N) = π/(2·AGM(1, k_N')) (DLMF 19.8.5)
                let kq = k.pi() / agm(&one, &kpc)?.mul_2si(1) * prod.clone();
                // v = πt/(2K) = t·AGM(1, k'), the value of AGM(1, k') from 192 bits
                let scale = agm(&one, kp)?;
                let exact = agm(&Float::with_val(top_kp.prec(), 1), top_kp)?;
                let scale = scale.clone() + scale.from_f64(exact.to_f64() - scale.to_f64());
                (kq, Some((Fourier::new(&kc, &kpc, (&rk, &rkp))?, scale)))
            }
            _ => (
                k.pi().mul_2si(-1) * prod.clone() * (one.clone() + kc.sqr().mul_2si(-2)),
                None,
            ),
        };
        Ok(Chain {
            levels,
            k2q: kc.sqr().mul_2si(-2),
            k2h: kc.sqr().mul_2si(-1),
            half: one.mul_2si(-1),
            k2: k.sqr(),
            tiny_kp,
            kp2,
            inv_prod: prod.recip(),
            fourier,
            imaginary: None,
            kq,
        })
    }

    /// Fixed precision, `k` near 1 (nome `q > Q_IMAG`): no Landen level; the nome
    /// series of the complementary modulus `k'` (nome `q' = exp(π²/ln q) < 2·10⁻³`) at
    /// imaginary argument ([`Fourier::eval_imaginary`]).  The series variable is
    /// `w = πt/(2K')` with `π/(2K') = AGM(1, k)`, and its terms decrease like
    /// `(q'·4 sinh²w)ⁿ ≤ √q'ⁿ` for `|t| ≤ K/2`, so it is cut after `terms(√q')` terms.
    fn imaginary(k: &R, kp: &R, reference: (&Float, &Float)) -> Result<Self, SpecialError> {
        let one = k.one();
        let (rk, rkp) = reference;
        let qc = nome(kp, k)?.to_f64();
        let series = Fourier::with_terms(kp, k, (rkp, rk), terms(qc.sqrt()))?;
        let scale = agm(&one, k)?;
        let exact = agm(&Float::with_val(rk.prec(), 1), rk)?;
        let scale = scale.clone() + scale.from_f64(exact.to_f64() - scale.to_f64());
        let kp2 = kp.sqr();
        Ok(Chain {
            levels: Vec::new(),
            k2q: k.zero(),
            k2h: k.zero(),
            half: one.mul_2si(-1),
            k2: k.sqr(),
            tiny_kp: false,
            kp2,
            inv_prod: one.clone(),
            fourier: None,
            imaginary: Some((series, scale)),
            // K = π/(2·AGM(1, k')) (DLMF 19.8.5)
            kq: k.pi() / agm(&one, kp)?.mul_2si(1),
        })
    }

    /// Does this chain end in the imaginary-argument series (fixed precision, `k`
    /// near 1)?
    pub(crate) fn has_imaginary(&self) -> bool {
        self.imaginary.is_some()
    }

    /// For `|t| ≤ K/2` on a chain with the imaginary-argument bottom: `(sn t, C, D)`
    /// with `cn t = 1/C`, `dn t = D/C`, from `sn(t,k) = −i sn(it,k')/cn(it,k')`,
    /// `cn(t,k) = 1/cn(it,k')`, `dn(t,k) = dn(it,k')/cn(it,k')` (DLMF Table 22.6.1)
    /// and [`Fourier::ratios_imaginary`] for `k'` at `y = sinh²w`: `C = cn(it,k')`,
    /// `D = dn(it,k')`, `sn t = tanh w·(1 + Δ/Q)`, `C = cosh w·Q`; `tanh`, `cosh` are the library
    /// functions of `w = t·AGM(1,k)` (each within about an ulp, better than forming them
    /// from one `expm1`); `Δ/Q`, `Q`, `D` from [`Fourier::ratios_imaginary`].
    #[inline]
    pub(crate) fn imaginary_eval(&self, t: &R) -> Option<(R, R, R)> {
        let (series, scale) = self.imaginary.as_ref()?;
        let w = t.clone() * scale.clone();
        let (th, ch) = (w.tanh(), w.cosh());
        let sh = th.clone() * ch.clone();
        let (dq, q, d) = series.ratios_imaginary(&sh);
        Some((th.clone() + th * dq, ch * q, d))
    }

    /// `(sn, cn, dn)(t, k)` for a reduced argument `|t| ≲ K/2`, each with relative
    /// accuracy (DLMF 22.10.4–6 at the bottom, 22.7.1–3 upwards).  `fixed` selects the
    /// form for types without guard bits (`f64`): there `1 − dn` is tracked next to `dn`
    /// and every update is written as "value + small correction", so that roundings
    /// scale with the correction (costs a few more operations).  With guard bits the
    /// plain quotients of DLMF 22.7.1–3 are used (fewer multi-precision operations).
    pub(crate) fn eval(&self, t: &R, fixed: bool) -> (R, R, R) {
        let one = t.one();
        if fixed && self.tiny_kp {
            // k' so small that k'⁴ terms are below the rounding (only reachable as the
            // complementary modulus of a tiny k, e.g. the imaginary part for k = 1e-10):
            // DLMF 22.10.7–9 directly, which keeps relative accuracy of the tiny cn, dn
            // that the ~8 near-1 levels of the climb would erode.
            let quarter = self.half.clone() * self.half.clone();
            let (sh, ch) = (t.sinh(), t.cosh());
            let se = ch.recip();
            let th = sh.clone() * se.clone();
            let shch = sh * ch;
            let a = self.kp2.clone() * quarter.clone() * (shch.clone() - t.clone());
            let b = self.kp2.clone() * quarter * (shch + t.clone());
            let s = th.clone() + a.clone() * se.sqr();
            let c = se.clone() - a * th.clone() * se.clone();
            let d = se.clone() + b * th * se;
            return (s, c, d);
        }
        if let (true, Some((sn, c, d))) = (fixed, self.imaginary_eval(t)) {
            // (callers normally use imaginary_eval directly)
            return (sn, c.recip(), d / c);
        }
        if let (true, Some((_, scale))) = (fixed, &self.fourier) {
            // (callers with a series bottom normally use eval_series directly)
            let (sv, cv) = (t.clone() * scale.clone()).sin_cos_kernel();
            if let Some(out) = self.eval_series(&sv, &cv) {
                return out;
            }
        }
        let z = t.clone() * self.inv_prod.clone();
        let (sz, cz) = z.sin_cos_kernel();
        let corr = (z - sz.clone() * cz.clone()) * self.k2q.clone();
        let s = sz.clone() - corr.clone() * cz.clone();
        if fixed {
            let c = cz + corr * sz.clone();
            let e = self.k2h.clone() * sz.sqr();
            let d = one.clone() - e.clone();
            self.climb_fixed(s, c, d, e)
        } else {
            let mut s = s;
            // With guard bits only sn is carried up (DLMF 22.7.1); cn and dn follow at
            // the top from cn = √((1−sn)(1+sn)), dn = √(k'² + k²cn²) (DLMF 22.6.1).
            // For |t| ≤ K/2, cn ≥ √(k'/(1+k')), so at most log2(1/k') bits are lost; the
            // caller adds that many guard bits.
            for [k1, _, opk] in self.levels.iter().rev() {
                s = opk.clone() * s.clone() / (one.clone() + k1.clone() * s.sqr());
            }
            let c = ((one.clone() - s.clone()) * (one + s.clone())).sqrt();
            let d = (self.kp2.clone() + self.k2.clone() * c.sqr()).sqrt();
            (s, c, d)
        }
    }

    /// `π/(2K) = AGM(1, k')` if this chain has the nome series at its bottom (fixed
    /// precision, `k` not tiny): then `v = t·π/(2K)` is the series variable.
    pub(crate) fn series_scale(&self) -> Option<&R> {
        self.fourier.as_ref().map(|(_, scale)| scale)
    }

    /// `(sn, cn, dn)(t)` from `sin v`, `cos v` (`v = πt/(2K)`, any `|v| ≤ π/2`) through
    /// the nome series and the climb; `None` without a series bottom.
    #[inline]
    pub(crate) fn eval_series(&self, sv: &R, cv: &R) -> Option<(R, R, R)> {
        let (series, _) = self.fourier.as_ref()?;
        let (s, c, d, e) = series.eval(sv, cv);
        Some(self.climb_fixed(s, c, d, e))
    }

    /// Climbs the chain in fixed precision from `(sn, cn, dn, 1 − dn)` at the bottom:
    /// every update is written as "value + small correction", so that roundings scale
    /// with the correction, and `1 − dn` is tracked next to `dn`.
    #[inline]
    fn climb_fixed(&self, mut s: R, mut c: R, mut d: R, mut e: R) -> (R, R, R) {
        let one = s.one();
        {
            let half = self.half.clone();
            for [k1, omk, _] in self.levels.iter().rev() {
                let ss = s.sqr();
                let cc = c.sqr();
                let kss = k1.clone() * ss.clone();
                let inv = (one.clone() + kss.clone()).recip();
                // sn = s(1+k₁)/(1+k₁s²) = s + s·k₁c²/(1+k₁s²)
                let s_new = s.clone() + s * k1.clone() * cc.clone() * inv.clone();
                // cn = c·dn/(1+k₁s²) = c − c(e + k₁s²)/(1+k₁s²)
                let c_new = if e < half {
                    c.clone() - c * (e + kss.clone()) * inv.clone()
                } else {
                    c * d * inv.clone()
                };
                // 1 − dn = 2k₁s²/(1+k₁s²); dn = 1 − (1 − dn) while that is above ½,
                // else dn = (c² + (1−k₁)s²)/(1+k₁s²) (relative accuracy for small dn)
                e = (kss.clone() + kss) * inv.clone();
                let d_new = if e < half {
                    one.clone() - e.clone()
                } else {
                    (cc + omk.clone() * ss) * inv
                };
                s = s_new;
                c = c_new;
                d = d_new;
            }
            (s, c, d)
        }
    }
}

/// One descending Landen step (DLMF 19.8.12, 22.7.1–3): `(k, k')` to `(k₁, k₁')` with
/// `k₁ = (k/(1+k'))²`, `k₁' = 2√k'/(1+k')`, and the level entry
/// `(k₁, 1 − k₁ = 2k'/(1+k'), 1 + k₁)`.
fn landen_step<S: Real>(k: &S, kp: &S) -> (S, S, [S; 3]) {
    let one = k.one();
    let inv = (one.clone() + kp.clone()).recip();
    let k1 = (k.clone() * inv.clone()).sqr();
    let inv2 = inv.mul_2si(1);
    let omk1 = kp.clone() * inv2.clone();
    let kp1 = kp.sqrt() * inv2;
    let opk = one + k1.clone();
    (k1.clone(), kp1, [k1, omk1, opk])
}
