//! The standard normal distribution with relative accuracy in the tails.
//!
//! Everything rests on the scaled Mills ratio `R_0(h) = Q(h)/phi(h)`
//! (`h >= 0`), evaluated without cancellation: `R_0 = R_2 + h R_1` (both
//! terms positive) with `R_1`, `R_2` the scaled Gaussian integrals of
//! [`gaussian_fn`](super::gaussian_fn) (Chebyshev pieces on `[0, 20)`, the
//! asymptotic series beyond). The density's exponent `h^2/2` is formed
//! exactly (Dekker's exact product gives the rounding error of `h*h`), so `phi(h)` keeps
//! full relative accuracy up to its underflow at `h ~ 38.6`.

use super::gaussian_fn::{r_asymptotic, scaled_integer_top};

/// `1/sqrt(2 pi)`.
pub const FRAC_1_SQRT_2PI: f64 = 0.398_942_280_401_432_677_939_946_059_934_381_868;
/// `sqrt(2/pi)`.
const SQRT_2_OVER_PI: f64 = 0.797_884_560_802_865_355_879_892_119_868_763_737;

/// `exp(-x^2/2)` with the exponent formed exactly: `x^2 = p + e` with
/// `p = fl(x*x)` and `e` its rounding error (Dekker's exact product), then
/// `exp(-p/2) (1 - e/2)` (`|e/2| < 1e-13` wherever the result is normal).
#[inline]
pub fn exp_minus_half_sq(x: f64) -> f64 {
    if !x.is_finite() {
        return if x.is_nan() { f64::NAN } else { 0.0 };
    }
    let p = x * x;
    if !(p < 1500.0) {
        // exp(-750) underflows; also keeps inf - inf out of the FMA.
        return 0.0;
    }
    // Exact rounding error of x*x by Veltkamp splitting (Dekker 1971);
    // no FMA needed (a library call on targets without the feature).
    let c = 134_217_729.0 * x; // 2^27 + 1
    let hi = c - (c - x);
    let lo = x - hi;
    let e = ((hi * hi - p) + 2.0 * hi * lo) + lo * lo;
    (-0.5 * p).exp() * (1.0 - 0.5 * e)
}

/// Standard normal density `phi(h) = exp(-h^2/2)/sqrt(2 pi)`, relative
/// accuracy ~2 ulp for all `h` where it is a normal number; 0 past
/// `|h| ~ 38.6`.
#[inline]
pub fn pdf(h: f64) -> f64 {
    FRAC_1_SQRT_2PI * exp_minus_half_sq(h)
}

/// [`pdf`] of every `h[i]` into `out[i]` (the shorter slice bounds the
/// work), written without branches so the compiler keeps the lanes in
/// vector registers: `exp` by Cody–Waite reduction and a degree-13 Taylor
/// polynomial (`exp_lane`), the rounding error of `h^2` restored as in
/// [`exp_minus_half_sq`]. Within 4e-16 relative of [`pdf`] where that is
/// a normal number (unit test); 0 past `|h| ~ 38.7`, NaN for NaN.
pub fn pdf_batch(h: &[f64], out: &mut [f64]) {
    // A `WithSimd` operation: compiled for the CPU's widest vectors
    // (AVX2/AVX-512); passed to `dispatch` as a closure it stays scalar.
    pulp::Arch::new().dispatch(PdfBatch { h, out });
}

struct PdfBatch<'a> {
    h: &'a [f64],
    out: &'a mut [f64],
}

impl pulp::WithSimd for PdfBatch<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        for (o, &x) in self.out.iter_mut().zip(self.h) {
            *o = FRAC_1_SQRT_2PI * exp_minus_half_sq_lane(x);
        }
    }
}

/// [`exp_minus_half_sq`] without branches (selects only).
#[inline(always)]
fn exp_minus_half_sq_lane(x: f64) -> f64 {
    let p = x * x;
    let c = 134_217_729.0 * x;
    let hi = c - (c - x);
    let lo = x - hi;
    let e = ((hi * hi - p) + 2.0 * hi * lo) + lo * lo;
    let v = exp_lane((-0.5 * p).max(-746.0)) * (1.0 - 0.5 * e);
    let v = if p < 1500.0 { v } else { 0.0 };
    if x.is_nan() {
        f64::NAN
    } else {
        v
    }
}

