//! The nome (Fourier) series of sn, cn, dn (DLMF 22.11.1–3), rewritten as polynomials
//! in `x = sin²v`, for the bottom of the Landen chain in fixed precision.
//!
//! With `q = exp(−πK'/K)` the nome of the modulus `κ` and `v = πu/(2K)`,
//!
//! * `sn = (2π/(κK)) Σₙ qⁿ⁺½/(1 − q²ⁿ⁺¹) · sin((2n+1)v)`  (DLMF 22.11.1)
//! * `cn = (2π/(κK)) Σₙ qⁿ⁺½/(1 + q²ⁿ⁺¹) · cos((2n+1)v)`  (DLMF 22.11.2)
//! * `dn = π/(2K) + (2π/K) Σₙ₌₁ qⁿ/(1 + q²ⁿ) · cos(2nv)`  (DLMF 22.11.3)
//!
//! and `sin((2n+1)v) = sin v · Sₙ(x)`, `cos((2n+1)v) = cos v · Cₙ(x)`,
//! `cos(2nv) = Tₙ(1 − 2x)` with polynomials of degree `n` in `x = sin²v` (Chebyshev
//! recurrences `Sₙ₊₁ = 2(1−2x)Sₙ − Sₙ₋₁`, `S₀ = 1`, `S₋₁ = −1`; the same for `Cₙ` with
//! `C₋₁ = 1`).  Hence `sn = sin v · P(x)`, `cn = cos v · Q(x)`, `dn = R(x)`, and since
//! `cn(0) = dn(0) = 1`, `Q(x) = 1 + x·Q₁(x)` and `R(x) = 1 + x·R₁(x)`.  Written this way
//! every output keeps relative accuracy next to its zeros (factors `sin v`, `cos v`),
//! `1 − dn = −x·R₁(x)` comes without cancellation, and no division is needed.
//!
//! Term `n` is below `qⁿ·(2n+1)` relative to the leading one (`|Sₙ| ≤ 2n+1`), so the
//! series is cut at the first `n` with `qⁿ(2n+1) < 2⁻⁶⁰`; callers descend the Landen
//! chain until `q ≤` [`Q_MAX`] or [`Q_MAX_DEEP`] (each Landen step squares the nome),
//! so at most 19 terms are needed.  The coefficients are summed generically (so that
//! derivatives, e.g. of `Dual` numbers, flow through them) and their values are then
//! replaced by the same sums evaluated in 192-bit MPFR and rounded once.

use super::agm::agm;
use super::SpecialError;
use crate::numbers::Real;
use rug::Float;

/// Largest nome handled by the series at the bottom of a chain with at most one
/// Landen level (17 terms).  Chosen by measurement: at `k = 0.8` (`q = 0.064`) one
/// level and 9 terms are faster than 17 terms, and at `k = 0.99` (`q₁ = 0.053`) one
/// level is more accurate than two.
pub(crate) const Q_MAX: f64 = 0.06;

/// Largest nome accepted once two or more Landen levels have been descended
/// (`k ≳ 0.999`; 19 terms): every level saved there removes about one ulp of error
/// from the climb, at the price of a polynomial conditioning factor
/// `Σ (5.8q)ⁿ ≤ 2.1` (`|Sₙ(x)| ≤ (3+2√2)ⁿ` for the monomial coefficients on `[0, 1]`).
pub(crate) const Q_MAX_DEEP: f64 = 0.09;

/// Above this nome (`k ≳ 0.986`) fixed-precision chains use the series of the
/// complementary modulus at imaginary argument instead of Landen levels with moduli
/// near 1 (each of which adds about one ulp); there `q' = exp(π²/ln q) < 2.2·10⁻³`.
pub(crate) const Q_IMAG: f64 = 0.2;

/// Precision of the reference evaluation of the coefficients.
const REF_BITS: u32 = 192;

