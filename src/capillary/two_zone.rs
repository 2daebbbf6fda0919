//! The two-zone contact: an elastic sphere on a flat held by two Dugdale
//! zones at once, the meniscus (`Delta p` up to the gap `h_m`) and the
//! solid's own short-range adhesion (`sigma_s` up to `delta_s`), exact in
//! the Maugis–Dugdale sense (Maugis 1992; two zones as in Maugis &
//! Gauthier-Manuel 1994).
//!
//! # Equations
//! Axisymmetric contact of radius `a` (Sneddon's method in Barthel's form,
//! J. Phys. D 41 (2008) 163001, section 3): with the auxiliary function
//! `g(t) = (E*/2)(delta - t^2/R)` for `t < a` and
//! `g(t) = -sum_i sigma_i sqrt(c_i^2 - t^2)_+` for `t > a` (zone `i` pulls
//! with `sigma_i` on `a < r < c_i`; the zones are nested since the gap grows
//! with `r`), the load is `P = 4 int_0^inf g dt`, the edge has no stress
//! singularity when `g` is continuous at `a`, and the gap outside contact is
//! `h(r) = (2/pi) int_a^r [t^2/R - delta + (2/E*) g(t)] / sqrt(r^2 - t^2) dt`:
//!
//! ```text
//! delta = a^2/R - g0 - (2/E*) sum sigma_i sqrt(c_i^2 - a^2)
//! P     = 4 E* a^3/(3R) - 2 sum sigma_i [c_i^2 acos(a/c_i) + a sqrt(c_i^2 - a^2)]
//! h(r)  = H(r; a) + g0 + (4/(pi E*)) sum sigma_i [sqrt(c_i^2 - a^2) acos(a/r) - I(r; a, c_i)]
//! H(r; a) = [(r^2 - 2a^2) acos(a/r) + a sqrt(r^2 - a^2)] / (pi R)
//! I(r; a, c) = int_a^min(r,c) sqrt(c^2 - t^2)/sqrt(r^2 - t^2) dt   (incomplete elliptic)
//! ```
//!
//! and Dugdale's conditions `h(c_i) = range_i` close the system. With one
//! zone these are Maugis's equations (1)-(3) (`h(c)` is his eq. (1)). On the
//! contact branch `g0 = 0`; on the non-contact branch (`a = 0`) `g0 = h(0)`
//! is the gap at the centre (a zone exists only while `g0 < range_i`).
//!
//! # Curve and instabilities
//! The curve is one path `s` from far (`s = -max range`, no force) through
//! the non-contact states (`s = -g0`) to the junction (`s = 0`) and deep
//! contact (`s = a`). Under displacement control an approaching asperity is
//! in the first state of the path at its interference (`min{s: delta(s) >=
//! delta}`), a retracting one in the last (`max{s: delta(s) <= delta}`):
//! every fold of `delta(s)` (one per zone at most here) is a jump, whatever
//! their number. The pull-off under load control is the most tensile point.

use super::carlson::incomplete_fe;
use crate::error::{Allowed, Error, Result};
use crate::law::{AsperityLaw, Branch, ContactState, Control, Instability, LawKernels};
use crate::numeric::roots::brent;
use crate::special::elliptic::ellip_e_comp;
use crate::special::elliptic::ellip_ke_comp;
use std::f64::consts::PI;

/// A Dugdale zone: a tension `stress` (Pa) wherever the gap is below
/// `range` (m); its work of adhesion is `stress * range` (J/m^2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Zone {
    /// Tension `sigma` (Pa), > 0.
    pub stress: f64,
    /// Range `delta_t` (m), > 0.
    pub range: f64,
}

/// Contact-radius nodes per decade of the table.
const PER_DECADE: usize = 24;
/// Decades of contact radius below and above the Maugis radius scale.
const DECADES: i32 = 5;
/// Non-contact nodes per interval between zone ranges.
const GAP_NODES: usize = 64;

