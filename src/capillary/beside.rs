//! A dry law with the meniscus beside it in the rigid (Derjaguin) form: the
//! summit's own law (any: elastic, elastic-plastic, tabulated) plus the
//! meniscus' attraction of a rigid sphere,
//!
//! ```text
//! P_m(delta) = -2 pi R w_m min(1, 1 + delta/h_m)   for delta > -h_m,   0 below,
//! ```
//!
//! the `lambda_m -> 0` limit of the meniscus' Maugis–Dugdale law (the
//! Derjaguin force of a Dugdale zone of stress `Delta p` and range `h_m`;
//! docs/physics.md). Reversible (an equilibrium meniscus has no
//! hysteresis); the dry law's history, instabilities and contact radius are
//! kept. Its model error against the elastic meniscus is the relative
//! difference of the pull-offs, `|P_MD(lambda_m) - 2 pi R w_m| / (2 pi R w_m)`
//! ([`derjaguin_error`]).

use super::Meniscus;
use crate::law::{
    AsperityLaw, Branch, ContactState, Control, Instability, LawKernels, RadiusScaling,
};
use std::sync::Arc;

/// The dry law `dry` with the Derjaguin meniscus of `meniscus` on a summit
/// of radius `radius` (m).
#[derive(Debug, Clone)]
pub struct WithMeniscus {
    dry: Arc<dyn LawKernels>,
    /// `2 pi R w_m` (N).
    full: f64,
    /// `h_m` (m).
    height: f64,
}

impl WithMeniscus {
    /// The dry law with the meniscus beside it.
    pub fn new(dry: Arc<dyn LawKernels>, meniscus: &Meniscus, radius: f64) -> Self {
        WithMeniscus {
            dry,
            full: meniscus.rigid_pull_off(radius),
            height: meniscus.height(),
        }
    }

    /// The meniscus' load alone (N) at `delta` (m).
    pub fn meniscus_load(&self, delta: f64) -> f64 {
        if !(delta > -self.height) {
            return 0.0;
        }
        -self.full * (1.0 + delta / self.height).min(1.0)
    }

    fn with(&self, s: ContactState, delta: f64) -> ContactState {
        ContactState {
            load: s.load + self.meniscus_load(delta),
            radius: s.radius,
        }
    }
}

/// Relative pull-off error of the Derjaguin meniscus against the elastic
/// one (the meniscus' Maugis–Dugdale law) on a summit of radius `radius`
/// and contact modulus `contact_modulus`; `None` when `lambda_m` is outside
/// the Maugis–Dugdale range.
pub fn derjaguin_error(meniscus: &Meniscus, radius: f64, contact_modulus: f64) -> Option<f64> {
    let md = meniscus.maugis(radius, contact_modulus).ok()?;
    let p = md.pull_off(Control::Load)?.load.abs();
    let r = meniscus.rigid_pull_off(radius);
    Some((p - r).abs() / r)
}

impl AsperityLaw for WithMeniscus {
    fn name(&self) -> &'static str {
        "with-meniscus"
    }

    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        self.with(self.dry.state(delta, branch), delta)
    }

    fn state_after(&self, delta: f64, delta_max: f64) -> ContactState {
        self.with(self.dry.state_after(delta, delta_max), delta)
    }

    fn load_after(&self, delta: f64, delta_max: f64) -> f64 {
        self.dry.load_after(delta, delta_max) + self.meniscus_load(delta)
    }

    fn reversible(&self) -> bool {
        self.dry.reversible()
    }

    fn detach_interference(&self) -> f64 {
        self.dry.detach_interference()
    }

    /// Below the meniscus' reach and the dry law's cutoff.
    fn cutoff_interference(&self) -> f64 {
        self.dry.cutoff_interference().min(-self.height)
    }

    fn interaction_range(&self) -> f64 {
        self.dry.interaction_range().min(-self.height)
    }

    crate::law::delegate_history!(dry);

    /// The dry law's, with the meniscus' reach `-h_m` and full wetting at 0.
    fn breakpoints(&self, branch: Branch) -> Vec<f64> {
        let mut v = self.dry.breakpoints(branch);
        v.extend([-self.height, 0.0]);
        v.retain(|d| d.is_finite());
        v.sort_by(f64::total_cmp);
        v.dedup();
        v
    }

    /// Load control: the most tensile of the dry pull-off with the meniscus
    /// added and the meniscus' full pull at the contact onset (the
    /// meniscus load is constant for `delta >= 0` and the dry law's on
    /// either side of its own minimum); displacement control: the dry law's
    /// snap with the meniscus load there.
    fn pull_off(&self, control: Control) -> Option<Instability> {
        let dry = self.dry.pull_off(control);
        let at = |d: f64, r: f64| Instability {
            load: self.dry.load(d, Branch::Retract) + self.meniscus_load(d),
            interference: d,
            radius: r,
        };
        match control {
            Control::Displacement => dry.map(|p| Instability {
                load: p.load + self.meniscus_load(p.interference),
                ..p
            }),
            Control::Load => {
                let mut best = at(0.0, self.dry.state(0.0, Branch::Retract).radius);
                if let Some(p) = dry {
                    let q = Instability {
                        load: p.load + self.meniscus_load(p.interference),
                        ..p
                    };
                    if q.load < best.load {
                        best = q;
                    }
                }
                Some(best)
            }
        }
    }

    fn zero_load_radius(&self) -> Option<f64> {
        // The meniscus adds a constant pull in contact: the dry law at
        // P = +2 pi R w_m is not asked of it; the dry zero-load radius is
        // the lower bound reported.
        self.dry.zero_load_radius()
    }

    /// Both parts scale with the summit radius only if the dry law does at
    /// `(0, 1, *)` (rigid): the meniscus' load is `~ R` at fixed interference.
    fn radius_scaling(&self) -> Option<RadiusScaling> {
        self.dry
            .radius_scaling()
            .filter(|s| s.interference == 0.0 && s.load == 1.0)
    }
}

impl LawKernels for WithMeniscus {
    fn cost_ns(&self) -> f64 {
        self.dry.cost_ns() + 2.0
    }
}
