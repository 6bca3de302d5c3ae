//! Elliptic coordinates (ell coord), the solution (sol) against (ET), the phase
//! steps (phis) against (master12)/(MV master), and the discrete solution (discr sol).

use eulertop::linalg::Vec3;
use eulertop::model::discretization::step;
use eulertop::model::elliptic_coords::{m_to_phi, phi_to_m};
use eulertop::model::orbit;
use eulertop::model::phase::{delta, step_phases};
use eulertop::model::solution::{continuous_from, discrete_from};
use eulertop::model::{Gamma, Inertia, Regime};
use eulertop::numbers::{Dual, Real};
use proptest::prelude::*;
use rug::Float;

fn inertia_strategy() -> impl Strategy<Value = (f64, f64, f64)> {
    (0.5f64..3.0, 0.1f64..2.0, 0.1f64..2.0).prop_map(|(c, db, da)| (c + db + da, c + db, c))
}

fn point_strategy() -> impl Strategy<Value = (f64, f64, f64)> {
    (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0).prop_filter("away from axes", |(x, y, z)| {
        [x.abs(), y.abs(), z.abs()]
            .iter()
            .filter(|v| **v > 0.1)
            .count()
            >= 2
    })
}

fn setup<R: Real>(like: &R, abc: (f64, f64, f64), m: (f64, f64, f64)) -> (Inertia<R>, Vec3<R>) {
    let i = Inertia::new(
        like.from_f64(abc.0),
        like.from_f64(abc.1),
        like.from_f64(abc.2),
    )
    .expect("A>B>C>0");
    (
        i,
        Vec3::new(like.from_f64(m.0), like.from_f64(m.1), like.from_f64(m.2)),
    )
}

/// Keeps away from the separatrix, where K → ∞ and Φ⁻¹ is ill-conditioned.
fn away_from_separatrix<R: Real>(i: &Inertia<R>, m: &Vec3<R>) -> bool {
    let r = (i.b.clone() * i.energy(m) / i.m2(m)).to_f64();
    (r - 1.0).abs() > 0.05
}

fn check_round_trip<R: Real>(like: &R, abc: (f64, f64, f64), m0: (f64, f64, f64)) {
    let (i, m) = setup(like, abc, m0);
    if !away_from_separatrix(&i, &m) {
        return;
    }
    let c = m_to_phi(&i, &m).expect("phi defined off the axes");
    let back = phi_to_m(&c.params, c.sector, &c.phi).unwrap();
    let tol = like.epsilon().to_f64() * 4096.0;
    assert!((back - m).max_magnitude() <= tol, "round trip");
}

fn check_sol<R: Real>(like: &R, abc: (f64, f64, f64), m0: (f64, f64, f64), t: f64) {
    let (i, m) = setup(like, abc, m0);
    if !away_from_separatrix(&i, &m) {
        return;
    }
    let c = m_to_phi(&i, &m).unwrap();
    let cd = eulertop::model::EllCoords {
        params: c.params.map(|x| Dual::constant(x.clone())),
        sector: c.sector,
        phi: Dual::constant(c.phi.clone()),
    };
    let md = continuous_from(&cd, &Dual::var(like.from_f64(t))).unwrap();
    let mt = Vec3(md.0.clone().map(|x| x.v));
    let deriv = Vec3(md.0.map(|x| x.d));
    let tol = like.epsilon().to_f64() * 4096.0;
    // (sol) satisfies (ET) ...
    assert!((deriv.clone() - i.field_et(&mt)).max_magnitude() <= tol);
    // ... and not the standard-cross reading of (ET v) (the field is nonzero here)
    assert!((deriv - i.field_cross_std(&mt)).max_magnitude() > 1e-6);
}

fn check_phase<R: Real>(like: &R, abc: (f64, f64, f64), m0: (f64, f64, f64), h: f64) {
    let (i, m) = setup(like, abc, m0);
    if !away_from_separatrix(&i, &m) {
        return;
    }
    let h = like.from_f64(h);
    let tol = like.epsilon().to_f64() * 65536.0;
    let c0 = m_to_phi(&i, &m).unwrap();
    for g in [Gamma::G1, Gamma::G2, Gamma::Vm] {
        let d = delta(&i, &c0.params, g, &h).expect("delta solvable for small h");
        // Δφ of actual steps at several φ̄ equals the φ̄-independent δ
        let pts = orbit(&i, g, &m, &h)
            .take(8)
            .collect::<Result<Vec<_>, _>>()
            .unwrap();
        for p in std::iter::once(&m).chain(pts.iter()) {
            let q = step(&i, g, p, &h).unwrap();
            let (_, _, dphi) = step_phases(&i, p, &q).unwrap();
            assert!(
                (dphi - d.clone()).abs().to_f64() <= tol,
                "{g:?}: Δφ depends on φ̄"
            );
        }
        // iterates match (discr sol)
        for (n, p) in pts.iter().enumerate() {
            let ds = discrete_from(&c0, &d, n as i64 + 1).unwrap();
            assert!((ds - p.clone()).max_magnitude() <= tol * (n as f64 + 1.0));
        }
    }
}

