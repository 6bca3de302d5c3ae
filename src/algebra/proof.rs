//! The zero test and the proof record.
//!
//! `lhs = rhs` is *proved* when the normal form of `lhs − rhs` is 0: then the
//! numerator lies in the ideal of the root relations, so it vanishes wherever the
//! symbols take values satisfying the relations — in particular at every point of the
//! domain where the recorded assumptions (branches, signs, comparisons) hold and no
//! denominator vanishes.  A non-zero normal form proves nothing (the tower may not be a
//! field, a named quantity may need its definition); the reason says which case it is.

use super::budget::BUDGET_MESSAGE;
use super::certificate::Refutation;
use super::elliptic::BaseHint;
use super::error::{AlgResult, AlgebraError};
use super::ring::{Assumption, MAX_TERMS, Ring, RingOptions, VarKind};
use super::sym::Sym;
use std::time::Instant;

/// The outcome of a zero test.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// The normal form of `lhs − rhs` is 0.
    Proved,
    /// Not proved, with the reason.
    NotProved(String),
}

/// A proof attempt: outcome and the facts it rests on.
#[derive(Clone, Debug)]
pub struct Proof {
    /// Proved or not (with the reason).
    pub outcome: Outcome,
    /// The symbols: name and what each stands for.
    pub symbols: Vec<(String, String)>,
    /// The relations `r² = a` of the root symbols.
    pub relations: Vec<String>,
    /// The decisions taken from the domain (branches, signs, comparisons).
    pub assumptions: Vec<Assumption>,
    /// Signs proved with the parametrization of the domain (not assumptions).
    pub proved_signs: Vec<String>,
    /// That parametrization, for the reader, when a sign was proved with it.
    pub parametrization: Option<String>,
    /// Addition-theorem instances and other steps, for the reader.
    pub notes: Vec<String>,
    /// Terms of the numerators of `lhs` and `rhs` (the size of the identity).
    pub terms: usize,
    /// Wall time in milliseconds (all attempts, including evaluation).
    pub ms: f64,
    /// The number of evaluations (restarts for refined bases or expanded names).
    pub attempts: usize,
    /// Whether named quantities had to be replaced by their definitions.
    pub expanded_named: bool,
    /// The steps the certificate format does not record (a proof with one has no
    /// certificate).
    pub uncertified: Vec<String>,
    /// The certificate, when the ring recorded derivations.
    pub certificate: Option<String>,
    /// The first sign that differed between domain points, by which the domain can be
    /// split (see [`super::split`]).
    pub split: Option<super::split::SignSplit>,
    /// Where the normal form of `lhs − rhs` is certified nonzero: the domain point and
    /// the enclosure (module [`super::witness`]).
    pub witness: Option<String>,
    /// The elliptic base arguments of the last attempt, as hints for a related proof
    /// (another case of the same claim).
    pub base_hints: Vec<BaseHint>,
}

impl Proof {
    /// Did the zero test succeed?
    pub fn is_proved(&self) -> bool {
        self.outcome == Outcome::Proved
    }

    fn failed(reason: String, ms: f64, attempts: usize) -> Proof {
        Proof {
            outcome: Outcome::NotProved(reason),
            symbols: Vec::new(),
            relations: Vec::new(),
            assumptions: Vec::new(),
            proved_signs: Vec::new(),
            parametrization: None,
            notes: Vec::new(),
            terms: 0,
            ms,
            attempts,
            expanded_named: false,
            uncertified: Vec::new(),
            certificate: None,
            base_hints: Vec::new(),
            split: None,
            witness: None,
        }
    }
}

impl Ring {
    /// The zero test of `lhs − rhs` on this ring (one evaluation; `ms` is the time of
    /// the test itself).
    pub fn prove(&self, lhs: &Sym, rhs: &Sym) -> Proof {
        self.prove_all(&[(lhs.clone(), rhs.clone())])
    }

