//! Missing pixels filled from their neighbours, only when asked
//! (`--fill-missing`).

use crate::error::{Error, Result};

/// Fills the NaN pixels of a row-major `rows x cols` map layer by layer:
/// each pass gives every missing pixel with at least one known 4-neighbour
/// the mean of those neighbours (known before the pass), until none is
/// missing. Deterministic; O(pixels x layers). Returns how many were
/// filled.
pub(super) fn fill(z: &mut [f64], rows: usize, cols: usize) -> Result<usize> {
    let mut todo: Vec<usize> = (0..z.len()).filter(|&k| z[k].is_nan()).collect();
    let total = todo.len();
    if total == 0 {
        return Ok(0);
    }
    if total == z.len() {
        return Err(Error::invalid(
            "topography",
            "every pixel is missing: nothing to fill from",
        ));
    }
    let mut layer = Vec::new();
    while !todo.is_empty() {
        layer.clear();
        let mut rest = Vec::new();
        for &k in &todo {
            let (i, j) = (k / cols, k % cols);
            let mut sum = 0.0;
            let mut n = 0.0;
            let mut add = |v: f64| {
                if !v.is_nan() {
                    sum += v;
                    n += 1.0;
                }
            };
            if i > 0 {
                add(z[k - cols]);
            }
            if i + 1 < rows {
                add(z[k + cols]);
            }
            if j > 0 {
                add(z[k - 1]);
            }
            if j + 1 < cols {
                add(z[k + 1]);
            }
            if n > 0.0 {
                layer.push((k, sum / n));
            } else {
                rest.push(k);
            }
        }
        for &(k, v) in &layer {
            z[k] = v;
        }
        todo = rest;
    }
    Ok(total)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fills_holes_from_their_edges_and_refuses_an_empty_map() {
        let n = f64::NAN;
        let mut z = vec![1.0, 1.0, 1.0, 1.0, n, 3.0, 1.0, 1.0, 1.0];
        assert_eq!(fill(&mut z, 3, 3).unwrap(), 1);
        assert_eq!(z[4], 1.5);
        let mut z = vec![n, n, n, n, n, n, n, n, 2.0];
        assert_eq!(fill(&mut z, 3, 3).unwrap(), 8);
        assert!(z.iter().all(|v| *v == 2.0));
        let mut z = vec![n; 9];
        assert!(fill(&mut z, 3, 3).is_err());
    }
}
