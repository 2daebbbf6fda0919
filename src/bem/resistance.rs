//! Constriction resistance of the contact clusters of a solution.
//!
//! Each cluster is a spot of the same area, radius `a_i = sqrt(A_i/pi)`,
//! with its Holm/Maxwell (or Sharvin, Wexler, film) resistance from
//! [`SpotResistance`], at its centroid; the spots interact through
//! Greenwood's (1966) formula ([`Spots::greenwood`]). On a periodic map the
//! centroids are taken in one cell (the interaction with the neighbouring
//! cells' images is left out).

use super::{Cluster, Problem};
use crate::electrical::{SpotResistance, Spots};
use crate::error::Result;

/// Resistances of the clusters (Ohm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClusterResistance {
    /// Independent parallel spots, `1/sum 1/R_i`.
    pub parallel: f64,
    /// Parallel plus Greenwood's interaction.
    pub greenwood: f64,
    /// Spots counted.
    pub spots: usize,
}

/// The resistance of `clusters` of `problem`'s map; `None` without contact.
///
/// # Errors
/// As [`Spots::merging`].
pub fn cluster_resistance(
    problem: &Problem,
    clusters: &[Cluster],
    spot: &SpotResistance,
) -> Result<Option<ClusterResistance>> {
    if clusters.is_empty() {
        return Ok(None);
    }
    // A cluster's spot has its area (pixels dx dy); sqrt(dx dx) = dx exactly.
    let (dx, dy) = problem.pixel_sizes();
    let side = (dx * dy).sqrt();
    let x = clusters.iter().map(|c| (c.x_px + 0.5) * dx).collect();
    let y = clusters.iter().map(|c| (c.y_px + 0.5) * dy).collect();
    let a = clusters
        .iter()
        .map(|c| (c.pixels as f64 / std::f64::consts::PI).sqrt() * side)
        .collect();
    let spots = Spots::merging(x, y, a)?.spots;
    Ok(Some(ClusterResistance {
        parallel: spots.parallel(spot),
        greenwood: spots.greenwood(spot),
        spots: spots.len(),
    }))
}