    /// The zero test of every component `lhsᵢ − rhsᵢ` (proved when all are 0).
    pub fn prove_all(&self, pairs: &[(Sym, Sym)]) -> Proof {
        let t0 = Instant::now();
        let mut outcome = Outcome::Proved;
        let mut witness = None;
        let mut refute = None;
        for (i, (l, r)) in pairs.iter().enumerate() {
            let (o, w) = self
                .zero_test(l, r)
                .unwrap_or_else(|e| (Outcome::NotProved(e.to_string()), None));
            witness = w.map(|(point, w)| {
                refute = Some(Refutation {
                    component: i,
                    point,
                });
                match pairs.len() {
                    1 => w,
                    _ => format!("component {}: {w}", i + 1),
                }
            });
            if let Outcome::NotProved(why) = o {
                let which = if pairs.len() > 1 {
                    format!("component {}: ", i + 1)
                } else {
                    String::new()
                };
                outcome = Outcome::NotProved(format!("{which}{why}"));
                break;
            }
        }
        if pairs.is_empty() {
            outcome = Outcome::NotProved("nothing to prove".into());
        }
        let certificate = match outcome {
            Outcome::Proved => self.certificate(pairs, "lhs = rhs", None),
            Outcome::NotProved(_) => {
                refute.and_then(|r| self.certificate(pairs, "lhs = rhs", Some(r)))
            }
        };
        let uncertified = self.state().uncertified.clone();
        Proof {
            outcome,
            symbols: self.symbols(),
            relations: self.relations(),
            assumptions: self.assumptions(),
            proved_signs: self.proved_signs(),
            parametrization: self.parametrization(),
            notes: self.notes(),
            terms: pairs.iter().map(|(l, r)| l.terms() + r.terms()).sum(),
            ms: t0.elapsed().as_secs_f64() * 1e3,
            attempts: 1,
            expanded_named: self.options().expand_named,
            uncertified,
            certificate,
            base_hints: self.options().base_hints.clone(),
            split: self.undecided_sign(),
            witness,
        }
    }

    /// The zero test of `lhs − rhs`, and where it is not 0, a point at which it is
    /// certified nonzero (module [`super::witness`]), if one is found.
    fn zero_test(&self, lhs: &Sym, rhs: &Sym) -> AlgResult<(Outcome, Option<(usize, String)>)> {
        if let Some(e) = self.error() {
            return Err(e);
        }
        if self.state().rebase_wanted {
            return Ok((
                Outcome::NotProved(
                    "provisional elliptic base arguments: evaluate again with refined bases (prove_identity does)".into(),
                ),
                None,
            ));
        }
        let d = lhs.try_sub(rhs)?;
        let prec = self.precision();
        if d.val.sh.has_non_finite() {
            return Err(AlgebraError::Internal(
                "a value is not finite at a domain point".into(),
            ));
        }
        if d.is_exact_zero() {
            if !d.val.sh.all_small(prec) {
                return Err(AlgebraError::Internal(
                    "the normal form is 0 but the numeric values differ (a bug in the prover)"
                        .into(),
                ));
            }
            return Ok((Outcome::Proved, None));
        }
        if self.algebraic_zero(&d)? {
            return Ok((Outcome::Proved, None));
        }
        let n = d.terms();
        // the carried error scale may be far too pessimistic (a long sum): a value is
        // called 0 at a point only if its normal form, evaluated afresh, is 0 there too
        let fresh = self.reevaluated(&d.val);
        let differs = |p: usize| !d.val.sh.is_small(p, prec) || !fresh.is_small(p, prec);
        let point = (0..self.points()).find(|&p| differs(p));
        let witness = point.and_then(|p| {
            let w = self.witness(&d, p)?;
            Some((p, format!("at domain point {}: {w}", p + 1)))
        });
        let reason = match point {
            Some(p) => format!(
                "the normal form of lhs - rhs has {n} terms, and the two sides differ at domain point {}",
                p + 1
            ),
            None => {
                let why = if self.has_named() {
                    "named quantities may need their definitions"
                } else {
                    "the tower may have zero divisors, or the identity needs a relation the prover does not know"
                };
                format!(
                    "the normal form of lhs - rhs has {n} terms, and is 0 within the rounding error of its terms at every domain point ({why})"
                )
            }
        };
        Ok((Outcome::NotProved(reason), witness))
    }