/// `exp(y)` for `y` in `[-746, 0]` without branches: `y = k ln 2 + r`,
/// `|r| <= ln 2/2` (Cody–Waite, fdlibm's split of `ln 2`), `exp(r)` by its
/// Taylor polynomial of degree 13 (remainder below 5e-18), times `2^k` as
/// two powers of two built from the exponent bits (so subnormal results
/// round once). Relative error ~2 ulp.
#[inline(always)]
pub(crate) fn exp_lane(y: f64) -> f64 {
    const LN2_HI: f64 = 6.931_471_803_691_238_164_90e-1;
    const LN2_LO: f64 = 1.908_214_929_270_587_700_02e-10;
    // 1.5 * 2^52: adding it rounds to an integer kept in the low bits.
    const SHIFT: f64 = 6_755_399_441_055_744.0;
    let kf = (y * std::f64::consts::LOG2_E + SHIFT) - SHIFT;
    let r = (y - kf * LN2_HI) - kf * LN2_LO;
    const INV_FACT: [f64; 14] = [
        1.0,
        1.0,
        0.5,
        1.0 / 6.0,
        1.0 / 24.0,
        1.0 / 120.0,
        1.0 / 720.0,
        1.0 / 5040.0,
        1.0 / 40320.0,
        1.0 / 362_880.0,
        1.0 / 3_628_800.0,
        1.0 / 39_916_800.0,
        1.0 / 479_001_600.0,
        1.0 / 6_227_020_800.0,
    ];
    let mut p = INV_FACT[13];
    for j in (0..13).rev() {
        p = p * r + INV_FACT[j];
    }
    // 2^k as 2^k1 2^k2, k1 = round(k/2): both normal for k >= -1077.
    // Integers in the low bits of `x + SHIFT`, in the float domain (no
    // 64-bit arithmetic shift, which AVX2 lacks).
    let k1 = (0.5 * kf + SHIFT) - SHIFT;
    let k2 = kf - k1;
    let two = |e: f64| {
        let bits = (e + SHIFT).to_bits().wrapping_sub(SHIFT.to_bits());
        f64::from_bits(bits.wrapping_add(1023) << 52)
    };
    p * two(k1) * two(k2)
}

/// Scaled Mills ratio `R_0(h) = Q(h)/phi(h) = int_0^inf exp(-h t - t^2/2) dt`
/// for `h >= 0` (relative error ~1e-16; `R_0(h) ~ 1/h` for large `h`). For
/// `h < 0` it is `(1 - Q(-h))/phi(h)`, which overflows below `h ~ -38.6`.
pub fn mills_ratio(h: f64) -> f64 {
    if h.is_nan() {
        return f64::NAN;
    }
    if h >= 0.0 {
        scaled_r0(h)
    } else {
        tail(h) / pdf(h)
    }
}

/// `R_0(h)`, `h >= 0` (including `+inf`).
#[inline]
pub(crate) fn scaled_r0(h: f64) -> f64 {
    if h == f64::INFINITY {
        return 0.0;
    }
    if h < super::gaussian_fn::TABLE_HI {
        let (r1, r2) = scaled_integer_top(h);
        h * r1 + r2
    } else {
        r_asymptotic(0.0, 1.0, h, h)
    }
}

/// Upper tail `Q(h) = P(S > h)` of a standard normal `S`: relative error
/// ~1e-15 for every `h` down to the underflow of `Q` near `h = 38.5`
/// (then 0), and `1 - Q(-h)` for `h < 0`.
pub fn tail(h: f64) -> f64 {
    if h.is_nan() {
        return f64::NAN;
    }
    if h >= 0.0 {
        pdf(h) * scaled_r0(h)
    } else {
        1.0 - pdf(h) * scaled_r0(-h)
    }
}

/// Lower distribution function `Phi(h) = P(S <= h) = Q(-h)`.
pub fn cdf(h: f64) -> f64 {
    tail(-h)
}

/// Complementary error function `erfc(x) = 2 Q(x sqrt 2)`, relative
/// accuracy ~1e-15 down to its underflow near `x = 27.2`: for `x >= 0`
/// `erfc(x) = sqrt(2/pi) exp(-x^2) R_0(x sqrt 2)` with `exp(-x^2)` formed
/// exactly (rounding `x sqrt 2` only perturbs the slowly varying `R_0`).
pub fn erfc(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x >= 0.0 {
        // exp(-x^2) = exp(-x^2/2)^2 keeps the exact exponent.
        let e = exp_minus_half_sq(x);
        SQRT_2_OVER_PI * scaled_r0(x * std::f64::consts::SQRT_2) * e * e
    } else {
        2.0 - erfc(-x)
    }
}

