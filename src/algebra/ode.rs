//! A second proof method: uniqueness of the solution of an algebraic ODE.
//!
//! The normal forms of the tower relate `sn`, `cn`, `dn` at one modulus only, so an
//! identity between Jacobi functions of different moduli (Landen's and Gauss's
//! transformations, DLMF 22.7; the reciprocal modulus, DLMF 22.17) is not a normal-form
//! identity.  It is proved instead as follows, for `f(x) = g(x)` in one real variable
//! `x` (the other variables fixed):
//!
//! 1. **The ODE.**  One side is a Jacobi function `y = pq(a·x + b, κ)` (`pq` one of sn,
//!    cn, dn, `a ≠ 0`, `b` and `κ` independent of `x`); it solves `y'' = a²·Φ(y)` with
//!    `Φ` the odd cubic of DLMF 22.13.13–15 (`Φ_sn(y) = −(1+κ²)y + 2κ²y³`,
//!    `Φ_cn(y) = −(1−2κ²)y − 2κ²y³`, `Φ_dn(y) = (2−κ²)y − 2y³`).
//! 2. **Both sides satisfy it identically.**  The Jacobi functions of the claim are jet
//!    symbols (module `jets`: `S, C, D` per argument and modulus, with the derivation
//!    `S' = C·D·a'`, …); for each side `F`, `F'' − a²Φ(F)` is computed exactly by the
//!    prover's derivation and its numerator reduced modulo `C² = 1 − S²`,
//!    `D² = 1 − κ²S²` (module `jets`).  The reduction is 0, or the method fails.
//!    The check is exact also for the side the ODE was taken from.
//! 3. **The same initial values.**  At `x₀ = 0` every jet's argument must vanish exactly
//!    (then `S = 0`, `C = D = 1` there); `F(0) = G(0)` and `F'(0) = G'(0)` exactly, and
//!    the denominators of `F`, `F'`, `G`, `G'` do not vanish at `x₀` (a singular starting
//!    point is rejected).  Each side must be a rational function of `x` and the jets
//!    with coefficients independent of `x` (no root of the tower may depend on `x`), so
//!    that it is analytic wherever its denominator does not vanish.
//!
//! **Why this proves `f = g`.**  `Y = (y, y')` solves the first-order system
//! `Y' = (y', a²Φ(y))`, whose right side is a polynomial, hence locally Lipschitz; by the
//! Picard–Lindelöf theorem two `C²` solutions on an interval `I ∋ x₀` with the same
//! `Y(x₀)` agree on `I`.  So `f = g` on every interval containing `0` on which both
//! sides are analytic (`C²` suffices; here: their denominators do not vanish), for each
//! value of the other variables at which the exact initial values are defined — the
//! scope the method states with its proof.  (With
//! analytic sides, agreement near `x₀` extends to the connected domain of analyticity
//! by the identity theorem.)  This is the simplest case of the zero test for
//! D-algebraic functions of J. van der Hoeven, "A new zero-test for formal power
//! series", ISSAC 2002: a function given by an algebraic ODE is zero when enough
//! initial conditions vanish at a nonsingular point.
//!
//! A false identity is never proved: either a side does not satisfy the ODE (its
//! residual's normal form is not 0) or the initial values differ.
//!
//! **The certificate** ([`OdeProof::certificate`]) records the jet trios, the ODE as a
//! polynomial `P(y, y', y'')`, the values of both sides and of their first two
//! derivatives, the common initial values and `∂P/∂y'' = 1` at the initial point; the
//! checker (`scripts/certcheck/ode.py`) evaluates the sides from the claim's formulas
//! and recomputes the derivatives, the residuals, the initial values and
//! `∂P/∂y''` itself.

use super::error::{AlgResult, AlgebraError};
use super::flint::Poly;
use super::ring::{Ring, VarKind};
use super::sym::Sym;

