//! Elastic materials, the contact modulus of a pair, adhesion, and the
//! dimensionless numbers that decide which adhesion theory applies.
//!
//! Conventions (Johnson, *Contact Mechanics*; Maugis 1992):
//! - contact modulus `1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2` (Pa),
//! - `K = 4 E*/3` (Pa), the modulus of JKR and Maugis' papers,
//! - effective radius `1/R = 1/R1 + 1/R2` (m),
//! - Tabor parameter `mu = (R w^2 / (E*^2 z0^3))^(1/3)`,
//! - Maugis parameter `lambda = 2 sigma0 (R / (pi w K^2))^(1/3)`.

pub mod gold;
pub mod plastic;

use crate::error::{non_negative, positive, Allowed, Result};
use std::f64::consts::PI;

/// `lambda / mu` when the Dugdale stress equals the Lennard-Jones maximum
/// tension `sigma0 = 16 w / (9 sqrt(3) z0)`:
/// `(32 / (9 sqrt 3)) (9 / (16 pi))^(1/3) = 1.157011634850799...`
/// (mpmath, 30 digits). Johnson & Greenwood (1997) quote 1.1570.
pub const LAMBDA_PER_TABOR: f64 = 1.157_011_634_850_799_3;

/// `sigma0 z0 / w` for the Lennard-Jones (Derjaguin 9-3) law:
/// `16 / (9 sqrt 3) = 1.0264004785593347`.
pub const LJ_MAX_TENSION_FACTOR: f64 = 1.026_400_478_559_334_7;

/// An isotropic linear-elastic material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    youngs_modulus: f64,
    poisson_ratio: f64,
}

impl Material {
    /// A material with Young's modulus `e` (Pa, finite and > 0) and Poisson
    /// ratio `nu` (in `[0, 0.5)`).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `youngs_modulus` or `poisson_ratio`.
    pub fn new(youngs_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        positive("youngs_modulus", youngs_modulus)?;
        Allowed::closed_open(0.0, 0.5).check("poisson_ratio", poisson_ratio)?;
        Ok(Material {
            youngs_modulus,
            poisson_ratio,
        })
    }

    /// Gold: `E = 79 GPa`, `nu = 0.42` (the default microswitch material,
    /// [`gold`]).
    pub fn gold() -> Self {
        Material {
            youngs_modulus: gold::YOUNGS_MODULUS,
            poisson_ratio: gold::POISSON_RATIO,
        }
    }

    /// Young's modulus `E` (Pa).
    pub fn youngs_modulus(&self) -> f64 {
        self.youngs_modulus
    }

    /// Poisson ratio `nu`.
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }

    /// Plane-strain modulus `E / (1 - nu^2)` (Pa).
    pub fn plane_strain_modulus(&self) -> f64 {
        self.youngs_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }
}

/// Contact modulus of a pair, `E* = [ (1-nu1^2)/E1 + (1-nu2^2)/E2 ]^-1` (Pa).
///
/// Two identical materials give `E / (2 (1 - nu^2))`.
pub fn contact_modulus(a: &Material, b: &Material) -> f64 {
    1.0 / (1.0 / a.plane_strain_modulus() + 1.0 / b.plane_strain_modulus())
}

/// Effective radius of two curved bodies, `R = (1/R1 + 1/R2)^-1` (m).
/// Pass `f64::INFINITY` for a flat.
///
/// # Errors
/// Each radius must be > 0 (infinity allowed for a flat); not both flat.
pub fn effective_radius(r1: f64, r2: f64) -> Result<f64> {
    for (name, r) in [("radius_1", r1), ("radius_2", r2)] {
        if !(r > 0.0) {
            return Err(crate::Error::OutOfRange {
                name: name.into(),
                value: r,
                allowed: Allowed::open(0.0, f64::INFINITY),
            });
        }
    }
    let inv = 1.0 / r1 + 1.0 / r2;
    if inv == 0.0 {
        return Err(crate::Error::invalid(
            "radius",
            "both bodies are flat: the effective radius is infinite",
        ));
    }
    Ok(1.0 / inv)
}

