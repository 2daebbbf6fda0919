//! Asperity laws calibrated from the full solver, and their on-disk cache.
//!
//! [`Calibration::compute`] traces the load–approach curve at one Tabor
//! parameter (and shape), splits it at the jump-in and jump-out into the
//! detached and attached branches of a [`CurveTable`] in Maugis units, and
//! [`Calibration::law`] applies it to any `R`, `E*`, `w` as a
//! [`Tabulated`] law usable by [`crate::gw::GwModel`]. The Maugis–Dugdale
//! equivalent is `lambda = 1.1570 mu` ([`crate::material::LAMBDA_PER_TABOR`]).
//!
//! Calibrations are serialisable and name themselves ([`Calibration::key`],
//! [`Calibration::matches`]); the study layer's cache
//! (`crate::study::cache`) stores them as files so sweeps never recompute
//! them. The core opens no files.

use super::{Shape, SphereFacts, SpherePoint, SphereProblem, SOLVER_VERSION};
use crate::error::{Error, Result};
use crate::law::tabulated::{BranchTable, CurveTable, Tabulated};
use crate::material::LAMBDA_PER_TABOR;
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// Bump when a change alters calibration tables (what is traced, how the
/// table is built or read): cached calibrations are keyed by it as well as
/// by [`SOLVER_VERSION`]. 2: tables reach `Pbar >= 100`, the far field's
/// elastic enhancement decays, no far-field cut. 3: the stored critical
/// points are the traced points themselves ([`SpherePoint`]).
pub const CALIBRATION_VERSION: u32 = 3;

/// Smallest load `P/(pi w R)` a calibration traces to, whatever
/// `max_load_bar` its options ask (a larger one is honoured): rough-surface
/// scenes press their highest summits to `Pbar ~ 100`, and the Hertz
/// continuation above a table ending at `Pbar = 2` had radii 4-5 % low
/// there. Costs (release, default options): 0.3 s at mu = 0.01-1.6, 3 s at
/// mu = 10 and 5.4 s at mu = 100 (solver version 5; 30 s at mu = 10 in
/// version 4), once per cache.
pub const TABLE_MIN_LOAD_BAR: f64 = 100.0;

/// A calibrated law table with its provenance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Calibration {
    /// Solver version that produced it.
    pub solver_version: u32,
    /// [`CALIBRATION_VERSION`] that built the table (0 in files written
    /// before it was recorded).
    #[serde(default)]
    pub calibration_version: u32,
    /// Tabor parameter.
    pub mu: f64,
    /// Shape.
    pub shape: Shape,
    /// `Debug` form of the solver options used.
    pub options: String,
    /// Maugis–Dugdale equivalent `lambda = 1.1570 mu`.
    pub lambda_equivalent: f64,
    /// Critical points from the solver.
    pub facts: SphereFacts,
    /// The table.
    pub table: CurveTable,
}

fn branch(points: &[SpherePoint]) -> BranchTable {
    let mut b = BranchTable {
        interference_bar: vec![],
        load_bar: vec![],
        radius_bar: vec![],
    };
    for p in points {
        if b.interference_bar
            .last()
            .is_none_or(|&d| p.interference_bar > d)
        {
            b.interference_bar.push(p.interference_bar);
            b.load_bar.push(p.load_bar);
            b.radius_bar.push(p.radius_bar);
        }
    }
    b
}

impl Calibration {
    /// Traces `problem` (to a load of at least [`TABLE_MIN_LOAD_BAR`]) and
    /// tabulates both branches.
    ///
    /// # Errors
    /// [`Error::NoConvergence`] from the solver; [`Error::Invalid`] if the
    /// traced branches are too short to tabulate.
    pub fn compute(problem: &SphereProblem) -> Result<Self> {
        let facts = problem.facts()?;
        // The table reaches at least TABLE_MIN_LOAD_BAR.
        let options = problem.options();
        let traced = SphereProblem::new(
            problem.mu(),
            problem.shape(),
            super::SolverOptions {
                max_load_bar: options.max_load_bar.max(TABLE_MIN_LOAD_BAR),
                ..*options
            },
        )?;
        let curve = traced.trace()?;
        let mu = problem.mu();
        let (detached, attached) = match (facts.jump_in, facts.jump_out) {
            (Some(ji), Some(jo)) => {
                // Along decreasing H(0): detached up to the jump-in, attached
                // from the jump-out. H(0) decreases monotonically along every
                // trace for mu in [0.005, 100] (it nearly folds at mu ~ 15-20
                // but does not turn back; checked at mu = 10, 30, 100), and
                // the jump-in comes before contact, at H(0) = 1.69 mu^(3/7).
                let mut det: Vec<SpherePoint> = curve
                    .iter()
                    .filter(|p| p.central_gap > ji.central_gap)
                    .copied()
                    .collect();
                det.push(ji);
                let mut att = vec![jo];
                att.extend(
                    curve
                        .iter()
                        .filter(|p| p.central_gap < jo.central_gap)
                        .copied(),
                );
                (branch(&det), branch(&att))
            }
            _ => {
                let b = branch(&curve);
                (b.clone(), b)
            }
        };
        if detached.interference_bar.len() < 2 || attached.interference_bar.len() < 2 {
            return Err(Error::invalid(
                "calibration",
                "traced branches have fewer than 2 points",
            ));
        }
        let table = CurveTable {
            source: format!(
                "asperity sphere solver v{SOLVER_VERSION}, mu = {mu}, {:?}",
                problem.shape()
            ),
            detached,
            attached,
            attach_bar: facts.jump_in.map(|j| j.interference_bar),
            detach_bar: facts.jump_out.map(|j| j.interference_bar),
            pull_off: facts.pull_off.bar(),
            jump_out: facts.jump_out.as_ref().map(SpherePoint::bar),
            zero_load_radius_bar: facts.zero_load_radius_bar,
            far_field_scale: mu * super::trace::MAUGIS_INTERFERENCE,
        };
        Ok(Calibration {
            solver_version: SOLVER_VERSION,
            calibration_version: CALIBRATION_VERSION,
            mu,
            shape: problem.shape(),
            options: format!("{:?}", problem.options()),
            lambda_equivalent: LAMBDA_PER_TABOR * mu,
            facts,
            table,
        })
    }

