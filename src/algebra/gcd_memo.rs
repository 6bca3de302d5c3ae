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
    let (mut free_a, mut free_b) = (only_a, only_b);
    if free_a.is_empty() && free_b.is_empty() {
        let outside = outside_gcd(a, b, &va);
        if outside.is_empty() {
            return Ok(a.gcd(b)?);
        }
        (free_a, free_b) = (outside.clone(), outside);
    }
    let mut parts = parts_free_of(a, &free_a);
    parts.extend(parts_free_of(b, &free_b));
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

/// Operands this large together are tested for variables outside their gcd.
const IMAGE_TERMS: usize = 400;

/// The variables of `vars` (which both `a` and `b` use) that provably do not occur
/// in `gcd(a, b)`.
///
/// Every variable but `x` is replaced by a fixed integer and everything is taken
/// modulo the prime 2⁶¹ − 1.  Where the leading coefficient of `a` in `x` does not
/// vanish there, a factor of the gcd of positive degree in `x` keeps its degree and
/// divides both univariate images, so a constant gcd of the images excludes `x`.
/// The point is fixed, so the result is deterministic; an unlucky point only
/// leaves a variable in.
fn outside_gcd(a: &Poly, b: &Poly, vars: &[usize]) -> Vec<usize> {
    if a.len() + b.len() < IMAGE_TERMS {
        return Vec::new();
    }
    let n = a.ctx().nvars();
    let point: Vec<u64> = (0..n as u64).map(|i| 2 + (i * 7 + 3) % 19).collect();
    let (ia, ib) = (images(a, &point, vars), images(b, &point, vars));
    let da = a.degrees();
    vars.iter()
        .zip(ia.iter().zip(&ib))
        .filter(|(&x, (pa, pb))| {
            degree(pa) == da[x] as usize && degree(&modp::gcd((*pa).clone(), (*pb).clone())) == 0
        })
        .map(|(&x, _)| x)
        .collect()
}

/// For each variable `x` of `vars`, the coefficients (by power of `x`) of `p` with
/// every other variable replaced by its value in `point`, modulo [`modp::P`].
fn images(p: &Poly, point: &[u64], vars: &[usize]) -> Vec<Vec<u64>> {
    let mut out: Vec<Vec<u64>> = vars.iter().map(|_| Vec::new()).collect();
    let inv: Vec<u64> = point.iter().map(|&v| modp::inv(v)).collect();
    p.for_each_term(|c, e| {
        let mut full = modp::reduce_integer(c);
        for (j, &ej) in e.iter().enumerate() {
            if ej > 0 {
                full = modp::mul(full, modp::pow(point[j], ej));
            }
        }
        for (k, &x) in vars.iter().enumerate() {
            let term = modp::mul(full, modp::pow(inv[x], e[x]));
            let slot = &mut out[k];
            let ex = e[x] as usize;
            if slot.len() <= ex {
                slot.resize(ex + 1, 0);
            }
            slot[ex] = modp::add(slot[ex], term);
        }
    });
    out
}

/// The degree of a coefficient vector (0 for the zero polynomial too).
fn degree(p: &[u64]) -> usize {
    p.iter().rposition(|&c| c != 0).unwrap_or(0)
}

/// Arithmetic modulo the Mersenne prime 2⁶¹ − 1.
mod modp {
    use rug::Integer;

    /// The modulus.
    pub(super) const P: u64 = (1 << 61) - 1;

    pub(super) fn add(a: u64, b: u64) -> u64 {
        let s = a + b;
        if s >= P {
            s - P
        } else {
            s
        }
    }

    pub(super) fn sub(a: u64, b: u64) -> u64 {
        if a >= b {
            a - b
        } else {
            a + P - b
        }
    }

    pub(super) fn mul(a: u64, b: u64) -> u64 {
        ((a as u128 * b as u128) % P as u128) as u64
    }

    pub(super) fn pow(mut b: u64, mut e: u64) -> u64 {
        let mut r = 1;
        while e > 0 {
            if e & 1 == 1 {
                r = mul(r, b);
            }
            b = mul(b, b);
            e >>= 1;
        }
        r
    }

    /// The inverse of a nonzero residue (Fermat).
    pub(super) fn inv(a: u64) -> u64 {
        pow(a, P - 2)
    }

    /// The residue of an integer in `[0, P)`.
    pub(super) fn reduce_integer(c: &Integer) -> u64 {
        let r = Integer::from(c % P);
        if r < 0 {
            (r + P).to_u64_wrapping()
        } else {
            r.to_u64_wrapping()
        }
    }

    /// A gcd (not normalised) of two coefficient vectors (trailing zeros allowed).
    pub(super) fn gcd(mut a: Vec<u64>, mut b: Vec<u64>) -> Vec<u64> {
        trim(&mut a);
        trim(&mut b);
        while !b.is_empty() {
            let r = rem(a, &b);
            a = b;
            b = r;
        }
        a
    }

    fn trim(p: &mut Vec<u64>) {
        while p.last() == Some(&0) {
            p.pop();
        }
    }

    fn rem(mut a: Vec<u64>, b: &[u64]) -> Vec<u64> {
        let lead_inv = inv(b[b.len() - 1]);
        while a.len() >= b.len() {
            let q = mul(a[a.len() - 1], lead_inv);
            let shift = a.len() - b.len();
            for (i, &bi) in b.iter().enumerate() {
                a[shift + i] = sub(a[shift + i], mul(q, bi));
            }
            trim(&mut a);
        }
        a
    }
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

    #[test]
    fn variables_outside_the_gcd_are_found_and_the_gcd_is_flints() {
        let ctx = Ctx::new(4);
        let x = |i| Poly::var(&ctx, i);
        let one = Poly::from_i64(&ctx, 1);
        let common = x(0).sub(&x(1)).mul(&x(0).add(&one)).mul(&x(0));
        for seed in 0..4u64 {
            let big = |k: u64| {
                scrambled(&ctx, k, &[0, 1, 2, 3], 30).mul(&scrambled(
                    &ctx,
                    k + 9,
                    &[0, 1, 2, 3],
                    30,
                ))
            };
            let (a, b) = (big(seed).mul(&common), big(seed + 50).mul(&common));
            assert!(a.len() + b.len() >= IMAGE_TERMS);
            let outside = outside_gcd(&a, &b, &[0, 1, 2, 3]);
            assert_eq!(outside, vec![2, 3]);
            assert_eq!(
                split_gcd(&a, &b).unwrap(),
                a.gcd(&b).unwrap(),
                "seed {seed}"
            );
            // a common factor in x2 keeps x2 in
            let c = a.mul(&x(2).add(&one));
            let d = b.mul(&x(2).add(&one));
            assert!(!outside_gcd(&c, &d, &[0, 1, 2, 3]).contains(&2));
            assert_eq!(split_gcd(&c, &d).unwrap(), c.gcd(&d).unwrap());
        }
    }

    #[test]
    fn residues_modulo_the_prime() {
        let p = rug::Integer::from(modp::P);
        assert_eq!(modp::reduce_integer(&rug::Integer::from(-1)), modp::P - 1);
        assert_eq!(modp::reduce_integer(&(p.clone() * 3 + 5)), 5);
        assert_eq!(modp::mul(modp::inv(12345), 12345), 1);
        // (t − 1)(t + 2) and (t − 1)(t − 3) share t − 1
        let f = vec![modp::P - 2, 1, 1];
        let g = vec![3, modp::P - 4, 1];
        assert_eq!(degree(&modp::gcd(f, g)), 1);
    }
}
