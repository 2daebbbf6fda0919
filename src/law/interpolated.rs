//! Any law, replaced over an interference interval by piecewise Chebyshev
//! interpolants accurate to a requested tolerance: the fast stand-in for an
//! expensive law (exact Maugis–Dugdale) inside rough-surface integration.
//!
//! Each branch's interval is split at the law's breakpoints and where
//! contact starts or ends (so the contact count stays exact), then panels
//! are bisected adaptively until a degree-6 Chebyshev interpolant (7
//! Chebyshev–Lobatto nodes) of the load `P` and of `a^2` matches the law at
//! the 6 interleaved test points within
//! `tol (|P| + P_s)` and `tol (a^2 + a_s^2)`, with `P_s` the law's adhesive
//! force scale (the magnitude of its load-controlled pull-off) and `a_s`
//! its zero-load radius (both 0 for Hertz: then purely relative). Square-
//! root endpoints (a JKR fold, Hertz at `delta = 0`) are resolved by
//! geometric refinement towards them, down to a panel width of `1e-12` of
//! the interval. Outside the interval the wrapped law is called directly.
//!
//! Evaluation: a binary search for the panel, its local coordinate
//! `t = (delta - m) s` (the panel's midpoint `m` and inverse half-width
//! `s` stored: no division) and two degree-6 polynomials in `t` by
//! Horner's rule on power-basis coefficients converted once from the
//! Chebyshev ones (6 multiplies and 6 adds against Clenshaw's 21 operations per
//! polynomial; the conversion is well conditioned at degree 6 on
//! `[-1, 1]`, and the panels are accepted on the converted form). About
//! 15 ns, against about 0.5 us for an exact Maugis–Dugdale solve.
//! Degree 6 was chosen by measurement: a GW curve with Maugis–Dugdale
//! asperities ran 29, 31, 36, 47 and 54 ms with degrees 4, 6, 8, 10 and 16
//! (`examples/md_curve_profile.rs`): short Clenshaw chains win over fewer
//! panels.

use super::{AsperityLaw, Branch, ContactState, Control, Instability, LawCursor, LawKernels};
use crate::error::{Allowed, Error, Result};
use crate::numeric::chebyshev::{
    horner, lobatto_coefficients, lobatto_nodes, monomial_coefficients,
};
use crate::numeric::lanes::{sqrt_lanes, StateSums, STATE_LANES};
use std::f64::consts::PI;
use std::sync::Arc;

/// Polynomial degree per panel (see the module doc for the measurement).
const DEG: usize = 6;
/// Panels below this fraction of the interval are accepted as they are.
const MIN_WIDTH: f64 = 1e-12;

/// Lanes of the interleaved polynomials of
/// [`load_near_batch`](LawKernels::load_near_batch).
const LANES: usize = 8;

/// [`horner_lanes`](crate::numeric::chebyshev::horner_lanes) at this
/// module's degree.
#[inline(always)]
fn horner_lanes<const L: usize>(x: &[f64; L], a: impl Fn(usize, usize) -> f64) -> [f64; L] {
    crate::numeric::chebyshev::horner_lanes::<{ DEG + 1 }, L>(x, a)
}

#[derive(Debug, Clone, Default)]
struct BranchTable {
    /// Panel edges, ascending (`panels + 1` values).
    edges: Vec<f64>,
    /// Each panel's map to its local coordinate, `[m, s]`:
    /// `t = (delta - m) s`, `m = (l + r)/2`, `s = 2/(r - l)`.
    map: Vec<[f64; 2]>,
    /// Power-basis coefficients (in `t`) of the load on each panel.
    load: Vec<[f64; DEG + 1]>,
    /// Power-basis coefficients (in `t`) of `a^2` on each panel.
    r2: Vec<[f64; DEG + 1]>,
    /// Whether each panel is in contact (`a > 0`).
    contact: Vec<bool>,
}

/// A law tabulated as piecewise Chebyshev interpolants on `[lo, hi]`.
#[derive(Debug, Clone)]
pub struct InterpolatedLaw {
    inner: Arc<dyn AsperityLaw>,
    tables: [BranchTable; 2],
    tol: f64,
    evaluations: usize,
    /// The wrapped law's attach interference (m).
    attach: f64,
}

