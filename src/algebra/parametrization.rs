//! Signs proved on a domain, not taken at points: a value is substituted with a
//! parametrization of the domain by positive parameters, and its sign is proved when
//! every coefficient of the resulting numerator and denominator has the same sign.
//!
//! **Parametrization.**  Each indeterminate of the claim is a rational function of
//! parameters `t > 0` (a range `(0, 1)` is `t/(1 + t)`) and of parameters `μ ≠ 0` of
//! either sign.  Such a parametrization covers a *superset* of the sampled domain (for
//! example `A > B > C > 0` for moments of inertia drawn with gaps of at least 0.2), so a
//! sign proved on it holds on the sampled domain, and on the paper's.
//!
//! **Test.**  For `p(x)` with `xᵢ = nᵢ(t)/dᵢ(t)` and `Dᵢ` the degree of `p` in `xᵢ`,
//! `p(x)·∏ dᵢ^Dᵢ = Σ c·∏ nᵢ^eᵢ·dᵢ^(Dᵢ−eᵢ)` is a polynomial in the parameters.  When
//! all its coefficients have one sign, and every parameter `μ` of either sign occurs
//! to even powers only, every term has that sign at every point of the parametrized
//! domain (with `μ ≠ 0`), so the sum does too; the signs of the `dᵢ` are proved the same
//! way.  A square root `r` proved to be the positive root of its radicand (module
//! [`super::positivity`]) enters as one more positive parameter (forgetting `r² = a`
//! only weakens the test).  The test is sufficient, not
//! necessary: a sign it does not prove is simply not proved.
//!
//! ```
//! use eulertop::algebra::parametrization::Parametrization;
//! let mut par = Parametrization::new();
//! let c = par.positive("t_C").unwrap();
//! let b = c.add(&par.positive("t_B").unwrap());
//! par.bind("C", c, "C = t_C".into());
//! par.bind("B", b, "B = C + t_B".into());
//! // B − C = t_B > 0, and 1/C − 1/B = t_B/(B C) > 0
//! assert!(par.image("B").is_some());
//! ```

use super::flint::{Ctx, Poly};
use rug::Rational;
use std::collections::{BTreeMap, HashMap};
use std::sync::{Arc, Mutex};

/// The most parameters of a parametrization.
pub const MAX_PARAMS: usize = 24;
/// Parameter slots for square roots (the ring's roots, by index).
const ROOT_SLOTS: usize = 64;
/// Parameter slots for `sn²` of real base arguments (the ring's field variables, by
/// index): `sn² = u/(1 + u)`, `u > 0`.
const UNIT_SLOTS: usize = 64;
/// The largest numerator, in terms, whose sign is tested.
const MAX_INPUT_TERMS: usize = 400;
/// The largest substituted polynomial, in terms.
const MAX_OUTPUT_TERMS: usize = 40_000;
/// The largest numerator, in terms, tested with `sn²` as a parameter or with the
/// alternative parametrization (their substitutions grow fast).
pub(crate) const MAX_WIDENED_TERMS: usize = 64;
/// The most substitutions a parametrization remembers (see [`SubstMemo`]).
const MAX_MEMO: usize = 4096;
/// The largest exponent of the Pólya multiplier (see [`Parametrization::poly_sign_polya`]).
const MAX_POLYA: u32 = 8;
/// The most terms a polynomial may have for a Pólya multiplication to be tried (the
/// test is tried on every undecided sign, so it must stay cheap).
const MAX_POLYA_START_TERMS: usize = 40;
/// The most terms a Pólya multiple may have.
const MAX_POLYA_TERMS: usize = 400;

/// How a parameter ranges.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamKind {
    /// `t > 0`.
    Positive,
    /// `μ ≠ 0`, of either sign.
    NonZero,
}

/// A rational function of the parameters, `num/den`.
#[derive(Clone, Debug)]
pub struct ParamRat {
    num: Poly,
    den: Poly,
}

