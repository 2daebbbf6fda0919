//! A number with a fixed count of decimals, the same bytes as
//! `format!("{x:>width$.decimals$}")` at a fraction of its cost: the
//! text report's table of a thousand listed states is five thousand such
//! cells, and the standard library's exact formatter (Grisu with a
//! Dragon fallback, through `core::fmt`'s padding) was most of the
//! report's time.
//!
//! The value is exact: `x = m 2^e` with the 53-bit integer `m`, so
//! `x 10^d = m 10^d 2^e`, an integer `m 10^d < 2^117` (for `d <= 19`)
//! shifted by `e`; the bits shifted out decide the rounding, half to even
//! as the standard library rounds (`{:.1}` of `0.25` is `0.2`). A value
//! outside that reach (`|x| >= 2^63`, more than 19 decimals, infinite or
//! NaN) goes to the standard formatter.

use std::fmt::Write as _;

/// The most decimals written here (`10^19 < 2^64`); more go to `core::fmt`.
const MAX_DECIMALS: usize = 19;

/// Appends `x` as `write!(out, "{x:>width$.decimals$}")` would.
pub fn push_fixed(out: &mut String, x: f64, decimals: usize, width: usize) {
    let mut buf = [0u8; 64];
    match fixed_digits(x, decimals, &mut buf) {
        Some(n) => {
            for _ in n..width {
                out.push(' ');
            }
            // Only ASCII digits, '-' and '.' were written.
            out.push_str(std::str::from_utf8(&buf[..n]).unwrap_or_default());
        }
        None => {
            let _ = write!(out, "{x:>width$.decimals$}");
        }
    }
}

/// `x` as `format!("{x:.decimals$}")` writes it.
pub fn fixed(x: f64, decimals: usize) -> String {
    let mut s = String::with_capacity(24);
    push_fixed(&mut s, x, decimals, 0);
    s
}

/// Writes `x` with `decimals` decimals into `buf`, returning its length,
/// or `None` where the standard formatter is left to do it.
fn fixed_digits(x: f64, decimals: usize, buf: &mut [u8; 64]) -> Option<usize> {
    if !x.is_finite() || decimals > MAX_DECIMALS {
        return None;
    }
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1u64 << 52) - 1);
    // x = m 2^e exactly.
    let (m, e) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1u64 << 52), biased - 1075)
    };
    let unit = 10u128.pow(decimals as u32);
    let scaled = m as u128 * unit; // < 2^53 2^64
    let q = if e >= 0 {
        if e > 10 {
            return None;
        }
        scaled << e
    } else {
        let shift = (-e) as u32;
        if shift >= 128 {
            0 // scaled < 2^117 <= 2^(shift - 1): below one half
        } else {
            let q = scaled >> shift;
            let rest = scaled & ((1u128 << shift) - 1);
            let half = 1u128 << (shift - 1);
            if rest > half || (rest == half && q & 1 == 1) {
                q + 1
            } else {
                q
            }
        }
    };
    // Most cells fit 64 bits, whose division is a few cycles (128-bit
    // division is a library call).
    let (int, frac) = match (u64::try_from(q), u64::try_from(unit)) {
        (Ok(q), Ok(unit)) => (u128::from(q / unit), u128::from(q % unit)),
        _ => (q / unit, q % unit),
    };
    let mut n = 0;
    if negative {
        buf[n] = b'-';
        n += 1;
    }
    n += write_digits(&mut buf[n..], int, 1);
    if decimals > 0 {
        buf[n] = b'.';
        n += 1;
        n += write_digits(&mut buf[n..], frac, decimals);
    }
    Some(n)
}

/// Writes `v` in decimal with at least `min` digits (leading zeros) at
/// the start of `buf`, returning the count.
fn write_digits(buf: &mut [u8], v: u128, min: usize) -> usize {
    let mut tmp = [0u8; 40];
    let mut k = 0;
    match u64::try_from(v) {
        Ok(mut v) => {
            while v > 0 || k < min {
                tmp[k] = b'0' + (v % 10) as u8;
                v /= 10;
                k += 1;
            }
        }
        Err(_) => {
            let mut v = v;
            while v > 0 || k < min {
                tmp[k] = b'0' + (v % 10) as u8;
                v /= 10;
                k += 1;
            }
        }
    }
    for i in 0..k {
        buf[i] = tmp[k - 1 - i];
    }
    k
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::rngs::Xoshiro256PlusPlus;
    use rand::{Rng, RngExt, SeedableRng};

    fn check(x: f64, decimals: usize, width: usize) {
        let mut got = String::new();
        push_fixed(&mut got, x, decimals, width);
        assert_eq!(
            got,
            format!("{x:>width$.decimals$}"),
            "x = {x:e} ({:#x}), {decimals} decimals, width {width}",
            x.to_bits()
        );
    }

    #[test]
    fn ties_signs_zeros_and_extremes_as_the_standard_library() {
        let special = [
            0.0,
            -0.0,
            0.5,
            1.5,
            2.5,
            -2.5,
            0.25,
            0.125,
            0.375,
            -0.0001,
            0.0005,
            0.0015,
            0.0025,
            -0.0035,
            999.9995,
            999.9994999999999,
            1e-320,
            -5e-324,
            f64::MIN_POSITIVE,
            f64::EPSILON,
            9.223372036854775e18,
            9.223372036854776e18,
            1e19,
            -1e300,
            f64::MAX,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            123456.789,
            4503599627370495.5,
            4503599627370497.0,
        ];
        for &x in &special {
            for decimals in [0, 1, 2, 3, 4, 7, 12, 19, 20, 25] {
                for width in [0, 8, 13, 40] {
                    check(x, decimals, width);
                }
            }
        }
    }

    #[test]
    fn exact_ties_at_every_decimal_count() {
        // k / 2^j with j small is exactly representable; at decimals = j - 1
        // and below some of them are exact ties between two outputs.
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(11);
        for _ in 0..20_000 {
            let j = rng.random_range(1..=20u32);
            let k = rng.random_range(0..1u64 << 40) as f64;
            let x =
                k / f64::from(1u32 << j.min(31)) * if rng.random_bool(0.5) { 1.0 } else { -1.0 };
            check(x, rng.random_range(0..=6), 13);
        }
    }

    #[test]
    fn random_bits_and_random_magnitudes() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(7);
        for _ in 0..100_000 {
            let x = f64::from_bits(rng.next_u64());
            check(x, rng.random_range(0..=21), 13);
        }
        for _ in 0..100_000 {
            let x = rng.random_range(-1.0..1.0) * 10f64.powi(rng.random_range(-25..25));
            check(x, rng.random_range(0..=6), 13);
            check(x, 3, 13);
        }
    }
}
