//! A measured axisymmetric profile: columns `r` (m) and `f(r)` (m),
//! interpolated by PCHIP (Fritsch–Butland slopes with Moler's shape-
//! preserving end slopes, the same interpolant as scipy's
//! `PchipInterpolator`), so `f` is C^1 and monotone between the nodes.
//!
//! Sneddon's integrals are taken in `r = a sin(u)`, where they have no
//! endpoint singularity, on the pieces between the nodes; on each piece
//! `f'` is a quadratic in `r`, so one 21-point Gauss–Kronrod panel is exact
//! to rounding:
//!
//! ```text
//! delta_0(a)   = a int_0^(pi/2) f'(a sin u) du
//! delta_0'(a)  =   int_0^(pi/2) [f'(a sin u) + a sin u f''(a sin u)] du
//! F_0(a)/(2E*) = a^2 int_0^(pi/2) sin^2 u f'(a sin u) du
//! ```

use crate::error::{Error, Result};
use crate::numeric::quadrature::kronrod21;

/// A validated, PCHIP-interpolated profile table.
#[derive(Debug, Clone, PartialEq)]
pub struct TabulatedProfile {
    r: Vec<f64>,
    f: Vec<f64>,
    /// PCHIP slopes `f'(r_i)`.
    d: Vec<f64>,
}

/// Largest jump of the chord slope between neighbouring intervals, as a
/// fraction of the largest chord slope: coarser tables are refused.
pub const MAX_SLOPE_JUMP: f64 = 0.5;

impl TabulatedProfile {
    /// Validates and interpolates a table: at least 3 points, all finite,
    /// `r` strictly increasing from `r_0 = 0`, `f_0 = 0` (heights measured
    /// from the apex), `f` non-decreasing (a monotone tip) with a positive
    /// last value, and smooth enough: no chord slope differs from its
    /// neighbour's by more than [`MAX_SLOPE_JUMP`] of the largest chord
    /// slope (a kink or a step means the table is too coarse).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `profile.r` or `profile.f` with the reason.
    pub fn new(r: Vec<f64>, f: Vec<f64>) -> Result<Self> {
        let n = r.len();
        if n < 3 || f.len() != n {
            return Err(Error::invalid(
                "profile.r",
                format!(
                    "needs >= 3 points and as many f values (got {n} r, {} f)",
                    f.len()
                ),
            ));
        }
        if let Some(i) = r.iter().position(|v| !v.is_finite()) {
            return Err(Error::invalid("profile.r", format!("r[{i}] is not finite")));
        }
        if let Some(i) = f.iter().position(|v| !v.is_finite()) {
            return Err(Error::invalid("profile.f", format!("f[{i}] is not finite")));
        }
        if r[0] != 0.0 || f[0] != 0.0 {
            return Err(Error::invalid(
                "profile.r",
                "the table must start at the apex: r[0] = 0 and f[0] = 0",
            ));
        }
        if let Some(i) = (1..n).find(|&i| !(r[i] > r[i - 1])) {
            return Err(Error::invalid(
                "profile.r",
                format!("r must increase strictly (r[{i}] = {})", r[i]),
            ));
        }
        if let Some(i) = (1..n).find(|&i| f[i] < f[i - 1]) {
            return Err(Error::invalid(
                "profile.f",
                format!("f must not decrease (f[{i}] = {} < f[{}])", f[i], i - 1),
            ));
        }
        if !(f[n - 1] > 0.0) {
            return Err(Error::invalid(
                "profile.f",
                "the profile is flat everywhere",
            ));
        }
        let h: Vec<f64> = r.windows(2).map(|w| w[1] - w[0]).collect();
        let del: Vec<f64> = (0..n - 1).map(|k| (f[k + 1] - f[k]) / h[k]).collect();
        let max_del = del.iter().cloned().fold(0.0, f64::max);
        if let Some(k) =
            (1..n - 1).find(|&k| (del[k] - del[k - 1]).abs() > MAX_SLOPE_JUMP * max_del)
        {
            return Err(Error::invalid(
                "profile.f",
                format!(
                    "not smooth enough: the slope jumps from {} to {} at r = {} m; \
                     tabulate more finely",
                    del[k - 1],
                    del[k],
                    r[k]
                ),
            ));
        }
        let d = crate::numeric::pchip::slopes(&h, &del);
        Ok(TabulatedProfile { r, f, d })
    }

    /// Last tabulated radius (m).
    pub fn max_radius(&self) -> f64 {
        self.r[self.r.len() - 1]
    }

    /// The radii (m) of the table.
    pub fn radii(&self) -> &[f64] {
        &self.r
    }

    /// The heights (m) of the table.
    pub fn heights(&self) -> &[f64] {
        &self.f
    }

    /// Interval index and local coordinate of `t` (clamped to the table).
    #[inline]
    fn locate(&self, t: f64) -> (usize, f64, f64) {
        let n = self.r.len();
        let k = (self.r.partition_point(|&v| v <= t).max(1) - 1).min(n - 2);
        let h = self.r[k + 1] - self.r[k];
        (k, h, ((t - self.r[k]) / h).clamp(0.0, 1.0))
    }

    /// `f(r)` (m); the last value beyond the table.
    pub fn height(&self, t: f64) -> f64 {
        let (k, h, s) = self.locate(t);
        let (y0, y1, d0, d1) = (self.f[k], self.f[k + 1], self.d[k] * h, self.d[k + 1] * h);
        let s2 = s * s;
        let s3 = s2 * s;
        (2.0 * s3 - 3.0 * s2 + 1.0) * y0
            + (s3 - 2.0 * s2 + s) * d0
            + (-2.0 * s3 + 3.0 * s2) * y1
            + (s3 - s2) * d1
    }

