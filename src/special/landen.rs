//! The descending Landen (Gauss) chain of moduli and the evaluation of sn, cn, dn of a
//! reduced argument by climbing it (DLMF 22.7.1–3, 22.10.4–6, 19.8.12): the
//! multi-precision algorithm ([`Bottom::Sine`](super::Bottom::Sine)).

use super::SpecialError;
use crate::numbers::Real;

/// The chain `k = k₀ > k₁ > … > k_N` with `k_{n+1} = k_n²/(1+k_n')²`,
/// `k'_{n+1} = 2√k'_n/(1+k'_n)`, descended until `k_N⁴ < ε/4`.
pub(crate) struct Chain<R> {
    /// One entry per level n = 1..N: `(k_n, 1 + k_n)`.
    levels: Vec<[R; 2]>,
    /// `1 / Π (1 + k_n)`, n = 1..N.
    inv_prod: R,
    /// `k_N²/4`.
    k2q: R,
    /// `k²` and `k'²` of the top modulus.
    k2: R,
    kp2: R,
    /// The quarter period `K(k) = (π/2)·Π(1+k_n)·(1 + k_N²/4)`.
    pub kq: R,
}

impl<R: Real> Chain<R> {
    /// Builds the chain for modulus `k` with complementary modulus `kp` (both given,
    /// so that the caller can pass an exactly known pair, e.g. `(k', k)`): descend until
    /// `k_N⁴ < ε/4`, where DLMF 22.10.4–6 is exact to rounding.
    pub(crate) fn new(k: &R, kp: &R) -> Result<Self, SpecialError> {
        let one = k.one();
        let tol = k.epsilon().mul_2si(-2);
        let mut levels = Vec::new();
        let (mut kc, mut kpc) = (k.clone(), kp.clone());
        let mut prod = one.clone();
        while kc.sqr().sqr() > tol {
            if levels.len() >= 64 {
                return Err(SpecialError::NoConvergence(
                    "Landen chain of moduli did not converge in 64 steps".into(),
                ));
            }
            let (k1, kp1) = landen_step(&kc, &kpc);
            let opk = one.clone() + k1.clone();
            prod = prod * opk.clone();
            levels.push([k1.clone(), opk]);
            (kc, kpc) = (k1, kp1);
        }
        let k2q = kc.sqr().mul_2si(-2);
        Ok(Chain {
            levels,
            kq: k.pi().mul_2si(-1) * prod.clone() * (one + k2q.clone()),
            k2q,
            k2: k.sqr(),
            kp2: kp.sqr(),
            inv_prod: prod.recip(),
        })
    }

    /// `(sn, cn, dn)(t, k)` for a reduced argument `|t| ≲ K/2`: `sn` at the bottom from
    /// `sin`/`cos` with the correction DLMF 22.10.4, carried up the chain alone
    /// (DLMF 22.7.1: one reciprocal and three products per level), and at the top
    /// `cn = √((1−sn)(1+sn))`, `dn = √(k'² + k²cn²)` (DLMF 22.6.1).  For `|t| ≤ K/2`,
    /// `cn ≥ √(k'/(1+k'))`, so at most `log2(1/k')` bits are lost; the caller adds that
    /// many guard bits.
    pub(crate) fn eval(&self, t: &R) -> (R, R, R) {
        let one = t.one();
        let z = t.clone() * self.inv_prod.clone();
        let (sz, cz) = z.sin_cos();
        let corr = (z - sz.clone() * cz.clone()) * self.k2q.clone();
        let mut s = sz - corr * cz;
        for [k1, opk] in self.levels.iter().rev() {
            s = opk.clone() * s.clone() / (one.clone() + k1.clone() * s.sqr());
        }
        let c = ((one.clone() - s.clone()) * (one + s.clone())).sqrt();
        let d = (self.kp2.clone() + self.k2.clone() * c.sqr()).sqrt();
        (s, c, d)
    }
}

/// One descending Landen step (DLMF 19.8.12, 22.7.1–3): `(k, k')` to `(k₁, k₁')` with
/// `k₁ = (k/(1+k'))²`, `k₁' = 2√k'/(1+k')`.
fn landen_step<S: Real>(k: &S, kp: &S) -> (S, S) {
    let one = k.one();
    let inv = (one + kp.clone()).recip();
    let k1 = (k.clone() * inv.clone()).sqr();
    let kp1 = kp.sqrt() * inv.mul_2si(1);
    (k1, kp1)
}
