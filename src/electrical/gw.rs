//! Many spots over a Greenwood–Williamson surface: independent parallel
//! spots (Holm) and Greenwood's (1966) mean-field interaction.
//!
//! `N = eta A_n` summits of radius `R`, heights `z = sigma s` with density
//! `phi(s)`, separation `d = h sigma`. A Hertz summit at height `s > h` makes
//! a spot of radius `a = sqrt(R sigma (s - h))`. Sums over spots are
//! `N int_h^inf g(a(s)) phi(s) ds`; closed forms (physics.md):
//! - Maxwell: `G = N sqrt(R sigma) F_1/2(h) / ((rho1 + rho2)/4)`
//!   (same metal `(2/rho) N sqrt(R sigma) F_1/2`),
//! - Sharvin: `G = N R sigma F_1(h) / c_S`, `c_S = 2 (rho1 l1 + rho2 l2)/(3 pi)`
//!   (same metal `(3 pi/(4 rho l)) N R sigma F_1`),
//!
//! and quadrature otherwise (Wexler, a film, distributions without closed
//! `F_n`), in `u = sqrt(s - h)` so the `sqrt` onset of `a` is smooth.
//!
//! Greenwood's interaction, mean field for spot centres uniform in a square
//! of side `L = sqrt(A_n)`: `R_int = (rho_eff c_sq/(pi L)) (1 - sum G_i^2 /
//! (sum G_i)^2)`, `rho_eff = (rho1 + rho2)/2`, `c_sq = E[1/|X - Y|]` in the
//! unit square. The weights are the spots' shares of the current in the
//! parallel solution, `G_i / sum G`; for Maxwell spots they are
//! `a_i / sum a`, Greenwood's form `1 - sum a^2/(sum a)^2` (physics.md).

use super::spot::{SpotResistance, Spreading};
use crate::error::{positive, Result};
use crate::heights::HeightDistribution;
use crate::law::{AsperityLaw, Branch};
use crate::numeric::quadrature::{integrate_pieces_n, QuadOptions};
use std::f64::consts::PI;
use std::sync::Arc;

/// `c_sq = E[1/|X - Y|]` for `X, Y` uniform in the unit square:
/// `4 ln(1 + sqrt 2) - (4/3)(sqrt 2 - 1)` (physics.md; mpmath check in
/// `tests/data/electrical.py`).
pub const C_SQ: f64 = 2.973_209_598_247_378_5;

/// Relative tolerance of the quadratures here.
const QUAD_RTOL: f64 = 1e-12;
/// Probability left out of each tail of the height density.
const TAIL_EPS: f64 = 1e-300;

/// Whether Greenwood's interaction term is added to the parallel spots.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interaction {
    /// Independent parallel spots (Holm).
    None,
    /// Parallel spots plus Greenwood's (1966) mean-field interaction term in
    /// a square apparent area.
    Greenwood,
}

impl Interaction {
    /// Both choices.
    pub const ALL: [Interaction; 2] = [Interaction::None, Interaction::Greenwood];

    /// `"none"` or `"greenwood"` (the scene's `interaction`).
    pub fn name(self) -> &'static str {
        match self {
            Interaction::None => "none",
            Interaction::Greenwood => "greenwood",
        }
    }
}

impl crate::named::Named for Interaction {
    const ALL: &'static [Self] = &Interaction::ALL;
    const WHAT: &'static str = "interaction";
    fn name(self) -> &'static str {
        Interaction::name(self)
    }
}
crate::serde_by_name!(Interaction);

/// Sums over the spots of one state.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SpotSums {
    /// Number of spots (expected, for a statistical surface).
    pub contacts: f64,
    /// `sum G_i` (S): the parallel conductance.
    pub conductance: f64,
    /// `sum G_i^2` (S^2), for the interaction weights.
    pub conductance_sq: f64,
}

