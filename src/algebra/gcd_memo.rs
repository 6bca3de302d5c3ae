//! Remembered gcds of one ring.
//!
//! A derivation meets the same denominators again and again: the components of a
//! vector or matrix share them, a dot product adds fractions over the same
//! denominators, and every sign case of a proof repeats the derivation.  The ring
//! therefore computes the gcd of two given polynomials once and recalls it after.
//! Small operands are not remembered, as FLINT's gcd is then cheaper than hashing.
//! The memo is bounded by the number of terms it holds, and is emptied when full.

use super::error::AlgResult;
use super::flint::Poly;
use std::collections::HashMap;
use std::sync::Mutex;

/// Operands with fewer terms together are not remembered.
const MIN_TERMS: usize = 12;
/// The memo is emptied when the polynomials it holds exceed this many terms.
const CAPACITY_TERMS: usize = 2_000_000;

#[derive(Default)]
struct Entries {
    map: HashMap<(Poly, Poly), Poly>,
    terms: usize,
}

/// A bounded memo of `gcd(a, b)` (see the module documentation).
#[derive(Default)]
pub(crate) struct GcdMemo {
    entries: Mutex<Entries>,
}

impl GcdMemo {
    /// `gcd(a, b)` with positive leading coefficient, as FLINT computes it.
    pub(crate) fn gcd(&self, a: &Poly, b: &Poly) -> AlgResult<Poly> {
        if a.len() + b.len() < MIN_TERMS {
            return Ok(a.gcd(b)?);
        }
        let key = if (a.len(), b.len()) <= (b.len(), a.len()) {
            (a.clone(), b.clone())
        } else {
            (b.clone(), a.clone())
        };
        if let Some(g) = self.lock().map.get(&key) {
            return Ok(g.clone());
        }
        let g = key.0.gcd(&key.1)?;
        let mut entries = self.lock();
        let size = key.0.len() + key.1.len() + g.len();
        if entries.terms + size > CAPACITY_TERMS {
            entries.map.clear();
            entries.terms = 0;
        }
        entries.terms += size;
        entries.map.insert(key, g.clone());
        Ok(g)
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Entries> {
        // A poisoned memo only lost an entry; its contents stay valid.
        self.entries.lock().unwrap_or_else(|e| e.into_inner())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::flint::Ctx;

    /// (x + y + 1)ⁿ·(x − y)ᵐ, large enough to be remembered.
    fn power(ctx: &std::sync::Arc<Ctx>, n: u32, m: u32) -> Poly {
        let (x, y) = (Poly::var(ctx, 0), Poly::var(ctx, 1));
        let a = x.add(&y).add(&Poly::from_i64(ctx, 1));
        let b = x.sub(&y);
        let mut p = Poly::from_i64(ctx, 1);
        for _ in 0..n {
            p = p.mul(&a);
        }
        for _ in 0..m {
            p = p.mul(&b);
        }
        p
    }

    #[test]
    fn recalled_gcds_equal_computed_ones_in_either_order() {
        let ctx = Ctx::new(2);
        let memo = GcdMemo::default();
        let (p, q) = (power(&ctx, 5, 2), power(&ctx, 3, 4));
        let direct = p.gcd(&q).unwrap();
        assert_eq!(direct, power(&ctx, 3, 2));
        assert_eq!(memo.gcd(&p, &q).unwrap(), direct);
        assert_eq!(memo.lock().map.len(), 1);
        assert_eq!(memo.gcd(&q, &p).unwrap(), direct);
        assert_eq!(memo.gcd(&p, &q).unwrap(), direct);
        assert_eq!(memo.lock().map.len(), 1);
        let small = power(&ctx, 1, 1);
        assert_eq!(memo.gcd(&small, &small).unwrap(), small);
        assert_eq!(memo.lock().map.len(), 1);
    }
}
