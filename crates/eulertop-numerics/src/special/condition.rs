//! The relative condition number of the twelve Jacobi functions with respect to their
//! argument: how strongly a relative change of `u` moves `pq(u)`, which next to a pole
//! (a zero of the denominator) is what limits any evaluation at a rounded argument.

use super::JacobiFn;
use crate::numbers::Real;

impl JacobiFn {
    /// The relative condition number of this function with respect to `u`,
    /// `κ_u = |u·f′(u)/f(u)|`, from the values `(sn, cn, dn)` at `u` and the parameter
    /// `m = k²` (any real `m`, as [`sncndn_m`](super::sncndn_m) takes it).  For
    /// `f = p/q` it is `|u·(L_p − L_q)|` with the logarithmic derivatives
    /// `L_sn = cn·dn/sn`, `L_cn = −sn·dn/cn`, `L_dn = −m·sn·cn/dn`, `L_1 = 0`
    /// (DLMF 22.13.1–3).
    ///
    /// A relative change `δ` of `u` changes `f(u)` by about `κ_u·δ` relative; as the
    /// argument of a quotient approaches a pole (a zero of `q`), `κ_u` grows like
    /// `|u/(u − u₀)|`.  There even a correctly rounded result at the given `u` is worth
    /// only as much as `u` itself: with `κ_u = 10¹⁰` a change of `u` in its last bit
    /// (`f64`) moves the quotient by about `10¹⁰ ε`.  `eulertop jacobi` warns on
    /// standard error when a quotient is evaluated where `κ_u ≥ 2^⌈N/2⌉` (`N` the
    /// precision in bits), and `reports/accuracy.md` lists the `f64` errors next to
    /// the poles with `κ_u`.  `+∞` at a pole of `f` (and wherever a value is not
    /// finite); at `u = 0` the limit (`1` for the odd functions, `0` for the even
    /// ones).  For `cd` and `dc` it is `|u·sn·(1 − m)/(cn·dn)|` (as `dn² − m·cn² = 1 − m`),
    /// so `0` at `m = 1`.
    ///
    /// ```
    /// use eulertop_numerics::special::{JacobiFn, ellipk, sncndn};
    /// let (k, u) = (0.8_f64, 0.7_f64);
    /// let (s, c, d) = sncndn(&u, &k).unwrap();
    /// let m = k * k;
    /// // sn: |u cn dn / sn|
    /// let kappa = JacobiFn::Sn.condition(&u, &m, (&s, &c, &d));
    /// assert!((kappa - (u * c * d / s).abs()).abs() < 1e-15);
    /// // nc = 1/cn next to its pole at u = K: κ_u ≈ K/|u − K|
    /// let kk = ellipk(&k).unwrap();
    /// let near = kk * (1.0 - 1e-9);
    /// let (s, c, d) = sncndn(&near, &k).unwrap();
    /// let kappa = JacobiFn::Nc.condition(&near, &m, (&s, &c, &d));
    /// assert!((kappa / 1e9 - 1.0).abs() < 1e-3);
    /// // at u = 0: the limits
    /// let zero = (&0.0, &1.0, &1.0);
    /// assert_eq!(JacobiFn::Ns.condition(&0.0, &m, zero), 1.0);
    /// assert_eq!(JacobiFn::Cn.condition(&0.0, &m, zero), 0.0);
    /// // cd = dc = 1 at m = 1, even where cn and dn underflow
    /// let flat = (&1.0, &0.0, &0.0);
    /// assert_eq!(JacobiFn::Cd.condition(&800.0, &1.0, flat), 0.0);
    /// ```
    pub fn condition<R: Real>(self, u: &R, m: &R, (s, c, d): (&R, &R, &R)) -> R {
        // u·L, with u·L_sn = 1 at u = 0 (the one zero of sn a real argument reaches:
        // the limit of u·cn·dn/sn)
        let scaled = |i: Option<usize>| match i {
            Some(0) if s.is_zero() => u.one(),
            Some(0) => u.clone() * c.clone() * d.clone() / s.clone(),
            Some(1) => -(u.clone() * s.clone() * d.clone() / c.clone()),
            Some(2) => -(u.clone() * m.clone() * s.clone() * c.clone() / d.clone()),
            _ => u.zero(),
        };
        let (p, q) = self.parts();
        let kappa = match (p, q) {
            // cd and dc: u·(L_cn − L_dn) = −u·sn·(1 − m)/(cn·dn), as dn² − m·cn² = 1 − m;
            // 0 at m = 1, where cd = dc = 1 even where cn and dn underflow
            (Some(1), Some(2)) | (Some(2), Some(1)) => {
                let gap = u.one() - m.clone();
                if gap.is_zero() {
                    u.zero()
                } else {
                    (u.clone() * s.clone() * gap / (c.clone() * d.clone())).abs()
                }
            }
            _ => (scaled(p) - scaled(q)).abs(),
        };
        if kappa.is_finite() {
            kappa
        } else {
            u.one() / u.zero()
        }
    }
}
