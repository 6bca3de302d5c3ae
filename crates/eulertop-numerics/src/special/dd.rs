//! Double-double arithmetic for the fixed-precision types (`f64`, `Dual<f64>`).
//!
//! A [`Dd`] is an unevaluated sum `hi + lo` with `hi: R` and `lo: f64`, `|lo| ≲ ulp(hi)`.
//! The error-free transformations (Knuth's two-sum, Dekker's two-product) act on the
//! `f64` values (`R::to_f64`), while `hi` is formed with `R`'s own operations, so the
//! derivative parts of a `Dual` ride along in `hi` (the derivative of `lo`, about
//! `2⁻⁵³` of the derivative of `hi`, is dropped).  For `R = f64` this is plain
//! double-double arithmetic at no extra cost.
//!
//! References: T. J. Dekker, *A floating-point technique for extending the available
//! precision*, Numer. Math. 18 (1971); Y. Hida, X. S. Li, D. H. Bailey, *Library for
//! double-double and quad-double arithmetic* (2007).

use crate::numbers::Real;
use rug::Float;
use std::sync::OnceLock;

/// `hi + lo`; see the module docs.
#[derive(Clone, Debug)]
pub(crate) struct Dd<R> {
    pub hi: R,
    pub lo: f64,
}

/// `(s, e)` with `s = fl(a + b)` and `s + e = a + b` exactly (Knuth).
#[inline(always)]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `(s, e)` with `s = fl(a + b)` and `s + e = a + b` exactly, for `a = 0` or
/// `|a| ≥ |b|` (Dekker's fast two-sum: three operations instead of six).
#[inline(always)]
pub(crate) fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `(p, e)` with `p = fl(a·b)` and `p + e = a·b` exactly, by one fused multiply-add
/// (`f64::mul_add` is correctly rounded everywhere; it is one instruction in code
/// compiled for FMA, see [`with_fma`], and a libm call elsewhere).
#[inline(always)]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// Runs `f` in code compiled for the fused multiply-add instruction when the CPU has it
/// (x86-64 run-time detection), so that [`two_prod`] is one instruction; otherwise
/// plainly.  Both give the same bits (`mul_add` is exact in both).  `f` and what it
/// calls should be `#[inline(always)]` to be compiled into the FMA clone.
#[inline(always)]
pub(crate) fn with_fma<T>(f: impl FnOnce() -> T) -> T {
    #[cfg(target_arch = "x86_64")]
    {
        #[target_feature(enable = "fma")]
        unsafe fn fma_clone<T>(f: impl FnOnce() -> T) -> T {
            f()
        }
        if std::arch::is_x86_feature_detected!("fma") {
            // SAFETY: the CPU supports the `fma` target feature (checked just above).
            return unsafe { fma_clone(f) };
        }
    }
    f()
}

/// `x` with its value replaced by `v` and its derivative parts kept: `v − (x.v − x)`.
/// For `f64` this is exactly `v` (also for `v = −0`).
#[inline(always)]
pub(crate) fn with_value<R: Real>(x: &R, v: f64) -> R {
    if R::PLAIN_F64 {
        return x.from_f64(v);
    }
    x.from_f64(v) - (x.from_f64(x.to_f64()) - x.clone())
}

impl<R: Real> Dd<R> {
    /// `x + 0`.
    #[inline(always)]
    pub(crate) fn from(x: R) -> Self {
        Dd { hi: x, lo: 0.0 }
    }

    /// The value rounded into `R` (`hi + lo`).
    #[inline(always)]
    pub(crate) fn to_r(&self) -> R {
        self.hi.clone() + self.hi.from_f64(self.lo)
    }

    /// The value in `R`: `hi + lo` rounded for the fixed-precision types; `hi` alone
    /// for the multi-precision ones, whose `hi` carries the working precision (their
    /// `lo`, formed from `f64` images, means nothing).  For code written once with
    /// [`Dd`] for both.
    #[inline(always)]
    pub(crate) fn value(&self) -> R {
        if R::FIXED {
            self.to_r()
        } else {
            self.hi.clone()
        }
    }

    /// `−self`.
    #[inline(always)]
    pub(crate) fn neg(&self) -> Self {
        Dd {
            hi: -self.hi.clone(),
            lo: -self.lo,
        }
    }

    /// `hi` as an `f64`.
    #[inline(always)]
    pub(crate) fn v(&self) -> f64 {
        self.hi.to_f64()
    }

