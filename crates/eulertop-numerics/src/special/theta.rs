//! The fixed-precision bottoms (`f64`, `Dual<f64>`): sn, cn, dn as quotients of theta
//! functions of a small nome, with every per-modulus quantity computed in `f64` /
//! double-double (no multi-precision arithmetic), so a new modulus costs about as much
//! as one evaluation.
//!
//! For the modulus `κ` with nome `q = exp(−πK'/K)` and `ζ = πu/(2K)` (DLMF 22.2.4,
//! theta functions DLMF 20.2.1–4):
//!
//! * `sn = θ₃(0)/θ₂(0) · θ₁(ζ)/θ₄(ζ)`, `cn = θ₄(0)/θ₂(0) · θ₂(ζ)/θ₄(ζ)`,
//!   `dn = θ₄(0)/θ₃(0) · θ₃(ζ)/θ₄(ζ)`.
//!
//! [`Bottom::Series`] takes these for `κ² ≤ 0.81` (`q < 0.1`), and
//! [`Bottom::Imaginary`] for `κ² > 0.81` takes them for the complementary modulus `κ'`
//! (nome `q' < 0.013`) at imaginary argument, by Jacobi's imaginary transformation
//! (DLMF Table 22.6.1): `sn(t,κ) = −i sn(it,κ')/cn(it,κ')`, `cn(t,κ) = 1/cn(it,κ')`,
//! `dn(t,κ) = dn(it,κ')/cn(it,κ')`.  With `q < 0.1` five terms of each theta series
//! reach `2⁻⁶²` (the exponents grow like `n²`).  (The series is the cheaper of the two, so
//! it is taken up to `κ = 0.9`; the switch at `q = q' = e^{−π}`, `κ² = ½`, would
//! balance the nomes.)
//!
//! Written with `x = sin²ζ` (resp. `x = −sinh²y` at imaginary argument),
//! `θ₁(ζ)/(2q^¼) = sin ζ·S(x)`, `θ₂(ζ)/(2q^¼) = cos ζ·C(x)`, `θ₃(ζ) = 1 + h(x)`,
//! `θ₄(ζ) = 1 + d(x)` with `S = 1 + s`, `C = 1 + c` and the Chebyshev polynomials
//! `sin((2n+1)ζ)/sin ζ`, `cos((2n+1)ζ)/cos ζ`, `cos 2nζ = Tₙ(1 − 2x)`; then for
//! example `sn = sin ζ·(1 + A/θ₄(ζ))` with `A = (r − 1)(1 + s) + (s − d)`,
//! `r = θ₃(0)/θ₂(0)`, where `s − d` is summed term by term (the ones cancel
//! symbolically) and `r − 1` from the series of `θ₃(0) − θ₂(0)`.  So every output is
//! `leading factor × (1 + small)`: it keeps the relative accuracy of `sin ζ`, `cos ζ`,
//! `tanh y`, `sech y` (also next to its zeros), and `1 − dn` comes without
//! cancellation.
//!
//! Per-modulus quantities: with `λ` the theta modulus (`κ` or `κ'`), `T = √λ'` (double-
//! double, one Newton step on `λ'² ` = the exact input), the nome from Jacobi's series
//! `q = ε + 2ε⁵ + 15ε⁹ + 150ε¹³ + 1707ε¹⁷ + …`, `ε = (1 − T)/(2(1 + T)) =
//! λ²/(2(1 + λ')(1 + T)²)` (DLMF 22.2.2 and its inversion), and the scale
//! `π/(2K_λ) = AGM(1, λ') = ((1 + T)/(2θ₃(0, q⁴)))²` (two AGM steps take `(1, λ')` to
//! `θ₃(q⁴)²/θ₃(q)²·(1, …)`, DLMF 19.8.1 with 20.7.E: `θ₃(q)² = AGM(1, λ')⁻¹`), with
//! `θ₃(0, q⁴)⁻²` as a series in `ε⁴` ([`ScaleKind`]), in double-double (the scale to
//! between `2⁻⁶⁴` and `2⁻⁹⁵` relative, depending on the modulus), so that `ζ = u·π/(2K)`
//! is exact enough for `|u| ≤ 256 K` with the cancellation the fast reduction accepts
//! ([`Theta::with_bottom`]).  At imaginary argument the period in `y = πt/(2K')` is
//! `πK/(2K') = −ln(q')/2`, also in double-double ([`Dd::ln`]).
//!
//! For `f64` the series (`κ² < 0.8125`) takes the nome and the scale from piecewise
//! polynomial fits in `κ²` instead (module `series_fit`, [`Theta::with_bottom`]): no
//! square root, division or series on the way to the evaluation.

use super::bottom::Bottom;
use super::dd::{Dd, fast_two_sum, two_prod, two_sum, with_value};
use super::series_fit::{FIT_MAX_M, SCALE_BOUND, series_data};
use crate::numbers::Real;

/// `π/2` as a double-double.
const PI_2: (f64, f64) = (std::f64::consts::FRAC_PI_2, 6.123_233_995_736_766e-17);

