//! Persson's distribution of interfacial separations `P(u)` and what the
//! flooded capillary model asks of it: the fraction of the nominal area
//! where the gap is below a height, and the gap's mean and RMS.
//!
//! (Almqvist, Campañá, Prodanov & Persson 2011, J. Mech. Phys. Solids 59,
//! 2355, eq. 5 there; Persson 2008, J. Phys.: Condens. Matter 20, 315007,
//! the flooded capillary bridges; Yang & Persson 2008 for `u_bar`.) As the
//! magnification `zeta = q/q0` grows, the apparent contact area `A(q)`
//! shrinks (`A(q)/A0 = erf(p w(q)/E*)`, [`super::Persson`]); the area
//! `-dA` that leaves contact between `q` and `q + dq` opens to a gap
//! spread like a Gaussian of mean `u_bar(q)` and variance `h_rms^2(q)`,
//! reflected at `u = 0`:
//!
//! ```text
//! P(u) = (A1/A0) delta(u) + int_{q0}^{q1} dq (-A'(q)/A0) [N(u; u_bar, h) + N(u; -u_bar, h)],
//! h_rms^2(q) = 2 pi int_q^{q1} q' C(q') dq',
//! u_bar(q)   = Persson's mean gap of the spectrum restricted to [q, q1]
//!              at the pressure p(q) = p A0/A(q) of the contact regions there,
//! -A'(q)/A0  = sqrt(pi) x w(q)^2 q^3 C(q) exp(-x^2),   x = p w(q)/E*,
//! ```
//!
//! `A1 = A(q1)` the real contact, `N(u; m, s)` the normal density. Its
//! integral is `A1/A0 + (1 - A1/A0) = 1`. The fraction below `H` is
//! `A1/A0 + int (-A'/A0) [Phi((H - u_bar)/h) - Phi((-H - u_bar)/h)] dq`;
//! the moments are those of the folded normal,
//! `E|X| = 2 h phi(u_bar/h) + u_bar (1 - 2 Q(u_bar/h))`,
//! `E X^2 = u_bar^2 + h^2`.
//!
//! The `q` integral is adaptive Gauss–Kronrod in `t = sqrt(q - q0)` on the
//! first segment (up to `2 q0`) and in `ln q` beyond, like
//! [`super::Persson::state`]; each node's `u_bar` is that function on the
//! truncated spectrum. The normalisation is integrated beside the rest and
//! its departure from 1 reported as the integration error.

use super::Persson;
use crate::error::{positive, Allowed, Result};
use crate::numeric::quadrature::{integrate_pieces_n, QuadOptions};
use crate::special::normal::{pdf, tail};
use crate::spectrum::{Segment, Spectrum};
use std::f64::consts::PI;

/// Relative tolerance of the integral over wavevectors.
pub const GAP_RTOL: f64 = 1e-10;

/// Persson's gap distribution at one mean pressure, summarised.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GapStatistics {
    /// Mean pressure `p` (Pa).
    pub pressure: f64,
    /// The height `H` (m) of [`GapStatistics::fraction_below`].
    pub height: f64,
    /// Real contact `A1/A0` (gap 0).
    pub contact_fraction: f64,
    /// `P(u < H)`: the fraction of the nominal area with a gap below `H`,
    /// contact included.
    pub fraction_below: f64,
    /// `int u P(u) du` (m).
    pub mean_gap: f64,
    /// `sqrt(int u^2 P(u) du)` (m).
    pub rms_gap: f64,
    /// `|int P(u) du - 1|` as integrated, plus the quadrature's own error
    /// estimate of `fraction_below`: its absolute error bound.
    pub error: f64,
}

