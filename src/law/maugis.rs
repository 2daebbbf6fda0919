//! Maugis–Dugdale (Maugis 1992): the exact solution of a sphere on a flat
//! with a Dugdale (constant-stress) cohesive zone, including the non-contact
//! branch.
//!
//! # Units and equations
//! Maugis units: `A = a (K/(pi w R^2))^(1/3)`, `C = c (K/(pi w R^2))^(1/3)`
//! (`c` = outer radius of the Dugdale zone), `Pbar = P/(pi w R)`,
//! `Dbar = delta (K^2/(pi^2 w^2 R))^(1/3)`, `K = 4E*/3`, and
//! `lambda = 2 sigma0 (R/(pi w K^2))^(1/3)`. With `m = c/a`,
//! `s = sqrt(m^2-1)`, `t = atan(s)` (physics.md, verified):
//!
//! ```text
//! (1)  (lambda A^2/2) [s + (m^2-2) t] + (4 lambda^2 A/3) [s t - m + 1] = 1
//! (2)  Pbar = A^3 - lambda A^2 [s + m^2 t]
//! (3)  Dbar = A^2 - (4/3) A lambda s
//! ```
//!
//! # Parametrisation (contact branch)
//! The branch is parametrised by the angle `t = atan(s)` in `(0, pi/2)`.
//! Multiplying (1) by `cos^2 t` it becomes a quadratic in `C = A/cos t = mA`:
//!
//! ```text
//! alpha C^2 + beta C - 1 = 0,  alpha = (lambda/4) (sin 2t - 2t cos 2t),
//!                              beta  = (4 lambda^2/3) (t sin t - (1 - cos t))
//! C = 2 / (beta + sqrt(beta^2 + 4 alpha))          (no cancellation)
//! A = C cos t,  Pbar = C^2 [C cos^3 t - lambda (sin t cos t + t)],
//! Dbar = C^2 cos^2 t - (4/3) lambda C sin t.
//! ```
//!
//! `t -> 0` (`m -> 1`) is deep contact (`A ~ t^(-3/2)`); there
//! `sin u - u cos u` (`u = 2t`) is summed as its series and
//! `1 - cos t = sin^2 t/(1 + cos t)`. `t -> pi/2` (`m -> inf`) is `A -> 0`;
//! near it the complementary angle `y = pi/2 - t` is carried exactly, so no
//! `m^2` ever overflows. At `t = pi/2` the branch ends at `A = 0`,
//! `C = C0`, where it meets the non-contact branch.
//!
//! # Non-contact branch (`a = 0`)
//! A Dugdale disc of tension `sigma0` over `r < c` on the half-space, no
//! contact. The surface under a uniform traction `p` on `r < c` moves by
//! `u(r) = (4 p c/(pi E*)) E(r/c)` (Johnson §3.4), so `u(0) = 2 p c/E*` and
//! `u(c) = 4 p c/(pi E*)`, towards the sphere for a tension. The gap is
//! `h(r) = -delta + r^2/(2R) - u(r)`; Dugdale's condition is that the gap
//! at the edge of the zone equals the range `delta_t = w/sigma0`:
//!
//! ```text
//! -delta + c^2/(2R) - 4 sigma0 c/(pi E*) = w/sigma0,      P = -sigma0 pi c^2.
//! ```
//!
//! In Maugis units (`sigma0 c/K = (lambda/2) C` times the interference
//! scale, `w/sigma0 = 2/(pi lambda)` times it):
//!
//! ```text
//! Dbar = C^2/2 - b C - 2/(pi lambda),  b = 8 lambda/(3 pi);   Pbar = -(pi lambda/2) C^2.
//! ```
//!
//! The branch is valid while the centre stays open, `h(0) >= 0`, i.e.
//! `Dbar <= -(4/3) lambda C`; equality gives
//! `(pi lambda/4) C^2 + (4 lambda^2/3)(pi/2 - 1) C = 1`, which is exactly
//! (1)-(3) at `A -> 0` (`m -> inf`, `mA -> C`): the two branches join
//! continuously at `C = C0`, `Dbar_j = -(4/3) lambda C0`,
//! `Pbar_j = -(pi lambda/2) C0^2`. As `lambda -> 0` the elastic term
//! `b C` vanishes and `Pbar = -2 - pi lambda Dbar`, i.e.
//! `P = 2 pi R (sigma0 g - w)` with `g = -delta` the rigid gap: the
//! Derjaguin (rigid, DMT-like) attraction of the Dugdale potential, `-2 pi w R`
//! at `g = 0` and zero at `g = delta_t` (see also Barthel, §6).
//!
//! # Stability, hysteresis and the instabilities
//! Follow the whole curve from `C = 0` (`Dbar = -2/(pi lambda)`, no force)
//! through the non-contact branch to the junction and down the contact
//! branch to deep contact. `Dbar` first decreases (for every `lambda`,
//! `dDbar/dC = C - b < 0` at `C = 0`), reaches a single minimum, then
//! increases without bound (checked for `lambda` in `[1e-3, 1e3]` by the
//! tests). Under displacement control the states past the minimum are
//! stable, the others unstable. Hence:
//! - **Approach**: no force until `Dbar_cut = -2/(pi lambda)`
//!   (`delta = -w/sigma0`, the gap at the centre equals the Dugdale range),
//!   then a jump-in to the stable state at the same `Dbar`: on the
//!   non-contact branch at `C = 2b` when `2b <= C0`
//!   (`lambda <= (9/32)^(1/3) = 0.6552`; the asperity then slides into
//!   contact continuously), otherwise straight into contact.
//! - **Retract**: the stable branch down to the minimum of `Dbar`, then a
//!   snap to zero force. For `lambda < lambda_c = (9 pi/(16 (pi-1)))^(1/3)
//!   = 0.93795` the minimum is on the non-contact branch at `C = b`
//!   (`Pbar = -32 lambda^3/(9 pi)`, `Dbar = -2/(pi lambda) - 32 lambda^2/(9 pi^2)`):
//!   the contact radius shrinks continuously to zero at the junction (no
//!   snap out of contact), then the Dugdale zone itself snaps off, with a
//!   force that vanishes like `lambda^3`. For `lambda >= lambda_c` it is on
//!   the contact branch (`dDbar/dt = 0`), the JKR-like jump-out.
//!   [`AsperityLaw::pull_off`] under [`Control::Displacement`] returns that
//!   snap in both cases (radius 0 when it is the non-contact one), so it is
//!   never `None` for `lambda > 0`: something always snaps in the Dugdale
//!   idealisation. [`MaugisCurve::contact_loss_bar`] tells when contact is
//!   lost continuously.
//! - The load is exactly zero on every branch below the retract minimum:
//!   that is the cutoff (below the approach threshold `Dbar_cut`, since the
//!   non-contact branch bends back below it).
//! - Load control: pull-off at the minimum of `Pbar`, always on the contact
//!   branch.