/// Largest `κ²` taken by [`Bottom::Series`] (nome below 0.1).
pub(crate) const SERIES_MAX_M: f64 = 0.81;

/// Largest quadrant handled by the double-double reduction.  Beyond it (and when the
/// reduced argument cancels by more than 20 bits) the caller reduces with the
/// quarter period known to 150 bits.
const J_FAST: i64 = 256;

/// Largest `κ²` for which the series takes the nome in `f64` ([`ScaleKind::F64`]):
/// there `ε⁴ < 2⁻¹⁸` (at `ε⁴ = 2⁻¹⁸`, `κ² ≈ 0.5078`), so the scale's error is below
/// `2⁻⁶⁵` (measured below `E·2⁻⁴⁸` with `E = 2q⁴ ≤ 2⁻¹⁷`, test
/// `scale_error_within_bound`), as the fast reduction needs for `|j| ≤ 64` (see
/// [`Theta::with_bottom`]); above it (`κ > 1/√2`) `ε` is a double-double
/// ([`ScaleKind::Series`]).  The test is on `κ²`, known at once, rather than on `ε`, so
/// that a new modulus does not wait for the nome to learn which way it goes.
const NOME_F64_MAX_M: f64 = 0.5;

/// The relative cancellation `|w|/|z|` the fast reduction always accepts (with a scale
/// good to `2⁻⁸⁵`: `|z| ≤ 2⁸·⁷` for `|j| ≤ 256`, so `w` keeps `2⁻⁵⁶`).
const CANCEL_PRECISE: f64 = 9.5367431640625e-7; // 2⁻²⁰

/// How the scale `π/(2K)` is formed ([`Nome::scale`]), from the cheapest to the most
/// accurate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum ScaleKind {
    /// The nome in `f64`, `δ` from `E = 2q⁴ + 2q¹⁶` in `f64`: error `E·2⁻⁴⁸` (series,
    /// `κ² ≤ NOME_F64_MAX_M`).
    F64,
    /// `ε` in double-double, `δ` from its series in `ε⁴` with the leading term in
    /// double-double: error `ε⁸·2⁻⁴⁶ + 2⁻⁹⁵` (the other moduli).
    Series,
    /// `1/θ₃(0, q⁴)` in double-double: error `2⁻⁸⁵` (the retry of a declined
    /// reduction).
    Precise,
}

/// Per-modulus data of the fixed-precision theta bottoms.
#[derive(Clone, Debug)]
pub(crate) struct Theta<R> {
    /// [`Bottom::Series`] or [`Bottom::Imaginary`].
    pub bottom: Bottom,
    /// `q, q², q⁴, q⁶, q⁹, q¹², q¹⁶` of the theta modulus.
    pow: [R; 7],
    /// `ratio − 1` of the theta-null quotients of sn, cn, dn (see [`Theta::new`]).
    ratio: [R; 3],
    /// `π/(2K)` (series) or `π/(2K')` (imaginary argument).
    pub scale: Dd<R>,
    /// The quarter period in the scaled variable: `π/2` or `πK/(2K')`.
    pub period: Dd<R>,
    /// The largest quadrant and the smallest `|w|/|z|` the fast reduction accepts (see
    /// [`Theta::reduce_fast`]): `256` and `2⁻²⁰`, or less where the scale's error bound
    /// is larger (see [`Theta::with_bottom`]).
    j_max: i64,
    cancel: f64,
    /// `1/period` rounded to `f64` (quadrant choice).
    inv_period: f64,
    /// `κ'` of the evaluated modulus (odd quadrants at imaginary argument; zero for the
    /// series, which does not use it).
    kp: R,
}

/// `x^{1/4}` of a positive double-double: two square roots, then one Newton step
/// `t + (x − t⁴)/(4t³)` with `x − t⁴` formed exactly.
#[inline(always)]
fn quarter_root<R: Real>(x: &Dd<R>) -> Dd<R> {
    let t = x.hi.sqrt().sqrt();
    // 1/(4t³) = t/(4t⁴) ≈ t/(4x): the division overlaps the square roots (issued after
    // the first one, which it would otherwise delay on the shared divider)
    let inv4x = 0.25 / x.v();
    let tv = t.to_f64();
    let t2 = Dd::from(t.clone()).sqr();
    let t4 = t2.sqr();
    let resid = (x.v() - t4.v()) + (x.lo - t4.lo);
    Dd {
        lo: resid * (tv * inv4x),
        hi: t,
    }
}

impl<R: Real> Theta<R> {
    /// The data for the modulus `κ` given by `m = κ²` and `mc = κ'² = 1 − κ²` (both as
    /// normalised double-doubles, `0 ≤ m`, `0 < mc`).
    #[inline(always)]
    pub(crate) fn new(m: &Dd<R>, mc: &Dd<R>) -> Self {
        Self::with_bottom(m, mc, m.v() > SERIES_MAX_M, false)
    }

