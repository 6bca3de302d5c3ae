//! Classes modulo squares: the vector over GF(2) of a radicand's odd exponents, with
//! one coordinate per factor met so far (−1, a prime, an irreducible polynomial), and
//! the reduced echelon form of the root symbols' vectors (module [`super::roots`]
//! keeps them independent, so the tower is a field).

use super::flint::Poly;
use rug::Integer;

/// A bit vector over GF(2).
#[derive(Clone, Default, PartialEq, Eq, Debug)]
pub(crate) struct Bits(Vec<u64>);

impl Bits {
    /// Is bit `i` set?
    pub fn get(&self, i: usize) -> bool {
        self.0.get(i / 64).is_some_and(|w| w >> (i % 64) & 1 == 1)
    }
    /// Flips bit `i`.
    pub fn flip(&mut self, i: usize) {
        if self.0.len() <= i / 64 {
            self.0.resize(i / 64 + 1, 0);
        }
        self.0[i / 64] ^= 1 << (i % 64);
    }
    /// Adds `o` (over GF(2)).
    pub fn xor(&mut self, o: &Bits) {
        if self.0.len() < o.0.len() {
            self.0.resize(o.0.len(), 0);
        }
        for (a, b) in self.0.iter_mut().zip(&o.0) {
            *a ^= b;
        }
    }
    /// Is every bit clear?
    pub fn is_zero(&self) -> bool {
        self.0.iter().all(|&w| w == 0)
    }
    /// The indices of the set bits, ascending.
    pub fn ones(&self) -> Vec<usize> {
        let mut out = Vec::new();
        for (k, &w) in self.0.iter().enumerate() {
            for b in 0..64 {
                if w >> b & 1 == 1 {
                    out.push(k * 64 + b);
                }
            }
        }
        out
    }
}

/// A coordinate of the GF(2) vectors: −1, a prime, or an irreducible polynomial.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Factor {
    /// The sign.
    MinusOne,
    /// A prime number.
    Prime(Integer),
    /// An irreducible polynomial.
    Poly(Poly),
}

/// A row of the echelon form: a vector, the roots whose vectors sum to it, and its
/// pivot coordinate.
#[derive(Clone, Debug)]
struct Row {
    v: Bits,
    combo: Bits,
    pivot: usize,
}

/// The factors met so far and the reduced echelon form of the roots' vectors.
#[derive(Clone, Debug, Default)]
pub(crate) struct FactorBasis {
    /// The coordinates: every factor met so far.
    pub factors: Vec<Factor>,
    rows: Vec<Row>,
}

impl FactorBasis {
    /// The coordinate of `f`, added if new.
    pub fn index_of(&mut self, f: Factor) -> usize {
        if let Some(i) = self.factors.iter().position(|g| *g == f) {
            return i;
        }
        self.factors.push(f);
        self.factors.len() - 1
    }

    /// `(residual, combination)`: `t = residual + Σ_{roots in combination} vector`.
    pub fn reduce(&self, t: &Bits) -> (Bits, Bits) {
        let mut r = t.clone();
        let mut combo = Bits::default();
        for row in &self.rows {
            if r.get(row.pivot) {
                r.xor(&row.v);
                combo.xor(&row.combo);
            }
        }
        (r, combo)
    }

    /// Records root `root` with vector `v`; false if `v` depends on earlier roots.
    pub fn add(&mut self, v: &Bits, root: usize) -> bool {
        let (r, mut combo) = self.reduce(v);
        if r.is_zero() {
            return false;
        }
        combo.flip(root);
        let pivot = r.ones()[0];
        for row in &mut self.rows {
            if row.v.get(pivot) {
                row.v.xor(&r);
                row.combo.xor(&combo);
            }
        }
        self.rows.push(Row { v: r, combo, pivot });
        true
    }
}