use super::{AsperityLaw, Branch, ContactState, Control, Instability, LawKernels};
use crate::error::{Allowed, Result};
use crate::material::MaugisScales;
use crate::numeric::roots::brent;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

/// Smallest `lambda` accepted. Below it MD is DMT to better than 2e-9 in
/// the pull-off (use [`super::Dmt`]), and the pull-off contact radius
/// falls below what the construction scan resolves.
pub const LAMBDA_MIN: f64 = 1e-6;
/// Largest `lambda` accepted. Above it MD is JKR to better than 2e-11 in
/// the pull-off (use [`super::Jkr`]).
pub const LAMBDA_MAX: f64 = 1e6;
/// Smallest `lambda` of the dense tests (property tests, references);
/// [`LAMBDA_MIN`] and [`LAMBDA_MAX`] are tested at the ends.
pub const LAMBDA_MIN_TESTED: f64 = 1e-3;
/// Largest `lambda` of the dense tests.
pub const LAMBDA_MAX_TESTED: f64 = 1e3;
/// `lambda_c = (9 pi/(16 (pi - 1)))^(1/3)`: below it the displacement-
/// controlled snap is on the non-contact branch (contact is lost
/// continuously), above it on the contact branch.
pub const LAMBDA_CONTINUOUS_DETACH: f64 = 0.937_947_457_210_712_3;
/// `(9/32)^(1/3)`: below it the jump-in lands on the non-contact branch.
pub const LAMBDA_NON_CONTACT_JUMP_IN: f64 = 0.655_185_348_552_224_2;