    /// [`Theta::new`] with the bottom chosen by the caller (`imaginary`); both forms are
    /// exact for every modulus, the choice only keeps the nome small (tests cross-check
    /// them where both nomes are moderate).  The scale ([`ScaleKind`], test
    /// `scale_error_within_bound`): for the series up to `κ² = NOME_F64_MAX_M` from the
    /// nome in `f64`, good to `E·2⁻⁴⁸` (about `2⁻⁶⁴`), which the fast reduction allows
    /// for `|u| ≤ 64K` and `|w| ≥ |z|·2⁹E` (at most 8 bits of cancellation); above it
    /// and at imaginary argument from the series of `δ` in `ε⁴`, good to
    /// `ε⁸·2⁻⁴⁶ + 2⁻⁹⁵`: `2⁻⁸⁵` where `ε⁴ < 2⁻²⁰` (every imaginary bottom), `2⁻⁷²` at
    /// `κ² = 0.81`, where the fast reduction accepts 15 bits of cancellation rather
    /// than 20.  `precise` asks for the scale to about `2⁻⁸⁵` for every modulus
    /// (through `1/θ₃(0, q⁴)` in double-double; the retry of a declined reduction).
    /// The series of `f64` (not `precise`) for `κ² < FIT_MAX_M` takes the fits instead
    /// ([`Theta::fitted`]); `Dual` numbers keep the formulas, whose derivative parts
    /// are exact.
    #[inline(always)]
    pub(crate) fn with_bottom(m: &Dd<R>, mc: &Dd<R>, imaginary: bool, precise: bool) -> Self {
        if R::PLAIN_F64 && !imaginary && !precise && m.v() > 0.0 && m.v() < FIT_MAX_M {
            return Self::fitted(m);
        }
        let (a, b) = if imaginary { (mc, m) } else { (m, mc) };
        let kind = if precise {
            ScaleKind::Precise
        } else if imaginary || a.v() > NOME_F64_MAX_M {
            ScaleKind::Series
        } else {
            ScaleKind::F64
        };
        let nome = Nome::new(a, b, kind);
        let pow = powers(&nome.q);
        let scale = nome.scale();
        let one = m.hi.one();
        let period = if imaginary {
            nome.half_log_period()
        } else {
            Dd {
                hi: one.from_f64(PI_2.0),
                lo: PI_2.1,
            }
        };
        // w keeps 2⁻⁵⁷ relative where |w| ≥ |z|·(error bound of the scale)·2⁵⁷ (test
        // `scale_error_within_bound`)
        let e4 = nome.e4.to_f64();
        let (j_max, cancel) = match kind {
            ScaleKind::F64 => (64, (e4 * 1024.0).clamp(2f64.powi(-40), 2f64.powi(-8))),
            ScaleKind::Series => (J_FAST, (e4 * e4 * 2048.0).max(CANCEL_PRECISE)),
            ScaleKind::Precise => (J_FAST, CANCEL_PRECISE),
        };
        Theta {
            cancel,
            bottom: if imaginary {
                Bottom::Imaginary
            } else {
                Bottom::Series
            },
            j_max,
            inv_period: if imaginary {
                1.0 / period.v()
            } else {
                std::f64::consts::FRAC_2_PI
            },
            ratio: ratios(&pow, imaginary),
            pow,
            scale,
            period,
            kp: if imaginary { mc.hi.sqrt() } else { one.zero() },
        }
    }

    /// The series data of an `f64` modulus with `κ² = m < FIT_MAX_M` from the fits in `m`
    /// (module `series_fit`): the scale good to `SCALE_BOUND = 2⁻⁷³`, so the fast
    /// reduction accepts `|j| ≤ 256` and 16 bits of cancellation (`w` keeps `2⁻⁵⁷`).
    #[inline(always)]
    fn fitted(m: &Dd<R>) -> Self {
        let one = m.hi.one();
        let (q, (s_hi, s_lo)) = series_data(m.v(), m.lo);
        let pow = powers(&one.from_f64(q));
        Theta {
            cancel: SCALE_BOUND * 2f64.powi(57),
            bottom: Bottom::Series,
            j_max: J_FAST,
            inv_period: std::f64::consts::FRAC_2_PI,
            ratio: ratios(&pow, false),
            pow,
            scale: Dd {
                hi: one.from_f64(s_hi),
                lo: s_lo,
            },
            period: Dd {
                hi: one.from_f64(PI_2.0),
                lo: PI_2.1,
            },
            kp: one.zero(),
        }
    }

    /// The quarter period `K` of the evaluated modulus (`period/scale`).
    pub(crate) fn quarter_period(&self) -> R {
        self.period.div(&self.scale).to_r()
    }

    /// `u/K` rounded to `f64`.
    #[inline(always)]
    pub(crate) fn ratio_of(&self, u: f64) -> f64 {
        u * self.scale.v() * self.inv_period
    }

