//! Plastic material data: yield strength, hardness, and the numbers built
//! from them (critical interference of each elastic-plastic law variant,
//! Greenwood–Williamson plasticity index, regime of a contact).
//!
//! - Hardness `H` defaults to `2.8 Y` (Tabor 1951; the value Chang, Etsion &
//!   Bogy 1987 and Kogut & Etsion 2002 use), and must be `>= Y`.
//! - Two different bodies: the constants use the Poisson ratio and yield
//!   strength of the body that yields, the one with the lower yield strength
//!   ([`Plasticity::yielding_body`]); the elastic side enters only through
//!   `E*`. This is the convention of the sphere-on-rigid-flat fits
//!   (Kogut & Etsion 2002; Jackson & Green 2005), whose flat is rigid.
//! - Plasticity index `psi = (E*/H) sqrt(sigma/R)` (Greenwood & Williamson
//!   1966): above about 1 most contacts yield.
//!
//! This module holds the *material* data; the elastic-plastic *laws* built
//! from it are in [`crate::law::plastic`]. The Poisson ratio is the yielding
//! body's, the one its [`Material`](super::Material) already carries:
//! [`Plasticity::of`] takes it from there, so it is given once.

use crate::error::{positive, Allowed, Error, Result};
use std::f64::consts::PI;

/// Default hardness over yield strength, `H = 2.8 Y` (Tabor 1951).
pub const HARDNESS_PER_YIELD: f64 = 2.8;

/// Plastic properties of the body that yields.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plasticity {
    yield_strength: f64,
    hardness: f64,
    poisson_ratio: f64,
}

impl Plasticity {
    /// Yield strength `Y` (Pa, finite, > 0), optional hardness `H` (Pa,
    /// `Y <= H` finite; default `2.8 Y`) and the Poisson ratio `nu` of the
    /// yielding body (`[0, 0.5)`).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `yield_strength`, `hardness` (below the
    /// yield strength, NaN, infinite) or `poisson_ratio`.
    pub fn new(yield_strength: f64, hardness: Option<f64>, poisson_ratio: f64) -> Result<Self> {
        positive("yield_strength", yield_strength)?;
        Allowed::closed_open(0.0, 0.5).check("poisson_ratio", poisson_ratio)?;
        let hardness = match hardness {
            Some(h) => Allowed {
                lo: yield_strength,
                lo_inclusive: true,
                hi: f64::INFINITY,
                hi_inclusive: false,
            }
            .check("hardness", h)?,
            None => HARDNESS_PER_YIELD * yield_strength,
        };
        Ok(Plasticity {
            yield_strength,
            hardness,
            poisson_ratio,
        })
    }

    /// The plastic data of `material` (the yielding body): its Poisson ratio,
    /// yield strength `Y` (Pa) and optional hardness `H` (Pa, default
    /// `2.8 Y`); the Poisson ratio is not given a second time.
    ///
    /// ```
    /// use asperity::prelude::*;
    /// let gold = Material::gold();
    /// let p = Plasticity::of(&gold, 0.4e9, None)?;
    /// assert_eq!(p.poisson_ratio(), gold.poisson_ratio());
    /// assert_eq!(p, Plasticity::gold());
    /// # Ok::<(), asperity::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Plasticity::new`].
    pub fn of(
        material: &super::Material,
        yield_strength: f64,
        hardness: Option<f64>,
    ) -> Result<Self> {
        Plasticity::new(yield_strength, hardness, material.poisson_ratio())
    }

    /// Plastic data from optional scene values: `law` (its name, for the
    /// message) needs a yield strength; `hardness` alone is checked against
    /// it. Returns `None` when neither is given (an elastic law may omit
    /// both; they then feed no diagnostics).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `yield_strength` when a plastic law has none
    /// or a hardness is given without one; otherwise as [`Plasticity::new`].
    pub fn from_optional(
        law: &str,
        plastic_law: bool,
        yield_strength: Option<f64>,
        hardness: Option<f64>,
        poisson_ratio: f64,
    ) -> Result<Option<Self>> {
        match (yield_strength, hardness) {
            (Some(y), h) => Plasticity::new(y, h, poisson_ratio).map(Some),
            (None, _) if plastic_law => Err(Error::invalid(
                "yield_strength",
                format!("the {law} law needs the yield strength of the softer body (Pa)"),
            )),
            (None, Some(_)) => Err(Error::invalid(
                "yield_strength",
                "a hardness is given without a yield strength",
            )),
            (None, None) => Ok(None),
        }
    }

