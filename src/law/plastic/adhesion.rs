//! Adhesion after plastic loading: JKR on the flattened shape.
//!
//! After loading to `delta_max` the asperity unloads elastically as a sphere
//! of radius `R_u >= R` seated at the residual interference `delta_res`
//! ([`Unloading`]). With short-range adhesion (work `w`), the unloading is
//! the JKR solution for that sphere, shifted by `delta_res`:
//!
//! ```text
//! P = K a^3/R_u - sqrt(6 pi w K a^3),   delta - delta_res = a^2/R_u - sqrt(8 pi w a/(3K)),   K = 4E*/3
//! ```
//!
//! so the load-controlled pull-off `-(3/2) pi w R_u` and the jump-out grow
//! with the flattening, i.e. with the maximum load reached: the stiction of
//! gold switches closed hard (Mesarovic & Johnson 2000 find this growth
//! for adhesive elastic-plastic spheres; Kogut & Etsion 2003 add adhesion
//! to the KE loading the same way, as a force on the non-adhesive deformed
//! shape). On approach, the asperity jumps in at `delta = 0` and sits on the
//! JKR branch of its current shape (`delta_max = delta`); with no plastic
//! deformation (`delta_max` below the elastic limit) this is exactly
//! [`crate::law::Jkr`]. This model is derived here (documented in
//! docs/physics.md), not a published fit: the residual profile is taken as
//! a sphere, where the true one is flattened; the general-axisymmetric JKR
//! solution can replace it.

use super::{PlasticLoading, Unloading};
use crate::error::{positive, Result};
use crate::law::jkr::{
    interference_bar, load_bar, stable_radius_bar, JUMP_OUT_INTERFERENCE, JUMP_OUT_LOAD,
    JUMP_OUT_RADIUS, PULL_OFF_LOAD, PULL_OFF_RADIUS, ZERO_LOAD_RADIUS,
};
use crate::law::{AsperityLaw, Branch, ContactState, Control, Instability, LawKernels, Prepared};
use crate::material::MaugisScales;
use std::sync::Arc;

/// An elastic-plastic law with JKR adhesion on the unloading shape.
///
/// Adding adhesion to a plastic law: build the non-adhesive law
/// ([`build`](super::build), or a variant's own `new`), take its loading
/// curve ([`PlasticLaw::as_loading`](super::PlasticLaw::as_loading)) and
/// wrap it with the work of adhesion. The result is an [`AsperityLaw`] like
/// any other (GW, Monte Carlo, scenes with `law.kind = "kogut-etsion"` and
/// `w > 0` do exactly this); its pull-off grows with the maximum load
/// reached, from JKR's `-(3/2) pi w R` below first yield.
///
/// ```
/// use asperity::prelude::*;
/// use std::sync::Arc;
///
/// let (r, e_star, w) = (1e-6, contact_modulus(&Material::gold(), &Material::gold()), 0.5);
/// let ke = build_plastic(Variant::KogutEtsion, r, e_star, Plasticity::gold())?;
/// let law = AdhesivePlastic::new(ke.clone().as_loading(), w)?;
/// let omega_c = ke.critical_interference();
/// let jkr = -1.5 * std::f64::consts::PI * w * r;
/// // Below first yield: JKR's pull-off.
/// let elastic = law.pull_off_after(0.5 * omega_c, Control::Load).load;
/// assert!((elastic - jkr).abs() < 1e-9 * jkr.abs());
/// // Pressed to 50 critical interferences: flattened, it sticks harder.
/// let pressed = law.pull_off_after(50.0 * omega_c, Control::Load).load;
/// assert!(pressed < 1.2 * jkr);
/// # Ok::<(), asperity::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct AdhesivePlastic {
    loading: Arc<dyn PlasticLoading>,
    work: f64,
    elastic: MaugisScales,
    cutoff: f64,
}

impl AdhesivePlastic {
    /// Wraps a non-adhesive elastic-plastic loading law with work of
    /// adhesion `w` (J/m^2, > 0).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `work_of_adhesion`.
    pub fn new(loading: Arc<dyn PlasticLoading>, work: f64) -> Result<Self> {
        positive("work_of_adhesion", work)?;
        let a = *loading.asperity();
        let elastic = MaugisScales::new(a.radius, a.contact_modulus, work)?;
        let mut law = AdhesivePlastic {
            loading,
            work,
            elastic,
            cutoff: 0.0,
        };
        law.cutoff = law.lowest_detach();
        Ok(law)
    }

