//! The liquid flags of `asperity bem` and `asperity persson`: the
//! relative humidity and the condensing liquid's properties.

use asperity::commands::wet_map::Liquid;
use clap::Args;

/// `--relative-humidity` and the liquid it condenses (water by default).
#[derive(Args, Debug)]
pub struct LiquidArgs {
    /// Relative humidity in (0, 1): adds the flooded capillary attraction
    /// (Laplace pressure where the gap is below the meniscus height: the
    /// map's exact gaps for bem, Persson's gap distribution for persson)
    /// beside per-summit menisci on GW's summits, and the regime.
    #[arg(long, allow_hyphen_values = true)]
    relative_humidity: Option<f64>,
    /// Surface tension of the condensing liquid (N/m); water 0.0728.
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 0.0728,
        requires = "relative_humidity"
    )]
    surface_tension: f64,
    /// Contact angle of the liquid on the rough body (degrees).
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 0.0,
        requires = "relative_humidity"
    )]
    contact_angle_1: f64,
    /// Contact angle of the liquid on the flat (degrees).
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 0.0,
        requires = "relative_humidity"
    )]
    contact_angle_2: f64,
    /// Temperature of liquid and vapour (K).
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 293.15,
        requires = "relative_humidity"
    )]
    temperature: f64,
    /// Molar volume of the liquid (m^3/mol); water 1.8e-5.
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 1.8e-5,
        requires = "relative_humidity"
    )]
    molar_volume: f64,
}

impl LiquidArgs {
    /// The liquid, when a humidity is given.
    pub fn liquid(&self) -> Option<Liquid> {
        self.relative_humidity.map(|rh| Liquid {
            relative_humidity: rh,
            surface_tension: self.surface_tension,
            contact_angle_1: self.contact_angle_1,
            contact_angle_2: self.contact_angle_2,
            temperature: self.temperature,
            molar_volume: self.molar_volume,
        })
    }
}
