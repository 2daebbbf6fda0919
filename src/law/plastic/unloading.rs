//! Elastic unloading (and reloading) after plastic loading.
//!
//! After the interference reached `delta_max` with load `P_m` and contact
//! radius `a_m`, unloading is elastic from the flattened shape (Johnson,
//! *Contact Mechanics* §6.2; the finite-element studies of Etsion, Kligerman
//! & Kadin 2005 and Kadin, Kligerman & Etsion 2006 find the same form with
//! fitted exponents, which were not reachable here). We model the unloaded
//! (residual) profile as a sphere of radius `R_u` seated at a residual
//! interference `delta_res`, and unload it as Hertz:
//!
//! ```text
//! span      = delta_max - delta_res = 3 P_m / (4 E* a_m)       (Hertz: P = (4/3) E* a x, x = a^2/R_u)
//! R_u       = a_m^2 / span                                     (>= R after plastic flattening)
//! P(delta)  = P_m ((delta - delta_res)/span)^(3/2)
//! a(delta)  = a_m ((delta - delta_res)/span)^(1/2)
//! ```
//!
//! so load and radius are continuous at `delta_max`, vanish at
//! `delta_res`, and the curve is exactly Hertz with radius `R_u`. An elastic
//! loading gives `span = delta_max`, `R_u = R`, `delta_res = 0`: nothing
//! changes. Where a fit is stiffer than Hertz just past yield (KE at
//! `1 < w < ~1.5`, CEB past `w = 1`), `3 P_m/(4 E* a_m)` exceeds `delta_max`;
//! the residual is then clamped to 0 and the same power form is kept.
//! Reloading below `delta_max` retraces the unloading curve (elastic
//! shakedown); beyond it, loading resumes on the virgin curve.

use super::PlasticLoading;
use crate::law::ContactState;

/// The elastic unloading curve from one peak.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unloading {
    /// Residual interference `delta_res` (m), `>= 0`.
    pub residual: f64,
    /// `delta_max - delta_res` (m); 0 for an elastic peak (see `elastic`).
    pub span: f64,
    /// Peak state `(P_m, a_m)`.
    pub peak: ContactState,
    /// Radius `R_u` (m) of the residual profile.
    pub radius: f64,
    /// Whether the peak was elastic (the unloading is the loading curve).
    pub elastic: bool,
}

impl Unloading {
    /// No plastic deformation: the residual profile is the sphere (`R`, m).
    pub fn elastic(radius: f64) -> Self {
        Unloading {
            residual: 0.0,
            span: 0.0,
            peak: ContactState::FREE,
            radius,
            elastic: true,
        }
    }

    /// Unloading from `peak` reached at `delta_max` (m) with contact
    /// modulus `E*` (Pa).
    pub fn from_peak(delta_max: f64, peak: ContactState, contact_modulus: f64) -> Self {
        let hertz_span = 0.75 * peak.load / (contact_modulus * peak.radius);
        let span = hertz_span.min(delta_max);
        Unloading {
            residual: delta_max - span,
            span,
            peak,
            radius: peak.radius * peak.radius / span,
            elastic: false,
        }
    }

    /// State at `delta` (m) on the unloading curve of a plastic peak.
    #[inline]
    pub fn plastic_state(&self, delta: f64) -> ContactState {
        let x = delta - self.residual;
        if !(x > 0.0) {
            return ContactState::FREE;
        }
        let t = (x / self.span).min(1.0);
        let st = t.sqrt();
        ContactState {
            load: self.peak.load * t * st,
            radius: self.peak.radius * st,
        }
    }
}

/// State at `delta` (m) after the interference reached `delta_max` (m):
/// the virgin curve at or beyond `delta_max` or for an elastic peak, the
/// elastic unloading curve otherwise.
#[inline]
pub fn state_after<L: PlasticLoading + ?Sized>(
    law: &L,
    delta: f64,
    delta_max: f64,
) -> ContactState {
    if delta >= delta_max || delta_max <= law.elastic_limit() {
        return law.loading(delta);
    }
    Unloading::from_peak(
        delta_max,
        law.loading(delta_max),
        law.asperity().contact_modulus,
    )
    .plastic_state(delta)
}

