//! The descending Landen (Gauss) chain of moduli and the evaluation of sn, cn, dn of a
//! reduced argument by climbing it (DLMF 22.7.1–3, 22.10.4–6, 19.8.12): the
//! multi-precision algorithm ([`Bottom::Sine`](super::bottom::Bottom::Sine)).

use super::SpecialError;
use crate::numbers::Real;

/// The chain `k = k₀ > k₁ > … > k_N` with `k_{n+1} = k_n²/(1+k_n')²`, descended until
/// `k_N⁴ < ε/4`, kept as the arithmetic–geometric mean sequence `a₀ = 1`, `b₀ = k'`,
/// `c₀ = k`, `a_{n+1} = (a_n + b_n)/2`, `b_{n+1} = √(a_n b_n)`, `c_{n+1} = (a_n − b_n)/2`
/// (DLMF 19.8.1–2), where `k_n = c_n/a_n` and `1 + k_n = a_{n−1}/a_n` (Gauss's
/// transformation, DLMF 19.8.12), so a level costs one product and one square root.
pub(crate) struct Chain<R> {
    /// One entry per level n = 1..N: `(a_n, c_n)` (`a_0 = 1`).
    pub(super) levels: Vec<[R; 2]>,
    /// `a_N = 1/Π(1 + k_n)`.
    pub(super) a_n: R,
    /// `k_N²/4`.
    pub(super) k2q: R,
    /// `k²` and `k'²` of the top modulus.
    pub(super) k2: R,
    pub(super) kp2: R,
    /// The quarter period `K(k) = (π/2)·Π(1+k_n)·(1 + k_N²/4) = π(1 + k_N²/4)/(2a_N)`.
    pub kq: R,
}

impl<R: Real> Chain<R> {
    /// Builds the chain for modulus `k` with complementary modulus `kp` (both given,
    /// so that the caller can pass an exactly known pair, e.g. `(k', k)`): descend until
    /// `k_N⁴ < ε/4`, where DLMF 22.10.4–6 is exact to rounding.  `c_{n+1} = (a_n − b_n)/2`
    /// cancels, but only its absolute accuracy matters (it enters as `a_n + c_n s²`).
    pub(crate) fn new(k: &R, kp: &R) -> Result<Self, SpecialError> {
        let one = k.one();
        // the stopping test c_N⁴ < (ε/4)·a_N⁴ needs no full precision: 64 bits (same
        // exponent range) suffice
        let tol = k.epsilon().mul_2si(-2).with_prec(64);
        let mut levels = Vec::new();
        let (mut a, mut b, mut c) = (one.clone(), kp.clone(), k.clone());
        while c.with_prec(64).sqr().sqr() > tol.clone() * a.with_prec(64).sqr().sqr() {
            if levels.len() >= 64 {
                return Err(SpecialError::NoConvergence(
                    "Landen chain of moduli did not converge in 64 steps".into(),
                ));
            }
            let a1 = (a.clone() + b.clone()).mul_2si(-1);
            let c1 = (a.clone() - b.clone()).mul_2si(-1);
            b = (a.clone() * b).sqrt();
            levels.push([a1.clone(), c1.clone()]);
            (a, c) = (a1, c1);
        }
        let k2q = (c / a.clone()).sqr().mul_2si(-2);
        Ok(Chain {
            levels,
            kq: k.pi() * (one + k2q.clone()) / a.mul_2si(1),
            a_n: a,
            k2q,
            k2: k.sqr(),
            kp2: kp.sqr(),
        })
    }

    /// `(sn, cn, dn)(t, k)` for a reduced argument `|t| ≲ K/2`: `sn` at the bottom from
    /// `sin`/`cos` of `z = t·a_N` with the correction DLMF 22.10.4, carried up the chain
    /// alone (DLMF 22.7.1: `sn_{n−1} = (1 + k_n) s/(1 + k_n s²) = a_{n−1}s/(a_n + c_n s²)`,
    /// one division and three products per level), and at the top
    /// `cn = √((1−sn)(1+sn))`, `dn = √(k'² + k²cn²)` (DLMF 22.6.1).  For `|t| ≤ K/2`,
    /// `cn ≥ √(k'/(1+k'))`, so at most `log2(1/k')` bits are lost; the caller adds that
    /// many guard bits.
    pub(crate) fn eval(&self, t: &R) -> (R, R, R) {
        let one = t.one();
        let z = t.clone() * self.a_n.clone();
        let (sz, cz) = z.sin_cos();
        let corr = (z - sz.clone() * cz.clone()) * self.k2q.clone();
        let mut s = sz - corr * cz;
        for (n, [a_cur, c_cur]) in self.levels.iter().enumerate().rev() {
            let a_prev = match n {
                0 => one.clone(),
                _ => self.levels[n - 1][0].clone(),
            };
            s = a_prev * s.clone() / (a_cur.clone() + c_cur.clone() * s.sqr());
        }
        let c = ((one.clone() - s.clone()) * (one + s.clone())).sqrt();
        let d = (self.kp2.clone() + self.k2.clone() * c.sqr()).sqrt();
        (s, c, d)
    }
}
