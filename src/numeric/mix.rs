//! SplitMix64 (Steele, Lea & Flood 2014): the one integer mixer, and
//! [`derive_seed`], the one place where a user's seed becomes the seed of
//! a stream (a Monte Carlo block's heights or radii, a pull-off
//! population, a sweep point, the sampled spots' positions).

/// One SplitMix64 step: a bijective avalanche of `x` (Vigna's constants).
pub fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// Seed offset of the radius streams (distinct from every height stream).
const RADIUS_STREAM: u64 = 0x5241_4449_5553_0001;

/// Seed offset of the sampled spots' positions ("SPOT").
const SPOT_STREAM: u64 = 0x5350_4f54;

/// What a derived seed feeds: each stream of random numbers the program
/// draws from one user seed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stream {
    /// The heights of Monte Carlo block `b` (a population's summits are
    /// drawn in blocks, each from its own generator, so the draw does not
    /// depend on the thread count).
    HeightBlock(u64),
    /// The radii of Monte Carlo block `b` (lognormal radii).
    RadiusBlock(u64),
    /// Pull-off population `k` of a run: the population that the scene
    /// with `[montecarlo] seed = seed + k` draws.
    Population(u64),
    /// Point `index` of a sweep (its own population, independent of the
    /// shards and threads that run it).
    SweepPoint(u64),
    /// The positions of the spots sampled for the cluster resistance.
    SpotPositions,
    /// The white noise of row `i` of a synthetic Gaussian map.
    SyntheticRow(u64),
}

/// The seed of `stream` from the user's `seed`; distinct streams give
/// unrelated sequences (SplitMix64 avalanches its input):
/// - heights of block `b`: `s(s(seed) ^ b)`, radii: the same of
///   `seed ^ RADIUS_STREAM`, with `s` = [`splitmix64`];
/// - population `k`: `seed + k` (wrapping), so population `k` is what the
///   scene with that seed draws;
/// - sweep point `i`: `s(seed + i)`;
/// - spot positions: `s(seed ^ "SPOT")`;
/// - synthetic map row `i`: `seed ^ (i + 1) gamma` (wrapping; `gamma` the
///   golden-ratio increment), which xoshiro's own seeding mixes.
pub fn derive_seed(seed: u64, stream: Stream) -> u64 {
    match stream {
        Stream::HeightBlock(b) => splitmix64(splitmix64(seed) ^ b),
        Stream::RadiusBlock(b) => splitmix64(splitmix64(seed ^ RADIUS_STREAM) ^ b),
        Stream::Population(k) => seed.wrapping_add(k),
        Stream::SweepPoint(i) => splitmix64(seed.wrapping_add(i)),
        Stream::SpotPositions => splitmix64(seed ^ SPOT_STREAM),
        Stream::SyntheticRow(i) => seed ^ (i + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_the_reference_sequence() {
        // SplitMix64 seeded with 0 (Vigna's reference C code): the state
        // advances by the golden gamma, so output k is splitmix64(k gamma).
        assert_eq!(splitmix64(0), 0xe220_a839_7b1d_cdaf);
        assert_eq!(splitmix64(0x9e37_79b9_7f4a_7c15), 0x6e78_9e6a_a1b9_65f4);
    }

    #[test]
    fn streams_differ_and_populations_wrap() {
        let seeds: Vec<u64> = [
            Stream::HeightBlock(0),
            Stream::RadiusBlock(0),
            Stream::Population(1),
            Stream::SweepPoint(0),
            Stream::SpotPositions,
        ]
        .iter()
        .map(|&s| derive_seed(42, s))
        .collect();
        for (i, a) in seeds.iter().enumerate() {
            assert!(seeds[i + 1..].iter().all(|b| b != a), "{seeds:?}");
        }
        assert_eq!(derive_seed(42, Stream::Population(0)), 42);
        assert_eq!(derive_seed(u64::MAX, Stream::Population(2)), 1);
        assert_eq!(derive_seed(7, Stream::SweepPoint(3)), splitmix64(10));
    }
}
