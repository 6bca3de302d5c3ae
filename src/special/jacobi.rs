//! Jacobi elliptic functions sn, cn, dn and the amplitude am of a real argument: the
//! choice of algorithm ([`sncndn_imp`]) and the public entry points.

use super::cache::{quarter_period_triple, with_chain, with_theta, ChainData};
use super::dd::{two_sum, with_value, Dd};
use super::reduce::reduce_dd2;
use super::theta::{tanh_sech, Theta};
use super::{check_finite, check_modulus, show, SpecialError, GUARD};
use crate::numbers::Real;

/// Which modulus of the pair `(k, k')` an evaluation is for: `k` itself, or its
/// complement `k'` (Jacobi's imaginary transformation, DLMF Table 22.6.1, needs the
/// functions of `k'` for the imaginary part of a complex argument).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Modulus {
    /// The modulus `k`.
    K,
    /// The complementary modulus `k' = √(1 − k²)`, with `k` the exactly given value.
    Complement,
}

/// The algorithm at the bottom of an evaluation of sn, cn, dn (see the module docs of
/// [`crate::special`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Bottom {
    /// `sin`/`cos` with DLMF 22.10.4–6, below a descending Landen chain (multi-precision).
    Sine,
    /// Theta quotients of the nome `q ≤ e^{−π}` (DLMF 22.2.4, 20.2.1–4; fixed precision).
    Series,
    /// Theta quotients of the complementary nome at imaginary argument (DLMF Table
    /// 22.6.1; fixed precision, `κ² > ½`).
    Imaginary,
    /// `tanh`/`sech` with DLMF 22.10.7–9: exact at `κ = 1` (DLMF 22.5.ii).
    TanhSech,
}

/// A real modulus as the caller gave it.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Spec<'a, R> {
    /// The modulus `k ≥ 0` (`k > 1` by DLMF 22.17.2–4), or its complement.
    Modulus(&'a R, Modulus),
    /// The parameter `m = k²`, any real (`m < 0`: imaginary modulus, DLMF 22.17.6–8).
    Parameter(&'a R),
}

/// How the evaluated modulus `κ ∈ [0, 1]` relates to the given one (DLMF §22.17):
/// with `v = f·u`, `Direct`: `(sn, cn, dn)(u) = (s, c, d)(v)`; `Reciprocal` (`k > 1`,
/// `κ = 1/k`, `f = k`): `(s/k, d, c)`; `Imaginary` (`m < 0`, `κ² = −m/(1−m)`,
/// `f = √(1−m)`): `(s/(f d), c/d, 1/d)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Form {
    Direct,
    Reciprocal,
    Imaginary,
}

/// `(sn, cn, dn)` of the evaluated modulus back to the given one (see [`Form`]); `f` is
/// the argument factor.
fn untransform<R: Real>(form: Form, f: &R, (s, c, d): (R, R, R)) -> (R, R, R) {
    match form {
        Form::Direct => (s, c, d),
        Form::Reciprocal => (s / f.clone(), d, c),
        Form::Imaginary => {
            let rd = d.recip();
            (s * rd.clone() / f.clone(), c * rd.clone(), rd)
        }
    }
}

/// `1 − x` as a double-double.
fn one_minus<R: Real>(x: &Dd<R>) -> Dd<R> {
    let (s, e) = two_sum(1.0, -x.v());
    Dd {
        hi: with_value(&(x.hi.one() - x.hi.clone()), s),
        lo: e - x.lo,
    }
    .norm()
}

/// Fixed precision: `(κ², κ'², f, form)` of a [`Spec`] in double-double.
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
        Spec::Modulus(k, _) => {
            // κ = 1/k: κ² = 1/k², κ'² = (k − 1)(k + 1)/k²
            let m = dd(&k.one()).div(&dd(k).sqr());
            let km1 = dd(k).add_r(&(-k.one()));
            let kp1 = dd(k).add_r(&k.one());
            (m.clone(), km1.mul(&kp1).mul(&m), dd(k), Form::Reciprocal)
        }
        Spec::Parameter(m) if *m < m.zero() => {
            let opm = one_minus(&dd(m));
            let inv = dd(&m.one()).div(&opm);
            (inv.mul_r(&-m.clone()), inv, opm.sqrt(), Form::Imaginary)
        }
        Spec::Parameter(m) if *m <= m.one() => {
            (dd(m), one_minus(&dd(m)), dd(&m.one()), Form::Direct)
        }
        Spec::Parameter(m) => {
            let inv = dd(&m.one()).div(&dd(m));
            let c = dd(m).add_r(&(-m.one())).mul(&inv);
            (inv, c, dd(m).sqrt(), Form::Reciprocal)
        }
    }
}