/// Deepest tabulated angle: `A(t) > 1e16`, where Hertz is exact to < 1e-24.
const T_DEEP: f64 = 1e-12;
/// Absolute angle tolerance of the root finders: Brent then stops at a few
/// ulps of the angle.
const XTOL: f64 = 1e-300;
/// Table nodes per decade of `t` in the deep-contact part.
const PER_DECADE: f64 = 16.0;
/// Table nodes in the `y = pi/2 - t` part.
const Y_NODES: usize = 48;

/// `sin u - u cos u` series coefficients: `(-1)^(k+1) 2k/(2k+1)!`.
const F_SERIES: [f64; 10] = [
    0.3333333333333333,
    -0.03333333333333333,
    0.0011904761904761906,
    -2.2045855379188714e-05,
    2.505210838544172e-07,
    -1.9270852604185937e-09,
    1.0706029224547743e-11,
    -4.498331606952833e-14,
    1.4797143443923793e-16,
    -3.9145882126782523e-19,
];

/// One point of the Maugis–Dugdale curve, in Maugis units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaugisPoint {
    /// Contact radius `A` (0 on the non-contact branch).
    pub radius_bar: f64,
    /// Outer radius `C` of the Dugdale zone.
    pub outer_radius_bar: f64,
    /// Load `Pbar` (> 0 compressive).
    pub load_bar: f64,
    /// Interference `Dbar`.
    pub interference_bar: f64,
}

/// A contact-branch angle `t` with its complement `y = pi/2 - t`; the
/// smaller of the two is exact, the other is derived from it.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Angle {
    t: f64,
    y: f64,
}

impl Angle {
    fn from_t(t: f64) -> Self {
        Angle {
            t,
            y: FRAC_PI_2 - t,
        }
    }
    fn from_y(y: f64) -> Self {
        Angle {
            t: FRAC_PI_2 - y,
            y,
        }
    }
    /// Along the variable that is exact here: `t` for `t <= pi/4`, else `y`.
    fn uses_t(self) -> bool {
        self.t <= FRAC_PI_4
    }
}

/// Contact-branch quantities at one angle.
#[derive(Debug, Clone, Copy)]
struct Raw {
    c_big: f64,
    cos: f64,
    sin: f64,
    load: f64,
    interference: f64,
    alpha: f64,
    beta: f64,
}

/// One table node on the stable contact branch.
#[derive(Debug, Clone, Copy)]
struct Node {
    angle: Angle,
    d: f64,
    /// `dt/dDbar` (infinite at a fold).
    dt_dd: f64,
}

/// The dimensionless Maugis–Dugdale curve for one `lambda`, with its
/// instabilities precomputed and a table for fast inversion `Dbar -> state`.
#[derive(Debug, Clone)]
pub struct MaugisCurve {
    lambda: f64,
    /// `b = 8 lambda/(3 pi)`.
    b: f64,
    /// `Dbar_cut = -2/(pi lambda)`.
    d_cut: f64,
    junction: MaugisPoint,
    detach: MaugisPoint,
    jump_in: MaugisPoint,
    pull_off: MaugisPoint,
    zero_load: MaugisPoint,
    /// Angle of the load-controlled pull-off.
    pull_angle: Angle,
    /// Whether the stable branch includes non-contact states
    /// (`lambda < lambda_c`).
    non_contact_stable: bool,
    /// Stable contact branch, `d` ascending (angle from the top down).
    nodes: Vec<Node>,
}

impl MaugisCurve {
    /// The curve for Maugis parameter `lambda` in `[1e-6, 1e6]`
    /// ([`LAMBDA_MIN`], [`LAMBDA_MAX`]; densely tested over `[1e-3, 1e3]`).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `lambda`.
    pub fn new(lambda: f64) -> Result<Self> {
        let mut curve = Self::bare(lambda)?;
        let b = curve.b;
        let c0 = curve.junction.outer_radius_bar;
        let samples = curve.scan();
        // One scan: every sample's raw quantities computed once.
        let raws: Vec<Raw> = samples.iter().map(|&a| curve.raw(a)).collect();
        // Displacement-controlled snap: the minimum of Dbar.
        let top = if curve.non_contact_stable {
            curve.detach = curve.non_contact_point(b);
            Angle::from_y(0.0)
        } else {
            let a = curve.refine(
                &samples,
                &raws,
                |r| r.interference,
                |c, a| c.d_interference(a),
            );
            curve.detach = curve.point(a);
            a
        };
        curve.build_table(top);
        // Load-controlled pull-off: the minimum of Pbar (contact branch).
        let ap = curve.refine(&samples, &raws, |r| r.load, |c, a| c.d_load(a));
        curve.pull_off = curve.point(ap);
        curve.pull_angle = ap;
        // Zero load on the stable side of the pull-off (t below it).
        curve.zero_load = curve.zero_load_point(ap);
        // Jump-in landing at Dbar_cut.
        curve.jump_in = if 2.0 * b <= c0 {
            curve.non_contact_point(2.0 * b)
        } else {
            curve.stable_point(curve.d_cut)
        };
        Ok(curve)
    }