impl InterpolatedLaw {
    /// Tabulates `inner` on `[lo, hi]` (m) on both branches to relative
    /// tolerance `tol` (in `[1e-13, 1e-2]`).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `tol`, `lo` or `hi` (finite,
    /// `lo < hi <= max_interference`).
    pub fn new(inner: Arc<dyn AsperityLaw>, lo: f64, hi: f64, tol: f64) -> Result<Self> {
        Allowed::closed(1e-13, 1e-2).check("tol", tol)?;
        crate::error::finite("lo", lo)?;
        Allowed::open(lo, inner.max_interference()).check("hi", hi)?;
        let p_scale = inner.pull_off(Control::Load).map_or(0.0, |p| p.load.abs());
        let a_scale = inner.zero_load_radius().unwrap_or(0.0);
        // The two branches are independent: built side by side (rayon), each
        // by the same serial code, so the tables do not depend on threads.
        let build = |branch: Branch| -> Result<(BranchTable, usize)> {
            let mut evaluations = 0;
            let mut t = BranchTable::default();
            let mut cuts = vec![lo.max(inner.cutoff_interference().max(f64::MIN)), hi];
            cuts.extend(
                inner
                    .breakpoints(branch)
                    .into_iter()
                    .filter(|&b| b > lo && b < hi),
            );
            cuts.sort_by(f64::total_cmp);
            cuts.dedup();
            cuts.retain(|&c| c >= lo);
            let mut pieces = Vec::new();
            for w in cuts.windows(2) {
                split_at_contact_changes(
                    inner.as_ref(),
                    branch,
                    w[0],
                    w[1],
                    &mut pieces,
                    &mut evaluations,
                );
            }
            let width = hi - lo;
            for (a, b) in pieces {
                fit_piece(
                    inner.as_ref(),
                    branch,
                    a,
                    b,
                    width,
                    tol,
                    p_scale,
                    a_scale,
                    &mut t,
                    &mut evaluations,
                )?;
            }
            Ok((t, evaluations))
        };
        let (approach, retract) =
            rayon::join(|| build(Branch::Approach), || build(Branch::Retract));
        let ((approach, ea), (retract, er)) = (approach?, retract?);
        let tables = [approach, retract];
        let evaluations = ea + er;
        Ok(InterpolatedLaw {
            attach: inner.attach_interference(),
            inner,
            tables,
            tol,
            evaluations,
        })
    }

    #[inline]
    fn table(&self, branch: Branch) -> &BranchTable {
        match branch {
            Branch::Approach => &self.tables[0],
            Branch::Retract => &self.tables[1],
        }
    }

    /// The branch an asperity is on after reaching `delta_max`: the
    /// wrapped law's attach interference decides (cached).
    #[inline]
    fn branch_after(&self, delta_max: f64) -> Branch {
        if delta_max >= self.attach {
            Branch::Retract
        } else {
            Branch::Approach
        }
    }

    /// Panels per branch (approach, retract).
    pub fn panels(&self) -> (usize, usize) {
        (self.tables[0].load.len(), self.tables[1].load.len())
    }

    /// Evaluations of the wrapped law spent building the tables.
    pub fn build_evaluations(&self) -> usize {
        self.evaluations
    }

    /// The tolerance the tables were built to.
    pub fn tolerance(&self) -> f64 {
        self.tol
    }

    /// The wrapped law.
    pub fn inner(&self) -> &dyn AsperityLaw {
        self.inner.as_ref()
    }
}

