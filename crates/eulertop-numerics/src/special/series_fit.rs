//! The per-modulus data of the `f64` theta series ([`Bottom::Series`]) from piecewise
//! polynomial fits in the parameter `m = κ²`, so that a new modulus costs no square
//! root, no division and no series of the nome before the evaluation can start.
//!
//! On each interval `[i/64, (i+1)/64)` of `m ∈ [0, FIT_MAX_M)`, with `x = m − cᵢ`
//! (`cᵢ` the midpoint, `|x| ≤ 1/128`), the interpolants at Chebyshev points of degree 13
//! of the scale `π/(2K) = AGM(1, κ')` (DLMF 19.8.5) and of degree 10 of the nome quotient
//! `q/m` (`q = exp(−πK'/K)`, DLMF 22.2.1; a quotient, so that `q` keeps its relative
//! accuracy as `m → 0`), computed with mpmath at 80 digits by
//! `scripts/gen_series_fit.py` (module `series_fit_table`; interpolation errors
//! `2⁻⁸⁵` and `2⁻⁶⁵` relative).  The scale is summed in double-double: `c₀ + … + c₃x³`
//! with `c₀ … c₃` and the products exact, the rest `x⁴·T(x)` in `f64`; its error,
//! measured against 256-bit AGMs, is below [`SCALE_BOUND`] (test
//! `scale_fit_against_mpfr`, and `theta::tests::scale_error_within_bound` for the bound
//! the fast reduction assumes).
//!
//! [`Bottom::Series`]: super::bottom::Bottom::Series

use super::dd::{fast_two_sum, two_prod, two_sum};
use super::series_fit_table::{INTERVALS, NOME, SCALE};

/// The fits cover `0 ≤ m < FIT_MAX_M` (`0.8125`, above the largest `κ²` of the series).
pub(crate) const FIT_MAX_M: f64 = INTERVALS as f64 / 64.0;

/// The relative error bound of the fitted scale (measured below `2⁻⁷⁵`, test
/// `scale_fit_against_mpfr`).
pub(crate) const SCALE_BOUND: f64 = 1.058_791_184_067_875_4e-22; // 2⁻⁷³

/// `c₀ + c₁x + … + c₉x⁹` by Estrin's scheme (`x2 = x²`, `x4 = x⁴`, `x8 = x⁸`), with
/// fused multiply-adds (one instruction each in the FMA clone where the `f64` path runs).
#[inline(always)]
fn estrin10(c: &[f64], x: f64, x2: f64, x4: f64, x8: f64) -> f64 {
    let a0 = c[1].mul_add(x, c[0]);
    let a1 = c[3].mul_add(x, c[2]);
    let a2 = c[5].mul_add(x, c[4]);
    let a3 = c[7].mul_add(x, c[6]);
    let a4 = c[9].mul_add(x, c[8]);
    let b0 = a1.mul_add(x2, a0);
    let b1 = a3.mul_add(x2, a2);
    a4.mul_add(x8, b1.mul_add(x4, b0))
}

/// `x = m + m_lo − c` on the interval `i` of `m` and what the sums need of it:
/// `x = xs + xr` (`|xr| ≤ ulp(xs)`), `x² = x2 + x2e`, `x³ = x3 + x3e` (exact), `x⁴`, `x⁸`.
struct Offset {
    i: usize,
    xs: f64,
    xr: f64,
    x2: f64,
    x2e: f64,
    x3: f64,
    x3e: f64,
    x4: f64,
    x8: f64,
}

impl Offset {
    /// The offset of `m + m_lo` (`0 < m < last/64`, `|m_lo| ≤ ulp(m)`) from the midpoint
    /// of its interval `⌊64m⌋` (`min(⌊64m⌋, last − 1)`).
    #[inline(always)]
    fn new(m: f64, m_lo: f64, last: usize) -> Self {
        // `0 ≤ f < last`: the conversion is exact (`as i32` is shorter than `as usize`)
        let f = (m * 64.0).floor().min((last - 1) as f64);
        let (xh, xe) = two_sum(m, -f.mul_add(1.0 / 64.0, 1.0 / 128.0));
        let (xs, xr) = fast_two_sum(xh, xe + m_lo);
        let (x2, x2e) = two_prod(xs, xs);
        let (x3, x3e) = two_prod(x2, xs);
        Offset {
            i: f as i32 as usize,
            xs,
            xr,
            x2,
            x2e,
            x3,
            x3e: x2e.mul_add(xs, x3e),
            x4: x2 * x2,
            x8: x2 * x2 * (x2 * x2),
        }
    }

    /// `c₀ + … + c₉x⁹` ([`estrin10`]).
    #[inline(always)]
    fn poly10(&self, c: &[f64]) -> f64 {
        estrin10(c, self.xs, self.x2, self.x4, self.x8)
    }

