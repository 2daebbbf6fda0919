//! Capillary (wet) adhesion: water menisci condensed from the vapour at a
//! relative humidity, beside the dry (solid) adhesion.
//!
//! # Equations (docs/physics.md, "Capillary adhesion")
//! - Kelvin radius `r_K = gamma V_m / (R_g T ln(1/RH))` (m): the meniscus'
//!   mean radius of curvature in equilibrium with the vapour (Israelachvili,
//!   *Intermolecular and Surface Forces*, 3rd ed., eq. 17.10). Water at
//!   293.15 K (`gamma = 0.0728 N/m`, `V_m = 1.8e-5 m^3/mol`): `0.538 nm / ln(1/RH)`.
//! - Laplace pressure `Delta p = gamma / r_K` (Pa), the suction inside the
//!   meniscus.
//! - For `r_K` much smaller than the sphere radius the meniscus acts as a
//!   Dugdale zone: tension `Delta p` wherever the gap is below
//!   `h_m = r_K (cos theta_1 + cos theta_2)`, work of adhesion
//!   `w_m = Delta p h_m = gamma (cos theta_1 + cos theta_2)` (Fogden & White
//!   1990, J. Colloid Interface Sci. 138, 414; Maugis & Gauthier-Manuel 1994,
//!   J. Adhes. Sci. Technol. 8, 1311). On a rigid sphere the pull-off tends to
//!   `2 pi R gamma (cos theta_1 + cos theta_2)`; on an elastic sphere it is
//!   the Maugis–Dugdale solution with `(sigma0, delta_t) = (Delta p, h_m)`
//!   ([`Meniscus::maugis`]); with the solid's own adhesion it is the
//!   two-zone solution ([`TwoZone`]).
//!
//! `RH = 0` means no meniscus: every wet quantity then equals the dry one
//! bit for bit (the callers keep the dry law).

mod beside;
mod carlson;
mod flooded;
mod summits;
mod two_zone;

pub use beside::{derjaguin_error, WithMeniscus};
pub use flooded::{flooded_force, FloodedForce, Regime};
pub use summits::per_summit_pressure;
pub use two_zone::{TwoZone, Zone};

use crate::error::{Allowed, Error, Result};
use crate::law::Maugis;
use crate::material::maugis_lambda;
use std::f64::consts::PI;

/// Molar gas constant `R_g` (J/(mol K)), exact SI value (2019).
pub const GAS_CONSTANT: f64 = 8.314_462_618;
/// Surface tension of water at 20 C (N/m).
pub const WATER_SURFACE_TENSION: f64 = 0.0728;
/// Molar volume of liquid water (m^3/mol).
pub const WATER_MOLAR_VOLUME: f64 = 1.8e-5;
/// Default temperature (K): 20 C.
pub const ROOM_TEMPERATURE: f64 = 293.15;

/// The largest Kelvin radius (m) a meniscus may have: `1e-4` m. Beyond it
/// the inputs are not a condensing liquid film (water at 293 K reaches it
/// near RH 0.999995) and the laws' ranges overflow.
pub const MAX_KELVIN_RADIUS: f64 = 1e-4;
/// Below this Kelvin radius (m) the meniscus is a few molecules across and
/// the continuum Kelvin equation does not hold (a water molecule is
/// ~0.3 nm; Fisher & Israelachvili 1981 verified it down to ~0.5 nm).
pub const MOLECULAR_SIZE: f64 = 0.2e-9;

/// Kelvin radius `r_K = gamma V_m / (R_g T ln(1/RH))` (m); 0 for `RH = 0`
/// (no meniscus), `+inf` for `RH = 1`. Arguments in SI units:
/// `surface_tension` N/m, `molar_volume` m^3/mol, `temperature` K.
pub fn kelvin_radius(
    surface_tension: f64,
    molar_volume: f64,
    temperature: f64,
    relative_humidity: f64,
) -> f64 {
    if relative_humidity <= 0.0 {
        return 0.0;
    }
    surface_tension * molar_volume / (GAS_CONSTANT * temperature * (-relative_humidity.ln()))
}