    /// The closed-form parts of the curve at `lambda` (junction, constants);
    /// the instabilities and the table are left empty.
    fn bare(lambda: f64) -> Result<Self> {
        Allowed::closed(LAMBDA_MIN, LAMBDA_MAX).check("lambda", lambda)?;
        let b = 8.0 * lambda / (3.0 * PI);
        let qa = PI * lambda / 4.0;
        let qb = 4.0 * lambda * lambda / 3.0 * (FRAC_PI_2 - 1.0);
        let c0 = 2.0 / (qb + (qb * qb + 4.0 * qa).sqrt());
        Ok(MaugisCurve {
            lambda,
            b,
            d_cut: -2.0 / (PI * lambda),
            junction: MaugisPoint {
                radius_bar: 0.0,
                outer_radius_bar: c0,
                load_bar: -0.5 * PI * lambda * c0 * c0,
                interference_bar: -4.0 / 3.0 * lambda * c0,
            },
            detach: MaugisPoint::ZERO,
            jump_in: MaugisPoint::ZERO,
            pull_off: MaugisPoint::ZERO,
            zero_load: MaugisPoint::ZERO,
            pull_angle: Angle::from_y(0.0),
            non_contact_stable: b < c0,
            nodes: Vec::new(),
        })
    }

    /// Maugis parameter `lambda`.
    pub fn lambda(&self) -> f64 {
        self.lambda
    }

    /// Contact-branch point at `m = c/a > 1` (`m = +inf` gives the junction
    /// with the non-contact branch). Both stable and unstable parts.
    /// Returns `None` for `m <= 1` or NaN.
    pub fn point_at_m(&self, m: f64) -> Option<MaugisPoint> {
        if !(m > 1.0) {
            return None;
        }
        if m == f64::INFINITY {
            return Some(self.junction);
        }
        let s = ((m - 1.0) * (m + 1.0)).sqrt();
        let angle = if s <= 1.0 {
            Angle::from_t(s.atan())
        } else {
            Angle::from_y((1.0 / s).atan())
        };
        Some(self.point(angle))
    }

    /// Non-contact point with Dugdale-zone radius `C` in `[0, C0]`
    /// (clamped): `Pbar = -(pi lambda/2) C^2`,
    /// `Dbar = C^2/2 - (8 lambda/(3 pi)) C - 2/(pi lambda)`.
    pub fn non_contact_point(&self, c_bar: f64) -> MaugisPoint {
        let c = c_bar.clamp(0.0, self.junction.outer_radius_bar);
        MaugisPoint {
            radius_bar: 0.0,
            outer_radius_bar: c,
            load_bar: -0.5 * PI * self.lambda * c * c,
            interference_bar: c * (0.5 * c - self.b) + self.d_cut,
        }
    }

    /// Where the contact branch meets the non-contact branch (`A = 0`,
    /// `C = C0`).
    pub fn junction_bar(&self) -> MaugisPoint {
        self.junction
    }

    /// Load-controlled pull-off: the most tensile point of the curve.
    pub fn pull_off_bar(&self) -> MaugisPoint {
        self.pull_off
    }

    /// Displacement-controlled snap-off on retraction (the minimum of
    /// `Dbar`); on the non-contact branch (`radius_bar = 0`) for
    /// `lambda < lambda_c`.
    pub fn jump_out_bar(&self) -> MaugisPoint {
        self.detach
    }

    /// Where contact is lost continuously on retraction (the junction),
    /// when it is (`lambda < lambda_c`); `None` when the contact snaps.
    pub fn contact_loss_bar(&self) -> Option<MaugisPoint> {
        self.non_contact_stable.then_some(self.junction)
    }

    /// Jump-in on approach: the state reached at `Dbar_cut = -2/(pi lambda)`.
    pub fn jump_in_bar(&self) -> MaugisPoint {
        self.jump_in
    }