    /// Fast reduction of `u + u_lo` (`|u_lo| ≤ ulp(u)`): `(w_hi, w_lo)` with
    /// `u·scale = j·period + w`, or `None` when `|j| > 256` or `|w| < |z|·cancel` (20
    /// bits of cancellation, fewer for the moduli whose scale is less accurate, see
    /// [`Theta::with_bottom`]), so that `w` keeps about 56 bits of relative accuracy;
    /// then the caller retries with the precise scale or reduces with the 150-bit
    /// quarter period.
    #[inline(always)]
    pub(crate) fn reduce_fast(&self, u: &R, u_lo: f64, j: i64) -> Option<(R, f64)> {
        let z = self.scale.mul_r(u);
        let zl = z.lo + self.scale.v() * u_lo;
        if j == 0 {
            return Some((z.hi, zl));
        }
        if j.abs() > self.j_max {
            return None;
        }
        let jf = j as f64;
        let (a, ae) = two_prod(jf, self.period.v());
        let zv = z.v();
        let r1 = zv - a;
        let (h, l) = two_sum(r1, (zl - ae) - jf * self.period.lo);
        if h.abs() < zv.abs() * self.cancel {
            return None;
        }
        let hi = z.hi - self.period.hi.clone() * u.from_i64(j);
        Some((with_value(&hi, h), l))
    }

    /// `(sn, cn, dn)` from the reduced scaled argument `w = w_hi + w_lo` (`|w| ≲
    /// period/2`) in quadrant `j`.
    #[inline(always)]
    pub(crate) fn eval(&self, j: i64, w: R, w_lo: f64) -> (R, R, R) {
        let out = match self.bottom {
            Bottom::Imaginary => self.eval_imaginary(j, w, w_lo),
            _ => self.eval_series(j, w, w_lo),
        };
        half_period_sign(j, out)
    }

    /// [`Bottom::Series`]: `ζ = jπ/2 + w`.
    #[inline(always)]
    fn eval_series(&self, j: i64, w: R, w_lo: f64) -> (R, R, R) {
        let (s0, c0) = w.sin_cos_kernel();
        let lo = w.from_f64(w_lo);
        let s = s0.clone() + c0.clone() * lo.clone();
        let c = c0 - s0 * lo;
        let (sv, cv) = if j & 1 == 0 { (s, c) } else { (c, -s) };
        let x = sv.sqr();
        let [s_, c_, d_, h_] = self.sums(&x);
        let one = x.one();
        let [r_s, r_c, r_d] = &self.ratio;
        let a_s = r_s.clone() * (one.clone() + s_.clone()) + (s_ - d_.clone());
        let a_c = r_c.clone() * (one.clone() + c_.clone()) + (c_ - d_.clone());
        let a_d = r_d.clone() * (one.clone() + h_.clone()) + (h_ - d_.clone());
        let rd = (one.clone() + d_).recip();
        (
            sv.clone() + sv * (a_s * rd.clone()),
            cv.clone() + cv * (a_c * rd.clone()),
            one + a_d * rd,
        )
    }

    /// [`Bottom::Imaginary`]: `y = |w|`, `t = u − jK`, `y = πt/(2K')`.
    #[inline(always)]
    fn eval_imaginary(&self, j: i64, w: R, w_lo: f64) -> (R, R, R) {
        let neg = w.to_f64() < 0.0;
        let (y, y_lo) = if neg { (-w, -w_lo) } else { (w, w_lo) };
        let one = y.one();
        // e = e^y − 1 at y + y_lo (one `expm1`, no square root on the way to sinh y),
        // g = e^y, sinh y = e(1 + 1/g)/2, h = e^{2y} − 1 = e(e + 2)
        let e0 = y.exp_m1();
        let e = e0.clone() + (one.clone() + e0) * y.from_f64(y_lo);
        let g = one.clone() + e.clone();
        let rg = g.recip();
        let sh = e.clone() * (one.clone() + rg.clone()) * one.mul_2si(-1);
        let h = e.clone() * (e + one.mul_2si(1));
        let x = -sh.sqr();
        let [s_, c_, d_, h_] = self.sums(&x);
        let den = one.clone() + c_.clone();
        let [r_s, r_c, r_d] = &self.ratio;
        let b_s = r_s.clone() * (one.clone() + s_.clone()) + (s_ - c_.clone());
        let b_c = r_c.clone() * (one.clone() + d_.clone()) + (d_ - c_.clone());
        let b_d = r_d.clone() * (one.clone() + h_.clone()) + (h_ - c_);
        let (sn, cn, dn) = if j & 1 == 0 {
            let rr = (h.clone() + one.mul_2si(1)).recip();
            let th = h * rr.clone();
            let sech = g.mul_2si(1) * rr;
            let r = den.recip();
            (
                th.clone() + th * (b_s * r.clone()),
                sech.clone() + sech.clone() * (b_c * r.clone()),
                sech.clone() + sech * (b_d * r),
            )
        } else {
            // DLMF 22.4.3: sn(t+K) = cd t, cn(t+K) = −κ' sd t, dn(t+K) = κ' nd t
            let ch = sh.clone() + rg;
            let ww = (den.clone() + b_d.clone()).recip();
            let kw = self.kp.clone() * ww.clone();
            (
                one + (b_c - b_d) * ww,
                -(sh * (den.clone() + b_s) * kw.clone()),
                ch * den * kw,
            )
        };
        if neg {
            if j & 1 == 0 {
                (-sn, cn, dn)
            } else {
                (sn, -cn, dn)
            }
        } else {
            (sn, cn, dn)
        }
    }

