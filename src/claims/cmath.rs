//! Complex arithmetic of the language on [`Cplx<T>`] over any backend: the operations
//! that may fail (division by an exact zero, functions the backend cannot compute) return
//! a one-line error instead of NaN.  Each formula is the textbook one, written once.

use super::backend::{Constant, Num, RealFn, RealFn2};
use crate::numbers::Cplx;

/// `re + 0i`.
pub fn real<T: Num>(re: T) -> Cplx<T> {
    let im = re.zero();
    Cplx::new(re, im)
}

/// The imaginary unit with the precision of `like`.
pub fn i<T: Num>(like: &T) -> Cplx<T> {
    Cplx::new(like.zero(), like.one())
}

/// The complex conjugate.
pub fn conj<T: Num>(z: &Cplx<T>) -> Cplx<T> {
    Cplx::new(z.re.clone(), -z.im.clone())
}

/// `s · z` for a real `s`, componentwise.
pub fn scale<T: Num>(z: &Cplx<T>, s: &T) -> Cplx<T> {
    Cplx::new(z.re.clone() * s.clone(), z.im.clone() * s.clone())
}

/// `z / w = z·w̄ / |w|²`; an error when `w` is exactly zero.
pub fn div<T: Num>(z: &Cplx<T>, w: &Cplx<T>) -> Result<Cplx<T>, String> {
    let den = w.re.clone() * w.re.clone() + w.im.clone() * w.im.clone();
    if den.is_zero() {
        return Err("division by zero".into());
    }
    let n = z.clone() * conj(w);
    Ok(Cplx::new(n.re / den.clone(), n.im / den))
}

/// `hypot(|re|, |im|)` in `f64`: the size of `z` for residuals.
pub fn magnitude<T: Num>(z: &Cplx<T>) -> f64 {
    z.re.magnitude().hypot(z.im.magnitude())
}

/// The modulus `√(re² + im²)`.
pub fn abs<T: Num>(z: &Cplx<T>) -> Result<T, String> {
    (z.re.clone() * z.re.clone() + z.im.clone() * z.im.clone()).real_fn(RealFn::Sqrt)
}

/// The argument in (−π, π].
pub fn arg<T: Num>(z: &Cplx<T>) -> Result<T, String> {
    z.im.real_fn2(RealFn2::Atan2, &z.re)
}

/// The principal square root, without cancellation: `t = √((|z| + |re|)/2)`.
pub fn sqrt<T: Num>(z: &Cplx<T>) -> Result<Cplx<T>, String> {
    let r = abs(z)?;
    if r.is_zero() {
        return Ok(z.clone());
    }
    let two = r.from_i64(2);
    let t = ((r + z.re.real_fn(RealFn::Abs)?) / two.clone()).real_fn(RealFn::Sqrt)?;
    if z.re >= z.re.zero() {
        let im = z.im.clone() / (t.clone() * two);
        Ok(Cplx::new(t, im))
    } else {
        let re = z.im.real_fn(RealFn::Abs)? / (t.clone() * two);
        let im = if z.im < z.im.zero() { -t } else { t };
        Ok(Cplx::new(re, im))
    }
}

/// `e^z = e^re (cos im + i sin im)`.
pub fn exp<T: Num>(z: &Cplx<T>) -> Result<Cplx<T>, String> {
    let e = z.re.real_fn(RealFn::Exp)?;
    Ok(Cplx::new(
        e.clone() * z.im.real_fn(RealFn::Cos)?,
        e * z.im.real_fn(RealFn::Sin)?,
    ))
}

/// The principal logarithm `ln|z| + i arg z`.
pub fn ln<T: Num>(z: &Cplx<T>) -> Result<Cplx<T>, String> {
    Ok(Cplx::new(abs(z)?.real_fn(RealFn::Ln)?, arg(z)?))
}

/// π with the precision of `like` (an error in backends without π).
pub fn pi<T: Num>(like: &T) -> Result<T, String> {
    like.constant(Constant::Pi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn principal_branches() {
        let z = Cplx::new(-4.0f64, 0.0);
        assert_eq!(sqrt(&z).unwrap(), Cplx::new(0.0, 2.0));
        let w = ln(&Cplx::new(-1.0f64, 0.0)).unwrap();
        assert_eq!((w.re, w.im), (0.0, std::f64::consts::PI));
        assert!(div(&z, &Cplx::new(0.0, 0.0)).is_err());
        // (1 + 2i)/(3 − 4i) = (−5 + 10i)/25
        let q = div(&Cplx::new(1.0f64, 2.0), &Cplx::new(3.0, -4.0)).unwrap();
        assert_eq!((q.re, q.im), (-0.2, 0.4));
    }
}