    /// `(f'(r), f''(r))` of the interpolant.
    #[inline]
    pub fn derivatives(&self, t: f64) -> (f64, f64) {
        let (k, h, s) = self.locate(t);
        let (y0, y1, d0, d1) = (self.f[k], self.f[k + 1], self.d[k] * h, self.d[k + 1] * h);
        let s2 = s * s;
        let dp = (6.0 * s2 - 6.0 * s) * (y0 - y1)
            + (3.0 * s2 - 4.0 * s + 1.0) * d0
            + (3.0 * s2 - 2.0 * s) * d1;
        let dpp = (12.0 * s - 6.0) * (y0 - y1) + (6.0 * s - 4.0) * d0 + (6.0 * s - 2.0) * d1;
        (dp / h, dpp / (h * h))
    }

    /// `int_0^(pi/2) g(u) du` split at the nodes `u_i = asin(r_i/a)`.
    fn angular<G: FnMut(f64) -> f64>(&self, a: f64, mut g: G) -> f64 {
        let mut lo = 0.0;
        let mut sum = 0.0;
        for &ri in self.r[1..].iter().take_while(|&&ri| ri < a) {
            let hi = (ri / a).asin();
            sum += kronrod21(&mut g, lo, hi).0;
            lo = hi;
        }
        sum + kronrod21(&mut g, lo, 0.5 * std::f64::consts::PI).0
    }

    /// `delta_0(a) = a int_0^(pi/2) f'(a sin u) du` (m).
    pub fn delta0(&self, a: f64) -> f64 {
        if !(a > 0.0) {
            return 0.0;
        }
        a * self.angular(a, |u| self.derivatives(a * u.sin()).0)
    }

    /// `d delta_0/da` (dimensionless).
    pub fn delta0_slope(&self, a: f64) -> f64 {
        if !(a > 0.0) {
            return self.d[0];
        }
        self.angular(a, |u| {
            let r = a * u.sin();
            let (d1, d2) = self.derivatives(r);
            d1 + r * d2
        })
    }

    /// `F_0(a)/(2E*) = a^2 int_0^(pi/2) sin^2 u f'(a sin u) du` (m^2).
    pub fn load_area(&self, a: f64) -> f64 {
        if !(a > 0.0) {
            return 0.0;
        }
        a * a
            * self.angular(a, |u| {
                let s = u.sin();
                s * s * self.derivatives(a * s).0
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::pchip::Pchip;

    fn parabola(n: usize) -> (Vec<f64>, Vec<f64>) {
        let r: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
        let f = r.iter().map(|x| x * x / 2.0).collect();
        (r, f)
    }

    #[test]
    fn matches_the_crate_pchip_and_its_own_derivative() {
        let (r, f) = parabola(41);
        let t = TabulatedProfile::new(r.clone(), f.clone()).unwrap();
        let p = Pchip::new(r, f).unwrap();
        for i in 0..100 {
            // Off the nodes: f'' jumps there, which spoils central differences.
            let x = (i as f64 + 0.37) / 100.0;
            assert!((t.height(x) - p.eval(x)).abs() < 1e-15);
            let e = 1e-6;
            let num = (t.height(x + e) - t.height(x - e)) / (2.0 * e);
            if x > e && x < 1.0 - e {
                let an = t.derivatives(x).0;
                assert!((num - an).abs() < 1e-8, "{x} {num} {an}");
            }
        }
    }

    #[test]
    fn a_finely_sampled_parabola_gives_hertz() {
        // R = 1: delta_0 = a^2, F_0/(2E*) = 2a^3/3; PCHIP error O(h^3) ~ 1e-6.
        let (r, f) = parabola(201);
        let t = TabulatedProfile::new(r, f).unwrap();
        for a in [0.1, 0.37, 0.8] {
            assert!((t.delta0(a) / (a * a) - 1.0).abs() < 1e-3, "{a}");
            assert!((t.load_area(a) / (2.0 * a * a * a / 3.0) - 1.0).abs() < 1e-3);
            assert!((t.delta0_slope(a) / (2.0 * a) - 1.0).abs() < 1e-2);
        }
    }

    #[test]
    fn rejects_bad_tables_naming_the_column() {
        let e = TabulatedProfile::new(vec![0.0, 1.0], vec![0.0, 1.0]).unwrap_err();
        assert_eq!(e.field(), Some("profile.r"));
        let e = TabulatedProfile::new(vec![0.0, 1.0, 2.0], vec![0.0, 1.0, 0.5]).unwrap_err();
        assert_eq!(e.field(), Some("profile.f"));
        let e = TabulatedProfile::new(vec![0.0, 2.0, 1.0], vec![0.0, 1.0, 2.0]).unwrap_err();
        assert_eq!(e.field(), Some("profile.r"));
        let e = TabulatedProfile::new(vec![1.0, 2.0, 3.0], vec![0.0, 1.0, 2.0]).unwrap_err();
        assert_eq!(e.field(), Some("profile.r"));
        // A step: flat then steep.
        let r = vec![0.0, 1.0, 2.0, 3.0, 4.0];
        let f = vec![0.0, 0.0, 0.0, 5.0, 5.1];
        let e = TabulatedProfile::new(r, f).unwrap_err();
        assert!(e.to_string().contains("smooth"), "{e}");
        let e = TabulatedProfile::new(vec![0.0, 1.0, 2.0], vec![0.0, 0.0, 0.0]).unwrap_err();
        assert_eq!(e.field(), Some("profile.f"));
    }
}
