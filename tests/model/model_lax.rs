//! The su(2) Lax representation with the corrected `(ρ, u₀)`: the discrete Lax
//! equation (2x2 dLax) `𝒱(u)M̂(u) = M(u)𝒱(u)` holds for the implicit maps
//! (impl spec 1–3) with `V = ½γΩ^{1/2}(M+M̂)` (dgET aux), and the continuous one
//! (2x2 Lax) `Ṁ(u) = [M(u), V(u)]` for (ET) with `V = Ω^{1/2}(M)`.

use eulertop::linalg::Vec3;
use eulertop::model::discretization::step;
use eulertop::model::lax::{lax_dv, lax_m, lax_v, omega_half, rho2_kappa2, u0_corrected};
use eulertop::model::{Gamma, Inertia};
use eulertop::numbers::{Cplx, Real};
use proptest::prelude::*;
use rug::Float;

fn check<R: Real>(like: &R, abc: (f64, f64, f64), m0: (f64, f64, f64), h: f64, u: (f64, f64)) {
    let i = Inertia::new(
        like.from_f64(abc.0),
        like.from_f64(abc.1),
        like.from_f64(abc.2),
    )
    .unwrap();
    let m = Vec3::new(
        like.from_f64(m0.0),
        like.from_f64(m0.1),
        like.from_f64(m0.2),
    );
    let h = like.from_f64(h);
    let kappa = rho2_kappa2(&i).1.sqrt();
    let (rho, u0) = u0_corrected(&i).unwrap();
    let u = Cplx::new(like.from_f64(u.0), like.from_f64(u.1));
    let tol = like.epsilon().to_f64() * 1e4;
    for g in [Gamma::G0, Gamma::G1, Gamma::G2, Gamma::Vm] {
        let mh = step(&i, g, &m, &h).unwrap();
        let gam = g.eval(&i, &m, &mh, &h).unwrap();
        let v = omega_half(&i, &(m.clone() + mh.clone())).scale(&(gam / like.from_i64(2)));
        let mu = lax_m(&m, &u, &rho, &kappa).unwrap();
        let mhu = lax_m(&mh, &u, &rho, &kappa).unwrap();
        let dv = lax_dv(&v, &u, &u0, &h, &rho, &kappa).unwrap();
        let scale = 1.0 + mu.max_magnitude() * dv.max_magnitude();
        let r = dv.clone() * mhu - mu * dv;
        assert!(
            r.max_magnitude() <= tol * scale,
            "{g:?}: {:e}",
            r.max_magnitude()
        );
    }
    // continuous: d/dt M(u) = [M(u), V(u)] with Ṁ from (ET), V = Ω^{1/2}(M)
    let md = lax_m(&i.field_et(&m), &u, &rho, &kappa).unwrap();
    let mu = lax_m(&m, &u, &rho, &kappa).unwrap();
    let vu = lax_v(&omega_half(&i, &m), &u, &u0, &rho, &kappa).unwrap();
    let r = md - mu.commutator(&vu);
    assert!(r.max_magnitude() <= tol * (1.0 + mu.max_magnitude() * vu.max_magnitude()));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]
    #[test]
    fn lax_f64(c in 0.5f64..2.0, db in 0.1f64..2.0, da in 0.1f64..2.0,
               m in (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0),
               h in 0.01f64..0.1, u in (0.1f64..0.6, 0.05f64..0.3)) {
        prop_assume!(m.0.abs() + m.1.abs() + m.2.abs() > 0.3);
        check(&1.0f64, (c + db + da, c + db, c), m, h, u);
    }
}

#[test]
fn lax_256_bits() {
    check(
        &Float::with_val(256, 1),
        (3.0, 2.0, 1.0),
        (0.3, -0.7, 1.1),
        0.05,
        (0.37, 0.21),
    );
}