    /// `[s, c, d, h]` at `x`: `S = 1 + s`, `C = 1 + c`, `θ₄ = 1 + d`, `θ₃ = 1 + h`.
    #[inline(always)]
    fn sums(&self, x: &R) -> [R; 4] {
        let [q, q2, q4, q6, q9, q12, q16] = &self.pow;
        let one = x.one();
        let t1 = one.clone() - x.mul_2si(1);
        let t1x2 = t1.mul_2si(1);
        let t2 = t1x2.clone() * t1.clone() - one.clone();
        let t3 = t1x2.clone() * t2.clone() - t1.clone();
        let t4 = t2.sqr().mul_2si(1) - one.clone();
        let s1 = t1x2.clone() + one.clone();
        let s2 = t1x2.clone() * s1.clone() - one.clone();
        let s3 = t1x2.clone() * s2.clone() - s1.clone();
        let c1 = t1x2.clone() - one.clone();
        let c2 = t1x2.clone() * c1.clone() - one;
        let c3 = t1x2 * c2.clone() - c1.clone();
        let s = -(q2.clone() * s1) + q6.clone() * s2 - q12.clone() * s3;
        let c = q2.clone() * c1 + q6.clone() * c2 + q12.clone() * c3;
        let even = (q4.clone() * t2 + q16.clone() * t4).mul_2si(1);
        let odd = (q.clone() * t1 + q9.clone() * t3).mul_2si(1);
        [s, c, even.clone() - odd.clone(), even + odd]
    }
}

/// The nome of the theta modulus `λ` (`λ² = a`, `λ'² = b`) and what the scale and the
/// period are made of: `T = √λ'`, `ε = λ²/(2(1 + λ')(1 + T)²)` and Jacobi's series
/// `q = ε(1 + w)`, `w = 2ε⁴ + t₈`, `t₈ = 15ε⁸ + 150ε¹² + 1707ε¹⁶ + …` (OEIS A002103).
struct Nome<R> {
    /// `1 + T`.
    opt: Dd<R>,
    /// `ε` and `ε⁴` in double-double.
    eps: Dd<R>,
    eps4: Dd<R>,
    /// `ε⁴`, `t₈ − 15ε⁸`, `t₈`, `w` in `R`.
    e4: R,
    tail12: R,
    w_tail: R,
    w: R,
    /// The nome.
    q: R,
    /// How the scale is formed.
    kind: ScaleKind,
}

impl<R: Real> Nome<R> {
    #[inline(always)]
    fn new(a: &Dd<R>, b: &Dd<R>, kind: ScaleKind) -> Self {
        let one = a.hi.one();
        let t = quarter_root(b);
        let opt = t.add_r(&one);
        let den = t.sqr().add_r(&one).mul(&opt.sqr()).mul_2si(1);
        // (for the series the quotient itself, a few ulp off, not renormalised, so that
        // the nome does not wait for its correction; the scale takes `ε⁴` from `eps4`)
        let eps = match kind {
            ScaleKind::F64 => Dd::from(a.hi.clone() / den.hi.clone()),
            ScaleKind::Series => a.div(&den),
            ScaleKind::Precise => a.div(&den).norm_fast(),
        };
        let e = eps.hi.clone();
        let e4 = e.sqr().sqr();
        // ε⁴ in double-double: (ε + ε_lo)⁴ = p² + 2p·p_lo + 4p·ε·ε_lo with p + p_lo = ε²
        let ev = e.to_f64();
        let (p, p_lo) = two_prod(ev, ev);
        let (_, p2_lo) = two_prod(p, p);
        let eps4 = Dd {
            hi: e4.clone(),
            lo: p2_lo + 2.0 * p * (p_lo + 2.0 * ev * eps.lo),
        };
        let c = |n: i64| one.from_i64(n);
        // Estrin's scheme in ε⁴ (a shorter dependency chain than Horner's)
        let e8 = e4.sqr();
        let tail12 = e8.clone()
            * e4.clone()
            * ((c(150) + e4.clone() * c(1707))
                + e8.clone()
                    * ((c(20910) + e4.clone() * c(268_616))
                        + e8.clone() * (c(3_567_400) + e4.clone() * c(48_555_069))));
        let w_tail = e8 * c(15) + tail12.clone();
        let w = e4.clone().mul_2si(1) + w_tail.clone();
        let q = e.clone() + e * w.clone() + one.from_f64(eps.lo);
        Nome {
            opt,
            eps,
            eps4,
            e4,
            tail12,
            w_tail,
            w,
            q,
            kind,
        }
    }

