//! Lower bounds of a population's retraction load between separations,
//! from its loads at them: what lets a pull-off search skip separations
//! that cannot hold the most tensile load.
//!
//! On retraction every summit's load is a unimodal function of its
//! interference when the law says so
//! ([`LawKernels::retraction_minimum`](crate::law::LawKernels::retraction_minimum)):
//! its least value between two separations is its load at one of them, or
//! its own most tensile load when that lies between
//! ([`RetractionMinimum::window_minimum`](crate::law::RetractionMinimum::window_minimum)).
//! Summed over the summits, these are rigorous lower bounds of the
//! population's load anywhere between the two separations.

use super::{MonteCarlo, CHUNK};

/// Loads of a population at a few separations on retraction, and lower
/// bounds of its load between consecutive ones.
///
/// Between separations `k` and `k + 1`, the summits whose load is concave
/// there ([`LawKernels::concave_tail`](crate::law::LawKernels::concave_tail):
/// the far field of a long-range law) are bounded by the chord of their
/// summed loads at the two ends, the others by their least value
/// ([`RetractionMinimum::window_minimum`](crate::law::RetractionMinimum::window_minimum)):
/// [`RetractionBounds::lower_at`].
#[derive(Debug, Clone, PartialEq)]
pub struct RetractionBounds {
    /// Load (N) at each separation (summed per summit, in another order
    /// than the sums of [`LoadingModel::states`](crate::loading::LoadingModel::states): equal
    /// to them within roundoff).
    pub loads: Vec<f64>,
    /// Lower bound (N) of the load anywhere between separations `k` and
    /// `k + 1`.
    pub lower: Vec<f64>,
    /// The part of `lower[k]` from the summits bounded by their least
    /// value (N).
    pub least_part: Vec<f64>,
    /// The summed loads (N) of the concave summits of window `k` at its
    /// two ends: `(at separation k, at separation k + 1)`.
    pub chord: Vec<(f64, f64)>,
    /// Largest sum of absolute per-summit terms (N) behind any of these:
    /// their roundoff is a tiny fraction of it.
    pub magnitude: f64,
}

impl RetractionBounds {
    /// Lower bound (N) of the load at the fraction `t` in `[0, 1]` of the
    /// way from separation `k` to `k + 1`: the least-value part plus the
    /// chord of the concave part.
    pub fn lower_at(&self, k: usize, t: f64) -> f64 {
        let (a, b) = self.chord[k];
        self.least_part[k] + (1.0 - t) * a + t * b
    }
}

impl MonteCarlo {
    /// [`RetractionBounds`] at `separations` (m, ascending, at least two)
    /// on retraction after the flat came to `closest` (m); `None` when the
    /// law does not say its retraction curves are unimodal.
    pub fn retraction_bounds(&self, separations: &[f64], closest: f64) -> Option<RetractionBounds> {
        let k = separations.len();
        if k < 2 {
            return None;
        }
        let law = self.law.law();
        let n = self.population.len();
        let firsts: Vec<usize> = separations
            .iter()
            .map(|&d| self.first_in_range(d))
            .collect();
        let start = firsts.iter().copied().min().unwrap_or(n);
        let z = self.population.heights();
        let reversible = law.reversible();
        let mut out = RetractionBounds {
            loads: vec![0.0; k],
            lower: vec![0.0; k - 1],
            least_part: vec![0.0; k - 1],
            chord: vec![(0.0, 0.0); k - 1],
            magnitude: 0.0,
        };
        // Interference (as the law sees it) below which a summit's load is
        // concave: `-inf` when the law does not say.
        let concave_below = law.concave_tail().unwrap_or(f64::NEG_INFINITY);
        let mut abs = vec![0.0; k];
        let (mut delta, mut load) = (vec![0.0; k * CHUNK], vec![0.0; k * CHUNK]);
        let (mut delta_max, mut radius) = ([0.0; CHUNK], [0.0; CHUNK]);
        // A plastic summit's shape after `closest`, once per chunk.
        let prepares = !reversible && law.prepares_history();
        let mut prepared = [[0.0; 4]; CHUNK];
        let mut a = start;
        while a < n {
            let m = CHUNK.min(n - a);
            let zc = &z[a..a + m];
            let f = self.chunk_factors(a, m);
            f.interferences(zc, closest, &mut delta_max[..m]);
            if prepares {
                law.prepare_after(&delta_max[..m], &mut prepared[..m]);
            }
            for (s, &d) in separations.iter().enumerate() {
                let (dl, ll) = (
                    &mut delta[s * CHUNK..s * CHUNK + m],
                    &mut load[s * CHUNK..s * CHUNK + m],
                );
                f.interferences(zc, d, dl);
                if prepares {
                    law.state_batch_prepared(
                        dl,
                        &delta_max[..m],
                        &prepared[..m],
                        ll,
                        &mut radius[..m],
                    );
                } else {
                    law.state_batch(
                        dl,
                        (!reversible).then_some(&delta_max[..m]),
                        ll,
                        &mut radius[..m],
                    );
                }
                f.scale(ll, &mut radius[..m]);
                // Summits out of the law's reach add nothing to the sums.
                let skip = firsts[s].saturating_sub(a).min(m);
                ll[..skip].fill(0.0);
                for &l in ll.iter() {
                    out.loads[s] += l;
                    abs[s] += l.abs();
                }
            }
            for i in 0..m {
                let rm = if prepares {
                    law.retraction_minimum_prepared(delta_max[i], &prepared[i])?
                } else {
                    law.retraction_minimum(delta_max[i])?
                };
                let [_, load_factor, _] = f.at(i);
                let rm = crate::law::RetractionMinimum {
                    load: rm.load * load_factor,
                    ..rm
                };
                for j in 0..k - 1 {
                    // Interferences fall as the separation grows.
                    let (hi, lo) = (delta[j * CHUNK + i], delta[(j + 1) * CHUNK + i]);
                    let (at_hi, at_lo) = (load[j * CHUNK + i], load[(j + 1) * CHUNK + i]);
                    if hi < concave_below {
                        // Concave over the window (interference linear in
                        // the separation): above its chord.
                        out.chord[j].0 += at_hi;
                        out.chord[j].1 += at_lo;
                    } else {
                        out.least_part[j] += rm.window_minimum(lo, at_lo, hi, at_hi);
                    }
                }
            }
            a += m;
        }
        out.finish(&abs);
        Some(out)
    }
}

impl RetractionBounds {
    /// Sets the lower bounds from the sums of the windows and the magnitude
    /// from `abs`, the sums of the summits' absolute loads.
    fn finish(&mut self, abs: &[f64]) {
        for (j, lower) in self.lower.iter_mut().enumerate() {
            let (a, b) = self.chord[j];
            *lower = self.least_part[j] + a.min(b);
        }
        self.magnitude = abs.iter().copied().fold(0.0, f64::max);
    }
}
