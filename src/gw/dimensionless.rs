//! Dimensionless groups of rough-surface adhesion, so published curves can
//! be reproduced.

/// GW's normalised separation `h = d / sigma`.
pub fn normalised_separation(separation: f64, sigma: f64) -> f64 {
    separation / sigma
}

/// Fuller & Tabor's (1975) adhesion parameter
/// `theta = E* sigma^(3/2) / (R^(1/2) w)`: the elastic force needed to push
/// an asperity of height `sigma` into a flat (`~E* R^(1/2) sigma^(3/2)`) over
/// the adhesive force `~w R`. Pull-off falls as `theta` grows; surfaces
/// become practically non-sticky above `theta ~ 10`.
///
/// Units: `contact_modulus` Pa, `sigma` and `radius` m, `work` J/m^2.
pub fn fuller_tabor_parameter(contact_modulus: f64, sigma: f64, radius: f64, work: f64) -> f64 {
    contact_modulus * sigma.powf(1.5) / (radius.sqrt() * work)
}

/// `sigma / delta_c`, the roughness over the JKR jump-out stretch
/// `delta_c = (3/4)(pi^2 w^2 R / E*^2)^(1/3)`; equal to
/// `(4/3) pi^(-2/3) theta^(2/3)` with `theta` Fuller & Tabor's parameter.
pub fn roughness_over_jkr_stretch(contact_modulus: f64, sigma: f64, radius: f64, work: f64) -> f64 {
    let pi = std::f64::consts::PI;
    let delta_c =
        0.75 * (pi * pi * work * work * radius / (contact_modulus * contact_modulus)).cbrt();
    sigma / delta_c
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameters_are_consistent() {
        let (e, s, r, w) = (1e9, 1e-6, 1e-4, 0.05);
        let theta = fuller_tabor_parameter(e, s, r, w);
        assert!((theta - 1e9 * 1e-9 / (1e-2 * 0.05)).abs() < 1e-9 * theta);
        let ratio = roughness_over_jkr_stretch(e, s, r, w);
        let from_theta = 4.0 / 3.0 * std::f64::consts::PI.powf(-2.0 / 3.0) * theta.powf(2.0 / 3.0);
        assert!((ratio / from_theta - 1.0).abs() < 1e-13);
        assert_eq!(normalised_separation(3.0, 2.0), 1.5);
    }
}