/// One evaluated point of the curve.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Point {
    s: f64,
    c: [f64; 2],
    delta: f64,
    load: f64,
    radius: f64,
}

/// The two-zone law of a sphere (radius `R`, contact modulus `E*`) with up
/// to two Dugdale zones (module doc).
#[derive(Debug, Clone)]
pub struct TwoZone {
    radius: f64,
    modulus: f64,
    /// Zones, largest range first (equal ranges merged).
    zones: Vec<Zone>,
    nodes: Vec<Point>,
    /// Running maximum of `delta` over the nodes (approach search).
    prefix_max: Vec<f64>,
    /// Running minimum of `delta` from the deep end (retraction search).
    suffix_min: Vec<f64>,
    pull_off: Point,
    detach: Point,
    zero_load: Option<Point>,
}

impl TwoZone {
    /// The sphere of radius `radius` (m), contact modulus `contact_modulus`
    /// (Pa) and the Dugdale `zones` (one or two, each stress and range > 0).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `radius`, `contact_modulus`,
    /// `zone.stress` or `zone.range`; [`Error::Invalid`] naming `zones`
    /// when none or more than two are given; [`Error::NoConvergence`] if a
    /// node of the curve cannot be solved.
    pub fn new(radius: f64, contact_modulus: f64, zones: &[Zone]) -> Result<Self> {
        Allowed::POSITIVE.check("radius", radius)?;
        Allowed::POSITIVE.check("contact_modulus", contact_modulus)?;
        if zones.is_empty() || zones.len() > 2 {
            return Err(Error::invalid("zones", "one or two Dugdale zones"));
        }
        let mut zs: Vec<Zone> = Vec::new();
        for z in zones {
            Allowed::POSITIVE.check("zone.stress", z.stress)?;
            Allowed::POSITIVE.check("zone.range", z.range)?;
            match zs.iter_mut().find(|q| q.range == z.range) {
                Some(q) => q.stress += z.stress,
                None => zs.push(*z),
            }
        }
        zs.sort_by(|a, b| b.range.total_cmp(&a.range));
        let mut law = TwoZone {
            radius,
            modulus: contact_modulus,
            zones: zs,
            nodes: Vec::new(),
            prefix_max: Vec::new(),
            suffix_min: Vec::new(),
            pull_off: Point::FREE,
            detach: Point::FREE,
            zero_load: None,
        };
        law.build()?;
        Ok(law)
    }

    /// The zones, largest range first.
    pub fn zones(&self) -> &[Zone] {
        &self.zones
    }

    /// Total work of adhesion `sum sigma_i range_i` (J/m^2).
    pub fn work(&self) -> f64 {
        self.zones.iter().map(|z| z.stress * z.range).sum()
    }

    /// Maugis radius scale `(pi w R^2 / K)^(1/3)` with the total work (m).
    fn radius_scale(&self) -> f64 {
        let k = 4.0 * self.modulus / 3.0;
        (PI * self.work() * self.radius * self.radius / k).cbrt()
    }

    fn build(&mut self) -> Result<()> {
        let mut s_values = Vec::new();
        // Non-contact: -range0 .. 0, split at the inner zone's birth.
        let mut edges: Vec<f64> = self.zones.iter().map(|z| -z.range).collect();
        edges.push(0.0);
        for w in edges.windows(2) {
            for k in 0..GAP_NODES {
                let u = 0.5 * (1.0 - (PI * k as f64 / GAP_NODES as f64).cos());
                s_values.push(w[0] + (w[1] - w[0]) * u);
            }
        }
        s_values.push(0.0);
        let scale = self.radius_scale();
        let n = 2 * DECADES as usize * PER_DECADE;
        for k in 0..=n {
            let e = -DECADES as f64 + k as f64 / PER_DECADE as f64;
            s_values.push(scale * 10f64.powf(e));
        }
        let mut nodes = Vec::with_capacity(s_values.len());
        let mut guess = [0.0; 2];
        for &s in &s_values {
            let p = self
                .point(s, Some(guess))
                .ok_or_else(|| Error::NoConvergence {
                    what: format!("two-zone contact at s = {s:e} m"),
                    iterations: 0,
                    residual: f64::NAN,
                })?;
            guess = p.c;
            nodes.push(p);
        }
        self.nodes = nodes;
        self.prefix_max = self
            .nodes
            .iter()
            .scan(f64::NEG_INFINITY, |m, p| {
                *m = m.max(p.delta);
                Some(*m)
            })
            .collect();
        let mut suffix = vec![0.0; self.nodes.len()];
        let mut m = f64::INFINITY;
        for (i, p) in self.nodes.iter().enumerate().rev() {
            m = m.min(p.delta);
            suffix[i] = m;
        }
        self.suffix_min = suffix;
        self.detach = self.refine_min(|p| p.delta);
        self.pull_off = self.refine_min(|p| p.load);
        self.zero_load = self.find_zero_load();
        Ok(())
    }

