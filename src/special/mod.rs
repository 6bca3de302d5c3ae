//! Special functions: Jacobi elliptic functions and complete/incomplete elliptic
//! integrals of the first kind, at any precision, for real and complex arguments.
//!
//! **Modulus convention.** Every function takes the *modulus* `k` (as in the paper and
//! in DLMF §22.2), **not** the parameter `m = k²` used by mpmath, SciPy and
//! Abramowitz–Stegun.  The complementary modulus is `k' = √(1−k²)`, computed as
//! `√((1−k)(1+k))` so that it keeps full relative accuracy as `k → 1`.
//! The domain is `0 ≤ k < 1`; anything else (including NaN) is an error, never a panic.
//!
//! All functions are written once, generically over [`Real`] / [`ComplexScalar`](crate::numbers::ComplexScalar):
//! they run on `f64`, on `rug::Float` at any precision, on complex pairs and on
//! [`crate::numbers::Dual`] (automatic differentiation flows through the algorithms,
//! e.g. `d/du sn = cn·dn` comes out of the arithmetic).
//!
//! # Algorithms (and why)
//!
//! * **Moduli chain** (module `landen`): the descending Landen / Gauss transformation
//!   `k₁ = k²/(1+k')²`, `k₁' = 2√k'/(1+k')`, `1−k₁ = 2k'/(1+k')` (DLMF 22.7.1–3,
//!   19.8.12), iterated until `k_N⁴` is below the working epsilon (quadratic
//!   convergence: 3 steps for k = 0.8 in double, ~10 at 4096 bits).  The quarter period
//!   follows as `K = (π/2)·Π(1+k_n)·(1+k_N²/4)`.
//! * **sn, cn, dn of a real argument, multi-precision** (module `jacobi`): the argument
//!   is reduced to `u = jK + t`, `|t| ≤ K/2`; at the bottom of the chain
//!   `sn(t/Π(1+k_n), k_N)` comes from `sin`/`cos` with the first-order correction
//!   DLMF 22.10.4–6, then only `sn` is carried up the chain (DLMF 22.7.1; one reciprocal
//!   and three products per level) and `cn = √((1−sn)(1+sn))`, `dn = √(k'² + k²cn²)`
//!   (DLMF 22.6.1) at the top; since `cn(t) ≥ √(k'/(1+k'))` for `|t| ≤ K/2` this loses at
//!   most `log2(1/k')` bits, which are added to the working precision.  The quadrant
//!   `j mod 4` is applied with the quarter-period shifts DLMF 22.4.3
//!   (`sn(t+K) = cd t`, `cn(t+K) = −k' sd t`, `dn(t+K) = k' nd t`), which keep relative
//!   accuracy next to the zeros (the complex case needs that near its poles).
//! * **sn, cn, dn of a real argument, fixed precision** (`f64`, `Dual<f64>`; no guard
//!   bits, so every rounding counts and speed matters):
//!   - `j = round(u/K)` and `r = u − jK`, `|r| ≤ K/2`, formed exactly (Cody–Waite with a
//!     triple-double `K`, module `reduce`);
//!   - the chain is descended only until the nome `q = exp(−πK'/K)` is at most 0.06
//!     (0.09 after two levels); each step squares the nome, so `k ≤ 0.8` needs at most
//!     one level.  At the bottom the nome series DLMF 22.11.1–3 is summed as polynomials
//!     in `x = sin²v`, `v = πt/(2K)` (module `fourier`): `sn = sin v·P(x)`,
//!     `cn = cos v·(1 + x Q₁(x))`, `dn = 1 + x R₁(x)`, with coefficients summed in
//!     192-bit MPFR per modulus and one `sin_cos` from the fdlibm kernel polynomials
//!     (`Real::sin_cos_kernel`).  For odd `j`, `sin v = cos v_r`, `cos v = −sin v_r`
//!     (`v = π/2 + v_r`), so no quotient is needed at the end; the levels above the
//!     series are climbed with DLMF 22.7.1–3 written as "value + small correction",
//!     with `1 − dn` tracked next to `dn`;
//!   - `k` near 1 (`q > 0.2`, `k ≳ 0.986`): no Landen level at all; the series of the
//!     complementary modulus (nome `q' = exp(π²/ln q) < 2.2·10⁻³`) at imaginary argument,
//!     through Jacobi's imaginary transformation (DLMF Table 22.6.1):
//!     `sn(t,k) = tanh w·P(−y)/Q(−y)`, `cn(t,k) = 1/(cosh w·Q(−y))`, `dn = R(−y)·cn`,
//!     `w = πt/(2K')`, `y = sinh²w` (all terms positive, no cancellation);
//!   - tiny `k` (`k⁴ < ε/4`) or tiny `k'` (`k'² < ε/8`, only reached as the
//!     complementary modulus of a tiny `k` in the complex case): DLMF 22.10.4–6 resp.
//!     the `tanh`/`sech` expansion DLMF 22.10.7–9 directly, exact to rounding there.
//!
//!   Measured (dense sweeps, `reports/accuracy.md`): absolute error below 2 ε for every
//!   `k` (below 1.9 ε for `k ≥ 0.99`), every output with relative accuracy next to its
//!   zeros.
//!   The chain depends only on `k`; the last few chains are cached per thread for
//!   `f64` and `rug::Float` (typed caches; not for `Dual`, whose derivative parts differ
//!   per call).
//! * **Argument reduction.**  For MPFR the working precision is raised to
//!   `N + 40 + log2(1/k') + log2|j| + (cancellation bits of t)`, adaptively: if `t = u − jK`
//!   cancels, the reduction is repeated with more bits.  For fixed-precision types
//!   (`f64`, `Dual<f64>`) `K` is taken as a triple-double from a 200-bit MPFR AGM
//!   (computed once per modulus) and `t` is formed with error-free transformations
//!   (Cody–Waite with a 32-bit head for `|j| < 2²⁰`, FMA beyond), so `t` is accurate to
//!   ~2⁻¹⁰⁰·|u| while the derivative with respect to `k` still flows through the
//!   generic `K`.
//! * **Complex argument** (module `complex`): the addition theorem DLMF 22.8.1–3 with
//!   Jacobi's imaginary transformation (DLMF Table 22.6.1) in the form of
//!   Abramowitz–Stegun 16.21.1–4: `sn(x+iy) = (s d₁ + i c d s₁ c₁)/(c₁² + k²s²s₁²)`,
//!   with `s,c,d` at `(x,k)` and `s₁,c₁,d₁` at `(y,k')`.  The denominator is a sum of
//!   squares and the numerators are products, so relative accuracy of the six real
//!   values (guaranteed by the reduction above, which measures `y` from the nearest
//!   multiple of `K'`) carries over, also next to the poles at `2jK + (2l+1)iK'`.
//! * **K, K'** (module `agm`): `K = π/(2·AGM(1,k'))`, `K' = π/(2·AGM(1,k))`
//!   (DLMF 19.8.5).
//! * **F(φ,k)** (module `ellint`): quasi-periodic reduction `F(φ+mπ) = F(φ)+2mK`
//!   (DLMF 19.2.10 with 19.2.8), then the AGM phase recursion
//!   `φ_{n+1} = φ_n + atan((b_n/a_n) tan φ_n)`, `F = φ_N/(2^N a_N)`
//!   (DLMF §19.8(i), Abramowitz–Stegun 17.6), quadratically convergent.
//! * **Inverse** (module `inverse`): `u = F(atan2(sn, cn), k)` (DLMF 22.15.11–12).
//!
//! # Error behaviour
//!
//! Results at precision `N` are computed at `N + guard` bits and rounded once; the
//! measured errors (see `reports/accuracy.md`) are below `2^(4−N)` absolute for real
//! arguments and relative to `max(1,|value|)` for complex ones.  `f64` results are
//! within a few ulp of 1 in absolute terms (see the report for measured maxima).
//! Errors are reported as [`SpecialError`]: modulus outside `[0,1)`, non-finite input,
//! arguments so large that `u/K ≥ 2⁵⁰`, poles (complex argument exactly at a pole,
//! `K'(0)`), inconsistent input to [`jacobi_inverse`].