/// Scaled complementary error function `erfcx(x) = exp(x^2) erfc(x)` for
/// `x >= 0` (`sqrt(2/pi) R_0(x sqrt 2)`, no overflow); for `x < 0` it is
/// `exp(x^2) erfc(x)`, which overflows below `x ~ -26.6`.
pub fn erfcx(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x >= 0.0 {
        SQRT_2_OVER_PI * scaled_r0(x * std::f64::consts::SQRT_2)
    } else {
        let e = exp_minus_half_sq(x);
        2.0 / (e * e) - erfcx(-x)
    }
}

/// Inverse upper tail: `s` with `Q(s) = q`, for `q` in `(0, 1)`; `+inf` at
/// `q = 0`, `-inf` at `q = 1`, NaN outside. Acklam's rational initial guess
/// (relative 1e-9) polished by two Halley steps on the accurate [`tail`],
/// so the result is accurate to a few ulp also in the far tails.
pub fn inverse_tail(q: f64) -> f64 {
    if q.is_nan() || !(0.0..=1.0).contains(&q) {
        return f64::NAN;
    }
    if q == 0.0 {
        return f64::INFINITY;
    }
    if q == 1.0 {
        return f64::NEG_INFINITY;
    }
    // Lower-tail quantile of p = q is -s.
    let mut s = -acklam(q);
    for _ in 0..2 {
        let d = pdf(s);
        if d == 0.0 {
            break;
        }
        let u = (tail(s) - q) / d;
        let step = u / (1.0 + 0.5 * s * u);
        s += step;
    }
    s
}

/// Quantile `Phi^-1(p)`: `s` with `P(S <= s) = p`, accurate in both tails.
pub fn quantile(p: f64) -> f64 {
    if p < 0.5 {
        -inverse_tail(p)
    } else {
        inverse_tail(1.0 - p)
    }
}

/// Acklam's rational approximation to the normal quantile `Phi^-1(p)`
/// (relative error 1.15e-9), `p` in `(0, 1)`.
fn acklam(p: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969683028665376e+01,
        2.209460984245205e+02,
        -2.759285104469687e+02,
        1.383577518672690e+02,
        -3.066479806614716e+01,
        2.506628277459239e+00,
    ];
    const B: [f64; 5] = [
        -5.447609879822406e+01,
        1.615858368580409e+02,
        -1.556989798598866e+02,
        6.680131188771972e+01,
        -1.328068155288572e+01,
    ];
    const C: [f64; 6] = [
        -7.784894002430293e-03,
        -3.223964580411365e-01,
        -2.400758277161838e+00,
        -2.549732539343734e+00,
        4.374664141464968e+00,
        2.938163982698783e+00,
    ];
    const D: [f64; 4] = [
        7.784695709041462e-03,
        3.224671290700398e-01,
        2.445134137142996e+00,
        3.754408661907416e+00,
    ];
    const P_LOW: f64 = 0.02425;
    let tail_form = |q: f64| {
        let r = (-2.0 * q.ln()).sqrt();
        (((((C[0] * r + C[1]) * r + C[2]) * r + C[3]) * r + C[4]) * r + C[5])
            / ((((D[0] * r + D[1]) * r + D[2]) * r + D[3]) * r + 1.0)
    };
    if p < P_LOW {
        tail_form(p)
    } else if p <= 1.0 - P_LOW {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    } else {
        -tail_form(1.0 - p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn batch_pdf_is_the_scalar_pdf_to_4e_16() {
        let h: Vec<f64> = (0..=80_000)
            .map(|i| -40.0 + 1e-3 * i as f64 + 1.234e-7)
            .chain([
                0.0,
                -0.0,
                f64::INFINITY,
                f64::NEG_INFINITY,
                38.5,
                38.6,
                38.7,
            ])
            .collect();
        let mut out = vec![0.0; h.len()];
        pdf_batch(&h, &mut out);
        for (&x, &v) in h.iter().zip(&out) {
            let p = pdf(x);
            if p >= f64::MIN_POSITIVE {
                assert!((v / p - 1.0).abs() <= 4e-16, "{x}: {v} vs {p}");
            } else {
                assert!(v.abs() <= 4.0 * f64::MIN_POSITIVE, "{x}: {v} vs {p}");
            }
        }
        let mut nan = [0.0];
        pdf_batch(&[f64::NAN], &mut nan);
        assert!(nan[0].is_nan());
        // exp_lane on its own range, against the library's exp.
        for i in 0..=746_000 {
            let y = -1e-3 * i as f64;
            let (a, b) = (exp_lane(y), y.exp());
            if b >= f64::MIN_POSITIVE {
                assert!((a / b - 1.0).abs() <= 4e-16, "{y}: {a} vs {b}");
            }
        }
    }
}
