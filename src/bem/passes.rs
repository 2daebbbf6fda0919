//! Fused element-wise passes: plain loops over chunks of the fields
//! (vectorised by the compiler), in parallel over chunks only when the
//! map is large enough for the threads to pay.

use rayon::prelude::*;
use std::ops::Range;

/// Elements per parallel chunk; maps below this run on one thread.
const CHUNK: usize = 1 << 15;

/// `sum over chunks of f(range)`, component-wise, in chunk order
/// (deterministic for any number of threads).
pub(crate) fn reduce<const K: usize, F>(n: usize, f: F) -> [f64; K]
where
    F: Fn(Range<usize>) -> [f64; K] + Sync,
{
    if n <= CHUNK {
        return f(0..n);
    }
    let parts: Vec<[f64; K]> = (0..n.div_ceil(CHUNK))
        .into_par_iter()
        .map(|c| f(c * CHUNK..((c + 1) * CHUNK).min(n)))
        .collect();
    add(parts)
}

/// The component-wise sum of the chunks' `parts`, in chunk order.
fn add<const K: usize>(parts: Vec<[f64; K]>) -> [f64; K] {
    let mut out = [0.0; K];
    for p in parts {
        for k in 0..K {
            out[k] += p[k];
        }
    }
    out
}

/// Applies `f(range, chunk_of_a)` to disjoint chunks of `a` (mutable),
/// returning the component-wise sum of the results.
pub(crate) fn update<const K: usize, F>(a: &mut [f64], f: F) -> [f64; K]
where
    F: Fn(Range<usize>, &mut [f64]) -> [f64; K] + Sync,
{
    let n = a.len();
    if n <= CHUNK {
        return f(0..n, a);
    }
    let parts: Vec<[f64; K]> = a
        .par_chunks_mut(CHUNK)
        .enumerate()
        .map(|(c, s)| f(c * CHUNK..c * CHUNK + s.len(), s))
        .collect();
    add(parts)
}
