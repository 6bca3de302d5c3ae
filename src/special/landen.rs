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
    /// `k_N` (or `k` when N = 0).
    kn: R,
    /// `Π (1 + k_n)`, n = 1..N.
    prod: R,
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
        let tol = k.epsilon().mul_2si(-6);
        let mut ks = Vec::new();
        let mut omks = Vec::new();
        let (mut kc, mut kpc) = (k.clone(), kp.clone());
        let mut prod = one.clone();
        while kc.sqr().sqr() > tol {
            if ks.len() >= 64 {
                return Err(SpecialError::NoConvergence(
                    "Landen chain of moduli did not converge in 64 steps".into(),
                ));
            }
            let den = one.clone() + kpc.clone();
            let k1 = (kc.clone() / den.clone()).sqr();
            let omk1 = two.clone() * kpc.clone() / den.clone();
            let kp1 = two.clone() * kpc.sqrt() / den;
            prod = prod * (one.clone() + k1.clone());
            ks.push(k1.clone());
            omks.push(omk1);
            kc = k1;
            kpc = kp1;
        }
        let kq = k.pi().mul_2si(-1) * prod.clone() * (one + kc.sqr().mul_2si(-2));
        Ok(Chain {
            ks,
            omks,
            kn: kc,
            prod,
            kq,
        })
    }

    /// `(sn, cn, dn)(t, k)` for a reduced argument `|t| ≲ K/2`, each with relative
    /// accuracy (DLMF 22.10.4–6 at the bottom, 22.7.1–3 upwards).
    pub(crate) fn eval(&self, t: &R) -> (R, R, R) {
        let one = t.one();
        let z = t.clone() / self.prod.clone();
        let (sz, cz) = z.sin_cos();
        let k2 = self.kn.sqr();
        let corr = (z - sz.clone() * cz.clone()) * k2.mul_2si(-2);
        let mut s = sz.clone() - corr.clone() * cz.clone();
        let mut c = cz + corr * sz.clone();
        // e = 1 − dn is tracked next to dn: for small k_n the updates below are
        // "value + small correction", so their roundings scale with the correction
        let mut e = k2.mul_2si(-1) * sz.sqr();
        let mut d = one.clone() - e.clone();
        let half = one.mul_2si(-1);
        for (k1, omk) in self.ks.iter().zip(self.omks.iter()).rev() {
            let ss = s.sqr();
            let cc = c.sqr();
            let kss = k1.clone() * ss.clone();
            let den = one.clone() + kss.clone();
            // sn = s(1+k₁)/(1+k₁s²) = s + s·k₁c²/(1+k₁s²)
            let s_new = s.clone() + s * k1.clone() * cc.clone() / den.clone();
            // cn = c·dn/(1+k₁s²) = c − c(e + k₁s²)/(1+k₁s²)
            let c_new = if e < half {
                c.clone() - c * (e + kss.clone()) / den.clone()
            } else {
                c * d / den.clone()
            };
            // dn = (c² + (1−k₁)s²)/(1+k₁s²), 1 − dn = 2k₁s²/(1+k₁s²)
            let d_new = (cc + omk.clone() * ss) / den.clone();
            e = kss.mul_2si(1) / den;
            s = s_new;
            c = c_new;
            d = d_new;
        }
        (s, c, d)
    }
}
