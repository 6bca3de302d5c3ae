//! Jacobi elliptic functions sn, cn, dn and the amplitude am of a real argument.

use super::reduce::{reduce_dd, with_chain, ChainData};
use super::{check_finite, check_modulus, is_fixed, show, SpecialError, GUARD};
use crate::numbers::Real;

/// A reduced evaluation: `u = j·K + t`, `|t| ≲ K/2`, with `s, c, d = sn, cn, dn(t)`
/// and the (top-level) complementary modulus `kp`, all at the working precision.
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

/// The quadrant `j = round(u/K)` (half away from zero), from `f64` values (exact
/// enough: a wrong `j` at a tie only moves `|t|` a rounding beyond `K/2`).
#[inline]
fn quadrant<R: Real>(u: &R, data: &ChainData<R>) -> Result<i64, SpecialError> {
    let ratio = u.to_f64() * data.inv_kq;
    if ratio.abs() >= 2f64.powi(50) {
        return Err(too_large(ratio, u));
    }
    // round half away from zero without a libm call (|ratio| < 2^50 checked above)
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

/// Fixed-precision types (`f64`, `Dual<f64>`) whose chain ends in the nome series:
/// `(sn, cn, dn)(u)` in one flat pass.  With `j = round(u/K)` the remainder
/// `r = u − jK`, `|r| ≤ K/2`, is formed exactly ([`reduce_dd`], triple-double `K`) and
/// `v = πt/(2K)` for `t = u − 2hK`, `2h = j − (j mod 2)`: for even `j`, `v = πr/(2K)`;
/// for odd `j`, `t = K + r`, so `sin v = cos v_r` and `cos v = −sin v_r` (every output
/// keeps its relative accuracy, e.g. cn next to its zeros at odd multiples of `K`).  The
/// nome series holds for any `v`, so no quotients are needed at the end; `sn`, `cn`
/// change sign with `h` (DLMF 22.4.3).
#[inline]
fn sncndn_series<R: Real>(
    u: &R,
    data: &ChainData<R>,
    tri: [f64; 3],
    scale: &R,
) -> Result<(R, R, R), SpecialError> {
    let j = quadrant(u, data)?;
    let r = remainder(u, data, j, tri);
    let (sr, cr) = (r * scale.clone()).sin_cos_kernel();
    let odd = j.rem_euclid(2);
    let (sv, cv) = if odd == 0 { (sr, cr) } else { (cr, -sr) };
    let (s, c, d) = data.chain.eval_series(&sv, &cv).ok_or_else(no_series)?;
    Ok(half_period_sign(j, (s, c, d)))
}

/// `(sn, cn, dn)(u)` from the values at `t = u − 2hK`, `2h = j − (j mod 2)`: sn and cn
/// change sign with `h` (DLMF 22.4.3, `sn(t + 2K) = −sn t`, `cn(t + 2K) = −cn t`).
#[inline]
fn half_period_sign<R: Real>(j: i64, (s, c, d): (R, R, R)) -> (R, R, R) {
    if (j - j.rem_euclid(2)) / 2 % 2 == 0 {
        (s, c, d)
    } else {
        (-s, -c, d)
    }
}

/// `u − jK` formed exactly with the triple-double `K` ([`reduce_dd`]); `u` for `j = 0`.
#[inline]
fn remainder<R: Real>(u: &R, data: &ChainData<R>, j: i64, tri: [f64; 3]) -> R {
    if j == 0 {
        u.clone()
    } else {
        reduce_dd(u, &data.chain.kq, j, tri)
    }
}

/// Fixed-precision types with `k` near 1 (the chain's imaginary-argument bottom, see
/// `Chain::imaginary_eval`): with `j = round(u/K)`, `r = u − jK` formed exactly,
/// `cn r = 1/C`, `dn r = D/C`; for odd `j` the quarter-period shift (DLMF 22.4.3)
/// becomes `sn = 1/D`, `cn = −k'·sn r·C/D`, `dn = k'C/D` (one quotient each, and cn keeps
/// its relative accuracy next to its zeros); then [`half_period_sign`].
#[inline]
fn sncndn_imaginary<R: Real>(
    u: &R,
    data: &ChainData<R>,
    tri: [f64; 3],
) -> Result<(R, R, R), SpecialError> {
    let j = quadrant(u, data)?;
    let r = remainder(u, data, j, tri);
    let (sn, c_big, d_big) = data.chain.imaginary_eval(&r).ok_or_else(no_series)?;
    let odd = j.rem_euclid(2);
    let (s, c, d) = if odd == 0 {
        (sn, c_big.recip(), d_big / c_big)
    } else {
        // cd = cn/dn = 1/D, −k'·sd = −k'·sn·C/D, k'·nd = k'·C/D (DLMF 22.4.3)
        let kp = data.kp.clone();
        let kc = kp * c_big;
        (
            d_big.recip(),
            -(kc.clone() * sn / d_big.clone()),
            kc / d_big,
        )
    };
    Ok(half_period_sign(j, (s, c, d)))
}

#[cold]
fn no_series() -> SpecialError {
    SpecialError::NoConvergence("internal: chain without a series bottom".into())
}

/// Fixed-precision types (`f64`, `Dual<f64>`): one pass, `t = u − jK` formed with the
/// triple-double `K` ([`reduce_dd`]), for chains without the nome series (tiny `k`,
/// where DLMF 22.10.4–6 needs no Landen level) and for [`am`].
#[inline]
fn reduce_fixed<R: Real>(u: &R, data: &ChainData<R>) -> Result<Reduced<R>, SpecialError> {
    let kq = &data.chain.kq;
    let j = quadrant(u, data)?;
    let t = match data.tri {
        Some(tri) => remainder(u, data, j, tri),
        None => u.clone() - u.from_i64(j) * kq.clone(),
    };
    let (s, c, d) = data.chain.eval(&t, true);
    Ok(Reduced {
        j,
        s,
        c,
        d,
        kp: data.kp.clone(),
    })
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
    let j = quadrant(&uw, data)?;
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
    let (s, c, d) = ch.eval(&t, false);
    let kp = data.kp.clone();
    Ok((Reduced { j, s, c, d, kp }, need))
}

/// `(sn, cn, dn)(u)` at working precision (modulus `k`, or `k'` when `comp`): the
/// reduced evaluation with its quadrant applied.  In fixed precision everything runs
/// inside the cached chain's closure, so only the three values travel back.
#[inline]
pub(crate) fn sncndn_at<R: Real>(
    u: &R,
    k: &R,
    comp: bool,
    n: u32,
) -> Result<(R, R, R), SpecialError> {
    if is_fixed(u, n + GUARD) {
        return with_chain(k, comp, n + GUARD, |data| sncndn_fixed(u, data))?;
    }
    reduced(u, k, comp, n).map(|r| r.finish())
}

/// Fixed precision: `(sn, cn, dn)(u)` on a given chain, by the chain's bottom.
#[inline]
fn sncndn_fixed<R: Real>(u: &R, data: &ChainData<R>) -> Result<(R, R, R), SpecialError> {
    match (data.tri, data.chain.series_scale()) {
        (Some(tri), Some(scale)) => sncndn_series(u, data, tri, scale),
        (Some(tri), None) if data.chain.has_imaginary() => sncndn_imaginary(u, data, tri),
        _ => reduce_fixed(u, data).map(|r| r.finish()),
    }
}

/// [`sncndn`] for many arguments and one modulus: `(sn, cn, dn)(u_i, k)` for every
/// `u_i` of `us`, in order.  Same algorithm and accuracy as [`sncndn`]; the modulus is
/// checked and its chain looked up once for the whole slice (in `f64` that saves about a
/// third of the work per argument), so this is the call for tables, orbits and plots.
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
    let n = k.prec();
    let fixed = us
        .first()
        .is_some_and(|u| u.prec() == n && is_fixed(u, n + GUARD));
    if fixed {
        return with_chain(k, false, n + GUARD, |data| {
            let mut out = Vec::with_capacity(us.len());
            for (i, u) in us.iter().enumerate() {
                match sncndn_fixed(u, data) {
                    Ok(v) => out.push(v),
                    Err(e) => return Err(indexed(i, e)),
                }
            }
            Ok(out)
        })?;
    }
    us.iter()
        .enumerate()
        .map(|(i, u)| sncndn(u, k).map_err(|e| indexed(i, e)))
        .collect()
}

