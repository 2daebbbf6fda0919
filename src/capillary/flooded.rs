//! The flooded regime: once the meniscus height `h_m` approaches the gaps
//! of the interface, the menisci merge and the liquid fills every region
//! where the gap is below `h_m` (Persson 2008, J. Phys.: Condens. Matter
//! 20, 315007; de Boer 2007, Exp. Mech. 47, 171). The attraction is the
//! Laplace pressure on the wetted area,
//!
//! ```text
//! F = Delta p A_w,   A_w = A_0 P(u < h_m),
//! ```
//!
//! with `P(u < h_m)` the fraction of the nominal area `A_0` where the gap
//! `u` is below `h_m` (contact spots, gap 0, included: the liquid surrounds
//! them and its pressure acts on the solid through them). The surface
//! tension along the wetted region's edge adds at most `gamma L` (`L` its
//! length), reported apart as a bound: the surfaces are nearly parallel
//! there and its normal component is small.

use super::Meniscus;
use crate::error::{Allowed, Error, Result};

/// Which model of capillary adhesion applies: the ratio of the meniscus
/// height to the RMS gap (docs/physics.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Regime {
    /// `h_m / u_rms < 0.1`: separate menisci around the summits in contact
    /// (Greenwood–Williamson with the two-zone law).
    PerSummit,
    /// `0.1 <= h_m / u_rms <= 1`: both models are approximations; their
    /// difference is the model error.
    Transition,
    /// `h_m / u_rms > 1`: merged menisci, the flooded model.
    Flooded,
}

impl Regime {
    /// The regime of the ratio `h_m / u_rms`.
    pub fn of_ratio(ratio: f64) -> Regime {
        if ratio < 0.1 {
            Regime::PerSummit
        } else if ratio <= 1.0 {
            Regime::Transition
        } else {
            Regime::Flooded
        }
    }
}

/// The flooded capillary force on one gap field.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FloodedForce {
    /// Wetted area `A_w` (m^2): where the gap is below `h_m`.
    pub wetted_area: f64,
    /// `A_w / A_0`.
    pub wetted_fraction: f64,
    /// Attraction `Delta p A_w` (N, > 0).
    pub force: f64,
    /// Length of the wetted region's edge (m), from the pixel edges between
    /// wet and dry pixels times `pi/4` (the mean projection of an isotropic
    /// curve on the grid's axes).
    pub perimeter: f64,
    /// `gamma L` (N): the bound on the edge's surface-tension term.
    pub perimeter_bound: f64,
    /// RMS gap `u_rms = sqrt(<u^2>)` (m) over the map.
    pub rms_gap: f64,
    /// `h_m / u_rms`.
    pub ratio: f64,
    /// The regime of `ratio`.
    pub regime: Regime,
}

/// The flooded force of `meniscus` on the gap field `gaps` (m, row-major
/// `nx` by `ny`, each >= 0) of pixels `dx` by `dy` (m), periodic.
///
/// # Errors
/// [`Error::Invalid`] naming `gaps` when its length is not `nx * ny` or a
/// gap is negative or not finite; [`Error::OutOfRange`] naming `dx`, `dy`.
pub fn flooded_force(
    meniscus: &Meniscus,
    gaps: &[f64],
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
) -> Result<FloodedForce> {
    Allowed::POSITIVE.check("dx", dx)?;
    Allowed::POSITIVE.check("dy", dy)?;
    if gaps.len() != nx * ny || gaps.is_empty() {
        return Err(Error::invalid(
            "gaps",
            format!("{} values for a {nx} x {ny} map", gaps.len()),
        ));
    }
    if let Some((i, g)) = gaps
        .iter()
        .enumerate()
        .find(|(_, g)| !(**g >= 0.0) || !g.is_finite())
    {
        return Err(Error::invalid(
            "gaps",
            format!("gap {i} is {g}: gaps are >= 0 m"),
        ));
    }
    let hm = meniscus.height();
    let wet = |i: usize, j: usize| gaps[i * ny + j] < hm;
    let mut count = 0usize;
    let (mut edges_x, mut edges_y) = (0usize, 0usize);
    let mut sq = 0.0;
    for i in 0..nx {
        for j in 0..ny {
            let w = wet(i, j);
            count += usize::from(w);
            sq += gaps[i * ny + j] * gaps[i * ny + j];
            edges_x += usize::from(w != wet((i + 1) % nx, j));
            edges_y += usize::from(w != wet(i, (j + 1) % ny));
        }
    }
    let n = (nx * ny) as f64;
    let area = n * dx * dy;
    let wetted_area = count as f64 * dx * dy;
    // An edge between rows i, i+1 runs along y (length dy), and vice versa.
    let perimeter = std::f64::consts::FRAC_PI_4 * (edges_x as f64 * dy + edges_y as f64 * dx);
    let rms_gap = (sq / n).sqrt();
    let ratio = hm / rms_gap;
    Ok(FloodedForce {
        wetted_area,
        wetted_fraction: wetted_area / area,
        force: meniscus.laplace_pressure() * wetted_area,
        perimeter,
        perimeter_bound: meniscus.surface_tension() * perimeter,
        rms_gap,
        ratio,
        regime: Regime::of_ratio(ratio),
    })
}