/// Splits `[a, b]` where the contact flag changes (bisection to 1e-15 of
/// the interval), appending the pieces.
fn split_at_contact_changes(
    law: &dyn AsperityLaw,
    branch: Branch,
    a: f64,
    b: f64,
    out: &mut Vec<(f64, f64)>,
    evals: &mut usize,
) {
    const SAMPLES: usize = 64;
    let contact = |x: f64, evals: &mut usize| {
        *evals += 1;
        law.state(x, branch).in_contact()
    };
    let mut start = a;
    let mut prev_x = a + (b - a) * 1e-12;
    let mut prev = contact(prev_x, evals);
    for i in 1..=SAMPLES {
        let x = if i == SAMPLES {
            b - (b - a) * 1e-12
        } else {
            a + (b - a) * i as f64 / SAMPLES as f64
        };
        let c = contact(x, evals);
        if c != prev {
            let (mut lo, mut hi) = (prev_x, x);
            while hi - lo > 1e-15 * (b - a).max(f64::MIN_POSITIVE) {
                let mid = 0.5 * (lo + hi);
                if contact(mid, evals) == prev {
                    lo = mid;
                } else {
                    hi = mid;
                }
                if mid == lo && mid == hi {
                    break;
                }
            }
            let cut = 0.5 * (lo + hi);
            if cut > start && cut < b {
                out.push((start, cut));
                start = cut;
            }
        }
        prev = c;
        prev_x = x;
    }
    out.push((start, b));
}

/// Adaptive bisection of one smooth piece into accepted panels.
#[allow(clippy::too_many_arguments)]
fn fit_piece(
    law: &dyn AsperityLaw,
    branch: Branch,
    a: f64,
    b: f64,
    width: f64,
    tol: f64,
    p_scale: f64,
    a_scale: f64,
    table: &mut BranchTable,
    evals: &mut usize,
) -> Result<()> {
    let x: [f64; DEG + 1] = lobatto_nodes();
    let mut stack = vec![(a, b)];
    let mut accepted = Vec::new();
    while let Some((l, r)) = stack.pop() {
        let map = |t: f64| 0.5 * (l + r) + 0.5 * (r - l) * t;
        let mut fl = [0.0; DEG + 1];
        let mut fr = [0.0; DEG + 1];
        for k in 0..=DEG {
            let s = law.state(map(x[k]), branch);
            fl[k] = s.load;
            fr[k] = s.radius * s.radius;
        }
        *evals += DEG + 1;
        // Accepted on the form evaluated: power-basis coefficients.
        let cl = monomial_coefficients(&lobatto_coefficients(&fl));
        let cr = monomial_coefficients(&lobatto_coefficients(&fr));
        let mut ok = true;
        for k in 0..DEG {
            let t = (PI * (k as f64 + 0.5) / DEG as f64).cos();
            let s = law.state(map(t), branch);
            *evals += 1;
            let el = (horner(&cl, t) - s.load).abs();
            let er = (horner(&cr, t) - s.radius * s.radius).abs();
            let r2 = s.radius * s.radius;
            if !(el <= tol * (s.load.abs() + p_scale) && er <= tol * (r2 + a_scale * a_scale)) {
                ok = false;
                break;
            }
        }
        if ok || (r - l) <= MIN_WIDTH * width {
            if !cl.iter().chain(&cr).all(|c| c.is_finite()) {
                return Err(Error::invalid(
                    "law",
                    format!("{} is not finite on [{l:e}, {r:e}] m", law.name()),
                ));
            }
            let contact = law.state(0.5 * (l + r), branch).in_contact();
            accepted.push((l, r, cl, cr, contact));
        } else {
            let m = 0.5 * (l + r);
            stack.push((m, r));
            stack.push((l, m));
        }
    }
    accepted.sort_by(|p, q| p.0.total_cmp(&q.0));
    for (l, r, cl, cr, contact) in accepted {
        if table.edges.last() != Some(&l) {
            if let Some(last) = table.edges.last() {
                // Pieces are contiguous; a gap would be a bug in the caller.
                debug_assert!((*last - l).abs() <= 1e-9 * width, "gap {last} {l}");
            }
            table.edges.push(l);
        }
        table.edges.push(r);
        let l = table.edges[table.edges.len() - 2];
        table.map.push([0.5 * (l + r), 2.0 / (r - l)]);
        table.load.push(cl);
        table.r2.push(cr);
        table.contact.push(contact);
    }
    Ok(())
}

