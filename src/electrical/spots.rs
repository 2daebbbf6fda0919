//! Explicit contact spots (centres `(x_i, y_i)`, radii `a_i`, m) in one
//! apparent area: three resistances of the same spots.
//!
//! Each spot has a self resistance `R_i` (its [`SpotResistance`]: Maxwell
//! `rho/(2a)`, or Wexler, plus any film) and conductance `G_i = 1/R_i`;
//! two spots at distance `s_ij` share the point-source mutual resistance
//! `M_ij = rho_eff/(pi s_ij)` (physics.md, "Contact resistance").
//! - Parallel (Holm, independent spots): `R = 1/sum G_i`.
//! - Greenwood (1966): currents shared as in the parallel solution,
//!   `w_i = G_i/sum G`, and the mutual terms added to first order:
//!   `R = 1/sum G + sum_{i != j} w_i w_j M_ij`; for Maxwell spots
//!   `R = rho/(2 sum a) + (rho/pi) sum_{i != j} a_i a_j/(s_ij (sum a)^2)`.
//! - Exact (equal potential on every spot): `sum_j M_ij I_j = V` with
//!   `M_ii = R_i`, `R = V/sum I_j`; a dense symmetric solve (faer: Cholesky,
//!   partial-pivot LU if the matrix is not positive definite).

use super::spot::SpotResistance;
use crate::error::{finite, positive, Error, Result};
use faer::prelude::*;
use faer::Side;
use std::f64::consts::PI;

/// Spots with validated positions and radii.
#[derive(Debug, Clone, PartialEq)]
pub struct Spots {
    x: Vec<f64>,
    y: Vec<f64>,
    radius: Vec<f64>,
}

impl Spots {
    /// Spots from centre coordinates `x`, `y` (m, finite) and radii
    /// `radius` (m, > 0), all of one length >= 1; no two centres may
    /// coincide.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `x[i]`, `y[i]` or `radius[i]`;
    /// [`Error::Invalid`] naming `spots` for empty or unequal lists or
    /// coinciding centres.
    pub fn new(x: Vec<f64>, y: Vec<f64>, radius: Vec<f64>) -> Result<Self> {
        if x.is_empty() || x.len() != y.len() || x.len() != radius.len() {
            return Err(Error::invalid(
                "spots",
                format!(
                    "need equally many x, y and radius values, at least one (got {}, {}, {})",
                    x.len(),
                    y.len(),
                    radius.len()
                ),
            ));
        }
        for i in 0..x.len() {
            finite(&format!("x[{i}]"), x[i])?;
            finite(&format!("y[{i}]"), y[i])?;
            positive(&format!("radius[{i}]"), radius[i])?;
        }
        let spots = Spots { x, y, radius };
        for i in 0..spots.len() {
            for j in 0..i {
                if !(spots.distance(i, j) > 0.0) {
                    return Err(Error::invalid(
                        "spots",
                        format!("spots {j} and {i} have the same centre"),
                    ));
                }
            }
        }
        Ok(spots)
    }

    /// Number of spots.
    pub fn len(&self) -> usize {
        self.radius.len()
    }

    /// Always false (at least one spot).
    pub fn is_empty(&self) -> bool {
        self.radius.is_empty()
    }

    /// Spot radii (m).
    pub fn radii(&self) -> &[f64] {
        &self.radius
    }

    /// Centre distance `s_ij` (m).
    #[inline]
    pub fn distance(&self, i: usize, j: usize) -> f64 {
        (self.x[i] - self.x[j]).hypot(self.y[i] - self.y[j])
    }

    /// Independent parallel spots: `1/sum G_i` (Ohm).
    pub fn parallel(&self, spot: &SpotResistance) -> f64 {
        1.0 / self.conductances(spot).iter().sum::<f64>()
    }

    /// Greenwood's (1966) formula: `1/sum G + sum_{i != j} w_i w_j
    /// rho_eff/(pi s_ij)`, `w_i = G_i/sum G` (Ohm). O(n^2).
    pub fn greenwood(&self, spot: &SpotResistance) -> f64 {
        let g = self.conductances(spot);
        let total: f64 = g.iter().sum();
        let mut mutual = 0.0;
        for i in 0..self.len() {
            let row: f64 = g[..i]
                .iter()
                .enumerate()
                .map(|(j, gj)| gj / self.distance(i, j))
                .sum();
            mutual += g[i] * row;
        }
        // Each unordered pair counted twice in sum_{i != j}.
        1.0 / total + 2.0 * spot.mutual_resistivity() / PI * mutual / (total * total)
    }