/// Polynomial coefficients of the series for one modulus, interleaved for a single
/// fused second-order Horner pass: entry `i` holds the coefficients of `x^(2i)` and
/// `x^(2i+1)` of `P`, `Q₁` and `R₁` (zero-padded to a common even length), where
/// `sn = sin v · P(x)`, `cn = cos v · (1 + x·Q₁(x))`, `dn = 1 + x·R₁(x)`.
pub(crate) struct Fourier<R> {
    pairs: Vec<[R; 6]>,
    /// `Δ = P − (1 + x·Q₁)` (lowest degree first), summed in 192 bits, so that
    /// `sn/cn`-type quotients `P/Q = 1 + Δ/Q` need no cancelling subtraction.
    delta: Vec<R>,
}

/// The nome `q = exp(−πK'/K)` of the modulus `k` with complement `kp` (DLMF 22.2.1,
/// `K = π/(2·AGM(1,k'))`, DLMF 19.8.5).
pub(crate) fn nome<S: Real>(k: &S, kp: &S) -> Result<S, SpecialError> {
    let one = k.one();
    // πK'/K = π·AGM(1,k')/AGM(1,k)
    let ratio = agm(&one, kp)? / agm(&one, k)?;
    Ok((-(k.pi() * ratio)).exp())
}

/// Number of terms for nome `q` (see the module docs).
pub(crate) fn terms(q: f64) -> usize {
    let mut n = 1usize;
    let mut qn = q;
    while qn * (2 * n + 1) as f64 >= 2f64.powi(-60) && n < 64 {
        qn *= q;
        n += 1;
    }
    n
}

/// `[P, Q₁, R₁]` for modulus `k` (complement `kp`) with `m` terms, in type `S`.
fn coefficients<S: Real>(k: &S, kp: &S, m: usize) -> Result<[Vec<S>; 3], SpecialError> {
    let one = k.one();
    let zero = k.zero();
    let two = k.from_i64(2);
    let kk = k.pi() / (two.clone() * agm(&one, kp)?);
    // √q/k without the cancellation of √q and k (both ~ k/4 for small k), which would
    // spoil derivative parts (e.g. d/dk through Dual numbers): below k = 1/2 in fixed
    // precision Jacobi's series q = ε + 2ε⁵ + 15ε⁹ + 150ε¹³ + 1707ε¹⁷ + …, with
    // ε = (1 − √k')/(2(1 + √k')) = k²/(2(1 + k')(1 + √k')²) (DLMF 22.2.2 and the
    // expansion of the nome; the next term 20910ε²¹ is below 2⁻⁵⁷ of the sum for
    // ε ≤ 0.018); otherwise q = exp(−πK'/K).
    let (q, sqrt_q_over_k) = if k.prec() <= 64 && k.to_f64() < 0.5 {
        let spk = kp.sqrt();
        let e_over_k2 =
            (two.clone() * (one.clone() + kp.clone()) * (one.clone() + spk).sqr()).recip();
        let eps = e_over_k2.clone() * k.sqr();
        let e4 = eps.sqr().sqr();
        let series = one.clone()
            + e4.clone()
                * (two.clone()
                    + e4.clone()
                        * (k.from_i64(15)
                            + e4.clone() * (k.from_i64(150) + e4 * k.from_i64(1707))));
        let q_over_k2 = e_over_k2 * series;
        (q_over_k2.clone() * k.sqr(), q_over_k2.sqrt())
    } else {
        let q = nome(k, kp)?;
        let r = q.sqrt() / k.clone();
        (q, r)
    };
    let pre = two.clone() * k.pi() / kk.clone() * sqrt_q_over_k;
    let dpre = two.clone() * k.pi() / kk.clone();
    let step = |cur: &[S], prev: &[S]| step_chebyshev(cur, prev, &zero, &two);
    let (mut s_prev, mut s_cur) = (vec![-one.clone()], vec![one.clone()]);
    let (mut c_prev, mut c_cur) = (vec![one.clone()], vec![one.clone()]);
    let (mut t_prev, mut t_cur) = (vec![one.clone()], vec![one.clone(), -two.clone()]);
    let mut p = vec![zero.clone(); m];
    let mut qq = vec![zero.clone(); m];
    let mut r = vec![zero.clone(); m];
    let mut qn = one.clone(); // q^n
    for n in 0..m {
        let q2 = qn.sqr() * q.clone(); // q^(2n+1)
        let a = pre.clone() * qn.clone() / (one.clone() - q2.clone());
        let b = pre.clone() * qn.clone() / (one.clone() + q2);
        for (i, c) in s_cur.iter().enumerate() {
            p[i] = p[i].clone() + a.clone() * c.clone();
        }
        for (i, c) in c_cur.iter().enumerate() {
            qq[i] = qq[i].clone() + b.clone() * c.clone();
        }
        if n >= 1 {
            let cn = dpre.clone() * qn.clone() / (one.clone() + qn.sqr());
            for (i, c) in t_cur.iter().enumerate().take(m) {
                r[i] = r[i].clone() + cn.clone() * c.clone();
            }
            let t_next = step(&t_cur, &t_prev);
            t_prev = std::mem::replace(&mut t_cur, t_next);
        }
        let s_next = step(&s_cur, &s_prev);
        s_prev = std::mem::replace(&mut s_cur, s_next);
        let c_next = step(&c_cur, &c_prev);
        c_prev = std::mem::replace(&mut c_cur, c_next);
        qn = qn * q.clone();
    }
    // Q(0) = R(0) = 1 exactly (cn(0) = dn(0) = 1): drop the constant terms.
    let q1 = qq.into_iter().skip(1).collect();
    let r1 = r.into_iter().skip(1).collect();
    Ok([p, q1, r1])
}