    /// Sputtered RF-MEMS gold: `Y = 0.4 GPa`, `H = 2.8 Y = 1.12 GPa`,
    /// `nu = 0.42`. With the default gold surface (`E* = 47.96 GPa`,
    /// `sigma = 5 nm`, `R = 1 um`) this gives `psi = 3.03`.
    pub fn gold() -> Self {
        use super::gold;
        Plasticity {
            yield_strength: gold::YIELD_STRENGTH,
            hardness: HARDNESS_PER_YIELD * gold::YIELD_STRENGTH,
            poisson_ratio: gold::POISSON_RATIO,
        }
    }

    /// Of two bodies, the one that yields first: the lower yield strength
    /// (ties: the lower hardness, then `a`).
    pub fn yielding_body(a: Plasticity, b: Plasticity) -> Plasticity {
        let key = |p: &Plasticity| (p.yield_strength, p.hardness);
        if key(&b) < key(&a) {
            b
        } else {
            a
        }
    }

    /// Yield strength `Y` (Pa).
    pub fn yield_strength(&self) -> f64 {
        self.yield_strength
    }

    /// Hardness `H` (Pa).
    pub fn hardness(&self) -> f64 {
        self.hardness
    }

    /// Poisson ratio of the yielding body.
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }

    /// Kogut–Etsion / Chang–Etsion–Bogy maximum contact pressure factor
    /// `K = 0.454 + 0.41 nu` (peak Hertz pressure at first yield is `K H`).
    pub fn ke_factor(&self) -> f64 {
        0.454 + 0.41 * self.poisson_ratio
    }

    /// Jackson–Green `C = 1.295 exp(0.736 nu)` (peak pressure at first
    /// yield is `C Y`).
    pub fn jg_factor(&self) -> f64 {
        1.295 * (0.736 * self.poisson_ratio).exp()
    }

    /// Critical interference (m) of `variant` for radius `R` (m) and
    /// contact modulus `E*` (Pa):
    /// - KE, CEB: `omega_c = (pi K H / (2 E*))^2 R`, `K = 0.454 + 0.41 nu`;
    /// - JG: `omega_c = (pi C Y / (2 E*))^2 R`, `C = 1.295 exp(0.736 nu)`;
    /// - ZMC: `omega_1 = (3 pi K H / (4 E*))^2 R`, `K = 0.6` (mean pressure
    ///   at first yield `K H`).
    pub fn critical_interference(
        &self,
        variant: Variant,
        radius: f64,
        contact_modulus: f64,
    ) -> f64 {
        let p = match variant {
            Variant::KogutEtsion | Variant::ChangEtsionBogy => {
                PI * self.ke_factor() * self.hardness / 2.0
            }
            Variant::JacksonGreen => PI * self.jg_factor() * self.yield_strength / 2.0,
            Variant::ZhaoMaiettaChang => 0.75 * PI * ZMC_PRESSURE_FACTOR * self.hardness,
        };
        let x = p / contact_modulus;
        x * x * radius
    }
}

/// Zhao–Maietta–Chang mean-pressure factor at first yield, `K = 0.6`
/// (mean pressure `K H` at `omega_1`).
pub const ZMC_PRESSURE_FACTOR: f64 = 0.6;

/// The elastic-plastic law variants (their constants differ).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Variant {
    /// Kogut & Etsion (2002) finite-element fit.
    KogutEtsion,
    /// Jackson & Green (2005) finite-element fit (hardness form
    /// `H_G/S_y = 2.84 (1 - exp(-0.82 (a/R)^-0.7))`).
    JacksonGreen,
    /// Chang, Etsion & Bogy (1987): Hertz, then volume-conserving plastic.
    ChangEtsionBogy,
    /// Zhao, Maietta & Chang (2000): Hertz, log-interpolated mean pressure
    /// and cubic area blend, fully plastic beyond `54 omega_1`.
    ZhaoMaiettaChang,
}

