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
}
