//! A validated height map: rows x cols finite heights, row-major.

use crate::error::{Error, Result};
use std::sync::Arc;

/// The name errors about a map's content carry; the CLI renames it to the
/// file (`Error::renamed`).
pub(crate) const NAME: &str = "topography";

/// Heights kept outside a `Vec` (a memory-mapped file): what a
/// [`HeightMap`] may hold instead of its own copy, so that a map read from
/// a file is the file's pages and nothing else.
pub trait HeightSource: Send + Sync + std::fmt::Debug {
    /// The heights, row-major (m, or the file's unit before scaling).
    fn heights(&self) -> &[f64];
}

/// The heights of a map: its own `Vec`, or a shared [`HeightSource`]
/// (copied into a `Vec` on the first change, [`Heights::to_mut`]).
#[derive(Debug, Clone)]
pub enum Heights {
    /// Heights owned.
    Owned(Vec<f64>),
    /// Heights held elsewhere, read only.
    Shared(Arc<dyn HeightSource>),
}

impl Heights {
    /// The heights as a mutable slice, copying shared ones into a `Vec`
    /// first.
    pub fn to_mut(&mut self) -> &mut [f64] {
        if let Heights::Shared(s) = self {
            *self = Heights::Owned(s.heights().to_vec());
        }
        match self {
            Heights::Owned(v) => v.as_mut_slice(),
            Heights::Shared(_) => &mut [],
        }
    }

    /// The heights as a `Vec` (a copy of shared ones).
    pub fn into_vec(self) -> Vec<f64> {
        match self {
            Heights::Owned(v) => v,
            Heights::Shared(s) => s.heights().to_vec(),
        }
    }
}

impl std::ops::Deref for Heights {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        match self {
            Heights::Owned(v) => v,
            Heights::Shared(s) => s.heights(),
        }
    }
}

impl From<Vec<f64>> for Heights {
    fn from(v: Vec<f64>) -> Self {
        Heights::Owned(v)
    }
}

impl PartialEq for Heights {
    fn eq(&self, other: &Self) -> bool {
        self[..] == other[..]
    }
}

/// Heights `z[i][j]` (m, or the file's unit before scaling) on a regular
/// grid, row-major: `heights[i * cols + j]`, row `i` along y, column `j`
/// along x.
#[derive(Debug, Clone, PartialEq)]
pub struct HeightMap {
    rows: usize,
    cols: usize,
    heights: Heights,
    /// The largest height magnitude, found while validating.
    largest: f64,
}

/// The largest `|z|` of `z`, or `None` when a height is NaN or infinite:
/// one pass in 8 lanes (a lane's maximum ignores nothing: a NaN or an
/// infinity fails `|z| <= f64::MAX` and is flagged).
fn largest_finite(z: &[f64]) -> Option<f64> {
    const L: usize = 8;
    let mut m = [0.0f64; L];
    let mut ok = [true; L];
    let chunks = z.chunks_exact(L);
    let tail = chunks.remainder();
    for c in chunks {
        for k in 0..L {
            let a = c[k].abs();
            ok[k] &= a <= f64::MAX;
            m[k] = if a > m[k] { a } else { m[k] };
        }
    }
    let mut largest = m.iter().fold(0.0f64, |x, y| x.max(*y));
    let mut fine = ok.iter().all(|b| *b);
    for v in tail {
        let a = v.abs();
        fine &= a <= f64::MAX;
        largest = largest.max(a);
    }
    fine.then_some(largest)
}

impl HeightMap {
    /// Validates a row-major map.
    ///
    /// # Errors
    /// [`Error::Invalid`] named `topography` when the map is empty, a 1-D
    /// profile (one row or one column), smaller than 3 x 3 (no interior
    /// pixel), when `heights.len() != rows * cols`, or when a height is NaN
    /// or infinite (the message gives its row and column, from 0).
    pub fn new(rows: usize, cols: usize, heights: Vec<f64>) -> Result<Self> {
        HeightMap::from_heights(rows, cols, Heights::Owned(heights))
    }

    /// Validates a row-major map held in `heights` (owned, or shared such
    /// as a memory-mapped file, which is then never copied unless changed):
    /// one pass over the heights.
    ///
    /// # Errors
    /// As [`HeightMap::new`].
    pub fn from_heights(rows: usize, cols: usize, heights: Heights) -> Result<Self> {
        if rows == 0 || cols == 0 || heights.is_empty() {
            return Err(Error::invalid(NAME, "empty: no heights"));
        }
        if rows == 1 || cols == 1 {
            return Err(Error::invalid(
                NAME,
                format!("a 1-D profile ({rows} x {cols}); a height map must be 2-D"),
            ));
        }
        if rows < 3 || cols < 3 {
            return Err(Error::invalid(
                NAME,
                format!("{rows} x {cols} pixels; at least 3 x 3 are needed"),
            ));
        }
        if heights.len() != rows * cols {
            return Err(Error::invalid(
                NAME,
                format!("{} heights for {rows} x {cols} pixels", heights.len()),
            ));
        }
        let Some(largest) = largest_finite(&heights) else {
            let k = heights.iter().position(|z| !z.is_finite()).unwrap_or(0);
            let what = if heights[k].is_nan() {
                "NaN"
            } else {
                "infinite"
            };
            return Err(Error::invalid(
                NAME,
                format!("{what} height at row {}, column {}", k / cols, k % cols),
            ));
        };
        Ok(HeightMap {
            rows,
            cols,
            heights,
            largest,
        })
    }