/// Surface interaction: work of adhesion and range of the surface force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Adhesion {
    work: f64,
    range: f64,
}

impl Adhesion {
    /// Work of adhesion `w` (Dupre energy, J/m^2, >= 0; 0 means no adhesion)
    /// and equilibrium separation `z0` of the Lennard-Jones law (m, > 0).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `work_of_adhesion` or `z0`.
    pub fn new(work: f64, range: f64) -> Result<Self> {
        non_negative("work_of_adhesion", work)?;
        positive("z0", range)?;
        Ok(Adhesion { work, range })
    }

    /// Work of adhesion `w` (J/m^2).
    pub fn work(&self) -> f64 {
        self.work
    }

    /// Equilibrium separation `z0` (m).
    pub fn range(&self) -> f64 {
        self.range
    }

    /// Maximum tension of the Lennard-Jones law, used as the Dugdale stress:
    /// `sigma0 = 16 w / (9 sqrt(3) z0) = 1.0264 w / z0` (Pa).
    pub fn dugdale_stress(&self) -> f64 {
        LJ_MAX_TENSION_FACTOR * self.work / self.range
    }

    /// Dugdale range `delta_t = w / sigma0 = 9 sqrt(3) z0 / 16 = 0.9743 z0` (m).
    pub fn dugdale_range(&self) -> f64 {
        self.range / LJ_MAX_TENSION_FACTOR
    }
}

/// Tabor parameter `mu = (R w^2 / (E*^2 z0^3))^(1/3)` (dimensionless):
/// elastic deformation at pull-off over the range of the surface force.
pub fn tabor_parameter(radius: f64, contact_modulus: f64, adhesion: &Adhesion) -> f64 {
    let w = adhesion.work();
    let z0 = adhesion.range();
    (radius * w * w / (contact_modulus * contact_modulus * z0 * z0 * z0)).cbrt()
}

/// The exponents of the Tabor parameter in its inputs,
/// `mu = R^(1/3) w^(2/3) E*^(-2/3) z0^(-1)` ([`tabor_parameter`]): each
/// input's share of `ln mu` is its exponent times its logarithm, which
/// tells which input drives `mu` (and the Maugis `lambda = 1.1570 mu`) out
/// of range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TaborExponents {
    /// Of the summit radius `R`.
    pub radius: f64,
    /// Of the work of adhesion `w`.
    pub work: f64,
    /// Of the contact modulus `E*`.
    pub contact_modulus: f64,
    /// Of the force range `z0`.
    pub range: f64,
}

/// [`TaborExponents`] of `mu = (R w^2 / (E*^2 z0^3))^(1/3)`.
pub const TABOR_EXPONENTS: TaborExponents = TaborExponents {
    radius: 1.0 / 3.0,
    work: 2.0 / 3.0,
    contact_modulus: -2.0 / 3.0,
    range: -1.0,
};

/// Maugis parameter from a Dugdale stress:
/// `lambda = 2 sigma0 (R / (pi w K^2))^(1/3)`, `K = 4 E*/3` (dimensionless).
/// Returns `+inf` when `w = 0`.
pub fn maugis_lambda(radius: f64, contact_modulus: f64, work: f64, dugdale_stress: f64) -> f64 {
    let k = 4.0 * contact_modulus / 3.0;
    2.0 * dugdale_stress * (radius / (PI * work * k * k)).cbrt()
}

/// Maugis parameter matched to a Tabor parameter: `lambda = 1.1570 mu`
/// ([`LAMBDA_PER_TABOR`]).
pub fn lambda_from_tabor(mu: f64) -> f64 {
    LAMBDA_PER_TABOR * mu
}

/// One spherical asperity of radius `R` against a flat: the inputs every
/// single-asperity law needs, validated once.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AsperityContact {
    /// Effective radius `R` (m).
    pub radius: f64,
    /// Contact modulus `E*` (Pa).
    pub contact_modulus: f64,
    /// Work of adhesion and force range.
    pub adhesion: Adhesion,
}

