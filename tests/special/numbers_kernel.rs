//! `Real::sin_cos_kernel`, the reduction-free sine/cosine used at the bottom of the
//! f64 Jacobi path.
//!
//! * `f64` (the fdlibm kernels `__kernel_sin`/`__kernel_cos`): against MPFR `sin`/`cos`
//!   at 128 bits (correctly rounded, so the reference error is below 2⁻¹²⁸ relative) on
//!   a dense grid of 200 001 points covering the documented domain
//!   `|x| ≤ π/4·(1 + 2⁻²⁰)`, on the doubles next to its ends, and on tiny arguments.
//!   The error must be below 1 ulp of the result, fdlibm's documented bound.
//! * `rug::Float` and `Dual<f64>` use the trait default, which must be `sin_cos`
//!   itself (bit for bit).

use eulertop::numbers::{Dual, Real};
use rug::Float;

/// Bits of the MPFR reference.
const REF: u32 = 128;

/// The size of one ulp of the double nearest to `y` (the spacing of doubles in the
/// binade of `y`; `2⁻¹⁰⁷⁴` for subnormals and zero).
fn ulp_of(y: f64) -> f64 {
    let a = y.abs();
    if a < f64::MIN_POSITIVE {
        return f64::from_bits(1);
    }
    // 2^e for the binade [2^e, 2^(e+1)) of a, times 2^-52 (exact, also when the
    // product is subnormal)
    let binade = f64::from_bits(a.to_bits() & (0x7ffu64 << 52));
    binade * 2f64.powi(-52)
}

/// Errors of `(sin, cos)` from the kernel at `x`, in ulps of the reference results.
fn kernel_error_ulps(x: f64) -> (f64, f64) {
    let (s, c) = x.sin_cos_kernel();
    let (rs, rc) = Float::with_val(REF, x).sin_cos(Float::new(REF));
    let err = |got: f64, want: &Float| {
        let e = Float::with_val(REF, got - want).abs().to_f64();
        e / ulp_of(want.to_f64())
    };
    (err(s, &rs), err(c, &rc))
}

/// The upper end of the documented domain, `π/4·(1 + 2⁻²⁰)`, rounded down to f64.
fn domain_end() -> f64 {
    let pi4 = Float::with_val(REF, rug::float::Constant::Pi) / 4u32;
    let end = pi4 * (Float::with_val(REF, 1) + Float::with_val(REF, Float::u_exp(1, -20)));
    end.to_f64_round(rug::float::Round::Down)
}

#[test]
fn f64_kernel_below_one_ulp_on_the_domain() {
    let a = domain_end();
    let n = 200_001usize;
    let mut xs: Vec<f64> = (0..n)
        .map(|i| -a + 2.0 * a * (i as f64) / ((n - 1) as f64))
        .filter(|x| x.abs() <= a)
        .collect();
    // the ends and their neighbours, π/4 itself and its neighbours
    let pi4 = std::f64::consts::FRAC_PI_4;
    for x in [
        a,
        a.next_down(),
        pi4,
        pi4.next_up(),
        pi4.next_down(),
        0.5,
        0.25,
    ] {
        xs.push(x);
        xs.push(-x);
    }
    assert!(xs.len() > 200_000);
    let (mut worst_s, mut worst_c) = ((0.0f64, 0.0f64), (0.0f64, 0.0f64));
    for &x in &xs {
        let (es, ec) = kernel_error_ulps(x);
        if es > worst_s.0 {
            worst_s = (es, x);
        }
        if ec > worst_c.0 {
            worst_c = (ec, x);
        }
        assert!(
            es < 1.0,
            "sin kernel at x = {x:e} ({:#x}): {es} ulp",
            x.to_bits()
        );
        assert!(
            ec < 1.0,
            "cos kernel at x = {x:e} ({:#x}): {ec} ulp",
            x.to_bits()
        );
    }
    eprintln!(
        "sin_cos_kernel f64 on {} points of |x| <= pi/4(1+2^-20): max sin error {:.4} ulp (x = {:e}), max cos error {:.4} ulp (x = {:e})",
        xs.len(),
        worst_s.0,
        worst_s.1,
        worst_c.0,
        worst_c.1
    );
}

#[test]
fn f64_kernel_tiny_arguments() {
    let tiny = [
        0.0,
        -0.0,
        1e-300,
        -1e-300,
        1e-20,
        -1e-20,
        2f64.powi(-26),
        -(2f64.powi(-26)),
        2f64.powi(-27),
        -(2f64.powi(-27)),
        f64::MIN_POSITIVE,
        -f64::MIN_POSITIVE,
    ];
    let mut worst = 0f64;
    for x in tiny {
        let (es, ec) = kernel_error_ulps(x);
        worst = worst.max(es).max(ec);
        assert!(es < 1.0, "sin kernel at x = {x:e}: {es} ulp");
        assert!(ec < 1.0, "cos kernel at x = {x:e}: {ec} ulp");
    }
    // exactly representable cases: sin 0 = 0, cos 0 = 1, and cos x = 1 for |x| < 2⁻²⁷
    for x in [0.0, -0.0, 1e-300, -1e-20] {
        let (s, c) = x.sin_cos_kernel();
        assert_eq!(c, 1.0, "cos kernel at {x:e}");
        assert_eq!(s.abs(), x.abs(), "sin kernel at {x:e}");
    }
    eprintln!("sin_cos_kernel f64 on tiny arguments: max error {worst:.4} ulp");
}

/// For the multi-precision and dual types the trait default is `sin_cos` (no
/// kernel-specific approximation), bit for bit, at several precisions.
#[test]
fn default_kernel_is_sin_cos() {
    let xs = [
        0.0,
        -0.0,
        1e-30,
        0.1,
        -0.3,
        0.5,
        std::f64::consts::FRAC_PI_4,
        -0.785,
        0.7,
    ];
    for prec in [53u32, 64, 128, 256, 1000] {
        for x in xs {
            let f = Float::with_val(prec, x);
            let (ks, kc) = f.sin_cos_kernel();
            let (s, c) = Real::sin_cos(&f);
            assert_eq!(ks.prec(), prec);
            assert_eq!(kc.prec(), prec);
            assert!(
                ks.total_cmp(&s).is_eq() && kc.total_cmp(&c).is_eq(),
                "rug::Float prec {prec} x = {x}: kernel differs from sin_cos"
            );
        }
    }
    for x in xs {
        for seed in [1.0, -2.5, 0.0] {
            let d = Dual::new(x, seed);
            let (ks, kc) = d.sin_cos_kernel();
            let (s, c) = Real::sin_cos(&d);
            for (a, b) in [(ks.v, s.v), (ks.d, s.d), (kc.v, c.v), (kc.d, c.d)] {
                assert_eq!(
                    a.to_bits(),
                    b.to_bits(),
                    "Dual<f64> x = {x} d = {seed}: kernel differs from sin_cos"
                );
            }
            // and it is the derivative of sin, cos: d sin = cos·dx, d cos = −sin·dx
            let (fs, fc) = x.sin_cos();
            assert_eq!(ks.v.to_bits(), fs.to_bits());
            assert_eq!(kc.v.to_bits(), fc.to_bits());
            assert_eq!(ks.d.to_bits(), (fc * seed).to_bits());
            assert_eq!(kc.d.to_bits(), (-fs * seed).to_bits());
        }
    }
}
