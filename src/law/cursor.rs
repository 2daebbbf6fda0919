//! A caller-held position in a tabulated law, so that nearby evaluations
//! (the nodes of one quadrature panel) find their table panel by a short
//! walk instead of a binary search.

/// Last table panel used on each branch (approach, retract). Laws without
/// tables ignore it; [`InterpolatedLaw`](super::interpolated::InterpolatedLaw)
/// starts its panel search there. The panel found, and so every value, does
/// not depend on the cursor: only the cost does.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LawCursor {
    /// Panel index per branch (`0` approach, `1` retract).
    pub panels: [usize; 2],
}
