//! Denominators in factored form, remembered per ring.
//!
//! A normal form `N/D` needs `gcd(N, D)` after almost every operation, and a
//! multivariate gcd of two large polynomials is the costliest step of a derivation.
//! The denominators, however, are products: a product's denominator is the product
//! of the operands' (after crosswise cancellation), a sum's is their least common
//! multiple, a quotient's comes from a numerator.  So the ring remembers each
//! denominator as `unit · Π fᵢ^eᵢ` with primitive irreducible `fᵢ` of positive
//! leading coefficient ([`Factors`]):
//!
//! - arithmetic derives the factors of a result's denominator from its operands'
//!   (products add exponents, gcds take the smaller, least common multiples the
//!   larger), and only a denominator met for the first time is factored: first by
//!   trial division by the irreducible factors the ring has met, then by FLINT for
//!   what remains;
//! - `gcd(N, D)` is then `c · Π fᵢ^kᵢ`, where `kᵢ ≤ eᵢ` is how often `fᵢ` divides `N`
//!   (exact trial division) and `c` the gcd of the integer contents.  As every `fᵢ` is
//!   primitive with positive leading coefficient, this is FLINT's gcd, term for term,
//!   so the normal forms are unchanged (see [`cancel`]).
//!
//! The memo is bounded by the number of terms it holds, and is emptied when full.

use super::error::{AlgResult, AlgebraError};
use super::flint::{Factored, Poly};
use rug::Integer;
use std::collections::HashMap;
use std::sync::{Arc, Mutex};

/// A denominator `unit · Π factorᵢ^expᵢ`: the factors primitive, irreducible, with
/// positive leading coefficient, and pairwise distinct.
#[derive(Clone, Debug)]
pub(crate) struct Factors {
    /// The integer unit: the content, with the sign of the denominator's leading
    /// coefficient.
    pub unit: Integer,
    /// The irreducible factors with their multiplicities (all ≥ 1).
    pub list: Vec<(Poly, u64)>,
}

impl Factors {
    /// The factorisation of an integer.
    pub(crate) fn integer(unit: Integer) -> Factors {
        Factors {
            unit,
            list: Vec::new(),
        }
    }

    fn from_flint(f: Factored) -> Factors {
        Factors {
            unit: f.constant,
            list: f.factors,
        }
        .sorted()
    }

    /// The factors in a canonical order (by multiplicity, then by their terms), so that
    /// a factorisation is listed alike however it was found (FLINT's order depends on
    /// its algorithm's path).
    fn sorted(mut self) -> Factors {
        self.list.sort_by_cached_key(|(p, e)| (*e, TermKey::of(p)));
        self
    }

    /// Whether this is the factorisation of 1.
    pub(crate) fn is_one(&self) -> bool {
        self.unit == 1 && self.list.is_empty()
    }

    /// The factors of `self · other`.
    pub(crate) fn mul(&self, other: &Factors) -> Factors {
        Factors {
            unit: Integer::from(&self.unit * &other.unit),
            list: self.merged(other, |a, b| a + b),
        }
    }

    /// The factors of both lists, a factor in both with the exponent `join` of its two.
    fn merged(&self, other: &Factors, join: fn(u64, u64) -> u64) -> Vec<(Poly, u64)> {
        let mut list = self.list.clone();
        for (f, e) in &other.list {
            match list.iter_mut().find(|(g, _)| g == f) {
                Some((_, k)) => *k = join(*k, *e),
                None => list.push((f.clone(), *e)),
            }
        }
        list
    }

    /// The factors of `gcd(self, other)` (positive unit).
    pub(crate) fn gcd(&self, other: &Factors) -> Factors {
        let list = self
            .list
            .iter()
            .filter_map(|(f, e)| {
                let k = other.exponent_of(f).min(*e);
                (k > 0).then(|| (f.clone(), k))
            })
            .collect();
        Factors {
            unit: self.unit.clone().gcd(&other.unit),
            list,
        }
    }

    /// The factors of `lcm(self, other)` (positive unit).
    pub(crate) fn lcm(&self, other: &Factors) -> Factors {
        Factors {
            unit: self.unit.clone().lcm(&other.unit),
            list: self.merged(other, u64::max),
        }
    }

