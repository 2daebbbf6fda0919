//! One fused pass over the residual heights: the difference sums of the
//! moments ([`super::Moments`]) and the summit test ([`super::Summit`])
//! together, each row read from the map once (plus two halo rows per block).
//!
//! The rows are split into blocks of [`BLOCK_ROWS`]; each block keeps three
//! row buffers (the rows above, at and below the current one, `cols` values
//! each) and fills them with residual heights as it goes, so no map-sized
//! buffer is made. Within a row the sums run in [`LANES`] interleaved
//! accumulators, and the 8-neighbour summit test is branch-free: each
//! row's 3-column maxima are made once and serve the rows above and below,
//! a pixel is a summit when it is above `max(west, east, max3 above, max3
//! below)` (the 8 strict comparisons in 4), the result goes into a byte
//! mask and the set bytes are read back 8 at a time. The blocks are fixed by the map, not by the threads, and their
//! sums are added in block order: the result is the same bit for bit on any
//! number of threads.
//!
//! Sums (indices of [`DiffSums`]): `z^2`; squared forward differences along
//! x and along y; squared 3-point second differences along x and along y;
//! only differences inside the array, or every pixel with wrapped
//! neighbours when periodic (definitions in `moments.rs`).

use super::Summit;
use rayon::prelude::*;

/// Rows per parallel work item. Fixed (not derived from the thread count)
/// so that the order of the reduction never changes.
const BLOCK_ROWS: usize = 64;

/// Interleaved accumulators per sum within a row.
const LANES: usize = 8;

/// The five difference sums: `[z^2, x first, y first, x second, y second]`.
pub(crate) type DiffSums = [f64; 5];

/// What the fused pass measures: the difference sums and the summits in
/// row-major order.
pub(crate) struct ScanResult {
    /// Sums over the whole map, in block order.
    pub sums: DiffSums,
    /// Summits (pixels strictly higher than their 8 neighbours).
    pub summits: Vec<Summit>,
}

/// Per-thread scratch: three residual rows, their 3-column maxima
/// ([`max3_along_row`]) and the summit mask of a row.
struct Scratch {
    rows: [Vec<f64>; 3],
    max3: [Vec<f64>; 3],
    mask: Vec<u8>,
}

/// Scans a `rows x cols` map (`rows, cols >= 3`) of pixels `dx` x `dy`
/// whose residual row `i` `fill(i, out)` writes into `out` (`cols` values).
pub(crate) fn scan<F>(
    rows: usize,
    cols: usize,
    (dx, dy): (f64, f64),
    periodic: bool,
    fill: F,
) -> ScanResult
where
    F: Fn(usize, &mut [f64]) + Sync,
{
    let kappa_scale = Kappa {
        x: 1.0 / (2.0 * dx * dx),
        y: 1.0 / (2.0 * dy * dy),
    };
    let blocks = rows.div_ceil(BLOCK_ROWS);
    let parts: Vec<ScanResult> = (0..blocks)
        .into_par_iter()
        .map_init(
            || Scratch {
                rows: [vec![0.0; cols], vec![0.0; cols], vec![0.0; cols]],
                max3: [vec![0.0; cols], vec![0.0; cols], vec![0.0; cols]],
                mask: vec![0; cols],
            },
            |scratch, b| {
                let end = ((b + 1) * BLOCK_ROWS).min(rows);
                scan_block(
                    b * BLOCK_ROWS..end,
                    rows,
                    periodic,
                    kappa_scale,
                    &fill,
                    scratch,
                )
            },
        )
        .collect();
    let mut sums = [0.0; 5];
    let count = parts.iter().map(|p| p.summits.len()).sum();
    let mut summits = Vec::with_capacity(count);
    for p in parts {
        for (a, b) in sums.iter_mut().zip(p.sums) {
            *a += b;
        }
        summits.extend_from_slice(&p.summits);
    }
    ScanResult { sums, summits }
}

