//! Decimal display of the engine's values: every number in a rendered value (`3/7`,
//! `-1.25e-3`, vectors, matrices, complex `a + bi`) rounded to [`DIGITS`] significant
//! digits, exactly (the value is read as a rational, rounded half to even).
//!
//! ```
//! use eulertop::report::decimal::round_numbers;
//! let (s, changed) = round_numbers("(1/3, -2.5e-1, 7)");
//! assert_eq!(s, "(0.333333333333, -0.25, 7)");
//! assert!(changed);
//! assert_eq!(round_numbers("1.5 + -2i"), ("1.5 + -2i".to_string(), false));
//! ```

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// Significant digits shown.
pub const DIGITS: u32 = 12;

/// Longest number token read (longer tokens are left as written: no allocation sized by a
/// 10^huge exponent).
const MAX_EXPONENT: i64 = 100_000;

fn pow10(e: u32) -> BigInt {
    num_traits::pow(BigInt::from(10u32), e as usize)
}

/// `r` × 10^e, exactly.
fn scale10(r: &BigRational, e: i64) -> BigRational {
    let p = BigRational::from_integer(pow10(e.unsigned_abs() as u32));
    if e >= 0 { r * p } else { r / p }
}

/// Parses `digits[.digits][e[+-]digits]` exactly; `None` if malformed or the exponent is
/// absurd.
fn parse_decimal(t: &str) -> Option<BigRational> {
    let (mant, exp) = match t.find(['e', 'E']) {
        Some(k) => (&t[..k], t[k + 1..].parse::<i64>().ok()?),
        None => (t, 0),
    };
    let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
    if int.is_empty() && frac.is_empty() {
        return None;
    }
    let digits = format!("{int}{frac}");
    if !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let e = exp.checked_sub(frac.len() as i64)?;
    if e.abs() > MAX_EXPONENT {
        return None;
    }
    let n: BigInt = digits.parse().ok()?;
    Some(scale10(&BigRational::from_integer(n), e))
}

/// Parses a decimal or a quotient `p/q` of decimals.
pub fn parse_number(t: &str) -> Option<BigRational> {
    match t.split_once('/') {
        Some((p, q)) => {
            let q = parse_decimal(q)?;
            (!q.is_zero()).then(|| parse_decimal(p).map(|p| p / q))?
        }
        None => parse_decimal(t),
    }
}

/// floor(log10 r) for r > 0.
fn floor_log10(r: &BigRational) -> i64 {
    let guess = r.numer().to_string().len() as i64 - r.denom().to_string().len() as i64;
    // r lies in [10^(guess-1), 10^(guess+1))
    if scale10(r, -guess) >= BigRational::one() {
        guess
    } else {
        guess - 1
    }
}

/// `r` with [`DIGITS`] significant digits (trailing zeros dropped): plain notation for
/// 10^-5 ≤ |r| < 10^12, else `d.ddde±N`.
pub fn format_rational(r: &BigRational) -> String {
    if r.is_zero() {
        return "0".to_string();
    }
    let sign = if r.is_negative() { "-" } else { "" };
    let a = r.abs();
    let mut e = floor_log10(&a);
    let x = scale10(&a, DIGITS as i64 - 1 - e);
    let (q, rem) = x.numer().div_rem(x.denom());
    let twice = rem * 2u32;
    let up = twice > *x.denom() || (twice == *x.denom() && q.is_odd());
    let mut n = if up { q + 1u32 } else { q };
    if n == pow10(DIGITS) {
        n /= 10u32;
        e += 1;
    }
    let digits = n.to_string();
    let (lead, rest) = digits.split_at(1);
    if (-5..12).contains(&e) {
        let s = if e >= 0 {
            let (i, f) = digits.split_at(e as usize + 1);
            format!("{i}.{f}")
        } else {
            format!("0.{}{}", "0".repeat((-e - 1) as usize), digits)
        };
        let s = s.trim_end_matches('0').trim_end_matches('.');
        format!("{sign}{s}")
    } else {
        let f = rest.trim_end_matches('0');
        let dot = if f.is_empty() { "" } else { "." };
        format!("{sign}{lead}{dot}{f}e{e}")
    }
}