    /// The factors of `self / other`, where `other` divides `self`.
    pub(crate) fn div(&self, other: &Factors) -> AlgResult<Factors> {
        let mut list = Vec::with_capacity(self.list.len());
        for (f, e) in &self.list {
            let k = other.exponent_of(f);
            if k > *e {
                return Err(not_a_divisor());
            }
            if k < *e {
                list.push((f.clone(), e - k));
            }
        }
        let (q, r) = self.unit.clone().div_rem(other.unit.clone());
        if r != 0 || other.list.iter().any(|(f, _)| self.exponent_of(f) == 0) {
            return Err(not_a_divisor());
        }
        Ok(Factors { unit: q, list })
    }

    /// The factors of the square root with positive leading coefficient, if every
    /// exponent is even and the unit a positive square.
    pub(crate) fn half(&self) -> Option<Factors> {
        if self.unit < 0 || self.list.iter().any(|(_, e)| e % 2 != 0) {
            return None;
        }
        let (root, rem) = self.unit.clone().sqrt_rem(Integer::new());
        if rem != 0 {
            return None;
        }
        Some(Factors {
            unit: root,
            list: self.list.iter().map(|(f, e)| (f.clone(), e / 2)).collect(),
        })
    }

    /// The factors of `-self`.
    pub(crate) fn neg(&self) -> Factors {
        Factors {
            unit: Integer::from(-&self.unit),
            list: self.list.clone(),
        }
    }

    fn exponent_of(&self, f: &Poly) -> u64 {
        self.list
            .iter()
            .find(|(g, _)| g.len() == f.len() && g == f)
            .map_or(0, |(_, e)| *e)
    }

    /// The product, multiplied out.
    pub(crate) fn expand(&self, like: &Poly) -> AlgResult<Poly> {
        let mut p = Poly::from_integer(like.ctx(), &self.unit);
        for (f, e) in &self.list {
            p = p.mul(&f.pow(*e)?);
        }
        Ok(p)
    }

    fn terms(&self) -> usize {
        self.list.iter().map(|(f, _)| f.len()).sum::<usize>() + 1
    }
}

fn not_a_divisor() -> AlgebraError {
    AlgebraError::Internal("a factored denominator does not divide".into())
}

/// The memo is emptied when the polynomials it holds exceed this many terms.
const CAPACITY_TERMS: usize = 2_000_000;

/// The factorisations remembered across rings are forgotten beyond this many terms
/// (a term takes some tens of bytes: a coefficient and a few exponents).
const GLOBAL_CAPACITY_TERMS: usize = 500_000;

/// A map emptied when the sizes of its entries (in terms) would exceed `capacity`.
struct Bounded<K, V> {
    map: HashMap<K, V>,
    terms: usize,
}

impl<K: std::hash::Hash + Eq, V> Default for Bounded<K, V> {
    fn default() -> Self {
        Bounded {
            map: HashMap::new(),
            terms: 0,
        }
    }
}

impl<K: std::hash::Hash + Eq, V> Bounded<K, V> {
    fn insert(&mut self, key: K, value: V, size: usize, capacity: usize) {
        if self.terms + size > capacity {
            self.map.clear();
            self.terms = 0;
        }
        if self.map.insert(key, value).is_none() {
            self.terms += size;
        }
    }
}

/// Locks a memo; a poisoned one only lost an entry, and its contents stay valid.
fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// The remembered factorisations of a ring's denominators (see the module
/// documentation).
#[derive(Default)]
pub(crate) struct DenFactors {
    entries: Mutex<Bounded<Poly, Arc<Factors>>>,
    /// The distinct irreducible factors of the remembered denominators, with their
    /// degrees: tried first when a new denominator is factored.
    known: Mutex<Known>,
}

/// The irreducible factors a ring has met ([`DenFactors::known`]), at most
/// [`MAX_KNOWN`].
#[derive(Default)]
struct Known {
    list: Vec<(Poly, Vec<i64>)>,
    seen: std::collections::HashSet<Poly>,
}

/// The most irreducible factors a ring keeps for trial division.
const MAX_KNOWN: usize = 256;

impl DenFactors {
    /// The factorisation of `d` (non-zero): remembered, or computed by FLINT and
    /// remembered.
    pub(crate) fn of(&self, d: &Poly) -> AlgResult<Arc<Factors>> {
        if let Some(c) = d.as_constant() {
            return Ok(Arc::new(Factors::integer(c)));
        }
        if let Some(f) = lock(&self.entries).map.get(d) {
            return Ok(f.clone());
        }
        let f = Arc::new(self.factor_known_first(d)?);
        self.record(d, f.clone());
        Ok(f)
    }

