//! A number in a table cell, in the layout of `format!("{x:e}")`: the
//! shortest digits that read back to the same `f64`, in scientific
//! notation (`1.9999999999999994e-8`, `2e0`, `-0e0`, `inf`, `NaN`), at a
//! fraction of its cost: the digits from `zmij` (Schubfach), rewritten
//! into the standard library's layout. The digits are the standard
//! library's but where 17 digits are needed and the exact value lies
//! halfway between two candidates: `zmij` rounds the tie to even (as
//! Python's `repr`), the standard library up, so the last digit may differ
//! by one; both read back to the same `f64`. A 1000-point curve writes
//! 10^4 of them; the standard formatter was a third of the CSV's cost.

use std::fmt::Write as _;

/// Appends `x` as `format!("{x:e}")` would.
pub fn push_sci(out: &mut String, x: f64) {
    if !x.is_finite() {
        let _ = write!(out, "{x:e}");
        return;
    }
    let mut buffer = zmij::Buffer::new();
    let text = buffer.format_finite(x);
    let (negative, text) = match text.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, text),
    };
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(i) => (&text[..i], text[i + 1..].parse::<i32>().unwrap_or(0)),
        None => (text, 0),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    // The digits without the point; the point stands after `int`.
    let mut digits = [0u8; 40];
    let mut n = 0;
    for b in int.bytes().chain(frac.bytes()).take(digits.len()) {
        digits[n] = b;
        n += 1;
    }
    if negative {
        out.push('-');
    }
    let Some(first) = digits[..n].iter().position(|&d| d != b'0') else {
        out.push_str("0e0");
        return;
    };
    let last = digits[..n]
        .iter()
        .rposition(|&d| d != b'0')
        .unwrap_or(first);
    let power = int.len() as i32 - 1 - first as i32 + exponent;
    out.push(digits[first] as char);
    if last > first {
        out.push('.');
        for &d in &digits[first + 1..=last] {
            out.push(d as char);
        }
    }
    let _ = write!(out, "e{power}");
}

/// `x` as [`push_sci`] writes it.
pub fn sci(x: f64) -> String {
    let mut s = String::with_capacity(24);
    push_sci(&mut s, x);
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::rngs::Xoshiro256PlusPlus;
    use rand::{Rng, RngExt, SeedableRng};

    #[test]
    fn the_standard_layout_and_digits_read_back_exactly() {
        let special = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            10.0,
            0.1,
            123.0,
            1e-3,
            1e-5,
            1e15,
            1e16,
            1e17,
            1e21,
            1e22,
            1e23,
            f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            1.9999999999999994e-8,
            2.0 / 3.0,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        for x in special {
            assert_eq!(sci(x), format!("{x:e}"), "{x:?}");
        }
        // Random bit patterns (every exponent) and random magnitudes of the
        // physical range: 10^6 of them, each read back bit for bit, in the
        // standard layout with the standard number of digits, and the same
        // digits but for a tie's last one.
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(20261129);
        let mut ties = 0;
        for _ in 0..500_000 {
            let x = f64::from_bits(rng.next_u64());
            let y = (rng.random::<f64>() - 0.5) * 10f64.powi(rng.random_range(-30..30));
            for v in [x, y] {
                if !v.is_finite() {
                    continue;
                }
                let (ours, std) = (sci(v), format!("{v:e}"));
                assert_eq!(
                    ours.parse::<f64>().unwrap().to_bits(),
                    v.to_bits(),
                    "{ours}"
                );
                if ours != std {
                    let (a, ea) = ours.split_once('e').unwrap();
                    let (b, eb) = std.split_once('e').unwrap();
                    assert_eq!((ea, a.len()), (eb, b.len()), "{ours} {std}");
                    assert_eq!(a[..a.len() - 1], b[..b.len() - 1], "{ours} {std}");
                    let last = |s: &str| i32::from(s.as_bytes()[s.len() - 1]);
                    assert_eq!((last(b) - last(a)).abs(), 1, "{ours} {std}");
                    ties += 1;
                }
            }
        }
        // Ties are rare (an exact value halfway at the 17th digit: about
        // one number in a thousand of these).
        assert!(ties < 3000, "{ties}");
    }
}