impl ParamRat {
    fn reduced(num: Poly, den: Poly) -> ParamRat {
        if num.is_zero() {
            let one = Poly::from_i64(num.ctx(), 1);
            return ParamRat { num, den: one };
        }
        match num.gcd(&den) {
            Ok(g) if !g.is_one() => match (num.divides(&g), den.divides(&g)) {
                (Ok(Some(n)), Ok(Some(d))) => ParamRat { num: n, den: d },
                _ => ParamRat { num, den },
            },
            _ => ParamRat { num, den },
        }
    }
    /// `self + o`.
    pub fn add(&self, o: &ParamRat) -> ParamRat {
        let n = self.num.mul(&o.den).add(&o.num.mul(&self.den));
        ParamRat::reduced(n, self.den.mul(&o.den))
    }
    /// `self − o`.
    pub fn sub(&self, o: &ParamRat) -> ParamRat {
        self.add(&o.neg())
    }
    /// `self · o`.
    pub fn mul(&self, o: &ParamRat) -> ParamRat {
        ParamRat::reduced(self.num.mul(&o.num), self.den.mul(&o.den))
    }
    /// `self / o`; `None` when `o` is 0.
    pub fn div(&self, o: &ParamRat) -> Option<ParamRat> {
        if o.num.is_zero() {
            return None;
        }
        Some(ParamRat::reduced(
            self.num.mul(&o.den),
            self.den.mul(&o.num),
        ))
    }
    /// `−self`.
    pub fn neg(&self) -> ParamRat {
        ParamRat {
            num: self.num.neg(),
            den: self.den.clone(),
        }
    }
    /// `self^e` for an integer `e` (`None` for 0 to a negative power or a huge power).
    pub fn powi(&self, e: i64) -> Option<ParamRat> {
        if e.unsigned_abs() > 64 {
            return None;
        }
        let (n, d) = (
            self.num.pow(e.unsigned_abs()).ok()?,
            self.den.pow(e.unsigned_abs()).ok()?,
        );
        if e >= 0 {
            Some(ParamRat { num: n, den: d })
        } else if n.is_zero() {
            None
        } else {
            Some(ParamRat::reduced(d, n))
        }
    }
    /// The value if it is a constant.
    pub fn as_constant(&self) -> Option<Rational> {
        let n = self.num.as_constant()?;
        let d = self.den.as_constant()?;
        Some(Rational::from((n, d)))
    }
}

/// A parametrization of a domain: images of the claim's indeterminates (by name) as
/// rational functions of positive and nonzero parameters.
pub struct Parametrization {
    ctx: Arc<Ctx>,
    params: Vec<(String, ParamKind)>,
    images: BTreeMap<String, ParamRat>,
    descriptions: Vec<String>,
    /// See [`Parametrization::set_alternative`].
    alternative: Option<Box<Parametrization>>,
    /// Substitutions already made (a claim's cases and decisions ask for the sign of
    /// the same polynomial many times).
    memo: Arc<SubstMemo>,
}

/// What a variable stands for in a substitution, as a memo key.
#[derive(Clone, PartialEq, Eq, Hash)]
enum ImageKey {
    Var(Poly, Poly),
    Root(usize),
    Square(usize),
}

/// The memo of [`Parametrization::substituted`]: the polynomial and the images of the
/// variables it uses determine the result.  At most [`MAX_MEMO`] entries.  A key
/// starts with the address of the polynomial's context, so that polynomials of
/// different contexts are never compared (the key's polynomial keeps its context
/// alive, so the address is not reused while the entry exists).
#[derive(Default)]
struct SubstMemo(Mutex<HashMap<SubstKey, Option<(Poly, i32)>>>);

/// See [`SubstMemo`].
type SubstKey = (usize, Poly, Vec<(usize, ImageKey)>);

impl std::fmt::Debug for Parametrization {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Parametrization({})", self.descriptions.join("; "))
    }
}

impl Default for Parametrization {
    fn default() -> Self {
        Parametrization::new()
    }
}

/// The most terms of a polynomial tested as `±q²` ([`Parametrization::square_sign`]).
const MAX_SQUARE_TERMS: usize = 400;

/// The exponent reported for a sign proved as that of `±q²`
/// ([`Parametrization::square_sign`]): no Pólya exponent, a step the certificate format
/// does not record.
pub(crate) const SQUARE: u32 = u32::MAX;

impl Parametrization {
    /// An empty parametrization.
    pub fn new() -> Parametrization {
        Parametrization {
            ctx: Ctx::new(MAX_PARAMS + ROOT_SLOTS + UNIT_SLOTS),
            params: Vec::new(),
            images: BTreeMap::new(),
            descriptions: Vec::new(),
            alternative: None,
            memo: Arc::default(),
        }
    }

    /// A second parametrization of the same domain, tried where this one proves no sign
    /// (such as the box of the sampled intervals, beside ranges relaxed to half-lines).
    pub fn set_alternative(&mut self, other: Parametrization) {
        self.alternative = Some(Box::new(other));
    }
    /// The alternative parametrization (see [`Parametrization::set_alternative`]).
    pub(crate) fn alternative(&self) -> Option<&Parametrization> {
        self.alternative.as_deref()
    }

