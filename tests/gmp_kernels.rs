//! The GMP kernels that `numbers::gmp_kernels::select` installs compute the same limbs
//! as GMP's own choice: integer products, squares, quotients, gcds and shifts across
//! the sizes where GMP changes algorithm (basecase, Toom-2, Toom-3), and MPFR
//! operations at 53 to 8192 bits, are computed before and after the selection and
//! compared bit for bit.
//!
//! The selection rewrites GMP's dispatch table, which must happen before any other
//! thread uses GMP, so this test is its own process with a single thread
//! (`harness = false`).

use eulertop::numbers::gmp_kernels::{Kernels, select};
use rug::{Float, Integer};

/// A deterministic integer of `limbs` 64-bit limbs (a linear congruential stream).
fn operand(limbs: usize, seed: u64) -> Integer {
    let mut x = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    let mut digits = Vec::with_capacity(limbs);
    for _ in 0..limbs {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        digits.push(x | 1);
    }
    Integer::from_digits(&digits, rug::integer::Order::Lsf)
}

/// Everything the test compares, as strings of exact values.
fn results() -> Vec<String> {
    let mut out = Vec::new();
    let sizes = [
        1usize, 2, 3, 7, 15, 16, 17, 31, 32, 33, 60, 106, 107, 108, 113, 114, 115, 128, 200, 400,
    ];
    for (j, &n) in sizes.iter().enumerate() {
        for &m in &sizes[..=j] {
            let (a, b) = (operand(n, n as u64), operand(m, 1000 + m as u64));
            let p = Integer::from(&a * &b);
            let (q, r) = a.clone().div_rem(b.clone());
            let g = Integer::from(a.gcd_ref(&b));
            let s = Integer::from(&a * &a);
            let sh = (
                Integer::from(&a << 77u32),
                Integer::from(&a >> 13u32),
                Integer::from(!&a),
            );
            out.push(format!(
                "{p:x} {q:x} {r:x} {g:x} {s:x} {:x} {:x} {:x}",
                sh.0, sh.1, sh.2
            ));
        }
    }
    for bits in [53u32, 256, 1024, 4096, 8192] {
        let x = Float::with_val(bits, 2).sqrt();
        let y = Float::with_val(bits, 3).ln();
        let z = Float::with_val(bits, &x * &y) / Float::with_val(bits, &y + 7u32);
        let w = Float::with_val(bits, z.sin_ref()) + Float::with_val(bits, x.exp_ref());
        out.push(format!(
            "{:?} {:?}",
            z.to_string_radix(16, None),
            w.to_string_radix(16, None)
        ));
    }
    out
}

fn main() {
    let before = results();
    let kernels = select();
    let after = results();
    let differ = before.iter().zip(&after).filter(|(a, b)| a != b).count();
    if differ > 0 || before.len() != after.len() {
        eprintln!(
            "gmp_kernels: {differ} of {} results differ after select() ({kernels:?})",
            before.len()
        );
        std::process::exit(1);
    }
    let which = match kernels {
        Kernels::Zen => "the Zen kernels were installed",
        Kernels::Gmp => "GMP's own choice stands",
    };
    println!(
        "test gmp_kernels::same_limbs ... ok ({} results; {which})",
        before.len()
    );
}