/// The rows `block` of the map: sums and summits.
fn scan_block<F>(
    block: std::ops::Range<usize>,
    rows: usize,
    periodic: bool,
    kappa_scale: Kappa,
    fill: &F,
    scratch: &mut Scratch,
) -> ScanResult
where
    F: Fn(usize, &mut [f64]),
{
    let above = |i: usize| match i {
        0 => periodic.then_some(rows - 1),
        _ => Some(i - 1),
    };
    let below = |i: usize| match i + 1 {
        n if n < rows => Some(n),
        _ => periodic.then_some(0),
    };
    let mut lanes = [[0.0; LANES]; 5];
    let mut edges = [0.0; 5];
    let mut summits = Vec::new();
    let [up, mid, _] = &mut scratch.rows;
    let mut has_up = above(block.start).map(|p| fill(p, up)).is_some();
    fill(block.start, mid);
    for (r, m) in scratch.rows.iter().zip(&mut scratch.max3).take(2) {
        max3_along_row(r, m);
    }
    for i in block {
        let has_down = below(i).map(|n| fill(n, &mut scratch.rows[2])).is_some();
        max3_along_row(&scratch.rows[2], &mut scratch.max3[2]);
        let [up, mid, down] = &scratch.rows;
        if has_up && has_down {
            let max3 = [&scratch.max3[0][..], &scratch.max3[2][..]];
            full_row(
                [up, mid, down],
                max3,
                &mut lanes,
                &mut edges,
                &mut scratch.mask,
            );
            mark_wrapped_edges(up, mid, down, periodic, &mut scratch.mask);
            collect_summits(i, up, mid, down, &scratch.mask, kappa_scale, &mut summits);
        } else {
            edge_row(
                has_up.then_some(up),
                mid,
                has_down.then_some(down),
                &mut edges,
            );
        }
        if periodic {
            x_wrap(mid, &mut edges);
        }
        scratch.rows.rotate_left(1);
        scratch.max3.rotate_left(1);
        has_up = true;
    }
    let mut sums = edges;
    for (s, l) in sums.iter_mut().zip(lanes) {
        *s += l.iter().sum::<f64>();
    }
    ScanResult { sums, summits }
}

/// `(a - 2 b + c)^2`: a squared 3-point second difference.
#[inline(always)]
fn d2(a: f64, b: f64, c: f64) -> f64 {
    let d = a - 2.0 * b + c;
    d * d
}

/// `max(a, b)` without the NaN rule of `f64::max` (one `maxpd`; the
/// heights are finite).
#[inline(always)]
fn max(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// `out[j] = max(r[j-1], r[j], r[j+1])` for `j` in `1..n-1`: computed once
/// per row, it serves the summit test of the rows above and below.
fn max3_along_row(r: &[f64], out: &mut [f64]) {
    for (o, w) in out[1..].iter_mut().zip(r.windows(3)) {
        *o = max(max(w[0], w[1]), w[2]);
    }
}

/// A row (`rows = [above, row, below]`) with the 3-column maxima of the
/// rows above and below (`max3`): every sum, and the summit mask of the
/// columns `1..cols-1` (`mask[j]` = 1 at a summit, 0 elsewhere). A pixel
/// is a summit when it is above the larger of its west and east neighbours
/// and the 3-column maxima above and below: the 8 strict comparisons in 4.
fn full_row(
    [up, mid, down]: [&[f64]; 3],
    [up_max3, down_max3]: [&[f64]; 2],
    lanes: &mut [[f64; LANES]; 5],
    edges: &mut [f64; 5],
    mask: &mut [u8],
) {
    let n = mid.len();
    // Columns 0 and n-1: z^2 and the y differences (and the x forward
    // difference at 0); the x differences that wrap are in `x_wrap`.
    for j in [0, n - 1] {
        let c = mid[j];
        edges[0] += c * c;
        edges[2] += (down[j] - c) * (down[j] - c);
        edges[4] += d2(down[j], c, up[j]);
    }
    edges[1] += (mid[1] - mid[0]) * (mid[1] - mid[0]);
    // Columns 1..n-1 in chunks of LANES: windows of LANES + 2 columns.
    let mut j0 = 1;
    while j0 + LANES < n {
        let u: &[f64; LANES + 2] = up[j0 - 1..j0 + LANES + 1].try_into().unwrap();
        let m: &[f64; LANES + 2] = mid[j0 - 1..j0 + LANES + 1].try_into().unwrap();
        let d: &[f64; LANES + 2] = down[j0 - 1..j0 + LANES + 1].try_into().unwrap();
        let out: &mut [u8; LANES] = (&mut mask[j0..j0 + LANES]).try_into().unwrap();
        let um: &[f64; LANES] = up_max3[j0..j0 + LANES].try_into().unwrap();
        let dm: &[f64; LANES] = down_max3[j0..j0 + LANES].try_into().unwrap();
        for l in 0..LANES {
            let (c, w, e) = (m[l + 1], m[l], m[l + 2]);
            lanes[0][l] += c * c;
            lanes[1][l] += (e - c) * (e - c);
            lanes[2][l] += (d[l + 1] - c) * (d[l + 1] - c);
            lanes[3][l] += d2(e, c, w);
            lanes[4][l] += d2(d[l + 1], c, u[l + 1]);
            out[l] = (c > max(max(w, e), max(um[l], dm[l]))) as u8;
        }
        j0 += LANES;
    }
    for j in j0..n - 1 {
        let (c, w, e) = (mid[j], mid[j - 1], mid[j + 1]);
        edges[0] += c * c;
        edges[1] += (e - c) * (e - c);
        edges[2] += (down[j] - c) * (down[j] - c);
        edges[3] += d2(e, c, w);
        edges[4] += d2(down[j], c, up[j]);
        let (u, d) = (up, down);
        mask[j] = is_summit(c, w, e, u[j - 1], u[j], u[j + 1], d[j - 1], d[j], d[j + 1]) as u8;
    }
}

/// The centre `c` is strictly above its 8 neighbours (`w`est, `e`ast, the
/// three above `u*` and the three below `d*`): the eight comparisons and-ed
/// without a branch.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn is_summit(c: f64, w: f64, e: f64, uw: f64, u: f64, ue: f64, dw: f64, d: f64, de: f64) -> bool {
    (c > w) & (c > e) & (c > uw) & (c > u) & (c > ue) & (c > dw) & (c > d) & (c > de)
}