/// A liquid (its surface tension, molar volume and temperature), the two
/// contact angles and the relative humidity: the meniscus that condenses
/// between two surfaces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Meniscus {
    surface_tension: f64,
    contact_angle_1: f64,
    cos_sum: f64,
    kelvin_radius: f64,
}

impl Meniscus {
    /// `surface_tension` (N/m, > 0), `contact_angle_1` and `contact_angle_2`
    /// (rad, in `[0, pi]`; surface 1 is the summit's body), `molar_volume`
    /// (m^3/mol, > 0), `temperature` (K, > 0), `relative_humidity` in
    /// `[0, 1)`. `None` when no meniscus condenses: `RH = 0`, or
    /// `cos theta_1 + cos theta_2 <= 0` (the liquid does not wet the gap).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming the argument.
    pub fn new(
        surface_tension: f64,
        contact_angle_1: f64,
        contact_angle_2: f64,
        molar_volume: f64,
        temperature: f64,
        relative_humidity: f64,
    ) -> Result<Option<Self>> {
        Allowed::POSITIVE.check("surface_tension", surface_tension)?;
        Allowed::closed(0.0, PI).check("contact_angle_1", contact_angle_1)?;
        Allowed::closed(0.0, PI).check("contact_angle_2", contact_angle_2)?;
        Allowed::POSITIVE.check("molar_volume", molar_volume)?;
        Allowed::POSITIVE.check("temperature", temperature)?;
        Allowed::closed_open(0.0, 1.0).check("relative_humidity", relative_humidity)?;
        let cos_sum = contact_angle_1.cos() + contact_angle_2.cos();
        if relative_humidity == 0.0 || cos_sum <= 0.0 {
            return Ok(None);
        }
        let r_k = kelvin_radius(
            surface_tension,
            molar_volume,
            temperature,
            relative_humidity,
        );
        if !(r_k > 0.0 && r_k <= MAX_KELVIN_RADIUS) {
            // Blame the input furthest (in decades) from water at room
            // temperature and RH 0.5, whose Kelvin radius is 0.78 nm.
            let ln_rh = |rh: f64| -rh.ln();
            let (name, value) = [
                (
                    "surface_tension",
                    surface_tension,
                    surface_tension / WATER_SURFACE_TENSION,
                ),
                (
                    "molar_volume",
                    molar_volume,
                    molar_volume / WATER_MOLAR_VOLUME,
                ),
                ("temperature", temperature, ROOM_TEMPERATURE / temperature),
                (
                    "relative_humidity",
                    relative_humidity,
                    ln_rh(0.5) / ln_rh(relative_humidity),
                ),
            ]
            .into_iter()
            .max_by(|a, b| a.2.log10().abs().total_cmp(&b.2.log10().abs()))
            .map(|(n, v, _)| (n, v))
            .unwrap_or(("relative_humidity", relative_humidity));
            return Err(Error::invalid(
                name,
                format!(
                    "{value:e} gives a Kelvin radius of {r_k:e} m, beyond {MAX_KELVIN_RADIUS:e} m \
                     (the Kelvin equation describes menisci of nanometres to micrometres; \
                     water at 293 K reaches 1e-4 m near RH 0.999995)"
                ),
            ));
        }
        Ok(Some(Meniscus {
            surface_tension,
            contact_angle_1,
            cos_sum,
            kelvin_radius: r_k,
        }))
    }

    /// Water at 293.15 K wetting both surfaces (contact angles 0) at
    /// `relative_humidity` in `(0, 1)`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `relative_humidity`.
    pub fn water(relative_humidity: f64) -> Result<Option<Self>> {
        Self::new(
            WATER_SURFACE_TENSION,
            0.0,
            0.0,
            WATER_MOLAR_VOLUME,
            ROOM_TEMPERATURE,
            relative_humidity,
        )
    }

    /// Kelvin radius `r_K` (m).
    pub fn kelvin_radius(&self) -> f64 {
        self.kelvin_radius
    }

    /// Laplace pressure `Delta p = gamma / r_K` (Pa).
    pub fn laplace_pressure(&self) -> f64 {
        self.surface_tension / self.kelvin_radius
    }

