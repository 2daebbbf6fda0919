//! Chebyshev series evaluation (Clenshaw). Plain multiply-adds: without a
//! target FMA feature `f64::mul_add` is a slow library call.

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
/// same operations per lane as [`clenshaw`], so the same bits.
#[inline(always)]
pub fn clenshaw_lanes<const D: usize, const L: usize>(
    x: &[f64; L],
    c: impl Fn(usize, usize) -> f64,
) -> [f64; L] {
    let mut b1 = [0.0; L];
    let mut b2 = [0.0; L];
    let x2 = x.map(|t| 2.0 * t);
    for j in (1..=D).rev() {
        for l in 0..L {
            let b = x2[l] * b1[l] - b2[l] + c(l, j);
            b2[l] = b1[l];
            b1[l] = b;
        }
    }
    std::array::from_fn(|l| x[l] * b1[l] - b2[l] + c(l, 0))
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