    /// The Maugis–Dugdale `lambda` that best reproduces this calibration:
    /// the minimiser of the worst load error on the attached branch,
    /// `max_i |Pbar_MD(Dbar_i) - Pbar_i| / (1 + |Pbar_i|)` over the table's
    /// attached points with `Pbar_i <= max_load_bar` (the measure of
    /// [`crate::law::errors`]), found by golden-section search in
    /// `ln lambda` over `[1e-3, 1e3]` to `1e-6` relative. Returns
    /// `(lambda, worst error)`; compare with `lambda_equivalent`
    /// (`1.1570 mu`, the Dugdale stress matched to Lennard-Jones).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `max_load_bar` unless it is finite and
    /// above the pull-off.
    pub fn best_fit_lambda(&self, max_load_bar: f64) -> Result<(f64, f64)> {
        use crate::law::{Branch, MaugisCurve};
        crate::error::Allowed::open(self.table.pull_off.load_bar, f64::INFINITY)
            .check("max_load_bar", max_load_bar)?;
        let a = &self.table.attached;
        let pts: Vec<(f64, f64)> = a
            .interference_bar
            .iter()
            .zip(&a.load_bar)
            .filter(|(_, &p)| p <= max_load_bar)
            .map(|(&d, &p)| (d, p))
            .collect();
        let worst = |ln_lambda: f64| -> f64 {
            match MaugisCurve::new(ln_lambda.exp()) {
                Ok(md) => pts
                    .iter()
                    .map(|&(d, p)| (md.state_bar(d, Branch::Retract).1 - p).abs() / (1.0 + p.abs()))
                    .fold(0.0, f64::max),
                Err(_) => f64::INFINITY,
            }
        };
        // A coarse scan first (the worst-error curve need not be unimodal
        // over six decades), then golden section around the best node.
        let (lo, hi, n) = (1e-3f64.ln(), 1e3f64.ln(), 48);
        let step = (hi - lo) / n as f64;
        let best = (0..=n)
            .map(|i| lo + step * i as f64)
            .min_by(|a, b| worst(*a).total_cmp(&worst(*b)))
            .unwrap_or(0.0);
        let (x, e) = crate::numeric::roots::golden_min(
            worst,
            (best - step).max(lo),
            (best + step).min(hi),
            1e-6,
        );
        Ok((x.exp(), e))
    }

    /// The calibrated law for radius `R` (m), contact modulus `E*` (Pa) and
    /// work of adhesion `w` (J/m^2). The caller keeps `mu` consistent.
    ///
    /// # Errors
    /// As [`Tabulated::new`].
    pub fn law(&self, radius: f64, contact_modulus: f64, work: f64) -> Result<Tabulated> {
        Tabulated::new(Arc::new(self.table.clone()), radius, contact_modulus, work)
    }
}

impl Calibration {
    /// Whether this calibration was made by this solver and calibration
    /// version for `problem` (mu, shape and options).
    pub fn matches(&self, problem: &SphereProblem) -> bool {
        self.solver_version == SOLVER_VERSION
            && self.calibration_version == CALIBRATION_VERSION
            && self.mu == problem.mu()
            && self.shape == problem.shape()
            && self.options == format!("{:?}", problem.options())
    }

    /// A stable name for `problem`'s calibration (solver and calibration
    /// versions, mu, shape and an FNV-1a hash of these plus the options),
    /// for caches.
    pub fn key(problem: &SphereProblem) -> String {
        let shape = match problem.shape() {
            Shape::Paraboloid => "paraboloid".to_string(),
            Shape::Sphere { rho } => format!("rho{rho:e}"),
        };
        let key = format!(
            "{SOLVER_VERSION}|{CALIBRATION_VERSION}|{:e}|{:?}|{:?}",
            problem.mu(),
            problem.shape(),
            problem.options()
        );
        format!(
            "sphere-v{SOLVER_VERSION}-c{CALIBRATION_VERSION}-mu{:e}-{shape}-{:016x}",
            problem.mu(),
            fnv1a(&key)
        )
    }
}

/// FNV-1a, 64 bit: a stable hash for cache keys.
fn fnv1a(text: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in text.bytes() {
        h ^= b as u64;
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

#[cfg(test)]
mod tests;
