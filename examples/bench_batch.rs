//! Times sn+cn+dn over the benchmark batch in-process (for scripts/bench_peers.py):
//! `cargo run --release --example bench_batch -- BITS N REPEATS`
//! prints the median and the minimum over REPEATS of the time per evaluation in
//! nanoseconds.  Time is the on-CPU time of this thread (Linux
//! `/proc/thread-self/schedstat`; wall clock elsewhere), so that waiting for a busy
//! CPU on a shared machine is not counted.
//! Batch: u_i = −10 + 20·(i + 0.5)/N, modulus k = 0.8 (parameter m = 0.64).

use eulertop::special::sncndn;
use rug::Float;
use std::hint::black_box;
use std::time::Instant;

/// On-CPU nanoseconds of the current thread, if the kernel reports them.
fn cpu_ns() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    s.split_whitespace().next()?.parse().ok()
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let arg = |i: usize, d: usize| a.get(i).and_then(|s| s.parse().ok()).unwrap_or(d);
    let (bits, n, reps) = (arg(1, 53) as u32, arg(2, 1000), arg(3, 5));
    let us: Vec<f64> = (0..n)
        .map(|i| -10.0 + 20.0 * (i as f64 + 0.5) / n as f64)
        .collect();
    let mut times = Vec::new();
    for _ in 0..reps {
        let c0 = cpu_ns();
        let t0 = Instant::now();
        if bits == 53 {
            let mut acc = 0.0;
            for u in &us {
                let (s, c, d) = sncndn(black_box(u), black_box(&0.8)).expect("in domain");
                acc += s + c + d;
            }
            black_box(acc);
        } else {
            let k = Float::with_val(bits, 0.8);
            for u in &us {
                let u = Float::with_val(bits, *u);
                black_box(sncndn(&u, &k).expect("in domain"));
            }
        }
        let wall = t0.elapsed().as_nanos() as f64;
        let used = match (c0, cpu_ns()) {
            (Some(a), Some(b)) => (b - a) as f64,
            _ => wall,
        };
        times.push(used / n as f64);
    }
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!("{} {}", times[times.len() / 2], times[0]);
}
