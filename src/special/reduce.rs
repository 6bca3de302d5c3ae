//! Argument reduction helpers for fixed-precision types (`f64`, `Dual<f64>`): a quarter
//! period known to ~150 bits as a triple-double, and an error-free `u − j·P`.

use super::landen::Chain;
use super::SpecialError;
use crate::numbers::Real;
use rug::float::Constant;
use rug::Float;
use std::any::{Any, TypeId};
use std::cell::RefCell;
use std::rc::Rc;

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
/// approximation (which carries derivatives).  `u − j·tri[0]` is formed exactly
/// (FMA product, Sterbenz subtraction); the tail and `j·(p − p.value)` (value zero,
/// derivative `j·dp`) are added afterwards.  For fixed-precision types only (`to_f64`
/// exact on the value).
pub(crate) fn reduce_dd<R: Real>(u: &R, p: &R, j: i64, tri: [f64; 3]) -> R {
    let jf = j as f64;
    let p0 = jf * tri[0];
    let e0 = jf.mul_add(tri[0], -p0);
    let p1 = jf * tri[1];
    let e1 = jf.mul_add(tri[1], -p1);
    let p2 = jf * tri[2];
    let lo = (e0 + p1) + (e1 + p2);
    let dp = p.clone() - u.from_f64(p.to_f64());
    (u.clone() - u.from_f64(p0)) - u.from_f64(lo) - u.from_i64(j) * dp
}

/// The moduli chain for one modulus at one working precision.
pub(crate) struct ChainData<R> {
    /// Complementary modulus at the working precision (`k` itself for `comp`).
    pub kp: R,
    /// The Landen chain (with the quarter period).
    pub chain: Chain<R>,
    /// `1/K` rounded to f64 (for choosing the quadrant).
    pub inv_kq: f64,
    /// The exact quarter period as a triple-double (fixed-precision types only).
    triple: std::cell::OnceCell<[f64; 3]>,
}

impl<R: Real> ChainData<R> {
    /// [`quarter_period_triple`] for this modulus, computed once.
    pub(crate) fn triple(&self, k0: &R, comp: bool) -> [f64; 3] {
        *self
            .triple
            .get_or_init(|| quarter_period_triple(k0.to_f64(), comp))
    }
}

struct Entry<R> {
    k0: R,
    comp: bool,
    w: u32,
    data: Rc<ChainData<R>>,
}

thread_local! {
    static CHAINS: RefCell<Vec<Box<dyn Any>>> = const { RefCell::new(Vec::new()) };
}

/// The chain for modulus `k0` (its complement when `comp`) at `w` bits.  For `f64` and
/// `rug::Float` the last few chains are cached per thread (keyed by the exact value of
/// `k0`, `comp` and `w`), since callers typically evaluate many arguments for one
/// modulus; other types (e.g. `Dual`, whose derivative parts must not be shared) are
/// always computed afresh.
pub(crate) fn chain_for<R: Real>(
    k0: &R,
    comp: bool,
    w: u32,
) -> Result<Rc<ChainData<R>>, SpecialError> {
    let cacheable =
        TypeId::of::<R>() == TypeId::of::<f64>() || TypeId::of::<R>() == TypeId::of::<Float>();
    if cacheable {
        let hit = CHAINS.with(|c| {
            c.borrow().iter().find_map(|e| {
                e.downcast_ref::<Entry<R>>()
                    .filter(|e| e.comp == comp && e.w == w && e.k0 == *k0)
                    .map(|e| e.data.clone())
            })
        });
        if let Some(d) = hit {
            return Ok(d);
        }
    }
    let kw = k0.with_prec(w);
    let kpw = super::agm::complementary(&kw);
    let (k, kp) = if comp { (kpw, kw) } else { (kw, kpw) };
    let chain = Chain::new(&k, &kp)?;
    let inv_kq = 1.0 / chain.kq.to_f64();
    let data = Rc::new(ChainData {
        kp,
        inv_kq,
        chain,
        triple: std::cell::OnceCell::new(),
    });
    if cacheable {
        CHAINS.with(|c| {
            let mut c = c.borrow_mut();
            if c.len() >= 8 {
                c.remove(0);
            }
            c.push(Box::new(Entry {
                k0: k0.clone(),
                comp,
                w,
                data: data.clone(),
            }));
        });
    }
    Ok(data)
}