/// What the ODE method proved, for the reader (and the certificate).
#[derive(Clone, Debug, PartialEq)]
pub struct OdeProof {
    /// The variable `x` of the ODE.
    pub variable: String,
    /// The ODE both sides satisfy, e.g. `y'' = (-k^2 - 1)*y + 2*k^2*y^3`.
    pub ode: String,
    /// The side the ODE is taken from and the function it is.
    pub source: String,
    /// `y(0)` and `y'(0)` of both sides (equal).
    pub initial: [String; 2],
    /// The proof's lines of a certificate (module [`super::certificate`]): the symbols,
    /// the jet trios, the ODE, the values of both sides and of their derivatives, the
    /// initial values and the nonsingularity value; the caller adds the header.
    pub certificate: String,
}

/// Why the method did not prove the identity.
pub type OdeResult<T> = Result<T, String>;

/// The second-order ODE `y'' = a²·Φ(y)` of a side that is one jet symbol.
struct Ode {
    f: u8,
    a2: Sym,
    k2: Sym,
}

impl Ode {
    /// The coefficients `(c₁, c₃)` of `a²·Φ(y) = c₁y + c₃y³`.
    fn coefficients(&self) -> AlgResult<(Sym, Sym)> {
        let r = self.a2.ring();
        let (one, two) = (r.integer(1), r.integer(2));
        let k2 = &self.k2;
        let (lin, cub) = match self.f {
            0 => (one.try_add(k2)?.negate(), two.try_mul(k2)?),
            1 => (two.try_mul(k2)?.try_sub(&one)?, two.try_mul(k2)?.negate()),
            _ => (two.try_sub(k2)?, two.negate()),
        };
        Ok((self.a2.try_mul(&lin)?, self.a2.try_mul(&cub)?))
    }

    /// `a²·Φ(y)`.
    fn rhs(&self, y: &Sym) -> AlgResult<Sym> {
        let (c1, c3) = self.coefficients()?;
        c1.try_mul(y)?.try_add(&c3.try_mul(&y.try_powi(3)?)?)
    }

    /// The ODE for the reader: `y'' = (c₁)*y + (c₃)*y^3`.
    fn render(&self) -> AlgResult<String> {
        let (c1, c3) = self.coefficients()?;
        Ok(format!(
            "y'' = ({})*y + ({})*y^3",
            c1.render_short(120),
            c3.render_short(120)
        ))
    }
}

/// The ODE of `side` in `x` when it is `±pq(a·x + b, κ)` for a jet trio.
fn ode_of(x: &Sym, side: &Sym) -> AlgResult<Option<Ode>> {
    let ring = side.ring();
    let j = match side.as_field_var() {
        Some(j) => j,
        None => match side.negate().as_field_var() {
            Some(j) => j,
            None => return Ok(None),
        },
    };
    let (f, arg, k) = match ring.state().vars[j].kind.clone() {
        VarKind::Jet { f, arg, k, .. } => (f, arg, k),
        _ => return Ok(None),
    };
    let arg = Sym::from_val(ring, *arg, None);
    let k = Sym::from_val(ring, *k, None);
    let a = arg.derivative_plain(x)?;
    if a.is_exact_zero() || !a.derivative_plain(x)?.is_exact_zero() {
        return Ok(None);
    }
    if !k.derivative_plain(x)?.is_exact_zero() {
        return Ok(None);
    }
    Ok(Some(Ode {
        f,
        a2: a.try_mul(&a)?,
        k2: k.try_mul(&k)?,
    }))
}

/// `y'' − a²Φ(y)` of `side`, reduced modulo the jets' relations, is 0; returns `y'` and
/// `y''`.
fn satisfies(x: &Sym, ode: &Ode, side: &Sym, which: &str) -> OdeResult<(Sym, Sym)> {
    let alg = |e: AlgebraError| format!("{which}: {e}");
    let ring = side.ring();
    let ix = (x.as_field_var()).ok_or_else(|| "the variable is not a symbol".to_string())?;
    rational_in_jets(ring, ix, &side.val.num).map_err(alg)?;
    rational_in_jets(ring, ix, &side.val.den).map_err(alg)?;
    let d1 = side.derivative_plain(x).map_err(alg)?;
    let d2 = d1.derivative_plain(x).map_err(alg)?;
    let residual = d2.try_sub(&ode.rhs(side).map_err(alg)?).map_err(alg)?;
    let reduced = side.ring().reduce_jets(&residual).map_err(alg)?;
    if !reduced.is_exact_zero() {
        return Err(format!(
            "the {which} does not satisfy the ODE: the reduced numerator of y'' - a^2*Phi(y) is {}",
            reduced.render_short(120)
        ));
    }
    Ok((d1, d2))
}

