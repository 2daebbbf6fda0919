//! Many spots in parallel and Greenwood's (1966) mean-field interaction.
//!
//! The parallel conductance is `sum G_i` over the spots; Greenwood's
//! interaction, mean field for spot centres uniform in a square of side
//! `L = sqrt(A_n)`: `R_int = (rho_eff c_sq/(pi L)) (1 - sum G_i^2 /
//! (sum G_i)^2)`, `rho_eff = (rho1 + rho2)/2`, `c_sq = E[1/|X - Y|]` in the
//! unit square. The weights are the spots' shares of the current in the
//! parallel solution, `G_i / sum G`; for Maxwell spots they are
//! `a_i / sum a`, Greenwood's form `1 - sum a^2/(sum a)^2` (physics.md).
//! The sums over a rough surface come from its one integrator (the spot
//! conductance is a per-asperity observable, [`super::observable`]).

use super::spot::SpotResistance;
use std::f64::consts::PI;

/// `c_sq = E[1/|X - Y|]` for `X, Y` uniform in the unit square:
/// `4 ln(1 + sqrt 2) - (4/3)(sqrt 2 - 1)` (physics.md; mpmath check in
/// `tests/data/electrical.py`).
pub const C_SQ: f64 = 2.973_209_598_247_378_5;

/// Whether Greenwood's interaction term is added to the parallel spots.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interaction {
    /// Independent parallel spots (Holm).
    None,
    /// Parallel spots plus Greenwood's (1966) mean-field interaction term in
    /// a square apparent area.
    Greenwood,
}

impl Interaction {
    /// Both choices.
    pub const ALL: [Interaction; 2] = [Interaction::None, Interaction::Greenwood];

    /// `"none"` or `"greenwood"` (the scene's `interaction`).
    pub fn name(self) -> &'static str {
        match self {
            Interaction::None => "none",
            Interaction::Greenwood => "greenwood",
        }
    }
}

crate::named_enum!(Interaction, "interaction");

/// Sums over the spots of one state.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SpotSums {
    /// Number of spots (expected, for a statistical surface).
    pub contacts: f64,
    /// `sum G_i` (S): the parallel conductance.
    pub conductance: f64,
    /// `sum G_i^2` (S^2), for the interaction weights.
    pub conductance_sq: f64,
}

/// Greenwood's mean-field interaction resistance (Ohm) of spots whose
/// centres are uniform in a square of side `side` (m):
/// `(rho_eff c_sq/(pi L)) (1 - sum G^2/(sum G)^2)`; 0 without conductance.
pub fn greenwood_mean_field(mutual_resistivity: f64, side: f64, sums: &SpotSums) -> f64 {
    if !(sums.conductance > 0.0) {
        return 0.0;
    }
    let w2 = sums.conductance_sq / (sums.conductance * sums.conductance);
    mutual_resistivity * C_SQ / (PI * side) * (1.0 - w2).max(0.0)
}

/// Resistance of a contact and its parts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactResistance {
    /// Total resistance (Ohm): parallel plus interaction; `inf` without
    /// contact.
    pub resistance: f64,
    /// Independent parallel spots `1/sum G_i` (Ohm).
    pub parallel: f64,
    /// Greenwood's interaction term (Ohm), when asked for and computed.
    pub interaction: Option<f64>,
    /// Whether the interaction was asked for but left out because fewer than
    /// 2 contacts are expected (the caller should warn).
    pub interaction_skipped: bool,
    /// Number of contact spots (expected).
    pub contacts: f64,
}

impl ContactResistance {
    /// Combines parallel sums with the interaction choice; the Greenwood
    /// term needs at least 2 (expected) contacts.
    pub fn from_sums(
        sums: &SpotSums,
        spot: &SpotResistance,
        interaction: Interaction,
        side: f64,
    ) -> Self {
        let parallel = 1.0 / sums.conductance;
        let (term, skipped) = match interaction {
            Interaction::None => (None, false),
            Interaction::Greenwood if sums.contacts >= 2.0 => (
                Some(greenwood_mean_field(spot.mutual_resistivity(), side, sums)),
                false,
            ),
            Interaction::Greenwood => (None, true),
        };
        ContactResistance {
            resistance: parallel + term.unwrap_or(0.0),
            parallel,
            interaction: term,
            interaction_skipped: skipped,
            contacts: sums.contacts,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn c_sq_is_the_closed_form() {
        let s2 = 2f64.sqrt();
        let c = 4.0 * (1.0 + s2).ln() - 4.0 / 3.0 * (s2 - 1.0);
        assert!((c - C_SQ).abs() < 1e-13);
    }
}