    /// Renormalised so that `hi = fl(hi + lo)`.
    #[inline(always)]
    pub(crate) fn norm(&self) -> Self {
        let (s, e) = two_sum(self.v(), self.lo);
        Dd {
            hi: with_value(&self.hi, s),
            lo: e,
        }
    }

    /// [`Dd::norm`] for `|lo| ≤ |hi|` (as after one operation), by a fast two-sum.
    #[inline(always)]
    pub(crate) fn norm_fast(&self) -> Self {
        let (s, e) = fast_two_sum(self.v(), self.lo);
        Dd {
            hi: with_value(&self.hi, s),
            lo: e,
        }
    }

    /// `self + o`.
    #[inline(always)]
    pub(crate) fn add(&self, o: &Self) -> Self {
        let (_, e) = two_sum(self.v(), o.v());
        Dd {
            hi: self.hi.clone() + o.hi.clone(),
            lo: e + (self.lo + o.lo),
        }
    }

    /// `self + x` for a plain `x`.
    #[inline(always)]
    pub(crate) fn add_r(&self, x: &R) -> Self {
        let (_, e) = two_sum(self.v(), x.to_f64());
        Dd {
            hi: self.hi.clone() + x.clone(),
            lo: e + self.lo,
        }
    }

    /// `self · o`.
    #[inline(always)]
    pub(crate) fn mul(&self, o: &Self) -> Self {
        let (a, b) = (self.v(), o.v());
        let (_, e) = two_prod(a, b);
        Dd {
            hi: self.hi.clone() * o.hi.clone(),
            lo: e + (a * o.lo + self.lo * b),
        }
    }

    /// `self · x` for a plain `x`.
    #[inline(always)]
    pub(crate) fn mul_r(&self, x: &R) -> Self {
        let b = x.to_f64();
        let (_, e) = two_prod(self.v(), b);
        Dd {
            hi: self.hi.clone() * x.clone(),
            lo: e + self.lo * b,
        }
    }

    /// `self·2ⁿ` (exact).
    #[inline(always)]
    pub(crate) fn mul_2si(&self, n: i32) -> Self {
        Dd {
            hi: self.hi.mul_2si(n),
            lo: self.lo * 2f64.powi(n),
        }
    }

    /// `self²`.
    #[inline(always)]
    pub(crate) fn sqr(&self) -> Self {
        self.mul(self)
    }

    /// `self / o`: one correction of the quotient of the leading parts (the correction
    /// divided by `o` through `1/o`, formed alongside the quotient, so that the two
    /// divisions overlap).
    #[inline(always)]
    pub(crate) fn div(&self, o: &Self) -> Self {
        let hi = self.hi.clone() / o.hi.clone();
        let b = o.v();
        let rb = 1.0 / b;
        let q = hi.to_f64();
        let (p, e) = two_prod(q, b);
        let r = ((self.v() - p) - e) + (self.lo - q * o.lo);
        Dd { hi, lo: r * rb }
    }

    /// `√self` (`self > 0`): one Newton correction of the root of the leading part.
    #[inline(always)]
    pub(crate) fn sqrt(&self) -> Self {
        let hi = self.hi.sqrt();
        let h = hi.to_f64();
        let (p, e) = two_prod(h, h);
        let r = ((self.v() - p) - e) + self.lo;
        Dd {
            hi,
            lo: r / (h + h),
        }
    }

    /// `ln self` (`self > 0`, normal) by the table-driven [`ln_dd`], to about `2⁻⁸⁷`
    /// absolutely (plus the relative error of `self`); derivative parts as `d(self)/self`.
    #[inline(always)]
    pub(crate) fn ln(&self) -> Self {
        let x = self.v();
        let (a, b) = ln_dd(x);
        // value a, derivative parts d(hi)/x (zero for f64)
        let d = (self.hi.clone() - self.hi.from_f64(x)) * self.hi.from_f64(1.0 / x);
        Dd {
            hi: self.hi.from_f64(a) + d,
            lo: b + self.lo / x,
        }
    }
}

