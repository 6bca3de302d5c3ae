//! The three largest symbolic proofs of the paper's identities (whole proof: evaluation
//! of both sides on a fresh ring, restarts, zero test).
//!
//! `cargo bench --bench algebra`

use criterion::{Criterion, criterion_group};
use eulertop::algebra::{RingOptions, prove_components};

#[path = "../tests/algebra_identities/mod.rs"]
mod algebra_identities;

use algebra_identities::{Regime, Variant, g0g1, g1_alphabeta, mm};

fn proofs(c: &mut Criterion) {
    let mut g = c.benchmark_group("algebra");
    g.sample_size(10);
    g.bench_function("M-M 1-3 from phi, phih (upper regime)", |b| {
        b.iter(|| {
            assert!(
                prove_components(RingOptions::default(), "M-M", |r| mm(
                    r,
                    Regime::Upper,
                    true
                ))
                .is_proved()
            )
        })
    });
    g.bench_function("(G0G1) with named k, nu (upper regime)", |b| {
        b.iter(|| {
            let p = prove_components(RingOptions::default(), "G0G1", |r| {
                g0g1(r, Regime::Upper, Variant::True, true)
            });
            assert!(p.is_proved())
        })
    });
    g.bench_function(
        "(MV alphabeta) G1 = k2 nu2 (1 + alpha sn2 - beta sn4) (upper regime)",
        |b| {
            b.iter(|| {
                let p = prove_components(RingOptions::default(), "G1", |r| {
                    g1_alphabeta(r, Regime::Upper)
                });
                assert!(p.is_proved())
            })
        },
    );
    g.finish();
}

criterion_group!(benches, proofs);
/// As `criterion_main!`, with GMP's kernels for this processor selected first (as the
/// `eulertop` binary does), so that the MPFR figures are the product's.
fn main() {
    eulertop::numbers::gmp_kernels::select();
    benches();
    Criterion::default().configure_from_args().final_summary();
}
