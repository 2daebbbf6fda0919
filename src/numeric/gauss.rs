//! Gauss–Legendre rules on `[0, 1]` with an error estimate from the same
//! nodes: the decay of the integrand's Legendre coefficients.
//!
//! The `n`-point rule is exact for polynomials of degree `2n - 1`. On
//! `[a, b]` with `x = (1 - z)/2` (`z` in `[-1, 1]`), `f = sum_k c_k P_k(z)`;
//! the rule's nodes give the coefficients of the interpolant exactly,
//! `c_k = (2k + 1) sum_i w_i P_k(z_i) f_i` (`w_i` the weights on `[0, 1]`,
//! summing to 1), and the rule's error is
//! `(b - a)/2 sum_{k >= 2n} c_k E_k` with `|E_k| <= 2`. Assuming the
//! coefficients fall geometrically, `|c_k| ~ C q^k`, from the last two
//! (`k = n-1, n-2`) and two in the middle (`k = n/2, n/2 - 1`) the
//! estimate is
//!
//! ```text
//! err ~ SAFETY (b - a) c_hi q^(n+1) / (1 - q),
//! c_hi = max(|c_{n-1}|, |c_{n-2}|),  q = (c_hi / c_mid)^(1/(n - 1 - n/2)) (<= 0.999)
//! ```
//!
//! (Trefethen, *Approximation Theory and Approximation Practice*, ch. 19:
//! Gauss quadrature converges like the Legendre coefficients at twice the
//! degree). Like QUADPACK's, the estimate is a heuristic; on the GW
//! integrands of `docs/performance.md` it exceeds the true error by 3 to
//! 100 times (unit test and `benches/peers/gw_curves_numpy.py`).

use std::sync::OnceLock;

/// Largest rule in the table.
pub const MAX_NODES: usize = 64;
/// Factor on the extrapolated tail of the Legendre coefficients.
const SAFETY: f64 = 4.0;

/// Lanes of [`GaussRule::sums`]: the padded length of its rows.
pub const LANES: usize = 8;

/// An `n`-point Gauss–Legendre rule on `[0, 1]` and the rows giving four
/// Legendre coefficients of the interpolant through its nodes.
#[derive(Debug, Clone)]
pub struct GaussRule {
    /// Nodes in `(0, 1)`, ascending.
    pub x: Vec<f64>,
    /// Weights, summing to 1.
    pub w: Vec<f64>,
    /// `(2k + 1) w_i P_k(1 - 2 x_i)` for `k = n-1, n-2, n/2, n/2 - 1`
    /// (empty rows for `n < 4`).
    pub rows: [Vec<f64>; 4],
    /// The weights and the four rows, each padded with zeros to a
    /// multiple of [`LANES`].
    padded: [Vec<f64>; 5],
    /// `1/m`, `m = n - 1 - n/2`: the exponent of the coefficient ratio in the
    /// estimate.
    inv_m: f64,
}

