//! Bracketed scalar root finding and minimisation.

/// Root of `f` in `[lo, hi]` where `f(lo)` and `f(hi)` have opposite signs
/// (or one is zero), by Brent's method (inverse quadratic interpolation
/// safeguarded by bisection). Converges to `|hi - lo| <= xtol` (absolute)
/// plus a few ulps. Returns `None` when the bracket does not change sign or
/// an end is NaN.
pub fn brent<F: FnMut(f64) -> f64>(mut f: F, lo: f64, hi: f64, xtol: f64) -> Option<f64> {
    let (mut a, mut b) = (lo, hi);
    let (mut fa, mut fb) = (f(a), f(b));
    if fa.is_nan() || fb.is_nan() {
        return None;
    }
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    if fa.signum() == fb.signum() {
        return None;
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * xtol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Some(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = d;
            }
        } else {
            d = m;
            e = d;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
        if fb.is_nan() {
            return None;
        }
    }
    Some(b)
}

/// [`brent`] of a fallible `f`: the first error of `f` ends the search
/// (no further evaluation) and is returned; otherwise `brent`'s answer.
///
/// # Errors
/// The first error `f` returns.
pub fn try_brent(
    mut f: impl FnMut(f64) -> crate::Result<f64>,
    lo: f64,
    hi: f64,
    xtol: f64,
) -> crate::Result<Option<f64>> {
    let mut failure = None;
    let root = brent(
        |x| {
            if failure.is_some() {
                return f64::NAN;
            }
            f(x).unwrap_or_else(|e| {
                failure = Some(e);
                f64::NAN
            })
        },
        lo,
        hi,
        xtol,
    );
    match failure {
        Some(e) => Err(e),
        None => Ok(root),
    }
}

/// Minimum of a unimodal `f` on `[lo, hi]` by golden-section search, to an
/// absolute abscissa tolerance `xtol`. Returns `(x_min, f(x_min))`.
pub fn golden_min<F: FnMut(f64) -> f64>(mut f: F, lo: f64, hi: f64, xtol: f64) -> (f64, f64) {
    const G: f64 = 0.618_033_988_749_894_9; // (sqrt 5 - 1)/2
    let (mut a, mut b) = (lo, hi);
    let mut x1 = b - G * (b - a);
    let mut x2 = a + G * (b - a);
    let (mut f1, mut f2) = (f(x1), f(x2));
    while (b - a).abs() > xtol {
        if f1 <= f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - G * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + G * (b - a);
            f2 = f(x2);
        }
    }
    if f1 <= f2 {
        (x1, f1)
    } else {
        (x2, f2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_finds_roots_to_tolerance() {
        let r = brent(|x| x * x * x - 2.0, 0.0, 2.0, 1e-15).unwrap();
        assert!((r - 2f64.cbrt()).abs() < 1e-15);
        let r = brent(|x| x.cos() - x, 0.0, 1.0, 1e-14).unwrap();
        assert!((r - 0.739_085_133_215_160_6).abs() < 1e-14);
        assert!(brent(|x| x * x + 1.0, -1.0, 1.0, 1e-12).is_none());
        assert!(brent(|_| f64::NAN, -1.0, 1.0, 1e-12).is_none());
    }

    #[test]
    fn golden_finds_minimum() {
        // Golden section resolves a minimum only to ~sqrt(eps) relative:
        // f differences below eps |f| are invisible.
        let (x, fx) = golden_min(|x| (x - 0.3).powi(2) + 1.0, -2.0, 2.0, 1e-7);
        assert!((x - 0.3).abs() < 2e-7);
        assert!((fx - 1.0).abs() < 1e-15);
    }
}
