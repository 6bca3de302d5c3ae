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
        if let Some(v) = ring.state().opaque_calls.get(&key) {
            return Ok(Sym::from_val(&ring, v.clone(), None));
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
        ring.state().opaque_calls.insert(key, s.val.clone());
        ring.note(format!(
            "{f}{n} stands for {f}(…), which the prover does not expand"
        ));
        Ok(s)
    }
}