/// Reduced evaluation `u = jK + t`.  Fixed-precision types take one pass
/// ([`reduce_fixed`]); multi-precision ones start at `n + 40` bits and retry with more
/// bits when the reduction `t = u − jK` lost too many.
/// `comp` evaluates for the complementary modulus `k'` (with complement `k`).
#[inline]
pub(crate) fn reduced<R: Real>(
    u: &R,
    k: &R,
    comp: bool,
    n: u32,
) -> Result<Reduced<R>, SpecialError> {
    if is_fixed(u, n + GUARD) {
        return with_chain(k, comp, n + GUARD, |data| reduce_fixed(u, data))?;
    }
    // cn from sn at the top of the chain loses up to log2(1/k') bits (see landen.rs);
    // only multi-precision types use that form and get the extra bits
    let kf = k.to_f64();
    let kp_f = if comp {
        kf
    } else {
        ((1.0 - kf) * (1.0 + kf)).sqrt()
    };
    let extra = if kp_f > 0.0 {
        (-kp_f.log2()).ceil().max(0.0) as u32
    } else {
        n
    };
    let mut w = n + GUARD + extra;
    for _ in 0..6 {
        let (r, need) = with_chain(k, comp, w, |data| reduce_mp(u, w, data))??;
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

/// Jacobi elliptic functions `(sn(u,k), cn(u,k), dn(u,k))` of a real argument `u`,
/// **modulus** `k` (DLMF 22.2; mpmath's `ellipfun(·, u, m=k²)`), `0 ≤ k < 1`.
///
/// Algorithm (see the [module docs](crate::special) for why): reduction `u = jK + t`,
/// `|t| ≤ K/2`, exact to ~2⁻¹⁰⁰·|u|.  Multi-precision: at `N + 40 + log2|j|` bits
/// (adaptive), descending Landen chain (DLMF 22.7.1–3) down to `k_N⁴ < ε`, `sin`/`cos`
/// with the correction DLMF 22.10.4–6, climbing back, quadrant shift DLMF 22.4.3;
/// result rounded once, absolute error `≤ 2^(4−N)`.  `f64`: at most one Landen level
/// (two or three for `0.95 ≲ k ≲ 0.986`) above the nome series DLMF 22.11.1–3 summed as
/// polynomials in `sin²v`, or for `k ≳ 0.986` the series of `k'` at imaginary argument
/// (DLMF Table 22.6.1); measured absolute error below 2 ε.
///
/// Errors: [`SpecialError::ModulusOutOfRange`] unless `0 ≤ k < 1`,
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
/// assert!(sncndn(&0.7_f64, &1.0).is_err());
/// ```
pub fn sncndn<R: Real>(u: &R, k: &R) -> Result<(R, R, R), SpecialError> {
    check_modulus(k)?;
    check_finite(u, "u")?;
    let n = u.prec().max(k.prec());
    let (s, c, d) = sncndn_at(u, k, false, n)?;
    Ok((s.with_prec(n), c.with_prec(n), d.with_prec(n)))
}

/// The Jacobi amplitude `am(u,k)`: the continuous, increasing function with
/// `sin am = sn`, `cos am = cn`, `am(0) = 0` (DLMF 22.16.1), modulus `k`.
///
/// Algorithm: with `u = jK + t` as in [`sncndn`], `am(u) = jπ/2 + ψ` where
/// `ψ = atan2(sn t, cn t)` for even `j` and `ψ = atan2(k' sn t, cn t)` for odd `j`
/// (from DLMF 22.4.3 and `am(u+2K) = am(u)+π`, DLMF 22.16.2).  Error: a few ulp of
/// `max(1,|am|)`.
///
/// Errors: as [`sncndn`].
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
    check_finite(u, "u")?;
    let n = u.prec().max(k.prec());
    let r = reduced(u, k, false, n)?;
    let psi = if r.j.rem_euclid(2) == 0 {
        r.s.atan2(&r.c)
    } else {
        (r.kp.clone() * r.s.clone()).atan2(&r.c)
    };
    let base = r.s.pi().mul_2si(-1) * r.s.from_i64(r.j);
    Ok((base + psi).with_prec(n))
}