/// Local coordinate `t = (delta - m) s` in `[-1, 1]` of `delta` on the
/// panel of map `[m, s]` (midpoint, inverse half-width).
#[inline(always)]
fn local_coordinate(delta: f64, [m, s]: [f64; 2]) -> f64 {
    ((delta - m) * s).clamp(-1.0, 1.0)
}

impl BranchTable {
    /// Panel index and local coordinate `t` in `[-1, 1]`, inside the table.
    #[inline]
    fn locate(&self, delta: f64) -> Option<(usize, f64)> {
        let n = self.load.len();
        if n == 0 || !(delta >= self.edges[0] && delta <= self.edges[n]) {
            return None;
        }
        let i = self.edges.partition_point(|&e| e <= delta).clamp(1, n) - 1;
        Some((i, local_coordinate(delta, self.map[i])))
    }

    /// As [`locate`](Self::locate), walking from panel `*hint` (updated):
    /// the same panel, found in O(1) when consecutive calls are close.
    #[inline]
    fn locate_from(&self, delta: f64, hint: &mut usize) -> Option<(usize, f64)> {
        let i = self.panel_from(delta, hint)?;
        Some((i, local_coordinate(delta, self.map[i])))
    }

    /// The panel of [`locate_from`](Self::locate_from) alone.
    #[inline]
    fn panel_from(&self, delta: f64, hint: &mut usize) -> Option<usize> {
        let n = self.load.len();
        if n == 0 || !(delta >= self.edges[0] && delta <= self.edges[n]) {
            return None;
        }
        // The last panel i with edges[i] <= delta (i <= n - 1), as the
        // binary search in `locate` finds it.
        let mut i = (*hint).min(n - 1);
        while i + 1 < n && self.edges[i + 1] <= delta {
            i += 1;
        }
        while i > 0 && self.edges[i] > delta {
            i -= 1;
        }
        *hint = i;
        Some(i)
    }

    #[inline]
    fn eval_from(&self, delta: f64, hint: &mut usize) -> Option<ContactState> {
        let (i, t) = self.locate_from(delta, hint)?;
        Some(self.eval_at(i, t))
    }

    #[inline]
    fn eval_at(&self, i: usize, t: f64) -> ContactState {
        let load = horner(&self.load[i], t);
        let radius = if self.contact[i] {
            horner(&self.r2[i], t).max(0.0).sqrt()
        } else {
            0.0
        };
        ContactState { load, radius }
    }

    #[inline]
    fn load(&self, delta: f64) -> Option<f64> {
        self.locate(delta).map(|(i, t)| horner(&self.load[i], t))
    }

    #[inline]
    fn load_from(&self, delta: f64, hint: &mut usize) -> Option<f64> {
        self.locate_from(delta, hint)
            .map(|(i, t)| horner(&self.load[i], t))
    }

    #[inline]
    fn eval(&self, delta: f64) -> Option<ContactState> {
        let (i, t) = self.locate(delta)?;
        Some(self.eval_at(i, t))
    }
}

/// Asperities evaluated together by [`InterpolatedLaw::state_batch`]
/// (four AVX-512 vectors; a multiple of [`STATE_LANES`]).
const GROUP: usize = 32;

/// Where [`TableBatch`] puts the states: arrays, or lane sums.
enum Sink<'a> {
    /// `load[i]`, `radius[i]` ([`LawKernels::state_batch`]).
    States {
        load: &'a mut [f64],
        radius: &'a mut [f64],
    },
    /// State `i` added to lane `i mod STATE_LANES`
    /// ([`LawKernels::add_state_sums`]).
    Sums(&'a mut StateSums),
}

/// [`InterpolatedLaw::state_batch`] as a [`pulp::WithSimd`] operation: per
/// group of [`GROUP`] asperities, the panels are found by a scalar walk,
/// then the two polynomials (load, `a^2`) and the square root run in
/// SIMD lanes with each lane's own coefficients, in the operation order of
/// [`horner`] (so bit for bit the scalar evaluation); the group's states
/// are then stored or summed ([`Sink`]).
struct TableBatch<'a> {
    groups: Groups<'a>,
    sink: Sink<'a>,
}