mod agm;
mod complex;
mod ellint;
mod fourier;
mod inverse;
mod jacobi;
mod landen;
mod reduce;

pub use agm::{ellipk, ellipkp};
pub use complex::sncndn_complex;
pub use ellint::ellipf;
pub use inverse::jacobi_inverse;
pub use jacobi::{am, sncndn, sncndn_many};

use crate::numbers::Real;

/// Errors of the special-function layer.  Every variant carries a one-line message
/// naming the offending value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SpecialError {
    /// The modulus is not in `[0, 1)` (or is NaN).
    #[error("modulus k = {0} is outside [0, 1)")]
    ModulusOutOfRange(String),
    /// The function has a pole at the given argument.
    #[error("pole: {0}")]
    Pole(String),
    /// An iteration did not converge.
    #[error("no convergence: {0}")]
    NoConvergence(String),
    /// A non-finite (NaN or infinite) argument or result.
    #[error("not finite: {0}")]
    NotFinite(String),
    /// The argument is too large for the argument reduction (`|u|/K ≥ 2^50`).
    #[error("argument too large: {0}")]
    ArgumentTooLarge(String),
    /// Input values that are not sn, cn, dn of one real argument.
    #[error("inconsistent input: {0}")]
    Inconsistent(String),
}

/// Checks `0 <= k < 1` and finiteness.
#[inline]
pub(crate) fn check_modulus<R: Real>(k: &R) -> Result<(), SpecialError> {
    if !k.is_finite() || *k < k.zero() || *k >= k.one() {
        return Err(modulus_error(k));
    }
    Ok(())
}

#[cold]
fn modulus_error<R: Real>(k: &R) -> SpecialError {
    SpecialError::ModulusOutOfRange(show(k))
}

/// Checks that an argument is finite.
#[inline]
pub(crate) fn check_finite<R: Real>(x: &R, what: &str) -> Result<(), SpecialError> {
    if !x.is_finite() {
        return Err(finite_error(x, what));
    }
    Ok(())
}

#[cold]
fn finite_error<R: Real>(x: &R, what: &str) -> SpecialError {
    SpecialError::NotFinite(format!("{what} = {}", show(x)))
}

/// Short rendering of a value for error messages.
pub(crate) fn show<R: Real>(x: &R) -> String {
    let v = x.to_f64();
    if v.is_nan() {
        "NaN".to_string()
    } else {
        format!("{v:e}")
    }
}

/// Is `x`'s type of fixed precision (`f64`, `Dual<f64>`), i.e. unable to hold `bits`?
/// Such types get no guard bits and take the fixed-precision algorithms.
pub(crate) fn is_fixed<R: Real>(x: &R, bits: u32) -> bool {
    x.with_prec(bits).prec() < bits
}

/// Guard bits added to the working precision of every multi-precision evaluation.
pub(crate) const GUARD: u32 = 40;