/// The summit test at columns 0 and `n-1`: with wrapped neighbours when
/// periodic, never otherwise (they are not candidates).
fn mark_wrapped_edges(up: &[f64], mid: &[f64], down: &[f64], periodic: bool, mask: &mut [u8]) {
    let n = mid.len();
    for (j, l, r) in [(0, n - 1, 1), (n - 1, n - 2, 0)] {
        mask[j] = (periodic
            && is_summit(
                mid[j], mid[l], mid[r], up[l], up[j], up[r], down[l], down[j], down[r],
            )) as u8;
    }
}

/// The curvature factors `1/(2 dx^2)` and `1/(2 dy^2)`.
#[derive(Clone, Copy)]
struct Kappa {
    x: f64,
    y: f64,
}

/// Appends the summits `mask` marks on row `i`, in column order, with the
/// curvature `-(d2x/dx^2 + d2y/dy^2)/2` from the 3-point second differences
/// (`-(5-point Laplacian) / (2 dx^2)` on square pixels, computed so).
fn collect_summits(
    i: usize,
    up: &[f64],
    mid: &[f64],
    down: &[f64],
    mask: &[u8],
    kappa_scale: Kappa,
    out: &mut Vec<Summit>,
) {
    let n = mid.len();
    let mut push = |j: usize| {
        let (l, r) = (if j == 0 { n - 1 } else { j - 1 }, (j + 1) % n);
        let c = mid[j];
        let curvature_per_m = if kappa_scale.x == kappa_scale.y {
            -(up[j] + down[j] + mid[l] + mid[r] - 4.0 * c) * kappa_scale.x
        } else {
            -((mid[l] + mid[r] - 2.0 * c) * kappa_scale.x
                + (up[j] + down[j] - 2.0 * c) * kappa_scale.y)
        };
        out.push(Summit {
            row: i,
            col: j,
            height_m: c,
            curvature_per_m,
        });
    };
    let mut chunks = mask.chunks_exact(8);
    for (k, chunk) in chunks.by_ref().enumerate() {
        let mut bits = u64::from_le_bytes(chunk.try_into().unwrap());
        while bits != 0 {
            push(8 * k + bits.trailing_zeros() as usize / 8);
            bits &= bits - 1;
        }
    }
    let base = n - chunks.remainder().len();
    for (t, &m) in chunks.remainder().iter().enumerate() {
        if m != 0 {
            push(base + t);
        }
    }
}

/// A row missing the row above or below (first or last row of a map that
/// is not periodic): the sums it has; it holds no summit candidate.
fn edge_row(up: Option<&[f64]>, mid: &[f64], down: Option<&[f64]>, edges: &mut [f64; 5]) {
    edges[0] += mid.iter().map(|v| v * v).sum::<f64>();
    edges[1] += mid
        .windows(2)
        .map(|w| (w[1] - w[0]) * (w[1] - w[0]))
        .sum::<f64>();
    edges[3] += mid.windows(3).map(|w| d2(w[2], w[1], w[0])).sum::<f64>();
    if let Some(down) = down {
        edges[2] += down
            .iter()
            .zip(mid)
            .map(|(a, b)| (a - b) * (a - b))
            .sum::<f64>();
        if let Some(up) = up {
            edges[4] += down
                .iter()
                .zip(mid)
                .zip(up)
                .map(|((a, b), c)| d2(*a, *b, *c))
                .sum::<f64>();
        }
    }
}

