//! A sign that differs between domain points, kept so that a prover can split the
//! domain by it and prove each part on its own (`X > 0` and `X < 0`).
//!
//! Only a value of the claim's indeterminates can serve: the parts must be drawn anew,
//! so the sign must be computable at any point from the point's values alone.
//!
//! ```
//! use eulertop::algebra::{Ring, RingOptions};
//! let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
//! let x = ring.indeterminate_f64("x", &[1.0, -1.0]).unwrap();
//! assert!(x.sign().is_err()); // +1 at one point, −1 at the other
//! let split = ring.undecided_sign().unwrap();
//! assert_eq!(split.sign_at(&|n: &str| (n == "x").then_some(-0.5)), Some(-1));
//! ```

use super::error::{AlgResult, AlgebraError};
use super::flint::Poly;
use super::ring::{Ring, VarKind};
use super::sign_state::Folded;
pub use super::sign_state::SignSplit;
use super::sym::Sym;
use rug::ops::Pow;
use rug::{Complex, Float};

/// Precision of the evaluation of a split's sign at a point.
const PREC: u32 = 128;

impl SignSplit {
    /// The sign at a point given by the values of the indeterminates; `None` when a
    /// value is missing or the value is too close to 0 to tell.
    pub fn sign_at(&self, value: &dyn Fn(&str) -> Option<f64>) -> Option<i32> {
        let n = self.eval(&self.num, value)?;
        let d = self.eval(&self.den, value)?;
        let (sn, sd) = (n.0.cmp0()?, d.0.cmp0()?);
        // a value within rounding of 0 does not tell its side
        if n.0.clone().abs() <= n.1 || d.0.clone().abs() <= d.1 {
            return None;
        }
        let s = |o: std::cmp::Ordering| o as i32;
        Some(s(sn) * s(sd))
    }

    /// Whether the value is one of the claim's indeterminates, such as `M3` (a single
    /// variable over a constant), whose sign a proof can carry as a sign symbol instead
    /// of splitting the domain by it ([`crate::algebra::RingOptions::sign_folds`]).
    pub fn is_indeterminate(&self) -> bool {
        let mut linear = 0;
        let mut terms = 0;
        self.num.for_each_term(|_, e| {
            terms += 1;
            let ones: Vec<usize> = (0..e.len()).filter(|&i| e[i] != 0).collect();
            if let [i] = ones[..]
                && e[i] == 1
                && self.names.get(i).is_some_and(|n| !n.is_empty())
            {
                linear += 1;
            }
        });
        let mut constant = true;
        self.den
            .for_each_term(|_, e| constant &= e.iter().all(|&k| k == 0));
        terms == 1 && linear == 1 && constant
    }

    /// Is the part where the value has sign `sign` empty by the value's form: numerator
    /// and denominator each a sum of even powers of the claim's (real) indeterminates
    /// with coefficients of one sign, so the value is never of the other sign
    /// (`−x² − y² > 0` has no point).  `false` when that is not evident.
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
    /// let x = ring.indeterminate_f64("x", &[1.0, 0.5]).unwrap();
    /// let y = ring.indeterminate_f64("y", &[-1.0, 2.0]).unwrap();
    /// let v = x.clone() * x.clone() - y.clone() * y.clone();
    /// assert!(v.sign().is_err());
    /// let split = ring.undecided_sign().unwrap();
    /// assert!(!split.never(1) && !split.never(-1));
    /// // −x² − y² is never positive
    /// let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
    /// let x = ring.indeterminate_f64("x", &[1.0, 0.5]).unwrap();
    /// let y = ring.indeterminate_f64("y", &[-1.0, 2.0]).unwrap();
    /// let v = -(x.clone() * x) - y.clone() * y;
    /// assert!(v.sign().is_err()); // 0 where x = y = 0
    /// let split = ring.undecided_sign().unwrap();
    /// assert!(split.never(1) && !split.never(-1));
    /// ```
    pub fn never(&self, sign: i32) -> bool {
        match (self.even_sign(&self.num), self.even_sign(&self.den)) {
            (Some(n), Some(d)) => n * d == -sign,
            _ => false,
        }
    }

    /// The common sign of the coefficients of `p` when every term is an even power
    /// product of named indeterminates (so `p` has that sign or is 0).
    fn even_sign(&self, p: &Poly) -> Option<i32> {
        let mut sign = 0;
        let mut ok = true;
        p.for_each_term(|c, e| {
            let named = (e.iter().enumerate()).all(|(i, &k)| {
                k == 0 || (k % 2 == 0 && self.names.get(i).is_some_and(|n| !n.is_empty()))
            });
            let s = c.cmp0() as i32;
            ok &= named && s != 0 && (sign == 0 || s == sign);
            sign = s;
        });
        (ok && sign != 0).then_some(sign)
    }

    /// Whether `other` is the same value (as the prover renders it).
    pub fn same(&self, other: &SignSplit) -> bool {
        self.text == other.text
    }

