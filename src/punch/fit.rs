//! Least-squares fit of `E*`, `w` and `A sqrt(l)` to measured `(a, P)` on loading and
//! unloading (paper section 4.3).
//!
//! The envelopes `P_+/-(a) = 4 E* a^3/(3R) - sqrt(8 pi w E* a^3) +/- 2 pi E* A sqrt(l a^3)`
//! (eq. 4.9; `+` loading, `-` unloading) are linear in
//! `theta = (E*, sqrt(8 pi w E*), 2 pi E* A sqrt(l))`:
//! `P = theta_1 (4 a^3/(3R)) + a^(3/2) (-theta_2 +/- theta_3)`. Ordinary least squares in
//! `theta` (Householder QR of the column-scaled design matrix, so no normal equations) gives
//! the global minimum of the sum of squared load residuals; then `E* = theta_1`,
//! `w = theta_2 |theta_2|/(8 pi theta_1)` (negative if the data show repulsion),
//! `A sqrt(l) = theta_3/(2 pi theta_1)`. Standard errors: `s^2 = RSS/(n - 3)`,
//! `Cov(theta) = s^2 (X^T X)^-1`, carried to the physical parameters by the Jacobian of that
//! map (delta method); their coverage is checked over noisy synthetic sets in
//! `tests/it/punch_fit.rs`.

use crate::error::{positive, Error, Result};
use nalgebra::{DMatrix, DVector, Matrix3};
use std::f64::consts::PI;

/// Which branch of the experiment a point belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// Loading (the upper envelope).
    Loading,
    /// Unloading (the lower envelope).
    Unloading,
}

/// One measured point: phase, contact radius `a` (m), load `P` (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitPoint {
    /// Loading or unloading.
    pub phase: Phase,
    /// Contact radius (m), > 0.
    pub radius: f64,
    /// Load (N), positive compressive.
    pub load: f64,
}

/// Fitted parameters with standard errors (`NaN` when `n = 3`: no degrees of freedom left).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PunchFit {
    /// Contact modulus `E*` (Pa).
    pub estar_pa: f64,
    /// Standard error of `E*` (Pa).
    pub estar_pa_stderr: f64,
    /// Work of adhesion `w` (J/m^2).
    pub w_j_per_m2: f64,
    /// Standard error of `w` (J/m^2).
    pub w_j_per_m2_stderr: f64,
    /// `A sqrt(l)` (m^1/2).
    pub amplitude_sqrt_wavelength_m_half: f64,
    /// Standard error of `A sqrt(l)` (m^1/2).
    pub amplitude_sqrt_wavelength_m_half_stderr: f64,
    /// Root-mean-square load residual (N).
    pub residual_rms_n: f64,
    /// Number of points.
    pub points: usize,
}

/// Fits the envelopes of a punch of radius of curvature `radius` (m) to `data`.
///
/// # Errors
/// [`Error::OutOfRange`] naming `radius`, or `data` for a non-positive radius or non-finite
/// load in a point; [`Error::Invalid`] naming `data` with one phase only, fewer than 3
/// points, data that do not determine the parameters (rank-deficient), a fitted `E*` that
/// is not positive or a negative amplitude (the loading envelope below the unloading one).
pub fn fit_envelopes(radius: f64, data: &[FitPoint]) -> Result<PunchFit> {
    positive("radius", radius)?;
    let n = data.len();
    if n < 3 {
        return Err(Error::invalid(
            "data",
            format!("{n} points; need at least 3 (three parameters)"),
        ));
    }
    for phase in [Phase::Loading, Phase::Unloading] {
        if !data.iter().any(|p| p.phase == phase) {
            return Err(Error::invalid(
                "data",
                format!("no {phase:?} points; both phases are needed").to_lowercase(),
            ));
        }
    }
    for p in data {
        positive("data", p.radius)?;
        crate::error::finite("data", p.load)?;
    }
    let (theta, cov_unit, rss) = least_squares(radius, data)?;
    let dof = (n - 3) as f64;
    let s2 = if n > 3 { rss / dof } else { f64::NAN };
    let [t1, t2, t3] = theta;
    if !(t1 > 0.0) {
        return Err(Error::invalid(
            "data",
            format!("the fitted modulus is {t1:e} Pa; the data do not follow the envelopes"),
        ));
    }
    if t3 < 0.0 {
        // The loading envelope lies below the unloading one: phases
        // swapped, or data that are not a wavy punch's.
        return Err(Error::invalid(
            "data",
            format!(
                "the fitted amplitude A sqrt(l) is negative ({:e} m^1/2): the loading points \
                 lie below the unloading ones, so the data do not fit the model (are the \
                 phases swapped?)",
                t3 / (2.0 * PI * t1)
            ),
        ));
    }
    // g(theta) = (t1, t2|t2|/(8 pi t1), t3/(2 pi t1)) and its Jacobian.
    let w = t2 * t2.abs() / (8.0 * PI * t1);
    let eps = t3 / (2.0 * PI * t1);
    let jac = Matrix3::new(
        1.0,
        0.0,
        0.0,
        -w / t1,
        2.0 * t2.abs() / (8.0 * PI * t1),
        0.0,
        -eps / t1,
        0.0,
        1.0 / (2.0 * PI * t1),
    );
    let cov = jac * (cov_unit * s2) * jac.transpose();
    Ok(PunchFit {
        estar_pa: t1,
        estar_pa_stderr: cov[(0, 0)].sqrt(),
        w_j_per_m2: w,
        w_j_per_m2_stderr: cov[(1, 1)].sqrt(),
        amplitude_sqrt_wavelength_m_half: eps,
        amplitude_sqrt_wavelength_m_half_stderr: cov[(2, 2)].sqrt(),
        residual_rms_n: (rss / n as f64).sqrt(),
        points: n,
    })
}

