//! Axisymmetric indenter profiles `f(r)` (m; `f(0) = 0`, the gap between
//! the undeformed bodies at radius `r` when the apexes touch) and their
//! non-adhesive (Sneddon) contact: the interference `delta_0(a)` and load
//! `F_0(a)` at contact radius `a`.
//!
//! Sneddon (1965), in Barthel's form (Barthel 2008, eqs 4.8, 4.14) with
//! `calK = E*/2`:
//!
//! ```text
//! delta_0(a) = a int_0^a f'(r) dr / sqrt(a^2 - r^2)   = a int_0^(pi/2) f'(a sin u) du
//! F_0(a)     = 2 E* int_0^a r^2 f'(r) dr / sqrt(a^2 - r^2)  (= 4 calK (a delta_0 - phi_0))
//! ```
//!
//! so [`Profile::load_area`] is `F_0 / (2 E*)` (m^2). Closed forms:
//!
//! | profile | `f(r)` | `delta_0(a)` | `F_0(a) / (2E*)` |
//! |---|---|---|---|
//! | paraboloid | `r^2/(2R)` | `a^2/R` | `2a^3/(3R)` |
//! | sphere | `R - sqrt(R^2 - r^2)` | `a atanh(a/R)` | `((a^2+R^2) atanh(a/R) - aR)/2` |
//! | cone | `r tan(beta)` | `(pi/2) a tan(beta)` | `(pi/4) a^2 tan(beta)` |
//! | flat punch | `0` for `r <= a0` | `0` | `0` (contact radius fixed at `a0`, stiffness `2 E* a0`) |
//! | power law | `A r^n` | `k_n A a^n` | `k_n A n a^(n+1)/(n+1)` |
//!
//! with `k_n = n sqrt(pi) Gamma(n/2) / (2 Gamma((n+1)/2))` (Steuermann;
//! Greenwood 2009, appendix 2): `k_1 = pi/2`, `k_2 = 2`. A tabulated
//! profile is interpolated by PCHIP and integrated by Gauss–Kronrod on the
//! pieces between nodes (see [`super::tabulated`]).

use super::tabulated::TabulatedProfile;
use crate::error::{positive, Error, Result};
use crate::special::gamma::gamma;
use std::f64::consts::PI;

/// An axisymmetric profile. Built by the validating constructors.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Profile {
    /// `f = r^2/(2R)`: the Hertz paraboloid of radius `R` (m).
    Paraboloid {
        /// Radius of curvature at the apex (m).
        radius: f64,
    },
    /// `f = R - sqrt(R^2 - r^2)`: the true sphere of radius `R` (m); contact
    /// radii must stay below `R`.
    Sphere {
        /// Sphere radius (m).
        radius: f64,
    },
    /// `f = r tan(beta)`: a cone whose flank makes angle `beta` with the flat.
    Cone {
        /// `tan(beta)` (dimensionless, > 0).
        tan_angle: f64,
    },
    /// A flat-ended cylindrical punch of radius `a0` (m).
    Flat {
        /// Punch radius (m).
        radius: f64,
    },
    /// `f = A r^n`.
    Power {
        /// `A` (m^(1-n)).
        coefficient: f64,
        /// `n` (> 0).
        exponent: f64,
        /// `k_n A` (m^(1-n)), cached.
        k_coefficient: f64,
    },
    /// A measured profile, PCHIP-interpolated.
    Tabulated(TabulatedProfile),
}

/// The kinds of [`Profile`], by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ProfileKind {
    /// [`Profile::Paraboloid`].
    Paraboloid,
    /// [`Profile::Sphere`].
    Sphere,
    /// [`Profile::Cone`].
    Cone,
    /// [`Profile::Flat`].
    Flat,
    /// [`Profile::Power`].
    Power,
    /// [`Profile::Tabulated`].
    Tabulated,
}

