//! Per-thread caches of per-modulus data: callers typically evaluate many arguments
//! for one modulus (tables, orbits, a complex argument needs the modulus and its
//! complement), so the last few moduli are kept.
//!
//! * the fixed-precision theta data ([`Theta`]) for `f64`;
//! * the multi-precision Landen chains ([`Chain`]) for `rug::Float`;
//! * the 150-bit quarter periods used by the exact reduction of large arguments.
//!
//! The caches are typed, one per scalar type; the data of a generic `R` is looked up
//! by downcasting (`std::any::Any`), resolved at compile time.  Other types (e.g.
//! `Dual`, whose derivative parts differ from call to call) build their data afresh.

use super::agm::complementary;
use super::dd::Dd;
use super::landen::Chain;
use super::theta::Theta;
use super::{Modulus, SpecialError};
use crate::numbers::Real;
use rug::float::Constant;
use rug::Float;
use std::any::Any;
use std::cell::RefCell;

/// Entries kept per cache.
const ENTRIES: usize = 4;

/// Quarter-period cache entries: (bits of κ'² as a double-double, triple-double K).
type Triples = Vec<([u64; 2], [f64; 3])>;

thread_local! {
    static TRIPLES: RefCell<Triples> = const { RefCell::new(Vec::new()) };
    static THETAS: RefCell<Vec<([u64; 2], Theta<f64>)>> = const { RefCell::new(Vec::new()) };
    static CHAINS: RefCell<Vec<Entry>> = const { RefCell::new(Vec::new()) };
}

/// Pushes `v` to the front of a cache, dropping the oldest entry.
fn remember<T>(c: &mut Vec<T>, v: T) {
    c.truncate(ENTRIES - 1);
    c.insert(0, v);
}

/// The quarter period `K` of the modulus with `κ'² = mc.0 + mc.1` as an unevaluated
/// sum of three doubles (about 150 bits), from a 200-bit MPFR AGM:
/// `K = π/(2·AGM(1, κ'))` (DLMF 19.8.5).
pub(crate) fn quarter_period_triple(mc: (f64, f64)) -> [f64; 3] {
    let key = [mc.0.to_bits(), mc.1.to_bits()];
    if let Some(v) = TRIPLES.with(|c| c.borrow().iter().find(|e| e.0 == key).map(|e| e.1)) {
        return v;
    }
    let p = 200;
    let kp = (Float::with_val(p, mc.0) + mc.1).sqrt();
    let m = Float::with_val(p, 1).agm(&kp);
    let q = Float::with_val(p, Constant::Pi) / (m * 2u32);
    let h = q.to_f64();
    let r = q - h;
    let l = r.to_f64();
    let v = [h, l, (r - l).to_f64()];
    TRIPLES.with(|c| remember(&mut c.borrow_mut(), (key, v)));
    v
}

/// Runs `f` on the theta data of the modulus `κ² = m`, `κ'² = mc` (fixed precision),
/// through the `f64` cache when `R` is `f64`.
#[inline]
pub(crate) fn with_theta<R: Real, T>(m: &Dd<R>, mc: &Dd<R>, f: impl FnOnce(&Theta<R>) -> T) -> T {
    if (&m.hi as &dyn Any).downcast_ref::<f64>().is_none() {
        return f(&Theta::new(m, mc));
    }
    let key = [m.v().to_bits(), m.lo.to_bits()];
    let mut f = Some(f);
    let hit = THETAS.with(|c| {
        let c = c.borrow();
        let e = c.iter().find(|e| e.0 == key)?;
        let t = (&e.1 as &dyn Any).downcast_ref::<Theta<R>>()?;
        f.take().map(|f| f(t))
    });
    if let Some(out) = hit {
        return out;
    }
    let theta = Theta::new(m, mc);
    let out = f.take().map(|f| f(&theta));
    if let Some(t64) = (&theta as &dyn Any).downcast_ref::<Theta<f64>>() {
        THETAS.with(|c| remember(&mut c.borrow_mut(), (key, t64.clone())));
    }
    out.expect("closure runs once")
}

/// The Landen chain for one modulus at one working precision (multi-precision).
pub(crate) struct ChainData<R> {
    /// Complementary modulus of the evaluated modulus, at the working precision.
    pub kp: R,
    /// The Landen chain (with the quarter period).
    pub chain: Chain<R>,
    /// `1/K` rounded to `f64` (for choosing the quadrant).
    pub inv_kq: f64,
}

/// A cached multi-precision chain: exact value of `k`, which modulus, precision.
struct Entry {
    k0: Float,
    modulus: Modulus,
    w: u32,
    data: ChainData<Float>,
}

/// Runs `f` on the chain for modulus `k0` (its complement for
/// [`Modulus::Complement`]) at `w` bits; for `rug::Float` through the cache (keyed by
/// the exact value of `k0`, the modulus and `w`, most recent first), otherwise built
/// afresh.
#[inline]
pub(crate) fn with_chain<R: Real, T>(
    k0: &R,
    modulus: Modulus,
    w: u32,
    f: impl FnOnce(&ChainData<R>) -> T,
) -> Result<T, SpecialError> {
    let Some(key) = (k0 as &dyn Any).downcast_ref::<Float>() else {
        return Ok(f(&build(k0, modulus, w)?));
    };
    let mut f = Some(f);
    let hit = CHAINS.with(|c| {
        let c = c.borrow();
        let e = c
            .iter()
            .find(|e| &e.k0 == key && e.modulus == modulus && e.w == w)?;
        let d = (&e.data as &dyn Any).downcast_ref::<ChainData<R>>()?;
        f.take().map(|f| f(d))
    });
    if let Some(out) = hit {
        return Ok(out);
    }
    let data = build(key, modulus, w)?;
    CHAINS.with(|c| {
        let mut c = c.borrow_mut();
        remember(
            &mut c,
            Entry {
                k0: key.clone(),
                modulus,
                w,
                data,
            },
        );
        let d = (&c[0].data as &dyn Any).downcast_ref::<ChainData<R>>();
        match (d, f.take()) {
            (Some(d), Some(f)) => Ok(f(d)),
            _ => Err(SpecialError::NoConvergence(
                "internal: chain cache type mismatch".into(),
            )),
        }
    })
}

/// Builds the chain data for `k0` (its complement for [`Modulus::Complement`]) at
/// `w` bits.
fn build<R: Real>(k0: &R, modulus: Modulus, w: u32) -> Result<ChainData<R>, SpecialError> {
    let kw = k0.with_prec(w);
    let kpw = complementary(&kw);
    let (k, kp) = match modulus {
        Modulus::K => (kw, kpw),
        Modulus::Complement => (kpw, kw),
    };
    let chain = Chain::new(&k, &kp)?;
    let inv_kq = 1.0 / chain.kq.to_f64();
    Ok(ChainData { kp, inv_kq, chain })
}
