//! The multi-precision evaluation of a real argument: the reduction `u = jK + t` at a
//! working precision raised adaptively, on the Landen chain of the modulus
//! ([`Bottom::Sine`](super::bottom::Bottom::Sine)), and the per-thread cache of the chains of
//! `rug::Float` (callers typically evaluate many arguments for one modulus: tables,
//! orbits, a complex argument needs the modulus and its complement).
//!
//! How a type gets and climbs its chain is a [`Chains`] strategy, chosen statically:
//! [`Cached`] for `rug::Float` (the chain of the last few moduli kept per thread, built
//! and climbed with in-place MPFR operations, reached through [`Real::as_mpfr`]), and
//! [`Fresh`] for every other type (e.g. `Dual<rug::Float>`, whose derivative parts
//! differ from call to call): built for the call by the generic arithmetic.

use super::agm::complementary;
use super::landen::Chain;
use super::modulus::{Modulus, quadrant};
use super::{GUARD, SpecialError, show};
use crate::numbers::Real;
use rug::Float;
use std::cell::RefCell;

/// The Landen chain for one modulus at one working precision.
pub(crate) struct ChainData<R> {
    /// Complementary modulus of the evaluated modulus, at the working precision.
    pub kp: R,
    /// The Landen chain (with the quarter period).
    pub chain: Chain<R>,
    /// `1/K` rounded to `f64` (for choosing the quadrant).
    pub inv_kq: f64,
}

/// How the chain of a modulus is obtained and climbed for the scalar type `R`.
trait Chains<R> {
    /// Runs `f` on the chain for modulus `k0` (its complement for
    /// [`Modulus::Complement`]) at `w` bits.
    fn with_chain<T>(
        k0: &R,
        modulus: Modulus,
        w: u32,
        f: impl FnOnce(&ChainData<R>) -> T,
    ) -> Result<T, SpecialError>;
    /// `(sn, cn, dn)(t)` for a reduced argument ([`Chain::eval`]).
    fn climb(chain: &Chain<R>, t: &R) -> (R, R, R);
}

/// Every type: the chain built for the call by the generic arithmetic.
struct Fresh;

impl<R: Real> Chains<R> for Fresh {
    fn with_chain<T>(
        k0: &R,
        modulus: Modulus,
        w: u32,
        f: impl FnOnce(&ChainData<R>) -> T,
    ) -> Result<T, SpecialError> {
        Ok(f(&build(k0, modulus, w, Chain::new)?))
    }
    fn climb(chain: &Chain<R>, t: &R) -> (R, R, R) {
        chain.eval(t)
    }
}

/// `rug::Float`: the chain through the per-thread cache, in-place MPFR operations.
struct Cached;

/// A cached multi-precision chain: exact value of `k`, which modulus, precision.
struct Entry {
    k0: Float,
    modulus: Modulus,
    w: u32,
    data: ChainData<Float>,
}

/// Chains kept per thread.
const ENTRIES: usize = 4;

thread_local! {
    static CHAINS: RefCell<Vec<Entry>> = const { RefCell::new(Vec::new()) };
}

impl Chains<Float> for Cached {
    /// Through the cache, keyed by the exact value of `k0`, the modulus and `w`, most
    /// recent first.
    fn with_chain<T>(
        k0: &Float,
        modulus: Modulus,
        w: u32,
        f: impl FnOnce(&ChainData<Float>) -> T,
    ) -> Result<T, SpecialError> {
        CHAINS.with(|c| {
            let mut c = c.borrow_mut();
            let hit = c
                .iter()
                .position(|e| &e.k0 == k0 && e.modulus == modulus && e.w == w);
            let i = match hit {
                Some(i) => i,
                None => {
                    let data = build(k0, modulus, w, Chain::new_mpfr)?;
                    c.truncate(ENTRIES - 1);
                    let k0 = k0.clone();
                    c.insert(
                        0,
                        Entry {
                            k0,
                            modulus,
                            w,
                            data,
                        },
                    );
                    0
                }
            };
            Ok(f(&c[i].data))
        })
    }
    fn climb(chain: &Chain<Float>, t: &Float) -> (Float, Float, Float) {
        chain.eval_mpfr(t)
    }
}

/// Builds the chain data for `k0` (its complement for [`Modulus::Complement`]) at
/// `w` bits with the chain constructor `new`.
fn build<R: Real>(
    k0: &R,
    modulus: Modulus,
    w: u32,
    new: impl FnOnce(&R, &R) -> Result<Chain<R>, SpecialError>,
) -> Result<ChainData<R>, SpecialError> {
    let kw = k0.with_prec(w);
    let kpw = complementary(&kw);
    let (k, kp) = match modulus {
        Modulus::K => (kw, kpw),
        Modulus::Complement => (kpw, kw),
    };
    let chain = new(&k, &kp)?;
    let inv_kq = 1.0 / chain.kq.to_f64();
    Ok(ChainData { kp, inv_kq, chain })
}