/// The peak interferences `delta_max` (m, ascending) whose unloading
/// curves lose contact after the flat retracted by `recovery` (m) from the
/// closest approach: the roots of `span(delta_max) = recovery` (`span =
/// delta_max - delta_res`). `span` is continuous between the law's
/// breakpoints but may jump at them (the Kogut–Etsion fit does), so the
/// summits still touching need not be a suffix of the heights: each piece
/// between consecutive breakpoints (and the last, open-ended one) is
/// searched for its own sign change, each root found by bisection to a few
/// ulp. Empty when `recovery` is not finite or no plastic peak has that
/// span (elastic peaks lose contact at `delta = 0`, a fixed breakpoint).
/// The GW integral splits its retraction quadrature at each: the count
/// jumps there, and load (`~ x^(3/2)`) and radius (`~ x^(1/2)`) kink.
pub fn contact_loss_peaks<L: PlasticLoading + ?Sized>(law: &L, recovery: f64) -> Vec<f64> {
    let e = law.asperity().contact_modulus;
    let span = |dm: f64| Unloading::from_peak(dm, law.loading(dm), e).span;
    let lim = law.elastic_limit();
    if !(recovery.is_finite() && recovery > 0.0 && lim > 0.0) {
        return Vec::new();
    }
    let mut ends = vec![lim];
    ends.extend(
        law.breakpoint_interferences()
            .into_iter()
            .filter(|&b| b > lim),
    );
    span_crossings(span, recovery, ends, 0.0, 1, 0.0)
}

/// The roots of `span(x) = recovery` (ascending) between consecutive
/// `ends` and in the open-ended piece beyond the last (its end grown by
/// doubling from `2 max(last, recovery, floor)` until the span reaches
/// `recovery`). `span` may jump at the ends, so each piece is searched on
/// its own: on `scan` subintervals, the piece's ends taken `inset` of its
/// width inside, each sign change bisected to a few ulp.
pub(crate) fn span_crossings(
    span: impl Fn(f64) -> f64,
    recovery: f64,
    mut ends: Vec<f64>,
    floor: f64,
    scan: usize,
    inset: f64,
) -> Vec<f64> {
    ends.sort_by(f64::total_cmp);
    ends.dedup();
    let last = *ends.last().unwrap_or(&0.0);
    let mut hi = 2.0 * last.max(recovery).max(floor);
    for _ in 0..200 {
        if span(hi) >= recovery {
            break;
        }
        hi *= 2.0;
    }
    ends.push(hi);
    let below = |x: f64| span(x) < recovery;
    let mut roots = Vec::new();
    for w in ends.windows(2) {
        let (a, b) = (w[0], w[1]);
        let at = |k: usize| match k {
            0 => a + inset * (b - a),
            _ if k == scan => b - inset * (b - a),
            _ => a + (b - a) * k as f64 / scan as f64,
        };
        for k in 0..scan {
            let (mut lo, mut hi) = (at(k), at(k + 1));
            if below(lo) == below(hi) {
                continue;
            }
            let rising = below(lo);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if !(mid > lo && mid < hi) {
                    break;
                }
                if below(mid) == rising {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            roots.push(hi);
        }
    }
    roots
}

/// One asperity's memory for any interference path (approach, retract,
/// reload, ...): its largest interference so far.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaxInterference {
    /// Largest interference reached (m); `-inf` before the first step.
    pub delta_max: f64,
}

impl Default for MaxInterference {
    fn default() -> Self {
        MaxInterference {
            delta_max: f64::NEG_INFINITY,
        }
    }
}

impl MaxInterference {
    /// Moves the asperity to `delta` (m) and returns its state: the virgin
    /// approach branch while `delta` is a new maximum, the history branch
    /// [`crate::law::AsperityLaw::state_after`] otherwise.
    #[inline]
    pub fn step(&mut self, law: &dyn crate::law::AsperityLaw, delta: f64) -> ContactState {
        if delta >= self.delta_max {
            self.delta_max = delta;
            law.state(delta, crate::law::Branch::Approach)
        } else {
            law.state_after(delta, self.delta_max)
        }
    }
}
