//! The descending Landen (Gauss) chain of moduli and the evaluation of sn, cn, dn of a
//! reduced argument by climbing it (DLMF 22.7.1–3, 22.10.4–6, 19.8.12).

use super::SpecialError;
use crate::numbers::Real;

/// The chain `k = k₀ > k₁ > … > k_N` with `k_{n+1} = k_n²/(1+k_n')²`,
/// `k'_{n+1} = 2√k'_n/(1+k'_n)`, `1 − k_{n+1} = 2k'_n/(1+k'_n)`.
pub(crate) struct Chain<R> {
    /// `k_1 … k_N`.
    ks: Vec<R>,
    /// `1 − k_1 … 1 − k_N`, computed without cancellation.
    omks: Vec<R>,
    /// `1 / Π (1 + k_n)`, n = 1..N.
    inv_prod: R,
    /// `1 + k_1 … 1 + k_N`.
    opks: Vec<R>,
    /// `k_N²/4` and `k_N²/2`.
    k2q: R,
    k2h: R,
    /// One half.
    half: R,
    /// `k²` and `k'²` of the top modulus.
    k2: R,
    kp2: R,
    /// The quarter period `K(k) = (π/2)·Π(1+k_n)·(1 + k_N²/4)`.
    pub kq: R,
}

impl<R: Real> Chain<R> {
    /// Builds the chain for modulus `k` with complementary modulus `kp` (both given,
    /// so that the caller can pass an exactly known pair, e.g. `(k', k)`).
    pub(crate) fn new(k: &R, kp: &R) -> Result<Self, SpecialError> {
        let one = k.one();
        let two = k.from_i64(2);
        // stop when k_N^4 < eps/64: the neglected O(k_N^4) terms are below the rounding
        let tol = k.epsilon().mul_2si(-2);
        let mut ks = Vec::new();
        let mut omks = Vec::new();
        let mut opks = Vec::new();
        let (mut kc, mut kpc) = (k.clone(), kp.clone());
        let mut prod = one.clone();
        while kc.sqr().sqr() > tol {
            if ks.len() >= 64 {
                return Err(SpecialError::NoConvergence(
                    "Landen chain of moduli did not converge in 64 steps".into(),
                ));
            }
            let inv = (one.clone() + kpc.clone()).recip();
            let k1 = (kc.clone() * inv.clone()).sqr();
            let inv2 = two.clone() * inv;
            let omk1 = kpc.clone() * inv2.clone();
            let kp1 = kpc.sqrt() * inv2;
            let opk = one.clone() + k1.clone();
            prod = prod * opk.clone();
            opks.push(opk);
            ks.push(k1.clone());
            omks.push(omk1);
            kc = k1;
            kpc = kp1;
        }
        let kq = k.pi().mul_2si(-1) * prod.clone() * (one.clone() + kc.sqr().mul_2si(-2));
        let k2q = kc.sqr().mul_2si(-2);
        let k2h = kc.sqr().mul_2si(-1);
        Ok(Chain {
            ks,
            omks,
            opks,
            k2q,
            k2h,
            half: one.mul_2si(-1),
            k2: k.sqr(),
            kp2: kp.sqr(),
            inv_prod: prod.recip(),
            kq,
        })
    }

    /// `(sn, cn, dn)(t, k)` for a reduced argument `|t| ≲ K/2`, each with relative
    /// accuracy (DLMF 22.10.4–6 at the bottom, 22.7.1–3 upwards).  `fixed` selects the
    /// form for types without guard bits (`f64`): there `1 − dn` is tracked next to `dn`
    /// and every update is written as "value + small correction", so that roundings
    /// scale with the correction (costs a few more operations).  With guard bits the
    /// plain quotients of DLMF 22.7.1–3 are used (fewer multi-precision operations).
    pub(crate) fn eval(&self, t: &R, fixed: bool) -> (R, R, R) {
        let one = t.one();
        if fixed && self.kp2 < t.epsilon().mul_2si(-3) {
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
        let z = t.clone() * self.inv_prod.clone();
        let (sz, cz) = z.sin_cos();
        let corr = (z - sz.clone() * cz.clone()) * self.k2q.clone();
        let mut s = sz.clone() - corr.clone() * cz.clone();
        let levels = self.ks.iter().zip(self.omks.iter()).zip(self.opks.iter());
        if fixed {
            let mut c = cz + corr * sz.clone();
            let mut e = self.k2h.clone() * sz.sqr();
            let mut d = one.clone() - e.clone();
            let half = self.half.clone();
            for ((k1, omk), _) in levels.rev() {
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
                // dn = (c² + (1−k₁)s²)/(1+k₁s²), 1 − dn = 2k₁s²/(1+k₁s²)
                let d_new = (cc + omk.clone() * ss) * inv.clone();
                e = (kss.clone() + kss) * inv;
                s = s_new;
                c = c_new;
                d = d_new;
            }
            (s, c, d)
        } else {
            // With guard bits only sn is carried up (DLMF 22.7.1); cn and dn follow at
            // the top from cn = √((1−sn)(1+sn)), dn = √(k'² + k²cn²) (DLMF 22.6.1).
            // For |t| ≤ K/2, cn ≥ √(k'/(1+k')), so at most log2(1/k') bits are lost; the
            // caller adds that many guard bits.
            for ((k1, _), opk) in levels.rev() {
                s = opk.clone() * s.clone() / (one.clone() + k1.clone() * s.sqr());
            }
            let c = ((one.clone() - s.clone()) * (one + s.clone())).sqrt();
            let d = (self.kp2.clone() + self.k2.clone() * c.sqr()).sqrt();
            (s, c, d)
        }
    }
}
