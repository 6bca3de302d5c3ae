//! The elliptic data of one modulus, as the ring stores it: the base arguments with
//! their `sn`, `cn`, `dn`, the directions that arguments are split into, and the
//! triples and half-period values computed so far.  Module [`super::elliptic`] fills
//! the tables in; module [`super::addition`] computes with them.

use super::val::Val;
use rug::{Integer, Rational};
use std::collections::HashMap;

/// The terms of a polynomial, as plain data (portable between rings built the same way).
pub type Terms = Vec<(Integer, Vec<u64>)>;

/// A direction: a monomial (exponent vector) over a primitive denominator.
pub type DirKey = (Vec<u64>, Terms);

/// Base arguments to start from, for a modulus (given by the terms of its normal form).
#[derive(Clone, Debug, PartialEq)]
pub struct BaseHint {
    /// Numerator and denominator terms of the modulus.
    pub modulus: (Terms, Terms),
    /// Each base as rational coefficients over directions.
    pub bases: Vec<Vec<(DirKey, Rational)>>,
}

/// A base argument of a table, with its `sn`, `cn`, `dn`.
#[derive(Clone, Debug)]
pub(crate) struct Base {
    /// Its coefficients over the table's directions.
    pub vec: Vec<Rational>,
    /// The argument itself.
    pub arg: Val,
    /// `sn` of the base: its symbol, or the prescribed value.
    pub s: Val,
    /// The name of `sn` of the base (its symbol, or `sn(v)` when prescribed).
    pub s_name: String,
    /// `cn` of the base.
    pub c: Val,
    /// `dn` of the base.
    pub d: Val,
    /// The field variable of `E(am b, k) − k'² b`, once a derivative in the modulus
    /// made it.
    pub z_var: Option<usize>,
    /// Whether the argument is real and the modulus in `(0, 1)`, by construction
    /// (module `elliptic_facts`).
    pub real: bool,
}

impl Base {
    /// Are sn, cn, dn of this base prescribed values (not symbols of its own)?
    pub(crate) fn is_prescribed(&self) -> bool {
        self.s_name.starts_with("sn(")
    }
}

/// The elliptic data of one modulus.
#[derive(Clone, Debug)]
pub(crate) struct Table {
    /// The modulus.
    pub k: Val,
    /// `k²`.
    pub k2: Val,
    /// `k' = √(1 − k²)`, once needed.
    pub kp: Option<Val>,
    /// The field variable of `K(k)`, once needed.
    pub k_var: Option<usize>,
    /// The field variable of `K'(k)`, once needed.
    pub kp_var: Option<usize>,
    /// The directions arguments are split into, with their values.
    pub dirs: Vec<(DirKey, Val)>,
    /// The base arguments.
    pub bases: Vec<Base>,
    /// `(sn, cn, dn)` of multiples of one base, by their coefficient vectors.
    pub triples: HashMap<Vec<i64>, [Val; 3]>,
    /// `(sn, cn, dn)(K/2)`, once needed.
    pub half_k: Option<[Val; 3]>,
    /// `(sn, cn, dn)(iK'/2)`, once needed.
    pub half_kp: Option<[Val; 3]>,
    /// `(sn, cn, dn)(K/3)`, once needed (module `thirds`).
    pub third_k: Option<[Val; 3]>,
    /// Every argument seen, over the directions (for a refined basis).
    pub seen: Vec<Vec<Rational>>,
    /// Hinted bases not yet made (their symbols do not exist yet).
    pub pending: Vec<Vec<(DirKey, Rational)>>,
}

impl Table {
    /// A table of modulus `k` (with `k2 = k²`) and no bases yet.
    pub fn new(k: Val, k2: Val) -> Table {
        Table {
            k,
            k2,
            kp: None,
            k_var: None,
            kp_var: None,
            dirs: Vec::new(),
            bases: Vec::new(),
            triples: HashMap::new(),
            half_k: None,
            half_kp: None,
            third_k: None,
            seen: Vec::new(),
            pending: Vec::new(),
        }
    }

    /// The index of direction `key`, added with value `val()` if new.
    pub fn dir_index(&mut self, key: DirKey, val: impl FnOnce() -> Val) -> usize {
        if let Some(i) = self.dirs.iter().position(|(k, _)| *k == key) {
            return i;
        }
        self.dirs.push((key, val()));
        self.dirs.len() - 1
    }
}
