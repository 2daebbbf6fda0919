//! A measured axisymmetric profile: columns `r` (m) and `f(r)` (m),
//! interpolated by PCHIP (Fritsch–Butland slopes with Moler's shape-
//! preserving end slopes, the same interpolant as scipy's
//! `PchipInterpolator`), so `f` is C^1 and monotone between the nodes.
//!
//! Sneddon's integrals are taken in `r = a sin(u)`, where they have no
//! endpoint singularity, on the pieces between the nodes:
//!
//! ```text
//! delta_0(a)   = a int_0^(pi/2) f'(a sin u) du
//! delta_0'(a)  =   int_0^(pi/2) [f'(a sin u) + a sin u f''(a sin u)] du
//! F_0(a)/(2E*) = a^2 int_0^(pi/2) sin^2 u f'(a sin u) du
//! ```
//!
//! On each piece `f'` is a quadratic in `r`, `b0 + b1 r + b2 r^2`, so every
//! integrand is a polynomial in `sin u` of degree <= 4 and each piece
//! integrates in closed form (`Moments`): one `asin` and one `sqrt`
//! per node instead of a 21-point quadrature with a table search per point
//! (a 400-node measured tip built its GW law in minutes before).

use crate::error::{Error, Result};

/// A validated, PCHIP-interpolated profile table.
#[derive(Debug, Clone, PartialEq)]
pub struct TabulatedProfile {
    r: Vec<f64>,
    f: Vec<f64>,
    /// PCHIP slopes `f'(r_i)`.
    d: Vec<f64>,
    /// Piece `k` (`r_k <= r <= r_k+1`): `f'(r) = b0 + b1 r + b2 r^2`.
    slope_poly: Vec<[f64; 3]>,
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
                "r",
                format!(
                    "needs >= 3 points and as many f values (got {n} r, {} f)",
                    f.len()
                ),
            ));
        }
        if let Some(i) = r.iter().position(|v| !v.is_finite()) {
            return Err(Error::invalid("r", format!("r[{i}] is not finite")));
        }
        if let Some(i) = f.iter().position(|v| !v.is_finite()) {
            return Err(Error::invalid("f", format!("f[{i}] is not finite")));
        }
        if r[0] != 0.0 || f[0] != 0.0 {
            return Err(Error::invalid(
                "r",
                "the table must start at the apex: r[0] = 0 and f[0] = 0",
            ));
        }
        if let Some(i) = (1..n).find(|&i| !(r[i] > r[i - 1])) {
            return Err(Error::invalid(
                "r",
                format!("r must increase strictly (r[{i}] = {:e})", r[i]),
            ));
        }
        if let Some(i) = (1..n).find(|&i| f[i] < f[i - 1]) {
            return Err(Error::invalid(
                "f",
                format!("f must not decrease (f[{i}] = {:e} < f[{}])", f[i], i - 1),
            ));
        }
        if !(f[n - 1] > 0.0) {
            return Err(Error::invalid("f", "the profile is flat everywhere"));
        }
        let h: Vec<f64> = r.windows(2).map(|w| w[1] - w[0]).collect();
        let del: Vec<f64> = (0..n - 1).map(|k| (f[k + 1] - f[k]) / h[k]).collect();
        let max_del = del.iter().cloned().fold(0.0, f64::max);
        if let Some(k) =
            (1..n - 1).find(|&k| (del[k] - del[k - 1]).abs() > MAX_SLOPE_JUMP * max_del)
        {
            return Err(Error::invalid(
                "f",
                format!(
                    "not smooth enough: the slope jumps from {:.4e} to {:.4e} at r = {:e} m; \
                     tabulate more finely",
                    del[k - 1],
                    del[k],
                    r[k]
                ),
            ));
        }
        let d = crate::numeric::pchip::slopes(&h, &del);
        let slope_poly = (0..n - 1)
            .map(|k| slope_polynomial(r[k], h[k], f[k], f[k + 1], d[k], d[k + 1]))
            .collect();
        Ok(TabulatedProfile {
            r,
            f,
            d,
            slope_poly,
        })
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
        crate::numeric::pchip::hermite(s, y0, y1, d0, d1)
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

    /// `sum over pieces of int c . (1, s, s^2, s^3, s^4) du`, `s = sin u`,
    /// `r = a s` from 0 to `a`, with the piece coefficients `coef(k)` in
    /// powers of `s` (piece `n - 1` is the clamped continuation beyond the
    /// table, as [`derivatives`](Self::derivatives) evaluates it).
    fn angular(&self, a: f64, coef: impl Fn(usize) -> [f64; 5]) -> f64 {
        let mut lo = Moments::AT_ZERO;
        let mut sum = 0.0;
        let last = self.r.len() - 1;
        for k in 0..last {
            let end = self.r[k + 1];
            let hi = if end < a {
                Moments::at(end / a)
            } else {
                Moments::AT_QUARTER_TURN
            };
            sum += dot(coef(k), hi.minus(&lo));
            if end >= a {
                return sum;
            }
            lo = hi;
        }
        sum + dot(coef(last), Moments::AT_QUARTER_TURN.minus(&lo))
    }

    /// `f'(r)` on piece `k` in powers of `s = r/a`; the constant end slope
    /// beyond the table.
    #[inline]
    fn slope_in_s(&self, k: usize, a: f64) -> [f64; 3] {
        match self.slope_poly.get(k) {
            Some(&[b0, b1, b2]) => [b0, b1 * a, b2 * a * a],
            None => [self.d[k], 0.0, 0.0],
        }
    }

    /// `delta_0(a) = a int_0^(pi/2) f'(a sin u) du` (m).
    pub fn delta0(&self, a: f64) -> f64 {
        if !(a > 0.0) {
            return 0.0;
        }
        a * self.angular(a, |k| {
            let [c0, c1, c2] = self.slope_in_s(k, a);
            [c0, c1, c2, 0.0, 0.0]
        })
    }

    /// `d delta_0/da` (dimensionless): the integrand `f' + r f''` is
    /// `b0 + 2 b1 r + 3 b2 r^2` on a piece, `f'(end) + r f''(end)` beyond.
    pub fn delta0_slope(&self, a: f64) -> f64 {
        if !(a > 0.0) {
            return self.d[0];
        }
        self.angular(a, |k| match self.slope_poly.get(k) {
            Some(&[b0, b1, b2]) => [b0, 2.0 * b1 * a, 3.0 * b2 * a * a, 0.0, 0.0],
            None => {
                let (d1, d2) = self.derivatives(self.max_radius());
                [d1, d2 * a, 0.0, 0.0, 0.0]
            }
        })
    }

    /// `F_0(a)/(2E*) = a^2 int_0^(pi/2) sin^2 u f'(a sin u) du` (m^2).
    pub fn load_area(&self, a: f64) -> f64 {
        if !(a > 0.0) {
            return 0.0;
        }
        a * a
            * self.angular(a, |k| {
                let [c0, c1, c2] = self.slope_in_s(k, a);
                [0.0, 0.0, c0, c1, c2]
            })
    }
}