impl ProfileKind {
    /// Every kind.
    pub const ALL: [ProfileKind; 6] = [
        ProfileKind::Paraboloid,
        ProfileKind::Sphere,
        ProfileKind::Cone,
        ProfileKind::Flat,
        ProfileKind::Power,
        ProfileKind::Tabulated,
    ];

    /// Short name: `paraboloid`, `sphere`, `cone`, `flat`, `power`, `tabulated`.
    pub fn name(self) -> &'static str {
        match self {
            ProfileKind::Paraboloid => "paraboloid",
            ProfileKind::Sphere => "sphere",
            ProfileKind::Cone => "cone",
            ProfileKind::Flat => "flat",
            ProfileKind::Power => "power",
            ProfileKind::Tabulated => "tabulated",
        }
    }

    /// The parameters the kind is built from, by their argument names in
    /// the constructors ([`Profile::paraboloid`], ...): `radius`;
    /// `tan_angle`; `exponent`, `coefficient`; `r`, `f`.
    pub fn parameters(self) -> &'static [&'static str] {
        match self {
            ProfileKind::Paraboloid | ProfileKind::Sphere | ProfileKind::Flat => &["radius"],
            ProfileKind::Cone => &["tan_angle"],
            ProfileKind::Power => &["exponent", "coefficient"],
            ProfileKind::Tabulated => &["r", "f"],
        }
    }
}

/// The parameters of a profile; each kind uses some of them
/// ([`ProfileKind::parameters`]).
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct ProfileParams {
    /// Radius (m) of a paraboloid, sphere or flat punch.
    pub radius: Option<f64>,
    /// `tan(beta)` of a cone.
    pub tan_angle: Option<f64>,
    /// Exponent `n` of a power law.
    pub exponent: Option<f64>,
    /// Coefficient `A` (m^(1-n)) of a power law.
    pub coefficient: Option<f64>,
    /// Radii (m) of a tabulated profile.
    pub r: Option<Vec<f64>>,
    /// Heights (m) of a tabulated profile at `r`.
    pub f: Option<Vec<f64>>,
}

impl ProfileParams {
    /// The parameters given, by name.
    pub fn given(&self) -> Vec<&'static str> {
        [
            ("radius", self.radius.is_some()),
            ("tan_angle", self.tan_angle.is_some()),
            ("exponent", self.exponent.is_some()),
            ("coefficient", self.coefficient.is_some()),
            ("r", self.r.is_some()),
            ("f", self.f.is_some()),
        ]
        .into_iter()
        .filter_map(|(n, g)| g.then_some(n))
        .collect()
    }
}

impl ProfileKind {
    /// Builds the profile from `p`.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming a parameter the kind needs and `p` lacks,
    /// or one it does not use (it would be silently ignored); the
    /// constructor's [`Error::OutOfRange`] for a bad value.
    pub fn build(self, p: &ProfileParams) -> Result<Profile> {
        let uses = self.parameters();
        if let Some(k) = p.given().into_iter().find(|k| !uses.contains(k)) {
            return Err(Error::invalid(
                k,
                format!(
                    "does not apply to profile {:?} (it uses {})",
                    self.name(),
                    uses.join(", ")
                ),
            ));
        }
        let need = |name: &str, x: Option<f64>| {
            x.ok_or_else(|| Error::invalid(name, format!("required for profile {:?}", self.name())))
        };
        match self {
            ProfileKind::Paraboloid => Profile::paraboloid(need("radius", p.radius)?),
            ProfileKind::Sphere => Profile::sphere(need("radius", p.radius)?),
            ProfileKind::Flat => Profile::flat(need("radius", p.radius)?),
            ProfileKind::Cone => Profile::cone(need("tan_angle", p.tan_angle)?),
            ProfileKind::Power => Profile::power(
                need("coefficient", p.coefficient)?,
                need("exponent", p.exponent)?,
            ),
            ProfileKind::Tabulated => {
                let missing =
                    |n: &str| Error::invalid(n, "required for profile \"tabulated\"".to_string());
                let r = p.r.clone().ok_or_else(|| missing("r"))?;
                let f = p.f.clone().ok_or_else(|| missing("f"))?;
                Profile::tabulated(r, f)
            }
        }
    }
}

