//! Special functions: Jacobi elliptic functions of real and complex arguments, the
//! elliptic integrals of the first, second and third kind, Jacobi's zeta and Heuman's
//! lambda functions, the nome and the theta functions, at any precision.
//!
//! **Modulus convention.** Every function takes the *modulus* `k` (as in the paper and
//! in DLMF §22.2), **not** the parameter `m = k²` used by mpmath, SciPy and
//! Abramowitz–Stegun (for that, [`sncndn_m`]).  The complementary modulus is
//! `k' = √(1−k²)`, computed as `√((1−k)(1+k))` so that it keeps full relative accuracy
//! as `k → 1`.  The Jacobi functions of a real argument take any `k ≥ 0` (`k = 1`:
//! `tanh`, `sech`, DLMF 22.5.ii; `k > 1`: DLMF 22.17.2–4) and [`sncndn_m`] any real
//! `m` (`m < 0`: imaginary modulus, DLMF 22.17.6–8); so does the complex argument
//! ([`sncndn_complex`] any `k ≥ 0`, [`sncndn_complex_m`] any real `m`); the elliptic
//! integrals take `0 ≤ k < 1` (those of the second kind `0 ≤ k ≤ 1`).  Anything else
//! (including NaN) is an error, never a panic.
//!
//! All functions are written once, generically over [`Real`] / [`ComplexScalar`](crate::numbers::ComplexScalar):
//! they run on `f64`, on `rug::Float` at any precision, on complex pairs and on
//! [`crate::numbers::Dual`] (automatic differentiation flows through the algorithms,
//! e.g. `d/du sn = cn·dn` comes out of the arithmetic).
//!
//! # Algorithms (and why)
//!
//! One function, `jacobi::sncndn_imp`, chooses the algorithm, trying the special cases
//! in order (as Boost's `jacobi_elliptic` does): the modulus transformations of DLMF
//! §22.17 to `κ ∈ [0, 1]`; `κ = 0` (DLMF 22.5.3); `κ = 1` (DLMF 22.5.ii); then the
//! fixed-precision theta bottoms or the multi-precision Landen chain.  The bottoms
//! (`Bottom`) are cross-checked against each other and MPFR at random moduli
//! (`special/tests.rs`).
//!
//! * **Fixed precision** (`Real::FIXED`: `f64`, `Dual<f64>`; no guard bits, so every
//!   rounding counts and speed matters; module `theta`): sn, cn, dn as theta quotients
//!   (DLMF 22.2.4) of a nome `q < 0.1` — the modulus itself for `κ² ≤ 0.81`, else the
//!   complementary modulus at imaginary argument (DLMF Table 22.6.1) — written as
//!   `leading factor × (1 + small)` with the leading factor `sin ζ`, `cos ζ`, `tanh y`
//!   or `sech y`, so every output keeps relative accuracy next to its zeros.  Every
//!   per-modulus quantity (the nome from Jacobi's series in `ε = (1−√κ')/(2(1+√κ'))`,
//!   `π/(2K)` from two AGM steps, the period at imaginary argument from a table-driven
//!   logarithm) is computed in `f64` / double-double (module `dd`), so a new modulus
//!   costs about as much as one evaluation; for `f64` the series takes the nome and
//!   `π/(2K)` from piecewise polynomial fits in `κ²` instead (module `series_fit`, no
//!   square root or division); the last few are cached per thread.
//!   Measured (dense sweeps, `reports/accuracy.md`): absolute error below 2 ε for every
//!   `k`.
//! * **Moduli chain** (module `landen`, multi-precision): the descending Landen / Gauss
//!   transformation `k₁ = k²/(1+k')²`, `k₁' = 2√k'/(1+k')` (DLMF 22.7.1–3, 19.8.12),
//!   iterated until `k_N⁴` is below the working epsilon (quadratic convergence, about
//!   10 steps at 4096 bits), kept as the AGM sequence `aₙ, bₙ, cₙ` (DLMF 19.8.1–2) with
//!   `kₙ = cₙ/aₙ`, `1 + kₙ = aₙ₋₁/aₙ`: one product and one square root per level.  The
//!   quarter period follows as `K = (π/2)·Π(1+k_n)·(1+k_N²/4) = π(1 + k_N²/4)/(2a_N)`.
//! * **sn, cn, dn of a real argument, multi-precision** (module `multi`): the argument
//!   is reduced to `u = jK + t`, `|t| ≤ K/2`; at the bottom of the chain
//!   `sn(t/Π(1+k_n), k_N)` comes from `sin`/`cos` (Arb's `arb_sin_cos`, module
//!   `sincos`, faster than MPFR's) with the first-order correction
//!   DLMF 22.10.4–6, then only `sn` is carried up the chain (DLMF 22.7.1; one division
//!   and three products per level) and `cn = √((1−sn)(1+sn))` (DLMF 22.6.1) at the top,
//!   `dn` from the top step (DLMF 22.7.3; for `rug::Float`, else `√(k'² + k²cn²)`); since `cn(t) ≥ √(k'/(1+k'))` for `|t| ≤ K/2` this loses at
//!   most `log2(1/k')` bits, which are added to the working precision.  The quadrant
//!   `j mod 4` is applied with the quarter-period shifts DLMF 22.4.3
//!   (`sn(t+K) = cd t`, `cn(t+K) = −k' sd t`, `dn(t+K) = k' nd t`), which keep relative
//!   accuracy next to the zeros (the complex case needs that near its poles).
//! * **Argument reduction.**  For MPFR the working precision is raised to
//!   `N + 40 + log2(1/k') + log2|j| + (cancellation bits of t)`, adaptively: if `t = u − jK`
//!   cancels, the reduction is repeated with more bits.  For fixed-precision types
//!   `ζ = u·π/(2K)` is reduced by the double-double period for `|u/K| ≤ 256` (the series
//!   with its nome in `f64` for `|u/K| ≤ 64`); beyond that, or when the reduced argument
//!   cancels by more than 20 bits (8 bits), `t = u − jK` is
//!   formed with error-free transformations from `K` as a triple-double of a 200-bit
//!   MPFR AGM (module `reduce`, cached per modulus), while the derivative with respect
//!   to `k` still flows through the generic `K`.
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
//! * **E, Π, Z, Λ₀** (modules `second`, `third`, `zeta` on `carlson`): Carlson's
//!   symmetric integrals `R_F`, `R_D`, `R_J` by the duplication algorithm (DLMF
//!   19.36.1–2), the amplitude reduced to `[−π/4, π/2]` with its sine and squared
//!   cosine taken exactly from the residual (module `phase`), and each function written
//!   as a sum of terms of one sign (DLMF 19.25.1, 19.25.10, 19.25.14; for `n < 0`
//!   Abramowitz–Stegun 17.7.15).  In fixed precision (no guard bits) the duplication
//!   terms of `R_D` and `R_J` are summed with their rounding errors collected
//!   (two-sums) and added to the series part error-free, the last step of `R_F`,
//!   `(1 + s)/√a`, is rounded about once, and `k'² = 1 − k²` is rounded once; that took
//!   the worst `f64` errors of `E` and `E(φ)` from 2.3–2.8 ε to 1.4–1.8 ε and those of
//!   `Π` from 2.7–3.1 ε to 2.2–2.9 ε.  `Π`, `Z` and `Λ₀` then combine their factors
//!   (`sin φ`, `cos φ`, `R_F`, `R_J`, for `n < 0` the three terms) in double-double and
//!   round once, with `AGM(1, k')` from the scale of the theta data (module `theta`, to
//!   about `2⁻⁸⁵`) and `Λ₀` folded to `[−π/4, π/2]` by `Λ₀(φ + π) = Λ₀(φ) + 2`: worst
//!   `Π` 1.97 ε (2.48 ε in the corner `n sin²φ → 1`, `k → 1`, where it is
//!   ill-conditioned in `φ`), `Z` 2.18 ε, `Λ₀` 1.79 ε (`reports/accuracy.md`).
//!   [`ToolkitFn`] names them for callers that choose at run time (the expression
//!   language).
//! * **Nome and θ_j** (module `jtheta`): Jacobi's series for `q` after Landen steps;
//!   the theta series for `q ≤ 1/4`, Gaussian sums after Jacobi's imaginary
//!   transformation above.
//!
//! # Error behaviour
//!
//! Results at precision `N` are computed at `N + guard` bits and rounded once; the
//! measured errors (see `reports/accuracy.md`) are below `2^(4−N)` absolute for real
//! arguments and relative to `max(1,|value|)` for complex ones.  Next to a pole of one
//! of the twelve functions (a zero of its denominator) the value depends on the last
//! bits of `u`: its relative condition number `κ_u = |u f'(u)/f(u)|`
//! ([`JacobiFn::condition`]) reaches `10¹⁷` at the double nearest to a zero.  The
//! evaluation itself stays accurate there (measured: within 1.3 ε in `f64` and 0.4 ε_N
//! at 64 bits relative to the value at the given `u`, `reports/accuracy.md`, where the
//! multi-precision path repeats a transformed modulus with the bits `κ_u` costs), but a
//! change of `u` in its last bit moves the exact value by `κ_u` units of its last bit;
//! `eulertop jacobi` says so on standard error where `κ_u ≥ 2^⌈N/2⌉`.  `f64` results are
//! within a few ulp of 1 in absolute terms (see the report for measured maxima).
//! Errors are reported as [`SpecialError`]: modulus outside the domain, non-finite input,
//! arguments so large that `u/K ≥ 2⁵⁰`, poles (complex argument exactly at a pole,
//! `K'(0)`), inconsistent input to [`jacobi_inverse`].