    /// Number of rows (along y).
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns (along x).
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// The heights, row-major.
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }

    /// The heights, giving the map up (a copy when they are shared).
    pub fn into_heights(self) -> Vec<f64> {
        self.heights.into_vec()
    }

    /// Whether the heights are held outside the map (a memory-mapped file)
    /// rather than in its own `Vec`.
    pub fn is_shared(&self) -> bool {
        matches!(self.heights, Heights::Shared(_))
    }

    /// The largest height magnitude `max |z|` (found while validating).
    pub fn largest(&self) -> f64 {
        self.largest
    }

    /// The same map with every height multiplied by `scale` (e.g. `1e-9`
    /// for a map in nm).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] named `scale` unless it is finite and > 0, and
    /// [`Error::Invalid`] when a scaled height overflows.
    pub fn scaled(mut self, scale: f64) -> Result<Self> {
        crate::error::positive("scale", scale)?;
        if scale != 1.0 {
            // Rounding is monotone: the largest scaled magnitude is the
            // largest magnitude scaled, to the bit.
            self.largest *= scale;
            if !(self.largest <= f64::MAX) {
                return Err(Error::invalid("scale", "a scaled height overflows"));
            }
            let shared = match &mut self.heights {
                Heights::Owned(v) => {
                    v.iter_mut().for_each(|z| *z *= scale);
                    None
                }
                Heights::Shared(s) => Some(s.heights().iter().map(|z| z * scale).collect()),
            };
            if let Some(v) = shared {
                self.heights = Heights::Owned(v);
            }
        }
        Ok(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_each_bad_shape_and_value_with_its_reason() {
        let msg = |r, c, h: Vec<f64>| HeightMap::new(r, c, h).unwrap_err().to_string();
        assert!(msg(0, 0, vec![]).contains("empty"));
        assert!(msg(1, 4, vec![0.0; 4]).contains("1-D"));
        assert!(msg(2, 4, vec![0.0; 8]).contains("at least 3 x 3"));
        assert!(msg(3, 3, vec![0.0; 8]).contains("8 heights for 3 x 3"));
        let mut h = vec![0.0; 9];
        h[5] = f64::NAN;
        assert!(msg(3, 3, h.clone()).contains("NaN height at row 1, column 2"));
        h[5] = f64::NEG_INFINITY;
        assert!(msg(3, 3, h).contains("infinite height at row 1, column 2"));
        let ok = HeightMap::new(3, 3, vec![1.0; 9]).unwrap();
        assert_eq!(ok.scaled(1e-9).unwrap().heights()[0], 1e-9);
        let ok = HeightMap::new(3, 3, vec![1e300; 9]).unwrap();
        assert!(ok.clone().scaled(1e10).is_err());
        assert_eq!(ok.scaled(-1.0).unwrap_err().field(), Some("scale"));
    }

    #[derive(Debug)]
    struct Held(Vec<f64>);
    impl HeightSource for Held {
        fn heights(&self) -> &[f64] {
            &self.0
        }
    }

    #[test]
    fn the_one_validating_pass_finds_every_bad_height_and_the_largest() {
        // 8 lanes and a tail of 3: a bad height in every position is found.
        let z: Vec<f64> = (0..35).map(|k| (k as f64 - 17.0) * 0.5).collect();
        assert_eq!(largest_finite(&z), Some(8.5));
        for k in 0..35 {
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                let mut w = z.clone();
                w[k] = bad;
                assert_eq!(largest_finite(&w), None, "{k} {bad}");
            }
        }
        let map = HeightMap::new(5, 7, z[..35].to_vec()).unwrap();
        assert_eq!(map.largest(), 8.5);
        assert_eq!(map.clone().scaled(0.1).unwrap().largest(), 8.5 * 0.1);
    }

    #[test]
    fn shared_heights_are_the_same_map_and_copied_only_when_changed() {
        let z: Vec<f64> = (0..12).map(|k| k as f64 * 0.25 - 1.0).collect();
        let held = Heights::Shared(Arc::new(Held(z.clone())));
        let map = HeightMap::from_heights(3, 4, held).unwrap();
        assert!(map.is_shared());
        assert_eq!(map, HeightMap::new(3, 4, z.clone()).unwrap());
        let scaled = map.clone().scaled(2.0).unwrap();
        assert!(!scaled.is_shared());
        assert_eq!(scaled.heights()[11], 2.0 * z[11]);
        assert_eq!(map.into_heights(), z);
        let mut h = Heights::Shared(Arc::new(Held(vec![f64::NAN; 9])));
        assert!(HeightMap::from_heights(3, 3, h.clone()).is_err());
        h.to_mut()[0] = 1.0;
        assert!(matches!(&h, Heights::Owned(v) if v[0] == 1.0));
    }
}
