//! Shared helpers for the special-function tests: reading the reference tables written
//! by scripts/gen_jacobi_ref.py (mpmath / python-flint) and measuring errors.
#![allow(dead_code)]

use rug::Float;

/// One CSV row: its fields as strings.
pub type Row = Vec<String>;

/// Reads a reference table (skipping `#` comments and the header line).
pub fn read_table(name: &str) -> Vec<Row> {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("reference table present");
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').map(|s| s.to_string()).collect())
        .collect()
}

/// Parses a decimal at `bits` of precision.
pub fn mp(s: &str, bits: u32) -> Float {
    Float::with_val(bits, Float::parse(s).expect("valid decimal in table"))
}

/// `|a − b|` as f64, computed with `bits` bits.
pub fn diff(a: &Float, b: &Float, bits: u32) -> f64 {
    let d = Float::with_val(bits, a - b);
    d.abs().to_f64()
}

/// Number of decimal digits a reference value needs for an `n`-bit comparison.
pub fn digits_needed(n: u32) -> usize {
    (n as f64 * std::f64::consts::LOG10_2).ceil() as usize + 3
}

/// The precisions of the multi-precision accuracy tests.
pub const PRECS: [u32; 10] = [64, 80, 128, 200, 256, 333, 512, 1024, 2048, 4096];