    /// The point of the curve at path parameter `s` (m): the non-contact
    /// state with central gap `-s` for `s < 0`, the contact state of radius
    /// `s` for `s >= 0`. `guess`: zone edges to start Newton from.
    fn point(&self, s: f64, guess: Option<[f64; 2]>) -> Option<Point> {
        let (a, g0) = if s < 0.0 { (0.0, -s) } else { (s, 0.0) };
        let c = self.solve_edges(a, g0, guess)?;
        let mut delta = a * a / self.radius - g0;
        let mut load = 4.0 * self.modulus * a * a * a / (3.0 * self.radius);
        for (z, &ci) in self.zones.iter().zip(&c) {
            if ci > a {
                let w = ((ci - a) * (ci + a)).sqrt();
                delta -= 2.0 * z.stress * w / self.modulus;
                load -= 2.0 * z.stress * (ci * ci * (a / ci).acos() + a * w);
            }
        }
        Some(Point {
            s,
            c,
            delta,
            load,
            radius: a,
        })
    }

    /// The gap `h(r)` (m) for contact radius `a`, central gap `g0` and zone
    /// edges `c` (module doc).
    fn gap(&self, r: f64, a: f64, g0: f64, c: &[f64; 2]) -> f64 {
        let mut h = hertz_gap(r, a, self.radius) + g0;
        let ac = if r > a { (a / r).acos() } else { 0.0 };
        for (z, &ci) in self.zones.iter().zip(c) {
            if ci > a {
                let w = ((ci - a) * (ci + a)).sqrt();
                h += 4.0 * z.stress / (PI * self.modulus) * (w * ac - zone_integral(r, a, ci));
            }
        }
        h
    }

    /// Dugdale's conditions `h(c_i) = range_i`: the zone edges at contact
    /// radius `a` and central gap `g0` (0 for an absent zone).
    fn solve_edges(&self, a: f64, g0: f64, guess: Option<[f64; 2]>) -> Option<[f64; 2]> {
        let r0 = self.zones[0].range;
        if g0 >= r0 {
            return Some([0.0, 0.0]);
        }
        let two = self.zones.len() == 2 && g0 < self.zones[1].range;
        let mut hi = a + (2.0 * self.radius * r0).sqrt();
        while hertz_gap(hi, a, self.radius) + g0 < r0 {
            hi *= 2.0;
        }
        if let Some(c) = guess.and_then(|g| self.newton(a, g0, g, two, hi)) {
            return Some(c);
        }
        let xtol = |x: f64| 4.0 * f64::EPSILON * x;
        if !two {
            let f = |c: f64| self.gap(c, a, g0, &[c, 0.0]) - r0;
            let c0 = brent(f, a, hi, xtol(hi))?;
            return Some([c0, 0.0]);
        }
        let r1 = self.zones[1].range;
        let inner = |c0: f64| -> f64 {
            let f1 = |c1: f64| self.gap(c1, a, g0, &[c0, c1]) - r1;
            if f1(c0) <= 0.0 {
                c0
            } else {
                brent(f1, a, c0, xtol(c0)).unwrap_or(c0)
            }
        };
        let f0 = |c0: f64| self.gap(c0, a, g0, &[c0, inner(c0)]) - r0;
        let c0 = brent(f0, a, hi, xtol(hi))?;
        Some([c0, inner(c0)])
    }