/// Greenwood's mean-field interaction resistance (Ohm) of spots whose
/// centres are uniform in a square of side `side` (m):
/// `(rho_eff c_sq/(pi L)) (1 - sum G^2/(sum G)^2)`; 0 without conductance.
pub fn greenwood_mean_field(mutual_resistivity: f64, side: f64, sums: &SpotSums) -> f64 {
    if !(sums.conductance > 0.0) {
        return 0.0;
    }
    let w2 = sums.conductance_sq / (sums.conductance * sums.conductance);
    mutual_resistivity * C_SQ / (PI * side) * (1.0 - w2).max(0.0)
}

/// Resistance of a contact and its parts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactResistance {
    /// Total resistance (Ohm): parallel plus interaction; `inf` without
    /// contact.
    pub resistance: f64,
    /// Independent parallel spots `1/sum G_i` (Ohm).
    pub parallel: f64,
    /// Greenwood's interaction term (Ohm), when asked for and computed.
    pub interaction: Option<f64>,
    /// Whether the interaction was asked for but left out because fewer than
    /// 2 contacts are expected (the caller should warn).
    pub interaction_skipped: bool,
    /// Number of contact spots (expected).
    pub contacts: f64,
}

impl ContactResistance {
    /// Combines parallel sums with the interaction choice; the Greenwood
    /// term needs at least 2 (expected) contacts.
    pub fn from_sums(
        sums: &SpotSums,
        spot: &SpotResistance,
        interaction: Interaction,
        side: f64,
    ) -> Self {
        let parallel = 1.0 / sums.conductance;
        let (term, skipped) = match interaction {
            Interaction::None => (None, false),
            Interaction::Greenwood if sums.contacts >= 2.0 => (
                Some(greenwood_mean_field(spot.mutual_resistivity(), side, sums)),
                false,
            ),
            Interaction::Greenwood => (None, true),
        };
        ContactResistance {
            resistance: parallel + term.unwrap_or(0.0),
            parallel,
            interaction: term,
            interaction_skipped: skipped,
            contacts: sums.contacts,
        }
    }
}

/// One state of a Hertz-summit GW contact with its resistance (the
/// `states` rows of the JSON contract).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElectricalState {
    /// Separation `d` (m) of the mean summit plane from the flat.
    pub separation: f64,
    /// Load (N), compressive > 0.
    pub load: f64,
    /// Real contact area `pi sum a^2` (m^2).
    pub real_area: f64,
    /// Resistance and its parts.
    pub resistance: ContactResistance,
}

/// A GW surface's summits for electrical sums: `N` summits of radius `R`
/// (m), height scale `sigma` (m), nominal area `A_n` (m^2), height density.
#[derive(Debug, Clone)]
pub struct GwSpots {
    count: f64,
    radius: f64,
    sigma: f64,
    side: f64,
    dist: Arc<dyn HeightDistribution>,
}

impl GwSpots {
    /// `count = eta A_n > 0` summits of radius `summit_radius > 0` (m),
    /// `sigma > 0` (m), `nominal_area > 0` (m^2), heights `dist`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming the argument.
    pub fn new(
        count: f64,
        summit_radius: f64,
        sigma: f64,
        nominal_area: f64,
        dist: Arc<dyn HeightDistribution>,
    ) -> Result<Self> {
        Ok(GwSpots {
            count: positive("count", count)?,
            radius: positive("summit_radius", summit_radius)?,
            sigma: positive("sigma", sigma)?,
            side: positive("nominal_area", nominal_area)?.sqrt(),
            dist,
        })
    }

    /// Side `L = sqrt(A_n)` (m) of the square apparent area.
    pub fn side(&self) -> f64 {
        self.side
    }