/// The input of a [`TableBatch`]: interferences `delta_i = (z_i - sep) s`
/// and, on retraction, the maximum interferences
/// `(m_i - closest) s` that pick each asperity's branch (given
/// interferences: `sep = closest = 0`, `s = 1`, which is exact).
struct Groups<'a> {
    law: &'a InterpolatedLaw,
    z: &'a [f64],
    sep: f64,
    /// `m` and `closest`.
    max: Option<(&'a [f64], f64)>,
    scale: f64,
}

/// The loads and squared radii (`max(a^2, 0)`, 0 outside contact; the
/// caller takes the root) of a group at local coordinates `t`, lane `j`'s
/// coefficient `k` given by `load(j, k)`, `r2(j, k)`.
#[inline(always)]
fn group_values(
    t: &[f64; GROUP],
    load: impl Fn(usize, usize) -> f64,
    r2: impl Fn(usize, usize) -> f64,
    contact: impl Fn(usize) -> bool,
) -> ([f64; GROUP], [f64; GROUP]) {
    let p = horner_lanes(t, load);
    let s = horner_lanes(t, r2);
    (
        p,
        std::array::from_fn(|j| if contact(j) { s[j].max(0.0) } else { 0.0 }),
    )
}

impl Groups<'_> {
    /// The branch table and panel holding every lane of a group, if one
    /// does (a sorted population's group nearly always lies on one panel):
    /// one branch, no NaN, and the least and greatest interference on the
    /// same panel (the panel index is monotone in `delta`).
    #[inline(always)]
    fn common_panel(
        &self,
        d: &[f64; GROUP],
        retract: &[bool; GROUP],
        hint: &mut [usize; 2],
    ) -> Option<(usize, usize)> {
        if retract.iter().any(|&x| x != retract[0]) {
            return None;
        }
        let k = usize::from(retract[0]);
        let table = &self.law.tables[k];
        let i = table.panel_from(d[0], &mut hint[k])?;
        // Every lane in panel i as `panel_from` bounds it: `[l, r)`, the
        // last panel `[l, r]` (NaN fails both; a plain AND, so the test
        // runs in vector lanes).
        let (l, r) = (table.edges[i], table.edges[i + 1]);
        let inside = if i + 1 == table.load.len() {
            d.iter().fold(true, |ok, &x| ok & (x >= l) & (x <= r))
        } else {
            d.iter().fold(true, |ok, &x| ok & (x >= l) & (x < r))
        };
        inside.then_some((k, i))
    }

    /// The states of the group of `len` asperities from `start`, padded
    /// with its first lane: loads and radii.
    #[inline(always)]
    fn group<S: pulp::Simd>(
        &self,
        simd: S,
        start: usize,
        len: usize,
        hint: &mut [usize; 2],
    ) -> ([f64; GROUP], [f64; GROUP]) {
        const ZERO: [f64; DEG + 1] = [0.0; DEG + 1];
        let law = self.law;
        // The group's interferences and branches, padded with its first
        // lane.
        let (sep, scale) = (self.sep, self.scale);
        let mut d = [self.z[start]; GROUP];
        d[..len].copy_from_slice(&self.z[start..start + len]);
        for x in &mut d {
            *x = (*x - sep) * scale;
        }
        let mut retract = [false; GROUP];
        if let Some((m, closest)) = self.max {
            let mut mx = [m[start]; GROUP];
            mx[..len].copy_from_slice(&m[start..start + len]);
            for j in 0..GROUP {
                retract[j] = law.branch_after((mx[j] - closest) * scale) == Branch::Retract;
            }
        }
        let mut t = [0.0; GROUP];
        if let Some((k, i)) = self.common_panel(&d, &retract, hint) {
            // One panel: its coefficients broadcast to every lane.
            let table = &law.tables[k];
            let map = table.map[i];
            for j in 0..GROUP {
                t[j] = local_coordinate(d[j], map);
            }
            let (a, b, c) = (&table.load[i], &table.r2[i], table.contact[i]);
            let (p, mut q) = group_values(&t, |_, k| a[k], |_, k| b[k], |_| c);
            sqrt_lanes(simd, &mut q);
            return (p, q);
        }
        // Each lane its own panel (found by a walk from the last one) or,
        // outside the table, the wrapped law.
        let mut map = [[0.0, 1.0]; GROUP];
        let mut cl = [&ZERO; GROUP];
        let mut cr = [&ZERO; GROUP];
        let mut contact = [false; GROUP];
        let mut outside = [None; GROUP];
        for j in 0..len {
            let k = usize::from(retract[j]);
            let table = &law.tables[k];
            match table.panel_from(d[j], &mut hint[k]) {
                Some(i) => {
                    map[j] = table.map[i];
                    (cl[j], cr[j]) = (&table.load[i], &table.r2[i]);
                    contact[j] = table.contact[i];
                }
                None => {
                    let branch = [Branch::Approach, Branch::Retract][k];
                    outside[j] = Some(law.inner.state(d[j], branch));
                    d[j] = 0.0;
                }
            }
        }
        for j in 0..GROUP {
            t[j] = local_coordinate(d[j], map[j]);
        }
        let (mut p, mut q) = group_values(&t, |j, k| cl[j][k], |j, k| cr[j][k], |j| contact[j]);
        sqrt_lanes(simd, &mut q);
        for j in 0..len {
            if let Some(s) = outside[j] {
                (p[j], q[j]) = (s.load, s.radius);
            }
        }
        (p, q)
    }
}