/// A reduced multi-precision evaluation: `u = j·K + t`, `|t| ≲ K/2`, with
/// `s, c, d = sn, cn, dn(t)` and the complementary modulus `kp`.
pub(crate) struct Reduced<R> {
    pub j: i64,
    pub s: R,
    pub c: R,
    pub d: R,
    pub kp: R,
}

impl<R: Real> Reduced<R> {
    /// `(sn, cn, dn)(u)` from the quadrant `j mod 4` (DLMF 22.4.3).
    pub(crate) fn finish(&self) -> (R, R, R) {
        let (s, c, d, kp) = (&self.s, &self.c, &self.d, &self.kp);
        match self.j.rem_euclid(4) {
            0 => (s.clone(), c.clone(), d.clone()),
            1 => {
                let kd = kp.clone() / d.clone();
                (c.clone() / d.clone(), -(kd.clone() * s.clone()), kd)
            }
            2 => (-s.clone(), -c.clone(), d.clone()),
            _ => {
                let kd = kp.clone() / d.clone();
                (-(c.clone() / d.clone()), kd.clone() * s.clone(), kd)
            }
        }
    }
}

impl Reduced<Float> {
    /// The same evaluation as values of `R` (`None` unless `R` is an MPFR type, see
    /// [`Real::from_mpfr`]).
    fn into_real<R: Real>(self) -> Option<Reduced<R>> {
        Some(Reduced {
            j: self.j,
            s: R::from_mpfr(self.s)?,
            c: R::from_mpfr(self.c)?,
            d: R::from_mpfr(self.d)?,
            kp: R::from_mpfr(self.kp)?,
        })
    }
}

/// One multi-precision attempt at working precision `w`; returns the evaluation and
/// the number of extra bits the reduction needed (for the adaptive retry).
fn reduce_mp<R: Real, C: Chains<R>>(
    u: &R,
    w: u32,
    data: &ChainData<R>,
) -> Result<(Reduced<R>, u32), SpecialError> {
    let uw = u.with_prec(w);
    let ch = &data.chain;
    let j = quadrant(uw.to_f64() * data.inv_kq, &uw)?;
    let mut need = 0u32;
    let t = if j == 0 {
        uw
    } else {
        let kq_f = ch.kq.to_f64();
        let t = uw.clone() - uw.from_i64(j) * ch.kq.clone();
        // bits lost: size of j, magnitude of K, cancellation in t
        let jb = 64 - j.unsigned_abs().leading_zeros();
        let kb = kq_f.log2().max(0.0);
        let tf = t.to_f64().abs();
        let cb = if tf > 0.0 {
            (kq_f / tf).log2().max(0.0)
        } else {
            w as f64
        };
        // Cancellation is capped at half the working precision: when t is that small
        // (t = 0 included) its relative accuracy w/2 still exceeds the n bits asked
        // for once the retry loop has grown w past 2(n + jb + 16).
        let lost = (kb + cb).ceil().min(w as f64 / 2.0) as u32;
        need = jb.saturating_add(lost).saturating_add(8);
        t
    };
    let (s, c, d) = C::climb(ch, &t);
    let kp = data.kp.clone();
    Ok((Reduced { j, s, c, d, kp }, need))
}

/// Multi-precision reduced evaluation `u = jK + t` for the modulus `k` (or its
/// complement): starts at `n + 40 + log2(1/k')` bits and retries with more bits when
/// the reduction `t = u − jK` lost too many.  `rug::Float` takes the cached in-place
/// chains ([`Cached`]), every other type builds its chain ([`Fresh`]).
pub(crate) fn reduced<R: Real>(
    u: &R,
    k: &R,
    modulus: Modulus,
    n: u32,
) -> Result<Reduced<R>, SpecialError> {
    if let (Some(uf), Some(kf)) = (u.as_mpfr(), k.as_mpfr()) {
        let r = reduced_by::<Float, Cached>(uf, kf, modulus, n)?;
        if let Some(r) = r.into_real() {
            return Ok(r);
        }
    }
    reduced_by::<R, Fresh>(u, k, modulus, n)
}

/// [`reduced`] with the chain strategy `C`.
fn reduced_by<R: Real, C: Chains<R>>(
    u: &R,
    k: &R,
    modulus: Modulus,
    n: u32,
) -> Result<Reduced<R>, SpecialError> {
    // cn from sn at the top of the chain loses up to log2(1/k') bits (see landen.rs)
    let kf = k.to_f64();
    let kp_f = match modulus {
        Modulus::K => ((1.0 - kf) * (1.0 + kf)).sqrt(),
        Modulus::Complement => kf,
    };
    let extra = if kp_f > 0.0 {
        (-kp_f.log2()).ceil().max(0.0) as u32
    } else {
        n
    };
    let mut w = n + GUARD + extra;
    for _ in 0..6 {
        let (r, need) = C::with_chain(k, modulus, w, |data| reduce_mp::<R, C>(u, w, data))??;
        if need + 8 <= w - n {
            return Ok(r);
        }
        w = (n + need + GUARD).max(w + w / 2);
    }
    Err(SpecialError::NoConvergence(format!(
        "argument reduction of u = {} kept cancelling",
        show(u)
    )))
}
