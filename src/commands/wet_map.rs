//! The flooded capillary model on a map's exact states (`asperity bem
//! --relative-humidity`): the Laplace pressure on the area where each
//! state's gap is below the meniscus height `h_m`
//! ([`crate::capillary::flooded_force`]), the regime from `h_m` over the
//! RMS gap, and beside it the per-summit menisci on GW's summits of the
//! same map at the same mean pressure
//! ([`crate::capillary::per_summit_pressure`]), with their difference where
//! both apply (the transition, `0.1 <= h_m/u_rms <= 1`).

use super::{param, CommandResult};
use crate::bem::compare::Comparison;
use crate::capillary::{flooded_force, per_summit_pressure, Meniscus, Regime};
use crate::persson::Persson;
use crate::Error;
use serde::Serialize;

/// The condensing liquid and the humidity (the scene's `adhesion.*` keys).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Liquid {
    /// Relative humidity, in `(0, 1)`.
    pub relative_humidity: f64,
    /// Surface tension `gamma` (N/m); water 0.0728.
    pub surface_tension: f64,
    /// Contact angle on the rough body (degrees), in `[0, 180]`; 0.
    pub contact_angle_1: f64,
    /// Contact angle on the flat (degrees), in `[0, 180]`; 0.
    pub contact_angle_2: f64,
    /// Temperature `T` (K); 293.15.
    pub temperature: f64,
    /// Molar volume `V_m` (m^3/mol); water 1.8e-5.
    pub molar_volume: f64,
}

impl Liquid {
    /// Water at 293.15 K wetting both surfaces at `relative_humidity`.
    pub fn water(relative_humidity: f64) -> Self {
        Liquid {
            relative_humidity,
            surface_tension: crate::capillary::WATER_SURFACE_TENSION,
            contact_angle_1: 0.0,
            contact_angle_2: 0.0,
            temperature: crate::capillary::ROOM_TEMPERATURE,
            molar_volume: crate::capillary::WATER_MOLAR_VOLUME,
        }
    }

    /// The meniscus, `None` when none condenses (`RH = 0`, or the liquid
    /// does not wet the gap).
    ///
    /// # Errors
    /// Naming the input (`{relative_humidity}`, `{contact_angle_1}`, ...).
    pub fn meniscus(&self) -> CommandResult<Option<Meniscus>> {
        for (name, deg) in [
            ("contact_angle_1", self.contact_angle_1),
            ("contact_angle_2", self.contact_angle_2),
        ] {
            crate::error::Allowed::closed(0.0, 180.0).check(&param(name), deg)?;
        }
        Meniscus::new(
            self.surface_tension,
            self.contact_angle_1.to_radians(),
            self.contact_angle_2.to_radians(),
            self.molar_volume,
            self.temperature,
            self.relative_humidity,
        )
        .map_err(|e| match e.field() {
            Some(f) => {
                let f = f.to_string();
                e.renamed(&param(&f))
            }
            None => e,
        })
    }
}

/// One state's capillary attraction.
#[derive(Serialize, Debug, Clone, Copy)]
pub struct WetState {
    /// The state's mean pressure (Pa) without the menisci.
    #[serde(rename = "pressure_Pa")]
    pub pressure: f64,
    /// Its mean gap (m).
    pub mean_gap_m: f64,
    /// RMS gap `u_rms` (m).
    pub rms_gap_m: f64,
    /// `h_m / u_rms`.
    pub ratio: f64,
    /// The regime of the ratio (`per-summit` below 0.1, `flooded` above 1).
    pub regime: Regime,
    /// The wetted fraction `A_w/A0` (gap below `h_m`).
    pub wetted_fraction: f64,
    /// Flooded attraction per nominal area `Delta p A_w/A0` (Pa, > 0).
    #[serde(rename = "flooded_pressure_Pa")]
    pub flooded_pressure: f64,
    /// The bound on the wetted edge's surface-tension term per nominal
    /// area, `gamma L/A0` (Pa).
    #[serde(rename = "edge_bound_Pa")]
    pub edge_bound: f64,
    /// Per-summit menisci on GW's summits at the same mean pressure (Pa),
    /// where GW has a state.
    #[serde(rename = "per_summit_pressure_Pa")]
    pub per_summit_pressure: Option<f64>,
    /// The model error in the transition: `per_summit/flooded - 1` (null
    /// outside it, where one model applies).
    pub model_error: Option<f64>,
    /// The flooded attraction from Persson's gap distribution on the map's
    /// radial spectrum at the same mean pressure (Pa), where it has one
    /// ([`crate::persson::Persson::gap_statistics`]).
    #[serde(rename = "persson_flooded_pressure_Pa")]
    pub persson_flooded_pressure: Option<f64>,
    /// Persson's flooded attraction against the exact gap field's,
    /// `persson/exact - 1`: the Persson route's model error on this map.
    pub persson_vs_exact: Option<f64>,
}

