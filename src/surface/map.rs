//! A validated height map: rows x cols finite heights, row-major.

use crate::error::{Error, Result};

/// The name errors about a map's content carry; the CLI renames it to the
/// file (`Error::renamed`).
pub(crate) const NAME: &str = "topography";

/// Heights `z[i][j]` (m, or the file's unit before scaling) on a regular
/// grid, row-major: `heights[i * cols + j]`, row `i` along y, column `j`
/// along x.
#[derive(Debug, Clone, PartialEq)]
pub struct HeightMap {
    rows: usize,
    cols: usize,
    heights: Vec<f64>,
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
        if let Some(k) = heights.iter().position(|z| !z.is_finite()) {
            let what = if heights[k].is_nan() {
                "NaN"
            } else {
                "infinite"
            };
            return Err(Error::invalid(
                NAME,
                format!("{what} height at row {}, column {}", k / cols, k % cols),
            ));
        }
        Ok(HeightMap {
            rows,
            cols,
            heights,
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

    /// The same map with every height multiplied by `scale` (e.g. `1e-9`
    /// for a map in nm).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] named `scale` unless it is finite and > 0, and
    /// [`Error::Invalid`] when a scaled height overflows.
    pub fn scaled(mut self, scale: f64) -> Result<Self> {
        crate::error::positive("scale", scale)?;
        if scale != 1.0 {
            self.heights.iter_mut().for_each(|z| *z *= scale);
            if self.heights.iter().any(|z| !z.is_finite()) {
                return Err(Error::invalid("scale", "a scaled height overflows"));
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
}
