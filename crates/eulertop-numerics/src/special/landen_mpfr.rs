//! The Landen chain ([`Chain`]) for `rug::Float`: the same arithmetic as the generic
//! build and climb, written with in-place MPFR operations, so that a level allocates
//! nothing but the values it keeps (the generic code, through [`Real`](crate::numbers::Real),
//! creates a new `Float` for every intermediate result).  Chosen statically by the
//! chain strategy of `rug::Float` (`multi::Cached`).

use super::SpecialError;
use super::landen::Chain;
use super::sincos::sin_cos_into;
use rug::{Assign, Float};

/// `log2 |x|` (`−∞` for zero), without overflow or underflow for any exponent.
fn log2_abs(x: &Float) -> f64 {
    if x.is_zero() {
        return f64::NEG_INFINITY;
    }
    let (m, e) = x.to_f64_exp();
    m.abs().log2() + f64::from(e)
}

impl Chain<Float> {
    /// [`Chain::new`] in place: descend while `c_n⁴ ≥ (ε/4)·a_n⁴` (compared through
    /// `log2`, which needs no full-precision arithmetic).
    pub(super) fn new_mpfr(k: &Float, kp: &Float) -> Result<Self, SpecialError> {
        let p = k.prec();
        let log2_tol = 1.0 - f64::from(p) - 2.0;
        let one = Float::with_val(p, 1);
        let mut levels: Vec<[Float; 2]> = Vec::new();
        let mut b = kp.clone();
        loop {
            // the running a_n, c_n are the last level's (a_0 = 1, c_0 = k): no copies
            let (a, c) = match levels.last() {
                Some([a, c]) => (a, c),
                None => (&one, k),
            };
            if 4.0 * (log2_abs(c) - log2_abs(a)) <= log2_tol {
                break;
            }
            if levels.len() >= 64 {
                return Err(SpecialError::NoConvergence(
                    "Landen chain of moduli did not converge in 64 steps".into(),
                ));
            }
            let mut a1 = Float::with_val(p, a + &b);
            a1 >>= 1;
            let mut c1 = Float::with_val(p, a - &b);
            c1 >>= 1;
            b *= a;
            b.sqrt_mut();
            levels.push([a1, c1]);
        }
        let (a, c) = match levels.last() {
            Some([a, c]) => (a.clone(), c),
            None => (one, k),
        };
        let mut k2q = Float::with_val(p, c / &a);
        k2q.square_mut();
        k2q >>= 2;
        let mut kq = Float::with_val(p, 1 + &k2q);
        kq *= Float::with_val(p, rug::float::Constant::Pi);
        kq /= &a;
        kq >>= 1;
        Ok(Chain {
            levels,
            kq,
            a_n: a,
            k2q,
            k2: Float::with_val(p, k.square_ref()),
            kp2: Float::with_val(p, kp.square_ref()),
        })
    }

    /// [`Chain::eval`] in place, at the precision of `t`, except that `dn` comes from the
    /// top climbing step (DLMF 22.7.3; a division instead of a square root, losing at most
    /// the `log2(1/k')` bits that `cn` may lose too).
    pub(super) fn eval_mpfr(&self, t: &Float) -> (Float, Float, Float) {
        let p = t.prec();
        let mut z = Float::with_val(p, t * &self.a_n);
        let (mut s, mut c) = (Float::new(p), Float::new(p));
        sin_cos_into(&z, &mut s, &mut c);
        // s = sin z − (k_N²/4)(z − sin z cos z) cos z
        let mut tmp = Float::with_val(p, &s * &c);
        z -= &tmp;
        z *= &self.k2q;
        z *= &c;
        s -= &z;
        // the top level gives dn too: dn = (a_1 − c_1 s_1²)/(a_1 + c_1 s_1²) (DLMF 22.7.3)
        let mut dn = None;
        for (n, [a_cur, c_cur]) in self.levels.iter().enumerate().rev() {
            tmp.assign(s.square_ref());
            tmp *= c_cur;
            tmp += a_cur;
            if n == 0 {
                let mut d = Float::with_val(p, a_cur << 1u32);
                d -= &tmp;
                d /= &tmp;
                dn = Some(d);
            } else {
                s *= &self.levels[n - 1][0];
            }
            s /= &tmp;
        }
        // cn = √((1 − s)(1 + s)); without levels dn = √(k'² + k²cn²)
        c.assign(1 - &s);
        tmp.assign(1 + &s);
        c *= &tmp;
        c.sqrt_mut();
        let dn = dn.unwrap_or_else(|| {
            tmp.assign(c.square_ref());
            tmp *= &self.k2;
            tmp += &self.kp2;
            tmp.sqrt_mut();
            tmp
        });
        (s, c, dn)
    }
}