fn check_gamma0_not_poisson<R: Real>(like: &R) {
    let (i, m) = setup(like, (3.0, 2.0, 1.0), (0.4, 0.5, 1.1));
    let h = like.from_f64(0.2);
    let pts = orbit(&i, Gamma::G0, &m, &h)
        .take(40)
        .collect::<Result<Vec<_>, _>>()
        .unwrap();
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for w in pts.windows(2) {
        let (_, _, d) = step_phases(&i, &w[0], &w[1]).unwrap();
        lo = lo.min(d.to_f64());
        hi = hi.max(d.to_f64());
    }
    assert!(hi - lo > 1e-8, "gamma0 Δφ spread {}", hi - lo);
    assert!(hi - lo > 1e6 * like.epsilon().to_f64());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]
    #[test]
    fn round_trip_f64(abc in inertia_strategy(), m in point_strategy()) {
        check_round_trip(&1.0f64, abc, m);
    }
    #[test]
    fn sol_satisfies_et_f64(abc in inertia_strategy(), m in point_strategy(), t in -3.0f64..3.0) {
        check_sol(&1.0f64, abc, m, t);
    }
    #[test]
    fn phase_f64(abc in inertia_strategy(), m in point_strategy(), h in 0.01f64..0.1) {
        check_phase(&1.0f64, abc, m, h);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 8, ..ProptestConfig::default() })]
    #[test]
    fn round_trip_256(abc in inertia_strategy(), m in point_strategy()) {
        check_round_trip(&Float::with_val(256, 1), abc, m);
    }
    #[test]
    fn sol_satisfies_et_256(abc in inertia_strategy(), m in point_strategy(), t in -3.0f64..3.0) {
        check_sol(&Float::with_val(256, 1), abc, m, t);
    }
    #[test]
    fn phase_256(abc in inertia_strategy(), m in point_strategy(), h in 0.01f64..0.1) {
        check_phase(&Float::with_val(256, 1), abc, m, h);
    }
}

#[test]
fn gamma0_phase_depends_on_phibar() {
    check_gamma0_not_poisson(&1.0f64);
    check_gamma0_not_poisson(&Float::with_val(256, 1));
}

#[test]
fn separatrix_exact_point() {
    // A=6, B=4, C=3, M=(6,2,6): B·E = 76 = M² exactly.
    let (i, m) = setup(&1.0f64, (6.0, 4.0, 3.0), (6.0, 2.0, 6.0));
    let c = m_to_phi(&i, &m).unwrap();
    assert_eq!(c.params.regime, Regime::Separatrix);
    let back = phi_to_m(&c.params, c.sector, &c.phi).unwrap();
    assert!((back - m.clone()).max_magnitude() < 1e-13);
    // hyperbolic (sol) satisfies (ET)
    let cd = eulertop::model::EllCoords {
        params: c.params.map(|x| Dual::constant(*x)),
        sector: c.sector,
        phi: Dual::constant(c.phi),
    };
    let md = continuous_from(&cd, &Dual::var(0.7)).unwrap();
    let mt = Vec3(md.0.clone().map(|x| x.v));
    let d = Vec3(md.0.map(|x| x.d));
    assert!((d - i.field_et(&mt)).max_magnitude() < 1e-12);
}

#[test]
fn phi_undefined_on_axes() {
    let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
    for m in [
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
        Vec3::new(0.0, 0.0, 1.0),
        Vec3::new(0.0, 0.0, 0.0),
    ] {
        assert!(m_to_phi(&i, &m).is_err());
    }
}

#[test]
fn delta_odd_in_h() {
    let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
    let m = Vec3::new(0.3, -0.7, 1.1);
    let c = m_to_phi(&i, &m).unwrap();
    for g in [Gamma::G1, Gamma::G2, Gamma::Vm] {
        let dp = delta(&i, &c.params, g, &0.1).unwrap();
        let dm = delta(&i, &c.params, g, &-0.1).unwrap();
        assert_eq!(dp, -dm);
        // and the backward step indeed has phase step δ(−h)
        let q = step(&i, g, &m, &-0.1).unwrap();
        let (_, _, d) = step_phases(&i, &m, &q).unwrap();
        assert!((d - dm).abs() < 1e-13);
    }
}

