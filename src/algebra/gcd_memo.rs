//! Remembered gcds of one ring.
//!
//! A derivation meets the same denominators again and again: the components of a
//! vector or matrix share them, a dot product adds fractions over the same
//! denominators, and every sign case of a proof repeats the derivation.  The ring
//! therefore computes the gcd of two given polynomials once and recalls it after.
//! Small operands are not remembered, as FLINT's gcd is then cheaper than hashing.
//! The memo is bounded by the number of terms it holds, and is emptied when full.
//!
//! Before FLINT's gcd, two cheaper routes are tried (see [`split_gcd`]): a divisor
//! of the other operand is the gcd itself, and a variable that occurs in one
//! operand only cannot occur in the gcd, so that operand is replaced by its
//! coefficients in such variables, smallest first.  The derivations' gcds are
//! mostly of this kind: a numerator free of the square roots against a
//! denominator with them, sharing a factor such as `A − C`.

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
        let g = split_gcd(&key.0, &key.1)?;
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

/// `gcd(a, b)` as FLINT defines it (positive leading coefficient, integer content
/// included), by the routes of the module documentation.
pub(crate) fn split_gcd(a: &Poly, b: &Poly) -> AlgResult<Poly> {
    if a.is_zero() || b.is_zero() || a.len() + b.len() < MIN_TERMS {
        return Ok(a.gcd(b)?);
    }
    if let Some(g) = divisor_of_other(a, b)? {
        return Ok(g);
    }
    let (va, vb) = (a.used_vars(), b.used_vars());
    let only_a: Vec<usize> = va.iter().copied().filter(|i| !vb.contains(i)).collect();
    let only_b: Vec<usize> = vb.iter().copied().filter(|i| !va.contains(i)).collect();
    if only_a.is_empty() && only_b.is_empty() {
        return Ok(a.gcd(b)?);
    }
    let mut parts = parts_free_of(a, &only_a);
    parts.extend(parts_free_of(b, &only_b));
    parts.sort_by_key(Poly::len);
    let mut g = parts[0].clone();
    for p in &parts[1..] {
        if let Some(c) = g.as_constant() {
            // Only the integer content is left to share.
            let mut z = c.abs();
            for q in &parts[1..] {
                z = z.gcd(&q.integer_content());
            }
            return Ok(Poly::from_integer(a.ctx(), &z));
        }
        g = split_gcd(&g, p)?;
    }
    Ok(g)
}

/// `[p]`, or the coefficients of `p` in `vars` when there are any.
fn parts_free_of(p: &Poly, vars: &[usize]) -> Vec<Poly> {
    if vars.is_empty() {
        vec![p.clone()]
    } else {
        p.coefficients_in(vars)
    }
}

/// `±b` when `b` divides `a` (or `±a` when `a` divides `b`), with positive
/// leading coefficient: the gcd without a gcd computation, tried only where the
/// lengths and degrees allow it.
fn divisor_of_other(a: &Poly, b: &Poly) -> AlgResult<Option<Poly>> {
    for (big, small) in [(a, b), (b, a)] {
        if small.len() > big.len() {
            continue;
        }
        let (db, ds) = (big.degrees(), small.degrees());
        if ds.iter().zip(&db).any(|(s, b)| s > b) {
            continue;
        }
        if big.divides(small)?.is_some() {
            let g = if small.leading_coefficient() < 0 {
                small.neg()
            } else {
                small.clone()
            };
            return Ok(Some(g));
        }
    }
    Ok(None)
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

    /// A polynomial in three variables from a small linear congruential generator.
    fn scrambled(ctx: &std::sync::Arc<Ctx>, seed: u64, vars: &[usize], terms: usize) -> Poly {
        let mut state = seed;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            state >> 33
        };
        let mut p = Poly::zero(ctx);
        for _ in 0..terms {
            let mut t = Poly::from_i64(ctx, (next() % 7) as i64 - 3);
            for &v in vars {
                for _ in 0..next() % 3 {
                    t = t.mul(&Poly::var(ctx, v));
                }
            }
            p = p.add(&t);
        }
        p.add(&Poly::from_i64(ctx, 1))
    }

    #[test]
    fn split_gcds_equal_flints_with_variables_missing_from_one_side() {
        let ctx = Ctx::new(4);
        let x = |i| Poly::var(&ctx, i);
        let one = Poly::from_i64(&ctx, 1);
        let common = x(0)
            .sub(&x(1))
            .mul(&x(0).add(&one))
            .scale(&rug::Integer::from(6));
        for seed in 0..12u64 {
            // a lacks x3, b lacks x2; both share `common`.
            let a = scrambled(&ctx, seed, &[0, 1, 2], 8).mul(&common);
            let b = scrambled(&ctx, seed + 100, &[0, 1, 3], 8).mul(&common);
            let b = b.scale(&rug::Integer::from(4));
            assert_eq!(
                split_gcd(&a, &b).unwrap(),
                a.gcd(&b).unwrap(),
                "seed {seed}"
            );
            // a divisor of the other operand
            let c = a.mul(&scrambled(&ctx, seed + 7, &[2, 3], 4));
            assert_eq!(split_gcd(&c, &a.neg()).unwrap(), a.gcd(&c).unwrap());
            assert!(split_gcd(&c, &a.neg()).unwrap().leading_coefficient() > 0);
        }
    }
}
