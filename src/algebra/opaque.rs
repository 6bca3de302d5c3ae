//! Functions the prover cannot expand (`asin`, the elliptic integral `F`): each distinct
//! call becomes one opaque symbol, carrying the function's numeric values at the domain
//! points.  An identity proved with the symbol free holds for every value of it, the
//! actual one included; the same call made twice gives the same symbol.

use super::error::{AlgResult, AlgebraError};
use super::sym::Sym;
use rug::Complex;

impl Sym {
    /// The opaque value `f(args)`: `values` computes the function at each domain point
    /// from the arguments' values there.
    pub fn opaque_call(
        f: &str,
        args: &[&Sym],
        values: impl Fn(&[Complex]) -> Option<Complex>,
    ) -> AlgResult<Sym> {
        let ring = args
            .first()
            .map(|a| a.ring.clone())
            .ok_or_else(|| AlgebraError::Internal("an opaque call without arguments".into()))?;
        let key = format!(
            "{f}({})",
            args.iter()
                .map(|a| a.render())
                .collect::<Vec<_>>()
                .join(", ")
        );
        let known = ring.state().opaque_calls.get(&key).cloned();
        if let Some(v) = known {
            return Ok(Sym::restored(&ring, v));
        }
        let mut shadow = Vec::new();
        for p in 0..ring.points() {
            let at: Vec<Complex> = args.iter().map(|a| a.val.sh.v[p].clone()).collect();
            let v = values(&at).ok_or_else(|| {
                AlgebraError::NotAlgebraic(format!("{f} is undefined at domain point {}", p + 1))
            })?;
            shadow.push(v);
        }
        let n = ring.state().opaque_calls.len() + 1;
        let s = ring.opaque(&format!("{f}{n}"), &shadow, false)?;
        ring.state().opaque_calls.insert(key, s.stored());
        if let Some(j) = s.as_field_var() {
            let vals = args.iter().map(|a| a.stored()).collect();
            ring.state().opaque_args.insert(j, (f.to_string(), vals));
        }
        ring.note(format!(
            "{f}{n} stands for {f}(…), which the prover does not expand"
        ));
        Ok(s)
    }
}

impl Sym {
    /// If `self` is the opaque symbol of a call of `f`, that call's arguments.
    pub(crate) fn opaque_call_args(&self, f: &str) -> Option<Vec<Sym>> {
        let j = self.as_field_var()?;
        let (g, vals) = self.ring.state().opaque_args.get(&j).cloned()?;
        (g == f).then(|| {
            vals.into_iter()
                .map(|v| Sym::restored(&self.ring, v))
                .collect()
        })
    }

    /// `am(u, k)` by rule: `u` itself at `k = 0` (DLMF 22.16.4), else an opaque symbol
    /// whose derivative in `u` is `dn(u, k)` (DLMF 22.16.3; module `derive`).
    pub(crate) fn am_rule(u: &Sym, k: &Sym) -> AlgResult<Sym> {
        if k.is_exact_zero() {
            u.ring.note("am(u, 0) = u (DLMF 22.16.4)".into());
            return Ok(u.clone());
        }
        Sym::opaque_call("am", &[u, k], |z| {
            let real = |c: &Complex| c.imag().is_zero().then(|| c.real().clone());
            let a = crate::special::am(&real(&z[0])?, &real(&z[1])?).ok()?;
            Some(Complex::with_val(a.prec(), (a, 0)))
        })
    }

    /// `F(φ, k)` by rule: an opaque symbol `v`; when `φ = asin x`, `v` has `sn v = x`,
    /// `cn v = √(1 − x²)`, `dn v = √(1 − k²x²)` (am v = φ ∈ [−π/2, π/2], DLMF 22.16.1 and
    /// 22.16.11), which the elliptic expansions use.
    pub(crate) fn ellipf_rule(phi: &Sym, k: &Sym) -> AlgResult<Sym> {
        let v = Sym::opaque_call("F", &[phi, k], |z| {
            let real = |c: &Complex| c.imag().is_zero().then(|| c.real().clone());
            let f = crate::special::ellipf(&real(&z[0])?, &real(&z[1])?).ok()?;
            Some(Complex::with_val(f.prec(), (f, 0)))
        })?;
        if let Some(x) = phi
            .opaque_call_args("asin")
            .and_then(|a| a.into_iter().next())
        {
            let one = phi.ring.integer(1);
            let c = one.try_sub(&x.try_mul(&x)?)?.sqrt()?;
            let d = one
                .try_sub(&k.try_mul(k)?.try_mul(&x)?.try_mul(&x)?)?
                .sqrt()?;
            phi.ring.prescribe_sncndn(
                &v,
                k,
                &x,
                &c,
                &d,
                "F(asin x, k) has amplitude asin x, so sn = x, cn = sqrt(1 - x^2), dn = sqrt(1 - k^2 x^2) (DLMF 22.16.1, 22.16.11)",
            )?;
        }
        Ok(v)
    }