/// A meniscus as the capillary outputs state it (`asperity bem` and
/// `asperity persson` with `--relative-humidity`).
#[derive(Serialize, Debug, Clone, Copy, PartialEq)]
pub struct MeniscusOutput {
    /// Kelvin radius `r_K` (m).
    pub kelvin_radius_m: f64,
    /// Laplace pressure `gamma/r_K` (Pa).
    #[serde(rename = "laplace_pressure_Pa")]
    pub laplace_pressure: f64,
    /// Meniscus height `h_m = r_K (cos theta_1 + cos theta_2)` (m).
    pub meniscus_height_m: f64,
}

impl MeniscusOutput {
    /// The scales of `m`.
    pub fn of(m: &Meniscus) -> MeniscusOutput {
        MeniscusOutput {
            kelvin_radius_m: m.kelvin_radius(),
            laplace_pressure: m.laplace_pressure(),
            meniscus_height_m: m.height(),
        }
    }
}

/// What `--relative-humidity` adds to `asperity bem`.
#[derive(Serialize, Debug, Clone)]
pub struct WetOutput {
    /// The meniscus (its keys inline).
    #[serde(flatten)]
    pub meniscus: MeniscusOutput,
    /// One per exact state, in order.
    pub states: Vec<WetState>,
}

/// The capillary attraction of every state of `cmp` on a `rows x cols`
/// map of pixels `(dx, dy)` (m), with Persson's gap distribution on the
/// map's spectrum (`persson`) beside each; `None` when no meniscus
/// condenses.
///
/// # Errors
/// Naming the liquid's input; [`Error::Invalid`] from the gap fields
/// (none expected: the solver's gaps are finite and >= 0).
pub fn wet_states(
    liquid: &Liquid,
    cmp: &Comparison,
    persson: Option<&Persson>,
    (rows, cols): (usize, usize),
    (dx, dy): (f64, f64),
) -> CommandResult<Option<WetOutput>> {
    let Some(m) = liquid.meniscus()? else {
        return Ok(None);
    };
    let area = (rows * cols) as f64 * dx * dy;
    let mut states = Vec::with_capacity(cmp.states.len());
    for st in &cmp.states {
        let s = &st.solution;
        // The adhesive gap solver may leave gaps of a rounding below 0
        // (freed pixels): they are in contact. Rows run along y (pixel
        // dy), a row along x (dx).
        let gaps: Vec<f64> = s.gap.iter().map(|g| g.max(0.0)).collect();
        let f = flooded_force(&m, &gaps, rows, cols, dy, dx)?;
        let per_summit = match (cmp.gw_summits, st.gw_separation) {
            (Some(g), Some(d)) => Some(per_summit_pressure(&m, g.density, g.radius, g.sigma, d)?),
            _ => None,
        };
        let flooded = f.force / area;
        let model_error = per_summit
            .filter(|_| f.regime == Regime::Transition && flooded > 0.0)
            .map(|p| p / flooded - 1.0);
        crate::cancel::check()?;
        let persson_flooded = persson
            .filter(|_| s.mean_pressure > 0.0)
            .and_then(|pm| pm.gap_statistics(s.mean_pressure, m.height()).ok())
            .map(|g| m.laplace_pressure() * g.fraction_below);
        states.push(WetState {
            pressure: s.mean_pressure,
            mean_gap_m: s.mean_gap,
            rms_gap_m: f.rms_gap,
            ratio: f.ratio,
            regime: f.regime,
            wetted_fraction: f.wetted_fraction,
            flooded_pressure: flooded,
            edge_bound: f.perimeter_bound / area,
            per_summit_pressure: per_summit,
            model_error,
            persson_flooded_pressure: persson_flooded,
            persson_vs_exact: persson_flooded
                .filter(|_| flooded > 0.0)
                .map(|p| p / flooded - 1.0),
        });
    }
    if states.is_empty() {
        return Err(Error::invalid(param("relative_humidity"), "no state"));
    }
    Ok(Some(WetOutput {
        meniscus: MeniscusOutput::of(&m),
        states,
    }))
}

/// Warnings of the capillary states: the regime, and the Kelvin equation
/// below its molecular limit.
pub fn warnings(w: &WetOutput) -> Vec<String> {
    regime_warnings(
        w.meniscus.kelvin_radius_m,
        w.states.iter().map(|s| s.regime),
    )
}