mod agm;
mod bottom;
mod carlson;
mod complex;
mod complex_modulus;
mod condition;
mod dd;
mod ellint;
mod fixed;
mod glaisher;
mod inverse;
mod jacobi;
mod jtheta;
mod landen;
mod landen_mpfr;
mod modulus;
mod multi;
mod phase;
mod reduce;
mod second;
mod series_fit;
mod series_fit_table;
mod sincos;
#[cfg(test)]
mod tests;
mod theta;
mod third;
mod toolkit;
mod zeta;

pub use agm::{ellipk, ellipkp};
pub use complex::{sncndn_complex, sncndn_complex_m};
pub use complex_modulus::sncndn_complex_modulus;
pub use ellint::ellipf;
pub use glaisher::{
    JacobiFn, jacobi, jacobi_complex, jacobi_complex_m_set, jacobi_complex_set, jacobi_m,
    jacobi_m_set, jacobi_set,
};
pub use inverse::jacobi_inverse;
pub use jacobi::{am, sncndn, sncndn_m, sncndn_many};
pub use jtheta::{jtheta, nome};
pub use second::{ellipe, ellipeinc};
pub use third::ellippi;
pub use toolkit::ToolkitFn;
pub use zeta::{heumanlambda, jacobizeta};

use crate::numbers::Real;