    /// Sums over Hertz spots `a = sqrt(R sigma (s - h))` at `h = d/sigma`:
    /// closed forms for Maxwell/Sharvin without film where `F_n` is closed,
    /// otherwise exact sample sums or quadrature.
    pub fn hertz_sums(&self, spot: &SpotResistance, h: f64) -> SpotSums {
        let rs = self.radius * self.sigma;
        let n = self.count;
        let closed = |k: f64| self.dist.closed_form_moment(k);
        let contacts = n * self.dist.moment_above(0.0, h);
        if !spot.has_film() && self.dist.sample_points().is_none() {
            // One spot: g = c a^p with c = 1/R(1) a^... : read c off a = 1.
            match spot.spreading() {
                Spreading::Maxwell if closed(0.5) && closed(1.0) => {
                    let c = spot.spot_conductance(1.0); // G = c a
                    return SpotSums {
                        contacts,
                        conductance: n * c * rs.sqrt() * self.dist.moment_above(0.5, h),
                        conductance_sq: n * c * c * rs * self.dist.moment_above(1.0, h),
                    };
                }
                Spreading::Sharvin if closed(1.0) && closed(2.0) => {
                    let c = spot.spot_conductance(1.0); // G = c a^2
                    return SpotSums {
                        contacts,
                        conductance: n * c * rs * self.dist.moment_above(1.0, h),
                        conductance_sq: n * c * c * rs * rs * self.dist.moment_above(2.0, h),
                    };
                }
                _ => {}
            }
        }
        let [g, g2] = self.integrate(h, |t| spot.spot_conductance((rs * t).sqrt()));
        SpotSums {
            contacts,
            conductance: n * g,
            conductance_sq: n * g2,
        }
    }

    /// Sums over spots whose radius comes from any `law` (built for this
    /// summit radius) on `branch`: spot radius `law.state(sigma (s - h),
    /// branch).radius`, so elastic, adhesive and elastic-plastic summits all
    /// conduct. Quadrature split at the law's breakpoints.
    pub fn law_sums(
        &self,
        law: &dyn AsperityLaw,
        branch: Branch,
        spot: &SpotResistance,
        h: f64,
    ) -> SpotSums {
        let sig = self.sigma;
        let onset = [law.attach_interference(), law.detach_interference(), 0.0]
            .into_iter()
            .filter(|x| x.is_finite())
            .fold(0.0, f64::min);
        let radius = |t: f64| law.state(sig * t + onset, branch).radius;
        let [c, g, g2] =
            self.integrate_law(h + onset / sig, &law.breakpoints(branch), onset, |t| {
                let a = radius(t);
                let gi = spot.spot_conductance(a);
                [if a > 0.0 { 1.0 } else { 0.0 }, gi, gi * gi]
            });
        SpotSums {
            contacts: self.count * c,
            conductance: self.count * g,
            conductance_sq: self.count * g2,
        }
    }

    /// Resistance of Hertz spots at `h = d/sigma` with `interaction`.
    pub fn hertz_resistance(
        &self,
        spot: &SpotResistance,
        interaction: Interaction,
        h: f64,
    ) -> ContactResistance {
        ContactResistance::from_sums(&self.hertz_sums(spot, h), spot, interaction, self.side)
    }

    /// Full state of the Hertz-summit contact at separation `d` (m) for
    /// contact modulus `e_star` (Pa): load `(4/3) N E* R^1/2 sigma^3/2
    /// F_3/2(h)`, real area `pi N R sigma F_1(h)`, resistance.
    pub fn hertz_state(
        &self,
        e_star: f64,
        spot: &SpotResistance,
        interaction: Interaction,
        d: f64,
    ) -> ElectricalState {
        let h = d / self.sigma;
        let (r, s, n) = (self.radius, self.sigma, self.count);
        ElectricalState {
            separation: d,
            load: 4.0 / 3.0 * n * e_star * r.sqrt() * s.powf(1.5) * self.dist.moment_above(1.5, h),
            real_area: PI * n * r * s * self.dist.moment_above(1.0, h),
            resistance: self.hertz_resistance(spot, interaction, h),
        }
    }

    /// `[int g phi, int g^2 phi]` over `s > h` with `g = f(s - h)`: exact
    /// average over a finite sample, otherwise quadrature in `u = sqrt(s - h)`.
    fn integrate<F: Fn(f64) -> f64>(&self, h: f64, f: F) -> [f64; 2] {
        if let Some(pts) = self.dist.sample_points() {
            let first = pts.partition_point(|&s| s <= h);
            let (mut a, mut b) = (0.0, 0.0);
            for &s in &pts[first..] {
                let g = f(s - h);
                a += g;
                b += g * g;
            }
            let m = pts.len() as f64;
            return [a / m, b / m];
        }
        let (lo, hi) = self.dist.numerical_support(TAIL_EPS);
        if !(hi > h) {
            return [0.0; 2];
        }
        let u0 = (lo - h).max(0.0).sqrt();
        let u1 = (hi - h).sqrt();
        let q = integrate_pieces_n(
            |u| {
                let w = 2.0 * u * self.dist.pdf(h + u * u);
                let g = f(u * u);
                [g * w, g * g * w]
            },
            &[u0, u1],
            &QuadOptions::relative(QUAD_RTOL),
        );
        q.value
    }