impl Variant {
    /// Every variant.
    pub const ALL: [Variant; 4] = [
        Variant::KogutEtsion,
        Variant::JacksonGreen,
        Variant::ChangEtsionBogy,
        Variant::ZhaoMaiettaChang,
    ];

    /// Scene name (`law.kind`).
    pub fn name(self) -> &'static str {
        match self {
            Variant::KogutEtsion => "kogut-etsion",
            Variant::JacksonGreen => "jackson-green",
            Variant::ChangEtsionBogy => "chang-etsion-bogy",
            Variant::ZhaoMaiettaChang => "zhao-maietta-chang",
        }
    }

    /// Regime limits in units of the variant's critical interference:
    /// `(elastic up to, fully plastic beyond)`. KE: `(1, 110)`; CEB: `(1, 1)`
    /// (no elastic-plastic range: plastic as soon as it yields); ZMC:
    /// `(1, 54)`; JG: `(1.9, inf)` (Hertz up to 1.9; the fit has no fully
    /// plastic limit: its hardness keeps falling with `a/R`).
    pub fn regime_multiples(self) -> (f64, f64) {
        match self {
            Variant::KogutEtsion => (1.0, 110.0),
            Variant::JacksonGreen => (1.9, f64::INFINITY),
            Variant::ChangEtsionBogy => (1.0, 1.0),
            Variant::ZhaoMaiettaChang => (1.0, 54.0),
        }
    }
}

crate::named_enum!(Variant, "law");

/// Deformation regime of one contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Regime {
    /// Not touching (`delta <= 0`).
    Free,
    /// Hertzian: below the law's elastic limit.
    Elastic,
    /// Between the elastic limit and full plasticity.
    ElasticPlastic,
    /// Beyond the law's fully plastic limit.
    FullyPlastic,
}

/// Interference limits (m) between regimes for one law and asperity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegimeLimits {
    /// Largest elastic interference (m).
    pub elastic: f64,
    /// Interference (m) beyond which the contact is fully plastic
    /// (`+inf` when the law has none).
    pub fully_plastic: f64,
}

impl RegimeLimits {
    /// Limits of `variant` for radius `R` (m), contact modulus `E*` (Pa).
    pub fn new(
        variant: Variant,
        plasticity: &Plasticity,
        radius: f64,
        contact_modulus: f64,
    ) -> Self {
        let wc = plasticity.critical_interference(variant, radius, contact_modulus);
        let (e, p) = variant.regime_multiples();
        RegimeLimits {
            elastic: e * wc,
            fully_plastic: p * wc,
        }
    }

    /// The regime of a contact at interference `delta` (m).
    pub fn classify(&self, delta: f64) -> Regime {
        if !(delta > 0.0) {
            Regime::Free
        } else if delta <= self.elastic {
            Regime::Elastic
        } else if delta <= self.fully_plastic {
            Regime::ElasticPlastic
        } else {
            Regime::FullyPlastic
        }
    }
}