/// Table for [`ln_dd`]: for `i = 0..1024`, `1/cᵢ` rounded to `f64` (`cᵢ = 1 + (i+½)/1024`)
/// and `−ln(1/cᵢ)` as a double-double, from MPFR at 160 bits (built once).
fn ln_table() -> &'static [(f64, f64, f64)] {
    static TABLE: OnceLock<Vec<(f64, f64, f64)>> = OnceLock::new();
    TABLE.get_or_init(|| {
        (0..1024)
            .map(|i| {
                let c = 1.0 + (i as f64 + 0.5) / 1024.0;
                let inv = 1.0 / c;
                let l = -Float::with_val(160, inv).ln();
                let hi = l.to_f64();
                let lo = Float::with_val(160, &l - hi).to_f64();
                (inv, hi, lo)
            })
            .collect()
    })
}

/// `ln x` for a positive normal double as a double-double, absolute error about
/// `2⁻⁸⁷` (plus `2⁻¹⁰⁰·|ln x|`): `x = 2ᵉ·m`, `m ∈ [1, 2)`, `m·(1/cᵢ) = 1 + r` exactly
/// as a double-double with `|r| ≲ 2⁻¹¹` (table [`ln_table`]), and
/// `ln x = e·ln 2 − ln(1/cᵢ) + ln(1 + r)` with `ln(1+r) = r − r²/2 + r³/3 − …`
/// (DLMF 4.6.1), the first two terms in double-double.
#[inline(always)]
pub(crate) fn ln_dd(x: f64) -> (f64, f64) {
    const LN2: (f64, f64) = (std::f64::consts::LN_2, 2.319_046_813_846_299_6e-17);
    let bits = x.to_bits();
    let e = ((bits >> 52) & 0x7ff) as i64 - 1023;
    let m = f64::from_bits((bits & ((1u64 << 52) - 1)) | (1023u64 << 52));
    let i = ((bits >> 42) & 0x3ff) as usize;
    let (inv, th, tl) = ln_table()[i];
    let (p, pe) = two_prod(m, inv);
    let (r, rl) = two_sum(p - 1.0, pe);
    // ln(1 + r) = r − r²/2 + r³·(1/3 − r/4 + r²/5 − …)
    let (r2, r2e) = two_prod(r, r);
    let tail = r * r2 * (1.0 / 3.0 + r * (-0.25 + r * (0.2 + r * (-1.0 / 6.0 + r * (1.0 / 7.0)))));
    let (h1, l1) = two_sum(r, -0.5 * r2);
    let l1 = l1 + rl + (-0.5 * r2e - r * rl) + tail;
    // e·ln 2 + table + ln(1 + r)
    let (eh, el) = two_prod(e as f64, LN2.0);
    let (s, se) = two_sum(eh, th);
    let (s, se2) = two_sum(s, h1);
    let lo = se + se2 + el + (e as f64) * LN2.1 + tl + l1;
    two_sum(s, lo)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ln_dd_against_mpfr() {
        let mut worst = 0f64;
        let mut x = 1.3e-30_f64;
        while x < 1e5 {
            for y in [x, x.next_up(), x * 1.000_976_5, x * 1.707] {
                let (h, l) = ln_dd(y);
                let want = Float::with_val(200, y).ln();
                let err = Float::with_val(200, Float::with_val(200, &want - h) - l)
                    .abs()
                    .to_f64();
                worst = worst.max(err);
            }
            x *= 1.37;
        }
        assert!(worst < 2f64.powi(-86), "worst ln_dd error {worst:e}");
    }

    #[test]
    fn dd_ops_against_mpfr() {
        let a = Dd::from(0.7_f64).add_r(&1e-17);
        let b = Dd::from(1.9_f64).add_r(&-3e-17);
        let mp = |d: &Dd<f64>| Float::with_val(200, d.hi) + d.lo;
        let (ma, mb) = (mp(&a), mp(&b));
        let close = |d: Dd<f64>, want: Float| {
            let e = Float::with_val(200, mp(&d) - &want).abs().to_f64() / want.to_f64().abs();
            assert!(e < 2f64.powi(-100), "{e:e}");
        };
        close(a.mul(&b), Float::with_val(200, &ma * &mb));
        close(a.div(&b), Float::with_val(200, &ma / &mb));
        close(a.add(&b), Float::with_val(200, &ma + &mb));
        close(b.sqrt(), mb.clone().sqrt());
        let (p, e) = two_prod(0.1, 0.3);
        assert_eq!(
            Float::with_val(200, p) + e,
            Float::with_val(200, 0.1) * Float::with_val(200, 0.3)
        );
    }
}