crate::named_enum!(ProfileKind, "profile");

/// `k_n = n sqrt(pi) Gamma(n/2) / (2 Gamma((n+1)/2))`: `delta_0 = k_n A a^n`
/// for `f = A r^n`.
pub fn power_law_factor(n: f64) -> f64 {
    n * PI.sqrt() * gamma(0.5 * n) / (2.0 * gamma(0.5 * (n + 1.0)))
}

impl Profile {
    /// Paraboloid `r^2/(2R)`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `radius` unless finite and > 0.
    pub fn paraboloid(radius: f64) -> Result<Self> {
        Ok(Profile::Paraboloid {
            radius: positive("radius", radius)?,
        })
    }

    /// True sphere `R - sqrt(R^2 - r^2)`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `radius` unless finite and > 0.
    pub fn sphere(radius: f64) -> Result<Self> {
        Ok(Profile::Sphere {
            radius: positive("radius", radius)?,
        })
    }

    /// Cone `r tan(beta)`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `tan_angle` unless finite and > 0.
    pub fn cone(tan_angle: f64) -> Result<Self> {
        Ok(Profile::Cone {
            tan_angle: positive("tan_angle", tan_angle)?,
        })
    }

    /// Flat punch of radius `a0` (m).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `radius` unless finite and > 0.
    pub fn flat(radius: f64) -> Result<Self> {
        Ok(Profile::Flat {
            radius: positive("radius", radius)?,
        })
    }

    /// Power law `A r^n`, `n` in `(0, 50]`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `exponent` or `coefficient`.
    pub fn power(coefficient: f64, exponent: f64) -> Result<Self> {
        crate::error::Allowed {
            lo: 0.0,
            lo_inclusive: false,
            hi: 50.0,
            hi_inclusive: true,
        }
        .check("exponent", exponent)?;
        let coefficient = positive("coefficient", coefficient)?;
        Ok(Profile::Power {
            coefficient,
            exponent,
            k_coefficient: power_law_factor(exponent) * coefficient,
        })
    }

    /// Tabulated profile from columns `r` (m) and `f(r)` (m); see
    /// [`TabulatedProfile::new`] for the validation.
    ///
    /// # Errors
    /// As [`TabulatedProfile::new`].
    pub fn tabulated(r: Vec<f64>, f: Vec<f64>) -> Result<Self> {
        Ok(Profile::Tabulated(TabulatedProfile::new(r, f)?))
    }

    /// The profile's kind.
    pub fn kind(&self) -> ProfileKind {
        match self {
            Profile::Paraboloid { .. } => ProfileKind::Paraboloid,
            Profile::Sphere { .. } => ProfileKind::Sphere,
            Profile::Cone { .. } => ProfileKind::Cone,
            Profile::Flat { .. } => ProfileKind::Flat,
            Profile::Power { .. } => ProfileKind::Power,
            Profile::Tabulated(_) => ProfileKind::Tabulated,
        }
    }