impl GaussRule {
    fn new(n: usize) -> GaussRule {
        let nf = n as f64;
        let mut x = vec![0.0; n];
        let mut w = vec![0.0; n];
        for i in 0..n {
            // Tricomi's initial guess, then Newton on P_n (largest z first,
            // so x ascends).
            let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (p, pm) = legendre_pair(n, z);
                dp = nf * (z * p - pm) / (z * z - 1.0);
                let dz = p / dp;
                z -= dz;
                if dz.abs() < 1e-16 {
                    break;
                }
            }
            let (p, pm) = legendre_pair(n, z);
            if z * z < 1.0 {
                dp = nf * (z * p - pm) / (z * z - 1.0);
            }
            x[i] = 0.5 * (1.0 - z);
            w[i] = 1.0 / ((1.0 - z * z) * dp * dp);
        }
        let ks = if n >= 4 {
            [n - 1, n - 2, n / 2, n / 2 - 1]
        } else {
            [0; 4]
        };
        let rows = ks.map(|k| {
            if n < 4 {
                return Vec::new();
            }
            (0..n)
                .map(|i| {
                    let z = 1.0 - 2.0 * x[i];
                    (2.0 * k as f64 + 1.0) * w[i] * legendre(k, z)
                })
                .collect()
        });
        let pad = n.div_ceil(LANES) * LANES;
        let padded = std::array::from_fn(|r| {
            let src = if r == 0 { &w } else { &rows[r - 1] };
            let mut v = src.clone();
            v.resize(pad, 0.0);
            v
        });
        let m = (n.max(4) - 1 - n.max(4) / 2) as f64;
        GaussRule {
            x,
            w,
            rows,
            padded,
            inv_m: 1.0 / m,
        }
    }

    /// `(sum w_i f_i, sum w_i |f_i|, c)` over the rule's nodes (`f` has
    /// at least `n` values; the rest are ignored), `c` the four coefficient
    /// sums of [`GaussRule::estimate`]; summed in [`LANES`] partial sums
    /// (vector registers), then across them.
    #[inline(always)]
    pub fn sums(&self, f: &[f64]) -> (f64, f64, [f64; 4]) {
        let n = self.len();
        let f = &f[..n];
        let [w, r0, r1, r2, r3] = &self.padded;
        let mut acc = [[0.0f64; LANES]; 6];
        let full = n / LANES * LANES;
        let mut tail = [0.0; LANES];
        tail[..n - full].copy_from_slice(&f[full..]);
        for c in (0..full + LANES * usize::from(full < n)).step_by(LANES) {
            let x: &[f64; LANES] = if c < full {
                f[c..c + LANES].try_into().expect("a full chunk")
            } else {
                &tail
            };
            let w: &[f64; LANES] = w[c..c + LANES].try_into().expect("padded");
            let r0: &[f64; LANES] = r0[c..c + LANES].try_into().expect("padded");
            let r1: &[f64; LANES] = r1[c..c + LANES].try_into().expect("padded");
            let r2: &[f64; LANES] = r2[c..c + LANES].try_into().expect("padded");
            let r3: &[f64; LANES] = r3[c..c + LANES].try_into().expect("padded");
            for l in 0..LANES {
                let x = x[l];
                acc[0][l] += w[l] * x;
                acc[1][l] += w[l] * x.abs();
                acc[2][l] += r0[l] * x;
                acc[3][l] += r1[l] * x;
                acc[4][l] += r2[l] * x;
                acc[5][l] += r3[l] * x;
            }
        }
        let total =
            |a: &[f64; LANES]| ((a[0] + a[4]) + (a[1] + a[5])) + ((a[2] + a[6]) + (a[3] + a[7]));
        (
            total(&acc[0]),
            total(&acc[1]),
            [
                total(&acc[2]),
                total(&acc[3]),
                total(&acc[4]),
                total(&acc[5]),
            ],
        )
    }

    /// Nodes.
    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// Whether the rule has no nodes.
    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }

    /// Error estimate (module docs) of the rule over a piece of width
    /// `width` from the four coefficient sums `c = rows . f`, or a bound
    /// on it when that bound is at most `enough`: with `q <= 0.999`,
    /// `q^c/(1 - q) <= 1000`, so `1000 SAFETY width c_hi r^2` (no root to
    /// take) bounds the estimate.
    #[inline(always)]
    pub fn estimate(&self, width: f64, c: [f64; 4], enough: f64) -> f64 {
        let n = self.len();
        if n < 4 {
            return f64::INFINITY;
        }
        let hi = c[0].abs().max(c[1].abs());
        let mid = c[2].abs().max(c[3].abs());
        if hi == 0.0 {
            return 0.0;
        }
        // q = r^(1/m), r = hi/mid, m = n - 1 - n/2; q^(n+1) = r^2 q^3
        // (n even, n + 1 = 2m + 3) or r^2 q^2 (n odd, n + 1 = 2m + 2).
        let r = if mid > 0.0 { (hi / mid).min(1.0) } else { 1.0 };
        let bound = 1000.0 * SAFETY * width * hi * (r * r);
        if bound <= enough {
            return bound;
        }
        let q = exp2_approx(log2_approx(r) * self.inv_m).min(0.999);
        let q_c = if n.is_multiple_of(2) {
            q * q * q
        } else {
            q * q
        };
        SAFETY * width * hi * (r * r * q_c) / (1.0 - q)
    }
}

