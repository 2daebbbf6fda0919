//! `asperity persson`: Persson's contact theory on an analytic self-affine
//! spectrum, with GW on the same spectrum beside it.

use super::criteria::{of_spectrum, Assessment};
use super::wet_map::Liquid;
use super::wet_persson::{persson_wet, PerssonWetOutput};
use super::{param, CommandResult};
use crate::error::positive;
use crate::gw::GwOnMoments;
use crate::persson::{Persson, QUAD_RTOL};
use crate::spectrum::{Normalisation, Spectrum};
use crate::Error;
use serde::Serialize;

/// The input of [`persson`]: a self-affine spectrum, the modulus and the
/// mean pressures.
#[derive(Debug, Clone)]
pub struct PerssonInput {
    /// Hurst exponent H, in (0, 1].
    pub hurst: f64,
    /// Smallest wavevector q_l (rad/m): the spectrum is zero below.
    pub q_long: f64,
    /// Roll-off wavevector q_r >= q_l (rad/m): flat between q_l and q_r.
    pub q_roll: f64,
    /// Largest wavevector q_s > q_r (rad/m): C ~ q^-2(1+H) up to it.
    pub q_short: f64,
    /// The spectrum's normalisation: its RMS height (m) or RMS gradient.
    pub normalisation: Normalisation,
    /// Contact modulus E* (Pa).
    pub estar: f64,
    /// Mean pressures (Pa), each > 0.
    pub pressures: Vec<f64>,
    /// Yang–Persson factor gamma in [0, 1] of the mean separation (1: all
    /// the elastic energy of the contact regions; Yang & Persson found
    /// 0.4-0.45). Default 1.
    pub gamma: f64,
    /// Work of adhesion w (J/m^2): adds the Persson–Tosatti number
    /// U_full/w.
    pub adhesion_energy: Option<f64>,
    /// Range rho (m) of `-w exp(-g/rho)`: adds the stickiness criteria.
    pub adhesion_range: Option<f64>,
    /// The condensing liquid and humidity: adds the flooded capillary
    /// attraction from Persson's gap distribution at each pressure
    /// ([`super::wet_persson`]).
    pub liquid: Option<Liquid>,
}

/// The normalisation from the two optional inputs, exactly one of which is
/// given: `h_rms` (m) or `slope_rms`.
///
/// # Errors
/// [`crate::Error::Invalid`] naming both when both or neither are given;
/// out of range naming the one given.
pub fn normalisation(h_rms: Option<f64>, slope_rms: Option<f64>) -> CommandResult<Normalisation> {
    match (h_rms, slope_rms) {
        (Some(h), None) => Ok(Normalisation::HRms(positive(&param("h_rms"), h)?)),
        (None, Some(g)) => Ok(Normalisation::SlopeRms(positive(&param("slope_rms"), g)?)),
        (Some(_), Some(_)) => Err(Error::invalid(
            format!("{}, {}", param("h_rms"), param("slope_rms")),
            "give only one of them",
        )),
        (None, None) => Err(Error::invalid(
            format!("{} or {}", param("h_rms"), param("slope_rms")),
            "one is needed",
        )),
    }
}

/// Each of `values` (named `name`, entry by entry) finite and > 0, and at
/// least one.
///
/// # Errors
/// Naming `{name}` (empty) or `{name[i]}`.
pub fn positive_values(name: &str, values: &[f64]) -> CommandResult<()> {
    if values.is_empty() {
        return Err(Error::invalid(param(name), "empty list"));
    }
    for (i, &x) in values.iter().enumerate() {
        positive(&param(&format!("{name}[{i}]")), x)?;
    }
    Ok(())
}

/// One mean pressure: Persson's and GW's area and gap.
#[derive(Serialize, Debug, Clone)]
pub struct PerssonState {
    /// Mean pressure (Pa).
    #[serde(rename = "pressure_Pa")]
    pub pressure: f64,
    /// Persson's real-area fraction `A/A0`.
    pub area_fraction: f64,
    /// Persson's mean gap (m).
    pub mean_gap_m: f64,
    /// GW's real-area fraction on the same spectrum.
    pub gw_area_fraction: f64,
    /// GW's mean gap (m).
    pub gw_mean_gap_m: f64,
    /// GW's area fraction against Persson's, `GW/Persson - 1`.
    pub gw_vs_persson_area: f64,
    /// GW's mean gap against Persson's, `GW/Persson - 1`.
    pub gw_vs_persson_mean_gap: f64,
}