/// Multi-precision: `(κ, modulus, f, form)` of a [`Spec`] at `w` bits.
fn mp_modulus<R: Real>(spec: Spec<'_, R>, w: u32) -> (R, Modulus, R, Form) {
    match spec {
        Spec::Modulus(k, modulus) if *k <= k.one() => (k.clone(), modulus, k.one(), Form::Direct),
        Spec::Modulus(k, _) => {
            let kw = k.with_prec(w);
            (kw.recip(), Modulus::K, kw, Form::Reciprocal)
        }
        Spec::Parameter(m) => {
            let mw = m.with_prec(w);
            let one = mw.one();
            if mw < mw.zero() {
                let opm = one.clone() - mw.clone();
                (
                    (-mw / opm.clone()).sqrt(),
                    Modulus::K,
                    opm.sqrt(),
                    Form::Imaginary,
                )
            } else if mw <= one {
                (mw.sqrt(), Modulus::K, one, Form::Direct)
            } else {
                let f = mw.sqrt();
                (f.recip(), Modulus::K, f, Form::Reciprocal)
            }
        }
    }
}

/// `(sn, cn, dn)(u)` for the modulus `spec`, at working precision (at least `n` bits;
/// the caller rounds).  The one place where the algorithm is chosen; the special cases
/// are tried in order:
///
/// 1. outside `[0, 1]`: the modulus transformations DLMF 22.17.2–4 (`k > 1`) and
///    22.17.6–8 (`m < 0`) to a modulus `κ ∈ [0, 1]` (see [`Form`]);
/// 2. `κ = 0`: `(sin u, cos u, 1)` (DLMF 22.5.3);
/// 3. `κ = 1`: `(tanh u, sech u, sech u)` (DLMF 22.5.ii, [`Bottom::TanhSech`]);
/// 4. fixed precision (`R::FIXED`): theta quotients, [`Bottom::Series`] for `κ² ≤ ½`
///    (DLMF 22.2.4), [`Bottom::Imaginary`] above (DLMF Table 22.6.1), with per-modulus
///    data in double-double (module `theta`);
/// 5. multi-precision: the descending Landen chain down to `κ_N⁴ < ε` and
///    [`Bottom::Sine`] (DLMF 22.7.1–3, 22.10.4–6) with guard bits.
pub(crate) fn sncndn_imp<R: Real>(
    u: &R,
    spec: Spec<'_, R>,
    n: u32,
) -> Result<(R, R, R), SpecialError> {
    if R::FIXED {
        let (m, mc, f, form) = fixed_modulus(spec);
        let v = match form {
            Form::Direct => Dd::from(u.clone()),
            _ => f.mul_r(u),
        };
        let bottom = if m.v() == 0.0 {
            Bottom::Sine
        } else if mc.v() == 0.0 {
            Bottom::TanhSech
        } else if m.v() > 0.5 {
            Bottom::Imaginary
        } else {
            Bottom::Series
        };
        let out = match bottom {
            Bottom::Sine => sine_cases(&v.to_r()),
            Bottom::TanhSech => tanh_sech(&v.to_r(), &mc.hi),
            Bottom::Series | Bottom::Imaginary => {
                with_theta(&m, &mc, |th| sncndn_theta(&v.hi, v.lo, th, &mc))?
            }
        };
        return Ok(untransform(form, &f.to_r(), out));
    }
    let w = n + GUARD;
    let (kappa, modulus, f, form) = mp_modulus(spec, w);
    let direct = form == Form::Direct;
    let (v, n) = if direct {
        (u.clone(), n)
    } else {
        (u.with_prec(w) * f.clone(), w)
    };
    let one = kappa.one();
    let (is_zero, is_one) = match modulus {
        Modulus::K => (kappa.is_zero(), kappa == one),
        Modulus::Complement => (kappa == one, kappa.is_zero()),
    };
    let bottom = if is_one {
        Bottom::TanhSech
    } else {
        Bottom::Sine
    };
    let out = match bottom {
        Bottom::TanhSech => tanh_sech(&v.with_prec(n + GUARD), &kappa.zero()),
        _ if is_zero => sine_cases(&v.with_prec(n + GUARD)),
        _ => reduced(&v, &kappa, modulus, n)?.finish(),
    };
    Ok(untransform(form, &f, out))
}