/// The x differences of a periodic row that wrap around its ends.
fn x_wrap(r: &[f64], edges: &mut [f64; 5]) {
    let n = r.len();
    let wrap = r[0] - r[n - 1];
    edges[1] += wrap * wrap;
    edges[3] += d2(r[1], r[0], r[n - 1]) + d2(r[0], r[n - 1], r[n - 2]);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The straightforward definitions (the code this pass replaced): each
    /// sum over its own loop, the summit test with `&&`.
    fn reference(z: &[f64], rows: usize, cols: usize, periodic: bool) -> (DiffSums, Vec<Summit>) {
        let at = |i: usize, j: usize| z[i * cols + j];
        let mut s = [0.0; 5];
        for i in 0..rows {
            for j in 0..cols {
                s[0] += at(i, j) * at(i, j);
                let jn = (j + 1) % cols;
                let jp = (j + cols - 1) % cols;
                if j + 1 < cols || periodic {
                    s[1] += (at(i, jn) - at(i, j)).powi(2);
                }
                if (j >= 1 && j + 1 < cols) || periodic {
                    s[3] += (at(i, jn) - 2.0 * at(i, j) + at(i, jp)).powi(2);
                }
                let (i_n, i_p) = ((i + 1) % rows, (i + rows - 1) % rows);
                if i + 1 < rows || periodic {
                    s[2] += (at(i_n, j) - at(i, j)).powi(2);
                }
                if (i >= 1 && i + 1 < rows) || periodic {
                    s[4] += (at(i_n, j) - 2.0 * at(i, j) + at(i_p, j)).powi(2);
                }
            }
        }
        let mut summits = Vec::new();
        for i in 0..rows {
            for j in 0..cols {
                let interior = i >= 1 && i + 1 < rows && j >= 1 && j + 1 < cols;
                if !(interior || periodic) {
                    continue;
                }
                let (i_n, i_p) = ((i + 1) % rows, (i + rows - 1) % rows);
                let (jn, jp) = ((j + 1) % cols, (j + cols - 1) % cols);
                let c = at(i, j);
                let mut top = true;
                for (a, b) in [
                    (i_p, jp),
                    (i_p, j),
                    (i_p, jn),
                    (i, jp),
                    (i, jn),
                    (i_n, jp),
                    (i_n, j),
                    (i_n, jn),
                ] {
                    top = top && c > at(a, b);
                }
                if top {
                    let lap = at(i_p, j) + at(i_n, j) + at(i, jp) + at(i, jn) - 4.0 * c;
                    summits.push(Summit {
                        row: i,
                        col: j,
                        height_m: c,
                        curvature_per_m: -lap * 0.5,
                    });
                }
            }
        }
        (s, summits)
    }

    /// A rough map with plateaus (equal neighbours, which are not summits)
    /// from a small linear congruential generator.
    fn rough(rows: usize, cols: usize, seed: u64) -> Vec<f64> {
        let mut x = seed;
        (0..rows * cols)
            .map(|_| {
                x = x
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                ((x >> 33) % 7) as f64 * 0.25 + ((x >> 20) % 3) as f64 * 1e-3
            })
            .collect()
    }

    /// Every shape the lanes, blocks and edges treat apart: widths below,
    /// at and above a chunk, rows across block boundaries, periodic or not.
    /// Summits equal exactly; sums to 1e-13 relative (order of addition).
    #[test]
    fn matches_the_straightforward_definitions() {
        for (rows, cols) in [(3, 3), (3, 5), (4, 6), (5, 7), (7, 9), (65, 13), (130, 37)] {
            for periodic in [false, true] {
                let z = rough(rows, cols, (rows * 1000 + cols) as u64);
                let got = scan(rows, cols, (1.0, 1.0), periodic, |i, out| {
                    out.copy_from_slice(&z[i * cols..(i + 1) * cols])
                });
                let (sums, summits) = reference(&z, rows, cols, periodic);
                let what = format!("{rows} x {cols}, periodic {periodic}");
                assert_eq!(got.summits, summits, "{what}");
                assert!(!summits.is_empty() || rows * cols < 50, "{what}");
                for (a, b) in got.sums.iter().zip(sums) {
                    assert!((a - b).abs() <= 1e-13 * b.abs(), "{what}: {a} {b}");
                }
            }
        }
    }
}