    /// Short name ([`ProfileKind::name`]).
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }

    /// Largest admissible contact radius (m): `R` for the sphere (excluded),
    /// `a0` for the flat punch (included), the last node of a table, `inf`
    /// otherwise.
    pub fn max_radius(&self) -> f64 {
        match self {
            Profile::Sphere { radius } | Profile::Flat { radius } => *radius,
            Profile::Tabulated(t) => t.max_radius(),
            _ => f64::INFINITY,
        }
    }

    /// Checks a contact radius `a` (m): finite, >= 0 and within
    /// [`max_radius`](Profile::max_radius) (below it for the sphere).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `name`.
    pub fn check_radius(&self, name: &str, a: f64) -> Result<f64> {
        let max = self.max_radius();
        let ok = a.is_finite()
            && a >= 0.0
            && match self {
                Profile::Sphere { .. } => a < max,
                _ => a <= max,
            };
        if ok {
            Ok(a)
        } else {
            Err(Error::invalid(
                name,
                format!(
                    "contact radius {a} m must be finite, >= 0 and {} the {} radius {max} m",
                    if matches!(self, Profile::Sphere { .. }) {
                        "below"
                    } else {
                        "at most"
                    },
                    self.name()
                ),
            ))
        }
    }

    /// Height `f(r)` (m) of the profile above its apex.
    pub fn height(&self, r: f64) -> f64 {
        match self {
            Profile::Paraboloid { radius } => r * r / (2.0 * radius),
            Profile::Sphere { radius } => {
                // R - sqrt(R^2 - r^2) without cancellation.
                let s = (radius * radius - r * r).max(0.0).sqrt();
                r * r / (radius + s)
            }
            Profile::Cone { tan_angle } => r * tan_angle,
            Profile::Flat { radius } => {
                if r <= *radius {
                    0.0
                } else {
                    f64::INFINITY
                }
            }
            Profile::Power {
                coefficient,
                exponent,
                ..
            } => coefficient * r.powf(*exponent),
            Profile::Tabulated(t) => t.height(r),
        }
    }

    /// Slope `f'(r)` (dimensionless) of the profile; `0` on the flat punch
    /// (its wall beyond `a0` has no slope).
    pub fn slope(&self, r: f64) -> f64 {
        match self {
            Profile::Paraboloid { radius } => r / radius,
            Profile::Sphere { radius } => r / (radius * radius - r * r).max(0.0).sqrt(),
            Profile::Cone { tan_angle } => *tan_angle,
            Profile::Flat { .. } => 0.0,
            Profile::Power {
                coefficient,
                exponent,
                ..
            } => coefficient * exponent * r.powf(exponent - 1.0),
            Profile::Tabulated(t) => t.derivatives(r).0,
        }
    }

    /// Non-adhesive interference `delta_0(a)` (m) at contact radius `a` (m).
    pub fn delta0(&self, a: f64) -> f64 {
        match self {
            Profile::Paraboloid { radius } => a * a / radius,
            Profile::Sphere { radius } => a * (a / radius).atanh(),
            Profile::Cone { tan_angle } => 0.5 * PI * a * tan_angle,
            Profile::Flat { .. } => 0.0,
            Profile::Power {
                exponent,
                k_coefficient,
                ..
            } => k_coefficient * a.powf(*exponent),
            Profile::Tabulated(t) => t.delta0(a),
        }
    }

    /// Slope `d delta_0 / da` (dimensionless).
    pub fn delta0_slope(&self, a: f64) -> f64 {
        match self {
            Profile::Paraboloid { radius } => 2.0 * a / radius,
            Profile::Sphere { radius } => {
                let x = a / radius;
                x.atanh() + x / (1.0 - x * x)
            }
            Profile::Cone { tan_angle } => 0.5 * PI * tan_angle,
            Profile::Flat { .. } => 0.0,
            Profile::Power {
                exponent,
                k_coefficient,
                ..
            } => exponent * k_coefficient * a.powf(exponent - 1.0),
            Profile::Tabulated(t) => t.delta0_slope(a),
        }
    }

    /// `F_0(a) / (2 E*) = int_0^a r^2 f'(r) dr / sqrt(a^2 - r^2)` (m^2): the
    /// non-adhesive load per `2 E*`.
    pub fn load_area(&self, a: f64) -> f64 {
        match self {
            Profile::Paraboloid { radius } => 2.0 * a * a * a / (3.0 * radius),
            Profile::Sphere { radius } => sphere_load_area(a, *radius),
            Profile::Cone { tan_angle } => 0.25 * PI * a * a * tan_angle,
            Profile::Flat { .. } => 0.0,
            Profile::Power {
                exponent,
                k_coefficient,
                ..
            } => k_coefficient * exponent * a.powf(exponent + 1.0) / (exponent + 1.0),
            Profile::Tabulated(t) => t.load_area(a),
        }
    }

    /// Non-adhesive (Sneddon) load `F_0(a) = 2 E* load_area(a)` (N) for
    /// contact modulus `E*` (Pa).
    pub fn load0(&self, a: f64, contact_modulus: f64) -> f64 {
        2.0 * contact_modulus * self.load_area(a)
    }

    /// Apex radius of curvature `1/f''(0)` (m) when the profile has a finite
    /// non-zero one (paraboloid, sphere, power law with `n = 2`); DMT needs it.
    pub fn apex_radius(&self) -> Option<f64> {
        match self {
            Profile::Paraboloid { radius } | Profile::Sphere { radius } => Some(*radius),
            Profile::Power {
                coefficient,
                exponent,
                ..
            } if *exponent == 2.0 => Some(0.5 / coefficient),
            _ => None,
        }
    }
}