impl Persson {
    /// The distribution of interfacial separations at mean pressure
    /// `pressure` (Pa), with the fraction of the area whose gap is below
    /// `height` (m) (module documentation).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `pressure` (finite, > 0) or
    /// `height` (finite, >= 0).
    pub fn gap_statistics(&self, pressure: f64, height: f64) -> Result<GapStatistics> {
        positive("pressure", pressure)?;
        Allowed::NON_NEGATIVE.check("height", height)?;
        let e = self.contact_modulus;
        let spectrum = &self.spectrum;
        let segs = spectrum.segments();
        let first = segs.iter().position(|s| s.c > 0.0).unwrap_or(0);
        let q0 = segs[first].q_lo;
        let contact = self.area_fraction(pressure);
        let prefix = Prefix::new(spectrum);
        let m0_half = spectrum.integral(1.0);
        // [-A'/A0, -A'/A0 P(u < H), -A'/A0 E|u|, -A'/A0 E u^2] per dq.
        let integrand = |q: f64| -> [f64; 4] {
            let c = prefix.c(q);
            if c == 0.0 {
                return [0.0; 4];
            }
            let w = self.w(q);
            let x = w * pressure / e;
            if !(x < 27.0) {
                // exp(-x^2) underflows: this area is still in contact.
                return [0.0; 4];
            }
            let density = PI.sqrt() * x * w * w * q * q * q * c * (-x * x).exp();
            if density == 0.0 {
                return [0.0; 4];
            }
            let a = super::special::erf(x);
            let ubar = self.mean_gap_above(&prefix, q, pressure / a);
            let h = (2.0 * PI * (m0_half - spectrum.cumulative(1.0, q)))
                .max(0.0)
                .sqrt();
            let (below, mean, square) = folded_normal(ubar, h, height);
            [density, density * below, density * mean, density * square]
        };
        let opts = QuadOptions::relative(GAP_RTOL);
        let qb = segs[first].q_hi.min(2.0 * q0);
        let near = integrate_pieces_n(
            |t| {
                let v = integrand(q0 + t * t);
                v.map(|f| 2.0 * t * f)
            },
            &[0.0, (qb - q0).sqrt()],
            &opts,
        );
        let mut points: Vec<f64> = vec![qb.ln()];
        points.extend(
            segs[first..]
                .iter()
                .filter(|s| s.q_hi > qb)
                .map(|s| s.q_hi.ln()),
        );
        let far = if points.len() > 1 {
            let r = integrate_pieces_n(
                |v| {
                    let q = v.exp();
                    integrand(q).map(|f| q * f)
                },
                &points,
                &opts,
            );
            (r.value, r.error)
        } else {
            ([0.0; 4], [0.0; 4])
        };
        let total = |i: usize| near.value[i] + far.0[i];
        let norm_error = (contact + total(0) - 1.0).abs();
        Ok(GapStatistics {
            pressure,
            height,
            contact_fraction: contact,
            fraction_below: (contact + total(1)).min(1.0),
            mean_gap: total(2),
            rms_gap: total(3).max(0.0).sqrt(),
            error: norm_error + near.error[1] + far.1[1],
        })
    }
}

/// The spectrum's segments with the running integrals `int q^3 C` at
/// their starts, so that `C(q)` and `int_{qz}^{q} q'^3 C dq'` cost a binary
/// search (a map's radial spectrum has one segment per annulus).
struct Prefix<'a> {
    segs: &'a [Segment],
    cum3: Vec<f64>,
}

impl<'a> Prefix<'a> {
    fn new(spectrum: &'a Spectrum) -> Self {
        let segs = spectrum.segments();
        let mut cum3 = Vec::with_capacity(segs.len() + 1);
        let mut acc = 0.0;
        cum3.push(0.0);
        for s in segs {
            acc += s.integral(3.0);
            cum3.push(acc);
        }
        Prefix { segs, cum3 }
    }

    /// The index of the segment holding `q` (clamped to the last).
    fn index(&self, q: f64) -> usize {
        self.segs
            .partition_point(|s| s.q_hi <= q)
            .min(self.segs.len() - 1)
    }

    /// `C(q)`, 0 outside the segments.
    fn c(&self, q: f64) -> f64 {
        let s = &self.segs[self.index(q)];
        if q >= s.q_lo && q < s.q_hi {
            s.c_at(q)
        } else {
            0.0
        }
    }

    /// `int_{qz}^{q} k^3 C dk` for `qz <= q`, the part in `qz`'s segment
    /// from the segment cut at `qz` (no cancellation near `qz`).
    fn cum3_from(&self, qz: f64, q: f64) -> f64 {
        let (i, j) = (self.index(qz), self.index(q));
        let cut = |s: &Segment, lo: f64| Segment {
            q_lo: lo,
            q_hi: s.q_hi,
            c: s.c_at(lo),
            exponent: s.exponent,
        };
        let si = cut(&self.segs[i], qz.max(self.segs[i].q_lo));
        if i == j {
            return si.integral_to(3.0, q);
        }
        si.integral(3.0) + (self.cum3[j] - self.cum3[i + 1]) + self.segs[j].integral_to(3.0, q)
    }
}

