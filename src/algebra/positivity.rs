//! Signs of the prover's values proved on the domain: a value's numerator and
//! denominator are substituted with the ring's parametrization of the domain (module
//! [`super::parametrization`], with its alternative, the box of the sampled intervals),
//! the roots proved positive and the `sn²` of real bases as further parameters, and the
//! sign is proved when the test of that module proves it.  A sign it does not prove is
//! not proved (module `decide` tries the other rules).
//!
//! ```
//! use eulertop::algebra::positivity::Parametrization;
//! let mut par = Parametrization::new();
//! let t = par.positive("t").unwrap();
//! par.bind("x", t, "x = t".into());
//! assert!(!par.is_empty());
//! ```

use super::flint::Poly;
use super::parametrization::{Image, MAX_WIDENED_TERMS};
pub use super::parametrization::{ParamKind, ParamRat, Parametrization};
use super::ring::{Ring, VarKind};
use super::sym::Sym;
use rug::Float;
use std::sync::Arc;

impl Sym {
    /// The sign of a real value proved with the ring's parametrization of the domain
    /// (see the module), with a note that says so; `None` when the test does not prove
    /// it.  A certificate records the sign (of the value's derivation, or of the value
    /// written out where it has none), which a recheck proves again.
    pub(crate) fn proved_sign(&self) -> Option<i32> {
        // without a parametrization of the domain, the signs of the roots' structure
        // (positive roots of positive constants) can still be proved
        let par = self.ring.domain();
        if self.ring.certifying() && self.node.is_none() {
            // a value without a derivation of its own (made only for a decision): a
            // certificate writes it out with its sign, which a recheck proves again
            let s = self.sign_by_parametrization(&par);
            if let Some(s) = s {
                self.record_valued_sign(s);
            }
            return s;
        }
        // a certificate records the value of each proved sign as it is first derived:
        // the memo serves proofs without one
        if self.ring.certifying() {
            return self.sign_by_parametrization(&par);
        }
        let key = (self.val.num.clone(), self.val.den.clone());
        if let Some(known) = self.ring.state().signs.sign_memo.get(&key) {
            return *known;
        }
        let s = self.sign_by_parametrization(&par);
        self.ring.state().signs.sign_memo.insert(key, s);
        s
    }

    /// [`Sym::proved_sign`] of a value made only to decide a sign (a quotient by a
    /// hypothesis or by a fact), which has no derivation of its own: a certificate
    /// writes the value out with its sign.
    pub(crate) fn proved_sign_of_quotient(&self) -> Option<i32> {
        self.proved_sign()
    }

    /// Records, for a certificate, the sign `s` of this value, which has no derivation:
    /// a `sign value (N)/(D) > 0` line, proved again by a recheck.
    fn record_valued_sign(&self, s: i32) {
        let mut st = self.ring.state();
        let known = (st.signs.valued.iter())
            .any(|(v, t)| *t == s && v.num == self.val.num && v.den == self.val.den);
        if !known {
            st.signs.valued.push(((*self.val).clone(), s));
        }
    }

    /// The sign of a factor a certificate records with its value (the factor of a
    /// hypothesis' value), proved with the parametrization of the domain, which the
    /// recheck repeats: no note, and the certificate kept.
    pub(crate) fn sign_of_recorded_factor(&self) -> Option<i32> {
        self.sign_by_parametrization(&self.ring.domain())
    }

    /// [`Sym::proved_sign`] as a test that leaves no trace in the proof (no proved sign
    /// recorded, the certificate kept): for checks whose result enters the proof only
    /// through a later decision, which records itself.
    pub(crate) fn proved_sign_unrecorded(&self) -> Option<i32> {
        let ring = &self.ring;
        let (signs, uncertified, valued, dominance) = {
            let st = ring.state();
            (
                st.signs.proved_signs.len(),
                st.uncertified.len(),
                st.signs.valued.len(),
                st.signs.dominance.len(),
            )
        };
        let s = if ring.certifying() && self.node.is_none() {
            self.sign_by_parametrization(&ring.domain())
        } else {
            self.proved_sign()
        };
        let mut st = ring.state();
        st.signs.proved_signs.truncate(signs);
        st.signs.valued.truncate(valued);
        st.signs.dominance.truncate(dominance);
        st.uncertified.truncate(uncertified);
        s
    }

    /// [`Sym::proved_sign`] computed: the test (with the alternative parametrization
    /// where the first proves nothing), the agreement with the points, the note.
    fn sign_by_parametrization(&self, par: &Parametrization) -> Option<i32> {
        let s = self.sign_with(par).or_else(|| {
            let alt = par.alternative()?;
            if self.val.num.len() + self.val.den.len() > MAX_WIDENED_TERMS {
                return None;
            }
            self.sign_with(alt)
        })?;
        // the points lie in the parametrized domain: their signs must agree
        let prec = self.ring.precision();
        let agree =
            (0..self.ring.points()).all(|p| self.val.sh.real_sign(p, prec).is_none_or(|x| x == s));
        if !agree {
            return None;
        }
        let rel = if s > 0 { ">" } else { "<" };
        let statement = format!("{} {rel} 0", self.render_short(160));
        let mut st = self.ring.state();
        if st
            .signs
            .proved_signs
            .iter()
            .all(|(_, _, t)| *t != statement)
        {
            st.signs
                .proved_signs
                .push((self.node.clone(), s, statement));
        }
        drop(st);
        Some(s)
    }
}