    fn param(&mut self, name: &str, kind: ParamKind) -> Option<ParamRat> {
        if self.params.len() >= MAX_PARAMS {
            return None;
        }
        let p = Poly::var(&self.ctx, self.params.len());
        self.params.push((name.to_string(), kind));
        Some(ParamRat {
            num: p,
            den: Poly::from_i64(&self.ctx, 1),
        })
    }

    /// A new parameter `t > 0` (`None` when there is no room).
    pub fn positive(&mut self, name: &str) -> Option<ParamRat> {
        self.param(name, ParamKind::Positive)
    }

    /// A new parameter `μ ≠ 0` of either sign (`None` when there is no room).
    pub fn nonzero(&mut self, name: &str) -> Option<ParamRat> {
        self.param(name, ParamKind::NonZero)
    }

    /// The constant `q`.
    pub fn constant(&self, q: &Rational) -> ParamRat {
        ParamRat {
            num: Poly::from_integer(&self.ctx, q.numer()),
            den: Poly::from_integer(&self.ctx, q.denom()),
        }
    }

    /// Binds the indeterminate `var` to `value`; `description` says how, for the reader
    /// (an empty one is left out).
    pub fn bind(&mut self, var: &str, value: ParamRat, description: String) {
        self.images.insert(var.to_string(), value);
        if !description.is_empty() {
            self.descriptions.push(description);
        }
    }

    /// The image of an indeterminate.
    pub fn image(&self, var: &str) -> Option<&ParamRat> {
        self.images.get(var)
    }

    /// Is no indeterminate parametrized?
    pub fn is_empty(&self) -> bool {
        self.images.is_empty()
    }

    /// The certificate lines of the parametrization: `param t positive|nonzero` for each
    /// parameter, then `image x = (N)/(D)` for each of `vars` (the indeterminates of a
    /// ring) that has an image; then the same lines of the alternative, each prefixed
    /// `alt `.
    pub(crate) fn certificate_lines(&self, vars: &[String]) -> String {
        let mut out = self.own_certificate_lines(vars);
        if let Some(alt) = &self.alternative {
            // the alternative's lines, each prefixed `alt ` (a second parametrization of
            // the same domain, tried where the first proves no sign)
            for line in alt.own_certificate_lines(vars).lines() {
                out.push_str(&format!("alt {line}\n"));
            }
        }
        out
    }

    /// [`Parametrization::certificate_lines`] without the alternative's.
    fn own_certificate_lines(&self, vars: &[String]) -> String {
        let mut names: Vec<String> = self.params.iter().map(|(n, _)| n.clone()).collect();
        names.extend((0..ROOT_SLOTS).map(|i| format!("unused_{i}")));
        let mut out = String::new();
        for (n, k) in &self.params {
            let kind = if *k == ParamKind::Positive {
                "positive"
            } else {
                "nonzero"
            };
            out.push_str(&format!("param {n} {kind}\n"));
        }
        for v in vars {
            if let Some(img) = self.images.get(v) {
                out.push_str(&format!(
                    "image {v} = ({})/({})\n",
                    img.num.render(&names),
                    img.den.render(&names)
                ));
            }
        }
        out
    }

    /// How the domain is parametrized, for the reader: the images, then the ranges of
    /// the parameters.
    pub fn describe(&self) -> String {
        let of = |kind: ParamKind| -> Vec<&str> {
            (self.params.iter())
                .filter(|(_, k)| *k == kind)
                .map(|(n, _)| n.as_str())
                .collect()
        };
        let mut ranges = Vec::new();
        for (kind, rel) in [(ParamKind::Positive, "> 0"), (ParamKind::NonZero, "≠ 0")] {
            let names = of(kind);
            if !names.is_empty() {
                ranges.push(format!("{} {rel}", names.join(", ")));
            }
        }
        format!(
            "{}, with {}",
            self.descriptions.join("; "),
            ranges.join(" and ")
        )
    }