/// `log2(x)` for positive normal `x` within 2e-6 (exponent bits plus
/// `2 atanh` of the mantissa's offset from `sqrt 2`, three terms): only
/// for error estimates. `-1100` for 0 and subnormals.
#[inline]
fn log2_approx(x: f64) -> f64 {
    if !(x >= f64::MIN_POSITIVE) {
        return if x >= 0.0 { -1100.0 } else { f64::NAN };
    }
    let bits = x.to_bits();
    let e = ((bits >> 52) & 0x7ff) as i64 - 1023;
    let m = f64::from_bits((bits & ((1u64 << 52) - 1)) | (1023u64 << 52)); // [1, 2)
    let (m, e) = if m > std::f64::consts::SQRT_2 {
        (0.5 * m, e + 1)
    } else {
        (m, e)
    };
    let z = (m - 1.0) / (m + 1.0); // |z| <= 0.172
    let z2 = z * z;
    let ln_m = 2.0 * z * (1.0 + z2 * (1.0 / 3.0 + z2 * (0.2 + z2 / 7.0)));
    e as f64 + ln_m * std::f64::consts::LOG2_E
}

/// `2^y` within 1e-7 relative for `-1000 < y <= 0` (0 below): only for
/// error estimates.
#[inline]
fn exp2_approx(y: f64) -> f64 {
    if !(y > -1000.0) {
        return 0.0;
    }
    // k = floor(y) without a library call (y > -1000).
    let k = (y + 1024.0) as i64 - 1024;
    // r in [0, ln 2); exp(r) by Taylor to r^9/9! (remainder < 4e-9 relative).
    let r = (y - k as f64) * std::f64::consts::LN_2;
    const INV_FACT: &[f64; 14] = &super::INV_FACTORIAL;
    let mut p = INV_FACT[9];
    for c in INV_FACT[..9].iter().rev() {
        p = p * r + c;
    }
    // 2^k, normal for k >= -1022 (below: 0, negligible in an estimate).
    let two_k = if k >= -1022 {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        0.0
    };
    p * two_k
}

/// `(P_n(z), P_{n-1}(z))` by the three-term recurrence.
fn legendre_pair(n: usize, z: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0f64, z);
    if n == 0 {
        return (1.0, 0.0);
    }
    for k in 2..=n {
        let kf = k as f64;
        let p2 = ((2.0 * kf - 1.0) * z * p1 - (kf - 1.0) * p0) / kf;
        p0 = p1;
        p1 = p2;
    }
    (p1, p0)
}

/// `P_k(z)`.
fn legendre(k: usize, z: f64) -> f64 {
    legendre_pair(k, z).0
}

