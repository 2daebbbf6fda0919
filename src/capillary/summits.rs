//! Per-summit menisci on a GW surface: the mean capillary pressure of
//! rigid menisci in their Derjaguin form beside every summit, to set
//! beside the flooded model ([`super::flooded`]) on the same state.
//!
//! A summit of radius `R` at gap `D` from the flat pulls with
//! `2 pi R w_m (1 - D/h_m)` for `0 <= D < h_m` and `2 pi R w_m` in contact
//! (`D <= 0`), `w_m = Delta p h_m` ([`Meniscus::rigid_load`] as `r_K/R ->
//! 0`, an `O(r_K/R)` to `O(sqrt(r_K/R))` approximation). With summit heights
//! `z ~ N(0, sigma)` about their mean, the flat at separation `d` from it
//! (`D = d - z`) and `eta` summits per area, the mean pressure (Pa) is
//!
//! ```text
//! p_s = 2 pi eta R w_m [Q(t0) + (1 - d/h_m) (Q(t1) - Q(t0)) + (sigma/h_m) (phi(t1) - phi(t0))],
//! ```
//!
//! `t0 = d/sigma`, `t1 = (d - h_m)/sigma`, `Q` the normal tail, `phi` its
//! density (the integral of `1 - (d - z)/h_m` over `d - h_m < z < d`).

use super::Meniscus;
use crate::error::{positive, Result};
use crate::special::normal::{pdf, tail};
use std::f64::consts::PI;

/// The mean capillary pressure (Pa, attractive > 0) of per-summit menisci
/// of `meniscus` on GW summits (`density` 1/m^2, `radius` m, height
/// standard deviation `sigma` m) with the flat at `separation` (m) from the
/// mean summit height (module documentation).
///
/// # Errors
/// [`crate::Error::OutOfRange`] naming `density`, `radius` or `sigma`
/// unless finite and > 0, or `separation` unless finite.
pub fn per_summit_pressure(
    meniscus: &Meniscus,
    density: f64,
    radius: f64,
    sigma: f64,
    separation: f64,
) -> Result<f64> {
    positive("density", density)?;
    positive("radius", radius)?;
    positive("sigma", sigma)?;
    crate::error::Allowed::FINITE.check("separation", separation)?;
    let hm = meniscus.height();
    let (t0, t1) = (separation / sigma, (separation - hm) / sigma);
    let (q0, q1) = (tail(t0), tail(t1));
    let mean = q0 + (1.0 - separation / hm) * (q1 - q0) + sigma / hm * (pdf(t1) - pdf(t0));
    Ok(2.0 * PI * density * radius * meniscus.work() * mean)
}
