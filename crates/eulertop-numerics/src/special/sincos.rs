//! `sin` and `cos` of a multi-precision argument, the one transcendental evaluation at
//! the bottom of the Landen chain: from Arb (FLINT's ball arithmetic, `arb_sin_cos`)
//! from [`ARB_MIN_PREC`] bits on, else from MPFR.  Measured at 1088 bits, Arb's
//! `sin_cos` takes 5.8 µs (through python-flint, call included) where `mpfr_sin_cos`
//! takes 7.8 µs, and a whole evaluation of sn, cn, dn is 10–15 % faster from 100 to
//! 4000 bits (`reports/performance.md`).  Arb
//! returns balls that contain the exact values; their midpoints are rounded to the
//! target precision, and a ball relatively wider than `2^(−prec)` (which does not happen
//! for these arguments) falls back to MPFR, so the result is within one ulp.  Without
//! the feature `arb` every evaluation is MPFR's correctly rounded `sin_cos`.

#[cfg(feature = "arb")]
use flint_sys::arb::{arb_clear, arb_init, arb_rel_accuracy_bits, arb_sin_cos};
#[cfg(feature = "arb")]
use flint_sys::arb_types::arb_struct;
#[cfg(feature = "arb")]
use flint_sys::arf::{arf_get_mpfr, arf_set_mpfr};
#[cfg(feature = "arb")]
use flint_sys::deps::{__mpfr_struct, mpfr_rnd_t_MPFR_RNDN};
use rug::{Assign, Float};
#[cfg(feature = "arb")]
use std::mem::MaybeUninit;

/// Precision (bits) from which Arb is used.
#[cfg(feature = "arb")]
const ARB_MIN_PREC: u32 = 64;

/// Extra bits of the Arb evaluation.
#[cfg(feature = "arb")]
const ARB_GUARD: u32 = 16;

/// An initialised Arb ball, cleared on drop.
#[cfg(feature = "arb")]
struct Ball(arb_struct);

#[cfg(feature = "arb")]
impl Ball {
    fn new() -> Self {
        let mut b = MaybeUninit::<arb_struct>::uninit();
        // SAFETY: arb_init initialises the struct it is given (exact zero).
        unsafe {
            arb_init(b.as_mut_ptr());
            Ball(b.assume_init())
        }
    }
}

#[cfg(feature = "arb")]
impl Drop for Ball {
    fn drop(&mut self) {
        // SAFETY: the ball was initialised by arb_init and is cleared once.
        unsafe { arb_clear(&mut self.0) }
    }
}

/// `(sin z, cos z)` into `s` and `c` (which keep their precisions).
#[cfg(feature = "arb")]
pub(crate) fn sin_cos_into(z: &Float, s: &mut Float, c: &mut Float) {
    let p = s.prec().max(c.prec());
    if p < ARB_MIN_PREC || z.is_zero() || !z.is_finite() || !arb_sin_cos_into(z, s, c, p) {
        (s, c).assign(z.sin_cos_ref());
    }
}

/// `(sin z, cos z)` into `s` and `c` (which keep their precisions), from MPFR.
#[cfg(not(feature = "arb"))]
pub(crate) fn sin_cos_into(z: &Float, s: &mut Float, c: &mut Float) {
    (s, c).assign(z.sin_cos_ref());
}

/// Arb's `sin_cos` at `p + ARB_GUARD` bits; `false` (nothing written) when a ball is
/// relatively wider than `2^(−p)`.
#[cfg(feature = "arb")]
fn arb_sin_cos_into(z: &Float, s: &mut Float, c: &mut Float, p: u32) -> bool {
    let (mut x, mut bs, mut bc) = (Ball::new(), Ball::new(), Ball::new());
    let prec = i64::from(p + ARB_GUARD);
    // SAFETY: rug and flint-sys link one and the same MPFR (gmp-mpfr-sys), so a
    // `rug::Float` is a valid `__mpfr_struct`; every ball is initialised.
    unsafe {
        arf_set_mpfr(&mut x.0.mid, z.as_raw().cast::<__mpfr_struct>());
        arb_sin_cos(&mut bs.0, &mut bc.0, &x.0, prec);
        let need = i64::from(p);
        if arb_rel_accuracy_bits(&bs.0) < need || arb_rel_accuracy_bits(&bc.0) < need {
            return false;
        }
        arf_get_mpfr(
            s.as_raw_mut().cast::<__mpfr_struct>(),
            &bs.0.mid,
            mpfr_rnd_t_MPFR_RNDN,
        );
        arf_get_mpfr(
            c.as_raw_mut().cast::<__mpfr_struct>(),
            &bc.0.mid,
            mpfr_rnd_t_MPFR_RNDN,
        );
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Against MPFR's correctly rounded `sin_cos` at random arguments in `[−1, 1]` and
    /// precisions from 64 to 4200 bits: within one ulp.
    #[test]
    fn arb_sin_cos_against_mpfr() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        for _ in 0..200 {
            let p = rng.gen_range(64..4200u32);
            let z = Float::with_val(p, rng.gen_range(-1.0..1.0f64)) / 3u32 * 2u32;
            let (mut s, mut c) = (Float::new(p), Float::new(p));
            sin_cos_into(&z, &mut s, &mut c);
            let (ws, wc) = (
                Float::with_val(p, z.sin_ref()),
                Float::with_val(p, z.cos_ref()),
            );
            for (got, want) in [(&s, &ws), (&c, &wc)] {
                let ulp = Float::with_val(64, want.get_exp().map_or(0, |e| e) - p as i32).exp2();
                let err = Float::with_val(p + 64, got - want).abs();
                assert!(err <= ulp, "p = {p}, z = {z}: error {err} > ulp {ulp}");
            }
        }
    }
}