    /// Newton on Dugdale's conditions from `guess` (finite-difference
    /// Jacobian); `None` when it leaves `(a, hi]` or does not converge.
    fn newton(&self, a: f64, g0: f64, guess: [f64; 2], two: bool, hi: f64) -> Option<[f64; 2]> {
        let r = [
            self.zones[0].range,
            self.zones.get(1).map_or(0.0, |z| z.range),
        ];
        let mut c = guess;
        if !two {
            c[1] = 0.0;
        }
        if !(c[0] > a && c[0] <= hi) || (two && !(c[1] > a && c[1] <= c[0])) {
            return None;
        }
        let res = |c: &[f64; 2]| -> [f64; 2] {
            let f0 = self.gap(c[0], a, g0, c) - r[0];
            let f1 = if two {
                self.gap(c[1], a, g0, c) - r[1]
            } else {
                0.0
            };
            [f0, f1]
        };
        for _ in 0..30 {
            let f = res(&c);
            let h0 = 1e-7 * (c[0] - a).max(1e-300);
            let mut cp = c;
            cp[0] += h0;
            let f_0 = res(&cp);
            let (j00, j10) = ((f_0[0] - f[0]) / h0, (f_0[1] - f[1]) / h0);
            let step = if two {
                let h1 = 1e-7 * (c[1] - a).max(1e-300);
                let mut cq = c;
                cq[1] += h1;
                let f_1 = res(&cq);
                let (j01, j11) = ((f_1[0] - f[0]) / h1, (f_1[1] - f[1]) / h1);
                let det = j00 * j11 - j01 * j10;
                [
                    (f[0] * j11 - f[1] * j01) / det,
                    (j00 * f[1] - j10 * f[0]) / det,
                ]
            } else {
                [f[0] / j00, 0.0]
            };
            let next = [c[0] - step[0], c[1] - step[1]];
            if !(next[0] > a && next[0] <= hi) || (two && !(next[1] > a && next[1] <= next[0])) {
                return None;
            }
            let done = (step[0].abs() <= 1e-13 * (c[0] - a).max(f64::MIN_POSITIVE))
                && (!two || step[1].abs() <= 1e-13 * (c[1] - a).max(f64::MIN_POSITIVE));
            c = next;
            if done {
                return Some(c);
            }
        }
        None
    }

    /// The node minimising `key`, refined by golden section on `s` between
    /// its neighbours.
    fn refine_min(&self, key: impl Fn(&Point) -> f64) -> Point {
        let k = (0..self.nodes.len())
            .min_by(|&i, &j| key(&self.nodes[i]).total_cmp(&key(&self.nodes[j])))
            .unwrap_or(0);
        let lo = self.nodes[k.saturating_sub(1)];
        let hi = self.nodes[(k + 1).min(self.nodes.len() - 1)];
        let best = self.nodes[k];
        let f = |s: f64| {
            self.point(s, Some(best.c))
                .map_or(f64::INFINITY, |p| key(&p))
        };
        let (s, _) = crate::numeric::roots::golden_min(f, lo.s, hi.s, 1e-12 * (hi.s - lo.s).abs());
        match self.point(s, Some(best.c)) {
            Some(p) if key(&p) <= key(&best) => p,
            _ => best,
        }
    }

