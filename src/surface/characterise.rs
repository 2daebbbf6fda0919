//! A measured topography and its characterisation.

use super::{
    summits, GwParameters, HeightMap, Moments, NayakPrediction, Plane, Summit, SummitStats,
};
use crate::error::{positive, Result};

/// A height map with its pixel size: the starting point of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct Topography {
    map: HeightMap,
    pixel_size: f64,
}

/// Everything measured on a topography (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Characterisation {
    /// Rows of the map (along y).
    pub rows: usize,
    /// Columns of the map (along x).
    pub cols: usize,
    /// Pixel size `dx` (m), the same along x and y.
    pub pixel_size_m: f64,
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
    /// A map of heights in m with square pixels of `pixel_size` m.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `pixel_size` unless finite and > 0.
    pub fn new(map: HeightMap, pixel_size: f64) -> Result<Self> {
        positive("pixel_size", pixel_size)?;
        Ok(Topography { map, pixel_size })
    }

    /// The height map.
    pub fn map(&self) -> &HeightMap {
        &self.map
    }

    /// The pixel size (m).
    pub fn pixel_size(&self) -> f64 {
        self.pixel_size
    }

    /// Removes the mean plane (the mean only if `periodic`), then measures
    /// the moments and the summits (interior pixels, or every pixel with
    /// wrapped neighbours if `periodic`). Parallel over rows; the result
    /// does not depend on the number of threads.
    ///
    /// # Errors
    /// [`crate::Error::Invalid`] named `topography` when the map is flat
    /// after the plane is removed (a moment is 0).
    pub fn characterise(&self, periodic: bool) -> Result<Characterisation> {
        let (rows, cols, dx) = (self.map.rows(), self.map.cols(), self.pixel_size);
        let plane = Plane::fit(self.map.heights(), rows, cols, dx, periodic);
        let z = plane.residual(self.map.heights(), cols);
        let moments = Moments::measure(&z, rows, cols, dx, periodic).check_not_flat()?;
        let summits = summits::find(&z, rows, cols, dx, periodic);
        let candidates = if periodic {
            rows * cols
        } else {
            (rows - 2) * (cols - 2)
        };
        let stats = SummitStats::new(&summits, candidates, dx);
        Ok(Characterisation {
            rows,
            cols,
            pixel_size_m: dx,
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

    /// Nominal area of the map, `rows cols dx^2` (m^2).
    pub fn nominal_area_m2(&self) -> f64 {
        (self.rows * self.cols) as f64 * self.pixel_size_m * self.pixel_size_m
    }
}
