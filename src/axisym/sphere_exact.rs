//! The exact (true) sphere `f = R - sqrt(R^2 - r^2)` in JKR adhesion:
//! Maugis (1995), *Langmuir* 11, 679; Greenwood (2009), appendix 2.
//! With `x = a/R`:
//!
//! ```text
//! delta = a atanh(x) - sqrt(2 pi w a/E*)            (= (a/2) ln((1+x)/(1-x)) - ...)
//! P     = (E*/2) [(a^2+R^2) ln((R+a)/(R-a)) - 2aR] - sqrt(8 pi E* w a^3)
//! ```
//!
//! These are [`super::jkr::AxisymJkr`] with [`Profile::Sphere`]; this module
//! gives them as standalone closed forms (the independent check of the
//! general route) and the validity warning: linear elasticity and the
//! small-strain boundary conditions fail once `a/R` exceeds about
//! [`RATIO_WARNING`] (Greenwood 2009: "the Hertzian analysis ... fails
//! when the contact radius exceeds about 0.3 R"). As `w/(E* R) -> 0` the
//! instabilities move to `a/R -> 0` and the sphere tends to the paraboloid
//! (relative difference `O((w/(E* R))^(2/3))`).
//!
//! The Lin & Chen (2006) large-strain correction (neo-Hookean finite-element
//! fit `P = (E* a^3/R) phi(a/R)`, `phi` an exponential of a quadratic in
//! `a/R`) is not implemented: the fit's constants are lost in the seed's
//! text extraction (Greenwood 2009, appendix 3) and the original paper was not
//! reachable; see docs/physics.md.

use super::profile::Profile;
use std::f64::consts::PI;

/// `a/R` above which results carry a warning.
pub const RATIO_WARNING: f64 = 0.3;

/// Maugis' interference `a atanh(a/R) - sqrt(2 pi w a/E*)` (m) for contact
/// radius `a` (m, `< R`), sphere radius `R` (m), `E*` (Pa), `w` (J/m^2).
pub fn interference(a: f64, radius: f64, contact_modulus: f64, work: f64) -> f64 {
    0.5 * a * ((radius + a) / (radius - a)).ln() - (2.0 * PI * work * a / contact_modulus).sqrt()
}

/// Maugis' load `(E*/2)[(a^2+R^2) ln((R+a)/(R-a)) - 2aR] - sqrt(8 pi E* w a^3)` (N).
/// The bracket cancels for `a << R` (relative loss `eps (R/a)^2`):
/// [`Profile::load0`] of [`Profile::Sphere`] uses a series there.
pub fn load(a: f64, radius: f64, contact_modulus: f64, work: f64) -> f64 {
    let bracket = (a * a + radius * radius) * ((radius + a) / (radius - a)).ln() - 2.0 * a * radius;
    0.5 * contact_modulus * bracket - (8.0 * PI * contact_modulus * work * a * a * a).sqrt()
}

/// The warning for a contact radius `a` on a sphere of radius `R`, when
/// `a/R > 0.3`.
pub fn ratio_warning(what: &str, a: f64, radius: f64) -> Option<String> {
    let x = a / radius;
    (x > RATIO_WARNING).then(|| {
        format!(
            "{what}: contact radius a/R = {x:.3} exceeds {RATIO_WARNING}; the exact-sphere \
             (small-strain) solution is unreliable there (large strains, Lin & Chen)"
        )
    })
}

/// Warnings for every contact radius of `profile` above the limit (only the
/// true sphere has one).
pub fn warnings(profile: &Profile, radii: &[(&str, f64)]) -> Vec<String> {
    match profile {
        Profile::Sphere { radius } => radii
            .iter()
            .filter_map(|(what, a)| ratio_warning(what, *a, *radius))
            .collect(),
        _ => Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::axisym::jkr::AxisymJkr;

    #[test]
    fn closed_forms_match_the_general_route() {
        let (r, e, w) = (1e-6, 1e9, 0.5);
        let j = AxisymJkr::new(Profile::sphere(r).unwrap(), e, w).unwrap();
        for x in [0.05, 0.3, 0.6, 0.9] {
            let a = x * r;
            let (d1, d2) = (interference(a, r, e, w), j.interference(a));
            assert!((d1 - d2).abs() < 1e-14 * r, "{x} {d1} {d2}");
            let p = load(a, r, e, w);
            // ln((R+a)/(R-a)) is good to eps/x relative and the bracket cancels
            // by x^2 more: relative loss ~ eps / x^3.
            let tol = 1e-15 / (x * x * x) * p.abs().max(e * r * r * x * x * x);
            assert!((p - j.load(a)).abs() < tol, "{x} {p} {} {tol}", j.load(a));
        }
        assert!(ratio_warning("pull-off", 0.31, 1.0).is_some());
        assert!(ratio_warning("pull-off", 0.29, 1.0).is_none());
    }
}
