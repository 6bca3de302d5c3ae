//! Argument reduction helpers for fixed-precision types (`f64`, `Dual<f64>`): a quarter
//! period known to ~150 bits as a triple-double, and an error-free `u − j·P`.

use super::landen::Chain;
use super::SpecialError;
use crate::numbers::Real;
use rug::float::Constant;
use rug::Float;
use std::any::{Any, TypeId};
use std::cell::RefCell;

/// Cache entries: ((bits of k, complementary?), triple-double quarter period).
type Entries = Vec<((u64, bool), [f64; 3])>;

thread_local! {
    static CACHE: RefCell<Entries> = const { RefCell::new(Vec::new()) };
}

/// `K(k)` (or `K'(k)` when `comp`) for the exact double `k`, as an unevaluated sum of
/// three doubles, from a 200-bit MPFR AGM (DLMF 19.8.5).  Cached per thread (8 entries).
pub(crate) fn quarter_period_triple(k: f64, comp: bool) -> [f64; 3] {
    let key = (k.to_bits(), comp);
    if let Some(v) = CACHE.with(|c| c.borrow().iter().find(|e| e.0 == key).map(|e| e.1)) {
        return v;
    }
    let p = 200;
    let kk = Float::with_val(p, k);
    let one = Float::with_val(p, 1);
    let omk = Float::with_val(p, &one - &kk);
    let opk = Float::with_val(p, &one + &kk);
    let kp = (omk * opk).sqrt();
    let b = if comp { kk } else { kp };
    let m = one.agm(&b);
    let q = Float::with_val(p, Constant::Pi) / (m * 2u32);
    let h = q.to_f64();
    let r = q - h;
    let l = r.to_f64();
    let l2 = (r - l).to_f64();
    let v = [h, l, l2];
    CACHE.with(|c| {
        let mut c = c.borrow_mut();
        if c.len() >= 8 {
            c.remove(0);
        }
        c.push((key, v));
    });
    v
}

/// `u − j·P` where `P ≈ tri[0]+tri[1]+tri[2]` is the exact period and `p` its generic
/// approximation (which carries derivatives).  For fixed-precision types only (`to_f64`
/// exact on the value).
///
/// * `|j| < 2²⁰` (Cody–Waite): `tri[0] = P₁ + P₂` with `P₁` its leading 32 bits, so
///   `j·P₁` and `j·P₂` are exact products.  `u − j·P₁` is exact (Sterbenz: `u` and
///   `j·P₁` are within a factor 2 of each other for `j ≠ 0`), and so is the next
///   subtraction of `j·P₂` (every term is a multiple of `ulp(P)/2` and the result is
///   below `P`); only the tail `j·(tri[1] + tri[2])`, of size `|j|·2⁻⁵³·P`, is
///   subtracted with a rounding, so `t` keeps its relative accuracy even when `u` is
///   within a few ulp of `j·P` (needed next to the complex poles).
/// * larger `j`: `u − j·tri[0]` is formed exactly with an FMA product and a Sterbenz
///   subtraction, then the tail.
///
/// In both, `j·(p − p.value)` (value zero, derivative `j·dp`) is added afterwards.
pub(crate) fn reduce_dd<R: Real>(u: &R, p: &R, j: i64, tri: [f64; 3]) -> R {
    let jf = j as f64;
    let (head, mid, lo) = if j.unsigned_abs() < 1 << 20 {
        let p1 = f64::from_bits(tri[0].to_bits() & !((1u64 << 21) - 1));
        let p2 = tri[0] - p1;
        (jf * p1, jf * p2, jf * tri[1] + jf * tri[2])
    } else {
        let p0 = jf * tri[0];
        let e0 = jf.mul_add(tri[0], -p0);
        let p1 = jf * tri[1];
        let e1 = jf.mul_add(tri[1], -p1);
        let p2 = jf * tri[2];
        (p0, 0.0, (e0 + p1) + (e1 + p2))
    };
    let dp = p.clone() - u.from_f64(p.to_f64());
    ((u.clone() - u.from_f64(head)) - u.from_f64(mid)) - u.from_f64(lo) - u.from_i64(j) * dp
}

/// The moduli chain for one modulus at one working precision.
pub(crate) struct ChainData<R> {
    /// Complementary modulus at the working precision (`k` itself for `comp`).
    pub kp: R,
    /// The Landen chain (with the quarter period).
    pub chain: Chain<R>,
    /// `1/K` rounded to f64 (for choosing the quadrant).
    pub inv_kq: f64,
    /// The exact quarter period as a triple-double (fixed-precision types only,
    /// computed when the chain is built).
    pub tri: Option<[f64; 3]>,
}