    /// The loading law.
    pub fn loading(&self) -> &dyn PlasticLoading {
        self.loading.as_ref()
    }

    /// Work of adhesion `w` (J/m^2).
    pub fn work(&self) -> f64 {
        self.work
    }

    /// Unloading shape and its JKR scales after `delta_max` (m).
    #[inline]
    pub fn shape_after(&self, delta_max: f64) -> (Unloading, MaugisScales) {
        let u = self.loading.unloading(delta_max);
        if u.elastic {
            return (u, self.elastic);
        }
        // The JKR scales of radius R_u from those of R: lengths go as
        // R^(1/3) (interference) and R^(2/3) (radius), the load as R (one
        // cube root instead of MaugisScales::new's two).
        let ratio = u.radius / self.loading.asperity().radius;
        let c = crate::special::cbrt::cbrt(ratio);
        let s = MaugisScales {
            radius: self.elastic.radius * c * c,
            load: self.elastic.load * ratio,
            interference: self.elastic.interference * c,
        };
        (u, s)
    }

    /// Pull-off after loading to `delta_max` (m): under load control
    /// `-(3/2) pi w R_u`, under displacement control the JKR jump-out
    /// (`-(5/6) pi w R_u`) at `delta_res + Dbar_c (pi^2 w^2 R_u/K^2)^(1/3)`.
    pub fn pull_off_after(&self, delta_max: f64, control: Control) -> Instability {
        let (u, s) = self.shape_after(delta_max);
        pull_off_on(u.residual, &s, control)
    }

    /// Jump-out interference (m) after loading to `delta_max`.
    pub fn detach_after(&self, delta_max: f64) -> f64 {
        let (u, s) = self.shape_after(delta_max);
        u.residual + JUMP_OUT_INTERFERENCE * s.interference
    }

    /// A lower bound of [`detach_after`](Self::detach_after) over every
    /// `delta_max`: the minimum over a log grid of `1e-3 .. 1e6` critical
    /// interferences, with a factor 2 of margin.
    fn lowest_detach(&self) -> f64 {
        let wc = self.loading.critical_interference();
        let mut lo = JUMP_OUT_INTERFERENCE * self.elastic.interference;
        for i in 0..=900 {
            let dm = wc * 10f64.powf(-3.0 + 9.0 * i as f64 / 900.0);
            lo = lo.min(self.detach_after(dm));
        }
        2.0 * lo.min(0.0)
    }

    #[inline]
    fn attached(&self, delta: f64, delta_max: f64) -> ContactState {
        let (u, s) = self.shape_after(delta_max);
        match stable_radius_bar((delta - u.residual) / s.interference) {
            Some(a) => ContactState {
                load: load_bar(a) * s.load,
                radius: a * s.radius,
            },
            None => ContactState::FREE,
        }
    }
}

/// JKR's pull-off on a shape with residual interference `residual` (m)
/// and JKR scales `s`: under load control `-(3/2) pi w R_u`, under
/// displacement control the jump-out.
fn pull_off_on(residual: f64, s: &MaugisScales, control: Control) -> Instability {
    let (a, p) = match control {
        Control::Load => (PULL_OFF_RADIUS, PULL_OFF_LOAD),
        Control::Displacement => (JUMP_OUT_RADIUS, JUMP_OUT_LOAD),
    };
    Instability {
        load: p * s.load,
        interference: residual + interference_bar(a) * s.interference,
        radius: a * s.radius,
    }
}

/// States per block of [`AdhesivePlastic`]'s batch (its prepared shapes
/// live on the stack).
const PREPARED_BLOCK: usize = 64;

/// Subintervals of each loading piece scanned for the roots of
/// [`AsperityLaw::contact_loss_peaks`] (the span need not be monotone).
const SPAN_SCAN: usize = 8;

