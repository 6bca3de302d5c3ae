//! The slowest symbolic proofs of the catalogue, whole: sampling the domain points,
//! parametrizing the implicit maps, evaluating both sides, restarts, and the zero test.
//!
//! The slowest proofs of orders by exact power series, likewise.
//!
//! `cargo bench --bench proofs`

/// The allocator of the `eulertop` binary, so that the timings are the product's.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use criterion::{Criterion, criterion_group};
use eulertop::bindings::euler_top::registry;
use eulertop::claims::catalogue::{Body, Catalogue, load_dir};
use eulertop::claims::verdict::context::Ctx;
use eulertop::claims::verdict::independence::derivative_sides;
use eulertop::claims::verdict::symbolic::{Order, prove, prove_order};

/// The three claims whose proofs took longest in `verify --format json` (`proof.ms`):
/// two phase-shift independence claims (d(sn(φ̂ − φ), φ) = 0, through a lemma and the
/// inverse of sn, cn, dn) and the Veselov–Moser phase step.  The lemma a claim rests on
/// is proved once per catalogue, so after the first iteration the figures are the
/// claims' own proofs.
const SLOWEST: [&str; 3] = [
    "sec4.prop3.poisson-shift.vm.lo",
    "sec7.prop6.g1-poisson.lo",
    "sec8.MV-master.step.up",
];

fn catalogue() -> Catalogue {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/identities"));
    load_dir(dir, registry().expect("registry")).expect("catalogue loads")
}

fn proofs(c: &mut Criterion) {
    let cat = catalogue();
    let mut g = c.benchmark_group("catalogue proofs");
    g.sample_size(10);
    for id in SLOWEST {
        let claim = cat.claims.iter().find(|c| c.id == id).expect("claim");
        let (lhs, rhs) = match &claim.body {
            Body::Identity { lhs, rhs } => (lhs.clone(), rhs.clone()),
            Body::Independence { expr, wrt, .. } => derivative_sides(expr, wrt),
            _ => panic!("{id} is neither an identity nor an independence claim"),
        };
        g.bench_function(id, |b| {
            b.iter(|| {
                let p = prove(Ctx { cat: &cat, claim }, &lhs, &rhs, false);
                assert!(p.is_proved(), "{id}: {:?}", p.reason);
            })
        });
    }
    g.finish();
}

/// The three slowest proofs of orders by exact power series (`proof.ms` of
/// `verify --format json`, method `series`): the finite-time approximation through the
/// phase step's series, and the determinant of (impl spec)'s Jacobian with γ₂.
const SLOWEST_SERIES: [&str; 3] = [
    "sec3.approx-finite-time.up",
    "sec3.approx-finite-time.lo",
    "sec3.impl-map.det.g2",
];

fn series_proofs(c: &mut Criterion) {
    let cat = catalogue();
    let mut g = c.benchmark_group("power-series proofs");
    g.sample_size(10);
    for id in SLOWEST_SERIES {
        let claim = cat.claims.iter().find(|c| c.id == id).expect("claim");
        let Body::Asymptotic {
            expr, var, order, ..
        } = &claim.body
        else {
            panic!("{id} is not an asymptotic claim")
        };
        let order = Order {
            expr,
            var,
            order: *order,
            certificate: false,
        };
        g.bench_function(id, |b| {
            b.iter(|| {
                let p = prove_order(Ctx { cat: &cat, claim }, order);
                assert!(p.is_proved(), "{id}: {:?}", p.reason);
            })
        });
    }
    g.finish();
}

criterion_group!(benches, proofs, series_proofs);
/// As `criterion_main!`, with GMP's kernels for this processor selected first (as the
/// `eulertop` binary does), so that the MPFR figures are the product's.
fn main() {
    eulertop::numbers::gmp_kernels::select();
    eulertop::allocator::small_pages();
    benches();
    Criterion::default().configure_from_args().final_summary();
}
