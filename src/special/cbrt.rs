//! The cube root in a few multiplications and one division (FreeBSD's
//! `s_cbrt.c`, Bruce D. Evans 2009, as in musl before 2024): the Rust
//! standard library's `f64::cbrt` on targets without a system `cbrt` is
//! the correctly rounded CORE-MATH version, whose `fma` calls cost several
//! times more than this in the plastic laws' inner loops.
//!
//! An estimate to 5 bits from the exponent divided by 3, a polynomial
//! step to 23 bits, rounded away from zero to 23 bits, then one Newton
//! step in the form `t + t (x/t^2 - t)/(2t + x/t^2)`: error below 0.667
//! ulp (Evans' analysis; unit test against the correctly rounded root).

/// `B1 = (1023 - 1023/3 - 0.03306235651) 2^20`: high word of the estimate.
const B1: u32 = 715_094_163;
/// `B2 = (1023 - 1023/3 - 54/3 - 0.03306235651) 2^20`: for subnormals
/// scaled by `2^54`.
const B2: u32 = 696_219_795;
const P0: f64 = 1.875_951_824_271_770_1;
const P1: f64 = -1.884_979_795_433_771_7;
const P2: f64 = 1.621_429_720_105_354_5;
const P3: f64 = -0.758_397_934_778_766;
const P4: f64 = 0.145_996_192_886_612_45;

/// `x^(1/3)` for every `f64` (odd: negative for negative `x`; 0, NaN and
/// infinities returned as they are), within 0.667 ulp of the exact root.
#[inline]
pub(crate) fn cbrt(x: f64) -> f64 {
    let mut bits = x.to_bits();
    let mut hx = ((bits >> 32) as u32) & 0x7fff_ffff;
    if hx >= 0x7ff0_0000 {
        return x + x;
    }
    if hx < 0x0010_0000 {
        // zero or subnormal
        bits = (x * f64::from_bits(0x4350_0000_0000_0000)).to_bits(); // 2^54
        hx = ((bits >> 32) as u32) & 0x7fff_ffff;
        if hx == 0 {
            return x;
        }
        hx = hx / 3 + B2;
    } else {
        hx = hx / 3 + B1;
    }
    let t = f64::from_bits((bits & (1 << 63)) | ((hx as u64) << 32));
    // to 23 bits
    let r = (t * t) * (t / x);
    let t = t * ((P0 + r * (P1 + r * P2)) + ((r * r) * r) * (P3 + r * P4));
    // rounded away from zero to 23 bits
    let t = f64::from_bits((t.to_bits().wrapping_add(0x8000_0000)) & 0xffff_ffff_c000_0000);
    // one Newton step to 53 bits
    let s = t * t;
    let r = x / s;
    let w = t + t;
    let r = (r - t) / (w + r);
    t + t * r
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Ulps between `a` and `b` (same sign, finite).
    fn ulps(a: f64, b: f64) -> f64 {
        (a - b).abs() / (b.abs() * f64::EPSILON).max(f64::from_bits(1))
    }

    /// Against the standard library's correctly rounded `cbrt` (so within
    /// 0.5 ulp of the exact root): at most 1 ulp apart, over 1e-320 to
    /// 1e300, both signs, with the special values.
    #[test]
    fn cube_root_within_one_ulp_of_the_correctly_rounded_one() {
        let mut worst = 0.0f64;
        let mut x = 1e-320f64;
        let mut k = 0u64;
        while x < 1e300 {
            // a varying mantissa: not only powers of a fixed ratio
            let y = x * (1.0 + 0.618_033_988_749_895 * ((k * 7919 % 1000) as f64 / 1000.0));
            for v in [y, -y] {
                let (got, want) = (cbrt(v), v.cbrt());
                worst = worst.max(ulps(got, want));
            }
            x *= 1.0007;
            k += 1;
        }
        assert!(k > 1_000_000, "{k}");
        assert!(worst <= 1.0, "{worst}");
        assert_eq!(cbrt(0.0).to_bits(), 0.0f64.to_bits());
        assert_eq!(cbrt(-0.0).to_bits(), (-0.0f64).to_bits());
        assert_eq!(cbrt(27.0), 3.0);
        assert_eq!(cbrt(-8.0), -2.0);
        assert_eq!(cbrt(f64::INFINITY), f64::INFINITY);
        assert_eq!(cbrt(f64::NEG_INFINITY), f64::NEG_INFINITY);
        assert!(cbrt(f64::NAN).is_nan());
    }
}
