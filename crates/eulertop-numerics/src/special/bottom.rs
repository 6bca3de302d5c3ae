//! The algorithms at the bottom of an evaluation of sn, cn, dn ([`Bottom`]), and the two
//! closed-form ones: `κ = 0` and `κ = 1`.

use crate::numbers::Real;

/// The algorithm at the bottom of an evaluation of sn, cn, dn (see the module docs of
/// [`crate::special`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Bottom {
    /// `sin`/`cos` with DLMF 22.10.4–6, below a descending Landen chain (multi-precision).
    Sine,
    /// Theta quotients of the nome `q < 0.1` (DLMF 22.2.4, 20.2.1–4; fixed precision,
    /// `κ² ≤ 0.81`).
    Series,
    /// Theta quotients of the complementary nome at imaginary argument (DLMF Table
    /// 22.6.1; fixed precision, `κ² > 0.81`).
    Imaginary,
    /// `tanh`/`sech` with DLMF 22.10.7–9: exact at `κ = 1` (DLMF 22.5.ii).
    TanhSech,
}

/// `κ = 0`: `(sin u, cos u, 1)` (DLMF 22.5.3; [`Bottom::Sine`] without Landen levels).
#[inline(always)]
pub(crate) fn sine_cases<R: Real>(u: &R) -> (R, R, R) {
    let (s, c) = u.sin_cos();
    (s, c, u.one())
}

/// [`Bottom::TanhSech`]: DLMF 22.10.7–9 for `κ'² = kp2` (exact at `κ = 1`, where
/// `sn = tanh u`, `cn = dn = sech u`, DLMF 22.5.ii; the `κ'²` terms carry the first
/// derivative in `κ` for `Dual` numbers and the leading correction for tiny `κ'`).
pub(crate) fn tanh_sech<R: Real>(u: &R, kp2: &R) -> (R, R, R) {
    let th = u.tanh();
    let sech = u.cosh().recip();
    if u.to_f64().abs() > 350.0 {
        // sinh·cosh overflows; the κ'² terms (zero in value at κ = 1) are dropped
        return (th, sech.clone(), sech);
    }
    let sh = u.sinh();
    let quarter = kp2.mul_2si(-2);
    // a·sech² = κ'²/4 (tanh − u sech²), a·tanh·sech = κ'²/4 (sinh − u sech) tanh
    let s = th.clone() + quarter.clone() * (th.clone() - u.clone() * sech.sqr());
    let c = sech.clone() - quarter.clone() * (sh.clone() - u.clone() * sech.clone()) * th.clone();
    let d = sech.clone() + quarter * (sh + u.clone() * sech.clone()) * th;
    (s, c, d)
}