/// Proves `lhs = rhs` as functions of the indeterminate `x` by the uniqueness of the
/// solution of `y'' = a²Φ(y)` with `y(0)`, `y'(0)` given (see the module doc).  The
/// ring must make its Jacobi functions jet symbols ([`Ring::jet_sncndn`]).
///
/// ```
/// use eulertop::algebra::{Ring, RingOptions, ode::prove_by_ode};
/// // Gauss's transformation (DLMF 22.7.2 with z = (1 + m²)u and k₁ = m²):
/// // sn((1 + m²)u, 2m/(1 + m²)) = (1 + m²) sn(u, m²) / (1 + m² sn²(u, m²))
/// let ring = Ring::new(RingOptions { points: 2, jets: true, max_vars: 32, ..Default::default() });
/// let u = ring.indeterminate_f64("u", &[0.3, -1.1]).unwrap();
/// let m = ring.indeterminate_f64("m", &[0.5, 0.8]).unwrap();
/// let one = ring.integer(1);
/// let q = one.clone() + m.clone() * m.clone();
/// let k = ring.integer(2) * m.clone() / q.clone();
/// let (lhs, _, _) = ring.jet_sncndn(&(q.clone() * u.clone()), &k).unwrap();
/// let (s, _, _) = ring.jet_sncndn(&u, &(m.clone() * m.clone())).unwrap();
/// let rhs = q.clone() * s.clone() / (one.clone() + m.clone() * m.clone() * s.clone() * s.clone());
/// let proof = prove_by_ode(&u, &lhs, &rhs).unwrap();
/// assert_eq!(proof.initial[0], "0");
/// // the factor 1 + m² replaced by 1 + m⁴: not proved
/// let m4 = m.try_powi(4).unwrap();
/// let wrong = (one.clone() + m4) * s.clone() / (one + m.clone() * m * s.clone() * s);
/// assert!(prove_by_ode(&u, &lhs, &wrong).is_err());
/// ```
pub fn prove_by_ode(x: &Sym, lhs: &Sym, rhs: &Sym) -> OdeResult<OdeProof> {
    let alg = |e: AlgebraError| e.to_string();
    let (ode, source) = match ode_of(x, lhs).map_err(alg)? {
        Some(o) => (o, "lhs"),
        None => match ode_of(x, rhs).map_err(alg)? {
            Some(o) => (o, "rhs"),
            None => {
                return Err(format!(
                    "neither side is sn, cn or dn of an argument linear in {} at a modulus independent of it",
                    x.render_short(20)
                ));
            }
        },
    };
    let (dl, ddl) = satisfies(x, &ode, lhs, "lhs")?;
    let (dr, ddr) = satisfies(x, &ode, rhs, "rhs")?;
    let y0 = same_at_zero(x, lhs, rhs, "y")?;
    let y1 = same_at_zero(x, &dl, &dr, "y'")?;
    let y2 = same_at_zero(x, &ddl, &ddr, "y''")?;
    let sides = [[lhs, &dl, &ddl], [rhs, &dr, &ddr]];
    let certificate = certificate_lines(x, &ode, sides, [&y0, &y1, &y2]).map_err(alg)?;
    Ok(OdeProof {
        variable: x.render_short(20),
        ode: ode.render().map_err(alg)?,
        source: format!(
            "the {source} is {} of an argument linear in {} (DLMF 22.13.13-15)",
            ["sn", "cn", "dn"][ode.f as usize],
            x.render_short(20)
        ),
        initial: [y0.render_short(200), y1.render_short(200)],
        certificate,
    })
}

