//! A measured topography and its characterisation.

use super::{scan, GwParameters, HeightMap, Moments, NayakPrediction, Plane, Summit, SummitStats};
use crate::error::{Allowed, Error, Result};

/// Pixel sizes (m) a topography may have: from 1 pm (below any
/// instrument's sampling) to 1 km; beyond, the moments of any map in
/// range would overflow or mean nothing.
pub const PIXEL_SIZE_RANGE: Allowed = Allowed::closed(1e-12, 1e3);

/// Largest height magnitude (m) of a topography: 1 km (a map in another
/// unit needs its scale; with heights and pixels in range every moment is
/// finite).
pub const MAX_HEIGHT: f64 = 1e3;

/// Relief at or below this many ulps of the largest height is roundoff:
/// a map whose heights differ only there is flat.
const ROUNDOFF_ULPS: f64 = 1e3;

/// A height map with its pixel sizes: the starting point of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct Topography {
    map: HeightMap,
    pixel_size: f64,
    /// The pixel size along y (m), `pixel_size` unless given apart.
    pixel_size_y: f64,
    /// The largest height magnitude (m), kept for the roundoff test.
    largest: f64,
}

/// Everything measured on a topography (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Characterisation {
    /// Rows of the map (along y).
    pub rows: usize,
    /// Columns of the map (along x).
    pub cols: usize,
    /// Pixel size `dx` (m) along x (a row).
    pub pixel_size_m: f64,
    /// Pixel size `dy` (m) along y (a column): `dx` for square pixels.
    pub pixel_size_y_m: f64,
    /// Whether the map was treated as periodic.
    pub periodic: bool,
    /// The removed mean plane (the mean only when periodic).
    pub plane: Plane,
    /// Finite-difference moments of the residual heights.
    pub moments: Moments,
    /// The summits, row-major order, heights above the mean plane.
    pub summits: Vec<Summit>,
    /// Their statistics.
    pub stats: SummitStats,
}

impl Topography {
    /// A map of heights in m (`|h| <=` [`MAX_HEIGHT`]) with square pixels
    /// of `pixel_size` m (in [`PIXEL_SIZE_RANGE`]).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `pixel_size` outside its range;
    /// [`crate::Error::Invalid`] naming `heights` when the largest
    /// magnitude is above [`MAX_HEIGHT`].
    pub fn new(map: HeightMap, pixel_size: f64) -> Result<Self> {
        Topography::with_pixels(map, pixel_size, pixel_size)
    }

    /// A map of heights in m with pixels of `dx` along x (a row) and `dy`
    /// along y (a column), both in [`PIXEL_SIZE_RANGE`] (m): instruments
    /// often sample the slow axis more coarsely. Every measure (plane,
    /// moments, curvatures, densities, areas) uses each direction's own
    /// size.
    ///
    /// # Errors
    /// As [`Topography::new`]; a bad `dy` is named `pixel_size_y`.
    pub fn with_pixels(map: HeightMap, pixel_size: f64, dy: f64) -> Result<Self> {
        PIXEL_SIZE_RANGE.check("pixel_size", pixel_size)?;
        PIXEL_SIZE_RANGE.check("pixel_size_y", dy)?;
        let largest = map.largest();
        if !(largest <= MAX_HEIGHT) {
            return Err(Error::invalid(
                "heights",
                format!(
                    "the largest height magnitude {largest:e} m is above {MAX_HEIGHT:e} m \
                     (a map in another unit needs its height scale)"
                ),
            ));
        }
        Ok(Topography {
            map,
            pixel_size,
            pixel_size_y: dy,
            largest,
        })
    }

    /// The height map.
    pub fn map(&self) -> &HeightMap {
        &self.map
    }

    /// The map, giving the topography up.
    pub fn into_map(self) -> HeightMap {
        self.map
    }

    /// The pixel size along x (m).
    pub fn pixel_size(&self) -> f64 {
        self.pixel_size
    }

    /// The pixel size along y (m).
    pub fn pixel_size_y(&self) -> f64 {
        self.pixel_size_y
    }

    /// Removes the mean plane (the mean only if `periodic`), then measures
    /// the moments and the summits (interior pixels, or every pixel with
    /// wrapped neighbours if `periodic`). Parallel over rows; the result
    /// does not depend on the number of threads.
    ///
    /// # Errors
    /// [`crate::Error::Invalid`] named `topography` when the map is flat
    /// after the plane is removed: a moment is 0, or the relief (rms) is at
    /// roundoff level, within 1000 ulps of the largest height (a constant
    /// map of 3e-9 m used to give a GW radius of 8.9e10 m).
    pub fn characterise(&self, periodic: bool) -> Result<Characterisation> {
        let (rows, cols) = (self.map.rows(), self.map.cols());
        let (dx, dy) = (self.pixel_size, self.pixel_size_y);
        let heights = self.map.heights();
        let plane = Plane::fit_xy(heights, rows, cols, (dx, dy), periodic);
        // One fused pass over the residual heights, made row by row.
        let columns = plane.columns(cols);
        let scan = scan::scan(rows, cols, (dx, dy), periodic, |i, out| {
            plane.residual_row(i, &heights[i * cols..(i + 1) * cols], &columns, out)
        });
        let moments =
            Moments::from_sums(&scan.sums, rows, cols, (dx, dy), periodic).check_not_flat()?;
        let largest = self.largest;
        let roundoff = ROUNDOFF_ULPS * f64::EPSILON * largest;
        if !(moments.m0.sqrt() > roundoff) {
            return Err(Error::invalid(
                super::map::NAME,
                format!(
                    "flat: the relief after mean-plane removal ({:.3e} m rms) is at roundoff \
                     level for heights up to {largest:.3e} m (at most {roundoff:.3e} m)",
                    moments.m0.sqrt()
                ),
            ));
        }
        let summits = scan.summits;
        let candidates = if periodic {
            rows * cols
        } else {
            (rows - 2) * (cols - 2)
        };
        let stats = SummitStats::new(&summits, candidates, (dx, dy));
        Ok(Characterisation {
            rows,
            cols,
            pixel_size_m: dx,
            pixel_size_y_m: dy,
            periodic,
            plane,
            moments,
            summits,
            stats,
        })
    }
}