/// One step `Y_{n+1} = 2(1−2x)·Yₙ − Yₙ₋₁` of the Chebyshev recurrences for `Sₙ`, `Cₙ`
/// and `Tₙ(1−2x)`, on coefficient vectors in `x` (lowest degree first).
fn step_chebyshev<S: Real>(cur: &[S], prev: &[S], zero: &S, two: &S) -> Vec<S> {
    let four = two.clone() * two.clone();
    let mut out = vec![zero.clone(); cur.len() + 1];
    for (i, c) in cur.iter().enumerate() {
        out[i] = out[i].clone() + two.clone() * c.clone();
        out[i + 1] = out[i + 1].clone() - four.clone() * c.clone();
    }
    for (i, c) in prev.iter().enumerate() {
        out[i] = out[i].clone() - c.clone();
    }
    out
}

impl<R: Real> Fourier<R> {
    /// The series for the bottom modulus `k` (complement `kp`) of a fixed-precision
    /// chain; `reference` is the same modulus pair at 192 bits (from the exact top
    /// modulus), whose coefficients replace the values of the generic ones.
    pub(crate) fn new(k: &R, kp: &R, reference: (&Float, &Float)) -> Result<Self, SpecialError> {
        Self::with_terms(k, kp, reference, terms(nome(k, kp)?.to_f64()))
    }

    /// [`Fourier::new`] with `m` terms.
    pub(crate) fn with_terms(
        k: &R,
        kp: &R,
        reference: (&Float, &Float),
        m: usize,
    ) -> Result<Self, SpecialError> {
        let generic = coefficients(k, kp, m)?;
        let (rk, rkp) = reference;
        let exact = coefficients(
            &Float::with_val(REF_BITS, rk),
            &Float::with_val(REF_BITS, rkp),
            m,
        )?;
        // keep the derivative part of each generic coefficient, take the value of the
        // reference one (rounded once)
        let fix = |g: Vec<R>, e: Vec<Float>| -> Vec<R> {
            g.into_iter()
                .zip(e)
                .map(|(g, e)| g.clone() + g.from_f64(e.to_f64() - g.to_f64()))
                .collect()
        };
        let [gp, gq, gr] = generic;
        let [ep, eq, er] = exact;
        // Δ = P − Q with Q = 1 + x·Q₁: coefficients p₀ − 1, pᵢ − q₁,ᵢ₋₁
        let diff = |p: &[R], q1: &[R], one: R| -> Vec<R> {
            (0..p.len())
                .map(|i| match i {
                    0 => p[0].clone() - one.clone(),
                    _ => p[i].clone() - q1.get(i - 1).cloned().unwrap_or_else(|| one.zero()),
                })
                .collect()
        };
        let gd = diff(&gp, &gq, k.one());
        let one_ref = Float::with_val(REF_BITS, 1);
        let ed: Vec<Float> = (0..ep.len())
            .map(|i| match i {
                0 => Float::with_val(REF_BITS, &ep[0] - &one_ref),
                _ => match eq.get(i - 1) {
                    Some(q) => Float::with_val(REF_BITS, &ep[i] - q),
                    None => ep[i].clone(),
                },
            })
            .collect();
        let delta = fix(gd, ed);
        let (p, q1, r1) = (fix(gp, ep), fix(gq, eq), fix(gr, er));
        let len = m.div_ceil(2);
        let at = |c: &[R], i: usize| c.get(i).cloned().unwrap_or_else(|| k.zero());
        let pairs = (0..len)
            .map(|i| {
                let (a, b) = (2 * i, 2 * i + 1);
                [
                    at(&p, a),
                    at(&p, b),
                    at(&q1, a),
                    at(&q1, b),
                    at(&r1, a),
                    at(&r1, b),
                ]
            })
            .collect();
        Ok(Fourier { pairs, delta })
    }

