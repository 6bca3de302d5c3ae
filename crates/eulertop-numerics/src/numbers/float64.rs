//! `f64` as a [`Scalar`] and [`Real`]: IEEE double precision, 53 bits.

use super::{NumError, Real, Scalar};

impl Scalar for f64 {
    fn zero(&self) -> Self {
        0.0
    }
    fn one(&self) -> Self {
        1.0
    }
    fn from_i64(&self, n: i64) -> Self {
        n as f64
    }
    fn from_f64(&self, x: f64) -> Self {
        x
    }
    fn parse_like(&self, s: &str) -> Result<Self, NumError> {
        let t = s.trim();
        if !super::is_decimal(t) {
            return Err(NumError::Parse(s.to_string()));
        }
        match t.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(NumError::Parse(s.to_string())),
        }
    }
    fn precision(&self) -> Option<u32> {
        Some(53)
    }
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
    fn magnitude(&self) -> f64 {
        f64::abs(*self)
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }
    fn try_sqrt(&self) -> Result<Self, NumError> {
        if *self < 0.0 {
            Err(NumError::NegativeSqrt(format!("{self:e}")))
        } else {
            Ok(f64::sqrt(*self))
        }
    }
    fn to_decimal(&self, digits: usize) -> String {
        format!("{:.*e}", digits.saturating_sub(1), self)
    }
}

impl Real for f64 {
    const FIXED: bool = true;
    const PLAIN_F64: bool = true;
    fn prec(&self) -> u32 {
        53
    }
    fn with_prec(&self, _bits: u32) -> Self {
        *self
    }
    fn pi(&self) -> Self {
        std::f64::consts::PI
    }
    fn epsilon(&self) -> Self {
        f64::EPSILON
    }
    fn mul_2si(&self, n: i32) -> Self {
        self * f64::powi(2.0, n)
    }
    fn abs(&self) -> Self {
        f64::abs(*self)
    }
    fn sqrt(&self) -> Self {
        f64::sqrt(*self)
    }
    fn exp(&self) -> Self {
        f64::exp(*self)
    }
    fn exp_m1(&self) -> Self {
        f64::exp_m1(*self)
    }
    fn ln(&self) -> Self {
        f64::ln(*self)
    }
    fn sin(&self) -> Self {
        f64::sin(*self)
    }
    fn cos(&self) -> Self {
        f64::cos(*self)
    }
    fn sin_cos(&self) -> (Self, Self) {
        f64::sin_cos(*self)
    }
    #[inline]
    fn sin_cos_kernel(&self) -> (Self, Self) {
        kernel_sin_cos(*self)
    }
    fn tan(&self) -> Self {
        f64::tan(*self)
    }
    fn atan(&self) -> Self {
        f64::atan(*self)
    }
    fn atan2(&self, x: &Self) -> Self {
        f64::atan2(*self, *x)
    }
    fn asin(&self) -> Self {
        f64::asin(*self)
    }
    fn sinh(&self) -> Self {
        f64::sinh(*self)
    }
    fn cosh(&self) -> Self {
        f64::cosh(*self)
    }
    fn tanh(&self) -> Self {
        f64::tanh(*self)
    }
    fn asinh(&self) -> Self {
        f64::asinh(*self)
    }
    fn atanh(&self) -> Self {
        f64::atanh(*self)
    }
    fn floor(&self) -> Self {
        f64::floor(*self)
    }
    fn round(&self) -> Self {
        f64::round(*self)
    }
    fn powf(&self, y: &Self) -> Self {
        f64::powf(*self, *y)
    }
}

/// Coefficients of the fdlibm kernel `__kernel_sin` (Sun Microsystems 1993, k_sin.c):
/// `sin x ≈ x + x³(S1 + x²(S2 + … + x²·S6))` on `[−π/4, π/4]`, polynomial error below
/// `2^−58` relative.
const S: [f64; 6] = [
    f64::from_bits(0xBFC5_5555_5555_5549), // -1.66666666666666324348e-01
    f64::from_bits(0x3F81_1111_1110_F8A6), //  8.33333333332248946124e-03
    f64::from_bits(0xBF2A_01A0_19C1_61D5), // -1.98412698298579493134e-04
    f64::from_bits(0x3EC7_1DE3_57B1_FE7D), //  2.75573137070700676789e-06
    f64::from_bits(0xBE5A_E5E6_8A2B_9CEB), // -2.50507602534068634195e-08
    f64::from_bits(0x3DE5_D93A_5ACF_D57C), //  1.58969099521155010221e-10
];

/// Coefficients of the fdlibm kernel `__kernel_cos` (k_cos.c):
/// `cos x ≈ 1 − x²/2 + x⁴(C1 + x²(C2 + … + x²·C6))` on `[−π/4, π/4]`, polynomial error
/// below `2^−58`.
const C: [f64; 6] = [
    f64::from_bits(0x3FA5_5555_5555_554C), //  4.16666666666666019037e-02
    f64::from_bits(0xBF56_C16C_16C1_5177), // -1.38888888888741095749e-03
    f64::from_bits(0x3EFA_01A0_19CB_1590), //  2.48015872894767294178e-05
    f64::from_bits(0xBE92_7E4F_809C_52AD), // -2.75573143513906633035e-07
    f64::from_bits(0x3E21_EE9E_BDB4_B1C4), //  2.08757232129817482790e-09
    f64::from_bits(0xBDA8_FAE9_BE88_38D4), // -1.13596475577881948265e-11
];

/// `(sin x, cos x)` for `|x| ≤ π/4` without argument reduction: the fdlibm kernels
/// (as in FreeBSD msun and musl `__sin`/`__cos`), each below 1 ulp.  The cosine is
/// formed as `w + ((1 − w) − x²/2 + x⁴·r)` with `w = 1 − x²/2`, so that the rounding
/// of `1 − x²/2` is recovered exactly.
#[inline]
fn kernel_sin_cos(x: f64) -> (f64, f64) {
    if x == 0.0 {
        // keeps the sign of −0.0 (the polynomial would return +0.0)
        return (x, 1.0);
    }
    let z = x * x;
    let w = z * z;
    let rs = S[1] + z * (S[2] + z * S[3]) + z * w * (S[4] + z * S[5]);
    let sin = x + z * x * (S[0] + z * rs);
    let rc = z * (C[0] + z * (C[1] + z * C[2])) + w * w * (C[3] + z * (C[4] + z * C[5]));
    let hz = 0.5 * z;
    let one_m = 1.0 - hz;
    let cos = one_m + (((1.0 - one_m) - hz) + z * rc);
    (sin, cos)
}