impl AsperityLaw for AdhesivePlastic {
    fn name(&self) -> &'static str {
        match self.loading.variant() {
            crate::material::plastic::Variant::KogutEtsion => "kogut-etsion+jkr",
            crate::material::plastic::Variant::JacksonGreen => "jackson-green+jkr",
            crate::material::plastic::Variant::ChangEtsionBogy => "chang-etsion-bogy+jkr",
            crate::material::plastic::Variant::ZhaoMaiettaChang => "zhao-maietta-chang+jkr",
        }
    }

    /// Approach: free below 0, then the JKR branch of the current shape.
    /// Retract without history: the same (the asperity at its maximum).
    #[inline]
    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        match branch {
            Branch::Approach if delta < 0.0 => ContactState::FREE,
            _ => self.attached(delta, delta.max(0.0)),
        }
    }

    #[inline]
    fn state_after(&self, delta: f64, delta_max: f64) -> ContactState {
        if delta_max < 0.0 {
            return ContactState::FREE;
        }
        self.attached(delta, delta.max(delta_max))
    }

    fn history_breakpoints(&self) -> Vec<f64> {
        self.loading.breakpoint_interferences()
    }

    /// The peaks `delta_max` whose summits let go after the flat retracted
    /// by `recovery` (m): the roots of `delta_max - detach_after(delta_max)
    /// = recovery` ([`AdhesivePlastic::detach_after`]: JKR's jump-out on the
    /// flattened shape). Each piece between the loading law's breakpoints
    /// (where the span may jump) is scanned on `SPAN_SCAN` (8) subintervals
    /// for sign changes, each root bisected to a few ulp. Without these the
    /// GW quadrature of a retraction state had to find each jump of the
    /// integrand (load `-(5/6) pi w R_u` to 0) by bisection.
    fn contact_loss_peaks(&self, recovery: f64) -> Vec<f64> {
        if !(recovery.is_finite() && recovery > 0.0) {
            return Vec::new();
        }
        let mut ends: Vec<f64> = self
            .loading
            .breakpoint_interferences()
            .into_iter()
            .filter(|&b| b >= 0.0)
            .collect();
        ends.push(0.0);
        // (just inside each piece: the span may jump at its ends)
        super::unloading::span_crossings(
            |dm| dm - self.detach_after(dm),
            recovery,
            ends,
            self.loading.critical_interference(),
            SPAN_SCAN,
            1e-12,
        )
    }

    /// The flattening (and so the JKR shape) depends on `delta_max`.
    fn remembers_maximum(&self) -> bool {
        true
    }

    fn attach_interference(&self) -> f64 {
        0.0
    }

    /// Jump-out of the elastic (never yielded) asperity; after plastic
    /// loading see [`AdhesivePlastic::detach_after`].
    fn detach_interference(&self) -> f64 {
        JUMP_OUT_INTERFERENCE * self.elastic.interference
    }

    fn cutoff_interference(&self) -> f64 {
        self.cutoff
    }

    fn breakpoints(&self, branch: Branch) -> Vec<f64> {
        let mut b = self.loading.breakpoint_interferences();
        if branch == Branch::Retract {
            b.insert(0, self.detach_interference());
        }
        b
    }

    /// Pull-off of the elastic (never yielded) asperity, JKR; after plastic
    /// loading see [`AdhesivePlastic::pull_off_after`].
    fn pull_off(&self, control: Control) -> Option<Instability> {
        Some(self.pull_off_after(0.0, control))
    }

    fn zero_load_radius(&self) -> Option<f64> {
        Some(ZERO_LOAD_RADIUS * self.elastic.radius)
    }
}

impl LawKernels for AdhesivePlastic {
    /// JKR on the flattened shape: the load-controlled pull-off after
    /// `delta_max` ([`AdhesivePlastic::pull_off_after`]); a summit that
    /// never touched stays free.
    fn retraction_minimum(&self, delta_max: f64) -> Option<crate::law::RetractionMinimum> {
        if delta_max < 0.0 {
            return Some(crate::law::RetractionMinimum::MONOTONE);
        }
        Some(self.pull_off_after(delta_max, Control::Load).into())
    }

    fn prepares_history(&self) -> bool {
        true
    }

    /// `[delta_res, Dbar scale, load scale, radius scale]` of the shape
    /// after `delta_max` ([`AdhesivePlastic::shape_after`]: the unloading
    /// law and a cube root, ~90 % of a state's cost); NaN where
    /// `delta_max < 0` (never in contact).
    fn prepare_after(&self, delta_max: &[f64], prepared: &mut [Prepared]) {
        for (&m, p) in delta_max.iter().zip(prepared.iter_mut()) {
            *p = if m < 0.0 {
                [f64::NAN; 4]
            } else {
                let (u, s) = self.shape_after(m);
                [u.residual, s.interference, s.load, s.radius]
            };
        }
    }