/// Length of the number token at the start of `b` (digits, `.`, exponent, `/`).
fn token_len(b: &[u8]) -> usize {
    let mut k = 0;
    let mut seen_e = false;
    while k < b.len() {
        let c = b[k];
        let exp_sign = seen_e && (c == b'+' || c == b'-') && matches!(b[k - 1], b'e' | b'E');
        if c.is_ascii_digit() || c == b'.' || c == b'/' || exp_sign {
            k += 1;
        } else if (c == b'e' || c == b'E') && !seen_e && k + 1 < b.len() {
            let n = b[k + 1];
            if n.is_ascii_digit() || n == b'+' || n == b'-' {
                seen_e = true;
                k += 1;
            } else {
                break;
            }
        } else {
            break;
        }
        if c == b'/' {
            seen_e = false;
        }
    }
    k
}

/// Rewrites every number in `s` with [`DIGITS`] significant digits.  Returns the text and
/// whether any value changed (i.e. was not exactly representable in 12 digits).
pub fn round_numbers(s: &str) -> (String, bool) {
    let b = s.as_bytes();
    let mut out = String::with_capacity(s.len());
    let mut changed = false;
    let mut i = 0;
    while i < b.len() {
        let prev_word = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_');
        if b[i].is_ascii_digit() && !prev_word {
            let k = token_len(&b[i..]);
            let tok = &s[i..i + k];
            match parse_number(tok) {
                Some(r) => {
                    let f = format_rational(&r);
                    changed |= parse_number(&f).is_none_or(|g| g != r);
                    out.push_str(&f);
                }
                None => out.push_str(tok),
            }
            i += k;
            continue;
        }
        let c = s[i..].chars().next().unwrap_or(' ');
        out.push(c);
        i += c.len_utf8();
    }
    (out, changed)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(p: i64, q: i64) -> BigRational {
        BigRational::new(p.into(), q.into())
    }

    #[test]
    fn rounds_half_to_even_at_twelve_digits() {
        assert_eq!(format_rational(&r(1, 3)), "0.333333333333");
        assert_eq!(format_rational(&r(2, 3)), "0.666666666667");
        assert_eq!(format_rational(&r(-1, 8)), "-0.125");
        // 0.1234567890125 has a tie at the 12th digit: even stays
        assert_eq!(
            format_rational(&parse_number("0.1234567890125").unwrap()),
            "0.123456789012"
        );
        assert_eq!(
            format_rational(&parse_number("0.1234567890135").unwrap()),
            "0.123456789014"
        );
        // carry into a new digit
        assert_eq!(
            format_rational(&parse_number("9.9999999999999").unwrap()),
            "10"
        );
    }

    #[test]
    fn scientific_outside_the_plain_range() {
        let x = parse_number("1.3906711615670008644e-309").unwrap();
        assert_eq!(format_rational(&x), "1.39067116157e-309");
        assert_eq!(format_rational(&parse_number("2e12").unwrap()), "2e12");
        assert_eq!(
            format_rational(&parse_number("1.5e-5").unwrap()),
            "0.000015"
        );
        assert_eq!(format_rational(&parse_number("1.5e-6").unwrap()), "1.5e-6");
    }

    #[test]
    fn rewrites_values_of_every_shape() {
        let (s, c) =
            round_numbers("(-85931562634191385469696293083/192289025187984730245478481920, 1e0)");
        assert_eq!(s, "(-0.446887504631, 1)"); // Python: Decimal(p)/Decimal(q) at 12 digits
        assert!(c);
        let (s, c) = round_numbers("5.8119987999203051255e-1 + 1.3906711615670008644e-309i");
        assert_eq!(s, "0.581199879992 + 1.39067116157e-309i");
        assert!(c);
        let (s, c) = round_numbers("[[0, 1/2], [-3/4, 0]]");
        assert_eq!(s, "[[0, 0.5], [-0.75, 0]]");
        assert!(!c);
        assert_eq!(round_numbers("slope 0.9990").0, "slope 0.999");
        assert_eq!(round_numbers("x2 = 3").0, "x2 = 3");
    }

    #[test]
    fn malformed_or_huge_tokens_are_kept() {
        assert_eq!(round_numbers("1e999999999").0, "1e999999999");
        assert_eq!(round_numbers("1/0").0, "1/0");
        assert_eq!(round_numbers("1.2.3").0, "1.2.3");
    }
}