    /// `Dbar_cut = -2/(pi lambda)`: where the approaching asperity first
    /// feels the Dugdale stress (`delta = -w/sigma0`).
    pub fn attach_bar(&self) -> f64 {
        self.d_cut
    }

    /// Zero-load point on the stable branch.
    pub fn zero_load_bar(&self) -> MaugisPoint {
        self.zero_load
    }

    /// The load-controlled stable state (the branch beyond the pull-off) at
    /// load `Pbar`; `None` below the pull-off load or for NaN.
    pub fn point_at_load(&self, p: f64) -> Option<MaugisPoint> {
        if !(p >= self.pull_off.load_bar) {
            return None;
        }
        let deep = self.point(Angle::from_t(T_DEEP));
        if p >= deep.load_bar {
            // Hertz beyond the deepest tabulated point.
            let a = p.cbrt();
            return Some(MaugisPoint {
                radius_bar: a,
                outer_radius_bar: a,
                load_bar: p,
                interference_bar: a * a,
            });
        }
        let f = |t: f64| self.raw(Angle::from_t(t)).load - p;
        let t = brent(f, T_DEEP, self.pull_angle.t, XTOL)?;
        Some(self.point(Angle::from_t(t)))
    }

    /// State `(A, Pbar)` at interference `Dbar` on `branch` (zero load
    /// below the branch's threshold, NaN gives zero).
    #[inline]
    pub fn state_bar(&self, d: f64, branch: Branch) -> (f64, f64) {
        let lo = match branch {
            Branch::Approach => self.d_cut,
            Branch::Retract => self.detach.interference_bar,
        };
        if !(d >= lo) {
            return (0.0, 0.0);
        }
        let p = self.stable_point(d);
        (p.radius_bar, p.load_bar)
    }

    /// The stable (displacement-controlled) state at `Dbar >= ` the
    /// jump-out interference; the jump-out point itself below it.
    pub fn stable_point(&self, d: f64) -> MaugisPoint {
        if !(d > self.detach.interference_bar) {
            return self.detach;
        }
        if self.non_contact_stable && d <= self.junction.interference_bar {
            // Larger root of C^2/2 - b C - 2/(pi lambda) = Dbar.
            let disc = (self.b * self.b + 2.0 * (d - self.d_cut)).max(0.0);
            return self.non_contact_point(self.b + disc.sqrt());
        }
        let last = self.nodes.len() - 1;
        if d >= self.nodes[last].d {
            // Deep contact beyond the table: Hertz to < 1e-24 relative.
            let a = d.sqrt();
            return MaugisPoint {
                radius_bar: a,
                outer_radius_bar: a,
                load_bar: d * a,
                interference_bar: d,
            };
        }
        // First node with d_i > d; the root lies in [i-1, i].
        let i = self.nodes.partition_point(|n| n.d <= d).clamp(1, last);
        let (lo, hi) = (self.nodes[i - 1], self.nodes[i]);
        let (angle, r) = self.solve_interference(lo, hi, d);
        MaugisPoint {
            radius_bar: r.c_big * r.cos,
            outer_radius_bar: r.c_big,
            load_bar: r.load,
            interference_bar: r.interference,
        }
        .or_junction(angle, self.junction)
    }