    /// Zero load on the retraction path: the last sign change of `P` from
    /// the deep end, on the stable part.
    fn find_zero_load(&self) -> Option<Point> {
        let n = self.nodes.len();
        let k = (0..n - 1)
            .rev()
            .find(|&i| self.nodes[i].load < 0.0 && self.nodes[i + 1].load >= 0.0)?;
        if self.nodes[k].s < self.detach.s {
            return None;
        }
        let (lo, hi) = (self.nodes[k], self.nodes[k + 1]);
        let s = brent(
            |s| self.point(s, Some(lo.c)).map_or(f64::NAN, |p| p.load),
            lo.s,
            hi.s,
            1e-15 * hi.s.abs(),
        )?;
        self.point(s, Some(lo.c))
    }

    /// The point at interference `delta` in the cell `[k, k+1]` of the
    /// table (`delta` between the two nodes' interferences).
    fn in_cell(&self, k: usize, delta: f64) -> Point {
        let (lo, hi) = (self.nodes[k], self.nodes[k + 1]);
        if delta == lo.delta {
            return lo;
        }
        if delta == hi.delta {
            return hi;
        }
        let guess = |s: f64| {
            let u = ((s - lo.s) / (hi.s - lo.s)).clamp(0.0, 1.0);
            [
                lo.c[0] + u * (hi.c[0] - lo.c[0]),
                lo.c[1] + u * (hi.c[1] - lo.c[1]),
            ]
        };
        let f = |s: f64| {
            self.point(s, Some(guess(s)))
                .map_or(f64::NAN, |p| p.delta - delta)
        };
        let xtol = 1e-14 * lo.s.abs().max(hi.s.abs());
        brent(f, lo.s, hi.s, xtol)
            .and_then(|s| self.point(s, Some(guess(s))))
            .unwrap_or(if (delta - lo.delta).abs() < (delta - hi.delta).abs() {
                lo
            } else {
                hi
            })
    }

    /// Deep contact beyond the table: the contact radius found by doubling
    /// and bisection on `delta(a)`.
    fn deep(&self, delta: f64) -> Point {
        let last = *self.nodes.last().expect("nodes");
        let mut hi = last.s * 2.0;
        let d = |s: f64| self.point(s, None).map_or(f64::NAN, |p| p.delta);
        while d(hi) < delta && hi.is_finite() {
            hi *= 2.0;
        }
        brent(|s| d(s) - delta, last.s, hi, 1e-15 * hi)
            .and_then(|s| self.point(s, None))
            .unwrap_or(last)
    }

    /// The state on `branch` at interference `delta` (m) as a curve point.
    fn state_point(&self, delta: f64, branch: Branch) -> Option<Point> {
        let n = self.nodes.len();
        match branch {
            Branch::Approach => {
                if !(delta >= self.nodes[0].delta) {
                    return None;
                }
                let k = self.prefix_max.partition_point(|&m| m < delta);
                if k >= n {
                    return Some(self.deep(delta));
                }
                if k == 0 {
                    return None;
                }
                Some(self.in_cell(k - 1, delta))
            }
            Branch::Retract => {
                if !(delta >= self.detach.delta) {
                    return None;
                }
                let k = self.suffix_min.partition_point(|&m| m <= delta);
                if k >= n {
                    return Some(self.deep(delta));
                }
                if k == 0 {
                    return Some(self.detach);
                }
                // Last node with delta_k <= delta is k-1; the crossing is in
                // [k-1, k].
                Some(self.in_cell(k - 1, delta))
            }
        }
    }

    /// The curve's path values for tests: `(s, delta, load, radius, c0, c1)`
    /// at path parameter `s` (m; `-g0` or `a`).
    pub fn point_at(&self, s: f64) -> Option<[f64; 6]> {
        self.point(s, None)
            .map(|p| [p.s, p.delta, p.load, p.radius, p.c[0], p.c[1]])
    }

    fn instability(p: Point) -> Instability {
        Instability {
            load: p.load,
            interference: p.delta,
            radius: p.radius,
        }
    }
}

impl Point {
    const FREE: Point = Point {
        s: 0.0,
        c: [0.0, 0.0],
        delta: 0.0,
        load: 0.0,
        radius: 0.0,
    };
}