/// GW's parameters from the spectrum's moments (McCool).
#[derive(Serialize, Debug, Clone)]
pub struct PerssonGw {
    /// Summit density (1/m^2).
    pub density_per_m2: f64,
    /// Summit radius (m).
    pub radius_m: f64,
    /// Summit-height standard deviation (m).
    pub sigma_m: f64,
    /// Mean summit height above the mean plane (m).
    pub mean_summit_height_m: f64,
}

/// What `asperity persson --json` prints.
#[derive(Serialize, Debug, Clone)]
pub struct PerssonOutput {
    /// One entry per mean pressure, in the order given.
    pub states: Vec<PerssonState>,
    /// The spectrum's RMS height (m).
    pub h_rms_m: f64,
    /// The spectrum's RMS gradient.
    pub slope_rms: f64,
    /// Spectral moment m0 (m^2).
    pub m0: f64,
    /// Spectral moment m2.
    pub m2: f64,
    /// Spectral moment m4 (1/m^2).
    pub m4: f64,
    /// Persson's `u0` (m): the slope of the mean gap against `ln p`.
    pub mean_gap_slope_m: f64,
    /// Elastic energy of full contact per area (J/m^2).
    #[serde(rename = "full_contact_energy_J_per_m2")]
    pub full_contact_energy: f64,
    /// The Yang–Persson factor used.
    pub gamma: f64,
    /// Persson–Tosatti number `U_full/w`, with an adhesion energy.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub persson_tosatti_number: Option<f64>,
    /// GW on the same spectrum.
    pub gw: PerssonGw,
    /// The errors in words, the warnings, the stickiness criteria with an
    /// adhesion energy and range, and with a liquid the flooded capillary
    /// attraction from Persson's gap distribution; its keys inline.
    #[serde(flatten)]
    pub assessment: Assessment<PerssonWetOutput>,
}

/// Persson's theory and GW on a self-affine spectrum (`asperity persson`).
///
/// # Errors
/// Naming an input (`{pressures[i]}`, `{q_long}`, ...); a state the
/// solvers cannot find at an extreme pressure is bad input naming
/// `{pressures}`.
pub fn persson(input: &PerssonInput) -> CommandResult<PerssonOutput> {
    positive_values("pressures", &input.pressures)?;
    check_wavevectors(input)?;
    positive(&param("estar"), input.estar)?;
    if let Some(l) = &input.liquid {
        l.meniscus()?;
    }
    let norm = input.normalisation;
    let named = |e: Error| spectrum_error(e, norm);
    let spectrum =
        Spectrum::self_affine(input.hurst, input.q_long, input.q_roll, input.q_short, norm)
            .map_err(named)?;
    let model = Persson::new(spectrum.clone(), input.estar, input.gamma).map_err(named)?;
    // GW per square metre (pressures and gaps do not depend on the area).
    let moments = spectrum.moments().map_err(named)?;
    let gw = GwOnMoments::new(&moments, input.estar, 1.0).map_err(named)?;
    let mut states = Vec::new();
    let mut worst_quad: f64 = 0.0;
    let mut warnings = Vec::new();
    // The states whose GW area fraction was above 1 (null, warned).
    let mut above_one = Vec::new();
    for &p in &input.pressures {
        crate::cancel::check()?;
        let s = model.state(p).map_err(|e| at_pressure(input, p, e))?;
        worst_quad = worst_quad.max(s.mean_gap_error / s.mean_gap.abs().max(f64::MIN_POSITIVE));
        let g = gw.state(p).map_err(|e| at_pressure(input, p, e))?;
        let gw_area_fraction = gw_fraction(states.len(), p, g.area_fraction, &mut warnings);
        if g.area_fraction > 1.0 {
            above_one.push(states.len());
        }
        states.push(PerssonState {
            pressure: p,
            area_fraction: s.area_fraction,
            mean_gap_m: s.mean_gap,
            gw_area_fraction,
            gw_mean_gap_m: g.mean_gap,
            gw_vs_persson_area: gw_area_fraction / s.area_fraction - 1.0,
            gw_vs_persson_mean_gap: g.mean_gap / s.mean_gap - 1.0,
        });
    }
    warnings.extend(apart_warnings(&states));
    let pt = input
        .adhesion_energy
        .map(|w| {
            model
                .persson_tosatti_number(w)
                .map_err(|e| e.renamed(&param("adhesion_energy")))
        })
        .transpose()?;
    warnings.extend(non_finite_warnings(&states, &above_one));
    let capillary = match &input.liquid {
        Some(l) => persson_wet(l, &model, &gw, &input.pressures)?,
        None => None,
    };
    if let Some(c) = &capillary {
        warnings.extend(super::wet_persson::warnings(c));
    }
    let adhesion = (input.adhesion_energy, input.adhesion_range);
    let adhesion_criteria = of_spectrum(&spectrum, input.estar, adhesion, &mut warnings)?;
    let pt = match (pt, input.adhesion_energy) {
        (Some(x), Some(w)) if !x.is_finite() => {
            warnings.push(format!(
                "persson_tosatti_number is null: the full-contact elastic energy {:e} J/m^2 over \
                 the work of adhesion {w:e} J/m^2 is beyond the largest double (so small a work \
                 of adhesion cannot pull the surfaces into full contact)",
                model.full_contact_energy()
            ));
            None
        }
        (pt, _) => pt,
    };
    Ok(PerssonOutput {
        states,
        h_rms_m: spectrum.h_rms(),
        slope_rms: spectrum.slope_rms(),
        m0: spectrum.m0(),
        m2: spectrum.m2(),
        m4: spectrum.m4(),
        mean_gap_slope_m: model.mean_gap_slope(),
        full_contact_energy: model.full_contact_energy(),
        gamma: input.gamma,
        persson_tosatti_number: pt,
        gw: PerssonGw {
            density_per_m2: gw.params.density_per_m2,
            radius_m: gw.params.radius_m,
            sigma_m: gw.sigma,
            mean_summit_height_m: gw.mean_summit_height,
        },
        assessment: Assessment {
            numerical_error: format!(
                "Persson: area in closed form (erf, ~1e-15); mean gap by adaptive Gauss-Kronrod to {QUAD_RTOL:e} relative (largest estimate here {worst_quad:.1e}); both checked against mpmath to 1e-9 in tests/it/persson.rs. GW: closed-form F_n, ~1e-15"
            ),
            model_error: format!("{MEASURED_STATEMENT} Here gamma = {}.", input.gamma),
            warnings,
            adhesion_criteria,
            capillary,
        },
    })
}