    /// `π/(2K_λ) = AGM(1, λ') = ((1 + T)/2)²·(1 − δ)` (two AGM steps take `(1, λ')` to
    /// `θ₃(q⁴)²/θ₃(q)²·(1, …)`, DLMF 19.8.1 with 20.7.E), `1 − δ = θ₃(0, q⁴)⁻²`.
    #[inline(always)]
    fn scale(&self) -> Dd<R> {
        let half_opt = self.opt.mul_2si(-1);
        match self.kind {
            ScaleKind::F64 => return self.scale_f64(&half_opt),
            ScaleKind::Precise => return self.scale_precise(&half_opt),
            ScaleKind::Series => {}
        }
        let s0 = half_opt.sqr();
        // δ = 1 − (1 + E)⁻², E = 2q⁴ + 2q¹⁶, as a series in e = ε⁴ (from Jacobi's series
        // of the nome): δ = 4e + e²·P(e), P = 20 + 176e + 1876e² + 22064e³ + 275568e⁴ +
        // 3584064e⁵ + 47995476e⁶ + 657037228e⁷ (next term 9150654952e¹⁰ < 2⁻⁹⁸ for
        // e ≤ 2⁻¹³, κ² ≤ 0.81); 4e in double-double, e²·P in `R` (a few ulp), so the
        // scale is good to e²·2⁻⁴⁶ (measured e²·2⁻⁴⁶·⁵, test `scale_error_within_bound`)
        let one = self.q.one();
        let c = |n: i64| one.from_i64(n);
        let e = &(self.eps4.hi.clone() + one.from_f64(self.eps4.lo));
        let e2 = e.sqr();
        let e4 = e2.sqr();
        let p = (c(20) + e.clone() * c(176))
            + e2.clone() * (c(1876) + e.clone() * c(22064))
            + e4 * ((c(275_568) + e.clone() * c(3_584_064))
                + e2.clone() * (c(47_995_476) + e.clone() * c(657_037_228)));
        let delta = self.eps4.mul_2si(2).add_r(&(e2 * p));
        let sd = s0.mul(&delta);
        // s0·(1 − δ) with 0 < δ < 2⁻¹⁰: a fast two-sum leaves it normalised to an ulp
        let (h, l) = fast_two_sum(s0.v(), -sd.v());
        Dd {
            hi: with_value(&(s0.hi.clone() - sd.hi), h),
            lo: l + (s0.lo - sd.lo),
        }
    }

    /// [`Nome::scale`] from the nome in `f64` ([`ScaleKind::F64`]): `1 − δ = (1 + E)⁻²`,
    /// `E = 2q⁴ + 2q¹⁶`, `q⁴ = ε⁴(1 + g)`, `g = 8ε⁴ + g₂`.
    #[inline(always)]
    fn scale_f64(&self, half_opt: &Dd<R>) -> Dd<R> {
        let one = self.q.one();
        let e4 = &self.e4;
        // (1 − c')² = (1 + E)⁻² = 1 − δ, δ = E(2 − 3E + 4E² − 5E³) + O(E⁵) with
        // E ≤ 2⁻¹⁷ (NOME_F64_MAX_M): no division after the nome; and with ε⁴ ≤ 2⁻¹⁸
        // `g₂ = 84ε⁸ + 992ε¹² + O(ε¹⁶)` (the next term moves `E` by under 2⁻⁷⁵), straight
        // from `ε⁴` rather than through `w`
        let g2 = e4.sqr() * (one.from_i64(84) + e4.clone() * one.from_i64(992));
        let q4 = e4.clone() * (one.clone() + e4.mul_2si(3) + g2);
        let big_e = (q4.clone() + q4.sqr().sqr()).mul_2si(1);
        let c = |n: i64| one.from_i64(n);
        let delta = big_e.clone()
            * (c(2) + big_e.clone() * (c(-3) + big_e.clone() * (c(4) - big_e.clone() * c(5))));
        let s0 = half_opt.sqr();
        // s0·(1 − δ) with 0 < δ < 2⁻¹⁵: a fast two-sum leaves it normalised to an ulp
        let corr = -(s0.hi.clone() * delta);
        let (h, e) = fast_two_sum(s0.v(), corr.to_f64());
        Dd {
            hi: with_value(&(s0.hi.clone() + corr), h),
            lo: e + s0.lo,
        }
    }