/// Errors of the special-function layer.  Every variant carries a one-line message
/// naming the offending value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SpecialError {
    /// The modulus (or parameter) is outside the domain of the function (or is NaN).
    #[error("modulus {0}")]
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
    /// An argument outside the domain where the function is real and finite (e.g. the
    /// characteristic `n > 1/sin²φ` of `Π(n, φ, k)`).
    #[error("domain: {0}")]
    Domain(String),
    /// Input values that are not sn, cn, dn of one real argument.
    #[error("inconsistent input: {0}")]
    Inconsistent(String),
    /// The scalar type evaluates elliptic functions by rules of its own
    /// ([`Real::BY_RULE`]), and the rule failed or this function has none.
    #[error("{0}")]
    Rule(String),
}

/// Refuses a function without a rule for a type that evaluates by rules
/// ([`Real::BY_RULE`]): such a type must never run the numerical iterations.
#[inline]
pub(crate) fn refuse_by_rule<R: Real>(what: &str) -> Result<(), SpecialError> {
    if R::BY_RULE {
        return Err(SpecialError::Rule(format!(
            "{what} is not algebraic: no exact rule for it"
        )));
    }
    Ok(())
}

/// Checks that the modulus `k` is finite and `k ≥ 0` (the Jacobi functions of a real
/// argument take any such `k`).
#[inline]
pub(crate) fn check_modulus<R: Real>(k: &R) -> Result<(), SpecialError> {
    if !k.is_finite() || *k < k.zero() {
        return Err(modulus_error(k, "[0, ∞)"));
    }
    Ok(())
}

/// `|k|` for the functions that depend on `k²` only, such as sn, cn, dn (DLMF 22.17.1:
/// a negative modulus gives the values of its absolute value); a modulus that is not
/// finite is an error.
#[inline]
pub(crate) fn even_modulus<R: Real>(k: &R) -> Result<R, SpecialError> {
    if !k.is_finite() {
        return Err(modulus_error(k, "(-∞, ∞)"));
    }
    Ok(if *k < k.zero() { -k.clone() } else { k.clone() })
}

/// Checks `0 ≤ k < 1` and finiteness (elliptic integrals).
#[inline]
pub(crate) fn check_modulus_below_one<R: Real>(k: &R) -> Result<(), SpecialError> {
    if !k.is_finite() || *k < k.zero() || *k >= k.one() {
        return Err(modulus_error(k, "[0, 1)"));
    }
    Ok(())
}

#[cold]
pub(crate) fn modulus_error<R: Real>(k: &R, range: &str) -> SpecialError {
    SpecialError::ModulusOutOfRange(format!("k = {} is outside {range}", show(k)))
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

/// Guard bits added to the working precision of every multi-precision evaluation.
pub(crate) const GUARD: u32 = 40;
