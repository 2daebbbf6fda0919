//! The flooded capillary model on Persson's distribution of interfacial
//! separations (`asperity persson --relative-humidity`): the Laplace
//! pressure on the area where the gap is below the meniscus height `h_m`,
//! `Delta p P(u < h_m)` ([`crate::persson::Persson::gap_statistics`];
//! Persson 2008, J. Phys.: Condens. Matter 20, 315007), the regime from
//! `h_m` over the distribution's RMS gap, and beside it the per-summit
//! menisci on GW's summits of the same spectrum at the same mean pressure
//! ([`crate::capillary::per_summit_pressure`]), with their difference
//! where both apply (the transition, `0.1 <= h_m/u_rms <= 1`).

use super::wet_map::{regime_warnings, state_cells, table_head, Liquid, MeniscusOutput};
use super::{param, CommandResult};
use crate::capillary::{per_summit_pressure, Regime};
use crate::gw::GwOnMoments;
use crate::persson::{Persson, GAP_RTOL};
use serde::Serialize;

/// One mean pressure's capillary attraction from Persson's gap
/// distribution.
#[derive(Serialize, Debug, Clone, Copy)]
pub struct PerssonWetState {
    /// Mean pressure without the menisci (Pa).
    #[serde(rename = "pressure_Pa")]
    pub pressure: f64,
    /// Real contact `A1/A0` (gap 0).
    pub contact_fraction: f64,
    /// The wetted fraction `P(u < h_m)`, contact included.
    pub wetted_fraction: f64,
    /// Flooded attraction per nominal area `Delta p P(u < h_m)` (Pa, > 0).
    #[serde(rename = "flooded_pressure_Pa")]
    pub flooded_pressure: f64,
    /// The gap distribution's mean `int u P(u) du` (m).
    pub mean_gap_m: f64,
    /// Its RMS gap `u_rms` (m).
    pub rms_gap_m: f64,
    /// `h_m / u_rms`.
    pub ratio: f64,
    /// The regime of the ratio.
    pub regime: Regime,
    /// Per-summit menisci on GW's summits of the same spectrum at the same
    /// mean pressure (Pa), where GW has a state.
    #[serde(rename = "per_summit_pressure_Pa")]
    pub per_summit_pressure: Option<f64>,
    /// `per_summit/flooded - 1` in the transition (null outside it).
    pub model_error: Option<f64>,
}

/// What `--relative-humidity` adds to `asperity persson`.
#[derive(Serialize, Debug, Clone)]
pub struct PerssonWetOutput {
    /// The meniscus (its keys inline).
    #[serde(flatten)]
    pub meniscus: MeniscusOutput,
    /// One per mean pressure, in order.
    pub states: Vec<PerssonWetState>,
    /// The numerical error, in words.
    pub numerical_error: String,
    /// The model error, in words.
    pub model_error: String,
}

/// What the Persson route's flooded attraction was measured to be against
/// the exact gap fields (docs/physics.md, "Capillary (wet) adhesion").
pub const MEASURED_FLOODED: &str = "Persson's wetted fraction is a model: on \
    examples/data/selfaffine-256.npy (E* = 1 GPa, gamma = 1, RH 0.99, h_m = 107 nm) at 1 and \
    10 MPa the attraction from it on the map's radial spectrum was 28.9 % and 10.0 % above \
    the exact boundary-element gap fields' (`asperity bem MAP --relative-humidity` prints \
    this difference, P/fl, for any map). One map, not a bound: Persson's distribution has \
    the right mean-field scales but not the exact gap field's shape";

/// The capillary attraction at each of `pressures` (Pa) from `model`'s gap
/// distribution, with per-summit menisci on `gw` beside it; `None` when
/// no meniscus condenses.
///
/// # Errors
/// Naming the liquid's input; `{pressures}` where the distribution cannot
/// be integrated.
pub fn persson_wet(
    liquid: &Liquid,
    model: &Persson,
    gw: &GwOnMoments,
    pressures: &[f64],
) -> CommandResult<Option<PerssonWetOutput>> {
    let Some(m) = liquid.meniscus()? else {
        return Ok(None);
    };
    let hm = m.height();
    let mut states = Vec::with_capacity(pressures.len());
    let mut worst: f64 = 0.0;
    for &p in pressures {
        crate::cancel::check()?;
        let s = model
            .gap_statistics(p, hm)
            .map_err(|e| e.renamed(&param("pressures")))?;
        worst = worst.max(s.error);
        let flooded = m.laplace_pressure() * s.fraction_below;
        let ratio = hm / s.rms_gap;
        let regime = Regime::of_ratio(ratio);
        let per_summit = gw
            .state(p)
            .ok()
            .map(|g| {
                per_summit_pressure(
                    &m,
                    gw.params.density_per_m2,
                    gw.params.radius_m,
                    gw.sigma,
                    g.separation,
                )
            })
            .transpose()?;
        let model_error = per_summit
            .filter(|_| regime == Regime::Transition && flooded > 0.0)
            .map(|ps| ps / flooded - 1.0);
        states.push(PerssonWetState {
            pressure: p,
            contact_fraction: s.contact_fraction,
            wetted_fraction: s.fraction_below,
            flooded_pressure: flooded,
            mean_gap_m: s.mean_gap,
            rms_gap_m: s.rms_gap,
            ratio,
            regime,
            per_summit_pressure: per_summit,
            model_error,
        });
    }
    Ok(Some(PerssonWetOutput {
        meniscus: MeniscusOutput::of(&m),
        states,
        numerical_error: format!(
            "wetted fraction by adaptive Gauss-Kronrod over the wavevector to {GAP_RTOL:e} \
             relative, each node's mean gap to 1e-12 (largest absolute error estimate here \
             {worst:.1e}, the distribution's normalisation included); checked against mpmath \
             to 1e-8 in tests/it/persson_gaps.rs"
        ),
        model_error: MEASURED_FLOODED.to_string(),
    }))
}

/// Warnings of the capillary states: the regime of each, and the Kelvin
/// equation below its molecular limit.
pub fn warnings(w: &PerssonWetOutput) -> Vec<String> {
    regime_warnings(
        w.meniscus.kelvin_radius_m,
        w.states.iter().map(|s| s.regime),
    )
}

/// The capillary table `asperity persson` prints.
pub fn text(w: &PerssonWetOutput) -> String {
    use std::fmt::Write as _;
    let mut t = table_head(&w.meniscus, "");
    for s in &w.states {
        let _ = writeln!(t, "{}", state_cells!(s));
    }
    t.push_str(
        "(flooded: Laplace pressure on the area where Persson's gap distribution is below h_m; \
         summits: menisci beside GW's summits at the same mean pressure; summ/fl: their \
         difference where both apply, 0.1 <= h_m/u_rms <= 1)\n",
    );
    let _ = writeln!(t, "capillary numerical error: {}", w.numerical_error);
    let _ = writeln!(t, "capillary model error: {}", w.model_error);
    t
}
