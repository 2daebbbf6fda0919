//! The standard normal distribution with relative accuracy in the tails.
//!
//! Everything rests on the scaled Mills ratio `R_0(h) = Q(h)/phi(h)`
//! (`h >= 0`), evaluated without cancellation: `R_0 = R_2 + h R_1` (both
//! terms positive) with `R_1`, `R_2` the scaled Gaussian integrals of
//! [`gaussian_fn`](super::gaussian_fn) (Chebyshev pieces on `[0, 20)`, the
//! asymptotic series beyond). The density's exponent `h^2/2` is formed
//! exactly (Dekker's exact product gives the rounding error of `h*h`), so `phi(h)` keeps
//! full relative accuracy up to its underflow at `h ~ 38.6`.

use super::scaled::{r_asymptotic, scaled_integer_top, TABLE_HI};

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
    crate::numeric::simd::arch().dispatch(PdfBatch { h, out });
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

/// `exp(y[i])` into `out[i]` for `y[i]` in `[-700, 700]` (the shorter
/// slice bounds the work), in vector registers as [`pdf_batch`]:
/// `exp_lane`, relative error ~2 ulp (unit test).
pub(crate) fn exp_batch(y: &[f64], out: &mut [f64]) {
    crate::numeric::simd::arch().dispatch(ExpBatch { y, out });
}

struct ExpBatch<'a> {
    y: &'a [f64],
    out: &'a mut [f64],
}

