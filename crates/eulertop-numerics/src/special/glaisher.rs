//! The twelve Jacobi elliptic functions `pq` in Glaisher's notation (DLMF 22.2.10):
//! `pq = pr/qr` for `p, q ∈ {s, c, d, n}`, `p ≠ q`, with `sn, cn, dn` and `nn = 1`.

use super::complex::sncndn_complex;
use super::jacobi::sncndn_imp;
use super::modulus::{Modulus, Spec};
use super::{SpecialError, check_finite, show};
use crate::numbers::{ComplexScalar, Real, Scalar};

/// One of the twelve Jacobi elliptic functions (DLMF 22.2.4–9): `sn cn dn cd dc ns nc
/// nd sc sd cs ds`, each the quotient `p/q` of two of `sn`, `cn`, `dn` and `1`.
///
/// ```
/// use eulertop_numerics::special::JacobiFn;
/// assert_eq!(JacobiFn::ALL.len(), 12);
/// assert_eq!(JacobiFn::from_name("cd"), Some(JacobiFn::Cd));
/// assert_eq!(JacobiFn::Cd.name(), "cd");
/// assert_eq!(JacobiFn::from_name("xy"), None);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum JacobiFn {
    /// `sn`.
    Sn,
    /// `cn`.
    Cn,
    /// `dn`.
    Dn,
    /// `cd = cn/dn`.
    Cd,
    /// `dc = dn/cn`.
    Dc,
    /// `ns = 1/sn`.
    Ns,
    /// `nc = 1/cn`.
    Nc,
    /// `nd = 1/dn`.
    Nd,
    /// `sc = sn/cn`.
    Sc,
    /// `sd = sn/dn`.
    Sd,
    /// `cs = cn/sn`.
    Cs,
    /// `ds = dn/sn`.
    Ds,
}

/// One of the letters `s, c, d, n`: which of `sn, cn, dn, 1`.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Letter {
    S,
    C,
    D,
    N,
}

impl JacobiFn {
    /// All twelve, in the order `sn cn dn cd dc ns nc nd sc sd cs ds`.
    pub const ALL: [JacobiFn; 12] = [
        JacobiFn::Sn,
        JacobiFn::Cn,
        JacobiFn::Dn,
        JacobiFn::Cd,
        JacobiFn::Dc,
        JacobiFn::Ns,
        JacobiFn::Nc,
        JacobiFn::Nd,
        JacobiFn::Sc,
        JacobiFn::Sd,
        JacobiFn::Cs,
        JacobiFn::Ds,
    ];

    /// The two-letter name (`"sn"`, …).
    pub fn name(self) -> &'static str {
        const NAMES: [&str; 12] = [
            "sn", "cn", "dn", "cd", "dc", "ns", "nc", "nd", "sc", "sd", "cs", "ds",
        ];
        NAMES[self as usize]
    }

    /// The function called `name`, if any.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|f| f.name() == name)
    }

    /// Where `p` and `q` of `pq = p/q` sit in `(sn, cn, dn)`: `None` for `n`, i.e. `1`.
    ///
    /// ```
    /// use eulertop_numerics::special::JacobiFn;
    /// assert_eq!(JacobiFn::Cd.parts(), (Some(1), Some(2))); // cd = cn/dn
    /// assert_eq!(JacobiFn::Ns.parts(), (None, Some(0))); // ns = 1/sn
    /// assert_eq!(JacobiFn::Dn.parts(), (Some(2), None));
    /// ```
    pub fn parts(self) -> (Option<usize>, Option<usize>) {
        let (p, q) = self.letters();
        let at = |l: Letter| (l != Letter::N).then_some(l as usize);
        (at(p), at(q))
    }

    /// Numerator and denominator letters.
    fn letters(self) -> (Letter, Letter) {
        use Letter::*;
        match self {
            JacobiFn::Sn => (S, N),
            JacobiFn::Cn => (C, N),
            JacobiFn::Dn => (D, N),
            JacobiFn::Cd => (C, D),
            JacobiFn::Dc => (D, C),
            JacobiFn::Ns => (N, S),
            JacobiFn::Nc => (N, C),
            JacobiFn::Nd => (N, D),
            JacobiFn::Sc => (S, C),
            JacobiFn::Sd => (S, D),
            JacobiFn::Cs => (C, S),
            JacobiFn::Ds => (D, S),
        }
    }
}

/// `p/q` from `(sn, cn, dn)`; `Err` with a pole or overflow message.
fn quotient<T: crate::numbers::Scalar>(
    f: JacobiFn,
    (s, c, d): (T, T, T),
    finite: impl Fn(&T) -> bool,
    at: impl Fn() -> String,
) -> Result<T, SpecialError> {
    let pick = |l: Letter| match l {
        Letter::S => s.clone(),
        Letter::C => c.clone(),
        Letter::D => d.clone(),
        Letter::N => s.one(),
    };
    let (p, q) = f.letters();
    let (num, den) = (pick(p), pick(q));
    if q == Letter::N {
        return Ok(num);
    }
    // sn vanishes only at its zeros 2jK (+ 2liK'), of which only 0 is representable; a
    // zero cn or dn is an underflow (e.g. sech u at k = 1), so the quotient overflows
    if den.is_zero() && q == Letter::S {
        return Err(SpecialError::Pole(format!(
            "{} has a pole at {} ({} = 0)",
            f.name(),
            at(),
            ["sn", "cn", "dn", "1"][q as usize]
        )));
    }
    let v = num / den.clone();
    if den.is_zero() || !finite(&v) {
        return Err(SpecialError::NotFinite(format!(
            "{} overflows at {}",
            f.name(),
            at()
        )));
    }
    Ok(v)
}