impl Characterisation {
    /// Nayak's bandwidth `alpha = m0 m4 / m2^2` of the measured moments.
    pub fn bandwidth_alpha(&self) -> f64 {
        self.moments.alpha()
    }

    /// The GW parameters McCool's relations give for the measured moments.
    pub fn gw_from_moments(&self) -> GwParameters {
        GwParameters::from_moments(&self.moments)
    }

    /// The continuum summit statistics predicted from the measured moments.
    pub fn nayak(&self) -> NayakPrediction {
        NayakPrediction::from_moments(&self.moments)
    }

    /// Nominal area of the map, `rows cols dx dy` (m^2).
    pub fn nominal_area_m2(&self) -> f64 {
        (self.rows * self.cols) as f64 * self.pixel_size_m * self.pixel_size_y_m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(f: impl Fn(usize, usize) -> f64) -> HeightMap {
        let h = (0..32 * 32).map(|k| f(k / 32, k % 32)).collect();
        HeightMap::new(32, 32, h).unwrap()
    }

    /// A tilted plane leaves only roundoff after the plane fit (9.9e-22 m
    /// rms): it was characterised as a surface; now it is flat.
    #[test]
    fn relief_at_roundoff_level_is_flat() {
        let plane = map(|i, j| 5e-6 + i as f64 * 1e-9 + j as f64 * 2e-9);
        let e = Topography::new(plane, 1e-7)
            .unwrap()
            .characterise(false)
            .unwrap_err();
        assert_eq!(e.field(), Some(super::super::map::NAME));
        assert!(e.to_string().contains("roundoff"), "{e}");
        // A relief of 1e-9 relative to the heights is not roundoff.
        let rough = map(|i, j| 1.0 + 1e-9 * ((i * 7 + j * 13) % 5) as f64);
        assert!(Topography::new(rough, 1e-7)
            .unwrap()
            .characterise(false)
            .is_ok());
    }

    /// The rows are split in fixed blocks added in block order: 1, 2 and 3
    /// threads give the same characterisation bit for bit (a map of 3
    /// blocks plus a partial one, periodic and not).
    #[test]
    fn the_result_does_not_depend_on_the_number_of_threads() {
        let (rows, cols) = (200, 77);
        let h = (0..rows * cols)
            .map(|k| {
                let (i, j) = ((k / cols) as f64, (k % cols) as f64);
                1e-8 * ((0.37 * i).sin() * (0.61 * j).cos() + (0.113 * i * j).sin()) + 2e-10 * i
            })
            .collect();
        let topo = Topography::new(HeightMap::new(rows, cols, h).unwrap(), 1e-7).unwrap();
        for periodic in [false, true] {
            let on = |threads: usize| {
                crate::test_threads::on_threads(threads, || topo.characterise(periodic).unwrap())
            };
            let one = on(1);
            assert!(one.stats.count > 100, "{}", one.stats.count);
            let bits = |c: &Characterisation| {
                let m = c.moments;
                let mut b = vec![
                    m.m0,
                    m.m2,
                    m.m4,
                    c.plane.c0,
                    c.plane.slope_x,
                    c.plane.slope_y,
                ];
                b.extend(
                    c.summits
                        .iter()
                        .flat_map(|s| [s.height_m, s.curvature_per_m]),
                );
                b.into_iter().map(f64::to_bits).collect::<Vec<_>>()
            };
            for threads in [2, 3] {
                let many = on(threads);
                let what = format!("{threads} threads, periodic {periodic}");
                assert!(bits(&many) == bits(&one), "{what}");
                assert!(many == one, "{what}");
            }
        }
    }

    #[test]
    fn pixel_size_and_heights_have_ranges() {
        let ok = map(|i, j| 1e-9 * ((i * 7 + j * 13) % 5) as f64);
        for dx in [1e-300, 1e-13, 1e4, f64::NAN, 0.0] {
            let e = Topography::new(ok.clone(), dx).unwrap_err();
            assert_eq!(e.field(), Some("pixel_size"), "{dx}");
        }
        let big = map(|i, j| 1e300 * ((i * 7 + j * 13) % 5) as f64);
        let e = Topography::new(big, 1e-7).unwrap_err();
        assert_eq!(e.field(), Some("heights"));
    }
}
