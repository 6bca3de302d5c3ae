//! Criterion benchmarks of the claim engine: parsing, evaluating one expression at 53 and
//! 256 bits, and verifying one background claim on the default ladder.

use criterion::{BatchSize, Criterion, black_box, criterion_group};
use eulertop::claims::catalogue::load_sources;
use eulertop::claims::eval::Evaluator;
use eulertop::claims::parser::parse_expr;
use eulertop::claims::registry::Registry;
use eulertop::claims::value::Value;
use eulertop::claims::verdict::{Options, run_claim};

const ADDITION: &str = "(sn(u, k) * cn(v, k) * dn(v, k) + sn(v, k) * cn(u, k) * dn(u, k)) / (1 - k^2 * sn(u, k)^2 * sn(v, k)^2) - sn(u + v, k)";

fn bench(c: &mut Criterion) {
    c.bench_function("parse sn addition theorem", |b| {
        b.iter(|| parse_expr(black_box(ADDITION)).unwrap())
    });
    let reg = Registry::new();
    let e = parse_expr(ADDITION).unwrap();
    // a fresh evaluation per iteration: an evaluation remembers its calls, so one
    // evaluator reused would answer every later iteration from memory
    let point = [("u", 0.3), ("v", 0.7), ("k", 0.6)];
    c.bench_function("eval sn addition theorem f64", |b| {
        b.iter_batched(
            || {
                let mut ev = Evaluator::new(&reg, 0.0f64);
                for (n, x) in point {
                    ev.bind(n, Value::Real(x));
                }
                ev
            },
            |ev| ev.eval(black_box(&e)).unwrap(),
            BatchSize::SmallInput,
        )
    });
    c.bench_function("eval sn addition theorem 256 bits", |b| {
        b.iter_batched(
            || {
                let mut ev = Evaluator::new(&reg, rug::Float::new(256));
                for (n, x) in point {
                    ev.bind(n, Value::Real(rug::Float::with_val(256, x)));
                }
                ev
            },
            |ev| ev.eval(black_box(&e)).unwrap(),
            BatchSize::SmallInput,
        )
    });
    let src = format!(
        "[[claim]]\nid = \"c\"\nlocation = \"l\"\nprinted = 'p'\nenvironment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\nexpect = \"holds\"\nvars = [[\"k\", \"uniform(0.1, 0.9)\"], [\"u\", \"uniform(-2, 2)\"], [\"v\", \"uniform(-2, 2)\"]]\nlhs = \"{ADDITION}\"\nrhs = \"0\"\nscale = \"1\"\n"
    );
    let cat = load_sources(&[("b.toml".into(), src)], Registry::new()).unwrap();
    let opts = Options::default();
    c.bench_function("verify one claim, default ladder, 8 samples", |b| {
        b.iter(|| run_claim(&cat, &cat.claims[0], &opts))
    });
}

criterion_group!(benches, bench);
/// As `criterion_main!`, with GMP's kernels for this processor selected first (as the
/// `eulertop` binary does), so that the MPFR figures are the product's.
fn main() {
    eulertop::numbers::gmp_kernels::select();
    benches();
    Criterion::default().configure_from_args().final_summary();
}