struct Entry<R> {
    k0: R,
    comp: bool,
    w: u32,
    data: ChainData<R>,
}

thread_local! {
    static F64_CHAINS: RefCell<Vec<Entry<f64>>> = const { RefCell::new(Vec::new()) };
    static MP_CHAINS: RefCell<Vec<Entry<Float>>> = const { RefCell::new(Vec::new()) };
}

/// Runs `f` on the chain for modulus `k0` (its complement when `comp`) at `w` bits.
/// For `f64` and `rug::Float` the last few chains are cached per thread (keyed by the
/// exact value of `k0`, `comp` and `w`; the most recent first), since callers
/// typically evaluate many arguments for one modulus; `f` then runs on the cached
/// entry in place.  The caches are typed (one per scalar type), and the type test
/// below is resolved at compile time, so a hit costs a few comparisons.  Other types
/// (e.g. `Dual`, whose derivative parts must not be shared) always build the chain
/// afresh.
#[inline]
pub(crate) fn with_chain<R: Real, T>(
    k0: &R,
    comp: bool,
    w: u32,
    f: impl FnOnce(&ChainData<R>) -> T,
) -> Result<T, SpecialError> {
    if TypeId::of::<R>() == TypeId::of::<f64>() {
        cached(&F64_CHAINS, k0, comp, w, f)
    } else if TypeId::of::<R>() == TypeId::of::<Float>() {
        cached(&MP_CHAINS, k0, comp, w, f)
    } else {
        Ok(f(&build(k0, comp, w)?))
    }
}

/// The chain data of a cache entry of type `C`, seen as type `R` (which it is).
fn typed<C: Real, R: Real>(e: &Entry<C>) -> Option<&ChainData<R>> {
    (&e.data as &dyn Any).downcast_ref::<ChainData<R>>()
}

/// [`with_chain`] through the typed cache `cache` (whose type `C` is `R`).
#[inline]
fn cached<C: Real, R: Real, T>(
    cache: &'static std::thread::LocalKey<RefCell<Vec<Entry<C>>>>,
    k0: &R,
    comp: bool,
    w: u32,
    f: impl FnOnce(&ChainData<R>) -> T,
) -> Result<T, SpecialError> {
    let key = (k0 as &dyn Any).downcast_ref::<C>();
    let mut f = Some(f);
    let hit = cache.with(|c| {
        let c = c.borrow();
        let e = c
            .iter()
            .find(|e| Some(&e.k0) == key && e.comp == comp && e.w == w)?;
        match (typed::<C, R>(e), f.take()) {
            (Some(d), Some(f)) => Some(f(d)),
            _ => None,
        }
    });
    if let Some(out) = hit {
        return Ok(out);
    }
    let internal = || SpecialError::NoConvergence("internal: chain cache type mismatch".into());
    let data: Box<dyn Any> = Box::new(build(k0, comp, w)?);
    let entry = Entry {
        k0: key.ok_or_else(internal)?.clone(),
        comp,
        w,
        data: *data.downcast::<ChainData<C>>().map_err(|_| internal())?,
    };
    cache.with(|c| {
        let mut c = c.borrow_mut();
        c.truncate(7);
        c.insert(0, entry);
        match (c.first().and_then(typed::<C, R>), f.take()) {
            (Some(d), Some(f)) => Ok(f(d)),
            _ => Err(internal()),
        }
    })
}

/// Builds the chain data for `k0` (its complement when `comp`) at `w` bits.
fn build<R: Real>(k0: &R, comp: bool, w: u32) -> Result<ChainData<R>, SpecialError> {
    let kw = k0.with_prec(w);
    let kpw = super::agm::complementary(&kw);
    let (k, kp) = if comp { (kpw, kw) } else { (kw, kpw) };
    // fixed precision: the exact top modulus pair at 192 bits for the nome series
    let fixed = super::is_fixed(k0, w);
    let reference = fixed.then(|| {
        let bits = 192;
        let k0f = Float::with_val(bits, k0.to_f64());
        let k0p = super::agm::complementary(&k0f);
        if comp {
            (k0p, k0f)
        } else {
            (k0f, k0p)
        }
    });
    let chain = Chain::new(&k, &kp, reference.as_ref().map(|(a, b)| (a, b)))?;
    let inv_kq = 1.0 / chain.kq.to_f64();
    Ok(ChainData {
        kp,
        inv_kq,
        chain,
        tri: fixed.then(|| quarter_period_triple(k0.to_f64(), comp)),
    })
}