impl pulp::WithSimd for TableBatch<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, simd: S) {
        let TableBatch { groups, sink } = self;
        let n = groups.z.len();
        let n = groups.max.map_or(n, |(m, _)| n.min(m.len()));
        let mut hint = [0usize; 2];
        match sink {
            Sink::States { load, radius } => {
                let n = n.min(load.len()).min(radius.len());
                for start in (0..n).step_by(GROUP) {
                    let len = GROUP.min(n - start);
                    let (p, q) = groups.group(simd, start, len, &mut hint);
                    load[start..start + len].copy_from_slice(&p[..len]);
                    radius[start..start + len].copy_from_slice(&q[..len]);
                }
            }
            Sink::Sums(sums) => {
                // In registers for the whole run.
                let mut acc = *sums;
                for start in (0..n).step_by(GROUP) {
                    let len = GROUP.min(n - start);
                    let (mut p, mut q) = groups.group(simd, start, len, &mut hint);
                    // Padding: free states, `+0.0` added to lanes that
                    // never hold `-0.0` (sums from `+0.0`), which changes
                    // nothing.
                    p[len..].fill(0.0);
                    q[len..].fill(0.0);
                    for (pl, ql) in p.chunks_exact(STATE_LANES).zip(q.chunks_exact(STATE_LANES)) {
                        for j in 0..STATE_LANES {
                            acc.add(j, pl[j], ql[j]);
                        }
                    }
                }
                *sums = acc;
            }
        }
    }
}

impl AsperityLaw for InterpolatedLaw {
    delegate_critical_points!(inner);
    fn name(&self) -> &'static str {
        self.inner.name()
    }

    #[inline]
    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        self.table(branch)
            .eval(delta)
            .unwrap_or_else(|| self.inner.state(delta, branch))
    }

    #[inline]
    fn load(&self, delta: f64, branch: Branch) -> f64 {
        self.table(branch)
            .load(delta)
            .unwrap_or_else(|| self.inner.load(delta, branch))
    }

    fn load_after(&self, delta: f64, delta_max: f64) -> f64 {
        self.load(delta, self.branch_after(delta_max))
    }

    fn state_after(&self, delta: f64, delta_max: f64) -> ContactState {
        self.state(delta, self.branch_after(delta_max))
    }

    fn interaction_range(&self) -> f64 {
        self.inner.interaction_range()
    }

    super::delegate_history!(inner);
}

