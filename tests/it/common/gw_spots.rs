//! An independent oracle for contact-resistance sums over a
//! Greenwood–Williamson surface: Hertz spots summed by the closed forms
//! `F_1/2` (Maxwell) and `F_1` (Sharvin) where they exist, by quadrature
//! in `u = sqrt(s - h)` otherwise. The engine computes the same sums
//! through its one GW integrator (the spot conductance as a per-asperity
//! observable, `asperity::electrical::ResistanceObservables`); the tests
//! compare the two. Moved here from the library, which keeps one
//! integrator.
#![allow(dead_code)]
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use asperity::electrical::{ContactResistance, Interaction, SpotResistance, SpotSums, Spreading};
use asperity::error::{positive, Result};
use asperity::heights::HeightDistribution;
use asperity::law::{AsperityLaw, Branch};
use asperity::numeric::quadrature::{integrate_pieces_n, QuadOptions};
use std::f64::consts::PI;
use std::sync::Arc;

/// Relative tolerance of the quadratures here.
const QUAD_RTOL: f64 = 1e-12;
/// Probability left out of each tail of the height density.
const TAIL_EPS: f64 = 1e-300;

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
    pub fn integrate<F: Fn(f64) -> f64>(&self, h: f64, f: F) -> [f64; 2] {
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
