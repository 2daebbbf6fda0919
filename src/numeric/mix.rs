//! SplitMix64 (Steele, Lea & Flood 2014): the one integer mixer that turns
//! seeds and indices into independent stream seeds (Monte Carlo blocks,
//! sweep points).

/// One SplitMix64 step: a bijective avalanche of `x` (Vigna's constants).
pub fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
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
}
