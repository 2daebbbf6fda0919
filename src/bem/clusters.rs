//! Contact clusters: connected components of the contact pixels
//! (4-neighbour connectivity, wrapped across the edges of a periodic map).

/// One cluster of contact pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cluster {
    /// Pixels in the cluster.
    pub pixels: usize,
    /// Centroid column (x, in pixels; on a periodic map the circular mean,
    /// in `[0, cols)`).
    pub x_px: f64,
    /// Centroid row (y, in pixels).
    pub y_px: f64,
}

/// A log2 bin of the cluster-size distribution.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SizeBin {
    /// Smallest size in the bin (pixels), a power of 2.
    pub min_px: usize,
    /// Largest size in the bin (pixels).
    pub max_px: usize,
    /// Clusters in the bin.
    pub count: usize,
}

fn find(parent: &mut [u32], mut i: u32) -> u32 {
    while parent[i as usize] != i {
        let p = parent[parent[i as usize] as usize];
        parent[i as usize] = p;
        i = p;
    }
    i
}

/// The clusters of `contact` (row-major `rows x cols`), largest first.
pub fn clusters(contact: &[bool], rows: usize, cols: usize, periodic: bool) -> Vec<Cluster> {
    let n = rows * cols;
    let mut parent: Vec<u32> = (0..n as u32).collect();
    let union = |parent: &mut Vec<u32>, a: usize, b: usize| {
        let (ra, rb) = (find(parent, a as u32), find(parent, b as u32));
        if ra != rb {
            let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
            parent[hi as usize] = lo;
        }
    };
    for i in 0..rows {
        for j in 0..cols {
            let k = i * cols + j;
            if !contact[k] {
                continue;
            }
            if j + 1 < cols || periodic {
                let r = i * cols + (j + 1) % cols;
                if contact[r] {
                    union(&mut parent, k, r);
                }
            }
            if i + 1 < rows || periodic {
                let d = ((i + 1) % rows) * cols + j;
                if contact[d] {
                    union(&mut parent, k, d);
                }
            }
        }
    }
    // Accumulate per root: count and angle sums (periodic) or plain sums.
    let tau = std::f64::consts::TAU;
    let mut acc: std::collections::HashMap<u32, [f64; 5]> = std::collections::HashMap::new();
    for (k, _) in contact.iter().enumerate().filter(|(_, c)| **c) {
        let root = find(&mut parent, k as u32);
        let (i, j) = ((k / cols) as f64, (k % cols) as f64);
        let e = acc.entry(root).or_insert([0.0; 5]);
        e[0] += 1.0;
        if periodic {
            let (ax, ay) = (tau * j / cols as f64, tau * i / rows as f64);
            e[1] += ax.cos();
            e[2] += ax.sin();
            e[3] += ay.cos();
            e[4] += ay.sin();
        } else {
            e[1] += j;
            e[3] += i;
        }
    }
    let mut out: Vec<Cluster> = acc
        .into_values()
        .map(|e| {
            let (x, y) = if periodic {
                let ang =
                    |c: f64, s: f64, len: usize| (s.atan2(c).rem_euclid(tau)) / tau * len as f64;
                (ang(e[1], e[2], cols), ang(e[3], e[4], rows))
            } else {
                (e[1] / e[0], e[3] / e[0])
            };
            Cluster {
                pixels: e[0] as usize,
                x_px: x,
                y_px: y,
            }
        })
        .collect();
    out.sort_by(|a, b| {
        b.pixels
            .cmp(&a.pixels)
            .then(a.y_px.total_cmp(&b.y_px))
            .then(a.x_px.total_cmp(&b.x_px))
    });
    out
}

/// The size distribution in log2 bins `[2^k, 2^(k+1) - 1]` (empty bins left out).
pub fn size_distribution(clusters: &[Cluster]) -> Vec<SizeBin> {
    let mut counts: Vec<usize> = Vec::new();
    for c in clusters {
        let k = (usize::BITS - 1 - c.pixels.max(1).leading_zeros()) as usize;
        if counts.len() <= k {
            counts.resize(k + 1, 0);
        }
        counts[k] += 1;
    }
    counts
        .iter()
        .enumerate()
        .filter(|(_, c)| **c > 0)
        .map(|(k, c)| SizeBin {
            min_px: 1 << k,
            max_px: (1 << (k + 1)) - 1,
            count: *c,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn components_wrap_only_when_periodic() {
        // 4 x 5 map: an L of 3 pixels, one pixel, and a pair split across the edge.
        let m = [
            "X...X", //
            "XX...", //
            ".....", //
            "..X..",
        ];
        let contact: Vec<bool> = m.iter().flat_map(|r| r.chars().map(|c| c == 'X')).collect();
        let open = clusters(&contact, 4, 5, false);
        assert_eq!(
            open.iter().map(|c| c.pixels).collect::<Vec<_>>(),
            vec![3, 1, 1]
        );
        let wrap = clusters(&contact, 4, 5, true);
        // (0,4) joins the L across x; nothing joins (3,2).
        assert_eq!(
            wrap.iter().map(|c| c.pixels).collect::<Vec<_>>(),
            vec![4, 1]
        );
        let bins = size_distribution(&open);
        assert_eq!(
            bins[0],
            SizeBin {
                min_px: 1,
                max_px: 1,
                count: 2
            }
        );
        assert_eq!(
            bins[1],
            SizeBin {
                min_px: 2,
                max_px: 3,
                count: 1
            }
        );
        assert!(
            (open[0].x_px - 1.0 / 3.0).abs() < 1e-12 && (open[0].y_px - 2.0 / 3.0).abs() < 1e-12
        );
    }
}