impl LawKernels for InterpolatedLaw {
    /// The panel search walks from the cursor's panel (the same panel as
    /// [`state`](AsperityLaw::state)'s binary search, so the same value).
    #[inline]
    fn state_near(
        &self,
        delta: f64,
        delta_max: Option<f64>,
        cursor: &mut LawCursor,
    ) -> ContactState {
        let branch = delta_max.map_or(Branch::Approach, |m| self.branch_after(m));
        let k = usize::from(branch == Branch::Retract);
        self.tables[k]
            .eval_from(delta, &mut cursor.panels[k])
            .unwrap_or_else(|| self.inner.state(delta, branch))
    }

    /// As [`state_near`](LawKernels::state_near), load only.
    #[inline]
    fn load_near(&self, delta: f64, delta_max: Option<f64>, cursor: &mut LawCursor) -> f64 {
        let branch = delta_max.map_or(Branch::Approach, |m| self.branch_after(m));
        let k = usize::from(branch == Branch::Retract);
        self.tables[k]
            .load_from(delta, &mut cursor.panels[k])
            .unwrap_or_else(|| self.inner.load(delta, branch))
    }

    /// Panels found by walking from the cursor (one walk for ascending
    /// input), then up to eight polynomials interleaved; the same panel
    /// and the same operations as [`load_near`](LawKernels::load_near),
    /// so the same bits.
    fn load_near_batch(
        &self,
        delta: &[f64],
        delta_max: Option<&[f64]>,
        load: &mut [f64],
        cursor: &mut LawCursor,
    ) {
        let n = delta
            .len()
            .min(load.len())
            .min(delta_max.map_or(usize::MAX, <[f64]>::len));
        let mut start = 0;
        while start < n {
            let m = (n - start).min(LANES);
            let mut coef = [[0.0; DEG + 1]; LANES];
            let mut t = [0.0; LANES];
            let mut tabled = [false; LANES];
            for l in 0..m {
                let i = start + l;
                let branch = delta_max.map_or(Branch::Approach, |dm| self.branch_after(dm[i]));
                let k = usize::from(branch == Branch::Retract);
                let table = &self.tables[k];
                match table.locate_from(delta[i], &mut cursor.panels[k]) {
                    Some((p, x)) => {
                        coef[l] = table.load[p];
                        t[l] = x;
                        tabled[l] = true;
                    }
                    None => load[i] = self.inner.load(delta[i], branch),
                }
            }
            let v = horner_lanes(&t, |l, j| coef[l][j]);
            for l in 0..m {
                if tabled[l] {
                    load[start + l] = v[l];
                }
            }
            start += m;
        }
    }

    /// Sorted input (a population's heights) finds each panel by walking
    /// from the previous one (amortised O(1)) instead of a binary search;
    /// the panel found, and so every value, is the one
    /// [`state`](AsperityLaw::state) finds (bit for bit). The polynomials
    /// of a group of asperities run in SIMD lanes (`TableBatch`).
    fn state_batch(
        &self,
        delta: &[f64],
        delta_max: Option<&[f64]>,
        load: &mut [f64],
        radius: &mut [f64],
    ) {
        crate::numeric::simd::arch().dispatch(TableBatch {
            groups: Groups {
                law: self,
                z: delta,
                sep: 0.0,
                max: delta_max.map(|m| (m, 0.0)),
                scale: 1.0,
            },
            sink: Sink::States { load, radius },
        });
    }