    /// [`factor`] of `d` after dividing out the irreducible factors the ring has met
    /// (exact trial division; a factor of higher degree than `d` in some variable is
    /// skipped), so that FLINT factors only what remains.  The result is FLINT's
    /// factorisation: the factors met are FLINT's own, primitive with positive leading
    /// coefficient, so the rest has `d`'s unit.
    fn factor_known_first(&self, d: &Poly) -> AlgResult<Factors> {
        if d.len() == 1 {
            return factor(d);
        }
        if let Some(f) = remembered(d) {
            return Ok(f);
        }
        let degrees = d.degrees();
        let mut rest = d.clone();
        let mut found = Vec::new();
        for (f, fd) in &lock(&self.known).list {
            if fd.iter().zip(&degrees).any(|(a, b)| a > b) {
                continue;
            }
            let mut e = 0;
            while let Some(q) = rest.divides(f)? {
                rest = q;
                e += 1;
            }
            if e > 0 {
                found.push((f.clone(), e));
            }
        }
        if found.is_empty() {
            return flint_factor(d);
        }
        let mut f = match rest.as_constant() {
            Some(c) => Factors::integer(c),
            None => factor(&rest)?,
        };
        f.list.extend(found);
        let f = f.sorted();
        remember(d, &f);
        Ok(f)
    }

    /// Remembers that `d` has the factorisation `f` (derived by the caller from its
    /// operands').
    pub(crate) fn record(&self, d: &Poly, f: Arc<Factors>) {
        if d.as_constant().is_some() {
            return;
        }
        debug_assert!(f.expand(d).is_ok_and(|p| &p == d), "a wrong factorisation");
        let size = d.len() + f.terms();
        let mut known = lock(&self.known);
        for (p, _) in &f.list {
            if known.list.len() < MAX_KNOWN && !known.seen.contains(p) {
                known.seen.insert(p.clone());
                known.list.push((p.clone(), p.degrees()));
            }
        }
        drop(known);
        lock(&self.entries).insert(d.clone(), f, size, CAPACITY_TERMS);
    }
}

/// The factorisation of a non-constant `d`, as FLINT gives it: directly for a
/// monomial, recalled for a polynomial factored before in any ring (the factorisation
/// depends on the terms alone), by FLINT otherwise.
pub(crate) fn factor(d: &Poly) -> AlgResult<Factors> {
    if d.len() == 1 {
        let mut list = Vec::new();
        let mut unit = Integer::new();
        d.for_each_term(|c, e| {
            unit = c.clone();
            for (i, &k) in e.iter().enumerate() {
                if k > 0 {
                    list.push((Poly::var(d.ctx(), i), k));
                }
            }
        });
        return Ok(Factors { unit, list });
    }
    match remembered(d) {
        Some(f) => Ok(f),
        None => flint_factor(d),
    }
}

/// FLINT's factorisation of `d` (not a monomial), remembered across rings.
fn flint_factor(d: &Poly) -> AlgResult<Factors> {
    let f = Factors::from_flint(d.factor()?);
    remember(d, &f);
    Ok(f)
}

/// The factorisation of `d` remembered across rings, if any.
fn remembered(d: &Poly) -> Option<Factors> {
    let known = lock(&GLOBAL).map.get(&TermKey::of(d)).cloned()?;
    Some(Factors {
        unit: known.0.clone(),
        list: known.1.iter().map(|(k, e)| (k.poly(d), *e)).collect(),
    })
}

/// Remembers the factorisation `f` of `d` across rings.
fn remember(d: &Poly, f: &Factors) {
    let key = TermKey::of(d);
    let stored = (
        f.unit.clone(),
        f.list
            .iter()
            .map(|(p, e)| (TermKey::of(p), *e))
            .collect::<Vec<_>>(),
    );
    let size = key.terms() + stored.1.iter().map(|(k, _)| k.terms()).sum::<usize>();
    lock(&GLOBAL).insert(key, Arc::new(stored), size, GLOBAL_CAPACITY_TERMS);
}

/// A polynomial's terms, independent of its ring: the key of the factorisations
/// remembered across rings.  The number of variables, then each term's coefficient and
/// its non-zero exponents as (variable, exponent).
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
struct TermKey(usize, Vec<(Integer, Vec<(u32, u64)>)>);

impl TermKey {
    fn of(p: &Poly) -> TermKey {
        let mut terms = Vec::with_capacity(p.len());
        p.for_each_term(|c, e| {
            let sparse = (0u32..)
                .zip(e)
                .filter(|&(_, &k)| k > 0)
                .map(|(i, &k)| (i, k));
            terms.push((c.clone(), sparse.collect()));
        });
        TermKey(p.ctx().nvars(), terms)
    }

