//! The shape of a retraction curve that lets sums over many summits skip
//! separations: where its most tensile point lies.
//!
//! A summit's retraction load `f(delta)` (after its maximum interference)
//! is *unimodal* when it is non-increasing in `delta` below one
//! interference `delta_p` and non-decreasing above it: pulled back from
//! its closest approach, the summit's load falls to its most tensile value
//! `f(delta_p)`, then rises (continuously, or jumping towards zero at a
//! jump-out) to zero. Every law of the JKR/DMT family, JKR on a plastically
//! flattened shape, and the monotone non-adhesive laws (Hertz, plastic
//! unloading: `delta_p = -inf`) have this shape. Then the least load over
//! any interval of interferences `[lo, hi]` follows from the two ends and
//! `delta_p` alone ([`RetractionMinimum::window_minimum`]): a rigorous lower
//! bound of a population's load between two separations, from the loads
//! at those separations.

/// The most tensile point of a unimodal retraction curve (see the module
/// notes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RetractionMinimum {
    /// Interference `delta_p` (m) of the minimum; `-inf` for a load that is
    /// non-decreasing in the interference throughout.
    pub interference: f64,
    /// The minimum load `f(delta_p)` (N); 0 when monotone.
    pub load: f64,
}

impl RetractionMinimum {
    /// A load non-decreasing in the interference everywhere (and zero out
    /// of contact): Hertz, plastic unloading, a summit never touched.
    pub const MONOTONE: RetractionMinimum = RetractionMinimum {
        interference: f64::NEG_INFINITY,
        load: 0.0,
    };

    /// The least load (N) over interferences `[lo, hi]` (m, `lo <= hi`)
    /// given the loads at the two ends: `f(delta_p)` if `delta_p` lies in
    /// the interval, else the end nearer to `delta_p` (unimodality).
    #[inline]
    pub fn window_minimum(&self, lo: f64, load_lo: f64, hi: f64, load_hi: f64) -> f64 {
        if self.interference < lo {
            load_lo
        } else if self.interference > hi {
            load_hi
        } else {
            self.load.min(load_lo).min(load_hi)
        }
    }

    /// The same point for a summit whose interferences are divided by
    /// `inv_len` and loads multiplied by `load_factor` (a radius rescaling,
    /// [`crate::law::RadiusScaling`]).
    pub fn scaled(&self, inv_len: f64, load_factor: f64) -> RetractionMinimum {
        RetractionMinimum {
            interference: self.interference / inv_len,
            load: self.load * load_factor,
        }
    }
}

impl From<super::Instability> for RetractionMinimum {
    /// The pull-off under load control of a unimodal retraction: its most
    /// tensile point (interference and load).
    fn from(p: super::Instability) -> RetractionMinimum {
        RetractionMinimum {
            interference: p.interference,
            load: p.load,
        }
    }
}