    /// The value in `ring`, whose indeterminates of the same names stand for it (`None`
    /// where one of them is missing there).
    pub(crate) fn in_ring(&self, ring: &Ring) -> Option<Sym> {
        let vars: Vec<Option<Sym>> = {
            let st = ring.state();
            (self.names.iter())
                .map(|n| {
                    (!n.is_empty())
                        .then(|| {
                            (st.vars.iter()).position(|v| {
                                v.name == *n && matches!(v.kind, VarKind::Indeterminate)
                            })
                        })
                        .flatten()
                })
                .collect::<Vec<Option<usize>>>()
        }
        .into_iter()
        .map(|j| j.map(|j| ring.var_sym(j)))
        .collect();
        let poly = |p: &Poly| -> Option<Sym> {
            let mut terms: Vec<(rug::Integer, Vec<u64>)> = Vec::new();
            p.for_each_term(|c, e| terms.push((c.clone(), e.to_vec())));
            let mut acc = ring.integer(0);
            for (c, e) in terms {
                let mut t = ring.rational(&rug::Rational::from(c));
                for (i, &k) in e.iter().enumerate().filter(|(_, k)| **k > 0) {
                    let v = vars.get(i).cloned().flatten()?;
                    t = t.try_mul(&v.try_powi(i32::try_from(k).ok()?).ok()?).ok()?;
                }
                acc = acc.try_add(&t).ok()?;
            }
            Some(acc)
        };
        poly(&self.num)?.try_div(&poly(&self.den)?).ok()
    }

    /// The value of a polynomial and a bound on its rounding error.
    fn eval(&self, p: &Poly, value: &dyn Fn(&str) -> Option<f64>) -> Option<(Float, Float)> {
        let mut sum = Float::new(PREC);
        let mut size = Float::new(PREC);
        let mut missing = false;
        p.for_each_term(|c, e| {
            let mut t = Float::with_val(PREC, c);
            for (i, &k) in e.iter().enumerate() {
                if k > 0 {
                    match self
                        .names
                        .get(i)
                        .filter(|n| !n.is_empty())
                        .and_then(|n| value(n))
                    {
                        Some(x) => t *= Float::with_val(PREC, x).pow(k as u32),
                        None => missing = true,
                    }
                }
            }
            size += t.clone().abs();
            sum += t;
        });
        if missing {
            return None;
        }
        Some((sum, size >> (PREC as i32 - 16)))
    }
}

impl Sym {
    /// The split of the domain by this value's sign, when the value depends on the
    /// claim's indeterminates only.
    pub(crate) fn split(&self) -> Option<SignSplit> {
        let inner = &self.ring.inner;
        let st = self.ring.state();
        let mut names = vec![String::new(); inner.ctx.nvars()];
        for (j, v) in st.vars.iter().enumerate() {
            if matches!(v.kind, VarKind::Indeterminate) {
                names[inner.kvar(j)] = v.name.clone();
            }
        }
        drop(st);
        let known = |p: &Poly| p.used_vars().iter().all(|&i| !names[i].is_empty());
        (known(&self.val.num) && known(&self.val.den)).then(|| SignSplit {
            what: self.render_short(160),
            text: self.render(),
            num: self.val.num.clone(),
            den: self.val.den.clone(),
            names,
        })
    }
}

impl Ring {
    /// The first sign that differed between domain points in this ring, when it can
    /// split the domain (see [`SignSplit`]).
    pub fn undecided_sign(&self) -> Option<SignSplit> {
        self.state().signs.undecided.clone()
    }

    /// Remembers the first undecided sign of the ring that can split the domain.
    pub(crate) fn note_undecided(&self, x: &Sym) {
        if self.state().signs.undecided.is_none()
            && let Some(split) = x.split().or_else(|| x.root_free_split())
        {
            self.state().signs.undecided = Some(split);
        }
    }
}

impl Sym {
    /// `±σ` for a value `±x` whose sign the ring folds ([`RingOptions::sign_folds`]):
    /// `σ = sign(x)` is a sign symbol (`σ² = 1`) with the signs of `x` at the domain
    /// points as its values, made at the first call, and `σ·x > 0` holds by its
    /// definition.  Arithmetic modulo `σ² = 1` holds for both signs, so this holds
    /// also where the points of a part happen to share one sign.  `None` for a value
    /// that is not folded.
    ///
    /// [`RingOptions::sign_folds`]: super::RingOptions::sign_folds
    pub(crate) fn folded_sign(&self) -> AlgResult<Option<Sym>> {
        let folds = &self.ring.options().sign_folds;
        if folds.is_empty() {
            return Ok(None);
        }
        let (text, neg) = (self.render(), self.negate().render());
        let Some((fold, s)) = folds.iter().find_map(|f| {
            (f.text == text)
                .then_some((f, 1))
                .or_else(|| (f.text == neg).then_some((f, -1)))
        }) else {
            return Ok(None);
        };
        let known = self
            .ring
            .state()
            .signs
            .folded
            .iter()
            .find(|f| f.value == fold.text)
            .cloned();
        let sigma = match known {
            Some(f) => self.ring.root_sym(f.root),
            None => {
                let Some(own) = self.point_signs() else {
                    return Ok(None);
                };
                let name = format!("sgn{}", fold.what);
                let prec = self.ring.precision();
                let values: Vec<Complex> = own
                    .iter()
                    .map(|&v| Complex::with_val(prec, v * s))
                    .collect();
                let sigma = self.ring.sign_symbol(&name, &values)?;
                let x = if s > 0 { self.clone() } else { self.negate() };
                let positive = sigma.try_mul(&x)?.render();
                let root = (self.ring.state().roots.iter())
                    .position(|r| r.name == name)
                    .ok_or_else(|| {
                        AlgebraError::Internal("a sign symbol that is not a root".into())
                    })?;
                let var = x.single_indeterminate();
                self.ring.state().signs.folded.push(Folded {
                    value: fold.text.clone(),
                    name: name.clone(),
                    root,
                    positive,
                    var,
                    x: (*x.val).clone(),
                });
                self.ring.note(format!(
                    "{name} = sign({}): a sign symbol, so that one normal form covers both signs of {}",
                    fold.what, fold.what
                ));
                sigma
            }
        };
        Ok(Some(if s > 0 { sigma } else { sigma.negate() }))
    }
}