/// The `n`-point rule (`1 <= n <= MAX_NODES`), built on first use (each
/// size on its own: building all 64 at once cost a run 5 ms of start-up).
pub fn gauss_rule(n: usize) -> &'static GaussRule {
    static TABLE: [OnceLock<GaussRule>; MAX_NODES + 1] = [const { OnceLock::new() }; MAX_NODES + 1];
    let n = n.clamp(1, MAX_NODES);
    TABLE[n].get_or_init(|| GaussRule::new(n))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_integrate_polynomials_of_degree_2n_minus_1() {
        for n in [1, 2, 3, 4, 7, 16, 33, 64] {
            let r = gauss_rule(n);
            assert_eq!(r.len(), n);
            for deg in [0, n, 2 * n - 1] {
                // int_0^1 x^deg = 1/(deg + 1)
                let q: f64 =
                    r.x.iter()
                        .zip(&r.w)
                        .map(|(x, w)| w * x.powi(deg as i32))
                        .sum();
                assert!(
                    (q * (deg as f64 + 1.0) - 1.0).abs() < 1e-13,
                    "n {n} deg {deg}: {q}"
                );
            }
            assert!(r.x.windows(2).all(|p| p[0] < p[1]));
        }
    }

    /// The rows give the interpolant's Legendre coefficients: exact for a
    /// polynomial of degree < n (here `P_{n-1}` itself, shifted).
    #[test]
    fn rows_recover_legendre_coefficients() {
        let n = 12;
        let r = gauss_rule(n);
        let f: Vec<f64> = r
            .x
            .iter()
            .map(|&x| 3.0 * legendre(n - 1, 1.0 - 2.0 * x) - 0.5 * legendre(n / 2, 1.0 - 2.0 * x))
            .collect();
        let c: Vec<f64> = r
            .rows
            .iter()
            .map(|row| row.iter().zip(&f).map(|(a, b)| a * b).sum())
            .collect();
        assert!((c[0] - 3.0).abs() < 1e-12, "{c:?}");
        assert!(c[1].abs() < 1e-12, "{c:?}");
        assert!((c[2] + 0.5).abs() < 1e-12, "{c:?}");
        assert!(c[3].abs() < 1e-12, "{c:?}");
    }

    #[test]
    fn approximate_logarithm_and_power_of_two() {
        for x in [1e-300, 1e-20, 0.3, 0.7, 0.708, 1.0, 1.5, 2.0, 1e10] {
            assert!((log2_approx(x) - x.log2()).abs() < 2e-6, "{x}");
        }
        for y in [-900.5, -60.25, -3.7, -1.0, -0.01, 0.0] {
            assert!((exp2_approx(y) / y.exp2() - 1.0).abs() < 1e-7, "{y}");
        }
        assert_eq!(exp2_approx(-2000.0), 0.0);
    }

    #[test]
    fn lane_sums_are_the_rule() {
        for n in [4, 8, 13, 22] {
            let r = gauss_rule(n);
            let f: Vec<f64> = r.x.iter().map(|x| (3.0 * x).sin() - 0.4).collect();
            let (v, m, c) = r.sums(&f);
            let v0: f64 = r.w.iter().zip(&f).map(|(w, f)| w * f).sum();
            let m0: f64 = r.w.iter().zip(&f).map(|(w, f)| w * f.abs()).sum();
            assert!((v - v0).abs() < 1e-15 && (m - m0).abs() < 1e-15);
            for (k, row) in r.rows.iter().enumerate() {
                let ck: f64 = row.iter().zip(&f).map(|(a, b)| a * b).sum();
                assert!((c[k] - ck).abs() < 1e-14, "n {n} k {k}");
            }
        }
    }

    /// On an analytic integrand the estimate bounds the true error without
    /// being wildly pessimistic: `int_0^3 exp(-(t^2 - 1)^2/2) 2t dt`
    /// (a Gaussian density in `t = sqrt(s + 1)`), reference by 64 nodes.
    #[test]
    fn estimate_bounds_the_error_of_a_gaussian_in_the_root() {
        let f = |t: f64| 2.0 * t * (-0.5 * (t * t - 1.0) * (t * t - 1.0)).exp();
        let rule_sum = |n: usize| {
            let r = gauss_rule(n);
            let vals: Vec<f64> = r.x.iter().map(|&x| f(3.0 * x)).collect();
            let v: f64 = 3.0 * r.w.iter().zip(&vals).map(|(w, v)| w * v).sum::<f64>();
            let c = r
                .rows
                .clone()
                .map(|row| row.iter().zip(&vals).map(|(a, b)| a * b).sum::<f64>());
            (v, r.estimate(3.0, c, 0.0))
        };
        let (exact, _) = rule_sum(64);
        for n in [8, 10, 12, 16, 20, 24] {
            let (v, e) = rule_sum(n);
            let err = (v - exact).abs();
            assert!(err <= e, "n {n}: error {err:e} above the estimate {e:e}");
            assert!(e < 1e4 * err.max(1e-15 * exact), "n {n}: {e:e} for {err:e}");
        }
    }
}
