//! The fixed-precision evaluation (`Real::FIXED`: `f64`, `Dual<f64>`): the per-modulus
//! data ([`FixedModulus`]: the bottom, its theta data, the modulus transformation, all
//! in double-double), the argument reduction, and the per-thread caches of `f64`:
//!
//! * the data of the two most recent moduli asked for more than once, shared by every
//!   `f64` call ([`Real::PLAIN_F64`]; a complex argument needs a modulus and its
//!   complement; a modulus met for the first time is evaluated without an entry);
//!   other fixed-precision types (`Dual`, whose derivative parts differ from call to
//!   call) build their data afresh;
//! * the 150-bit quarter periods used by the exact reduction of large arguments.

use super::bottom::{Bottom, sine_cases, tanh_sech};
use super::dd::{Dd, fast_two_sum, two_sum, with_fma, with_value};
use super::modulus::{Form, Modulus, Spec, quadrant, untransform};
use super::reduce::reduce_dd2;
use super::theta::{SERIES_MAX_M, Theta};
use super::{SpecialError, show};
use crate::numbers::Real;
use rug::Float;
use rug::float::Constant;
use std::cell::RefCell;

/// Per-modulus data of the fixed-precision path (what the per-thread cache keeps): the
/// bottom, its theta data, `κ'²` (for the exact reduction) and the modulus
/// transformation.
#[derive(Clone, Debug)]
pub(crate) struct FixedModulus<R> {
    bottom: Bottom,
    theta: Option<Theta<R>>,
    m: Dd<R>,
    mc: Dd<R>,
    f: Dd<R>,
    form: Form,
}

/// `(sn, cn, dn)(u)` for the modulus `spec` in fixed precision: through the cached
/// data for `f64` ([`Real::PLAIN_F64`]), else with data built for this call.
#[inline(always)]
pub(crate) fn sncndn_fixed<R: Real>(u: &R, spec: Spec<'_, R>) -> Result<(R, R, R), SpecialError> {
    if R::PLAIN_F64 {
        let uf = u.to_f64();
        let (s, c, d) = spec.with_f64(|sf| sncndn_cached_f64(uf, sf))?;
        return Ok((u.from_f64(s), u.from_f64(c), u.from_f64(d)));
    }
    with_fma(
        #[inline(always)]
        || FixedModulus::new(spec).eval(u),
    )
}

/// An error with the index of the argument it is about.
pub(crate) type AtIndex = (usize, SpecialError);

/// The `f64` path of [`sncndn_fixed`]: the cached data of `sf` and the evaluation,
/// compiled into the FMA clone.  Not generic and never inlined, so that it is compiled
/// once, in this crate, and not again in every crate that calls the generic entry
/// points (the whole fixed-precision path is `#[inline(always)]`; in the merged
/// documentation examples these copies were a third of the generated code).
#[inline(never)]
fn sncndn_cached_f64(u: f64, sf: Spec<'_, f64>) -> Result<(f64, f64, f64), SpecialError> {
    FixedModulus::with_cached(
        sf,
        #[inline(always)]
        |fm| fm.eval(&u),
    )
}

/// The `f64` path of [`sncndn_fixed_many`]; compiled once, as [`sncndn_cached_f64`] is.
#[inline(never)]
fn sncndn_cached_f64_many(us: &[f64], sf: Spec<'_, f64>) -> Result<Vec<(f64, f64, f64)>, AtIndex> {
    FixedModulus::with_cached(
        sf,
        #[inline(always)]
        |fm| fm.eval_all(us),
    )
}