impl pulp::WithSimd for ExpBatch<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        for (o, &y) in self.out.iter_mut().zip(self.y) {
            *o = exp_lane(y);
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
    const INV_FACT: &[f64; 14] = &crate::numeric::INV_FACTORIAL;
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
    if h < TABLE_HI {
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
/// `q = 0`, `-inf` at `q = 1`, NaN outside: `s = -Phi^-1(q)` by
/// Wichura's AS 241 (`ppnd16`; no cancellation: its central form takes `q - 1/2`, its
/// tails `min(q, 1 - q)`, both exact), polished by one Halley step on the
/// accurate [`tail`] where `min(q, 1 - q) < 1e-10`.
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
    let mut s = -ppnd16(q);
    // Beyond |s| = 6.4 (q < 1e-10 either side) a relative error e of s
    // moves the tail by ~s^2 e: one Halley step on the accurate tail keeps
    // Q(s) = q to ~1e-15 out to q = 1e-300 (tests/it/heights.rs round trips).
    if !(q.min(1.0 - q) >= 1e-10) {
        let d = pdf(s);
        if d > 0.0 {
            let u = if q <= 0.5 {
                (tail(s) - q) / d
            } else {
                // Q(s) - q = (1 - q) - P(S <= s) = (1 - q) - Q(-s)
                ((1.0 - q) - tail(-s)) / d
            };
            s += u / (1.0 + 0.5 * s * u);
        }
    }
    s
}

/// Quantile `Phi^-1(p)`: `s` with `P(S <= s) = p`, accurate in both tails
/// (Wichura's AS 241; `-inf`/`+inf` at 0/1, NaN outside `[0, 1]`).
pub fn quantile(p: f64) -> f64 {
    -inverse_tail(p)
}

/// Wichura's algorithm AS 241 (PPND16) for `Phi^-1(p)`, `p` in `(0, 1)`:
/// a ratio of degree-7 polynomials in `r = 0.180625 - (p - 1/2)^2` for
/// `|p - 1/2| <= 0.425`, else in `r = sqrt(-ln min(p, 1 - p))` (shifted by
/// 1.6 for `r <= 5`, by 5 beyond), "accurate to about 1 part in 10^16"
/// down to `p = 1e-300` (Wichura, Appl. Statist. 37 (1988) 477-484; the
/// coefficients as in CPython's `statistics.NormalDist.inv_cdf`). Measured
/// against mpmath: `tests/it/gaussian_fn.rs` `normal_quantile_matches_mpmath`.
/// About 15 ns (one `ln`, one `sqrt`, one division), a tenth of the
/// Halley-polished Acklam guess it replaced in the Monte Carlo draws.
#[inline]
fn ppnd16(p: f64) -> f64 {
    let q = p - 0.5;
    if q.abs() <= 0.425 {
        let r = 0.180625 - q * q;
        let num = (((((((2.509_080_928_730_122_7e3 * r + 3.343_057_558_358_812_8e4) * r
            + 6.726_577_092_700_870_0e4)
            * r
            + 4.592_195_393_154_987_1e4)
            * r
            + 1.373_169_376_550_946_1e4)
            * r
            + 1.971_590_950_306_551_4e3)
            * r
            + 1.331_416_678_917_843_8e2)
            * r
            + 3.387_132_872_796_366_6)
            * q;
        let den = ((((((5.226_495_278_852_854_6e3 * r + 2.872_908_573_572_194_3e4) * r
            + 3.930_789_580_009_271_0e4)
            * r
            + 2.121_379_430_158_659_6e4)
            * r
            + 5.394_196_021_424_751_1e3)
            * r
            + 6.871_870_074_920_579_1e2)
            * r
            + 4.231_333_070_160_091_1e1)
            * r
            + 1.0;
        return num / den;
    }
    let tail = if q <= 0.0 { p } else { 1.0 - p };
    let r = (-tail.ln()).sqrt();
    let x = if r <= 5.0 {
        let r = r - 1.6;
        let num = ((((((7.745_450_142_783_414_1e-4 * r + 2.272_384_498_926_918_5e-2) * r
            + 2.417_807_251_774_506_1e-1)
            * r
            + 1.270_458_252_452_368_4)
            * r
            + 3.647_848_324_763_204_6)
            * r
            + 5.769_497_221_460_691_4)
            * r
            + 4.630_337_846_156_545_3)
            * r
            + 1.423_437_110_749_683_6;
        let den = ((((((1.050_750_071_644_416_8e-9 * r + 5.475_938_084_995_344_9e-4) * r
            + 1.519_866_656_361_645_7e-2)
            * r
            + 1.481_039_764_274_800_7e-1)
            * r
            + 6.897_673_349_851_000_0e-1)
            * r
            + 1.676_384_830_183_803_8)
            * r
            + 2.053_191_626_637_758_8)
            * r
            + 1.0;
        num / den
    } else {
        let r = r - 5.0;
        let num = ((((((2.010_334_399_292_288_1e-7 * r + 2.711_555_568_743_487_6e-5) * r
            + 1.242_660_947_388_078_4e-3)
            * r
            + 2.653_218_952_657_612_3e-2)
            * r
            + 2.965_605_718_285_048_9e-1)
            * r
            + 1.784_826_539_917_291_3)
            * r
            + 5.463_784_911_164_114_4)
            * r
            + 6.657_904_643_501_103_8;
        let den = ((((((2.044_263_103_389_939_8e-15 * r + 1.421_511_758_316_445_9e-7) * r
            + 1.846_318_317_510_054_7e-5)
            * r
            + 7.868_691_311_456_132_6e-4)
            * r
            + 1.487_536_129_085_061_5e-2)
            * r
            + 1.369_298_809_227_358_1e-1)
            * r
            + 5.998_322_065_558_879_4e-1)
            * r
            + 1.0;
        num / den
    };
    if q < 0.0 {
        -x
    } else {
        x
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

    /// `exp_batch` on its documented range, both signs, against the
    /// library's `exp` (each within 2 ulp of the true value: 4e-16).
    #[test]
    fn batch_exp_is_the_library_exp_to_4e_16() {
        let y: Vec<f64> = (0..=140_000)
            .map(|i| -700.0 + 1e-2 * i as f64 + 3.21e-9)
            .collect();
        let mut out = vec![0.0; y.len()];
        exp_batch(&y, &mut out);
        for (&y, &v) in y.iter().zip(&out) {
            let e = y.exp();
            assert!((v / e - 1.0).abs() <= 4e-16, "{y}: {v} vs {e}");
        }
    }
}