/// `f'(r) = b0 + b1 r + b2 r^2` on the piece from `r0` (width `h`) of the
/// cubic Hermite interpolant with end values `y0, y1` and slopes `d0, d1`:
/// in `t = (r - r0)/h`, `f' = p0 + p1 t + p2 t^2` with `p0 = d0`,
/// `p1 = (6 (y1 - y0)/h - 4 d0 - 2 d1)`, `p2 = (6 (y0 - y1)/h + 3 d0 + 3 d1)`.
fn slope_polynomial(r0: f64, h: f64, y0: f64, y1: f64, d0: f64, d1: f64) -> [f64; 3] {
    let [p0, p1, p2] = crate::numeric::pchip::hermite_derivative(h, y0, y1, d0, d1);
    // t = alpha + beta r
    let beta = 1.0 / h;
    let alpha = -r0 / h;
    [
        p0 + alpha * (p1 + alpha * p2),
        beta * (p1 + 2.0 * alpha * p2),
        p2 * beta * beta,
    ]
}

#[inline]
fn dot(c: [f64; 5], m: [f64; 5]) -> f64 {
    c[0] * m[0] + c[1] * m[1] + c[2] * m[2] + c[3] * m[3] + c[4] * m[4]
}

/// The antiderivatives `S_j(u) = int_0^u sin^j v dv`, `j = 0..4`, at one
/// angle: `S0 = u`, `S1 = 1 - cos u`, `S2 = (u - s c)/2`,
/// `S3 = 2/3 - c + c^3/3`, `S4 = (3 S2 - s^3 c)/4` (`s = sin u`,
/// `c = cos u`; the reduction `S_j = ((j-1) S_(j-2) - s^(j-1) c)/j`).
struct Moments([f64; 5]);

impl Moments {
    const AT_ZERO: Moments = Moments([0.0; 5]);
    const AT_QUARTER_TURN: Moments = Moments([
        std::f64::consts::FRAC_PI_2,
        1.0,
        std::f64::consts::FRAC_PI_4,
        2.0 / 3.0,
        3.0 * std::f64::consts::PI / 16.0,
    ]);

    /// At `u = asin(x)`, `0 <= x <= 1`.
    #[inline]
    fn at(x: f64) -> Moments {
        let u = x.asin();
        let c = ((1.0 - x) * (1.0 + x)).sqrt();
        // 1 - c = x^2/(1 + c), without cancellation at small x.
        let s1 = x * x / (1.0 + c);
        let s2 = 0.5 * (u - x * c);
        // 2/3 - c + c^3/3 = (1 - c)^2 (2 + c)/3
        let s3 = s1 * s1 * (2.0 + c) / 3.0;
        let s4 = 0.25 * (3.0 * s2 - x * x * x * c);
        Moments([u, s1, s2, s3, s4])
    }