    /// Whether the non-zero normal form `d` vanishes modulo the relations of the
    /// algebraic symbols (module `algebraic`), its values being 0 as well.
    fn algebraic_zero(&self, d: &Sym) -> AlgResult<bool> {
        if self.state().algebraic.is_empty() || !self.inner.algebraic_rem(&d.val.num)?.is_zero() {
            return Ok(false);
        }
        if !d.val.sh.all_small(self.precision()) {
            return Err(AlgebraError::Internal(
                "lhs - rhs is 0 modulo an algebraic relation but the numeric values differ (a bug in the prover)".into(),
            ));
        }
        self.note("lhs - rhs is 0 modulo the defining polynomials of the algebraic symbols".into());
        Ok(true)
    }

    /// Does the ring hold a named quantity as a free symbol ([`Ring::named`])?
    fn has_named(&self) -> bool {
        (self.state().vars.iter()).any(|v| matches!(v.kind, VarKind::Named(_)))
    }
}

/// Proves `lhs = rhs` built by `build` on a fresh ring, restarting when the elliptic
/// base arguments must be refined or the ring's capacity runs out, and once more with
/// named quantities replaced by their definitions if the normal form is not 0 or the
/// attempt with them stopped with an error.  `ms` covers every evaluation.
///
/// ```
/// use eulertop::algebra::{prove_identity, RingOptions};
/// let proof = prove_identity(RingOptions::default(), "sn(2u) by doubling", |r| {
///     let u = r.indeterminate_f64("u", &[0.3, 0.6, 1.1])?;
///     let k = r.indeterminate_f64("k", &[0.5, 0.7, 0.2])?;
///     let (s, c, d) = u.sncndn(&k)?;
///     let two = r.integer(2);
///     let lhs = (&two * &u).sn(&k)?;
///     let den = r.integer(1) - &(&k * &k) * &s.try_powi(4)?;
///     Ok((lhs, &(&(&two * &s) * &c) * &d / den))
/// });
/// assert!(proof.is_proved(), "{:?}", proof.outcome);
/// ```
pub fn prove_identity<F>(opts: RingOptions, title: &str, build: F) -> Proof
where
    F: Fn(&Ring) -> AlgResult<(Sym, Sym)>,
{
    prove_components(opts, title, |r| Ok(vec![build(r)?]))
}

/// The start of the message of [`AlgebraError::Capacity`], as it reads when the error
/// reached the build only as text.
const CAPACITY_MESSAGE: &str = "too many symbols";

/// The reason, if the attempt ran out of its budget (module [`super::budget`]): the
/// error typed or as text, or the deadline passed.
fn over_budget<T>(ring: &Ring, built: &AlgResult<T>, opts: &RingOptions) -> Option<String> {
    let text = |e: &AlgebraError| match e {
        AlgebraError::Budget(why) => Some(why.clone()),
        e => {
            let s = e.to_string();
            let at = s.find(BUDGET_MESSAGE)?;
            let rest = &s[at + BUDGET_MESSAGE.len()..];
            Some(
                rest.trim_start_matches(" (")
                    .trim_end_matches(')')
                    .to_string(),
            )
        }
    };
    let typed = match built {
        Err(e) => text(e),
        Ok(_) => None,
    };
    typed
        .or_else(|| ring.error().as_ref().and_then(text))
        .or_else(|| opts.budget.expired().then(|| opts.budget.time_reason()))
}

/// Did the build run out of symbols or roots?  A capacity error that reached the build
/// only as text counts when no rebase is wanted (a rebase comes first: it may need
/// fewer symbols).
fn needs_room<T>(ring: &Ring, built: &AlgResult<T>, wanted: bool) -> bool {
    let typed = matches!(built, Err(AlgebraError::Capacity(_)))
        || matches!(ring.error(), Some(AlgebraError::Capacity(_)));
    let as_text = !wanted
        && ring.state().capacity_hit
        && matches!(built, Err(e) if e.to_string().contains(CAPACITY_MESSAGE));
    typed || as_text
}

/// The size of the value that exceeded the bound, if the attempt stopped there.
fn overflow<T>(ring: &Ring, built: &AlgResult<T>) -> Option<usize> {
    match (built, ring.error()) {
        (Err(AlgebraError::TooLarge(n, _)), _) => Some(*n),
        (_, Some(AlgebraError::TooLarge(n, _))) => Some(n),
        _ => None,
    }
}