/// Gap of a Hertzian contact of radius `a` outside it (m):
/// `[(r^2 - 2a^2) acos(a/r) + a sqrt(r^2 - a^2)] / (pi R)`; `r^2/(2R)` at `a = 0`.
fn hertz_gap(r: f64, a: f64, radius: f64) -> f64 {
    if a == 0.0 {
        return r * r / (2.0 * radius);
    }
    if r <= a {
        return 0.0;
    }
    ((r * r - 2.0 * a * a) * (a / r).acos() + a * ((r - a) * (r + a)).sqrt()) / (PI * radius)
}

/// `I(r; a, c) = int_a^min(r,c) sqrt(c^2 - t^2)/sqrt(r^2 - t^2) dt` (m).
/// `r <= c`: `c [E(k) - E(asin(a/r), k)]`, `k = r/c`; `r > c`:
/// `(c^2/r) [G(pi/2) - G(asin(a/c))]`, `k = c/r`, `G = (E - k'^2 F)/k^2`.
fn zone_integral(r: f64, a: f64, c: f64) -> f64 {
    if c <= a || r <= a {
        return 0.0;
    }
    if r == c {
        return c - a;
    }
    if r < c {
        let k = r / c;
        let e_full = ellip_e_comp((c - r) * (c + r) / (c * c));
        let s = a / r;
        let (_, e_a) = incomplete_fe(s, (r - a) * (r + a) / (r * r), k);
        c * (e_full - e_a)
    } else {
        let k = c / r;
        let m1 = (r - c) * (r + c) / (r * r);
        let (kk, ee) = ellip_ke_comp(m1);
        let g_full = (ee - m1 * kk) / (k * k);
        let s = a / c;
        let g_a = if s == 0.0 {
            0.0
        } else {
            let (f, e) = incomplete_fe(s, (c - a) * (c + a) / (c * c), k);
            (e - m1 * f) / (k * k)
        };
        c * c / r * (g_full - g_a)
    }
}

impl AsperityLaw for TwoZone {
    fn name(&self) -> &'static str {
        "two-zone"
    }

    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        self.state_point(delta, branch)
            .map_or(ContactState::FREE, |p| ContactState {
                load: p.load,
                radius: p.radius,
            })
    }

    /// `-h_max`: the gap at the centre reaches the longest range.
    fn attach_interference(&self) -> f64 {
        self.nodes[0].delta
    }

    fn detach_interference(&self) -> f64 {
        self.detach.delta
    }

    fn cutoff_interference(&self) -> f64 {
        self.detach.delta.min(self.nodes[0].delta)
    }

    /// The thresholds, every fold's interference (jumps) on the branch, the
    /// junction and the births of the inner zone.
    fn breakpoints(&self, branch: Branch) -> Vec<f64> {
        let mut v = vec![match branch {
            Branch::Approach => self.nodes[0].delta,
            Branch::Retract => self.detach.delta,
        }];
        let n = self.nodes.len();
        for i in 1..n - 1 {
            let (a, b, c) = (
                self.nodes[i - 1].delta,
                self.nodes[i].delta,
                self.nodes[i + 1].delta,
            );
            let fold = (b >= a && b >= c) || (b <= a && b <= c);
            let kink =
                self.nodes[i].s == 0.0 || self.zones.iter().any(|z| self.nodes[i].s == -z.range);
            if fold || kink {
                v.push(b);
            }
        }
        v.retain(|d| d.is_finite());
        v.sort_by(f64::total_cmp);
        v.dedup();
        v
    }

    fn pull_off(&self, control: Control) -> Option<Instability> {
        Some(Self::instability(match control {
            Control::Load => self.pull_off,
            Control::Displacement => self.detach,
        }))
    }

    fn zero_load_radius(&self) -> Option<f64> {
        self.zero_load.map(|p| p.radius)
    }
}

impl LawKernels for TwoZone {
    /// A state is a root search over nested elliptic-integral solves:
    /// worth tabulating.
    fn cost_ns(&self) -> f64 {
        50_000.0
    }
}
