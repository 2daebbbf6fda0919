//! Summits on a grid: pixels strictly higher than their 8 neighbours.
//!
//! Candidates are the interior pixels (rows `1..rows-1`, columns
//! `1..cols-1`, 0-based, end exclusive), or every pixel with neighbours
//! wrapped around the edges for a periodic map. A summit's curvature is
//! minus half the 5-point Laplacian,
//! `kappa = -(z[i+1,j] + z[i-1,j] + z[i,j+1] + z[i,j-1] - 4 z[i,j]) / (2 dx^2)`
//! (the mean of the two principal curvatures; `1/kappa` is the summit
//! radius of a paraboloid cap).

/// One measured summit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summit {
    /// Row index `i` (y = i dx).
    pub row: usize,
    /// Column index `j` (x = j dx).
    pub col: usize,
    /// Height above the mean plane (m).
    pub height_m: f64,
    /// Mean curvature from the 5-point Laplacian (1/m); > 0 at a summit
    /// unless the Laplacian is degenerate.
    pub curvature_per_m: f64,
}

/// Statistics of the summits of a map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SummitStats {
    /// Number of summits.
    pub count: usize,
    /// Number of candidate pixels (interior, or all when periodic).
    pub candidates: usize,
    /// `count / (candidates dx^2)` (1/m^2).
    pub density_per_m2: f64,
    /// Mean summit curvature (1/m); `None` without summits.
    pub mean_curvature_per_m: Option<f64>,
    /// `1 / mean_curvature_per_m` (m).
    pub radius_m: Option<f64>,
    /// Standard deviation of summit heights, divisor N (m).
    pub height_std_m: Option<f64>,
    /// Mean summit height above the mean plane (m).
    pub mean_height_m: Option<f64>,
}

/// The summits of residual heights `z` (row-major, `rows, cols >= 3`),
/// in row-major order.
#[cfg(test)]
pub(crate) fn find(z: &[f64], rows: usize, cols: usize, dx: f64, periodic: bool) -> Vec<Summit> {
    super::scan::scan(rows, cols, (dx, dx), periodic, |i, out| {
        out.copy_from_slice(&z[i * cols..(i + 1) * cols])
    })
    .summits
}

impl SummitStats {
    /// Statistics of `summits` found among `candidates` pixels of `dx` x
    /// `dy`.
    pub(crate) fn new(summits: &[Summit], candidates: usize, (dx, dy): (f64, f64)) -> Self {
        let n = summits.len();
        let density_per_m2 = n as f64 / (candidates as f64 * dx * dy);
        if n == 0 {
            return SummitStats {
                count: 0,
                candidates,
                density_per_m2,
                mean_curvature_per_m: None,
                radius_m: None,
                height_std_m: None,
                mean_height_m: None,
            };
        }
        let nf = n as f64;
        let kappa = summits.iter().map(|s| s.curvature_per_m).sum::<f64>() / nf;
        let mean = summits.iter().map(|s| s.height_m).sum::<f64>() / nf;
        let var = summits
            .iter()
            .map(|s| (s.height_m - mean) * (s.height_m - mean))
            .sum::<f64>()
            / nf;
        SummitStats {
            count: n,
            candidates,
            density_per_m2,
            mean_curvature_per_m: Some(kappa),
            radius_m: Some(1.0 / kappa),
            height_std_m: Some(var.sqrt()),
            mean_height_m: Some(mean),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strict_rule_interior_and_wrapped() {
        // A single bump at (1, 1) of a 4 x 4 map; a plateau pair at row 2
        // (equal heights) is not a summit; a corner peak counts only when
        // periodic.
        #[rustfmt::skip]
        let z = [
            0.0, 0.0, 0.0, 0.0,
            0.0, 2.0, 0.0, 0.0,
            0.0, 0.0, 1.0, 1.0,
            0.0, 0.0, 0.0, 3.0,
        ];
        let dx = 0.5;
        let s = find(&z, 4, 4, dx, false);
        assert_eq!(s.len(), 1);
        assert_eq!((s[0].row, s[0].col, s[0].height_m), (1, 1, 2.0));
        // -(0 + 0 + 0 + 0 - 8) / (2 * 0.25) = 16.
        assert_eq!(s[0].curvature_per_m, 16.0);
        let p = find(&z, 4, 4, dx, true);
        assert_eq!(
            p.iter().map(|s| (s.row, s.col)).collect::<Vec<_>>(),
            [(1, 1), (3, 3)]
        );
        // Wrapped Laplacian at (3,3): up 1, down z[0][3] = 0, left 0, right z[3][0] = 0.
        assert_eq!(p[1].curvature_per_m, -(1.0 - 12.0) * 2.0);
        let st = SummitStats::new(&p, 16, (dx, dx));
        assert_eq!(st.count, 2);
        assert_eq!(st.density_per_m2, 2.0 / 4.0);
        assert_eq!(st.mean_height_m, Some(2.5));
        assert_eq!(st.height_std_m, Some(0.5));
        assert_eq!(st.radius_m, Some(1.0 / 19.0));
        assert_eq!(SummitStats::new(&[], 4, (dx, dx)).radius_m, None);
    }
}
