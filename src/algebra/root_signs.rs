//! Signs of values in a square root, decided from the signs of their root-free parts.
//!
//! A value `(a + b·r)/d`, with `r` the positive root of a radicand `R` proved positive
//! (its most significant root) and `a`, `b`, `d` free of `r`, has the sign
//! * of `a` and `b` where these agree (or of `b` where `a = 0`),
//! * of `a` times that of `q = a² − b²·R` where they differ: `(a + b·r)(a − b·r) = q`,
//!   and `a − b·r` has the sign of `a` when `b` has the other one,
//!
//! divided by the sign of `d`.  Module [`super::decide`] proves such signs with the
//! parametrization of the domain alone (its rule 2); here each part is decided as any
//! sign is ([`Sym::decision`]), so that the condition of a part of the domain can
//! decide it too.  And where a part's sign is undecided, that part (free of `r`, so
//! computable at any point from the claim's indeterminates once its own roots are
//! gone) is the sign to split the domain by ([`Sym::root_free_split`]).
//!
//! ```
//! use eulertop::algebra::{Ring, RingOptions};
//! let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
//! let x = ring.indeterminate_f64("x", &[1.0, 2.0]).unwrap();
//! let two = ring.integer(2);
//! // x − √2 is positive at both points, but its sign is not proved on the domain
//! assert!((x - two.sqrt().unwrap()).sign().is_err());
//! ```

use super::decide::Decision;
use super::flint::Poly;
use super::split::SignSplit;
use super::sym::Sym;

/// How deep the parts of parts are examined (one square root per level).
const MAX_DEPTH: usize = 4;

/// The most terms (numerator and denominator) of a value whose root-free parts may split
/// the domain.
const MAX_SPLIT_TERMS: usize = 8;

/// The parts `a`, `b`, `q = a² − b²R` of a value's numerator in its most significant
/// positive root, with the radicand `R`; `None` where the numerator has no root, or
/// its most significant one is not a positive principal root.
struct Parts {
    a: Sym,
    b: Sym,
    q: Sym,
    radicand: Sym,
}

impl Sym {
    fn root_parts(&self) -> Option<Parts> {
        let ring = &self.ring;
        let inner = &ring.inner;
        let p = &self.val.num;
        let rv = (p.used_vars().into_iter()).find(|&v| inner.root_of_var(v).is_some())?;
        let i = inner.root_of_var(rv)?;
        let radicand = {
            let st = ring.state();
            let r = st.roots.get(i)?;
            if !r.is_positive() || r.radicand.is_one() {
                return None;
            }
            r.radicand.clone()
        };
        let a = p.coefficient_in(rv, 0);
        let b = p.coefficient_in(rv, 1);
        let q = inner.reduce(a.mul(&a).sub(&b.mul(&b).mul(&radicand)));
        let sym = |x: Poly| ring.quotient_of_polys(x, Poly::from_i64(p.ctx(), 1)).ok();
        Some(Parts {
            a: sym(a)?,
            b: sym(b)?,
            q: sym(q)?,
            radicand: sym(radicand)?,
        })
    }

    /// The denominator as a value, where it is free of roots.
    fn root_free_den(&self) -> Option<Sym> {
        let inner = &self.ring.inner;
        let d = &self.val.den;
        if (d.used_vars().into_iter()).any(|v| inner.root_of_var(v).is_some()) {
            return None;
        }
        (self.ring)
            .quotient_of_polys(d.clone(), Poly::from_i64(d.ctx(), 1))
            .ok()
    }

    /// The sign of a value in a square root from the decided signs of its parts (see
    /// the module); `None` where a part is undecided.
    ///
    /// Tried only where the proof has conditions beyond the domain (a part's, or stated
    /// hypotheses): with the domain alone, rule 2 of [`super::decide`] has tried it.
    pub(crate) fn root_decision(&self) -> Option<Decision> {
        let conditions = !self.ring.options().hypotheses.is_empty()
            || !self.ring.state().signs.stated.is_empty();
        conditions.then(|| self.root_decision_at(0)).flatten()
    }

    /// [`Sym::root_decision`] where every part is, up to its roots, the condition of
    /// the part of the domain the proof is on or a rational number: a cheap test, made
    /// before any proof (see [`Sym::part_condition_sign`]).
    pub(crate) fn quick_root_decision(&self) -> Option<Decision> {
        if self.ring.options().hypotheses.is_empty() {
            return None;
        }
        self.root_decision_in(0, true)
    }

    fn root_decision_at(&self, depth: usize) -> Option<Decision> {
        self.root_decision_in(depth, false)
    }

