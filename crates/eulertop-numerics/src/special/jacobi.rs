//! Jacobi elliptic functions sn, cn, dn and the amplitude am of a real argument: the
//! choice of algorithm ([`sncndn_imp`]) and the public entry points.

use super::bottom::{Bottom, sine_cases, tanh_sech};
use super::fixed::{sncndn_fixed, sncndn_fixed_many};
use super::modulus::{Form, Modulus, Spec, mp_modulus, untransform};
use super::multi::reduced;
use super::{GUARD, SpecialError, check_finite, check_modulus, even_modulus, show};
use crate::numbers::Real;

/// `(sn, cn, dn)(u)` for the modulus `spec`, at working precision (at least `n` bits;
/// the caller rounds).  The one place where the algorithm is chosen; the special cases
/// are tried in order:
///
/// 1. outside `[0, 1]`: the modulus transformations DLMF 22.17.2–4 (`k > 1`) and
///    22.17.6–8 (`m < 0`) to a modulus `κ ∈ [0, 1]` (see [`Form`]);
/// 2. `κ = 0`: `(sin u, cos u, 1)` (DLMF 22.5.3);
/// 3. `κ = 1`: `(tanh u, sech u, sech u)` (DLMF 22.5.ii, [`Bottom::TanhSech`]);
/// 4. fixed precision (`R::FIXED`): theta quotients, [`Bottom::Series`] for `κ² ≤ 0.81`
///    (DLMF 22.2.4), [`Bottom::Imaginary`] above (DLMF Table 22.6.1), with per-modulus
///    data in double-double (module `theta`);
/// 5. multi-precision: the descending Landen chain down to `κ_N⁴ < ε` and
///    [`Bottom::Sine`] (DLMF 22.7.1–3, 22.10.4–6) with guard bits; when the modulus
///    had to be transformed (a parameter, `k > 1`) and the result lies next to a zero
///    of sn, cn or dn, again with the bits that the rounded `κ` and `f·u` cost there
///    ([`lost_bits`]).
pub(crate) fn sncndn_imp<R: Real>(
    u: &R,
    spec: Spec<'_, R>,
    n: u32,
) -> Result<(R, R, R), SpecialError> {
    if R::FIXED {
        return sncndn_fixed(u, spec);
    }
    let out = sncndn_mp(u, spec, n, n + GUARD)?;
    // the modulus exactly as given: nothing was rounded before the reduction, which
    // measures `u` from the nearest multiple of `K` adaptively
    if matches!(spec, Spec::Modulus(k, _) if *k <= k.one()) {
        return Ok(out);
    }
    // a transformed modulus `κ` (and argument `f·u`) were rounded to `n + GUARD` bits:
    // next to a zero of sn, cn or dn that rounding moves the result by its condition
    // number, so the evaluation is repeated with that many more bits
    match lost_bits(u, &out) {
        0 => Ok(out),
        extra => sncndn_mp(u, spec, n, n + GUARD + extra),
    }
}

/// An estimate of the bits that the rounding of a transformed modulus and argument to
/// the working precision may have cost `(s, c, d) = (sn, cn, dn)(u)`: with `b` the
/// `log2` of the largest of `|u·cn·dn/sn|`, `|u·sn·dn/cn|`, `|u·sn·cn/dn|` (the relative
/// condition numbers with respect to `u`, DLMF 22.13.1–3, with the parameter taken as
/// 1), `2b + 16` (the rounded modulus moves the zeros as well, by up to a factor `1/κ'²`
/// more where `κ → 1`); `0` when `b < 16`.
fn lost_bits<R: Real>(u: &R, (s, c, d): &(R, R, R)) -> u32 {
    let (sf, cf, df, uf) = (s.to_f64(), c.to_f64(), d.to_f64(), u.to_f64().abs());
    let kappa = [uf * cf * df / sf, uf * sf * df / cf, uf * sf * cf / df]
        .into_iter()
        .map(f64::abs)
        .filter(|x| x.is_finite())
        .fold(1.0, f64::max);
    let bits = kappa.log2().ceil() as u32;
    if bits < 16 { 0 } else { 2 * bits + 16 }
}

