//! Isotropic height power spectra `C(q)` and their moments.
//!
//! Convention (Persson 2001): the 2-D spectrum `C(q)` of an isotropic
//! surface depends on `q = |q|` only, with
//! `<h^2> = int d^2q C(q) = 2 pi int q C(q) dq`. The profile moments of
//! Nayak (1971) follow from the angular averages of `cos^n`:
//! - `m0 = 2 pi int q C dq` (height variance, m^2),
//! - `m2 = pi int q^3 C dq` (mean square slope of a profile; the mean
//!   square gradient is `g^2 = <|grad h|^2> = 2 m2 = 2 pi int q^3 C dq`),
//! - `m4 = (3 pi/4) int q^5 C dq` (mean square curvature of a profile).
//!
//! A [`Spectrum`] is a list of power-law [`Segment`]s,
//! `C(q) = c (q/q_lo)^(-e)` on `[q_lo, q_hi)`, so every moment and every
//! cumulative integral `int_{q_min}^{q} q^k C dq` is a closed form. The
//! analytic self-affine spectrum is two segments ([`Spectrum::self_affine`]);
//! the radial spectrum of a measured map ([`radial`]) is one flat segment per
//! annulus. The GW parameters from the moments use McCool's relations, the
//! same rules as `asperity surface` ([`crate::surface::GwParameters`]).

pub mod radial;
pub mod synthesis;

use crate::error::{positive, Allowed, Error, Result};
use crate::surface::{GwParameters, Moments, NayakPrediction};
use std::f64::consts::PI;

/// One power-law piece: `C(q) = c (q/q_lo)^(-exponent)` for
/// `q_lo <= q < q_hi` (`C` in m^4, `q` in rad/m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// Lower wavevector (rad/m), > 0.
    pub q_lo: f64,
    /// Upper wavevector (rad/m), > `q_lo`.
    pub q_hi: f64,
    /// `C(q_lo)` (m^4), >= 0.
    pub c: f64,
    /// Power-law exponent `e` of `C ~ q^-e` (0 for a flat piece).
    pub exponent: f64,
}

/// How to normalise an analytic spectrum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Normalisation {
    /// RMS height `sqrt(m0)` (m).
    HRms(f64),
    /// RMS gradient `g = sqrt(<|grad h|^2>) = sqrt(2 m2)` (dimensionless).
    SlopeRms(f64),
}

/// An isotropic power spectrum made of contiguous power-law segments.
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrum {
    segments: Vec<Segment>,
}

/// `(exp(x) - 1)/x`, 1 at 0, accurate for every x.
fn exprel(x: f64) -> f64 {
    if x.abs() < 1e-5 {
        1.0 + x / 2.0 + x * x / 6.0
    } else {
        x.exp_m1() / x
    }
}

impl Segment {
    /// `C(q)` on this segment (no range check).
    #[inline]
    pub fn c_at(&self, q: f64) -> f64 {
        if self.exponent == 0.0 {
            self.c
        } else {
            self.c * (q / self.q_lo).powf(-self.exponent)
        }
    }

    /// `int_{q_lo}^{q} q'^k C(q') dq'` for `q_lo <= q`, in closed form:
    /// `c q_lo^(k+1) ln(r) exprel(m ln r)`, `r = q/q_lo`, `m = k + 1 - e`
    /// (exact also where `m = 0`, the logarithmic case).
    pub fn integral_to(&self, k: f64, q: f64) -> f64 {
        if q <= self.q_lo || self.c == 0.0 {
            return 0.0;
        }
        // ln(q/q_lo) through ln_1p: exact near q_lo (Persson's w(q) there).
        let lr = ((q - self.q_lo) / self.q_lo).ln_1p();
        let m = k + 1.0 - self.exponent;
        self.c * self.q_lo.powf(k + 1.0) * lr * exprel(m * lr)
    }

    /// `int q^k C dq` over the whole segment.
    pub fn integral(&self, k: f64) -> f64 {
        self.integral_to(k, self.q_hi)
    }
}