impl Persson {
    /// Persson's mean gap of the spectrum restricted to `[qz, q_max]` at
    /// the pressure `pressure` (Pa): `u_bar(qz)` (m), the same integral as
    /// [`Persson::state`] with `w` measured from `qz`.
    fn mean_gap_above(&self, pre: &Prefix, qz: f64, pressure: f64) -> f64 {
        let (e, gamma) = (self.contact_modulus, self.gamma);
        let f = |q: f64| {
            let c = pre.c(q);
            if c == 0.0 {
                return 0.0;
            }
            let cum = pre.cum3_from(qz, q);
            if !(cum > 0.0) {
                return 0.0;
            }
            let w = 1.0 / (PI * cum).sqrt();
            let s = w * pressure / e;
            let mut inner = 0.5 * gamma * super::special::e1(s * s);
            if gamma < 1.0 {
                inner += 3.0 * (1.0 - gamma) * super::f_erf2(s);
            }
            if inner == 0.0 {
                return 0.0;
            }
            q * q * c * w * inner
        };
        let i = pre.index(qz);
        let q1 = pre.segs[pre.segs.len() - 1].q_hi;
        if !(qz < q1) {
            return 0.0;
        }
        let qb = pre.segs[i].q_hi.min(2.0 * qz);
        let ends = pre.segs[i..].iter().map(|s| s.q_hi);
        PI.sqrt() * super::integrate_from(f, qz, qb, ends).0
    }
}

/// For `|X|`, `X ~ N(m, s^2)` (`m >= 0`): `P(|X| < H)`, `E|X|`, `E X^2`.
/// A point mass at `m` when `s = 0`.
fn folded_normal(m: f64, s: f64, height: f64) -> (f64, f64, f64) {
    if !(s > 0.0) {
        return (f64::from(u8::from(m < height)), m, m * m);
    }
    let (a, b) = ((height - m) / s, (height + m) / s);
    // Phi(a) - Phi(-b), from tails where each is small.
    let below = if a < 0.0 {
        tail(-a) - tail(b)
    } else {
        1.0 - tail(a) - tail(b)
    };
    let z = m / s;
    let mean = 2.0 * s * pdf(z) + m * (1.0 - 2.0 * tail(z));
    (below.clamp(0.0, 1.0), mean, m * m + s * s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::Normalisation;

    /// `u_bar(qz)` against [`Persson::state`] on the spectrum cut at `qz`
    /// (the same integral by the other code path: adaptive quadrature on
    /// each to 1e-12).
    #[test]
    fn mean_gap_above_is_persson_on_the_cut_spectrum() {
        let s = Spectrum::self_affine(0.7, 1e6, 3e6, 1e9, Normalisation::HRms(1e-8)).unwrap();
        for gamma in [1.0, 0.45] {
            let m = Persson::new(s.clone(), 1e9, gamma).unwrap();
            let pre = Prefix::new(&s);
            for (qz, p) in [(1e6, 1e6), (2e6, 3e6), (5e7, 2e7)] {
                let segs: Vec<Segment> = s
                    .segments()
                    .iter()
                    .filter(|g| g.q_hi > qz)
                    .map(|g| Segment {
                        q_lo: g.q_lo.max(qz),
                        c: g.c_at(g.q_lo.max(qz)),
                        ..*g
                    })
                    .collect();
                let cut = Persson::new(Spectrum::from_segments(segs).unwrap(), 1e9, gamma).unwrap();
                let want = cut.state(p).unwrap().mean_gap;
                let got = m.mean_gap_above(&pre, qz, p);
                assert!((got / want - 1.0).abs() < 1e-10, "{qz} {p}: {got} {want}");
            }
        }
    }

    #[test]
    fn folded_normal_limits() {
        // m = 0: half-normal, P(|X| < s) = erf(1/sqrt 2), E|X| = s sqrt(2/pi).
        let (p, m, sq) = folded_normal(0.0, 2.0, 2.0);
        assert!((p - 0.682_689_492_137_085_9).abs() < 1e-15);
        assert!((m - 2.0 * (2.0 / PI).sqrt()).abs() < 1e-15);
        assert_eq!(sq, 4.0);
        // Far from 0 it is the normal itself.
        let (p, m, _) = folded_normal(100.0, 1.0, 100.0);
        assert!((p - 0.5).abs() < 1e-15 && (m - 100.0).abs() < 1e-12);
    }
}