    /// The low parts of `cⱼxʲ` for `j = 1, 2, 3` (`c` = `[c₁, c₁ₗₒ, c₂, …]`, `p` the low
    /// halves of the exact products `cⱼ·xʲ` of the leading parts): `p + cⱼ·(xʲ)ₗₒ +
    /// cⱼₗₒ·xʲ` with `(xʲ)ₗₒ` including `j·xʲ⁻¹·xr`.
    #[inline(always)]
    fn low_parts(&self, c: &[f64], p: [f64; 3]) -> f64 {
        let l1 = c[1].mul_add(self.xs, c[0].mul_add(self.xr, p[0]));
        let x2l = (2.0 * self.xs).mul_add(self.xr, self.x2e);
        let l2 = c[3].mul_add(self.x2, c[2].mul_add(x2l, p[1]));
        let x3l = (3.0 * self.x2).mul_add(self.xr, self.x3e);
        let l3 = c[5].mul_add(self.x3, c[4].mul_add(x3l, p[2]));
        l1 + (l2 + l3)
    }
}

/// The nome `q` and the scale `π/(2K)` as a double-double `(hi, lo)` of the modulus with
/// `κ² = m + m_lo` (`0 < m < FIT_MAX_M`, `|m_lo| ≤ ulp(m)`): `q` to about an ulp, the
/// scale to [`SCALE_BOUND`] relative.
///
/// The terms `cⱼxʲ`, `j = 1, 2, 3`, are the exact products `pⱼ + pⱼₑ` of the leading
/// parts plus [`Offset::low_parts`]; `x⁴·T(x)` (`|x⁴T| < 2⁻²⁴`) in `f64`.  Every `pⱼ`
/// is smaller than the sum before it, so the leading parts are added by fast two-sums.
#[inline(always)]
pub(crate) fn series_data(m: f64, m_lo: f64) -> (f64, (f64, f64)) {
    let o = Offset::new(m, m_lo, INTERVALS);
    let (s, n) = (&SCALE[o.i], &NOME[o.i]);
    let qm = o.xs.mul_add(o.poly10(&n[1..]), n[0]);
    let q = m.mul_add(qm, m_lo * qm);
    let (p1, p1e) = two_prod(s[2], o.xs);
    let (p2, p2e) = two_prod(s[4], o.x2);
    let (p3, p3e) = two_prod(s[6], o.x3);
    let lo = o.x4.mul_add(
        o.poly10(&s[8..]),
        s[1] + o.low_parts(&s[2..8], [p1e, p2e, p3e]),
    );
    let (h1, e1) = fast_two_sum(s[0], p1);
    let (h2, e2) = fast_two_sum(h1, p2);
    let (h3, e3) = fast_two_sum(h2, p3);
    (q, fast_two_sum(h3, (e1 + e2 + e3) + lo))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;
    use rug::float::Constant;

    /// 256-bit `(π/(2K), q)` for `κ² = m + m_lo`.
    fn reference(m: f64, m_lo: f64) -> (Float, Float) {
        let p = 256;
        let mm = Float::with_val(p, m) + m_lo;
        let kp = Float::with_val(p, 1 - mm.clone()).sqrt();
        let k = mm.sqrt();
        let agm = Float::with_val(p, 1).agm(&kp);
        let agm_c = Float::with_val(p, 1).agm(&k);
        // q = exp(−πK'/K) = exp(−π·AGM(1, κ')/AGM(1, κ))
        let pi = Float::with_val(p, Constant::Pi);
        let q = (-(pi * &agm) / agm_c).exp();
        (agm, q)
    }

    /// The fitted scale to [`SCALE_BOUND`] and the nome to `2⁻⁵⁰` relative, against
    /// 256-bit AGMs, at both ends and 40 points of every interval (with a `lo` part of
    /// `m`), and down to `m = 10⁻³⁰⁰`.
    #[test]
    fn scale_fit_against_mpfr() {
        let mut worst = (0f64, 0f64);
        let mut ms: Vec<(f64, f64)> = vec![(1e-300, 0.0), (1e-20, 3e-37), (1e-5, -4e-22)];
        for i in 0..INTERVALS {
            for t in 0..=40 {
                let m = (i as f64 + f64::from(t) / 40.0) / 64.0;
                let m = if t == 40 { m.next_down() } else { m };
                let lo = m * f64::EPSILON * 0.37 * if t % 2 == 0 { 1.0 } else { -1.0 };
                ms.push((m, if m > 0.0 { lo } else { 0.0 }));
            }
        }
        for (m, m_lo) in ms.into_iter().filter(|p| p.0 > 0.0) {
            let (q, (h, l)) = series_data(m, m_lo);
            let (agm, qr) = reference(m, m_lo);
            let es = (Float::with_val(256, &agm - h) - l).abs().to_f64() / agm.to_f64();
            let eq = (Float::with_val(256, &qr - q)).abs().to_f64() / qr.to_f64();
            assert!(es < SCALE_BOUND, "m = {m}: scale error {es:e}");
            assert!(eq < 2f64.powi(-50), "m = {m}: nome error {eq:e}");
            worst = (worst.0.max(es), worst.1.max(eq));
        }
        eprintln!(
            "fitted scale error 2^{:.2}, nome 2^{:.2}",
            worst.0.log2(),
            worst.1.log2()
        );
    }
}
