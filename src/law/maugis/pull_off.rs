//! The load-controlled pull-off alone: the same point as
//! [`MaugisCurve::new`]`(lambda).pull_off_bar()` (bit for bit for
//! `lambda >= 1e-5`; below, where the load is flat to rounding at its
//! minimum, the same load to a few ulp), without the displacement-controlled
//! snap, the zero-load point, the jump-in or the inversion table, and with a
//! sparse scan.

use super::{scan_angle, Angle, MaugisCurve, MaugisPoint, Raw, SCAN_LEN};
use crate::error::Result;

/// Stride of the sparse scan: every 8th sample of the full scan, then the
/// full samples within one stride of the sparse minimum.
const STRIDE: usize = 8;

impl MaugisCurve {
    /// Load-controlled pull-off point (Maugis units: radius
    /// `(pi w R^2/K)^(1/3)`, load `pi w R`, interference
    /// `(pi^2 w^2 R/K^2)^(1/3)`) at Maugis parameter `lambda`: the minimum
    /// of `Pbar` over the contact branch (Maugis 1992, eqs. 1-3 of the
    /// module doc), identical to
    /// [`pull_off_bar`](MaugisCurve::pull_off_bar) of
    /// [`MaugisCurve::new`] (bit for bit for `lambda >= 1e-5`; below it the
    /// load is flat to rounding around the minimum and agrees to a few
    /// ulp). The full scan's sample with the least load is
    /// found from every 8th sample (`STRIDE`) and the samples within a
    /// stride of the least of those (the full scan when that minimum lies at
    /// the window's edge), then refined by the same root search of
    /// `dPbar/dt`. About 1/5 of the work of `new`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `lambda` outside `[1e-6, 1e6]`.
    pub fn pull_off_only(lambda: f64) -> Result<MaugisPoint> {
        let curve = Self::bare(lambda)?;
        Ok(curve.point(curve.sparse_pull_off_angle()))
    }

    /// The pull-off angle as `new` finds it (`refine` on the load), from a
    /// sparse scan.
    fn sparse_pull_off_angle(&self) -> Angle {
        let load = |k: usize| self.raw(scan_angle(k)).load;
        // The first least sparse sample (as `min_by` picks the first).
        let mut best = (0, load(0));
        for k in (STRIDE..SCAN_LEN).step_by(STRIDE) {
            let p = load(k);
            if p < best.1 {
                best = (k, p);
            }
        }
        let lo = best.0.saturating_sub(STRIDE);
        let hi = (best.0 + STRIDE).min(SCAN_LEN - 1);
        let samples: Vec<Angle> = (lo..=hi).map(scan_angle).collect();
        let raws: Vec<Raw> = samples.iter().map(|&a| self.raw(a)).collect();
        let k = (0..raws.len())
            .min_by(|&i, &j| raws[i].load.total_cmp(&raws[j].load))
            .unwrap_or(0);
        // At the window's inner edge the full scan's minimum may lie
        // outside it: scan everything (as `new`).
        let at_edge = (k == 0 && lo > 0) || (k == raws.len() - 1 && hi < SCAN_LEN - 1);
        if at_edge {
            let samples = self.scan();
            let raws: Vec<Raw> = samples.iter().map(|&a| self.raw(a)).collect();
            return self.refine(&samples, &raws, |r| r.load, |c, a| c.d_load(a));
        }
        // Interior: the window holds the minimum and both neighbours, so
        // `refine` brackets exactly as on the full scan.
        self.refine(&samples, &raws, |r| r.load, |c, a| c.d_load(a))
    }
}