/// The Jacobi elliptic function `f` (any of the twelve, [`JacobiFn`]) of a real argument
/// `u`, modulus `k ≥ 0` (as [`sncndn`](super::sncndn); DLMF 22.2), as the quotient of
/// two of `sn, cn, dn` at the working precision (one rounding at the end).
///
/// Errors: as [`sncndn`](super::sncndn); [`SpecialError::Pole`] where the denominator
/// vanishes (e.g. `ns(0)`), [`SpecialError::NotFinite`] where the quotient overflows
/// (e.g. `nc` at `k = 1` for `|u| > 710` in `f64`, where `sech u` underflows).
///
/// ```
/// use eulertop_numerics::special::{jacobi, sncndn, JacobiFn};
/// let (s, c, d) = sncndn(&0.7_f64, &0.5).unwrap();
/// assert!((jacobi(JacobiFn::Sd, &0.7_f64, &0.5).unwrap() - s / d).abs() < 1e-15);
/// assert!(jacobi(JacobiFn::Ns, &0.0_f64, &0.5).is_err()); // pole
/// ```
pub fn jacobi<R: Real>(f: JacobiFn, u: &R, k: &R) -> Result<R, SpecialError> {
    Ok(jacobi_set(&[f], u, k)?.remove(0))
}

/// Several of the twelve Jacobi functions at one `(u, k)`, from one evaluation of
/// `sn, cn, dn` (the quotients cost one division each): the values of [`jacobi`] for
/// each of `fs`, in order.  The first error (pole, overflow) of any of them is returned.
///
/// ```
/// use eulertop_numerics::special::{jacobi, jacobi_set, JacobiFn};
/// let fs = [JacobiFn::Sn, JacobiFn::Cd, JacobiFn::Ds];
/// let v = jacobi_set(&fs, &0.7_f64, &0.5).unwrap();
/// for (f, x) in fs.iter().zip(&v) {
///     assert_eq!(*x, jacobi(*f, &0.7_f64, &0.5).unwrap());
/// }
/// ```
pub fn jacobi_set<R: Real>(fs: &[JacobiFn], u: &R, k: &R) -> Result<Vec<R>, SpecialError> {
    let k = &super::even_modulus(k)?;
    check_finite(u, "u")?;
    real(fs, u, Spec::Modulus(k, Modulus::K), k.prec())
}

/// [`jacobi`] for the parameter `m = k²`, any real `m` (as [`sncndn_m`](super::sncndn_m)).
///
/// ```
/// use eulertop_numerics::special::{jacobi_m, JacobiFn};
/// // mpmath: ellipfun('cd', 0.7, m=-0.5) = 0.67688118364789303415
/// let cd = jacobi_m(JacobiFn::Cd, &0.7_f64, &-0.5).unwrap();
/// assert!((cd - 0.676881183647893).abs() < 1e-15);
/// ```
pub fn jacobi_m<R: Real>(f: JacobiFn, u: &R, m: &R) -> Result<R, SpecialError> {
    Ok(jacobi_m_set(&[f], u, m)?.remove(0))
}

/// [`jacobi_set`] for the parameter `m = k²`, any real `m` (as [`jacobi_m`]).
///
/// ```
/// use eulertop_numerics::special::{jacobi_m, jacobi_m_set, JacobiFn};
/// let v = jacobi_m_set(&[JacobiFn::Cd, JacobiFn::Nc], &0.7_f64, &-0.5).unwrap();
/// assert_eq!(v[0], jacobi_m(JacobiFn::Cd, &0.7_f64, &-0.5).unwrap());
/// assert_eq!(v[1], jacobi_m(JacobiFn::Nc, &0.7_f64, &-0.5).unwrap());
/// ```
pub fn jacobi_m_set<R: Real>(fs: &[JacobiFn], u: &R, m: &R) -> Result<Vec<R>, SpecialError> {
    if !m.is_finite() {
        return Err(SpecialError::ModulusOutOfRange(format!(
            "parameter m = {} is not finite",
            show(m)
        )));
    }
    check_finite(u, "u")?;
    real(fs, u, Spec::Parameter(m), m.prec())
}