    /// Angle in the cell `[lo, hi]` (ascending `Dbar`) where `Dbar = d`:
    /// cubic Hermite start from the table (`x(Dbar)` with the nodes'
    /// slopes), then Newton safeguarded by bisection on the cell, in the
    /// variable that is exact there (`t`, or `y = pi/2 - t` near the
    /// junction). Stops at a few ulps of the angle.
    #[inline]
    fn solve_interference(&self, lo: Node, hi: Node, d: f64) -> (Angle, Raw) {
        let in_t = lo.angle.uses_t() && hi.angle.uses_t();
        // x = t or y; dx/dt = +-1.
        let sign = if in_t { 1.0 } else { -1.0 };
        let (x_lo, x_hi) = if in_t {
            (lo.angle.t, hi.angle.t)
        } else {
            (lo.angle.y, hi.angle.y)
        };
        let make = |x: f64| {
            if in_t {
                Angle::from_t(x)
            } else {
                Angle::from_y(x)
            }
        };
        let h = hi.d - lo.d;
        let u = ((d - lo.d) / h).clamp(0.0, 1.0);
        let (s_lo, s_hi) = (sign * lo.dt_dd * h, sign * hi.dt_dd * h);
        let dx = x_hi - x_lo;
        let mut x = if s_lo.is_finite()
            && s_hi.is_finite()
            && s_lo.abs() < 3.0 * dx.abs()
            && s_hi.abs() < 3.0 * dx.abs()
        {
            crate::numeric::pchip::hermite(u, x_lo, x_hi, s_lo, s_hi)
        } else {
            x_lo + u * dx
        };
        // Bracket: f(a) <= 0 <= f(b) with f = Dbar(x) - d.
        let (mut a, mut b) = (x_lo, x_hi);
        if !(x > a.min(b) && x < a.max(b)) {
            x = 0.5 * (a + b);
        }
        let mut r = self.raw(make(x));
        for _ in 0..64 {
            let f = r.interference - d;
            if f == 0.0 {
                break;
            }
            if f < 0.0 {
                a = x;
            } else {
                b = x;
            }
            let slope = sign * self.d_interference_raw(make(x), &r);
            let newton = x - f / slope;
            // Converged: the Newton correction is at rounding level.
            if (newton - x).abs() <= 4.0 * f64::EPSILON * x.abs() {
                break;
            }
            x = if newton > a.min(b) && newton < a.max(b) {
                newton
            } else {
                0.5 * (a + b)
            };
            r = self.raw(make(x));
            if (b - a).abs() <= 4.0 * f64::EPSILON * x.abs() {
                break;
            }
        }
        (make(x), r)
    }

    /// Full contact-branch point at `angle`.
    fn point(&self, angle: Angle) -> MaugisPoint {
        if angle.y <= 0.0 {
            return self.junction;
        }
        let r = self.raw(angle);
        MaugisPoint {
            radius_bar: r.c_big * r.cos,
            outer_radius_bar: r.c_big,
            load_bar: r.load,
            interference_bar: r.interference,
        }
    }

    /// Equations (1)-(3) at `angle` (see the module doc).
    #[inline]
    fn raw(&self, angle: Angle) -> Raw {
        let lam = self.lambda;
        let t = angle.t;
        let (sin, cos) = if angle.uses_t() {
            t.sin_cos()
        } else {
            let (sy, cy) = angle.y.sin_cos();
            (cy, sy)
        };
        // f = sin u - u cos u, u = 2t.
        let f = if t < 0.5 {
            let u = 2.0 * t;
            let u2 = u * u;
            let mut acc = 0.0;
            for &k in F_SERIES.iter().rev() {
                acc = acc * u2 + k;
            }
            acc * u2 * u
        } else {
            // Double angle: sin 2t = 2 sin cos, cos 2t = (cos - sin)(cos + sin)
            // (absolute error a few ulp, as a second sin_cos of 2t or 2y).
            2.0 * sin * cos - 2.0 * t * ((cos - sin) * (cos + sin))
        };
        let alpha = 0.25 * lam * f;
        // t sin t - (1 - cos t), with 1 - cos t = sin^2 t/(1 + cos t).
        let g = t * sin - sin * sin / (1.0 + cos);
        let beta = 4.0 / 3.0 * lam * lam * g;
        let c_big = 2.0 / (beta + (beta * beta + 4.0 * alpha).sqrt());
        let load = c_big * c_big * (c_big * cos * cos * cos - lam * (sin * cos + t));
        let interference = c_big * (c_big * cos * cos - 4.0 / 3.0 * lam * sin);
        Raw {
            c_big,
            cos,
            sin,
            load,
            interference,
            alpha,
            beta,
        }
    }

    /// `dC/dt` from the implicit quadratic.
    fn d_c(&self, angle: Angle, r: &Raw) -> f64 {
        let lam = self.lambda;
        let t = angle.t;
        let da = 2.0 * lam * t * r.sin * r.cos;
        let db = 4.0 / 3.0 * lam * lam * t * r.cos;
        -(da * r.c_big * r.c_big + db * r.c_big) / (2.0 * r.alpha * r.c_big + r.beta)
    }

    /// `dDbar/dt` on the contact branch.
    fn d_interference(&self, angle: Angle) -> f64 {
        self.d_interference_raw(angle, &self.raw(angle))
    }