/// `(N)/(D)`: a value as the certificate writes it.
fn frac_text(v: &Sym, names: &[String]) -> String {
    format!(
        "({})/({})",
        v.val.num.render(names),
        v.val.den.render(names)
    )
}

/// The certificate's lines of the proof: `field` and `root` lines of the ring's
/// symbols, a `jet S C D arg=(…) k=(…)` line per trio, and the `ode` lines: the
/// variable and the initial point, the ODE as an expression in `y0 = y`, `y1 = y'`,
/// `y2 = y''` and the symbols, the values `y0`, `y1`, `y2` of each side, the common
/// initial values and `∂P/∂y2` there (1: the ODE is explicit in `y''`).
fn certificate_lines(
    x: &Sym,
    ode: &Ode,
    sides: [[&Sym; 3]; 2],
    init: [&Sym; 3],
) -> AlgResult<String> {
    use std::fmt::Write;
    let ring = x.ring();
    let names = ring.inner.names();
    let mut out = String::new();
    {
        let st = ring.state();
        for v in &st.vars {
            let tag = match v.kind {
                VarKind::Indeterminate => "indeterminate",
                VarKind::Jet { .. } => "jet",
                VarKind::Opaque { constant: true } => "constant",
                _ => "other",
            };
            let _ = writeln!(out, "field {} {tag}", v.name);
        }
        for r in &st.roots {
            let _ = writeln!(out, "root {} = {}", r.name, r.radicand.render(&names));
        }
    }
    for jet in ring.jets() {
        let (arg, k) = (
            Sym::from_val(ring, jet.arg, None),
            Sym::from_val(ring, jet.k, None),
        );
        let trio: Vec<String> = (0..3)
            .map(|f| names[ring.inner.kvar(jet.s + f)].clone())
            .collect();
        let _ = writeln!(
            out,
            "jet {} arg={} k={}",
            trio.join(" "),
            frac_text(&arg, &names),
            frac_text(&k, &names)
        );
    }
    let (c1, c3) = ode.coefficients()?;
    let _ = writeln!(out, "ode var {} at 0", x.render());
    let _ = writeln!(
        out,
        "ode equation y2 - {}*y0 - {}*y0**3",
        frac_text(&c1, &names),
        frac_text(&c3, &names)
    );
    for (which, ys) in ["lhs", "rhs"].iter().zip(sides) {
        let vals: Vec<String> = (ys.iter().enumerate())
            .map(|(i, y)| format!("y{i}={}", frac_text(y, &names)))
            .collect();
        let _ = writeln!(out, "ode side {which} {}", vals.join(" "));
    }
    let vals: Vec<String> = (init.iter().enumerate())
        .map(|(i, y)| format!("y{i}={}", frac_text(y, &names)))
        .collect();
    let _ = writeln!(out, "ode initial {}", vals.join(" "));
    let _ = writeln!(out, "ode nonsingular (1)/(1)");
    Ok(out)
}

/// `f(0) = g(0)` exactly, with nonzero denominators at 0; returns the common value.
fn same_at_zero(x: &Sym, f: &Sym, g: &Sym, what: &str) -> OdeResult<Sym> {
    let f0 = at_zero(x, f).map_err(|e| format!("{what}(0) of the lhs: {e}"))?;
    let g0 = at_zero(x, g).map_err(|e| format!("{what}(0) of the rhs: {e}"))?;
    let d = f0.try_sub(&g0).map_err(|e| e.to_string())?;
    if !d.is_exact_zero() {
        return Err(format!(
            "the initial values differ: {what}(0) is {} on the lhs and {} on the rhs",
            f0.render_short(80),
            g0.render_short(80)
        ));
    }
    Ok(f0)
}

