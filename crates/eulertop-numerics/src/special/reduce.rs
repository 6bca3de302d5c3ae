//! Argument reduction for fixed-precision types (`f64`, `Dual<f64>`): an error-free
//! `u − j·P` with a period known to ~150 bits as a triple-double.

use super::dd::{two_sum, with_value};
use crate::numbers::Real;

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
    let (r, lo) = reduce_dd2(u, p, j, tri);
    r + u.from_f64(lo)
}

/// [`reduce_dd`] as `(r, lo)`: the value of `r` is the last subtraction rounded to
/// `f64` and `lo` its rounding error (two-sum), so `r + lo` is `u − j·P` to about
/// `2⁻¹⁰⁰·|u|`.
pub(crate) fn reduce_dd2<R: Real>(u: &R, p: &R, j: i64, tri: [f64; 3]) -> (R, f64) {
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
    let a = (u.to_f64() - head) - mid;
    let (h, l) = two_sum(a, -lo);
    let r = u.clone() - u.from_i64(j) * dp;
    (with_value(&r, h), l)
}
