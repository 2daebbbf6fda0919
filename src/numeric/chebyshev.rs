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