/// `f(u)` for each `f` of `fs`, the modulus `spec` given at `prec` bits: one
/// evaluation of `sn, cn, dn`.
fn real<R: Real>(
    fs: &[JacobiFn],
    u: &R,
    spec: Spec<'_, R>,
    prec: u32,
) -> Result<Vec<R>, SpecialError> {
    let n = u.prec().max(prec);
    // at k = 1 (m = 1) cn = dn = sech u: cd = dc = 1 exactly, also where sech u
    // underflows
    let unit = match spec {
        Spec::Modulus(k, super::modulus::Modulus::K) => *k == k.one(),
        Spec::Parameter(m) => *m == m.one(),
        Spec::Modulus(..) => false,
    };
    let is_unit = |f: &JacobiFn| unit && matches!(f, JacobiFn::Cd | JacobiFn::Dc);
    if fs.iter().all(is_unit) {
        return Ok(fs.iter().map(|_| u.one().with_prec(n)).collect());
    }
    let values = sncndn_imp(u, spec, n).map_err(|e| match e {
        // the reduction names the argument after the modulus transformation (k·u for
        // k > 1, DLMF 22.17): the message names the given one too
        SpecialError::ArgumentTooLarge(m) => {
            let given = format!("u = {}", show(u));
            if m.contains(&format!("({given})")) {
                SpecialError::ArgumentTooLarge(m)
            } else {
                let m = m.replace(
                    "(u = ",
                    "(the argument after the transformation of the modulus to [0, 1] is ",
                );
                SpecialError::ArgumentTooLarge(format!("{m} at the given {given}"))
            }
        }
        e => e,
    })?;
    let at = || format!("u = {}", show(u));
    fs.iter()
        .map(|f| {
            if is_unit(f) {
                return Ok(u.one().with_prec(n));
            }
            quotient(*f, values.clone(), |v: &R| v.is_finite(), at).map(|v| v.with_prec(n))
        })
        .collect()
}

/// [`jacobi`] of a complex argument, real modulus `k ≥ 0` (from
/// [`sncndn_complex`]).
///
/// ```
/// use eulertop_numerics::numbers::C64;
/// use eulertop_numerics::special::{jacobi_complex, sncndn_complex, JacobiFn};
/// let z = C64::new(0.5, 0.25);
/// let (s, c, _) = sncndn_complex(&z, &0.5).unwrap();
/// let sc = jacobi_complex(JacobiFn::Sc, &z, &0.5).unwrap();
/// let want = s / c;
/// assert!((sc.re - want.re).abs() < 1e-15 && (sc.im - want.im).abs() < 1e-15);
/// ```
pub fn jacobi_complex<C: ComplexScalar>(f: JacobiFn, u: &C, k: &C::R) -> Result<C, SpecialError> {
    Ok(jacobi_complex_set(&[f], u, k)?.remove(0))
}

/// [`jacobi_set`] of a complex argument (as [`jacobi_complex`]): one evaluation of
/// `sn, cn, dn`.
///
/// ```
/// use eulertop_numerics::numbers::C64;
/// use eulertop_numerics::special::{jacobi_complex, jacobi_complex_set, JacobiFn};
/// let z = C64::new(0.5, 0.25);
/// let v = jacobi_complex_set(&[JacobiFn::Sc, JacobiFn::Dn], &z, &0.5).unwrap();
/// assert_eq!(v[0], jacobi_complex(JacobiFn::Sc, &z, &0.5).unwrap());
/// ```
pub fn jacobi_complex_set<C: ComplexScalar>(
    fs: &[JacobiFn],
    u: &C,
    k: &C::R,
) -> Result<Vec<C>, SpecialError> {
    complex_quotients(fs, u, k, sncndn_complex(u, k)?)
}

/// [`jacobi_complex_set`] for the parameter `m = k²`, any real `m` (from
/// [`sncndn_complex_m`](super::sncndn_complex_m)).
///
/// ```
/// use eulertop_numerics::numbers::C64;
/// use eulertop_numerics::special::{jacobi_complex_m_set, sncndn_complex_m, JacobiFn};
/// let z = C64::new(0.5, 0.25);
/// let (s, _, d) = sncndn_complex_m(&z, &-0.5).unwrap();
/// let v = jacobi_complex_m_set(&[JacobiFn::Sd], &z, &-0.5).unwrap();
/// assert_eq!(v[0], s / d);
/// ```
pub fn jacobi_complex_m_set<C: ComplexScalar>(
    fs: &[JacobiFn],
    u: &C,
    m: &C::R,
) -> Result<Vec<C>, SpecialError> {
    complex_quotients(fs, u, m, super::sncndn_complex_m(u, m)?)
}

/// The functions `fs` from `(sn, cn, dn)` of the complex `u` (`k`: the modulus or
/// parameter, for messages).
fn complex_quotients<C: ComplexScalar>(
    fs: &[JacobiFn],
    u: &C,
    k: &C::R,
    values: (C, C, C),
) -> Result<Vec<C>, SpecialError> {
    let at = || {
        format!(
            "u = {} + {}i, k = {}",
            show(&u.re()),
            show(&u.im()),
            show(k)
        )
    };
    let finite = |v: &C| v.re().is_finite() && v.im().is_finite();
    fs.iter()
        .map(|f| quotient(*f, values.clone(), finite, at))
        .collect()
}