    /// `dDbar/dt` from an evaluated point.
    #[inline]
    fn d_interference_raw(&self, angle: Angle, r: &Raw) -> f64 {
        let dc = self.d_c(angle, r);
        let (c, co, si) = (r.c_big, r.cos, r.sin);
        2.0 * c * dc * co * co
            - 2.0 * c * c * co * si
            - 4.0 / 3.0 * self.lambda * (dc * si + c * co)
    }

    /// `dPbar/dt` on the contact branch.
    fn d_load(&self, angle: Angle) -> f64 {
        let r = self.raw(angle);
        let dc = self.d_c(angle, &r);
        let (c, co, si) = (r.c_big, r.cos, r.sin);
        let lam = self.lambda;
        3.0 * c * c * dc * co * co * co
            - 3.0 * c * c * c * co * co * si
            - 2.0 * lam * c * dc * (si * co + angle.t)
            - 2.0 * lam * c * c * co * co
    }

    /// Sample angles from near the junction to deep contact: [`SCAN_LEN`]
    /// of them, [`scan_angle`] in order.
    fn scan(&self) -> Vec<Angle> {
        (0..SCAN_LEN).map(scan_angle).collect()
    }

    /// Angle minimising `value` over the samples (`raws` evaluated at
    /// `samples`), refined as the root of
    /// its derivative `deriv` (a sign change around the sampled minimum).
    fn refine(
        &self,
        samples: &[Angle],
        raws: &[Raw],
        value: impl Fn(&Raw) -> f64,
        deriv: impl Fn(&Self, Angle) -> f64,
    ) -> Angle {
        let k = (0..raws.len())
            .min_by(|&i, &j| value(&raws[i]).total_cmp(&value(&raws[j])))
            .unwrap_or(0);
        let lo = samples[k.saturating_sub(1)];
        let hi = samples[(k + 1).min(samples.len() - 1)];
        let mid = samples[k];
        // The search runs in the exact one of `t` and `y` at the middle.
        let uses_t = mid.uses_t();
        let of = |a: &Angle| if uses_t { a.t } else { a.y };
        let at = |x: f64| {
            if uses_t {
                Angle::from_t(x)
            } else {
                Angle::from_y(x)
            }
        };
        brent(
            |x| deriv(self, at(x)),
            of(&lo).min(of(&hi)),
            of(&lo).max(of(&hi)),
            XTOL,
        )
        .map_or(mid, at)
    }

    /// Zero-load point between the pull-off angle and deep contact.
    fn zero_load_point(&self, pull: Angle) -> MaugisPoint {
        let f = |t: f64| self.raw(Angle::from_t(t)).load;
        let t = brent(f, T_DEEP, pull.t, XTOL).unwrap_or(pull.t);
        self.point(Angle::from_t(t))
    }

    /// Table of the stable contact branch from `top` (the fold, or the
    /// junction) down to `T_DEEP`.
    fn build_table(&mut self, top: Angle) {
        let mut angles = Vec::new();
        if !top.uses_t() {
            for k in 0..Y_NODES {
                let y = top.y + (FRAC_PI_4 - top.y) * k as f64 / Y_NODES as f64;
                angles.push(Angle::from_y(y));
            }
        }
        let t_start = top.t.min(FRAC_PI_4);
        let decades = (t_start / T_DEEP).log10();
        let n = (decades * PER_DECADE).ceil().max(2.0) as usize;
        for k in 0..=n {
            let t = t_start * (T_DEEP / t_start).powf(k as f64 / n as f64);
            angles.push(Angle::from_t(t));
        }
        self.nodes = angles
            .into_iter()
            .map(|angle| Node {
                angle,
                d: self.point(angle).interference_bar,
                dt_dd: 1.0 / self.d_interference(angle),
            })
            .collect();
        // A fold node holds the minimum exactly.
        if !self.non_contact_stable {
            self.nodes[0].d = self.nodes[0].d.min(self.detach.interference_bar);
        }
    }
}

impl MaugisPoint {
    /// The junction itself when `angle` is exactly there (`y = 0`).
    fn or_junction(self, angle: Angle, junction: MaugisPoint) -> MaugisPoint {
        if angle.y <= 0.0 {
            junction
        } else {
            self
        }
    }

    const ZERO: MaugisPoint = MaugisPoint {
        radius_bar: 0.0,
        outer_radius_bar: 0.0,
        load_bar: 0.0,
        interference_bar: 0.0,
    };
}