    /// `(sn, cn, dn, 1 − dn)` at `v` with `sin v`, `cos v` given (`|v| ≤ π/2`).
    ///
    /// The three polynomials are summed in one pass, each as two independent Horner
    /// chains in `x²` (even and odd coefficients), which halves the latency of a plain
    /// Horner rule and lets the six chains run side by side.
    #[inline]
    pub(crate) fn eval(&self, sv: &R, cv: &R) -> (R, R, R, R) {
        let x = sv.sqr();
        let (p, xq, xr) = self.polys(&x);
        let e = -xr;
        let one = sv.one();
        (
            sv.clone() * p,
            cv.clone() + cv.clone() * xq,
            one - e.clone(),
            e,
        )
    }

    /// `(P(x), x·Q₁(x), x·R₁(x))`.  The three polynomials are summed in one pass, each
    /// as two independent Horner chains in `x²` (even and odd coefficients), which
    /// halves the latency of a plain Horner rule and lets the six chains run side by
    /// side.
    #[inline]
    fn polys(&self, x: &R) -> (R, R, R) {
        let x2 = x.sqr();
        let z = x.zero();
        let mut acc = [z.clone(), z.clone(), z.clone(), z.clone(), z.clone(), z];
        for c in self.pairs.iter().rev() {
            for (a, ci) in acc.iter_mut().zip(c) {
                *a = a.clone() * x2.clone() + ci.clone();
            }
        }
        let [pe, po, qe, qo, re, ro] = acc;
        let p = pe + po * x.clone();
        let xq = x.clone() * (qe + qo * x.clone());
        let xr = x.clone() * (re + ro * x.clone());
        (p, xq, xr)
    }

    /// The series at imaginary argument `v = iw` (`sin v = i sinh w`, so `x = −y`,
    /// `y = sinh²w`): `(P(−y)/Q(−y) − 1, Q(−y), 1 − y·R₁(−y))`, where `Q = 1 + x·Q₁`,
    /// i.e. `sn(iw') = i sinh w·P(−y)`, `cn(iw') = cosh w·Q(−y)`, `dn(iw') = 1 − y·R₁(−y)`
    /// for the series variable `w`.  The monomial coefficients alternate in sign, so at
    /// `x = −y` every term is positive (no cancellation).  The ratio `P/Q` is formed as
    /// `1 + Δ/Q` from the separately summed `Δ = P − Q`, so `sn = tanh w·P/Q` keeps the
    /// accuracy of `tanh w`.
    #[inline]
    pub(crate) fn ratios_imaginary(&self, sh: &R) -> (R, R, R) {
        let x = -sh.sqr();
        let (_, xq, xr) = self.polys(&x);
        let mut d = x.zero();
        for c in self.delta.iter().rev() {
            d = d * x.clone() + c.clone();
        }
        let one = sh.one();
        let q = one.clone() + xq;
        (d / q.clone(), q, one + xr)
    }
}