impl Sym {
    /// The sign by one parametrization: the plain test, then the rules of module
    /// `decide` through the square roots.
    fn sign_with(&self, par: &Parametrization) -> Option<i32> {
        let images = self.ring.sign_images(par, &self.val.num)?;
        let ring = &self.ring;
        if let Some((s, n)) = par.sign_of_polya(&self.val.num, &self.val.den, &images) {
            ring.note_polya(n);
            return Some(s);
        }
        Some(ring.tower_sign(par, &self.val.num, 0)? * ring.tower_sign(par, &self.val.den, 0)?)
    }
}

impl Ring {
    /// Records that a sign test needed the Pólya multiplier `(1 + Σ tᵢ)ᴺ` (`n > 0`),
    /// which the certificate format does not record.
    pub(crate) fn note_polya(&self, n: u32) {
        if n == super::parametrization::SQUARE && self.certifying() {
            self.mark_uncertified(
                "a sign proved as that of ±q² with q of proved sign, which the certificate format does not record",
            );
            return;
        }
        if n > 0 && self.certifying() {
            self.mark_uncertified(
                "a sign proved after a Pólya multiplication by (1 + Σ t)^N, which the certificate format does not record",
            );
        }
    }

    /// The parametrization of the domain, or an empty one (which still proves the signs
    /// of constants and of positive roots of positive constants).
    fn domain(&self) -> Arc<Parametrization> {
        static EMPTY: std::sync::OnceLock<Arc<Parametrization>> = std::sync::OnceLock::new();
        (self.inner.opts.positivity.clone()).unwrap_or_else(|| {
            EMPTY
                .get_or_init(|| Arc::new(Parametrization::new()))
                .clone()
        })
    }

    /// The images of the variables of the ring's context in a sign test of `num`:
    /// indeterminates by name, and square roots whose radicands are proved positive
    /// and whose values at the domain points are positive.
    pub(crate) fn sign_images<'p>(
        &self,
        par: &'p Parametrization,
        num: &Poly,
    ) -> Option<Vec<Image<'p>>> {
        let max_roots = self.inner.opts.max_roots;
        let used_roots: Vec<usize> = (num.used_vars().into_iter())
            .filter(|&i| i < max_roots)
            .map(|i| max_roots - 1 - i)
            .collect();
        // only the roots the value uses and those their radicands use, in order
        let (vars, roots, squares) = {
            let st = self.state();
            let vars: Vec<Option<String>> = (st.vars.iter())
                .map(|v| matches!(v.kind, VarKind::Indeterminate).then(|| v.name.clone()))
                .collect();
            // sn of a real base argument: sn² ∈ [0, 1]
            let squares: Vec<bool> = (st.vars.iter())
                .map(|v| match v.kind {
                    VarKind::Sn { table, base } => {
                        (st.tables.get(table).and_then(|t| t.bases.get(base)))
                            .is_some_and(|b| b.real)
                    }
                    _ => false,
                })
                .collect();
            let mut needed: Vec<usize> = (used_roots.iter())
                .filter_map(|&i| st.roots.get(i))
                .flat_map(|r| r.closure.iter().copied())
                .collect();
            needed.sort_unstable();
            needed.dedup();
            let roots: Vec<(usize, Poly, bool)> = (needed.into_iter())
                .filter_map(|i| {
                    st.roots
                        .get(i)
                        .map(|r| (i, r.radicand.clone(), r.is_positive()))
                })
                .collect();
            (vars, roots, squares)
        };
        let mut images = vec![Image::None; num.ctx().nvars()];
        for (j, name) in vars.iter().enumerate() {
            if let (Some(n), Some(slot)) = (name, images.get_mut(max_roots + j))
                && let Some(img) = par.image(n)
            {
                *slot = Image::Var(img);
            }
        }
        for (j, real) in squares.iter().enumerate() {
            if *real && let Some(slot) = images.get_mut(max_roots + j) {
                *slot = Image::Square(j);
            }
        }
        for (i, radicand, positive) in roots {
            if positive && let Some((1, n)) = par.poly_sign_polya(&radicand, &images) {
                self.note_polya(n);
                images[max_roots - 1 - i] = Image::Root(i);
            }
        }
        Some(images)
    }
}

impl super::ring::RootInfo {
    /// Is the root the principal root of its radicand (see [`RootInfo::principal`]),
    /// with a positive real value at every domain point?  Where its radicand is proved
    /// positive, it is then the positive root on the whole domain.
    ///
    /// [`RootInfo::principal`]: super::ring::RootInfo
    pub(crate) fn is_positive(&self) -> bool {
        self.principal
            && self.values.iter().all(|z| {
                let (re, im) = (z.real(), z.imag());
                *re > 0
                    && (im.is_zero()
                        || Float::with_val(64, im.abs_ref()) < Float::with_val(64, re) >> 100)
            })
    }
}