/// After an overflow of `size` terms: whether to try again, with `opts` changed.  The
/// bases chosen as the arguments came may write a later argument with large multiples,
/// so a basis of every argument seen comes first (at most three rebases); then a value
/// just beyond the bound gets one more attempt with twice the room (values that
/// explode, such as written-out iterations, do not).
fn more_room(ring: &Ring, opts: &mut RingOptions, rebases: &mut usize, size: usize) -> bool {
    let hints = ring.rebase_hints();
    let just_beyond = opts.max_terms == MAX_TERMS && size < 2 * MAX_TERMS;
    if *rebases < 3 && hints != opts.base_hints {
        *rebases += 1;
        opts.base_hints = hints;
        if just_beyond {
            // the next attempt may need the room too: one attempt less when it does
            opts.max_terms = 2 * MAX_TERMS;
        }
        return true;
    }
    if just_beyond {
        opts.max_terms = 2 * MAX_TERMS;
        return true;
    }
    false
}

/// [`prove_identity`] for several components (a vector or matrix identity): proved
/// when every component's normal form is 0.
pub fn prove_components<F>(opts: RingOptions, title: &str, build: F) -> Proof
where
    F: Fn(&Ring) -> AlgResult<Vec<(Sym, Sym)>>,
{
    let t0 = Instant::now();
    let mut opts = opts;
    // one deadline for every restart of the attempt
    opts.budget = opts.budget.started();
    let (mut attempts, mut rebases, mut grows) = (0, 0, 0);
    let ms = |t0: &Instant| t0.elapsed().as_secs_f64() * 1e3;
    loop {
        attempts += 1;
        let ring = Ring::new(opts.clone());
        let built = build(&ring);
        if let Some(why) = over_budget(&ring, &built, &opts) {
            return Proof::failed(format!("{BUDGET_MESSAGE} ({why})"), ms(&t0), attempts);
        }
        let wanted = ring.state().rebase_wanted;
        let capacity = needs_room(&ring, &built, wanted);
        if capacity && grows < 3 {
            grows += 1;
            opts.max_roots *= 2;
            opts.max_vars *= 2;
            if wanted {
                opts.base_hints = ring.rebase_hints();
            }
            continue;
        }
        if wanted {
            if rebases < 3 {
                rebases += 1;
                let hints: Vec<BaseHint> = ring.rebase_hints();
                opts.base_hints = hints;
                continue;
            }
            return Proof::failed(
                "the elliptic base arguments could not be settled".into(),
                ms(&t0),
                attempts,
            );
        }
        if let Some(size) = overflow(&ring, &built)
            && more_room(&ring, &mut opts, &mut rebases, size)
        {
            continue;
        }
        let pairs = match built {
            Ok(p) => p,
            // a free symbol may have stopped the attempt (a sign that only its
            // definition proves): the definitions are tried as after a nonzero form
            Err(_) if !opts.expand_named && ring.has_named() => {
                opts.expand_named = true;
                continue;
            }
            Err(e) => {
                let mut p = Proof::failed(e.to_string(), ms(&t0), attempts);
                p.split = ring.undecided_sign();
                return p;
            }
        };
        let mut proof = ring.prove_all(&pairs);
        if !proof.is_proved()
            && let Some(why) = over_budget(&ring, &Ok(()), &opts)
        {
            return Proof::failed(format!("{BUDGET_MESSAGE} ({why})"), ms(&t0), attempts);
        }
        if !proof.is_proved() && ring.has_named() && !opts.expand_named {
            opts.expand_named = true;
            continue;
        }
        proof.ms = ms(&t0);
        proof.attempts = attempts;
        return titled(proof, title, opts.base_hints);
    }
}

/// The finished proof: its certificate titled with the claim, and the bases it ended on.
fn titled(mut proof: Proof, title: &str, base_hints: Vec<BaseHint>) -> Proof {
    if let Some(c) = proof.certificate.as_mut() {
        *c = c.replacen(
            "# claim: lhs = rhs",
            &format!("# claim: {}", title.replace('\n', " ")),
            1,
        );
    }
    proof.base_hints = base_hints;
    proof
}