    /// [`Nome::scale`] to about `2⁻⁸⁵` for every modulus: `1 − δ = (1 − c')²`,
    /// `1/θ₃(0, q⁴) = 1 − c'`, `c' = E/(1 + E)`, `E = 2q⁴ + 2q¹⁶`, and `q⁴ = ε⁴(1 + g)`,
    /// `g = (1 + w)⁴ − 1 = 8ε⁴ + g₂`, `g₂ = 4t₈ + w²(6 + 4w + w²)` (about `84ε⁸`), in
    /// double-double.
    #[inline(always)]
    fn scale_precise(&self, half_opt: &Dd<R>) -> Dd<R> {
        let one = self.q.one();
        let w = &self.w;
        let g2 = self.w_tail.mul_2si(2)
            + w.sqr() * (one.from_i64(6) + w.clone() * (one.from_i64(4) + w.clone()));
        let eps4 = &self.eps4;
        let q4 = eps4.add(&eps4.sqr().mul_2si(3).add_r(&(eps4.hi.clone() * g2)));
        let q16 = q4.hi.sqr().sqr();
        let big_e = q4.add_r(&q16).mul_2si(1).norm_fast();
        let ev = big_e.hi.clone();
        let cprime = big_e.add_r(&(-(ev.sqr() / (one.clone() + ev))));
        let neg = Dd {
            hi: -half_opt.hi.clone(),
            lo: -half_opt.lo,
        };
        // (the square is normalised to within an ulp: no renormalisation)
        half_opt.add(&neg.mul(&cprime)).sqr()
    }

    /// `−ln(q)/2` (the quarter period `πK/(2K')` at imaginary argument):
    /// `ln q = ln ε + ln(1 + w)`, `ln(1 + w) = w − w²/2 + w³/3 − w⁴/4
    /// = 2ε⁴ + 13ε⁸ + (t₈ − 15ε⁸) − 2ε⁴t₈ − t₈²/2 + w³(1/3 − w/4)`, the first two terms
    /// from `ε` in double-double ([`Dd::ln`] for `ln ε`).
    #[inline(always)]
    fn half_log_period(&self) -> Dd<R> {
        let one = self.q.one();
        let (w, e4, w_tail) = (&self.w, &self.e4, &self.w_tail);
        let eps4 = &self.eps4;
        let low = self.tail12.clone()
            - (e4.clone() * w_tail.clone()).mul_2si(1)
            - w_tail.sqr().mul_2si(-1)
            + w.sqr() * w.clone() * (one.from_ratio(1, 3) - w.clone() * one.mul_2si(-2));
        let ln1p_w = eps4
            .mul_2si(1)
            .add(&eps4.sqr().mul_r(&one.from_i64(13)))
            .add_r(&low);
        let lnq = self.eps.ln().add(&ln1p_w);
        Dd {
            hi: -lnq.hi.mul_2si(-1),
            lo: -lnq.lo / 2.0,
        }
        .norm_fast()
    }
}

/// `[q, q², q⁴, q⁶, q⁹, q¹², q¹⁶]` (and `q²⁰` separately where needed).
#[inline(always)]
fn powers<R: Real>(q: &R) -> [R; 7] {
    let q2 = q.sqr();
    let q4 = q2.sqr();
    let q6 = q4.clone() * q2.clone();
    let q9 = q6.clone() * q2.clone() * q.clone();
    let q12 = q6.sqr();
    let q16 = q12.clone() * q4.clone();
    [q.clone(), q2, q4, q6, q9, q12, q16]
}

/// The theta-null quotients minus one, from `θ₂(0)/(2q^¼) = 1 + E₂`,
/// `θ₃(0) = 1 + E₃ + O₃`, `θ₄(0) = 1 + E₃ − O₃` (`E₂ = q² + q⁶ + q¹² + q²⁰`,
/// `E₃ = 2q⁴ + 2q¹⁶`, `O₃ = 2q + 2q⁹`; DLMF 20.4.1–4).  Series: `θ₃/θ₂ − 1`,
/// `θ₄/θ₂ − 1`, `θ₄/θ₃ − 1`; imaginary argument: `θ₃/θ₄ − 1`, `θ₂/θ₄ − 1`,
/// `θ₂/θ₃ − 1`.  The differences are summed term by term (no cancellation).
#[inline(always)]
fn ratios<R: Real>(pow: &[R; 7], imaginary: bool) -> [R; 3] {
    let [q, q2, q4, q6, q9, q12, q16] = pow;
    let one = q.one();
    let e2 = q2.clone() + q6.clone() + q12.clone() + q16.clone() * q4.clone();
    let e3 = (q4.clone() + q16.clone()).mul_2si(1);
    let o3 = (q.clone() + q9.clone()).mul_2si(1);
    let th3 = one.clone() + e3.clone() + o3.clone();
    if imaginary {
        let th4 = one + e3.clone() - o3.clone();
        let (r4, r3) = (th4.recip(), th3.recip());
        [
            o3.mul_2si(1) * r4.clone(),
            (e2.clone() - e3.clone() + o3.clone()) * r4,
            (e2 - e3 - o3) * r3,
        ]
    } else {
        let th2 = one + e2.clone();
        let (r2, r3) = (th2.recip(), th3.recip());
        [
            (e3.clone() + o3.clone() - e2.clone()) * r2.clone(),
            (e3 - o3.clone() - e2) * r2,
            -(o3.mul_2si(1) * r3),
        ]
    }
}

