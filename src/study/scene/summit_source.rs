//! `surface.summits`: which model of a measured map a study uses.

/// Which model of the map a study uses (`surface.summits`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SummitSource {
    /// The measured summits, summed exactly with their own heights and radii.
    Measured,
    /// Gaussian GW with McCool's parameters from the measured moments.
    Moments,
}

impl SummitSource {
    /// `"measured"` or `"moments"`.
    pub fn name(self) -> &'static str {
        match self {
            SummitSource::Measured => "measured",
            SummitSource::Moments => "moments",
        }
    }

    /// The other one.
    pub fn other(self) -> SummitSource {
        match self {
            SummitSource::Measured => SummitSource::Moments,
            SummitSource::Moments => SummitSource::Measured,
        }
    }
}

impl crate::named::Named for SummitSource {
    const ALL: &'static [Self] = &[SummitSource::Measured, SummitSource::Moments];
    const WHAT: &'static str = "summit source";
    fn name(self) -> &'static str {
        SummitSource::name(self)
    }
}
crate::serde_by_name!(SummitSource);
