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
//!
//! Distributions (one file each; [`DistributionKind::build`] builds them from their names):
//! [`Gaussian`] (closed `F_n` for `n = 0, 1/2, ..., 5/2`), [`Exponential`]
//! (GW's `e^-s`; closed for integer and half-integer `n`), [`Weibull`]
//! (unit standard deviation, origin at the lowest summit),
//! [`TruncatedGaussian`] (bounded above) and [`Empirical`] (measured
//! heights; `F_n` is the exact sample average).

use std::fmt;

/// Largest order `n` of [`HeightDistribution::moment_above_checked`]: the
/// GW integrals use `n <= 5/2`; `Gamma(n + 1)` overflows f64 past 170.
pub const MAX_MOMENT_ORDER: f64 = 100.0;

/// A standardised summit-height distribution. Object-safe, `Send + Sync`.
///
/// Built once with validated parameters; evaluation never fails.
pub trait HeightDistribution: Send + Sync + fmt::Debug {
    /// Short lower-case name (`"gaussian"`, `"exponential"`, ...).
    fn name(&self) -> &'static str;

    /// Probability density `phi(s)`.
    fn pdf(&self, s: f64) -> f64;

    /// [`pdf`](HeightDistribution::pdf) of every `s[i]` into `out[i]` (the
    /// shorter slice bounds the work): a quadrature panel's nodes in one
    /// call. Default: one `pdf` after another; the Gaussian's is written
    /// for vector registers.
    fn pdf_batch(&self, s: &[f64], out: &mut [f64]) {
        for (o, &x) in out.iter_mut().zip(s) {
            *o = self.pdf(x);
        }
    }

    /// `ln phi(s)`, finite where `phi(s)` underflows (default: `ln` of
    /// [`pdf`](HeightDistribution::pdf), `-inf` there).
    fn log_pdf(&self, s: f64) -> f64 {
        self.pdf(s).ln()
    }

    /// `phi(s)/phi(r)`, accurate where both densities underflow (default:
    /// `exp(log_pdf(s) - log_pdf(r))`). Integrators factor `phi(r)` out of
    /// far-tail integrals with it.
    fn pdf_ratio(&self, s: f64, r: f64) -> f64 {
        (self.log_pdf(s) - self.log_pdf(r)).exp()
    }

    /// Height (at most the support's upper end) above `s` where `ln phi`
    /// has fallen by `drop` below its value at `max(s, 0)` (the densities
    /// are standardised: the bulk is near 0), so that the density beyond
    /// carries a fraction of about `exp(-drop)` of the integrals from `s`
    /// up. Default: steps doubling from `1/(1 + max(s, 0))` until
    /// [`log_pdf`](HeightDistribution::log_pdf) has fallen that far.
    fn decay_end(&self, s: f64, drop: f64) -> f64 {
        let (_, hi) = self.support();
        let r = s.max(0.0);
        let target = self.log_pdf(r) - drop;
        let mut step = 1.0 / (1.0 + r);
        let mut top = r + step;
        for _ in 0..64 {
            if top >= hi || !(self.log_pdf(top) > target) {
                break;
            }
            step *= 2.0;
            top = r + step;
        }
        top.min(hi)
    }

    /// Tail probability `P(S > s) = F_0(s)`, accurate in relative terms far
    /// into the upper tail.
    fn tail(&self, s: f64) -> f64;

    /// Support `[lo, hi]` (infinite ends allowed).
    fn support(&self) -> (f64, f64);

    /// `F_n(h) = int_h^inf (s - h)^n phi(s) ds` for real `n >= 0`: closed
    /// form where one exists, otherwise quadrature. NaN only for NaN input
    /// or `n < 0`.
    fn moment_above(&self, n: f64, h: f64) -> f64;

    /// [`moment_above`](HeightDistribution::moment_above) with its
    /// arguments checked and a finite value promised: `n` in
    /// `[0, `[`MAX_MOMENT_ORDER`]`]`, `h` finite, and `F_n(h)` within f64
    /// (it grows like `|h|^n` below the distribution and like `Gamma(n+1)`
    /// at any `h`).
    ///
    /// # Errors
    /// [`Error::OutOfRange`](crate::Error::OutOfRange) naming `n` or `h`;
    /// [`Error::Invalid`](crate::Error::Invalid) naming `h` (or `n` where
    /// even `h` above the distribution's mode overflows) when `F_n(h)`
    /// overflows f64.
    fn moment_above_checked(&self, n: f64, h: f64) -> crate::Result<f64> {
        crate::error::Allowed::closed(0.0, MAX_MOMENT_ORDER).check("n", n)?;
        crate::error::finite("h", h)?;
        let f = self.moment_above(n, h);
        if f.is_finite() {
            return Ok(f);
        }
        let name = if h >= 0.0 { "n" } else { "h" };
        Err(crate::Error::invalid(
            name,
            format!(
                "F_{n}({h:e}) of the {} distribution overflows f64",
                self.name()
            ),
        ))
    }

    /// Quantile `s` with `P(S <= s) = p`, `p` in `(0, 1)`; used to sample.
    fn quantile(&self, p: f64) -> f64;

    /// Upper quantile `s` with `P(S > s) = q`, `q` in `(0, 1)`: accurate
    /// for small `q`, where `1 - q` has lost its digits (the highest
    /// summits of a large draw). Default: `quantile(1 - q)`, which loses
    /// nothing where `q` is not below ~1e-8 relative to the quantile's own
    /// slope (distributions with an accurate closed form override it).
    fn quantile_upper(&self, q: f64) -> f64 {
        self.quantile(1.0 - q)
    }

    /// Interval outside which the density carries less than `eps` of the
    /// probability in each tail; integrators skip heights beyond it.
    fn numerical_support(&self, eps: f64) -> (f64, f64);

    /// The standardised heights themselves, ascending, when the
    /// distribution is a finite sample (measured summits): integrals over it
    /// are then exact averages over these points, and integrators sum them
    /// instead of integrating a smoothed density. Default: `None`.
    fn sample_points(&self) -> Option<&[f64]> {
        None
    }

    /// Whether [`moment_above`](HeightDistribution::moment_above) is a closed
    /// form accurate to about 1e-13 relative for this `n` (not quadrature).
    /// Integrators use closed forms only then. Default: `false`.
    fn closed_form_moment(&self, _n: f64) -> bool {
        false
    }

    /// Whether this is the standard normal density, whose shifts have the
    /// product form `phi(s + d) = phi(s) exp(-s d) exp(-d^2/2)`: integrators
    /// of many shifted copies of the density then step from one shift to
    /// the next with one `exp` per node and distinct step
    /// (`roughsphere/shifted_density.rs`). Default: `false`.
    fn is_standard_normal(&self) -> bool {
        false
    }
}

mod empirical;
mod exponential;
mod gaussian;
mod quad;
mod truncated;
mod weibull;

pub use empirical::Empirical;
pub use exponential::Exponential;
pub use gaussian::Gaussian;
pub use truncated::{TruncatedGaussian, MIN_TRUNCATION};
pub use weibull::Weibull;

mod kind;
pub use kind::{DistributionKind, DistributionParams};
