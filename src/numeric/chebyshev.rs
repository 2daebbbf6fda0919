//! Chebyshev series evaluation (Clenshaw), and the power-basis form of a
//! short series with Horner's rule. Plain multiply-adds: without a target
//! FMA feature `f64::mul_add` is a slow library call. The interpolant at
//! the Chebyshev–Lobatto nodes ([`lobatto_nodes`], [`lobatto_coefficients`])
//! gives the series.

use std::f64::consts::PI;

/// The `N` Chebyshev–Lobatto nodes `cos(pi k / (N - 1))`, `k = 0..N`, on
/// `[-1, 1]`, descending (`N >= 2`).
pub fn lobatto_nodes<const N: usize>() -> [f64; N] {
    let deg = N - 1;
    std::array::from_fn(|k| (PI * k as f64 / deg as f64).cos())
}

/// Coefficients `c_j` of `sum' c_j T_j` (degree `N - 1`) interpolating `f`
/// at the `N` Lobatto nodes of [`lobatto_nodes`]: a DCT-I, the first and
/// last coefficients halved.
pub fn lobatto_coefficients<const N: usize>(f: &[f64; N]) -> [f64; N] {
    let deg = N - 1;
    let n = deg as f64;
    std::array::from_fn(|j| {
        let mut s = 0.0;
        for (k, fk) in f.iter().enumerate() {
            let w = if k == 0 || k == deg { 0.5 } else { 1.0 };
            s += w * fk * (PI * (j * k) as f64 / n).cos();
        }
        let c = 2.0 * s / n;
        if j == 0 || j == deg {
            0.5 * c
        } else {
            c
        }
    })
}

/// `sum_j c_j T_j(x)` for `x` in `[-1, 1]` by Clenshaw's recurrence.
#[inline]
pub fn clenshaw<const N: usize>(c: &[f64; N], x: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    let x2 = 2.0 * x;
    for &cj in c[1..].iter().rev() {
        let b = x2 * b1 - b2 + cj;
        b2 = b1;
        b1 = b;
    }
    x * b1 - b2 + c[0]
}

/// [`clenshaw`] of degree `D` in `L` lanes: `clenshaw(c_l, x[l])` for
/// every lane `l`, coefficient `j` of lane `l` given by `c(l, j)`, with
/// the recurrences interleaved (independent chains in flight instead of
/// one latency-bound chain; in SIMD lanes inside a `pulp` operation): the
/// same operations per lane as [`clenshaw`], so the same bits. The degree
/// fixed at compile time; [`clenshaw_lanes_dyn`] is the same sum with the
/// degree given at run time.
#[inline(always)]
pub fn clenshaw_lanes<const D: usize, const L: usize>(
    x: &[f64; L],
    c: impl Fn(usize, usize) -> f64,
) -> [f64; L] {
    clenshaw_lanes_dyn(D, x, c)
}

/// [`clenshaw_lanes`] of degree `degree` given at run time (a series of
/// `degree + 1` coefficients `c(l, 0..=degree)`, e.g. an interpolant
/// whose order is chosen by its error estimate):
/// `b_j = 2 x b_(j+1) - b_(j+2) + c_j` from `j = degree` down to 1, then
/// `x b_1 - b_2 + c_0` (Clenshaw 1955). The one lane recurrence: the same
/// operations per lane as [`clenshaw`], so the same bits.
#[inline(always)]
pub fn clenshaw_lanes_dyn<const L: usize>(
    degree: usize,
    x: &[f64; L],
    c: impl Fn(usize, usize) -> f64,
) -> [f64; L] {
    let mut b1 = [0.0; L];
    let mut b2 = [0.0; L];
    let x2 = x.map(|t| 2.0 * t);
    for j in (1..=degree).rev() {
        for l in 0..L {
            let b = x2[l] * b1[l] - b2[l] + c(l, j);
            b2[l] = b1[l];
            b1[l] = b;
        }
    }
    std::array::from_fn(|l| x[l] * b1[l] - b2[l] + c(l, 0))
}

