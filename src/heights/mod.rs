//! Summit-height distributions, in standardised units.
//!
//! A rough surface's summit heights are `z = sigma s` where `s` has the
//! standardised density `phi(s)` of a [`HeightDistribution`] and `sigma` (m)
//! is the summit-height standard deviation (for GW's exponential form,
//! `phi(s) = e^-s`, `sigma` is its scale). Everything here is dimensionless;
//! the surface model applies `sigma`.
//!
//! The central quantity of Greenwood–Williamson theory is
//! `F_n(h) = int_h^inf (s - h)^n phi(s) ds` (no prefactor), for real `n >= 0`.

use std::fmt;

/// A standardised summit-height distribution. Object-safe, `Send + Sync`.
///
/// Built once with validated parameters; evaluation never fails.
pub trait HeightDistribution: Send + Sync + fmt::Debug {
    /// Short lower-case name (`"gaussian"`, `"exponential"`, ...).
    fn name(&self) -> &'static str;

    /// Probability density `phi(s)`.
    fn pdf(&self, s: f64) -> f64;

    /// Tail probability `P(S > s) = F_0(s)`, accurate in relative terms far
    /// into the upper tail.
    fn tail(&self, s: f64) -> f64;

    /// Support `[lo, hi]` (infinite ends allowed).
    fn support(&self) -> (f64, f64);

    /// `F_n(h) = int_h^inf (s - h)^n phi(s) ds` for real `n >= 0`: closed
    /// form where one exists, otherwise quadrature. NaN only for NaN input
    /// or `n < 0`.
    fn moment_above(&self, n: f64, h: f64) -> f64;

    /// Quantile `s` with `P(S <= s) = p`, `p` in `(0, 1)`; used to sample.
    fn quantile(&self, p: f64) -> f64;

    /// Interval outside which the density carries less than `eps` of the
    /// probability in each tail; integrators skip heights beyond it.
    fn numerical_support(&self, eps: f64) -> (f64, f64);

    /// Whether [`moment_above`](HeightDistribution::moment_above) is a closed
    /// form accurate to about 1e-13 relative for this `n` (not quadrature).
    /// Integrators use closed forms only then. Default: `false`.
    fn closed_form_moment(&self, _n: f64) -> bool {
        false
    }
}