/// The value at `x = 0` (every jet's argument must vanish there: `S = 0`, `C = D = 1`).
fn at_zero(x: &Sym, v: &Sym) -> AlgResult<Sym> {
    let ring = v.ring();
    let ix = x
        .as_field_var()
        .ok_or_else(|| AlgebraError::Domain("the ODE variable is not a symbol".into()))?;
    let mut zeros = vec![ring.inner.kvar(ix)];
    let mut ones = Vec::new();
    for jet in ring.jets() {
        let arg = Sym::from_val(ring, jet.arg.clone(), None);
        let at = substitute(ring, &arg.val.num, &[ring.inner.kvar(ix)], &[]);
        if !at.is_zero() {
            return Err(AlgebraError::Domain(format!(
                "the argument {} of a Jacobi function is not 0 at 0",
                arg.render_short(60)
            )));
        }
        zeros.push(ring.inner.kvar(jet.s));
        ones.extend([ring.inner.kvar(jet.s + 1), ring.inner.kvar(jet.s + 2)]);
    }
    let num = substitute(ring, &v.val.num, &zeros, &ones);
    let den = substitute(ring, &v.val.den, &zeros, &ones);
    let singular =
        || AlgebraError::Domain("singular starting point: the denominator vanishes at 0".into());
    if den.is_zero() {
        return Err(singular());
    }
    let den = ring.poly_sym(&den);
    let prec = ring.precision();
    if (0..ring.points()).any(|p| den.val.sh.is_small(p, prec)) {
        return Err(singular());
    }
    ring.poly_sym(&num).try_div(&den)
}

/// `p` with the variables `zeros` set to 0 and `ones` set to 1.
fn substitute(ring: &Ring, p: &Poly, zeros: &[usize], ones: &[usize]) -> Poly {
    let mut p = p.clone();
    for &i in zeros {
        p = p.coefficient_in(i, 0);
    }
    for &i in ones {
        let mut sum = Poly::zero(&ring.inner.ctx);
        for e in 0..=p.degree(i).max(0) as u64 {
            sum = sum.add(&p.coefficient_in(i, e));
        }
        p = sum;
    }
    p
}