    /// `[P(contact), int g phi, int g^2 phi]` for a law: `t = s - h0` with
    /// `h0 = h + onset/sigma`; pieces at the law's breakpoints.
    fn integrate_law<F: Fn(f64) -> [f64; 3]>(
        &self,
        h0: f64,
        breaks: &[f64],
        onset: f64,
        f: F,
    ) -> [f64; 3] {
        if let Some(pts) = self.dist.sample_points() {
            let first = pts.partition_point(|&s| s < h0);
            let mut acc = [0.0; 3];
            for &s in &pts[first..] {
                let v = f(s - h0);
                (0..3).for_each(|k| acc[k] += v[k]);
            }
            let m = pts.len() as f64;
            return acc.map(|x| x / m);
        }
        let (lo, hi) = self.dist.numerical_support(TAIL_EPS);
        let t0 = (lo - h0).max(0.0);
        let t1 = hi - h0;
        if !(t1 > t0) {
            return [0.0; 3];
        }
        let mut pts = vec![t0, t1];
        pts.extend(
            breaks
                .iter()
                .map(|b| (b - onset) / self.sigma)
                .filter(|t| *t > t0 && *t < t1),
        );
        pts.sort_by(f64::total_cmp);
        let mut opts = QuadOptions::relative(1e-10);
        opts.abs_tol = 1e-300;
        let q = integrate_pieces_n(|t| f(t).map(|v| v * self.dist.pdf(h0 + t)), &pts, &opts);
        q.value
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::heights::Gaussian;

    fn surface() -> GwSpots {
        GwSpots::new(1e4, 1e-6, 1e-8, 1e-8, Arc::new(Gaussian::new())).unwrap()
    }

    #[test]
    fn c_sq_is_the_closed_form() {
        let s2 = 2f64.sqrt();
        let c = 4.0 * (1.0 + s2).ln() - 4.0 / 3.0 * (s2 - 1.0);
        assert!((c - C_SQ).abs() < 1e-13);
    }

    #[test]
    fn closed_forms_match_quadrature() {
        let gw = surface();
        let rho = 2.44e-8;
        let maxwell = SpotResistance::same_metal(Spreading::Maxwell, rho, None).unwrap();
        let sharvin = SpotResistance::same_metal(Spreading::Sharvin, rho, Some(3.46e-8)).unwrap();
        for spot in [maxwell, sharvin] {
            for h in [-1.0, 0.0, 1.5, 4.0] {
                let closed = gw.hertz_sums(&spot, h);
                let [g, g2] = gw.integrate(h, |t| spot.spot_conductance((1e-6 * 1e-8 * t).sqrt()));
                let quad = (1e4 * g, 1e4 * g2);
                assert!((closed.conductance / quad.0 - 1.0).abs() < 1e-10, "{h}");
                assert!((closed.conductance_sq / quad.1 - 1.0).abs() < 1e-10, "{h}");
            }
        }
    }

    #[test]
    fn interaction_is_skipped_below_two_contacts() {
        let gw = surface();
        let spot = SpotResistance::same_metal(Spreading::Maxwell, 2.44e-8, None).unwrap();
        let far = gw.hertz_resistance(&spot, Interaction::Greenwood, 4.5);
        assert!(far.contacts < 2.0);
        assert!(far.interaction_skipped && far.interaction.is_none());
        assert_eq!(far.resistance, far.parallel);
        let near = gw.hertz_resistance(&spot, Interaction::Greenwood, 1.0);
        assert!(!near.interaction_skipped);
        assert!(near.interaction.unwrap() > 0.0);
        assert!(near.resistance > near.parallel);
    }
}