/// Power-basis coefficients `a_k` of `sum_j c_j T_j(x) = sum_k a_k x^k`
/// (from `T_(j+1) = 2 x T_j - T_(j-1)`, whose integer coefficients are
/// exact). Well conditioned at low degree on `[-1, 1]`:
/// `sum_k |a_k| <= (1 + sqrt 2)^(N-1) max_j |c_j|` (about 200 at `N = 7`).
pub fn monomial_coefficients<const N: usize>(c: &[f64; N]) -> [f64; N] {
    let mut a = [0.0; N];
    // T_(j-1) and T_j as power-basis coefficients.
    let (mut prev, mut cur) = ([0.0; N], [0.0; N]);
    for (j, &cj) in c.iter().enumerate() {
        let next = match j {
            0 => std::array::from_fn(|k| if k == 0 { 1.0 } else { 0.0 }),
            1 => std::array::from_fn(|k| if k == 1 { 1.0 } else { 0.0 }),
            _ => std::array::from_fn(|k| {
                let up = if k > 0 { 2.0 * cur[k - 1] } else { 0.0 };
                up - prev[k]
            }),
        };
        for k in 0..N {
            a[k] += cj * next[k];
        }
        (prev, cur) = (cur, next);
    }
    a
}

/// `sum_k a_k x^k` by Horner's rule, `p = p x + a_k` from the top
/// coefficient down (a multiply and an add per degree).
#[inline]
pub fn horner<const N: usize>(a: &[f64; N], x: f64) -> f64 {
    let mut p = a[N - 1];
    for k in (0..N - 1).rev() {
        p = p * x + a[k];
    }
    p
}

/// [`horner`] in `L` lanes: `horner(a_l, x[l])` for every lane `l`,
/// coefficient `k` of lane `l` given by `a(l, k)`, the chains interleaved
/// (in SIMD lanes inside a `pulp` operation): the same operations per lane
/// as [`horner`], so the same bits.
#[inline(always)]
pub fn horner_lanes<const N: usize, const L: usize>(
    x: &[f64; L],
    a: impl Fn(usize, usize) -> f64,
) -> [f64; L] {
    let mut p: [f64; L] = std::array::from_fn(|l| a(l, N - 1));
    for k in (0..N - 1).rev() {
        for l in 0..L {
            p[l] = p[l] * x[l] + a(l, k);
        }
    }
    p
}

/// Evaluates a table of unit-width pieces starting at `lo` at `h`
/// (`lo <= h < lo + pieces`).
#[inline]
pub fn piecewise<const N: usize, const P: usize>(t: &[[f64; N]; P], lo: f64, h: f64) -> f64 {
    let y = h - lo;
    // `y` is in [0, P); the min guards the last piece's right end.
    let i = (y as usize).min(P - 1);
    let x = 2.0 * (y - i as f64) - 1.0;
    clenshaw(&t[i], x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_basis_is_the_chebyshev_series() {
        // T_6 = 32 x^6 - 48 x^4 + 18 x^2 - 1 exactly.
        let t6 = monomial_coefficients(&[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
        assert_eq!(t6, [-1.0, 0.0, 18.0, 0.0, -48.0, 0.0, 32.0]);
        let c = [0.7, -1.3, 0.25, 2e-3, -4e-5, 6e-7, -8e-9];
        let a = monomial_coefficients(&c);
        for k in 0..=40 {
            let x = -1.0 + k as f64 / 20.0;
            let (p, q) = (horner(&a, x), clenshaw(&c, x));
            assert!((p - q).abs() <= 1e-15 * 4.0, "{x}: {p} {q}");
        }
    }

    /// Three series of degree 6 for the lane tests (either basis): mixed
    /// signs, tiny coefficients, a sparse one.
    const LANE_SERIES: [[f64; 7]; 3] = [
        [0.1, -0.2, 0.3, -0.4, 0.5, -0.6, 0.7],
        [1e-7, 3e-8, -2e-9, 1e-10, 5e-12, -1e-13, 2e-15],
        [-3.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1e-3],
    ];

    /// A point in `[-1, 1]` per lane.
    const LANE_POINTS: [f64; 3] = [0.3, -0.999, 0.123456789];

    #[test]
    fn clenshaw_lanes_are_clenshaw_bit_for_bit() {
        let (c, x) = (LANE_SERIES, LANE_POINTS);
        let fixed = clenshaw_lanes::<6, 3>(&x, |l, j| c[l][j]);
        let dynamic = clenshaw_lanes_dyn(6, &x, |l, j| c[l][j]);
        for l in 0..3 {
            assert_eq!(fixed[l].to_bits(), clenshaw(&c[l], x[l]).to_bits());
            assert_eq!(dynamic[l].to_bits(), fixed[l].to_bits());
        }
    }

    #[test]
    fn horner_lanes_are_horner_bit_for_bit() {
        let (a, x) = (LANE_SERIES, LANE_POINTS);
        let v = horner_lanes::<7, 3>(&x, |l, k| a[l][k]);
        for l in 0..3 {
            assert_eq!(v[l].to_bits(), horner(&a[l], x[l]).to_bits());
        }
    }
}