    /// The inverse of the Jacobi functions by rule: `φ` with `sn φ = s`, `cn φ = c`,
    /// `dn φ = d` at modulus `k` is an opaque symbol whose sn, cn, dn are prescribed as
    /// these values, so that the elliptic expansions of `sn(φ ± …)` use them and its
    /// derivative is `s'/(c d)`.  The values must satisfy `s² + c² = 1` and
    /// `d² + k² s² = 1` identically, and `d > 0` on the domain (dn of a real argument
    /// with `k < 1`); otherwise the rule does not apply.  Any `φ + 4nK` has the same
    /// values, so an identity proved with the symbol holds for the argument the
    /// numerical inverse selects (in (−2K, 2K]).
    pub(crate) fn jacobi_inverse_rule(s: &Sym, c: &Sym, d: &Sym, k: &Sym) -> AlgResult<Sym> {
        let ring = &s.ring;
        let one = ring.integer(1);
        let r1 = s.try_mul(s)?.try_add(&c.try_mul(c)?)?.try_sub(&one)?;
        let r2 = d
            .try_mul(d)?
            .try_add(&k.try_mul(k)?.try_mul(s)?.try_mul(s)?)?
            .try_sub(&one)?;
        if !r1.is_exact_zero() || !r2.is_exact_zero() {
            return Err(AlgebraError::NotAlgebraic(
                "the inverse of sn, cn, dn: the values are not identically sn, cn, dn of one argument".into(),
            ));
        }
        if d.sign()? <= 0 {
            return Err(AlgebraError::NotAlgebraic(
                "the inverse of sn, cn, dn: dn is not positive on the domain".into(),
            ));
        }
        let v = Sym::opaque_call("phiinv", &[s, c, d, k], |z| {
            let real = |c: &Complex| c.real().clone();
            let u = crate::special::jacobi_inverse(
                &real(&z[0]),
                &real(&z[1]),
                &real(&z[2]),
                &real(&z[3]),
            )
            .ok()?;
            Some(Complex::with_val(u.prec(), (u, 0)))
        })?;
        let var = v
            .as_field_var()
            .ok_or_else(|| AlgebraError::Internal("an opaque value that is not a symbol".into()))?;
        if !ring.state().prescribed.iter().any(|p| p.var == var) {
            let equivalent = ring.seen_argument_with(k, s, c, d)?;
            ring.prescribe_sncndn(
                &v,
                k,
                s,
                c,
                d,
                "the inverse of sn, cn, dn has the given values as its sn, cn, dn (DLMF 22.15.11-12); they satisfy sn^2 + cn^2 = 1 and dn^2 + k^2 sn^2 = 1 identically, and dn > 0",
            )?;

            match equivalent {
                Some((u, None)) => {
                    ring.set_equivalent(&v, &u, None);
                    ring.note(format!(
                        "{} has the sn, cn, dn of {}: inside sn, cn, dn (period 4K) it is replaced by that argument",
                        v.render_short(40),
                        u.render_short(80)
                    ));
                }
                Some((u, Some(sigma))) => {
                    ring.set_equivalent(&v, &u, Some(&sigma));
                    ring.note(format!(
                        "{} has sn, cn = {} times those of {}, and its dn: it is that argument plus (1 - {})K, so inside sn, cn, dn (period 4K) an integer multiple q of it is replaced by q times the argument, with sn and cn multiplied by ({})^q",
                        v.render_short(40),
                        sigma.render_short(20),
                        u.render_short(80),
                        sigma.render_short(20),
                        sigma.render_short(20)
                    ));
                }
                None => {}
            }
        }
        Ok(v)
    }
}