    /// The polynomial in the ring of `like`, which has the key's number of variables.
    fn poly(&self, like: &Poly) -> Poly {
        let full: Vec<(Integer, Vec<u64>)> = self
            .1
            .iter()
            .map(|(c, sparse)| {
                let mut e = vec![0u64; self.0];
                for &(i, k) in sparse {
                    e[i as usize] = k;
                }
                (c.clone(), e)
            })
            .collect();
        Poly::from_terms(like.ctx(), full.iter().map(|(c, e)| (c, e.as_slice())))
    }

    fn terms(&self) -> usize {
        self.1.len()
    }
}

/// A factorisation remembered across rings: the unit and the factors' terms.
type Stored = Arc<(Integer, Vec<(TermKey, u64)>)>;

/// Factorisations remembered across rings, by the terms of the factored polynomial.
static GLOBAL: std::sync::LazyLock<Mutex<Bounded<TermKey, Stored>>> =
    std::sync::LazyLock::new(|| Mutex::new(Bounded::default()));

/// `(n/g, g)` for `g = gcd(n, d)` (FLINT's gcd: positive leading coefficient, integer
/// content included), where `fd` is the factorisation of `d`, with the factors of `g`.
///
/// Each factor of `d` is divided out of `n` as often as it divides it, at most its
/// multiplicity in `d` (a factor of higher degree than `n` in some variable is not
/// tried); the integer contents share their gcd.
pub(crate) fn cancel(n: &Poly, fd: &Factors) -> AlgResult<(Poly, Factors)> {
    let mut cur = n.clone();
    let mut list = Vec::new();
    // A factor of higher degree than `cur` in some variable cannot divide it (the
    // degrees of an exact quotient are the differences).
    let mut degs = cur.degrees();
    for (f, e) in &fd.list {
        let fdegs = f.degrees();
        let mut k = 0;
        while k < *e && fdegs.iter().zip(&degs).all(|(a, b)| a <= b) {
            match cur.divides(f)? {
                Some(q) => {
                    cur = q;
                    k += 1;
                    for (b, a) in degs.iter_mut().zip(&fdegs) {
                        *b -= a;
                    }
                }
                None => break,
            }
        }
        if k > 0 {
            list.push((f.clone(), k));
        }
    }
    let c = if fd.unit == 1 || fd.unit == -1 {
        Integer::from(1)
    } else {
        cur.integer_content().gcd(&fd.unit)
    };
    if c != 1 {
        cur = cur.div_integer(&c)?;
    }
    Ok((cur, Factors { unit: c, list }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::flint::Ctx;

    fn polys() -> (Arc<Ctx>, Poly, Poly, Poly) {
        let ctx = Ctx::new(3);
        let (x, y, z) = (Poly::var(&ctx, 0), Poly::var(&ctx, 1), Poly::var(&ctx, 2));
        let one = Poly::from_i64(&ctx, 1);
        // x − y, x·z + 1, y² + z
        let a = x.sub(&y);
        let b = x.mul(&z).add(&one);
        let c = y.mul(&y).add(&z);
        (ctx, a, b, c)
    }

    #[test]
    fn cancelling_by_factors_is_flints_gcd() {
        let (ctx, a, b, c) = polys();
        let six = Poly::from_i64(&ctx, 6);
        let four = Poly::from_i64(&ctx, 4);
        // d = 6 a² b, n = 4 a b² c: gcd = 2 a b
        let d = six.mul(&a).mul(&a).mul(&b);
        let n = four.mul(&a).mul(&b).mul(&b).mul(&c);
        let memo = DenFactors::default();
        let fd = memo.of(&d).unwrap();
        let (rest, fg) = cancel(&n, &fd).unwrap();
        let g = n.gcd(&d).unwrap();
        assert_eq!(fg.expand(&d).unwrap(), g);
        assert_eq!(rest, n.divides(&g).unwrap().unwrap());
        // a numerator of negative sign and coprime to d
        let m = c.neg();
        let (rest, fg) = cancel(&m, &fd).unwrap();
        assert_eq!(rest, m);
        assert!(fg.expand(&d).unwrap().is_one());
    }

    /// A denominator whose factors the ring has met is factored by trial division
    /// first: the result is FLINT's factorisation, listed in the same canonical order.
    #[test]
    fn factors_met_before_are_divided_out_first() {
        let ctx = Ctx::new(3);
        let (x, y, z) = (Poly::var(&ctx, 0), Poly::var(&ctx, 1), Poly::var(&ctx, 2));
        let k = |n: i64| Poly::from_i64(&ctx, n);
        // polynomials of their own, so that no other test has factored them
        let a = x.sub(&y.scale(&Integer::from(7)));
        let b = x.mul(&z).scale(&Integer::from(3)).add(&k(5));
        let c = y.mul(&y).add(&z.scale(&Integer::from(11)));
        let memo = DenFactors::default();
        memo.of(&a.mul(&b)).unwrap();
        let d = k(-6).mul(&a).mul(&a).mul(&b).mul(&c);
        let mine = memo.of(&d).unwrap();
        let flint = Factors::from_flint(d.factor().unwrap());
        assert_eq!(mine.unit, flint.unit);
        // the same factors in the same (canonical) order
        assert_eq!(mine.list, flint.list);
        assert_eq!(mine.list.len(), 3);
        assert_eq!(mine.expand(&d).unwrap(), d);
    }

    #[test]
    fn derived_factorisations_multiply_out_to_their_polynomials() {
        let (ctx, a, b, c) = polys();
        let memo = DenFactors::default();
        let two = Poly::from_i64(&ctx, 2);
        let p = two.mul(&a).mul(&b).mul(&b);
        let q = a.mul(&a).mul(&c).neg();
        let (fp, fq) = (memo.of(&p).unwrap(), memo.of(&q).unwrap());
        assert_eq!(fp.mul(&fq).expand(&p).unwrap(), p.mul(&q));
        let g = fp.gcd(&fq);
        assert_eq!(g.expand(&p).unwrap(), p.gcd(&q).unwrap());
        let l = fp.lcm(&fq).expand(&p).unwrap();
        // lcm = p·q / gcd, up to sign
        let pq_over_g = p.mul(&q).divides(&p.gcd(&q).unwrap()).unwrap().unwrap();
        assert!(l == pq_over_g || l == pq_over_g.neg());
        assert_eq!(
            fp.div(&g).unwrap().expand(&p).unwrap(),
            p.divides(&p.gcd(&q).unwrap()).unwrap().unwrap()
        );
        assert!(fp.div(&fq).is_err());
        assert_eq!(fq.neg().expand(&q).unwrap(), q.neg());
    }

    use proptest::prelude::*;

    /// A polynomial in three variables from (coefficient, exponents) terms.
    fn poly(ctx: &Arc<Ctx>, terms: &[(i64, [u64; 3])]) -> Poly {
        let cs: Vec<Integer> = terms.iter().map(|(c, _)| Integer::from(*c)).collect();
        Poly::from_terms(ctx, cs.iter().zip(terms).map(|(c, (_, e))| (c, &e[..])))
    }

    fn terms() -> impl Strategy<Value = Vec<(i64, [u64; 3])>> {
        let coefficient = (1i64..=3, any::<bool>()).prop_map(|(c, neg)| if neg { -c } else { c });
        prop::collection::vec((coefficient, [0u64..3, 0u64..3, 0u64..3]), 1..4)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

        /// Cancelling `n/d` by the factors of `d` divides out FLINT's gcd, and the
        /// factorisations derived for products, gcds and quotients multiply out to the
        /// polynomials FLINT computes.
        #[test]
        fn factored_cancellation_is_flints_gcd(a in terms(), b in terms(), c in terms(), e in 1u64..3) {
            let ctx = Ctx::new(3);
            let (a, b, c) = (poly(&ctx, &a), poly(&ctx, &b), poly(&ctx, &c));
            prop_assume!(!a.is_zero() && !b.is_zero() && !c.is_zero());
            let d = a.mul(&b.pow(e).unwrap());
            let n = b.mul(&c);
            let memo = DenFactors::default();
            let fd = memo.of(&d).unwrap();
            let (rest, fg) = cancel(&n, &fd).unwrap();
            let g = n.gcd(&d).unwrap();
            let mine = fg.expand(&d).unwrap();
            prop_assert_eq!(&mine, &g);
            prop_assert_eq!(rest, n.divides(&g).unwrap().unwrap());
            let fq = fd.div(&fg).unwrap();
            prop_assert_eq!(fq.expand(&d).unwrap(), d.divides(&g).unwrap().unwrap());
            let fc = memo.of(&c).unwrap();
            prop_assert_eq!(fd.mul(&fc).expand(&d).unwrap(), d.mul(&c));
            let common = fd.gcd(&fc).expand(&d).unwrap();
            prop_assert_eq!(common, d.gcd(&c).unwrap());
        }
    }
}
