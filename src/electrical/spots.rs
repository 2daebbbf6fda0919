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

/// Single-core seconds per `n^3` of the exact solve (measured on a
/// 2-core x86-64: 1.24 s at 5,000 spots, 4.5 s at 8,000; rounded up).
pub const EXACT_SECONDS_PER_CUBE: f64 = 1e-11;

/// Peak bytes per `n^2` of the exact solve: the dense matrix and its
/// factor, 8 bytes each (measured: 397 MB peak at 5,000 spots).
pub const EXACT_BYTES_PER_SQUARE: f64 = 16.0;

/// Spots with validated positions and radii.
#[derive(Debug, Clone, PartialEq)]
pub struct Spots {
    x: Vec<f64>,
    y: Vec<f64>,
    radius: Vec<f64>,
}

/// Overlapping spots gathered into single spots by
/// [`Spots::merging`].
#[derive(Debug, Clone, PartialEq)]
pub struct Merged {
    /// The spots after merging (no two overlap).
    pub spots: Spots,
    /// The groups of input indices merged into one spot (each of two or
    /// more; empty when nothing overlapped).
    pub groups: Vec<Vec<usize>>,
}

impl Spots {
    /// Spots from centre coordinates `x`, `y` (m, finite) and radii
    /// `radius` (m, > 0), all of one length >= 1; no two spots may overlap
    /// (centre distance `s_ij < a_i + a_j`), since the point-source mutual
    /// resistance `rho/(pi s)` of separate spots then means nothing (two
    /// spots of 1 um 0.1 um apart gave 3.7 times one spot alone).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `x[i]`, `y[i]` or `radius[i]`;
    /// [`Error::Invalid`] naming `spots` for empty or unequal lists, or for
    /// the first overlapping pair (its indices, distance and radii).
    pub fn new(x: Vec<f64>, y: Vec<f64>, radius: Vec<f64>) -> Result<Self> {
        let spots = Spots::checked(x, y, radius)?;
        if let Some((i, j)) = spots.overlaps().first().copied() {
            return Err(Error::invalid(
                "spots",
                format!(
                    "spots {i} and {j} (0-based) overlap: centres {:.6e} m apart, radii \
                     {:.6e} + {:.6e} m; separate spots must not overlap (merge them into one \
                     spot of their joint area)",
                    spots.distance(i, j),
                    spots.radius[i],
                    spots.radius[j]
                ),
            ));
        }
        Ok(spots)
    }

    /// Spots as [`Spots::new`], with overlapping spots merged instead of
    /// refused: each group of spots linked by overlaps becomes one spot of
    /// their joint area (`a = sqrt(sum a_i^2)`) at their area-weighted
    /// centroid, repeated until no two overlap. For spots placed at random
    /// (a population's) or clusters' equivalent circles.
    ///
    /// # Errors
    /// As [`Spots::new`], except for overlaps.
    pub fn merging(x: Vec<f64>, y: Vec<f64>, radius: Vec<f64>) -> Result<Merged> {
        let mut spots = Spots::checked(x, y, radius)?;
        // members[k]: the input indices of spot k.
        let mut members: Vec<Vec<usize>> = (0..spots.len()).map(|i| vec![i]).collect();
        loop {
            let pairs = spots.overlaps();
            if pairs.is_empty() {
                break;
            }
            let mut parent: Vec<usize> = (0..spots.len()).collect();
            fn root(p: &mut [usize], mut i: usize) -> usize {
                while p[i] != i {
                    p[i] = p[p[i]];
                    i = p[i];
                }
                i
            }
            for (i, j) in pairs {
                let (ri, rj) = (root(&mut parent, i), root(&mut parent, j));
                if ri != rj {
                    parent[ri.max(rj)] = ri.min(rj);
                }
            }
            let mut index = vec![usize::MAX; spots.len()];
            let (mut x, mut y, mut a2, mut m) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
            for (k, mk) in members.iter().enumerate() {
                let r = root(&mut parent, k);
                if index[r] == usize::MAX {
                    index[r] = a2.len();
                    x.push(0.0);
                    y.push(0.0);
                    a2.push(0.0);
                    m.push(Vec::new());
                }
                let g = index[r];
                let w = spots.radius[k] * spots.radius[k];
                x[g] += w * spots.x[k];
                y[g] += w * spots.y[k];
                a2[g] += w;
                m[g].extend(mk.iter().copied());
            }
            for g in 0..a2.len() {
                x[g] /= a2[g];
                y[g] /= a2[g];
            }
            spots = Spots {
                x,
                y,
                radius: a2.iter().map(|w| w.sqrt()).collect(),
            };
            members = m;
        }
        let mut groups: Vec<Vec<usize>> = members.into_iter().filter(|g| g.len() > 1).collect();
        for g in &mut groups {
            g.sort_unstable();
        }
        Ok(Merged { spots, groups })
    }

    /// Validated values, overlaps not checked.
    fn checked(x: Vec<f64>, y: Vec<f64>, radius: Vec<f64>) -> Result<Self> {
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
        Ok(Spots { x, y, radius })
    }

    /// The overlapping pairs `(i, j)`, `i < j` (centre distance `<` the
    /// sum of the radii; coinciding centres included), ordered: a sweep
    /// along `x` compares only spots closer in `x` than the sum of their
    /// radii and the largest radius.
    fn overlaps(&self) -> Vec<(usize, usize)> {
        let n = self.len();
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&a, &b| self.x[a].total_cmp(&self.x[b]));
        let a_max = self.radius.iter().copied().fold(0.0, f64::max);
        let mut pairs = Vec::new();
        for (k, &i) in order.iter().enumerate() {
            let reach = self.radius[i] + a_max;
            for &j in &order[k + 1..] {
                if self.x[j] - self.x[i] > reach {
                    break;
                }
                let s = self.distance(i, j);
                if !(s >= self.radius[i] + self.radius[j]) {
                    pairs.push((i.min(j), i.max(j)));
                }
            }
        }
        pairs.sort_unstable();
        pairs
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