/// Refuses a value that depends on `x` otherwise than rationally through `x` and the
/// jet symbols: through a root whose radicand depends on `x` (such as `√(1 − sn²)`,
/// which is `|cn|`, not analytic where `cn` vanishes) or a symbol of another kind.
fn rational_in_jets(ring: &Ring, ix: usize, p: &Poly) -> AlgResult<()> {
    for idx in p.used_vars() {
        let depends = match ring.inner.root_of_var(idx) {
            Some(i) => {
                let rad = ring.state().roots[i].radicand.clone();
                !ring
                    .poly_sym(&rad)
                    .derivative_plain(&ring.var_sym(ix))?
                    .is_exact_zero()
            }
            None => {
                let j = idx - ring.inner.opts.max_roots;
                let kind = ring.state().vars[j].kind.clone();
                !matches!(
                    kind,
                    VarKind::Indeterminate
                        | VarKind::Jet { .. }
                        | VarKind::Opaque { constant: true }
                )
            }
        };
        if depends {
            return Err(AlgebraError::Domain(format!(
                "the side depends on {} otherwise than rationally through the variable and sn, cn, dn",
                ring.inner.names()[idx]
            )));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::prove_by_ode;
    use crate::algebra::parametrization::Parametrization;
    use crate::algebra::{Ring, RingOptions, Sym};

    /// A jet ring with `u` and `k` (values in the Landen domain) and `k' = √(1 − k²)`,
    /// `k₁ = (1 − k')/(1 + k')` (DLMF 22.7.1).
    fn landen() -> (Ring, Sym, Sym, Sym) {
        // the domain 0 < k < 1 as k = t/(1 + t), t > 0, so that k' > 0 is proved
        let mut par = Parametrization::new();
        let t = par.positive("t").unwrap();
        let one = par.constant(&rug::Rational::from(1));
        par.bind("k", t.div(&one.add(&t)).unwrap(), String::new());
        let ring = Ring::new(RingOptions {
            points: 3,
            jets: true,
            max_vars: 32,
            positivity: Some(std::sync::Arc::new(par)),
            ..Default::default()
        });
        let u = ring.indeterminate_f64("u", &[0.3, -1.1, 1.7]).unwrap();
        let k = ring.indeterminate_f64("k", &[0.5, 0.8, 0.2]).unwrap();
        let one = ring.integer(1);
        let kp = (one.clone() - k.clone() * k.clone()).sqrt().unwrap();
        let k1 = (one.clone() - kp.clone()) / (one + kp);
        (ring, u, k, k1)
    }

    /// `(1 + f)·sn(w, k₁)/(1 + k₁ sn²(w, k₁))` with `w = u/(1 + k₁)`: DLMF 22.7.2 for
    /// `f = k₁`.
    fn gauss_rhs(ring: &Ring, u: &Sym, k1: &Sym, factor: &Sym) -> Sym {
        let one = ring.integer(1);
        let w = u.clone() / (one.clone() + k1.clone());
        let (s, _, _) = ring.jet_sncndn(&w, k1).unwrap();
        (one.clone() + factor.clone()) * s.clone() / (one + k1.clone() * s.clone() * s)
    }

    #[test]
    fn gauss_transformation_is_proved() {
        let (ring, u, k, k1) = landen();
        let (lhs, _, _) = ring.jet_sncndn(&u, &k).unwrap();
        let rhs = gauss_rhs(&ring, &u, &k1, &k1);
        let p = prove_by_ode(&u, &lhs, &rhs).unwrap();
        assert_eq!(p.initial, ["0".to_string(), "1".to_string()]);
    }

    #[test]
    fn gauss_with_a_misprinted_factor_is_not_proved() {
        // the factor 1 + k₁ replaced by 1 + k₁²
        let (ring, u, k, k1) = landen();
        let (lhs, _, _) = ring.jet_sncndn(&u, &k).unwrap();
        let rhs = gauss_rhs(&ring, &u, &k1, &(k1.clone() * k1.clone()));
        let e = prove_by_ode(&u, &lhs, &rhs).unwrap_err();
        assert!(e.contains("does not satisfy the ODE"), "{e}");
    }

    #[test]
    fn a_wrong_initial_value_is_rejected() {
        // −sn u solves the ODE of sn u (Φ is odd) but y'(0) = −1, not 1
        let (ring, u, k, _) = landen();
        let (s, c, _) = ring.jet_sncndn(&u, &k).unwrap();
        let e = prove_by_ode(&u, &s, &s.negate()).unwrap_err();
        assert!(e.contains("initial values differ: y'(0)"), "{e}");
        // cn u and −cn u: y(0) = 1 against −1
        let e = prove_by_ode(&u, &c, &c.negate()).unwrap_err();
        assert!(e.contains("initial values differ: y(0)"), "{e}");
    }

    #[test]
    fn a_singular_starting_point_is_rejected() {
        // 1/(k sn u) = sn(u + iK') solves the ODE of sn u (DLMF 22.4.3), with a pole at 0
        let (ring, u, k, _) = landen();
        let (s, _, _) = ring.jet_sncndn(&u, &k).unwrap();
        let ns = ring.integer(1) / (k.clone() * s.clone());
        let e = prove_by_ode(&u, &s, &ns).unwrap_err();
        assert!(e.contains("singular starting point"), "{e}");
    }

    #[test]
    fn a_root_depending_on_the_variable_is_refused() {
        // a side with √(1 + u²): not rational in u, sn, cn, dn (the analyticity of such
        // roots is not checked, so the method refuses them)
        let (ring, u, k, _) = landen();
        let (s, _, _) = ring.jet_sncndn(&u, &k).unwrap();
        let r = (ring.integer(1) + u.clone() * u.clone()).sqrt().unwrap();
        let e = prove_by_ode(&u, &s, &(s.clone() * r)).unwrap_err();
        assert!(e.contains("otherwise than rationally"), "{e}");
    }

    #[test]
    fn an_argument_not_zero_at_the_start_is_refused() {
        let (ring, u, k, _) = landen();
        let (s, _, _) = ring.jet_sncndn(&u, &k).unwrap();
        let (t, _, _) = ring.jet_sncndn(&(u.clone() + ring.integer(1)), &k).unwrap();
        let e = prove_by_ode(&u, &s, &t).unwrap_err();
        assert!(e.contains("is not 0 at 0"), "{e}");
    }
}