    /// Exact equal-potential resistance (Ohm): solve `M I = 1`, `R =
    /// 1/sum I`. O(n^3) time, O(n^2) memory (2000 spots: 32 MB, well under
    /// a second).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `spots` when the system is singular or
    /// gives no positive total current (spots so close that the
    /// point-source mutual resistance exceeds the self resistances).
    pub fn exact(&self, spot: &SpotResistance) -> Result<f64> {
        let n = self.len();
        let k = spot.mutual_resistivity() / PI;
        let m = Mat::<f64>::from_fn(n, n, |i, j| {
            if i == j {
                spot.resistance(self.radius[i])
            } else {
                k / self.distance(i, j)
            }
        });
        let ones = Col::<f64>::from_fn(n, |_| 1.0);
        let current = match m.llt(Side::Lower) {
            Ok(llt) => llt.solve(&ones),
            Err(_) => m.partial_piv_lu().solve(&ones),
        };
        let total: f64 = current.iter().sum();
        if total.is_finite() && total > 0.0 {
            Ok(1.0 / total)
        } else {
            Err(Error::invalid(
                "spots",
                "the equal-potential system is singular: spots too close for point sources",
            ))
        }
    }

    fn conductances(&self, spot: &SpotResistance) -> Vec<f64> {
        self.radius
            .iter()
            .map(|&a| spot.spot_conductance(a))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::electrical::spot::Spreading;

    const RHO: f64 = 2.44e-8;

    fn maxwell() -> SpotResistance {
        SpotResistance::same_metal(Spreading::Maxwell, RHO, None).unwrap()
    }

    #[test]
    fn one_spot_is_holm() {
        let s = Spots::new(vec![0.0], vec![0.0], vec![1e-6]).unwrap();
        let holm = RHO / 2e-6;
        for r in [
            s.parallel(&maxwell()),
            s.greenwood(&maxwell()),
            s.exact(&maxwell()).unwrap(),
        ] {
            assert!((r / holm - 1.0).abs() < 1e-14, "{r}");
        }
    }

    #[test]
    fn two_spots_match_the_closed_two_by_two_solution() {
        // M = [[m1, k], [k, m2]], R = (m1 m2 - k^2)/(m1 + m2 - 2k).
        let (a1, a2, s) = (1e-6, 3e-6, 2e-5);
        let sp = Spots::new(vec![0.0, s], vec![0.0, 0.0], vec![a1, a2]).unwrap();
        let (m1, m2, k) = (RHO / (2.0 * a1), RHO / (2.0 * a2), RHO / (PI * s));
        let r = (m1 * m2 - k * k) / (m1 + m2 - 2.0 * k);
        assert!((sp.exact(&maxwell()).unwrap() / r - 1.0).abs() < 1e-13);
        // Equal spots: exact = Greenwood = rho/(4a) + rho/(2 pi s).
        let eq = Spots::new(vec![0.0, s], vec![0.0, 0.0], vec![a1, a1]).unwrap();
        let r = RHO / (4.0 * a1) + RHO / (2.0 * PI * s);
        assert!((eq.exact(&maxwell()).unwrap() / r - 1.0).abs() < 1e-13);
        assert!((eq.greenwood(&maxwell()) / r - 1.0).abs() < 1e-13);
    }

    #[test]
    fn bad_spots_are_rejected_by_name() {
        let e = Spots::new(vec![0.0], vec![0.0], vec![-1.0]).unwrap_err();
        assert_eq!(e.field(), Some("radius[0]"));
        let e = Spots::new(vec![0.0, f64::NAN], vec![0.0, 1.0], vec![1.0, 1.0]).unwrap_err();
        assert_eq!(e.field(), Some("x[1]"));
        let e = Spots::new(vec![], vec![], vec![]).unwrap_err();
        assert_eq!(e.field(), Some("spots"));
        let e = Spots::new(vec![1.0, 1.0], vec![2.0, 2.0], vec![1.0, 1.0]).unwrap_err();
        assert_eq!(e.field(), Some("spots"));
    }
}