    /// `cos theta_1 + cos theta_2`.
    pub fn cos_sum(&self) -> f64 {
        self.cos_sum
    }

    /// Surface tension `gamma` (N/m).
    pub fn surface_tension(&self) -> f64 {
        self.surface_tension
    }

    /// Meniscus height `h_m = r_K (cos theta_1 + cos theta_2)` (m): the
    /// largest gap the meniscus spans, the range of its Dugdale zone.
    pub fn height(&self) -> f64 {
        self.kelvin_radius * self.cos_sum
    }

    /// Work of adhesion of the meniscus `w_m = Delta p h_m =
    /// gamma (cos theta_1 + cos theta_2)` (J/m^2).
    pub fn work(&self) -> f64 {
        self.surface_tension * self.cos_sum
    }

    /// The meniscus as a Dugdale zone: stress `Delta p` up to the gap `h_m`.
    pub fn zone(&self) -> Zone {
        Zone {
            stress: self.laplace_pressure(),
            range: self.height(),
        }
    }

    /// Load (N, < 0 tensile) on a rigid sphere of radius `R` (m) at the gap
    /// `D >= 0` (m) from a rigid flat, with the meniscus in equilibrium with
    /// the vapour (closed form). The meniscus fills the gap where it is below
    /// `h_m`: out to the wetted radius `r_c` with
    /// `R - sqrt(R^2 - r_c^2) = h_m - D`, i.e.
    /// `r_c^2 = 2 R (h_m - D) - (h_m - D)^2`; the Laplace pressure acts on the
    /// wetted disc and the surface tension along its edge on the sphere, at
    /// the filling angle `sin phi = r_c / R`:
    ///
    /// ```text
    /// P(D) = -[pi Delta p r_c^2 + 2 pi r_c gamma sin(phi + theta_1)],   D < h_m
    /// P(D) = 0,                                                          D >= h_m
    /// ```
    ///
    /// (Orr, Scriven & Rivas 1975, J. Fluid Mech. 67, 723, with the circular
    /// meniscus of radius `r_K`). As `r_K / R -> 0`,
    /// `P(0) -> -2 pi R gamma (cos theta_1 + cos theta_2)` with a relative
    /// correction `O(sqrt(r_K / R))` ([`Meniscus::rigid_pull_off`]).
    pub fn rigid_load(&self, radius: f64, gap: f64) -> f64 {
        let h = self.height() - gap.max(0.0);
        if !(h > 0.0) {
            return 0.0;
        }
        let h = h.min(radius);
        let rc2 = h * (2.0 * radius - h);
        let rc = rc2.sqrt();
        let phi = (rc / radius).min(1.0).asin();
        -(PI * self.laplace_pressure() * rc2
            + 2.0 * PI * rc * self.surface_tension * (phi + self.contact_angle_1).sin())
    }

    /// The Derjaguin (rigid, `r_K << R`) limit of the pull-off,
    /// `2 pi R gamma (cos theta_1 + cos theta_2)` (N, > 0).
    pub fn rigid_pull_off(&self, radius: f64) -> f64 {
        2.0 * PI * radius * self.work()
    }

    /// Maugis parameter of the meniscus zone on an elastic sphere,
    /// `lambda_m = 2 Delta p (R / (pi w_m K^2))^(1/3)`, `K = 4 E*/3`.
    pub fn lambda(&self, radius: f64, contact_modulus: f64) -> f64 {
        maugis_lambda(
            radius,
            contact_modulus,
            self.work(),
            self.laplace_pressure(),
        )
    }

    /// The elastic sphere (radius `R`, contact modulus `E*`, Pa) held by the
    /// meniscus alone: the Maugis–Dugdale law with `sigma0 = Delta p`,
    /// `delta_t = h_m`, `w = w_m` (Maugis & Gauthier-Manuel 1994).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `radius`, `contact_modulus` or `lambda`
    /// (outside `[1e-6, 1e6]`).
    pub fn maugis(&self, radius: f64, contact_modulus: f64) -> Result<Maugis> {
        Maugis::new(
            radius,
            contact_modulus,
            self.work(),
            self.lambda(radius, contact_modulus),
        )
    }
}