    #[inline]
    fn minus(&self, lo: &Moments) -> [f64; 5] {
        std::array::from_fn(|j| self.0[j] - lo.0[j])
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

    /// The closed forms against Gauss–Kronrod panels between the nodes (the
    /// previous implementation, exact to rounding for the quadratic `f'`)
    /// on an uneven 400-node tip table (a blunted cone plus a ripple), at
    /// contact radii inside a piece, on a node and at the end of the table.
    #[test]
    fn closed_forms_match_quadrature_of_the_interpolant() {
        use crate::numeric::quadrature::kronrod21;
        let n = 400;
        let r: Vec<f64> = (0..n)
            .map(|i| {
                let x = i as f64 / (n - 1) as f64;
                1e-7 * (x + 0.3 * x * x)
            })
            .collect();
        let f: Vec<f64> = r
            .iter()
            .map(|&x| {
                let s = x / 2e-8;
                2e-8 * ((1.0 + s * s).sqrt() - 1.0) + 1e-10 * (x / 1e-8).sin().powi(2)
            })
            .collect();
        let t = TabulatedProfile::new(r.clone(), f).unwrap();
        let quad = |a: f64, g: &dyn Fn(f64) -> f64| {
            let mut lo = 0.0;
            let mut sum = 0.0;
            for &ri in r[1..].iter().take_while(|&&ri| ri < a) {
                let hi = (ri / a).asin();
                sum += kronrod21(&mut |u| g(u), lo, hi).0;
                lo = hi;
            }
            sum + kronrod21(&mut |u| g(u), lo, std::f64::consts::FRAC_PI_2).0
        };
        for a in [3.3e-10, 1.7e-9, r[57], 4.1e-8, 9.99e-8, t.max_radius()] {
            let d0 = a * quad(a, &|u| t.derivatives(a * u.sin()).0);
            let sl = quad(a, &|u| {
                let x = a * u.sin();
                let (d1, d2) = t.derivatives(x);
                d1 + x * d2
            });
            let la = a * a * quad(a, &|u| u.sin().powi(2) * t.derivatives(a * u.sin()).0);
            for (what, got, want) in [
                ("delta0", t.delta0(a), d0),
                ("slope", t.delta0_slope(a), sl),
                ("load", t.load_area(a), la),
            ] {
                assert!(
                    (got - want).abs() <= 1e-12 * want.abs(),
                    "{what} at a = {a}: {got} vs {want}"
                );
            }
        }
    }

    /// `int_0^asin(x) sin^j u du` against 21-point Kronrod (exact to rounding
    /// for these smooth integrands on short intervals) at small and large x.
    #[test]
    fn sine_moments_are_the_integrals_of_sine_powers() {
        use crate::numeric::quadrature::kronrod21;
        for x in [1e-4, 0.01, 0.3, 0.9, 0.999, 1.0] {
            let m = Moments::at(x).0;
            for (j, mj) in m.iter().enumerate() {
                let want = kronrod21(&mut |u: f64| u.sin().powi(j as i32), 0.0, x.asin()).0;
                assert!((mj - want).abs() <= 1e-15 * want.abs().max(1e-300) + 1e-17);
            }
        }
    }

    #[test]
    fn rejects_bad_tables_naming_the_column() {
        let e = TabulatedProfile::new(vec![0.0, 1.0], vec![0.0, 1.0]).unwrap_err();
        assert_eq!(e.field(), Some("r"));
        let e = TabulatedProfile::new(vec![0.0, 1.0, 2.0], vec![0.0, 1.0, 0.5]).unwrap_err();
        assert_eq!(e.field(), Some("f"));
        let e = TabulatedProfile::new(vec![0.0, 2.0, 1.0], vec![0.0, 1.0, 2.0]).unwrap_err();
        assert_eq!(e.field(), Some("r"));
        let e = TabulatedProfile::new(vec![1.0, 2.0, 3.0], vec![0.0, 1.0, 2.0]).unwrap_err();
        assert_eq!(e.field(), Some("r"));
        // A step: flat then steep.
        let r = vec![0.0, 1.0, 2.0, 3.0, 4.0];
        let f = vec![0.0, 0.0, 0.0, 5.0, 5.1];
        let e = TabulatedProfile::new(r, f).unwrap_err();
        assert!(e.to_string().contains("smooth"), "{e}");
        let e = TabulatedProfile::new(vec![0.0, 1.0, 2.0], vec![0.0, 0.0, 0.0]).unwrap_err();
        assert_eq!(e.field(), Some("f"));
    }
}