/// `(sn, cn, dn)(u)` from the values at `u − 2hK`, `2h = j − (j mod 2)`: sn and cn
/// change sign with `h` (DLMF 22.4.3, `sn(t + 2K) = −sn t`, `cn(t + 2K) = −cn t`).
#[inline(always)]
pub(crate) fn half_period_sign<R: Real>(j: i64, (s, c, d): (R, R, R)) -> (R, R, R) {
    if (j - j.rem_euclid(2)) / 2 % 2 == 0 {
        (s, c, d)
    } else {
        (-s, -c, d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;
    use rug::float::Constant;

    /// 256-bit `(π/(2K), π/(2K'), πK/(2K'))` of the modulus `k`.
    fn reference(k: f64) -> [Float; 3] {
        let p = 256;
        let kf = Float::with_val(p, k);
        let kp = Float::with_val(p, 1 - Float::with_val(p, &kf * &kf)).sqrt();
        let pi = Float::with_val(p, Constant::Pi);
        let agm = Float::with_val(p, 1).agm(&kp);
        let agm_c = Float::with_val(p, 1).agm(&kf);
        let period = Float::with_val(p, &pi * &agm_c) / (2 * agm.clone());
        [agm, agm_c, period]
    }

    /// `|d − want|/want` at 256 bits.
    fn rel(d: &Dd<f64>, want: &Float) -> f64 {
        let got = Float::with_val(256, Float::with_val(256, d.hi) + d.lo);
        (got - want).abs().to_f64() / want.to_f64()
    }

    /// The data of `k` as [`Theta::new`] builds it (`k² ≤ 0.81`: the series, else the
    /// imaginary argument).
    fn theta_of(k: f64) -> Theta<f64> {
        let k2 = Dd::from(k).sqr();
        let (s, e) = two_sum(1.0, -k2.v());
        let mc = Dd {
            hi: s,
            lo: e - k2.lo,
        }
        .norm();
        Theta::new(&k2, &mc)
    }

    /// The scale of every [`ScaleKind`] the fast reduction takes, against a 256-bit
    /// AGM, within the bound that its accepted cancellation assumes (`cancel·2⁻⁵⁷`, so
    /// that `w` keeps `2⁻⁵⁷` relative; up to `2⁻⁵⁶` for the nome in `f64`, whose error
    /// reaches `E·2⁻⁴⁸`), over a dense sweep of moduli; the
    /// period at imaginary argument to `2⁻⁸⁴`.
    #[test]
    fn scale_error_within_bound() {
        let mut worst = [0f64; 2];
        for i in 1..4000 {
            let k = f64::from(i) / 4000.0;
            for k in [k, 1.0 - (1.0 - k) * 1e-6] {
                let th = theta_of(k);
                let [agm, agm_c, period] = reference(k);
                let imaginary = th.bottom == Bottom::Imaginary;
                let scale = if imaginary { agm_c } else { agm };
                let err = rel(&th.scale, &scale);
                let slack = if th.j_max == J_FAST { 1.0 } else { 2.0 };
                let bound = th.cancel * 2f64.powi(-57) * slack;
                assert!(err < bound, "k = {k}: scale error {err:e}, bound {bound:e}");
                worst[usize::from(imaginary)] = worst[usize::from(imaginary)].max(err / bound);
                if imaginary {
                    let ep = rel(&th.period, &period);
                    assert!(ep < 2f64.powi(-84), "k = {k}: period error {ep:e}");
                    assert!(
                        th.cancel == CANCEL_PRECISE && th.j_max == J_FAST,
                        "k = {k}: the imaginary bottom's scale is precise"
                    );
                }
            }
        }
        assert!(worst.iter().all(|w| *w > 0.0), "{worst:?}");
    }

    /// `scale` and `period` in double-double against MPFR (to 2⁻⁸⁴; the reduction needs
    /// 2⁻⁸⁰ for `|j| ≤ 256` and 20 bits of cancellation) (`π/(2K)`, `π/(2K')`,
    /// `πK/(2K')` from 256-bit AGMs).
    #[test]
    fn scale_and_period_against_mpfr() {
        for k in [1e-9, 0.1, 0.5, 0.7, 0.71, 0.8, 0.99, 0.999999, 1.0 - 1e-12] {
            let k2 = Dd::from(k).sqr();
            let (s, e) = two_sum(1.0, -k2.v());
            let mc = Dd {
                hi: s,
                lo: e - k2.lo,
            }
            .norm();
            let th = Theta::with_bottom(&k2, &mc, k2.v() > 0.5, true);
            let [agm, agm_c, period] = reference(k);
            let half_pi = Float::with_val(256, Constant::Pi) / 2;
            let (scale, period) = if th.bottom == Bottom::Imaginary {
                (agm_c, period)
            } else {
                (agm, half_pi)
            };
            let (es, ep) = (rel(&th.scale, &scale), rel(&th.period, &period));
            assert!(
                es < 2f64.powi(-84) && ep < 2f64.powi(-84),
                "k = {k}: scale {es:e}, period {ep:e}"
            );
        }
    }
}
