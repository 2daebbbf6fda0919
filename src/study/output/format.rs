//! Numbers for people: the text report writes a value with the SI prefix
//! that puts it in `[1, 1000)` and four significant digits (`13.05 mN`,
//! `23.43 um^2`), counts as integers where they are integers, and drops
//! the last-bit noise of products such as `k x travel`
//! (`1.9999999999999998e-5` is `2e-5`).

/// A display unit for a set of values: the SI prefix that puts the largest
/// magnitude in `[1, 1000)`, e.g. `(1e-6, "u")`.
pub fn si_prefix(values: impl Iterator<Item = f64>) -> (f64, &'static str) {
    let max = values
        .filter(|v| v.is_finite())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    const PREFIXES: [(f64, &str); 10] = [
        (1e-18, "a"),
        (1e-15, "f"),
        (1e-12, "p"),
        (1e-9, "n"),
        (1e-6, "u"),
        (1e-3, "m"),
        (1.0, ""),
        (1e3, "k"),
        (1e6, "M"),
        (1e9, "G"),
    ];
    if max == 0.0 {
        return (1.0, "");
    }
    PREFIXES
        .iter()
        .rev()
        .find(|(s, _)| max >= *s)
        .copied()
        .unwrap_or(PREFIXES[0])
}

/// A display unit for areas: the length prefix that puts the largest
/// `sqrt(area)` in `[1, 1000)`, squared, e.g. `(1e-12, "u")` for um^2.
pub fn si_prefix_area(values: impl Iterator<Item = f64>) -> (f64, &'static str) {
    let (s, p) = si_prefix(values.map(|v| v.abs().sqrt()));
    (s * s, p)
}

/// `x` rounded to 15 significant digits: the product of two decimal
/// inputs (`10 N/m x 2e-6 m`) without its last-bit round-off.
pub fn tidy(x: f64) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    format!("{x:.14e}").parse().unwrap_or(x)
}

/// `v` in `unit` with an SI prefix and four significant digits, e.g.
/// `si(-2.0704e-5, "N")` is `-20.70 uN`; areas (`m^2`) take the length
/// prefix squared (`um^2`). Units without prefixes (`K`, `%`, `-`, empty)
/// are written as [`plain`].
pub fn si(v: f64, unit: &str) -> String {
    if !v.is_finite() {
        return format!("{v} {unit}");
    }
    let (scale, prefix) = match unit {
        "m^2" | "m2" => si_prefix_area(std::iter::once(v)),
        "N" | "m" | "J" | "Ohm" | "ohm" | "V" | "A" | "s" | "Pa" | "W" => {
            si_prefix(std::iter::once(v))
        }
        _ => return plain(v, unit),
    };
    let (unit, prefix) = match unit {
        "m2" | "m^2" => ("m^2", prefix),
        "ohm" => ("Ohm", prefix),
        u => (u, prefix),
    };
    format!("{} {prefix}{unit}", digits4(v / scale))
}

/// `x` with four significant digits for `|x|` in `[1, 1000)` (`13.05`,
/// `230.4`, `1.000`); 0 as `0`.
fn digits4(x: f64) -> String {
    let a = x.abs();
    if a == 0.0 {
        "0".into()
    } else if a >= 100.0 {
        format!("{x:.1}")
    } else if a >= 10.0 {
        format!("{x:.2}")
    } else {
        format!("{x:.3}")
    }
}

/// A number without a prefixable unit: an integer when it is one, else
/// four significant digits in fixed point between 1e-3 and 1e6, else
/// scientific (`2.500e-7`); the unit follows after a space when given.
pub fn plain(v: f64, unit: &str) -> String {
    let a = v.abs();
    let n = if v.fract() == 0.0 && a < 1e15 {
        format!("{v:.0}")
    } else if (1e-3..1e6).contains(&a) {
        let decimals = (3 - a.log10().floor() as i32).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.3e}")
    };
    match unit {
        "" | "-" => n,
        u => format!("{n} {u}"),
    }
}

/// An expected number of summits or contacts: an integer when it is one,
/// else one decimal from 10 up, three significant digits below
/// (`538.4`, `1.50`, `0.00500`).
pub fn count(v: f64) -> String {
    let mut s = String::with_capacity(16);
    push_count(&mut s, v, 0);
    s
}

/// Appends [`count`]`(v)` right-aligned in `width` characters.
pub fn push_count(out: &mut String, v: f64, width: usize) {
    let a = v.abs();
    let decimals = if v.fract() == 0.0 && a < 1e15 {
        0
    } else if a >= 10.0 {
        1
    } else if a >= 1.0 {
        2
    } else if a == 0.0 {
        for _ in 1..width {
            out.push(' ');
        }
        out.push('0');
        return;
    } else {
        (2 - a.log10().floor() as i32).max(0) as usize
    };
    super::fixed::push_fixed(out, v, decimals, width);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_lose_their_last_bit_noise() {
        let k_travel = 10.0 * 2e-6;
        assert_ne!(k_travel, 2e-5);
        assert_eq!(tidy(k_travel), 2e-5);
        assert_eq!(tidy(0.1 + 0.2), 0.3);
        assert_eq!(tidy(-3.4089e-5), -3.4089e-5);
    }

    #[test]
    fn prefixes_and_four_digits() {
        assert_eq!(si(-2.0704e-5, "N"), "-20.70 uN");
        assert_eq!(si(1.3046e-2, "N"), "13.05 mN");
        assert_eq!(si(2.3428e-11, "m^2"), "23.43 um^2");
        assert_eq!(si(5.986e-3, "Ohm"), "5.986 mOhm");
        assert_eq!(si(4.6134e-13, "J"), "461.3 fJ");
        assert_eq!(si(0.0, "N"), "0 N");
        assert_eq!(si(293.16, "K"), "293.2 K");
    }

    #[test]
    fn counts_are_integers_where_they_are_integers() {
        assert_eq!(count(10000.0), "10000");
        assert_eq!(count(538.375), "538.4");
        assert_eq!(count(11.905), "11.9");
        assert_eq!(count(1.497), "1.50");
        assert_eq!(count(0.005), "0.00500");
        assert_eq!(plain(1930.1, ""), "1930");
        assert_eq!(plain(44.461, "-"), "44.46");
        assert_eq!(plain(2.5e-7, ""), "2.500e-7");
    }

    #[test]
    fn prefixes_put_the_largest_value_in_one_to_a_thousand() {
        assert_eq!(si_prefix([2.5e-6, -1e-7].into_iter()), (1e-6, "u"));
        assert_eq!(si_prefix([999e-9].into_iter()), (1e-9, "n"));
        assert_eq!(si_prefix([0.0].into_iter()), (1.0, ""));
        assert_eq!(si_prefix([f64::NAN, 3.0].into_iter()), (1.0, ""));
        let (s, p) = si_prefix_area([2.2e-11].into_iter());
        assert_eq!(p, "u");
        assert!((s - 1e-12).abs() < 1e-27);
    }
}