    /// The estimated cost of [`Spots::exact`] on `n` spots: `(seconds,
    /// bytes)`, [`EXACT_SECONDS_PER_CUBE`]` x n^3` of single-core time and
    /// [`EXACT_BYTES_PER_SQUARE`]` x n^2` bytes at the peak (the matrix
    /// and its factor).
    pub fn exact_cost(n: usize) -> (f64, f64) {
        let n = n as f64;
        (
            EXACT_SECONDS_PER_CUBE * n * n * n,
            EXACT_BYTES_PER_SQUARE * n * n,
        )
    }

    /// Exact equal-potential resistance (Ohm): solve `M I = 1`, `R =
    /// 1/sum I`. O(n^3) time, O(n^2) memory (2000 spots: 32 MB, well under
    /// a second; [`Spots::exact_cost`] estimates both).
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
        if total.is_finite() && total > 0.0 && (1.0 / total).is_finite() {
            return Ok(1.0 / total);
        }
        // Why: a pair so close that its point-source mutual resistance
        // passes a spot's own, or spots so small that their currents leave
        // the floating-point range.
        let own = (0..n).map(|i| m[(i, i)]);
        let own_min = own.clone().fold(f64::INFINITY, f64::min);
        let own_all_finite = own.clone().all(f64::is_finite);
        let own_max = own.fold(0.0, f64::max);
        let mut closest = f64::INFINITY;
        for i in 0..n {
            for j in 0..i {
                closest = closest.min(self.distance(i, j));
            }
        }
        let mutual_max = k / closest;
        let r_min = self.radius.iter().copied().fold(f64::INFINITY, f64::min);
        Err(Error::invalid(
            "spots",
            if mutual_max >= own_min {
                format!(
                    "the equal-potential system is singular: spots too close for point sources \
                     (the closest pair is {closest:e} m apart, its mutual resistance {mutual_max:e} \
                     Ohm above a spot's own {own_min:e} Ohm)"
                )
            } else {
                // (no NaN in the words: a quantity that is not a number is
                // said so)
                let own = if own_max > 0.0 && own_max.is_finite() && own_all_finite {
                    format!("up to {own_max:e} Ohm")
                } else {
                    "not all finite numbers".to_string()
                };
                let current = if total.is_finite() {
                    format!("{total:e} A/V, not a positive current with a finite inverse")
                } else {
                    "not a finite number".to_string()
                };
                format!(
                    "the spots' own resistances ({own}, radii down to {r_min:e} m) leave the \
                     total current out of the floating-point range ({current}): spots this small \
                     carry no current this solve can resolve"
                )
            },
        ))
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

    /// Two spots of 1 um, 0.1 um apart, gave 0.0449 Ohm (3.7 times one
    /// spot): refused naming the pair; merged, they are one spot of their
    /// joint area.
    #[test]
    fn overlapping_spots_are_refused_or_merged() {
        let (x, y, a) = (vec![0.0, 1e-7, 5e-5], vec![0.0; 3], vec![1e-6; 3]);
        let e = Spots::new(x.clone(), y.clone(), a.clone()).unwrap_err();
        assert_eq!(e.field(), Some("spots"));
        assert!(
            e.to_string().contains("spots 0 and 1 (0-based) overlap"),
            "{e}"
        );
        // Touching is not overlapping.
        assert!(Spots::new(vec![0.0, 2e-6], vec![0.0; 2], vec![1e-6; 2]).is_ok());
        let m = Spots::merging(x, y, a).unwrap();
        assert_eq!(m.groups, vec![vec![0, 1]]);
        assert_eq!(m.spots.len(), 2);
        assert!((m.spots.radii()[0] - 2f64.sqrt() * 1e-6).abs() < 1e-20);
        assert!((m.spots.x[0] - 0.5e-7).abs() < 1e-20);
        // A chain merges in steps: the merged spot reaches the third.
        let m = Spots::merging(
            vec![0.0, 1.5e-6, 3.2e-6],
            vec![0.0; 3],
            vec![1e-6, 1e-6, 1e-6],
        )
        .unwrap();
        assert_eq!(m.groups, vec![vec![0, 1, 2]]);
        assert_eq!(m.spots.len(), 1);
        assert!((m.spots.radii()[0] - 3f64.sqrt() * 1e-6).abs() < 1e-20);
        // The sweep finds what all pairs find.
        let n = 400;
        let mut state = 7u64;
        let mut u = || {
            state = crate::numeric::mix::splitmix64(state);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (x, y, a): (Vec<f64>, Vec<f64>, Vec<f64>) =
            (0..n).map(|_| (u(), u(), 0.02 * u())).fold(
                (vec![], vec![], vec![]),
                |(mut x, mut y, mut a), (p, q, r)| {
                    x.push(p);
                    y.push(q);
                    a.push(r);
                    (x, y, a)
                },
            );
        let s = Spots::checked(x, y, a).unwrap();
        let mut brute = Vec::new();
        for i in 0..n {
            for j in i + 1..n {
                if s.distance(i, j) < s.radius[i] + s.radius[j] {
                    brute.push((i, j));
                }
            }
        }
        assert!(!brute.is_empty());
        assert_eq!(s.overlaps(), brute);
    }
}