/// Jacobian of Φ (proof of Proposition 3) and the bracket (PB in ell), by AD.
/// Finding: det ∂(M₁,M₂,M₃)/∂(M²,E,φ) = −1/(4ν), independent of φ — the printed
/// value is −dn²φ/(4ν); −1/(4ν) is what (PB in ell) {E,φ} = −2ν implies, since
/// det ∂(M²,E,φ)/∂M = ⟨∇M², ∇E × ∇φ⟩ = 2{E,φ}.
#[test]
fn jacobian_of_phi_and_bracket_e_phi() {
    use eulertop::linalg::Mat3;
    use eulertop::model::EllipticParams;
    let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
    let id = i.to_dual();
    for m in [
        Vec3::new(0.3, -0.7, 1.1),
        Vec3::new(1.1, -0.7, 0.3),
        Vec3::new(-0.5, 0.2, -0.9),
    ] {
        let c = m_to_phi(&i, &m).unwrap();
        let mut jac = Mat3::zeros(&0.0);
        for col in 0..3 {
            let s = |k: usize, v: f64| Dual::new(v, if k == col { 1.0 } else { 0.0 });
            let p = EllipticParams::new(&id, &s(0, c.params.m2), &s(1, c.params.e)).unwrap();
            let x = phi_to_m(&p, c.sector, &s(2, c.phi)).unwrap();
            for r in 0..3 {
                jac.0[r][col] = x.0[r].d;
            }
        }
        let nu = c.params.nu();
        assert!((jac.det() + 1.0 / (4.0 * nu)).abs() < 1e-13);
        let (_, _, dn) = eulertop::special::sncndn(&c.phi, &c.params.k()).unwrap();
        assert!(
            (jac.det() + dn * dn / (4.0 * nu)).abs() > 1e-3,
            "printed dn² factor"
        );
        // {E, φ} = −2ν with φ = Φ⁻¹(M) differentiated by AD
        let b = i.poisson_bracket(
            &m,
            |x: &Vec3<Dual<f64>>| id.energy(x),
            |x: &Vec3<Dual<f64>>| m_to_phi(&id, x).unwrap().phi,
        );
        assert!((b + 2.0 * nu).abs() < 1e-12, "{b} vs {}", -2.0 * nu);
    }
}

/// The residual of the equation that `δ` solves, `sn(1 − α sn²) − (hν/2) cn dn`
/// (master12) or `sn cn dn − (hν/2)(1 + α sn² − β sn⁴)` (MV master), at `d`.
fn phase_residual(
    i: &Inertia<Float>,
    p: &eulertop::model::EllipticParams<Float>,
    g: Gamma,
    h: &Float,
    d: &Float,
) -> Float {
    use eulertop::model::elliptic_coords::sncndn_params;
    use eulertop::model::phase::{master12_equation, mv_master_equation};
    let (s, c, dn) = sncndn_params(d, p).unwrap();
    let hnu2 = h.clone() * p.nu() / 2u32;
    match g {
        Gamma::G1 => master12_equation(&p.alpha1(), &hnu2, &s, &c, &dn),
        Gamma::G2 => master12_equation(&p.alpha2(i), &hnu2, &s, &c, &dn),
        _ => {
            let (a, b) = p.alpha_beta_vm(i).unwrap();
            mv_master_equation(&a, &b, &hnu2, &s, &c, &dn)
        }
    }
}

/// Above `LADDER_BITS` the phase step starts Newton's method at the solution at about
/// half the precision.  At 2048 and 4096 bits `δ` solves its equation to working
/// precision (residual at most `2⁸·2^−bits·|h|`), and it is the root that the plain
/// iteration from `hν/2` finds at `LADDER_BITS` bits: the two agree to
/// `2^(16 − LADDER_BITS)` relative, the accuracy of the lower-precision root up to the
/// conditioning of the equation.
#[test]
fn delta_at_high_precision_solves_its_equation() {
    use eulertop::model::ladder::LADDER_BITS;
    for bits in [2048u32, 4096] {
        let f = |x: f64| Float::with_val(bits, x);
        let i = Inertia::new(f(3.0), f(2.0), f(1.0)).unwrap();
        let m = Vec3::new(f(0.3), f(-0.7), f(1.1));
        let c = m_to_phi(&i, &m).unwrap();
        let lo = |x: &Float| Float::with_val(LADDER_BITS, x);
        let (i_lo, p_lo) = (i.map(lo), c.params.map(lo));
        for g in [Gamma::G1, Gamma::G2, Gamma::Vm] {
            for h in [f(0.1), f(-0.3), f(0.01)] {
                let d = delta(&i, &c.params, g, &h).unwrap();
                let r = phase_residual(&i, &c.params, g, &h, &d);
                let tol = Float::with_val(bits, Float::u_exp(1, 8 - bits as i32)) * h.clone().abs();
                assert!(
                    r.clone().abs() <= tol,
                    "{g:?} h = {h:.5} at {bits} bits: residual {r:.5e}"
                );
                let plain = delta(&i_lo, &p_lo, g, &lo(&h)).unwrap();
                let rel = (lo(&d) - plain.clone()).abs() / plain.clone().abs();
                let bound = Float::with_val(LADDER_BITS, Float::u_exp(1, 16 - LADDER_BITS as i32));
                assert!(
                    rel <= bound,
                    "{g:?} h = {h:.5}: {bits} bits against {LADDER_BITS}: relative difference {rel:.3e}"
                );
            }
        }
    }
}