impl Spectrum {
    /// A spectrum from contiguous segments (`q_hi` of one is `q_lo` of the
    /// next, to a relative 1e-12).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `q_lo`, `q_hi`, `c` or `exponent` of a
    /// bad segment; [`Error::Invalid`] naming `spectrum` when empty, not
    /// contiguous, or zero everywhere.
    pub fn from_segments(segments: Vec<Segment>) -> Result<Self> {
        if segments.is_empty() {
            return Err(Error::invalid("spectrum", "no segments"));
        }
        for (i, s) in segments.iter().enumerate() {
            positive("q_lo", s.q_lo)?;
            Allowed::open(s.q_lo, f64::INFINITY).check("q_hi", s.q_hi)?;
            Allowed::NON_NEGATIVE.check("c", s.c)?;
            Allowed::FINITE.check("exponent", s.exponent)?;
            if i > 0 {
                let prev = segments[i - 1].q_hi;
                if (s.q_lo - prev).abs() > 1e-12 * prev {
                    return Err(Error::invalid(
                        "spectrum",
                        format!(
                            "segment {i} starts at {} but the previous ends at {prev}",
                            s.q_lo
                        ),
                    ));
                }
            }
        }
        if segments.iter().all(|s| s.c == 0.0) {
            return Err(Error::invalid("spectrum", "zero everywhere"));
        }
        Ok(Spectrum { segments })
    }

    /// The self-affine spectrum of Persson (2006): flat between `q_long` and
    /// `q_roll`, `C ~ q^(-2(1+H))` from `q_roll` to `q_short`, zero outside;
    /// scaled to the given RMS height or RMS gradient. `q_long = q_roll`
    /// gives a pure power law.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `hurst` (in (0, 1]), `q_long` (> 0),
    /// `q_roll` (>= `q_long`), `q_short` (> `q_roll`), `h_rms` or
    /// `slope_rms` (> 0).
    pub fn self_affine(
        hurst: f64,
        q_long: f64,
        q_roll: f64,
        q_short: f64,
        norm: Normalisation,
    ) -> Result<Self> {
        Allowed {
            lo: 0.0,
            lo_inclusive: false,
            hi: 1.0,
            hi_inclusive: true,
        }
        .check("hurst", hurst)?;
        positive("q_long", q_long)?;
        Allowed::closed(q_long, f64::MAX).check("q_roll", q_roll)?;
        Allowed::open(q_roll, f64::INFINITY).check("q_short", q_short)?;
        let mut segs = Vec::new();
        if q_roll > q_long {
            segs.push(Segment {
                q_lo: q_long,
                q_hi: q_roll,
                c: 1.0,
                exponent: 0.0,
            });
        }
        segs.push(Segment {
            q_lo: q_roll,
            q_hi: q_short,
            c: 1.0,
            exponent: 2.0 * (1.0 + hurst),
        });
        let unit = Spectrum { segments: segs };
        let scale = match norm {
            Normalisation::HRms(h) => positive("h_rms", h)?.powi(2) / unit.m0(),
            Normalisation::SlopeRms(g) => {
                positive("slope_rms", g)?.powi(2) / unit.mean_square_gradient()
            }
        };
        Ok(unit.scaled(scale))
    }

    /// Every `C` multiplied by `factor` (> 0).
    fn scaled(mut self, factor: f64) -> Self {
        self.segments.iter_mut().for_each(|s| s.c *= factor);
        self
    }

    /// The segments, ascending in `q`.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// Smallest wavevector with `C` defined (rad/m).
    pub fn q_min(&self) -> f64 {
        self.segments[0].q_lo
    }

    /// Largest wavevector (rad/m).
    pub fn q_max(&self) -> f64 {
        self.segments[self.segments.len() - 1].q_hi
    }

    /// `C(q)` (m^4); 0 outside `[q_min, q_max)`.
    pub fn c(&self, q: f64) -> f64 {
        match self.segments.iter().find(|s| q >= s.q_lo && q < s.q_hi) {
            Some(s) => s.c_at(q),
            None => 0.0,
        }
    }

    /// `int q^k C(q) dq` over the whole spectrum.
    pub fn integral(&self, k: f64) -> f64 {
        self.segments.iter().map(|s| s.integral(k)).sum()
    }