/// GW's plasticity index `psi = (E*/H) sqrt(sigma/R)` (Greenwood &
/// Williamson 1966; dimensionless): above about 1 most contacts yield.
/// `E*` (Pa), `H` (Pa), summit-height scale `sigma` (m), summit radius `R`
/// (m).
///
/// # Errors
/// [`Error::OutOfRange`] naming `contact_modulus`, `hardness`, `sigma` or
/// `radius` unless each is finite and > 0.
pub fn plasticity_index(
    contact_modulus: f64,
    hardness: f64,
    sigma: f64,
    radius: f64,
) -> Result<f64> {
    crate::error::positive("contact_modulus", contact_modulus)?;
    crate::error::positive("hardness", hardness)?;
    crate::error::positive("sigma", sigma)?;
    crate::error::positive("radius", radius)?;
    Ok(contact_modulus / hardness * (sigma / radius).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validates_yield_strength_and_hardness() {
        for (y, h, field) in [
            (0.0, None, "yield_strength"),
            (-1.0, None, "yield_strength"),
            (f64::NAN, None, "yield_strength"),
            (f64::INFINITY, None, "yield_strength"),
            (1e9, Some(0.5e9), "hardness"),
            (1e9, Some(f64::NAN), "hardness"),
            (1e9, Some(f64::INFINITY), "hardness"),
        ] {
            let e = Plasticity::new(y, h, 0.3).unwrap_err();
            assert_eq!(e.field(), Some(field), "{y} {h:?}");
        }
        assert_eq!(
            Plasticity::new(1e9, None, 0.5).unwrap_err().field(),
            Some("poisson_ratio")
        );
        let p = Plasticity::new(1e9, None, 0.3).unwrap();
        assert_eq!(p.hardness(), 2.8e9);
        assert_eq!(
            Plasticity::new(1e9, Some(1e9), 0.3).unwrap().hardness(),
            1e9
        );
    }

    #[test]
    fn optional_scene_values() {
        let e = Plasticity::from_optional("kogut-etsion", true, None, None, 0.3).unwrap_err();
        assert_eq!(e.field(), Some("yield_strength"));
        assert!(e.to_string().contains("kogut-etsion"), "{e}");
        let e = Plasticity::from_optional("hertz", false, None, Some(1e9), 0.3).unwrap_err();
        assert_eq!(e.field(), Some("yield_strength"));
        assert_eq!(
            Plasticity::from_optional("hertz", false, None, None, 0.3).unwrap(),
            None
        );
        let e = Plasticity::from_optional("hertz", false, Some(1e9), Some(0.9e9), 0.3).unwrap_err();
        assert_eq!(e.field(), Some("hardness"));
        assert!(
            Plasticity::from_optional("jkr", false, Some(1e9), None, 0.3)
                .unwrap()
                .is_some()
        );
    }

    #[test]
    fn softer_body_yields() {
        let a = Plasticity::new(1e9, None, 0.3).unwrap();
        let b = Plasticity::new(0.4e9, None, 0.42).unwrap();
        assert_eq!(Plasticity::yielding_body(a, b), b);
        assert_eq!(Plasticity::yielding_body(b, a), b);
    }

    #[test]
    fn critical_interference_is_hertz_yield_onset() {
        // KE: the Hertz peak pressure 2 E* sqrt(omega/R)/pi equals K H at omega_c.
        let p = Plasticity::gold();
        let (r, e) = (1e-6, 4.8e10);
        let wc = p.critical_interference(Variant::KogutEtsion, r, e);
        let p0 = 2.0 * e * (wc / r).sqrt() / PI;
        assert!((p0 / (p.ke_factor() * p.hardness()) - 1.0).abs() < 1e-14);
        // ZMC: the Hertz mean pressure (2/3) p0 equals 0.6 H at omega_1.
        let w1 = p.critical_interference(Variant::ZhaoMaiettaChang, r, e);
        let pm = 4.0 * e * (w1 / r).sqrt() / (3.0 * PI);
        assert!((pm / (0.6 * p.hardness()) - 1.0).abs() < 1e-14);
        // JG: peak pressure C Y.
        let wj = p.critical_interference(Variant::JacksonGreen, r, e);
        let p0 = 2.0 * e * (wj / r).sqrt() / PI;
        assert!((p0 / (p.jg_factor() * p.yield_strength()) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn gold_psi_is_about_three_and_regimes_classify() {
        let psi = plasticity_index(4.796e10, Plasticity::gold().hardness(), 5e-9, 1e-6).unwrap();
        assert!((psi - 3.03).abs() < 0.01, "{psi}");
        let l = RegimeLimits::new(Variant::KogutEtsion, &Plasticity::gold(), 1e-6, 4.8e10);
        assert_eq!(l.classify(-1.0), Regime::Free);
        assert_eq!(l.classify(0.5 * l.elastic), Regime::Elastic);
        assert_eq!(l.classify(2.0 * l.elastic), Regime::ElasticPlastic);
        assert_eq!(l.classify(111.0 * l.elastic), Regime::FullyPlastic);
    }
}