/// The Maugis–Dugdale law for a sphere of radius `R` (m), contact modulus
/// `E*` (Pa), work of adhesion `w` (J/m^2) and Maugis parameter `lambda`.
#[derive(Debug, Clone)]
pub struct Maugis {
    curve: MaugisCurve,
    scales: MaugisScales,
}

impl Maugis {
    /// All arguments finite and > 0, `lambda` in `[1e-6, 1e6]` (densely
    /// tested over `[1e-3, 1e3]`).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `radius`, `contact_modulus`,
    /// `work_of_adhesion` or `lambda`.
    pub fn new(radius: f64, contact_modulus: f64, work: f64, lambda: f64) -> Result<Self> {
        let scales = MaugisScales::new(radius, contact_modulus, work)?;
        Ok(Maugis {
            curve: MaugisCurve::new(lambda)?,
            scales,
        })
    }

    /// The dimensionless curve.
    pub fn curve(&self) -> &MaugisCurve {
        &self.curve
    }

    /// The Maugis scales of this contact.
    pub fn scales(&self) -> MaugisScales {
        self.scales
    }

    fn instability(&self, p: MaugisPoint) -> Instability {
        Instability {
            load: p.load_bar * self.scales.load,
            interference: p.interference_bar * self.scales.interference,
            radius: p.radius_bar * self.scales.radius,
        }
    }
}

impl AsperityLaw for Maugis {
    identity_of_kind!(Maugis);

    #[inline]
    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        let (a, p) = self
            .curve
            .state_bar(delta / self.scales.interference, branch);
        ContactState {
            load: p * self.scales.load,
            radius: a * self.scales.radius,
        }
    }

    /// `-w/sigma0`: the gap at the centre equals the Dugdale range.
    fn attach_interference(&self) -> f64 {
        self.curve.d_cut * self.scales.interference
    }

    fn detach_interference(&self) -> f64 {
        self.curve.detach.interference_bar * self.scales.interference
    }

    /// The retract snap (below the approach threshold).
    fn cutoff_interference(&self) -> f64 {
        self.detach_interference()
    }

    /// The branch threshold, and the junction where the contact radius
    /// leaves zero (the contact count jumps there) when it is on the branch.
    fn breakpoints(&self, branch: Branch) -> Vec<f64> {
        let s = self.scales.interference;
        let lo = match branch {
            Branch::Approach => self.curve.d_cut,
            Branch::Retract => self.curve.detach.interference_bar,
        };
        let mut v = vec![lo * s];
        let j = self.curve.junction.interference_bar;
        if self.curve.non_contact_stable && j > lo {
            v.push(j * s);
        }
        v
    }

    fn pull_off(&self, control: Control) -> Option<Instability> {
        Some(self.instability(match control {
            Control::Load => self.curve.pull_off,
            Control::Displacement => self.curve.detach,
        }))
    }

    fn zero_load_radius(&self) -> Option<f64> {
        Some(self.curve.zero_load.radius_bar * self.scales.radius)
    }
}

impl LawKernels for Maugis {
    fn cost_ns(&self) -> f64 {
        super::LawKind::Maugis.cost_ns()
    }
}

/// Samples per half of the scan (`y` near the junction, then `t`).
const SCAN_HALF: usize = 200;
/// Length of the scan: `SCAN_HALF` in `y`, `SCAN_HALF + 1` in `t`.
const SCAN_LEN: usize = 2 * SCAN_HALF + 1;

/// Sample `k` of the scan: `y` geometric from 1e-9 to pi/4 (`k <
/// SCAN_HALF`), then `t` geometric from pi/4 down to 1e-9. Computed once
/// per process (the `powf`s were a fifth of a pull-off).
fn scan_angle(k: usize) -> Angle {
    static ANGLES: std::sync::OnceLock<Vec<Angle>> = std::sync::OnceLock::new();
    ANGLES.get_or_init(|| (0..SCAN_LEN).map(compute_scan_angle).collect())[k]
}

fn compute_scan_angle(k: usize) -> Angle {
    let n = SCAN_HALF as f64;
    if k < SCAN_HALF {
        Angle::from_y(1e-9 * (FRAC_PI_4 / 1e-9f64).powf(k as f64 / n))
    } else {
        let k = k - SCAN_HALF;
        Angle::from_t(FRAC_PI_4 * (1e-9 / FRAC_PI_4).powf(k as f64 / n))
    }
}

mod pull_off;

#[cfg(test)]
mod tests;