/// [`sncndn_fixed`] for every `u` of `us` with one modulus, looked up once; an error
/// comes with the index of its argument.
#[inline(always)]
pub(crate) fn sncndn_fixed_many<R: Real>(
    us: &[R],
    spec: Spec<'_, R>,
) -> Result<Vec<(R, R, R)>, AtIndex> {
    if R::PLAIN_F64 {
        // `R` is `f64`: both conversions are copies
        let uf: Vec<f64> = us.iter().map(|u| u.to_f64()).collect();
        let v = spec.with_f64(|sf| sncndn_cached_f64_many(&uf, sf))?;
        let back =
            |((s, c, d), u): ((f64, f64, f64), &R)| (u.from_f64(s), u.from_f64(c), u.from_f64(d));
        return Ok(v.into_iter().zip(us).map(back).collect());
    }
    with_fma(
        #[inline(always)]
        || FixedModulus::new(spec).eval_all(us),
    )
}

/// `1 − x` as a normalised double-double, for any `x`.
#[inline(always)]
fn one_minus_any<R: Real>(x: &Dd<R>) -> Dd<R> {
    let (s, e) = two_sum(1.0, -x.v());
    Dd {
        hi: with_value(&(x.hi.one() - x.hi.clone()), s),
        lo: e - x.lo,
    }
    .norm()
}

/// `1 − x` as a normalised double-double, for `0 ≤ x ≤ 1` with `|x.lo| ≤ ulp(x.hi)`:
/// `1 − x.hi` is exact for `x.hi ≥ ½` (Sterbenz) and at least `½` otherwise, so both
/// sums are fast two-sums ([`fast_two_sum`]).
#[inline(always)]
fn one_minus<R: Real>(x: &Dd<R>) -> Dd<R> {
    let (s, e) = fast_two_sum(1.0, -x.v());
    let (h, l) = fast_two_sum(s, e - x.lo);
    Dd {
        hi: with_value(&(x.hi.one() - x.hi.clone()), h),
        lo: l,
    }
}

/// `(κ², κ'², f, form)` of a [`Spec`] in double-double, `κ²` and `κ'²` normalised (as
/// [`Theta::with_bottom`] takes them).
#[inline(always)]
fn fixed_modulus<R: Real>(spec: Spec<'_, R>) -> (Dd<R>, Dd<R>, Dd<R>, Form) {
    let dd = |x: &R| Dd::from(x.clone());
    match spec {
        Spec::Modulus(k, modulus) if *k <= k.one() => {
            let k2 = dd(k).sqr();
            let c = one_minus(&k2);
            let one = dd(&k.one());
            match modulus {
                Modulus::K => (k2, c, one, Form::Direct),
                Modulus::Complement => (c, k2, one, Form::Direct),
            }
        }
        Spec::Modulus(k, _) if k.to_f64() > 1e150 => {
            // κ = 1/k, where k² would overflow: κ² = (1/k)², κ'² = (1 − κ)(1 + κ)
            let inv = dd(&k.one()).div(&dd(k));
            let m = inv.sqr();
            let mc = one_minus_any(&m);
            (m.norm(), mc, dd(k), Form::Reciprocal)
        }
        Spec::Modulus(k, _) => {
            // κ = 1/k: κ² = 1/k², κ'² = (k − 1)(k + 1)/k²
            let m = dd(&k.one()).div(&dd(k).sqr());
            let km1 = dd(k).add_r(&(-k.one()));
            let kp1 = dd(k).add_r(&k.one());
            let mc = km1.mul(&kp1).mul(&m).norm();
            (m.norm(), mc, dd(k), Form::Reciprocal)
        }
        Spec::Parameter(m) if *m < m.zero() => {
            let opm = one_minus_any(&dd(m));
            let inv = dd(&m.one()).div(&opm);
            (
                inv.mul_r(&-m.clone()).norm(),
                inv.norm(),
                opm.sqrt(),
                Form::Imaginary,
            )
        }
        Spec::Parameter(m) if *m <= m.one() => {
            (dd(m), one_minus(&dd(m)), dd(&m.one()), Form::Direct)
        }
        Spec::Parameter(m) => {
            let inv = dd(&m.one()).div(&dd(m));
            let c = dd(m).add_r(&(-m.one())).mul(&inv);
            (inv.norm(), c.norm(), dd(m).sqrt(), Form::Reciprocal)
        }
    }
}

