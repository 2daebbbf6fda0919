//! Contact spots of an explicit population: each summit in contact is a
//! spot of the law's contact radius, placed uniformly at random in the
//! square apparent area the population stands for, so that Greenwood's
//! cluster term and the exact equal-potential solution are computed from
//! the sample itself (not from a mean field).

use super::spot::SpotResistance;
use super::spots::{Merged, Spots};
use crate::error::{positive, Result};
use crate::law::Branch;
use crate::montecarlo::{Population, SummitLaw};
use crate::numeric::mix::splitmix64;

/// Most spots for which [`SampleResistance::new`] solves the exact dense
/// system (`n^3/3` flops: 2000 spots take ~0.2 s).
pub const EXACT_MAX_SPOTS: usize = 3000;

/// Resistances of one population's spots at one separation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SampleResistance {
    /// Number of spots (summits in contact).
    pub spots: usize,
    /// Independent parallel spots `1/sum G_i` (Ohm); `inf` without spots.
    pub parallel: f64,
    /// Greenwood's (1966) formula for the explicit positions (Ohm).
    pub greenwood: f64,
    /// The exact equal-potential solution (Ohm), for at most
    /// [`EXACT_MAX_SPOTS`] spots.
    pub exact: Option<f64>,
    /// Summits whose spots overlapped others where they fell and were
    /// merged with them (0 from [`SampleResistance::new`]; the caller that
    /// merged sets it).
    pub merged: usize,
}

/// The spots of `population` summed with `law` on approach at separation
/// `d` (m), positions uniform in a square of side `side` (m) drawn from
/// `seed` (splitmix64 stream, reproducible).
///
/// Spots that overlap where they fell are merged into one spot of their
/// joint area ([`Spots::merging`]; the groups are returned). `None` when
/// no summit is in contact.
///
/// # Errors
/// [`crate::Error::OutOfRange`] naming `side`; as the law's radius scaling.
pub fn population_spots(
    population: &Population,
    law: &SummitLaw,
    separation: f64,
    side: f64,
    seed: u64,
) -> Result<Option<Merged>> {
    positive("side", side)?;
    let (mut x, mut y, mut a) = (Vec::new(), Vec::new(), Vec::new());
    let mut state = seed;
    let mut uniform = || {
        state = splitmix64(state);
        // 53 random bits to [0, 1).
        (state >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    };
    for (i, &z) in population.heights().iter().enumerate() {
        let f = law.factors_for(population.radius(i))?;
        let s = law.law().state((z - separation) * f[0], Branch::Approach);
        // Every summit draws its position, in contact or not, so positions
        // do not depend on the separation.
        let (px, py) = (uniform() * side, uniform() * side);
        let r = s.radius * f[2];
        if r > 0.0 {
            x.push(px);
            y.push(py);
            a.push(r);
        }
    }
    if a.is_empty() {
        return Ok(None);
    }
    Spots::merging(x, y, a).map(Some)
}

impl SampleResistance {
    /// Parallel, Greenwood and (up to [`EXACT_MAX_SPOTS`]) exact
    /// resistances of `spots`.
    ///
    /// # Errors
    /// As [`Spots::exact`].
    pub fn new(spots: &Spots, spot: &SpotResistance) -> Result<Self> {
        Ok(SampleResistance {
            spots: spots.len(),
            parallel: spots.parallel(spot),
            greenwood: spots.greenwood(spot),
            exact: if spots.len() <= EXACT_MAX_SPOTS {
                Some(spots.exact(spot)?)
            } else {
                None
            },
            merged: 0,
        })
    }
}