    /// As `retraction_minimum`: the load-controlled pull-off of the
    /// prepared shape.
    fn retraction_minimum_prepared(
        &self,
        delta_max: f64,
        prepared: &Prepared,
    ) -> Option<crate::law::RetractionMinimum> {
        if delta_max < 0.0 {
            return Some(crate::law::RetractionMinimum::MONOTONE);
        }
        let [residual, interference, load, radius] = *prepared;
        let s = MaugisScales {
            radius,
            load,
            interference,
        };
        Some(pull_off_on(residual, &s, Control::Load).into())
    }

    /// The shapes of a block of states prepared at once and their JKR
    /// roots in SIMD lanes
    /// ([`state_batch_prepared`](LawKernels::state_batch_prepared)), bit
    /// for bit `state_after` on retraction and `state` on approach (the
    /// state after its own interference as peak, `state_after(delta,
    /// delta)`; for NaN after 0, as `state` takes it): what a GW quadrature
    /// panel's nodes take (each node has its own peak, so nothing is shared
    /// but the lanes).
    fn state_batch(
        &self,
        delta: &[f64],
        delta_max: Option<&[f64]>,
        load: &mut [f64],
        radius: &mut [f64],
    ) {
        let n = delta.len().min(load.len()).min(radius.len());
        let n = delta_max.map_or(n, |m| n.min(m.len()));
        let mut words = [[0.0; 4]; PREPARED_BLOCK];
        let mut peaks = [0.0; PREPARED_BLOCK];
        for a in (0..n).step_by(PREPARED_BLOCK) {
            let b = (a + PREPARED_BLOCK).min(n);
            let m = match delta_max {
                Some(m) => &m[a..b],
                None => {
                    for (p, &d) in peaks.iter_mut().zip(&delta[a..b]) {
                        *p = if d.is_nan() { 0.0 } else { d };
                    }
                    &peaks[..b - a]
                }
            };
            let w = &mut words[..b - a];
            self.prepare_after(m, w);
            self.state_batch_prepared(&delta[a..b], m, w, &mut load[a..b], &mut radius[a..b]);
        }
    }

    /// [`state_batch`](LawKernels::state_batch)'s loads (the radii into a
    /// scratch block), bit for bit `load_after` and `load`.
    fn load_near_batch(
        &self,
        delta: &[f64],
        delta_max: Option<&[f64]>,
        load: &mut [f64],
        cursor: &mut crate::law::LawCursor,
    ) {
        let _ = cursor;
        let n = delta.len().min(load.len());
        let n = delta_max.map_or(n, |m| n.min(m.len()));
        let mut radius = [0.0; PREPARED_BLOCK];
        for a in (0..n).step_by(PREPARED_BLOCK) {
            let b = (a + PREPARED_BLOCK).min(n);
            let m = delta_max.map(|m| &m[a..b]);
            self.state_batch(&delta[a..b], m, &mut load[a..b], &mut radius[..b - a]);
        }
    }

    fn state_batch_prepared(
        &self,
        delta: &[f64],
        delta_max: &[f64],
        prepared: &[Prepared],
        load: &mut [f64],
        radius: &mut [f64],
    ) {
        // The JKR roots of every state on its prepared shape in SIMD lanes
        // (free where the words are NaN: never in contact), then, as
        // `state_after`, a state above its peak on its own shape.
        crate::numeric::simd::arch().dispatch(crate::law::jkr::JkrShapesBatch {
            delta,
            words: prepared,
            load: &mut *load,
            radius: &mut *radius,
        });
        let out = load.iter_mut().zip(radius.iter_mut());
        for ((&d, &m), (l, r)) in delta.iter().zip(delta_max).zip(out) {
            if !(m < 0.0) && !(d <= m) {
                let st = self.attached(d, d.max(m));
                (*l, *r) = (st.load, st.radius);
            }
        }
    }

    /// Measured: retraction sums over gold summits (JKR on the flattened
    /// shape, `asperity run examples/scenes/gold-rf-mems-plastic.toml`)
    /// cost about 370 ns per summit.
    fn cost_ns(&self) -> f64 {
        370.0
    }

    /// Measured on the same populations with the shapes prepared once per
    /// summit ([`LawKernels::prepare_after`]): 28.7 ns per evaluation
    /// (27.7 ns on 2026-11-28, `examples/population_cost.rs`).
    fn batch_cost_ns(&self) -> f64 {
        28.7
    }
}
