//! The two special functions Persson's theory needs, to ~1e-15 relative.

use crate::special::normal::erfc;

/// Euler's constant.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_860_606_512_090_082;

/// `erf(x)`: Maclaurin series `(2/sqrt(pi)) sum (-1)^n x^(2n+1)/(n! (2n+1))`
/// for `|x| < 0.5` (full relative accuracy near 0), `1 - erfc(x)` beyond.
pub fn erf(x: f64) -> f64 {
    if x.abs() < 0.5 {
        let x2 = x * x;
        let (mut term, mut sum) = (x, x);
        for n in 1..40 {
            term *= -x2 / n as f64;
            let add = term / (2 * n + 1) as f64;
            sum += add;
            if add.abs() < 1e-17 * sum.abs() {
                break;
            }
        }
        sum * std::f64::consts::FRAC_2_SQRT_PI
    } else if x > 0.0 {
        1.0 - erfc(x)
    } else {
        erfc(-x) - 1.0
    }
}

/// The exponential integral `E1(x) = int_x^inf exp(-t)/t dt`, `x > 0`:
/// the series `-gamma - ln x - sum_k (-x)^k/(k k!)` for `x <= 1`, the
/// continued fraction `exp(-x)/(x + 1 - 1/(x + 3 - 4/(x + 5 - ...)))`
/// (modified Lentz) beyond; `inf` at 0, 0 where it underflows.
pub fn e1(x: f64) -> f64 {
    if !(x > 0.0) {
        return if x == 0.0 { f64::INFINITY } else { f64::NAN };
    }
    if x > 740.0 {
        return 0.0;
    }
    if x <= 1.0 {
        let (mut term, mut sum) = (1.0, 0.0);
        for k in 1..60 {
            term *= -x / k as f64;
            let add = term / k as f64;
            sum += add;
            if add.abs() < 1e-17 {
                break;
            }
        }
        return -EULER_GAMMA - x.ln() - sum;
    }
    let tiny = 1e-300;
    let mut b = x + 1.0;
    let mut c = 1.0 / tiny;
    let mut d = 1.0 / b;
    let mut h = d;
    for i in 1..200 {
        let an = -((i * i) as f64);
        b += 2.0;
        d = 1.0 / (an * d + b);
        c = b + an / c;
        let del = c * d;
        h *= del;
        if (del - 1.0).abs() < 1e-16 {
            break;
        }
    }
    h * (-x).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_against_mpmath() {
        // mpmath.e1 and mpmath.erf at 30 digits.
        let e1_ref = [
            (1e-10, 22.448_635_265_138_923_98),
            (0.5, 0.559_773_594_776_160_811_7),
            (1.0, 0.219_383_934_395_520_273_7),
            (2.0, 0.048_900_510_708_061_119_57),
            (30.0, 3.021_552_010_688_812_5e-15),
        ];
        for (x, r) in e1_ref {
            assert!(
                (e1(x) / r - 1.0).abs() < 3e-15,
                "E1({x}) = {} vs {r}",
                e1(x)
            );
        }
        let erf_ref = [
            (1e-8, 1.128_379_167_095_512_5e-8),
            (0.3, 0.328_626_759_459_127_4),
            (0.49, 0.511_668_261_188_523_1),
            (1.5, 0.966_105_146_475_310_7),
        ];
        for (x, r) in erf_ref {
            assert!(
                (erf(x) / r - 1.0).abs() < 3e-15,
                "erf({x}) = {} vs {r}",
                erf(x)
            );
            assert_eq!(erf(-x), -erf(x));
        }
    }
}