    /// `int_{q_min}^{q} q'^k C(q') dq'`.
    pub fn cumulative(&self, k: f64, q: f64) -> f64 {
        let mut sum = 0.0;
        for s in &self.segments {
            if q <= s.q_lo {
                break;
            }
            sum += s.integral_to(k, q.min(s.q_hi));
        }
        sum
    }

    /// `m0 = 2 pi int q C dq` (m^2).
    pub fn m0(&self) -> f64 {
        2.0 * PI * self.integral(1.0)
    }

    /// `m2 = pi int q^3 C dq`.
    pub fn m2(&self) -> f64 {
        PI * self.integral(3.0)
    }

    /// `m4 = (3 pi/4) int q^5 C dq` (1/m^2).
    pub fn m4(&self) -> f64 {
        0.75 * PI * self.integral(5.0)
    }

    /// RMS height `sqrt(m0)` (m).
    pub fn h_rms(&self) -> f64 {
        self.m0().sqrt()
    }

    /// `g^2 = <|grad h|^2> = 2 pi int q^3 C dq`.
    pub fn mean_square_gradient(&self) -> f64 {
        2.0 * PI * self.integral(3.0)
    }

    /// RMS gradient `g` (Persson's rms slope).
    pub fn slope_rms(&self) -> f64 {
        self.mean_square_gradient().sqrt()
    }

    /// The moments `m0, m2, m4`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if a moment is 0 (a spectrum zero above its
    /// first segment cannot have all three > 0 only when it is all zero).
    pub fn moments(&self) -> Result<Moments> {
        Moments::new(self.m0(), self.m2(), self.m4())
    }

    /// McCool's GW parameters from the moments (as `asperity surface`).
    ///
    /// # Errors
    /// As [`Spectrum::moments`].
    pub fn gw_parameters(&self) -> Result<GwParameters> {
        Ok(GwParameters::from_moments(&self.moments()?))
    }

    /// Nayak's continuum summit statistics from the moments.
    ///
    /// # Errors
    /// As [`Spectrum::moments`].
    pub fn nayak(&self) -> Result<NayakPrediction> {
        Ok(NayakPrediction::from_moments(&self.moments()?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_form_moments_of_a_self_affine_spectrum() {
        let (h, ql, qr, qs) = (0.8, 1e5, 4e5, 4e8);
        let s = Spectrum::self_affine(h, ql, qr, qs, Normalisation::HRms(1e-9)).unwrap();
        assert!((s.h_rms() / 1e-9 - 1.0).abs() < 1e-14);
        // Direct closed forms of int q^k C with C0 = C(q_roll).
        let c0 = s.segments()[0].c;
        let e = 2.0 * (1.0 + h);
        let direct = |k: f64| {
            c0 * (qr.powf(k + 1.0) - ql.powf(k + 1.0)) / (k + 1.0)
                + c0 * qr.powf(e) * (qs.powf(k + 1.0 - e) - qr.powf(k + 1.0 - e)) / (k + 1.0 - e)
        };
        for k in [1.0, 2.0, 3.0, 5.0] {
            assert!((s.integral(k) / direct(k) - 1.0).abs() < 1e-12, "k = {k}");
        }
        // H = 1/2 makes int q^2 C logarithmic.
        let s = Spectrum::self_affine(0.5, ql, ql, qs, Normalisation::SlopeRms(0.3)).unwrap();
        let c0 = s.segments()[0].c;
        let log = c0 * ql.powi(3) * (qs / ql).ln();
        assert!((s.integral(2.0) / log - 1.0).abs() < 1e-13);
        assert!((s.slope_rms() - 0.3).abs() < 1e-15);
        assert!((s.cumulative(3.0, qs) / s.integral(3.0) - 1.0).abs() < 1e-14);
        assert_eq!(s.c(qs * 1.01), 0.0);
        assert!(Spectrum::self_affine(1.2, ql, qr, qs, Normalisation::HRms(1.0)).is_err());
        let e = Spectrum::self_affine(0.8, ql, ql / 2.0, qs, Normalisation::HRms(1.0));
        assert_eq!(e.unwrap_err().field(), Some("q_roll"));
    }
}