/// The warnings of a Kelvin radius `r_k` (m) below a molecule and of each
/// state's regime outside the transition (shared by `bem` and `persson`).
pub fn regime_warnings(r_k: f64, regimes: impl Iterator<Item = Regime>) -> Vec<String> {
    let mut out = Vec::new();
    if r_k < crate::capillary::MOLECULAR_SIZE {
        out.push(format!(
            "capillary: Kelvin radius {:.3e} m below a molecule ({:e} m): the continuum meniscus \
             is outside its validity",
            r_k,
            crate::capillary::MOLECULAR_SIZE
        ));
    }
    for (i, regime) in regimes.enumerate() {
        let note = match regime {
            Regime::Flooded => {
                "flooded (h_m/u_rms > 1): the flooded column applies, per-summit \
                                menisci have merged"
            }
            Regime::PerSummit => {
                "per-summit (h_m/u_rms < 0.1): the per-summit column applies, \
                                  the menisci have not merged"
            }
            Regime::Transition => continue,
        };
        out.push(format!("capillary state {i}: {note}"));
    }
    out
}

/// The regime's name as the tables print it.
pub fn regime_name(r: Regime) -> &'static str {
    match r {
        Regime::PerSummit => "per-summit",
        Regime::Transition => "transition",
        Regime::Flooded => "flooded",
    }
}

/// The capillary tables' first line (the meniscus) and column titles: the
/// eight columns of both tables ([`state_cells!`]), then `extra` (the
/// caller's own titles, laid out).
pub(super) fn table_head(m: &MeniscusOutput, extra: &str) -> String {
    use std::fmt::Write as _;
    let MeniscusOutput {
        kelvin_radius_m,
        laplace_pressure,
        meniscus_height_m,
    } = m;
    let mut t = format!(
        "capillary: Kelvin radius {kelvin_radius_m:.4e} m, Laplace pressure \
         {laplace_pressure:.4e} Pa, meniscus height h_m {meniscus_height_m:.4e} m\n"
    );
    let _ = writeln!(
        t,
        "{:>12} {:>12} {:>8} {:>11} {:>10} {:>14} {:>14} {:>9}{extra}",
        "p (Pa)",
        "u_rms (m)",
        "h_m/u",
        "regime",
        "A_w/A0",
        "flooded (Pa)",
        "summits (Pa)",
        "summ/fl",
    );
    t
}

/// A table cell: `-` for none, a signed percentage for a relative
/// difference (`relative`), else four significant digits.
pub(super) fn cell(x: Option<f64>, relative: bool) -> String {
    match x {
        Some(v) if relative => format!("{:+.1}%", 100.0 * v),
        Some(v) => format!("{v:.4e}"),
        None => "-".into(),
    }
}

/// The eight cells of a capillary state's row under [`table_head`]'s
/// titles, from a state with the fields `pressure`, `rms_gap_m`, `ratio`,
/// `regime`, `wetted_fraction`, `flooded_pressure`, `per_summit_pressure`
/// and `model_error` ([`WetState`], `PerssonWetState`).
macro_rules! state_cells {
    ($s:expr) => {
        format!(
            "{:>12.4e} {:>12.4e} {:>8.3} {:>11} {:>10.4e} {:>14.4e} {:>14} {:>9}",
            $s.pressure,
            $s.rms_gap_m,
            $s.ratio,
            $crate::commands::wet_map::regime_name($s.regime),
            $s.wetted_fraction,
            $s.flooded_pressure,
            $crate::commands::wet_map::cell($s.per_summit_pressure, false),
            $crate::commands::wet_map::cell($s.model_error, true)
        )
    };
}
pub(super) use state_cells;

/// The capillary table `asperity bem` prints.
pub fn text(w: &WetOutput) -> String {
    use std::fmt::Write as _;
    let extra = format!(" {:>14} {:>9}", "Persson (Pa)", "P/fl");
    let mut t = table_head(&w.meniscus, &extra);
    for s in &w.states {
        let _ = writeln!(
            t,
            "{} {:>14} {:>9}",
            state_cells!(s),
            cell(s.persson_flooded_pressure, false),
            cell(s.persson_vs_exact, true)
        );
    }
    t.push_str(
        "(flooded: Laplace pressure on the area where the gap is below h_m; summits: menisci \
         beside GW's summits at the same mean pressure; summ/fl: their difference where both \
         apply, 0.1 <= h_m/u_rms <= 1; Persson: the Laplace pressure on Persson's gap \
         distribution of the map's spectrum below h_m; P/fl: its difference from the exact \
         gap field's, the Persson route's model error)\n",
    );
    t
}