/// The multi-precision evaluation of [`sncndn_imp`] with the transformed modulus and
/// argument (DLMF §22.17) formed at `w` bits.
fn sncndn_mp<R: Real>(u: &R, spec: Spec<'_, R>, n: u32, w: u32) -> Result<(R, R, R), SpecialError> {
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

/// [`sncndn`] for many arguments and one modulus: `(sn, cn, dn)(u_i, k)` for every
/// `u_i` of `us`, in order.  Same algorithm and accuracy as [`sncndn`]; in fixed
/// precision the modulus is checked and its data looked up once for the whole slice,
/// so this is the call for tables, orbits and plots.
///
/// Errors: as [`sncndn`]; an argument error names its index in `us`.
///
/// ```
/// use eulertop_numerics::special::{sncndn, sncndn_many};
/// let us = [0.1_f64, 0.7, 2.5, -40.0];
/// let many = sncndn_many(&us, &0.8).unwrap();
/// for (u, v) in us.iter().zip(&many) {
///     assert_eq!(*v, sncndn(u, &0.8).unwrap());
/// }
/// assert!(sncndn_many(&[0.1, f64::NAN], &0.8).unwrap_err().to_string().contains("u[1]"));
/// ```
pub fn sncndn_many<R: Real>(us: &[R], k: &R) -> Result<Vec<(R, R, R)>, SpecialError> {
    if R::BY_RULE {
        return us.iter().map(|u| sncndn(u, k)).collect();
    }
    let k = &even_modulus(k)?;
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
    if R::FIXED {
        return sncndn_fixed_many(us, Spec::Modulus(k, Modulus::K)).map_err(|(i, e)| indexed(i, e));
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
/// of a nome `q < 0.1` (DLMF 22.2.4; for `k² > 0.81` those of `k'` at imaginary
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
/// use eulertop_numerics::special::sncndn;
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
/// // sn, cn, dn depend on k² only (DLMF 22.17.1)
/// assert_eq!(sncndn(&0.7_f64, &-0.5).unwrap(), sncndn(&0.7_f64, &0.5).unwrap());
/// ```
pub fn sncndn<R: Real>(u: &R, k: &R) -> Result<(R, R, R), SpecialError> {
    if R::BY_RULE {
        return R::sncndn_by_rule(u, k).map_err(SpecialError::Rule);
    }
    let k = &even_modulus(k)?;
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
/// use eulertop_numerics::special::sncndn_m;
/// // mpmath: ellipfun('sn', 0.7, m=-0.5) = 0.66395932651367945152
/// let (sn, cn, dn) = sncndn_m(&0.7_f64, &-0.5).unwrap();
/// assert!((sn - 0.6639593265136795).abs() < 1e-15);
/// assert!((sn * sn + cn * cn - 1.0).abs() < 1e-15);
/// assert!((dn * dn - 0.5 * sn * sn - 1.0).abs() < 1e-15);
/// ```
pub fn sncndn_m<R: Real>(u: &R, m: &R) -> Result<(R, R, R), SpecialError> {
    super::refuse_by_rule::<R>("sn, cn, dn of a parameter m")?;
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
/// use eulertop_numerics::special::{am, ellipk};
/// // mpmath: ellipf(am, m) inverts am; am(K, k) = π/2
/// let k = 0.9_f64;
/// let kk = ellipk(&k).unwrap();
/// assert!((am(&kk, &k).unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// assert!((am(&(3.0 * kk), &k).unwrap() - 1.5 * std::f64::consts::PI).abs() < 1e-14);
/// ```
pub fn am<R: Real>(u: &R, k: &R) -> Result<R, SpecialError> {
    if R::BY_RULE {
        return R::am_by_rule(u, k).map_err(SpecialError::Rule);
    }
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