impl AsperityContact {
    /// Validates `radius > 0` (m) and `contact_modulus > 0` (Pa).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `radius` or `contact_modulus`.
    pub fn new(radius: f64, contact_modulus: f64, adhesion: Adhesion) -> Result<Self> {
        positive("radius", radius)?;
        positive("contact_modulus", contact_modulus)?;
        Ok(AsperityContact {
            radius,
            contact_modulus,
            adhesion,
        })
    }

    /// The default gold-on-gold microswitch asperity: `R = 1 um`,
    /// `E = 79 GPa`, `nu = 0.42` on both sides, `w = 0.5 J/m^2`, `z0 = 0.3 nm`.
    pub fn gold_microswitch() -> Self {
        let g = Material::gold();
        AsperityContact {
            radius: gold::SUMMIT_RADIUS,
            contact_modulus: contact_modulus(&g, &g),
            adhesion: Adhesion {
                work: gold::WORK_OF_ADHESION,
                range: gold::FORCE_RANGE,
            },
        }
    }

    /// Tabor parameter `mu` of this contact.
    pub fn tabor(&self) -> f64 {
        tabor_parameter(self.radius, self.contact_modulus, &self.adhesion)
    }

    /// Maugis `lambda` with the Dugdale stress matched to the Lennard-Jones
    /// maximum tension (`lambda = 1.1570 mu`).
    pub fn lambda(&self) -> f64 {
        maugis_lambda(
            self.radius,
            self.contact_modulus,
            self.adhesion.work(),
            self.adhesion.dugdale_stress(),
        )
    }

    /// Maugis' scales for this contact.
    ///
    /// # Errors
    /// When `w = 0` (there is no adhesive scale).
    pub fn scales(&self) -> Result<MaugisScales> {
        MaugisScales::new(self.radius, self.contact_modulus, self.adhesion.work())
    }
}

/// Maugis' (1992) normalisation of a sphere-on-flat adhesive contact:
/// `A = a / (pi w R^2 / K)^(1/3)`, `Pbar = P / (pi w R)`,
/// `Dbar = delta / (pi^2 w^2 R / K^2)^(1/3)`, with `K = 4 E*/3`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaugisScales {
    /// Radius scale `(pi w R^2 / K)^(1/3)` (m).
    pub radius: f64,
    /// Load scale `pi w R` (N).
    pub load: f64,
    /// Interference scale `(pi^2 w^2 R / K^2)^(1/3)` (m).
    pub interference: f64,
}