    fn root_decision_in(&self, depth: usize, quick: bool) -> Option<Decision> {
        if depth >= MAX_DEPTH {
            return None;
        }
        let den = self.root_free_den()?;
        let parts = self.root_parts()?;
        let full = |x: &Sym| match x.decision() {
            Decision::Unknown => None,
            d => Some(d),
        };
        let part = |x: &Sym| -> Option<Decision> {
            if let Some(r) = x.as_rational() {
                return Some(Decision::Proved(r.cmp0() as i32));
            }
            if let Some((s, source)) = x.part_condition_sign() {
                return Some(Decision::Hypothesis(s, source));
            }
            x.root_decision_in(depth + 1, true)
        };
        let decide = |x: &Sym| -> Option<Decision> {
            if quick {
                return part(x);
            }
            let d = match x.hypothesis_sign() {
                Some((s, source)) => Decision::Hypothesis(s, source),
                None => x.decision(),
            };
            match d {
                Decision::Unknown => x.root_decision_at(depth + 1),
                d => Some(d),
            }
        };
        if full(&parts.radicand)?.sign()? != 1 {
            return None;
        }
        let mut used = vec![full(&den)?];
        let sd = used[0].sign().filter(|&s| s != 0)?;
        let b = decide(&parts.b)?;
        let sb = b.sign()?;
        used.push(b);
        let sa = if parts.a.is_exact_zero() {
            0
        } else {
            let a = decide(&parts.a)?;
            let sa = a.sign()?;
            used.push(a);
            sa
        };
        let s = if sa == 0 || sa == sb {
            sb
        } else {
            let q = decide(&parts.q)?;
            let sq = q.sign()?;
            used.push(q);
            sa * sq
        };
        combine(s * sd, &used, self)
    }

    /// Records, for a certificate, the sign `sign` of this value decided from its parts
    /// (a `sign … > 0 parts` line, decided again by a recheck), once per value.
    fn record_root_sign(&self, sign: i32) {
        let mut st = self.ring.state();
        let known = (st.signs.root_signs.iter())
            .any(|e| e.sign == sign && e.value.num == self.val.num && e.value.den == self.val.den);
        if !known {
            st.signs
                .root_signs
                .push(super::sign_state::RootSignEvidence {
                    node: self.node.clone(),
                    value: (*self.val).clone(),
                    sign,
                });
        }
    }

    /// Is `source` the label of the condition of a part of the domain the proof is on
    /// (as [`Sym::part_condition_sign`] names it), not a stated hypothesis?
    fn is_part_condition(&self, source: &str) -> bool {
        (self.ring.options().hypotheses.iter())
            .any(|(h, s)| source == format!("{} {} 0", h.what, if *s > 0 { ">" } else { "<" }))
    }

    /// A root-free part of this value whose sign is undecided and can split the domain
    /// (module [`super::split`]): the first of `a`, `b`, `q` (see the module), or of
    /// their own parts, that is undecided.
    ///
    /// Only for a value of at most [`MAX_SPLIT_TERMS`] terms: the parts of a larger one
    /// are large polynomials, whose parts of the domain cost more proof than they save.
    pub(crate) fn root_free_split(&self) -> Option<SignSplit> {
        if self.val.num.len() + self.val.den.len() > MAX_SPLIT_TERMS {
            return None;
        }
        self.root_free_split_at(0)
    }

    fn root_free_split_at(&self, depth: usize) -> Option<SignSplit> {
        if depth >= MAX_DEPTH {
            return None;
        }
        let parts = self.root_parts()?;
        [parts.a, parts.b, parts.q]
            .into_iter()
            .filter(|x| !x.is_exact_zero() && x.decided_sign().is_none())
            .find_map(|x| x.split().or_else(|| x.root_free_split_at(depth + 1)))
    }
}

/// The decision of a sign made from `used`: by a hypothesis where one of them is (the
/// first one's source), else by a definition.  `None` where every part is proved: rule 2
/// of [`super::decide`] has decided such a value already, or could not, and the proof
/// goes on as it would without this module.  A certificate records the sign (a recheck
/// decides it again from the parts, a part by a proved sign, the condition of the part
/// of the domain or a sign symbol's definition); a part decided by a stated hypothesis
/// it does not record.
fn combine(sign: i32, used: &[Decision], value: &Sym) -> Option<Decision> {
    if used.iter().all(|d| matches!(d, Decision::Proved(_))) {
        return None;
    }
    let stated = (used.iter())
        .any(|d| matches!(d, Decision::Hypothesis(_, source) if !value.is_part_condition(source)));
    if stated {
        value.ring.mark_uncertified(
            "a sign in a square root decided from the signs of its parts, one by a stated hypothesis",
        );
    } else if value.ring.certifying() {
        value.record_root_sign(sign);
    }
    for d in used {
        if let Decision::Hypothesis(_, source) = d {
            return Some(Decision::Hypothesis(sign, source.clone()));
        }
    }
    Some(Decision::Definition(sign))
}