    /// The states of [`state_batch`](LawKernels::state_batch) (the same
    /// groups, panels and operations) added to `sums` group by group, in
    /// order, each group's interferences computed in the same pass: no
    /// interference, load or radius arrays (the heights stream from memory
    /// while the polynomials run).
    fn add_state_sums(
        &self,
        z: &[f64],
        sep: f64,
        closest: Option<f64>,
        scale: f64,
        sums: &mut StateSums,
    ) -> bool {
        crate::numeric::simd::arch().dispatch(TableBatch {
            groups: Groups {
                law: self,
                z,
                sep,
                max: closest.map(|c| (z, c)),
                scale,
            },
            sink: Sink::Sums(sums),
        });
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::law::{Hertz, Jkr};

    fn worst(law: &InterpolatedLaw, lo: f64, hi: f64, branch: Branch, p_s: f64) -> f64 {
        let mut w: f64 = 0.0;
        for i in 0..=20_000 {
            let d = lo + (hi - lo) * i as f64 / 20_000.0;
            let (e, g) = (law.inner().state(d, branch), law.state(d, branch));
            w = w.max((e.load - g.load).abs() / (e.load.abs() + p_s));
            assert_eq!(e.in_contact(), g.in_contact(), "contact flag at {d:e}");
        }
        w
    }

    #[test]
    fn coefficients_reproduce_a_polynomial() {
        let x: [f64; DEG + 1] = lobatto_nodes();
        let f: [f64; DEG + 1] = std::array::from_fn(|k| 3.0 * x[k].powi(5) - x[k] + 0.5);
        let c = lobatto_coefficients(&f);
        let a = monomial_coefficients(&c);
        for t in [-1.0, -0.3, 0.0, 0.77, 1.0] {
            let want: f64 = 3.0 * f64::powi(t, 5) - t + 0.5;
            assert!(
                (crate::numeric::chebyshev::clenshaw(&c, t) - want).abs() < 1e-14,
                "{t}"
            );
            assert!((horner(&a, t) - want).abs() < 1e-14, "{t}");
        }
    }

    #[test]
    fn jkr_tables_meet_their_tolerance_on_both_branches() {
        let jkr: Arc<dyn AsperityLaw> = Arc::new(Jkr::new(1e-6, 5e10, 0.5).unwrap());
        let p_s = jkr.pull_off(Control::Load).unwrap().load.abs();
        let (lo, hi) = (-3e-9, 40e-9);
        for tol in [1e-4, 1e-8, 1e-11] {
            let t = InterpolatedLaw::new(jkr.clone(), lo, hi, tol).unwrap();
            for branch in [Branch::Approach, Branch::Retract] {
                let w = worst(&t, lo, hi, branch, p_s);
                // Test points between the checked ones: allow a factor 10.
                assert!(w <= 10.0 * tol, "tol {tol} {branch:?}: {w:e}");
            }
            let (pa, pr) = t.panels();
            assert!(pa > 0 && pr > 0 && pa + pr < 2000, "{pa} {pr}");
        }
    }

    #[test]
    fn hertz_is_relative_and_falls_back_outside() {
        let h: Arc<dyn AsperityLaw> = Arc::new(Hertz::new(1e-6, 5e10).unwrap());
        let t = InterpolatedLaw::new(h.clone(), -1e-9, 1e-8, 1e-9).unwrap();
        for d in [1e-12, 1e-10, 3e-9, 1e-8] {
            let (e, g) = (h.load(d, Branch::Approach), t.load(d, Branch::Approach));
            assert!((e - g).abs() <= 1e-8 * e, "{d:e}: {e} {g}");
        }
        // Outside the table: the law itself.
        assert_eq!(
            t.load(2e-8, Branch::Approach),
            h.load(2e-8, Branch::Approach)
        );
        assert_eq!(t.load(-5e-9, Branch::Approach), 0.0);
    }

    #[test]
    fn bad_arguments_are_rejected() {
        let h: Arc<dyn AsperityLaw> = Arc::new(Hertz::new(1e-6, 5e10).unwrap());
        assert_eq!(
            InterpolatedLaw::new(h.clone(), 0.0, 1e-8, 0.5)
                .unwrap_err()
                .field(),
            Some("tol")
        );
        assert_eq!(
            InterpolatedLaw::new(h.clone(), 1e-8, 1e-8, 1e-6)
                .unwrap_err()
                .field(),
            Some("hi")
        );
        assert_eq!(
            InterpolatedLaw::new(h.clone(), f64::NAN, 1e-8, 1e-6)
                .unwrap_err()
                .field(),
            Some("lo")
        );
        assert_eq!(
            InterpolatedLaw::new(h, 0.0, f64::INFINITY, 1e-6)
                .unwrap_err()
                .field(),
            Some("hi")
        );
    }
}