/// What Persson's and GW's errors were measured to be against exact
/// boundary-element solutions, with the maps and loads
/// (`tools/reports/model_error_maps.rs`, docs/physics.md "GW and Persson
/// against the exact solution").
pub const MEASURED_STATEMENT: &str = "measured against exact elastic boundary-element \
    solutions (`cargo run --release --example model_error_maps`; docs/physics.md): on two \
    periodic self-affine maps, the shipped 256^2 examples/data/selfaffine-256.npy and a 512^2 \
    random-phase map (H = 0.8, roll-off at 4 q_l, q_s at a 4-pixel wavelength, RMS slope 0.1), \
    at p/E* = 0.001, 0.003 and 0.01 (exact A/A0 0.024 to 0.22), Persson's area (gamma = 1) was \
    24-37 % below the exact one and its mean gap -14 % to +48 % off; GW's area 33-49 % below and \
    its mean gap -21 % to +72 % off. Two maps, not a bound: a map's own errors are measured by \
    `asperity bem` on it. Persson's gap depends on gamma (Yang & Persson 2008 recommend about \
    0.4-0.45); GW neglects the elastic interaction of its summits and their coalescence.";

/// GW's area fraction `a` at `p` (Pa) for state `index`: null (NaN) with a
/// warning above 1, warned beyond GW's light-load validity above 0.1.
fn gw_fraction(index: usize, p: f64, a: f64, warnings: &mut Vec<String>) -> f64 {
    let mut gw_area_fraction = a;
    if a > 1.0 {
        // GW sums its summits' areas as if they never overlapped: above
        // 1 that sum is not a fraction, so it is not reported.
        warnings.push(format!(
            "states[{}].gw_area_fraction at p = {p:e} Pa is null: GW's sum of summit areas \
                 is {:.3} of the nominal area, more than all of it (GW holds below about 0.1, \
                 without asperity interaction)",
            index, a
        ));
        gw_area_fraction = f64::NAN;
    } else if a > 0.1 {
        warnings.push(format!(
                "GW at p = {p:e} Pa: area fraction {:.3} > 0.1, outside GW's light-load validity (no asperity interaction)",
                a
            ));
    }
    gw_area_fraction
}

/// A warning for each state's value that is not a finite number (null in
/// the JSON), except the GW area fractions above 1 in `above_one`, which
/// have their own.
fn non_finite_warnings(states: &[PerssonState], above_one: &[usize]) -> Vec<String> {
    let mut warnings = Vec::new();
    for (i, s) in states.iter().enumerate() {
        for (key, v) in [
            ("area_fraction", s.area_fraction),
            ("mean_gap_m", s.mean_gap_m),
            ("gw_area_fraction", s.gw_area_fraction),
            ("gw_mean_gap_m", s.gw_mean_gap_m),
        ] {
            // A GW area fraction above 1 is null with its own sentence.
            let explained = key == "gw_area_fraction" && above_one.contains(&i);
            if !v.is_finite() && !explained {
                warnings.push(format!(
                    "states[{i}].{key} at p = {:e} Pa is null: the model's value there is not a \
                     finite number (the pressure is beyond what its formula resolves in double \
                     precision)",
                    s.pressure
                ));
            }
        }
    }
    warnings
}