    /// The sign of `num/den` (polynomials of another context) where the variable of
    /// index `i` of that context is `images[i]`; `None` when the test does not decide.
    #[cfg(test)]
    pub(crate) fn sign_of(&self, num: &Poly, den: &Poly, images: &[Image<'_>]) -> Option<i32> {
        self.sign_of_polya(num, den, images).map(|(s, _)| s)
    }

    /// [`Parametrization::sign_of`] with the larger of the two Pólya exponents it needed
    /// (see [`Parametrization::poly_sign_polya`]).
    pub(crate) fn sign_of_polya(
        &self,
        num: &Poly,
        den: &Poly,
        images: &[Image<'_>],
    ) -> Option<(i32, u32)> {
        let (a, m) = self.poly_sign_polya(num, images)?;
        let (b, n) = self.poly_sign_polya(den, images)?;
        Some((a * b, m.max(n)))
    }

    /// The sign of `p` on the domain and the exponent `N` of the Pólya multiplier
    /// `(1 + Σ tᵢ)ᴺ` (0 when the coefficients have one sign at once): a polynomial
    /// positive on the closed orthant of the positive parameters, its leading form
    /// included, has a multiple by such a power with positive coefficients (Pólya's
    /// theorem, for the form homogenized by `t₀ = 1`); as the multiplier is positive,
    /// the sign of the product is the sign of `p`.
    pub(crate) fn poly_sign_polya(&self, p: &Poly, images: &[Image<'_>]) -> Option<(i32, u32)> {
        let (acc, factor) = self.substituted(p, images)?;
        if let Some(s) = self.definite_sign(&acc) {
            return Some((s * factor, 0));
        }
        match self.polya(acc) {
            Some((s, n)) => Some((s * factor, n)),
            None => self.square_sign(p, images),
        }
    }

    /// The sign of `p = ±q²` where `q` has a proved sign on the domain (then `q ≠ 0`
    /// there, so `q² > 0`): the Jacobian determinant of decoupled equations, say, is
    /// `−(64ABC(A − B)(A − C)(B − C))²`, whose expanded coefficients have both signs.
    /// Only for polynomials of at most [`MAX_SQUARE_TERMS`] terms.
    fn square_sign(&self, p: &Poly, images: &[Image<'_>]) -> Option<(i32, u32)> {
        if p.len() > MAX_SQUARE_TERMS || p.as_constant().is_some() {
            return None;
        }
        for s in [1, -1] {
            let signed = if s > 0 { p.clone() } else { p.neg() };
            if let Some(q) = signed.sqrt() {
                self.poly_sign_polya(&q, images)?;
                return Some((s, SQUARE));
            }
        }
        None
    }

    /// Multiplies by `1 + Σ tᵢ` (over the parameters that occur) until the coefficients
    /// have one sign, from at most [`MAX_POLYA_START_TERMS`] terms, within [`MAX_POLYA`]
    /// steps and [`MAX_POLYA_TERMS`] terms; not for a
    /// polynomial in a parameter of either sign.
    fn polya(&self, mut acc: Poly) -> Option<(i32, u32)> {
        let used = acc.used_vars();
        let either = |i: &usize| {
            self.params
                .get(*i)
                .is_some_and(|(_, k)| *k == ParamKind::NonZero)
        };
        if acc.len() > MAX_POLYA_START_TERMS || used.iter().any(either) {
            return None;
        }
        let mut step = Poly::from_i64(&self.ctx, 1);
        for &i in &used {
            step = step.add(&Poly::var(&self.ctx, i));
        }
        for n in 1..=MAX_POLYA {
            acc = acc.mul(&step);
            if acc.len() > MAX_POLYA_TERMS {
                return None;
            }
            if let Some(s) = self.definite_sign(&acc) {
                return Some((s, n));
            }
        }
        None
    }

    /// `p` with the images substituted and the denominators cleared (a polynomial in
    /// the parameters), and the sign of the cleared denominators; remembered.
    fn substituted(&self, p: &Poly, images: &[Image<'_>]) -> Option<(Poly, i32)> {
        if p.is_zero() || p.len() > MAX_INPUT_TERMS {
            return None;
        }
        let mut key_images = Vec::new();
        for i in p.used_vars() {
            key_images.push((
                i,
                match images.get(i)? {
                    Image::Var(r) => ImageKey::Var(r.num.clone(), r.den.clone()),
                    Image::Root(slot) => ImageKey::Root(*slot),
                    Image::Square(slot) => ImageKey::Square(*slot),
                    Image::None => return None,
                },
            ));
        }
        let key = (Arc::as_ptr(p.ctx()) as usize, p.clone(), key_images);
        if let Some(known) = self.memo.0.lock().ok()?.get(&key) {
            return known.clone();
        }
        let out = self.substitute(p, images);
        let mut memo = self.memo.0.lock().ok()?;
        if memo.len() < MAX_MEMO {
            memo.insert(key, out.clone());
        }
        out
    }

    /// [`Parametrization::substituted`] computed.
    fn substitute(&self, p: &Poly, images: &[Image<'_>]) -> Option<(Poly, i32)> {
        let degs = p.degrees();
        let used = p.used_vars();
        let mut factor = 1;
        let mut rows: Vec<(usize, Vec<Poly>, Vec<Poly>, bool)> = Vec::new();
        for &i in &used {
            let (n, d, halve) = match images.get(i)? {
                Image::Var(r) => (r.num.clone(), r.den.clone(), false),
                Image::Root(slot) => (self.root_param(*slot)?, Poly::from_i64(&self.ctx, 1), false),
                Image::Square(slot) => {
                    if p.len() > MAX_WIDENED_TERMS {
                        return None;
                    }
                    let u = self.unit_param(*slot)?;
                    let one = Poly::from_i64(&self.ctx, 1);
                    (u.clone(), one.add(&u), true)
                }
                Image::None => return None,
            };
            let mut deg = usize::try_from(degs[i]).ok()?;
            if halve {
                // the variable enters through its square only
                let mut even = true;
                p.for_each_term(|_, e| even &= e[i] % 2 == 0);
                if !even {
                    return None;
                }
                deg /= 2;
            }
            let sd = self.definite_sign(&d)?;
            if deg % 2 == 1 {
                factor *= sd;
            }
            rows.push((i, powers(&n, deg)?, powers(&d, deg)?, halve));
        }
        let mut acc = Poly::zero(&self.ctx);
        let mut failed = false;
        p.for_each_term(|c, e| {
            if failed {
                return;
            }
            let mut t = Poly::from_integer(&self.ctx, c);
            for (i, np, dp, halve) in &rows {
                let k = if *halve {
                    e[*i] as usize / 2
                } else {
                    e[*i] as usize
                };
                t = t.mul(&np[k]).mul(&dp[dp.len() - 1 - k]);
            }
            acc = acc.add(&t);
            failed = acc.len() > MAX_OUTPUT_TERMS;
        });
        if failed {
            return None;
        }
        Some((acc, factor))
    }

    fn root_param(&self, slot: usize) -> Option<Poly> {
        (slot < ROOT_SLOTS).then(|| Poly::var(&self.ctx, MAX_PARAMS + slot))
    }

    fn unit_param(&self, slot: usize) -> Option<Poly> {
        (slot < UNIT_SLOTS).then(|| Poly::var(&self.ctx, MAX_PARAMS + ROOT_SLOTS + slot))
    }

    /// The sign of a polynomial in the parameters whose terms all have one sign.
    fn definite_sign(&self, p: &Poly) -> Option<i32> {
        if p.is_zero() {
            return None;
        }
        let nonzero: Vec<usize> = (self.params.iter().enumerate())
            .filter(|(_, (_, k))| *k == ParamKind::NonZero)
            .map(|(i, _)| i)
            .collect();
        let (mut pos, mut neg, mut odd) = (false, false, false);
        p.for_each_term(|c, e| {
            if *c > 0 {
                pos = true;
            } else {
                neg = true;
            }
            odd |= nonzero.iter().any(|&i| e[i] % 2 == 1);
        });
        match (pos, neg, odd) {
            (true, false, false) => Some(1),
            (false, true, false) => Some(-1),
            _ => None,
        }
    }
}

/// `p⁰ … p^deg`.
fn powers(p: &Poly, deg: usize) -> Option<Vec<Poly>> {
    let mut out = vec![Poly::from_i64(p.ctx(), 1)];
    for _ in 0..deg {
        let next = out.last()?.mul(p);
        if next.len() > MAX_OUTPUT_TERMS {
            return None;
        }
        out.push(next);
    }
    Some(out)
}

/// What a variable of the ring's context stands for in a sign test.
#[derive(Clone, Copy)]
pub(crate) enum Image<'a> {
    /// An indeterminate with its image.
    Var(&'a ParamRat),
    /// A positive square root, by root index.
    Root(usize),
    /// `sn` of a real base argument at a modulus in `(0, 1)`, which enters through its
    /// square `sn² ∈ [0, 1]` only (by field-variable index).
    Square(usize),
    /// Anything else: the test does not apply.
    None,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// C = t₁, B = C + t₂, and x = μ of either sign, as images of variables 0, 1, 2.
    fn setup() -> (Parametrization, Arc<Ctx>) {
        let mut par = Parametrization::new();
        let c = par.positive("t1").unwrap();
        let b = c.add(&par.positive("t2").unwrap());
        let x = par.nonzero("mu").unwrap();
        par.bind("C", c, "C = t1".into());
        par.bind("B", b, "B = C + t2".into());
        par.bind("x", x, "x = mu".into());
        (par, Ctx::new(3))
    }

    fn sign(par: &Parametrization, ctx: &Arc<Ctx>, num: &Poly, den: &Poly) -> Option<i32> {
        let images: Vec<Image<'_>> = ["C", "B", "x"]
            .iter()
            .map(|n| Image::Var(par.image(n).unwrap()))
            .collect();
        assert_eq!(images.len(), ctx.nvars());
        par.sign_of(num, den, &images)
    }

    #[test]
    fn signs_follow_from_the_parametrization() {
        let (par, ctx) = setup();
        let (c, b, x) = (Poly::var(&ctx, 0), Poly::var(&ctx, 1), Poly::var(&ctx, 2));
        let one = Poly::from_i64(&ctx, 1);
        // B − C = t2 > 0; C − B < 0; 1/C − 1/B = (B − C)/(B C) > 0
        assert_eq!(sign(&par, &ctx, &b.sub(&c), &one), Some(1));
        assert_eq!(sign(&par, &ctx, &c.sub(&b), &one), Some(-1));
        assert_eq!(sign(&par, &ctx, &b.sub(&c), &b.mul(&c)), Some(1));
        // (B − C) x² > 0 for x ≠ 0; x³ C has the sign of x: undecided
        let x2 = x.mul(&x);
        assert_eq!(sign(&par, &ctx, &b.sub(&c).mul(&x2), &one), Some(1));
        assert_eq!(sign(&par, &ctx, &x2.mul(&x).mul(&c), &one), None);
        // B − 2C = t2 − t1 changes sign: undecided; the zero polynomial: undecided
        let two_c = c.scale(&rug::Integer::from(2));
        assert_eq!(sign(&par, &ctx, &b.sub(&two_c), &one), None);
        assert_eq!(sign(&par, &ctx, &Poly::zero(&ctx), &one), None);
    }

    #[test]
    fn a_unit_range_parameter_is_below_one() {
        let mut par = Parametrization::new();
        let t = par.positive("t").unwrap();
        let one = par.constant(&Rational::from(1));
        let u = t.div(&one.add(&t)).unwrap();
        par.bind("u", u, "u = t/(1 + t)".into());
        let ctx = Ctx::new(1);
        let images = [Image::Var(par.image("u").unwrap())];
        let (u, one) = (Poly::var(&ctx, 0), Poly::from_i64(&ctx, 1));
        assert_eq!(par.sign_of(&one.sub(&u), &one, &images), Some(1));
        assert_eq!(par.sign_of(&u, &one.sub(&u), &images), Some(1));
        let half = Poly::from_i64(&ctx, 2).mul(&u).sub(&one);
        assert_eq!(par.sign_of(&half, &one, &images), None);
    }

    #[test]
    fn a_positive_polynomial_with_coefficients_of_both_signs_is_proved_after_polya() {
        // x = t/(1 + t) ∈ (0, 1): x² − x + c is positive for c > 1/4
        let mut par = Parametrization::new();
        let x = par.positive("t").unwrap();
        let one = par.constant(&Rational::from(1));
        let x = x.div(&one.add(&x)).unwrap();
        par.bind("x", x, "x = t/(1 + t)".into());
        let ctx = Ctx::new(1);
        let images = [Image::Var(par.image("x").unwrap())];
        let v = Poly::var(&ctx, 0);
        let q = |c: (i64, i64)| {
            let p = v.mul(&v).sub(&v).mul(&Poly::from_i64(&ctx, c.1));
            p.add(&Poly::from_i64(&ctx, c.0))
        };
        // 3/10: (1 + t)³ times 0.3t² − 0.4t + 0.3 has no negative coefficient
        assert_eq!(par.poly_sign_polya(&q((3, 10)), &images), Some((1, 3)));
        // 1/4: (x − 1/2)² vanishes at x = 1/2; 1/5: negative near x = 1/2
        assert_eq!(par.poly_sign_polya(&q((1, 4)), &images), None);
        assert_eq!(par.poly_sign_polya(&q((1, 5)), &images), None);
    }
}