impl MaugisScales {
    /// Scales for radius `R` (m), contact modulus `E*` (Pa) and work of
    /// adhesion `w` (J/m^2), all finite and > 0.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming the bad argument.
    pub fn new(radius: f64, contact_modulus: f64, work: f64) -> Result<Self> {
        positive("radius", radius)?;
        positive("contact_modulus", contact_modulus)?;
        positive("work_of_adhesion", work)?;
        let k = 4.0 * contact_modulus / 3.0;
        Ok(MaugisScales {
            radius: (PI * work * radius * radius / k).cbrt(),
            load: PI * work * radius,
            interference: (PI * PI * work * work * radius / (k * k)).cbrt(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contact_modulus_of_identical_pair() {
        let g = Material::gold();
        let es = contact_modulus(&g, &g);
        let expect = 79e9 / (2.0 * (1.0 - 0.42 * 0.42));
        assert!((es / expect - 1.0).abs() < 1e-15);
    }

    #[test]
    fn rigid_partner_limit() {
        // A very stiff partner leaves the soft body's plane-strain modulus.
        let soft = Material::new(1e6, 0.3).unwrap();
        let hard = Material::new(1e20, 0.3).unwrap();
        let es = contact_modulus(&soft, &hard);
        assert!((es / soft.plane_strain_modulus() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn material_rejects_bad_input() {
        for (e, nu, field) in [
            (-1.0, 0.3, "youngs_modulus"),
            (0.0, 0.3, "youngs_modulus"),
            (f64::NAN, 0.3, "youngs_modulus"),
            (f64::INFINITY, 0.3, "youngs_modulus"),
            (1e9, 0.5, "poisson_ratio"),
            (1e9, 0.7, "poisson_ratio"),
            (1e9, -0.1, "poisson_ratio"),
            (1e9, f64::NAN, "poisson_ratio"),
        ] {
            let err = Material::new(e, nu).unwrap_err();
            assert_eq!(err.field(), Some(field), "{e} {nu}");
        }
    }

    #[test]
    fn adhesion_rejects_bad_input() {
        assert_eq!(
            Adhesion::new(-0.1, 1e-9).unwrap_err().field(),
            Some("work_of_adhesion")
        );
        assert_eq!(Adhesion::new(0.1, 0.0).unwrap_err().field(), Some("z0"));
        assert_eq!(
            Adhesion::new(f64::NAN, 1e-9).unwrap_err().field(),
            Some("work_of_adhesion")
        );
        assert!(Adhesion::new(0.0, 1e-9).is_ok());
    }

    #[test]
    fn effective_radius_cases() {
        assert_eq!(effective_radius(2.0, 2.0).unwrap(), 1.0);
        assert_eq!(effective_radius(1.5, f64::INFINITY).unwrap(), 1.5);
        assert!(effective_radius(f64::INFINITY, f64::INFINITY).is_err());
        assert!(effective_radius(-1.0, 1.0).is_err());
        assert!(effective_radius(f64::NAN, 1.0).is_err());
    }

    #[test]
    fn lambda_is_1_157_mu_for_lennard_jones_dugdale_stress() {
        // Independent of R, E*, w, z0: check over several decades.
        for &(r, e, w, z0) in &[
            (1e-6, 2.1e10, 0.5, 3e-10),
            (1e-3, 1e6, 0.05, 1e-9),
            (1e-8, 1e11, 2.0, 2e-10),
        ] {
            let c = AsperityContact::new(r, e, Adhesion::new(w, z0).unwrap()).unwrap();
            let ratio = c.lambda() / c.tabor();
            assert!((ratio - LAMBDA_PER_TABOR).abs() < 1e-14, "{ratio}");
        }
        // The closed form of the constant.
        let exact = 32.0 / (9.0 * 3f64.sqrt()) * (9.0 / (16.0 * PI)).cbrt();
        assert!((exact - LAMBDA_PER_TABOR).abs() < 1e-15);
        assert!((LJ_MAX_TENSION_FACTOR - 16.0 / (9.0 * 3f64.sqrt())).abs() < 1e-15);
    }

    #[test]
    fn gold_microswitch_numbers() {
        let c = AsperityContact::gold_microswitch();
        // E* = 79e9 / (2 (1 - 0.42^2)) = 47.96 GPa
        assert!((c.contact_modulus / 4.796_017_484_215_639e10 - 1.0).abs() < 1e-12);
        // mu = (1e-6 * 0.25 / (E*^2 * 2.7e-29))^(1/3)
        let mu = (1e-6 * 0.25 / (c.contact_modulus.powi(2) * 2.7e-29)).cbrt();
        assert!((c.tabor() / mu - 1.0).abs() < 1e-14);
        assert!(c.tabor() > 1.0 && c.tabor() < 2.0, "{}", c.tabor());
    }

    #[test]
    fn maugis_scales_match_definitions() {
        let s = MaugisScales::new(2.0, 3.0, 0.7).unwrap();
        let k = 4.0;
        assert!((s.radius.powi(3) - PI * 0.7 * 4.0 / k).abs() < 1e-14);
        assert!((s.load - PI * 0.7 * 2.0).abs() < 1e-14);
        assert!((s.interference.powi(3) - PI * PI * 0.49 * 2.0 / (k * k)).abs() < 1e-14);
        assert!(MaugisScales::new(1.0, 1.0, 0.0).is_err());
    }
}