impl<R: Real> FixedModulus<R> {
    /// The data of `spec`: the bottom by the special cases of `jacobi::sncndn_imp`.
    #[inline(always)]
    pub(crate) fn new(spec: Spec<'_, R>) -> Self {
        let (m, mc, f, form) = fixed_modulus(spec);
        let bottom = if m.v() == 0.0 {
            Bottom::Sine
        } else if mc.v() == 0.0 {
            Bottom::TanhSech
        } else if m.v() > SERIES_MAX_M {
            Bottom::Imaginary
        } else {
            Bottom::Series
        };
        let theta =
            matches!(bottom, Bottom::Series | Bottom::Imaginary).then(|| Theta::new(&m, &mc));
        FixedModulus {
            bottom,
            theta,
            m,
            mc,
            f,
            form,
        }
    }

    /// [`eval`](Self::eval) for every `u` of `us`; an error comes with the index of its
    /// argument.
    #[inline(always)]
    fn eval_all(&self, us: &[R]) -> Result<Vec<(R, R, R)>, AtIndex> {
        let mut out = Vec::with_capacity(us.len());
        for (i, u) in us.iter().enumerate() {
            out.push(self.eval(u).map_err(|e| (i, e))?);
        }
        Ok(out)
    }

    /// `(sn, cn, dn)(u)`.
    #[inline(always)]
    pub(crate) fn eval(&self, u: &R) -> Result<(R, R, R), SpecialError> {
        let v = match self.form {
            Form::Direct => Dd::from(u.clone()),
            _ => self.f.mul_r(u),
        };
        let out = match (&self.theta, self.bottom) {
            (Some(th), _) => sncndn_theta(&v.hi, v.lo, th, &self.m, &self.mc)?,
            (None, Bottom::TanhSech) => tanh_sech(&v.to_r(), &self.mc.hi),
            (None, _) => sine_cases(&v.to_r()),
        };
        Ok(match self.form {
            Form::Direct => out,
            _ => untransform(self.form, &self.f.to_r(), out),
        })
    }
}

/// The two most recent `f64` moduli that were asked for more than once, with the keys
/// of their specs ([`Spec::key`]), and the keys of the two most recent ones (`seen`).
struct Slots {
    slots: [Option<([u64; 2], FixedModulus<f64>)>; 2],
    next: usize,
    seen: [[u64; 2]; 2],
}

thread_local! {
    static FIXED_F64: RefCell<Slots> = const {
        RefCell::new(Slots { slots: [None, None], next: 0, seen: [[u64::MAX; 2]; 2] })
    };
    static TRIPLES: RefCell<Vec<Triple>> = const { RefCell::new(Vec::new()) };
}

impl FixedModulus<f64> {
    /// Runs `f` on the data of `spec` through the per-thread two-entry cache (a modulus
    /// seen before among the last two replaces the older entry, so the pair of a
    /// modulus and its complement, as a complex argument needs, stays cached; a modulus
    /// seen for the first time is evaluated from data that stay in registers, since
    /// storing them costs about as much as forming them).  The lookup, a new entry and
    /// `f` are compiled together into the FMA clone ([`with_fma`]).
    #[inline(always)]
    fn with_cached<T>(spec: Spec<'_, f64>, f: impl FnOnce(&FixedModulus<f64>) -> T) -> T {
        let key = spec.key();
        FIXED_F64.with(
            #[inline(always)]
            |c| {
                with_fma(
                    #[inline(always)]
                    || {
                        let mut c = c.borrow_mut();
                        let c = &mut *c;
                        if let Some((_, data)) = c.slots.iter().flatten().find(|e| e.0 == key) {
                            return f(data);
                        }
                        if !c.seen.contains(&key) {
                            c.seen = [key, c.seen[0]];
                            return f(&FixedModulus::new(spec));
                        }
                        let i = c.next;
                        c.next = 1 - i;
                        let (_, data) = c.slots[i].insert((key, FixedModulus::new(spec)));
                        f(data)
                    },
                )
            },
        )
    }
}