/// The largest `|GW/Persson - 1|` at which both theories can still be
/// within 10 % of the exact answer: `1.1/0.9 - 1`.
const APART_LIMIT: f64 = 1.1 / 0.9 - 1.0;

/// Warnings where GW and Persson differ by more than they could if both
/// were within 10 % of the exact answer (`0.9/1.1 <= GW/Persson <=
/// 1.1/0.9`): then at least one is off by more, which a spectrum alone
/// cannot tell.
fn apart_warnings(states: &[PerssonState]) -> Vec<String> {
    type Pick = fn(&PerssonState) -> f64;
    let picks: [(&str, Pick); 2] = [
        ("area fraction", |s| s.gw_vs_persson_area),
        ("mean gap", |s| s.gw_vs_persson_mean_gap),
    ];
    picks
        .into_iter()
        .filter_map(|(name, pick)| {
            let apart: Vec<&PerssonState> = states
                .iter()
                .filter(|s| pick(s).is_finite())
                .filter(|s| pick(s) > APART_LIMIT || pick(s) < 0.9 / 1.1 - 1.0)
                .collect();
            let worst = apart
                .iter()
                .max_by(|a, b| pick(a).abs().total_cmp(&pick(b).abs()))?;
            Some(format!(
                "GW's {name} differs from Persson's by {:+.1} % at p = {:e} Pa ({} of {} \
                 pressures beyond {:+.1} % .. {:+.1} %): at least one of them is more than 10 % from \
                 the exact answer there (`asperity bem` on a map measures which)",
                100.0 * pick(worst),
                worst.pressure,
                apart.len(),
                states.len(),
                100.0 * (0.9 / 1.1 - 1.0),
                100.0 * APART_LIMIT
            ))
        })
        .collect()
}

/// A state the solvers cannot find at an extreme pressure or modulus is
/// the inputs' fault (p/E* far outside contact mechanics): the error of
/// pressure `p` (Pa) named by `{pressures}`, with the modulus beside it.
fn at_pressure(input: &PerssonInput, p: f64, e: Error) -> Error {
    let context = format!(
        "{p:e} Pa with {} {:e} Pa (p/E* = {:.3e})",
        param("estar"),
        input.estar,
        p / input.estar
    );
    if e.is_bad_input() {
        // The reason without its own field's name: the pressure and the
        // modulus together are what is out of reach.
        let text = e.to_string();
        let reason = e
            .field()
            .and_then(|f| text.strip_prefix(&format!("{f}: ")))
            .unwrap_or(&text)
            .to_string();
        return Error::invalid(param("pressures"), format!("{context}: {reason}"));
    }
    Error::invalid(param("pressures"), format!("{context}: {e}"))
}

/// The wavevectors' order, named by both inputs of a pair.
///
/// # Errors
/// Naming `{q_long}` above `{q_roll}`, or `{q_roll}` not below `{q_short}`.
fn check_wavevectors(input: &PerssonInput) -> CommandResult<()> {
    let (long, roll, short) = (
        ("q_long", input.q_long),
        ("q_roll", input.q_roll),
        ("q_short", input.q_short),
    );
    super::check_order(long, roll, "", false)?;
    super::check_order(roll, short, "", true)
}

/// A spectrum's error named by the command's inputs: a moment of the
/// spectrum by every spectrum input (normalised by `norm`), any other
/// field by its own name.
fn spectrum_error(e: Error, norm: Normalisation) -> Error {
    let norm_name = match norm {
        Normalisation::HRms(_) => param("h_rms"),
        Normalisation::SlopeRms(_) => param("slope_rms"),
    };
    let f = e.field().unwrap_or("").to_string();
    if f.is_empty() {
        e
    } else if matches!(f.as_str(), "m0" | "m2" | "m4") {
        // A moment of the spectrum: every spectrum input sets it.
        e.renamed(&format!(
            "{f} of the spectrum from {}, {}, {}, {} and {norm_name}",
            param("hurst"),
            param("q_long"),
            param("q_roll"),
            param("q_short")
        ))
    } else {
        e.renamed(&param(&f))
    }
}
