//! Lennard-Jones (Derjaguin 9-3) surface traction between two half-spaces,
//! in units of `w/z0` and gaps in units of `z0`:
//!
//! ```text
//! sigma_hat(H) = (8/3) (H^-9 - H^-3)          (> 0 repulsive)
//! ```
//!
//! `int_1^inf sigma_hat dH = -1` (the work of adhesion); maximum tension
//! `-16/(9 sqrt 3) = -1.0264` at `H = 3^(1/6)` (physics.md; Greenwood 1997).

/// `3^(1/6)`: the gap of maximum tension; the contact edge is where the gap
/// crosses it.
pub const GAP_MAX_TENSION: f64 = 1.200_936_955_176_002_7;

/// `sigma_hat(H) = (8/3)(H^-9 - H^-3)` for `H > 0`.
#[inline]
pub fn traction(h: f64) -> f64 {
    let x = 1.0 / h;
    let x3 = x * x * x;
    (8.0 / 3.0) * (x3 * x3 * x3 - x3)
}

/// `d sigma_hat / dH = (8/3)(-9 H^-10 + 3 H^-4)`.
#[inline]
pub fn traction_slope(h: f64) -> f64 {
    let x = 1.0 / h;
    let x2 = x * x;
    let x4 = x2 * x2;
    (8.0 / 3.0) * (-9.0 * x4 * x4 * x2 + 3.0 * x4)
}

/// `int_h^inf sigma_hat dH = h^-8/3 - 4 h^-2/3`.
#[inline]
pub fn tail_integral(h: f64) -> f64 {
    let x2 = 1.0 / (h * h);
    let x8 = x2 * x2 * x2 * x2;
    x8 / 3.0 - 4.0 * x2 / 3.0
}

/// `int_h^inf sigma_hat H dH = (8/3)(h^-7/7 - h^-1)`.
#[inline]
pub fn tail_moment(h: f64) -> f64 {
    let x = 1.0 / h;
    let x7 = x.powi(7);
    (8.0 / 3.0) * (x7 / 7.0 - x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::quadrature::{integrate, QuadOptions};

    #[test]
    fn work_of_adhesion_and_maximum_tension() {
        assert_eq!(traction(1.0), 0.0);
        assert!((tail_integral(1.0) + 1.0).abs() < 1e-15);
        let max_t = traction(GAP_MAX_TENSION);
        assert!((max_t + crate::material::LJ_MAX_TENSION_FACTOR).abs() < 1e-15);
        assert!(traction_slope(GAP_MAX_TENSION).abs() < 1e-14);
        assert!((GAP_MAX_TENSION.powi(6) - 3.0).abs() < 1e-14);
    }

    #[test]
    fn closed_forms_match_quadrature() {
        let opts = QuadOptions::relative(1e-13);
        for h in [0.8, 1.0, 1.7, 5.0] {
            // map [h, inf) to (0, 1]: H = h / t
            let q = integrate(|t: f64| traction(h / t) * h / (t * t), 0.0, 1.0, &opts);
            assert!((q.value - tail_integral(h)).abs() < 1e-10, "{h}");
            let q1 = integrate(
                |t: f64| traction(h / t) * h * h / (t * t * t),
                0.0,
                1.0,
                &opts,
            );
            assert!((q1.value - tail_moment(h)).abs() < 1e-10, "{h}");
            let d = 1e-6;
            let fd = (traction(h + d) - traction(h - d)) / (2.0 * d);
            assert!((fd - traction_slope(h)).abs() < 1e-7 * (1.0 + fd.abs()));
        }
    }
}