/// `κ = 0`: `(sin u, cos u, 1)` (DLMF 22.5.3; [`Bottom::Sine`] without Landen levels).
fn sine_cases<R: Real>(u: &R) -> (R, R, R) {
    let (s, c) = u.sin_cos();
    (s, c, u.one())
}

/// The quadrant `j = round(u/K)` (half away from zero) from `ratio = u/K` in `f64`.
#[inline]
fn quadrant<R: Real>(ratio: f64, u: &R) -> Result<i64, SpecialError> {
    if ratio.is_nan() || ratio.abs() >= 2f64.powi(50) {
        return Err(too_large(ratio, u));
    }
    Ok(if ratio >= 0.0 {
        (ratio + 0.5) as i64
    } else {
        (ratio - 0.5) as i64
    })
}

#[cold]
fn too_large<R: Real>(ratio: f64, u: &R) -> SpecialError {
    SpecialError::ArgumentTooLarge(format!(
        "|u|/K = {:e} >= 2^50 (u = {})",
        ratio.abs(),
        show(u)
    ))
}

/// Fixed precision: `(sn, cn, dn)(u + u_lo)` on the theta data `th` of the modulus with
/// `κ'² = mc`: the double-double reduction `u·π/(2K) = j·period + w`, or for large or
/// cancelling `w` the exact one ([`reduce_exact`]).
#[inline]
pub(crate) fn sncndn_theta<R: Real>(
    u: &R,
    u_lo: f64,
    th: &Theta<R>,
    mc: &Dd<R>,
) -> Result<(R, R, R), SpecialError> {
    let j = quadrant(th.ratio_of(u.to_f64()), u)?;
    match th.reduce_fast(u, u_lo, j) {
        Some((w, w_lo)) => Ok(th.eval(j, w, w_lo)),
        None => reduce_exact(u, u_lo, th, mc, j),
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

/// One multi-precision attempt at working precision `w`; returns the evaluation and
/// the number of extra bits the reduction needed (for the adaptive retry).
fn reduce_mp<R: Real>(
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
    let (s, c, d) = ch.eval(&t);
    let kp = data.kp.clone();
    Ok((Reduced { j, s, c, d, kp }, need))
}

/// Multi-precision reduced evaluation `u = jK + t` for the modulus `k` (or its
/// complement): starts at `n + 40 + log2(1/k')` bits and retries with more bits when
/// the reduction `t = u − jK` lost too many.
pub(crate) fn reduced<R: Real>(
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
        let (r, need) = with_chain(k, modulus, w, |data| reduce_mp(u, w, data))??;
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

/// [`sncndn`] for many arguments and one modulus: `(sn, cn, dn)(u_i, k)` for every
/// `u_i` of `us`, in order.  Same algorithm and accuracy as [`sncndn`]; in fixed
/// precision the modulus is checked and its data looked up once for the whole slice,
/// so this is the call for tables, orbits and plots.
///
/// Errors: as [`sncndn`]; an argument error names its index in `us`.
///
/// ```
/// use eulertop::special::{sncndn, sncndn_many};
/// let us = [0.1_f64, 0.7, 2.5, -40.0];
/// let many = sncndn_many(&us, &0.8).unwrap();
/// for (u, v) in us.iter().zip(&many) {
///     assert_eq!(*v, sncndn(u, &0.8).unwrap());
/// }
/// assert!(sncndn_many(&[0.1, f64::NAN], &0.8).unwrap_err().to_string().contains("u[1]"));
/// ```
pub fn sncndn_many<R: Real>(us: &[R], k: &R) -> Result<Vec<(R, R, R)>, SpecialError> {
    check_modulus(k)?;
    let name = |i: usize| format!("u[{i}]");
    if let Some(i) = us.iter().position(|u| !u.is_finite()) {
        check_finite(&us[i], &name(i))?;
    }
    let indexed = |i: usize, e: SpecialError| match e {
        SpecialError::ArgumentTooLarge(m) => {
            SpecialError::ArgumentTooLarge(format!("{}: {m}", name(i)))
        }
        other => other,
    };
    let (m, mc, _, form) = if R::FIXED {
        fixed_modulus(Spec::Modulus(k, Modulus::K))
    } else {
        let zero = Dd::from(k.zero());
        (zero.clone(), zero.clone(), zero, Form::Imaginary)
    };
    if form == Form::Direct && m.v() > 0.0 && mc.v() > 0.0 {
        return with_theta(&m, &mc, |th| {
            let mut out = Vec::with_capacity(us.len());
            for (i, u) in us.iter().enumerate() {
                match sncndn_theta(u, 0.0, th, &mc) {
                    Ok(v) => out.push(v),
                    Err(e) => return Err(indexed(i, e)),
                }
            }
            Ok(out)
        });
    }
    us.iter()
        .enumerate()
        .map(|(i, u)| sncndn(u, k).map_err(|e| indexed(i, e)))
        .collect()
}

/// Jacobi elliptic functions `(sn(u,k), cn(u,k), dn(u,k))` of a real argument `u`,
/// **modulus** `k ≥ 0` (DLMF 22.2; mpmath's `ellipfun(·, u, m=k²)`); `k = 1` gives
/// `(tanh u, sech u, sech u)` (DLMF 22.5.ii) and `k > 1` is taken to `1/k` by DLMF
/// 22.17.2–4.  For the parameter `m = k²` (also `m < 0`) see [`sncndn_m`].
///
/// Algorithm (see the [module docs](crate::special) for why).  `f64`: theta quotients
/// of a nome `q ≤ e^{−π}` (DLMF 22.2.4; for `k² > ½` those of `k'` at imaginary
/// argument, DLMF Table 22.6.1) with every per-modulus quantity in double-double, so a
/// new `k` costs about one evaluation; measured absolute error below 2 ε.
/// Multi-precision: reduction `u = jK + t` at `N + 40 + log2|j|` bits (adaptive),
/// descending Landen chain (DLMF 22.7.1–3) down to `k_N⁴ < ε`, `sin`/`cos` with the
/// correction DLMF 22.10.4–6, climbing back, quadrant shift DLMF 22.4.3; result
/// rounded once, absolute error `≤ 2^(4−N)`.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `k ≥ 0` is finite,
/// [`SpecialError::NotFinite`] for a NaN/infinite `u`,
/// [`SpecialError::ArgumentTooLarge`] if `|u|/K ≥ 2⁵⁰`.
///
/// ```
/// use eulertop::special::sncndn;
/// // mpmath: ellipfun('sn', 0.7, m=0.25) = 0.634293276335112372021362809680
/// //         ellipfun('cn', 0.7, m=0.25) = 0.773092516841334311031368435940
/// let (sn, cn, dn) = sncndn(&0.7_f64, &0.5).unwrap();
/// assert!((cn - 0.7730925168413343).abs() < 1e-15);
/// assert!((sn - 0.6342932763351124).abs() < 1e-15);
/// assert!((sn * sn + cn * cn - 1.0).abs() < 1e-15);
/// assert!((dn * dn + 0.25 * sn * sn - 1.0).abs() < 1e-15);
/// // 256 bits: same call with rug::Float
/// let u = rug::Float::with_val(256, 0.7);
/// let k = rug::Float::with_val(256, 0.5);
/// let (sn256, _, _) = sncndn(&u, &k).unwrap();
/// assert!((sn256 - sn).abs() < 1e-15);
/// // k = 1: tanh, sech, sech
/// let (s1, c1, _) = sncndn(&0.7_f64, &1.0).unwrap();
/// assert!((s1 - 0.7_f64.tanh()).abs() < 1e-16 && (c1 - 1.0 / 0.7_f64.cosh()).abs() < 1e-16);
/// assert!(sncndn(&0.7_f64, &-0.5).is_err());
/// ```
pub fn sncndn<R: Real>(u: &R, k: &R) -> Result<(R, R, R), SpecialError> {
    check_modulus(k)?;
    check_finite(u, "u")?;
    let n = u.prec().max(k.prec());
    let (s, c, d) = sncndn_imp(u, Spec::Modulus(k, Modulus::K), n)?;
    Ok((s.with_prec(n), c.with_prec(n), d.with_prec(n)))
}

/// [`sncndn`] for the **parameter** `m = k²` (the convention of mpmath, SciPy, GSL and
/// Abramowitz–Stegun), any real `m`: `m < 0` is an imaginary modulus (DLMF
/// 22.17.6–8: with `μ = −m`, `κ = √(μ/(1+μ))`, `v = u√(1+μ)`, `sn = κ'·sd(v, κ)`,
/// `cn = cd(v, κ)`, `dn = nd(v, κ)`), `m > 1` a modulus above one (DLMF 22.17.2–4).
/// In `f64` the transformed modulus and argument are formed in double-double.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] for a non-finite `m`; otherwise as
/// [`sncndn`].
///
/// ```
/// use eulertop::special::sncndn_m;
/// // mpmath: ellipfun('sn', 0.7, m=-0.5) = 0.661141183380470455...
/// let (sn, cn, dn) = sncndn_m(&0.7_f64, &-0.5).unwrap();
/// assert!((sn - 0.6611411833804705).abs() < 1e-15);
/// assert!((sn * sn + cn * cn - 1.0).abs() < 1e-15);
/// assert!((dn * dn - 0.5 * sn * sn - 1.0).abs() < 1e-15);
/// ```
pub fn sncndn_m<R: Real>(u: &R, m: &R) -> Result<(R, R, R), SpecialError> {
    if !m.is_finite() {
        return Err(SpecialError::ModulusOutOfRange(format!(
            "parameter m = {} is not finite",
            show(m)
        )));
    }
    check_finite(u, "u")?;
    let n = u.prec().max(m.prec());
    let (s, c, d) = sncndn_imp(u, Spec::Parameter(m), n)?;
    Ok((s.with_prec(n), c.with_prec(n), d.with_prec(n)))
}

/// The Jacobi amplitude `am(u,k)`: the continuous, increasing function with
/// `sin am = sn`, `cos am = cn`, `am(0) = 0` (DLMF 22.16.1), modulus `0 ≤ k ≤ 1`.
///
/// Algorithm: with `j = round(u/K)`, `am(u) = jπ/2 + ψ` (`am(u+2K) = am(u)+π`, DLMF
/// 22.16.2).  Multi-precision: with `u = jK + t` as in [`sncndn`],
/// `ψ = atan2(sn t, cn t)` for even `j` and `ψ = atan2(k' sn t, cn t)` for odd `j`
/// (DLMF 22.4.3).  Fixed precision: `atan2(sn u, cn u)` moved by the multiple of `2π`
/// that brings it next to `jπ/2`.  Error: a few ulp of `max(1,|am|)`.
///
/// Errors: as [`sncndn`]; [`SpecialError::ModulusOutOfRange`] also for `k > 1`.
///
/// ```
/// use eulertop::special::{am, ellipk};
/// // mpmath: ellipf(am, m) inverts am; am(K, k) = π/2
/// let k = 0.9_f64;
/// let kk = ellipk(&k).unwrap();
/// assert!((am(&kk, &k).unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// assert!((am(&(3.0 * kk), &k).unwrap() - 1.5 * std::f64::consts::PI).abs() < 1e-14);
/// ```
pub fn am<R: Real>(u: &R, k: &R) -> Result<R, SpecialError> {
    check_modulus(k)?;
    if *k > k.one() {
        return Err(SpecialError::ModulusOutOfRange(format!(
            "am needs a modulus in [0, 1], not k = {}",
            show(k)
        )));
    }
    check_finite(u, "u")?;
    let n = u.prec().max(k.prec());
    let half_pi = u.pi().mul_2si(-1);
    if R::FIXED || k.is_zero() || *k == k.one() {
        let (s, c, _) = sncndn_imp(u, Spec::Modulus(k, Modulus::K), n)?;
        let psi = s.atan2(&c);
        let j = if *k == k.one() || k.is_zero() {
            (u.to_f64() / std::f64::consts::FRAC_PI_2).round()
        } else {
            (u.to_f64() / super::ellipk(&k.to_f64())?).round()
        };
        if *k == k.one() {
            return Ok(psi.with_prec(n));
        }
        let turns =
            ((j * std::f64::consts::FRAC_PI_2 - psi.to_f64()) / std::f64::consts::TAU).round();
        return Ok((psi + half_pi.mul_2si(2) * u.from_f64(turns)).with_prec(n));
    }
    let r = reduced(u, k, Modulus::K, n)?;
    let psi = if r.j.rem_euclid(2) == 0 {
        r.s.atan2(&r.c)
    } else {
        (r.kp.clone() * r.s.clone()).atan2(&r.c)
    };
    let base = half_pi.with_prec(r.s.prec()) * r.s.from_i64(r.j);
    Ok((base + psi).with_prec(n))
}