/// OLS in `theta`: `(theta, (X^T X)^-1, RSS)`, by QR of the column-scaled design.
fn least_squares(radius: f64, data: &[FitPoint]) -> Result<([f64; 3], Matrix3<f64>, f64)> {
    let n = data.len();
    let mut x = DMatrix::<f64>::zeros(n, 3);
    let mut y = DVector::<f64>::zeros(n);
    for (i, p) in data.iter().enumerate() {
        let a = p.radius;
        let s = if p.phase == Phase::Loading { 1.0 } else { -1.0 };
        x[(i, 0)] = 4.0 * a * a * a / (3.0 * radius);
        x[(i, 1)] = -(a * a * a).sqrt();
        x[(i, 2)] = s * (a * a * a).sqrt();
        y[i] = p.load;
    }
    let scale: Vec<f64> = (0..3).map(|j| x.column(j).norm()).collect();
    for (j, &sc) in scale.iter().enumerate() {
        x.column_mut(j).scale_mut(1.0 / sc);
    }
    let qr = x.clone().qr();
    let r = qr.r();
    let rank_ok = (0..3).all(|j| r[(j, j)].abs() > 1e-12);
    if !rank_ok {
        return Err(Error::invalid(
            "data",
            "the radii do not determine the three parameters (too few distinct radii)",
        ));
    }
    let qty = qr.q().transpose() * &y;
    let r3 = Matrix3::from_fn(|i, j| r[(i, j)]);
    let rinv = r3
        .try_inverse()
        .ok_or_else(|| Error::invalid("data", "singular design"))?;
    let beta = rinv * nalgebra::Vector3::new(qty[0], qty[1], qty[2]);
    let resid = &y - &x * DVector::from_column_slice(beta.as_slice());
    let rss = resid.norm_squared();
    let unscale = Matrix3::from_diagonal(&nalgebra::Vector3::new(
        1.0 / scale[0],
        1.0 / scale[1],
        1.0 / scale[2],
    ));
    let theta = unscale * beta;
    let cov = unscale * (rinv * rinv.transpose()) * unscale;
    Ok(([theta[0], theta[1], theta[2]], cov, rss))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_phase_or_too_few_points_are_rejected() {
        let p = |phase, radius, load| FitPoint {
            phase,
            radius,
            load,
        };
        let one = [
            p(Phase::Loading, 1.0, 1.0),
            p(Phase::Loading, 2.0, 3.0),
            p(Phase::Loading, 3.0, 9.0),
        ];
        assert_eq!(fit_envelopes(1.0, &one).unwrap_err().field(), Some("data"));
        let two = [p(Phase::Loading, 1.0, 1.0), p(Phase::Unloading, 2.0, 3.0)];
        assert_eq!(fit_envelopes(1.0, &two).unwrap_err().field(), Some("data"));
        assert_eq!(
            fit_envelopes(-1.0, &two).unwrap_err().field(),
            Some("radius")
        );
    }
}