/// `(sn, cn, dn)(u + u_lo)` on the theta data `th` of the modulus with `κ'² = mc`: the
/// double-double reduction `u·π/(2K) = j·period + w`, or for large or cancelling `w`
/// the exact one ([`reduce_exact`]).
#[inline(always)]
pub(crate) fn sncndn_theta<R: Real>(
    u: &R,
    u_lo: f64,
    th: &Theta<R>,
    m: &Dd<R>,
    mc: &Dd<R>,
) -> Result<(R, R, R), SpecialError> {
    let j = quadrant(th.ratio_of(u.to_f64()), u)?;
    match th.reduce_fast(u, u_lo, j) {
        Some((w, w_lo)) => Ok(th.eval(j, w, w_lo)),
        // (the data by value: `th` need not be stored for the cold path)
        None => reduce_precise(u, u_lo, m.clone(), mc.clone(), th.bottom, j),
    }
}

/// [`sncndn_theta`] when the fast reduction declined: again with the data of the
/// precise scale (formed here, so that the caller's data need not be stored), else the
/// exact reduction.
#[cold]
fn reduce_precise<R: Real>(
    u: &R,
    u_lo: f64,
    m: Dd<R>,
    mc: Dd<R>,
    bottom: Bottom,
    j: i64,
) -> Result<(R, R, R), SpecialError> {
    let precise = Theta::with_bottom(&m, &mc, bottom == Bottom::Imaginary, true);
    match precise.reduce_fast(u, u_lo, j) {
        Some((w, w_lo)) => Ok(precise.eval(j, w, w_lo)),
        None => reduce_exact(u, u_lo, &precise, &mc, j),
    }
}

/// The exact reduction `t = u − jK` with `K` to 150 bits ([`quarter_period_triple`],
/// [`reduce_dd2`]), then `w = t·scale`; `j` is corrected when the `f64` quotient `u/K`
/// rounded to the wrong side of a half-integer.
#[cold]
fn reduce_exact<R: Real>(
    u: &R,
    u_lo: f64,
    th: &Theta<R>,
    mc: &Dd<R>,
    j: i64,
) -> Result<(R, R, R), SpecialError> {
    let tri = quarter_period_triple((mc.v(), mc.lo));
    let kq = th.quarter_period();
    let half = th.period.v() * 0.5 * (1.0 + 2f64.powi(-30));
    let mut j = j;
    for _ in 0..4 {
        let (t, t_lo) = reduce_dd2(u, &kq, j, tri);
        let w = th.scale.mul_r(&t);
        let (h, l) = two_sum(w.v(), w.lo + th.scale.v() * (t_lo + u_lo));
        if h.abs() <= half {
            return Ok(th.eval(j, with_value(&w.hi, h), l));
        }
        j += if h > 0.0 { 1 } else { -1 };
    }
    Err(SpecialError::NoConvergence(format!(
        "argument reduction of u = {} did not settle",
        show(u)
    )))
}

/// Quarter-period cache entry: (bits of κ'² as a double-double, triple-double K).
type Triple = ([u64; 2], [f64; 3]);

/// Entries kept by the quarter-period cache.
const TRIPLE_ENTRIES: usize = 4;

/// The quarter period `K` of the modulus with `κ'² = mc.0 + mc.1` as an unevaluated
/// sum of three doubles (about 150 bits), from a 200-bit MPFR AGM:
/// `K = π/(2·AGM(1, κ'))` (DLMF 19.8.5); the last few are cached per thread.
fn quarter_period_triple(mc: (f64, f64)) -> [f64; 3] {
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
    TRIPLES.with(|c| {
        let mut c = c.borrow_mut();
        c.truncate(TRIPLE_ENTRIES - 1);
        c.insert(0, (key, v));
    });
    v
}