/// `((a^2+R^2) atanh(x) - aR)/2`, `x = a/R`, for the true sphere; the series
/// `2 R^2 sum_k k x^(2k+1)/(4k^2-1)` below `x = 0.3`, where the closed form
/// cancels (relative loss `eps/x^2`).
fn sphere_load_area(a: f64, r: f64) -> f64 {
    let x = a / r;
    if x < 0.3 {
        let x2 = x * x;
        let mut term = x * x2; // x^(2k+1)
        let mut sum = 0.0;
        for k in 1..80 {
            let kf = k as f64;
            let add = kf * term / (4.0 * kf * kf - 1.0);
            sum += add;
            if add < 1e-17 * sum {
                break;
            }
            term *= x2;
        }
        2.0 * r * r * sum
    } else {
        0.5 * ((a * a + r * r) * x.atanh() - a * r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_law_factor_matches_paraboloid_and_cone() {
        assert!((power_law_factor(2.0) - 2.0).abs() < 1e-15);
        assert!((power_law_factor(1.0) - 0.5 * PI).abs() < 1e-15);
        // k_4 = 4 sqrt(pi) Gamma(2) / (2 Gamma(5/2)) = 8/3.
        assert!((power_law_factor(4.0) - 8.0 / 3.0).abs() < 1e-15);
    }

    #[test]
    fn sphere_series_and_closed_form_agree_at_the_switch() {
        let r = 2e-6;
        let (a, b) = (0.3 * r * (1.0 - 1e-16), 0.3 * r);
        let s = sphere_load_area(a, r);
        let c = sphere_load_area(b, r);
        assert!((s / c - 1.0).abs() < 1e-13, "{s} {c}");
        // Small x: F_0/(2E*) -> 2a^3/(3R).
        let a = 1e-4 * r;
        let hertz = 2.0 * a * a * a / (3.0 * r);
        assert!((sphere_load_area(a, r) / hertz - 1.0).abs() < 1e-8);
    }

    #[test]
    fn constructors_name_their_parameter() {
        assert_eq!(Profile::cone(0.0).unwrap_err().field(), Some("tan_angle"));
        assert_eq!(
            Profile::power(1.0, -1.0).unwrap_err().field(),
            Some("exponent")
        );
        assert_eq!(
            Profile::power(0.0, 2.0).unwrap_err().field(),
            Some("coefficient")
        );
        assert_eq!(
            Profile::sphere(f64::NAN).unwrap_err().field(),
            Some("radius")
        );
        let s = Profile::sphere(1.0).unwrap();
        assert!(s.check_radius("radii", 1.0).is_err());
        assert!(s.check_radius("radii", 0.99).is_ok());
        let f = Profile::flat(1.0).unwrap();
        assert!(f.check_radius("radii", 1.0).is_ok());
        assert_eq!(
            f.check_radius("radii", 1.1).unwrap_err().field(),
            Some("radii")
        );
    }
}
