//! A law tabulated in Maugis units, e.g. calibrated from the full
//! Lennard-Jones sphere solver ([`mod@crate::sphere::calibrate`]).
//!
//! One [`CurveTable`] (dimensionless: `Pbar = P/(pi w R)`,
//! `Dbar = delta/(pi^2 w^2 R/K^2)^(1/3)`, `A = a/(pi w R^2/K)^(1/3)`,
//! `K = 4E*/3`) serves every `R`, `E*`, `w` with the same Tabor parameter.
//! Two branches, each interpolated by PCHIP (monotone, no overshoot):
//! the *detached* branch (approach from far apart up to the jump-in at
//! `attach_bar`) and the *attached* contact branch (from the jump-out at
//! `detach_bar` upwards). Without hysteresis (small mu: no S-curve) both
//! branches are the same curve and attach/detach are `-inf`.
//!
//! Interference origin: `Dbar = 0` where the undeformed bodies are a rigid
//! gap `z0` apart (the Lennard-Jones equilibrium separation, where the
//! continuum laws' surfaces touch). This is the origin of every law in
//! [`crate::law`]: the continuum laws' contact surface is the plane where
//! the Lennard-Jones traction changes sign, so at large loads the
//! calibrated law carries the Hertz/Maugis–Dugdale load at the same
//! interference; Bradley uses it too. Measured from the geometric
//! touching of the force-law planes instead, the same scene would shift by
//! `z0` against the continuum laws (17 % in load at `Pbar = 4`, mu = 2).
//!
//! Outside the table, below its first interference (`Dbar_1`, rigid gap
//! `H_1 = 1 - s Dbar_1 > 1`): Bradley's rigid far field times an elastic
//! enhancement that decays as `H^(-7/2)`,
//! `Pbar = -(8/3) (H^-2 - H^-8/4) [1 + (E_1 - 1) (H_1/H)^(7/2)]`,
//! `H = 1 - s Dbar` the rigid gap in `z0`
//! (`s = alpha/(z0 Dbar) = mu (9 pi^2/16)^(1/3)`), `E_1` the table's ratio
//! to Bradley at its first point (so the load is continuous there). The
//! exponent is first-order elasticity: the far-field traction
//! `~ (w/z0) H^-3` over a patch of radius `sqrt(2 R z0 H)` deflects the
//! half-space by `u ~ mu^(3/2) z0 H^(-5/2)`, changing the force by a
//! relative `~ 2u/(H z0) ~ mu^(3/2) H^(-7/2)`; the full solver confirms it
//! (mu = 1.59: enhancement 2.4e-2, 3.9e-3, 2.6e-4 at H = 6, 10, 20 against
//! 3.9e-3, 3.8e-4 predicted from H = 6). The load is never cut: it decays
//! like `H^-2`, its rough-surface integrals are finite without a cut, and a
//! cut at any gap drops a share `~ (4/3)/H_cut` of the pull-off once sigma
//! is far larger than `H_cut z0`. [`RANGE_GAP`] only places the default
//! start of a loading program ([`AsperityLaw::interaction_range`]).
//!
//! The retraction curve (the continuation, the attached nodes down to the
//! jump-out, the detached branch below, the far field) is checked when the
//! law is built for one minimum ([`LawKernels::retraction_minimum`]): each
//! PCHIP piece is monotone between its nodes, so the node values decide.
//!
//! Above the table's last interference (the calibration reaches
//! `Pbar >= 100`, [`crate::sphere::calibrate::TABLE_MIN_LOAD_BAR`]) a
//! Hertz continuation `Pbar = P_last + Dbar^(3/2) - Dbar_last^(3/2)`,
//! `A^2 = A_last^2 + Dbar - Dbar_last` (adhesion changes slowly there).

use super::{
    AsperityLaw, Branch, ContactState, Control, Instability, InstabilityBar, LawCursor, LawKernels,
    RetractionMinimum,
};
use crate::error::{Error, Result};
use crate::material::MaugisScales;
use crate::numeric::pchip::Pchip;
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// One branch: interference ascending, load and radius (Maugis units).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BranchTable {
    /// `Dbar`, strictly increasing.
    pub interference_bar: Vec<f64>,
    /// `Pbar` at each interference.
    pub load_bar: Vec<f64>,
    /// `A` at each interference (0 when not in contact).
    pub radius_bar: Vec<f64>,
}

/// A dimensionless two-branch law table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CurveTable {
    /// Where the numbers come from.
    pub source: String,
    /// Out-of-contact branch followed on approach, up to the jump-in.
    pub detached: BranchTable,
    /// Contact branch, from the jump-out up.
    pub attached: BranchTable,
    /// Jump-in interference `Dbar`; `None` without hysteresis.
    pub attach_bar: Option<f64>,
    /// Jump-out interference `Dbar`; `None` without hysteresis.
    pub detach_bar: Option<f64>,
    /// Load-controlled pull-off (minimum load).
    pub pull_off: InstabilityBar,
    /// Displacement-controlled jump-out, if any.
    pub jump_out: Option<InstabilityBar>,
    /// Zero-load contact radius `A`, if any.
    pub zero_load_radius_bar: Option<f64>,
    /// `s = mu (9 pi^2/16)^(1/3)`: rigid gap `H = 1 - s Dbar` for the far field.
    pub far_field_scale: f64,
}

/// Rigid gap (units `z0`) beyond which a single asperity's Lennard-Jones
/// pull, `(8/3)/H^2 = 2.7e-4 pi w R`, is below 0.02 % of its pull-off:
/// where the default start of a loading program is placed. The load is
/// not cut there.
pub const RANGE_GAP: f64 = 100.0;

/// Exponent of the far-field elastic enhancement's decay, `(H_1/H)^(7/2)`
/// (first-order elasticity, see the module notes).
pub const ENHANCEMENT_DECAY: f64 = 3.5;

impl CurveTable {
    /// Interference `Dbar = (1 - RANGE_GAP)/s` at the rigid gap
    /// [`RANGE_GAP`].
    pub fn range_bar(&self) -> f64 {
        (1.0 - RANGE_GAP) / self.far_field_scale
    }
}

#[derive(Debug, Clone)]
struct Interp {
    load: Pchip,
    radius: Pchip,
    /// `h1 = 1 - s Dbar_1` at the first node (`s` the far-field scale).
    far_h1: f64,
    /// `sqrt(h1)` (NaN where `h1 < 0`; used only where `h1 > 1`).
    far_sqrt_h1: f64,
    /// `E_1 - 1` with `E_1 = Pbar_1/Bradley(h1)` (used where `h1 > 1`).
    far_excess: f64,
}

impl Interp {
    fn new(b: &BranchTable, which: &str, far_field_scale: f64) -> Result<Self> {
        let bad = || {
            Error::invalid(
                format!("table.{which}"),
                "needs >= 2 finite points with strictly increasing interference and equal lengths",
            )
        };
        let load = Pchip::new(b.interference_bar.clone(), b.load_bar.clone()).ok_or_else(bad)?;
        let radius =
            Pchip::new(b.interference_bar.clone(), b.radius_bar.clone()).ok_or_else(bad)?;
        // Constants of the far field below the first node (per call they
        // cost a division and the Bradley shape).
        let far_h1 = 1.0 - far_field_scale * load.x()[0];
        let far_excess = load.y()[0] / (-BRADLEY * bradley_shape(far_h1)) - 1.0;
        Ok(Interp {
            load,
            radius,
            far_h1,
            far_sqrt_h1: far_h1.sqrt(),
            far_excess,
        })
    }
}

/// A [`CurveTable`] applied to one contact (`R`, `E*`, `w`).
#[derive(Debug, Clone)]
pub struct Tabulated {
    table: Arc<CurveTable>,
    detached: Interp,
    attached: Interp,
    scales: MaugisScales,
    /// `1/scales.interference` (1/m): `Dbar = delta * inv_interference`, a
    /// multiplication where every state took a division.
    inv_interference: f64,
    /// `(Dbar, Pbar)` of the retraction curve's minimum when the curve is
    /// unimodal ([`Tabulated::unimodal_retraction`]).
    retraction_minimum: Option<(f64, f64)>,
}

/// Bradley's load `-(8/3) (H^-2 - H^-8/4)` in `pi w R`: this factor.
const BRADLEY: f64 = 8.0 / 3.0;

/// Rigid LJ sphere force shape `H^-2 - H^-8/4`.
fn bradley_shape(h: f64) -> f64 {
    let x2 = 1.0 / (h * h);
    x2 - 0.25 * x2 * x2 * x2 * x2
}

impl Tabulated {
    /// The table for a sphere of radius `R` (m), contact modulus `E*` (Pa),
    /// work of adhesion `w` (J/m^2).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a bad `radius`, `contact_modulus`,
    /// `work_of_adhesion`; [`Error::Invalid`] naming `table.*` for a table
    /// that is not strictly increasing in interference or has NaNs.
    pub fn new(
        table: Arc<CurveTable>,
        radius: f64,
        contact_modulus: f64,
        work: f64,
    ) -> Result<Self> {
        let scales = MaugisScales::new(radius, contact_modulus, work)?;
        let detached = Interp::new(&table.detached, "detached", table.far_field_scale)?;
        let attached = Interp::new(&table.attached, "attached", table.far_field_scale)?;
        if !(table.far_field_scale > 0.0 && table.far_field_scale.is_finite()) {
            return Err(Error::invalid(
                "table.far_field_scale",
                "must be finite and > 0",
            ));
        }
        let mut law = Tabulated {
            table,
            detached,
            attached,
            scales,
            inv_interference: 1.0 / scales.interference,
            retraction_minimum: None,
        };
        law.retraction_minimum = law.unimodal_retraction();
        Ok(law)
    }

    /// The minimum `(Dbar, Pbar)` of the retraction curve if it is
    /// unimodal ([`RetractionMinimum`]), checked on the points where it can
    /// turn: each PCHIP piece is monotone between its nodes, so the curve
    /// followed on retraction (the Hertz continuation above the attached
    /// branch, its nodes down to the jump-out, the detached branch's below
    /// it, then the far field) is unimodal if these values, in descending
    /// `Dbar`, fall to one minimum and then rise. The far field is monotone
    /// when its elastic enhancement is not negative (`E_1 >= 1`: the factor
    /// and Bradley's shape both fall with the gap); the continuation rises
    /// with `Dbar`. `None` when the check fails.
    fn unimodal_retraction(&self) -> Option<(f64, f64)> {
        let detach = self.table.detach_bar;
        let mut points: Vec<(f64, f64)> = Vec::new();
        let attached = &self.attached.load;
        for (&x, &y) in attached.x().iter().zip(attached.y()).rev() {
            if detach.is_none_or(|a| x >= a) {
                points.push((x, y));
            }
        }
        let far = match detach {
            Some(a) => {
                points.push((a, self.eval(&self.attached, a).0));
                points.push((a, self.eval(&self.detached, a).0));
                let det = &self.detached.load;
                for (&x, &y) in det.x().iter().zip(det.y()).rev() {
                    if x < a {
                        points.push((x, y));
                    }
                }
                &self.detached
            }
            None => &self.attached,
        };
        let (first, p1) = (far.load.x()[0], far.load.y()[0]);
        let h1 = 1.0 - self.table.far_field_scale * first;
        if h1 > 1.0 && p1 / (-BRADLEY * bradley_shape(h1)) < 1.0 {
            return None;
        }
        // A summit that never jumped in stays on the detached branch below
        // the jump-in: it must rise (towards zero) as `Dbar` falls there.
        if let Some(a) = self.table.attach_bar {
            let det = &self.detached.load;
            let mut approach = vec![self.eval(&self.detached, a).0];
            approach.extend(
                det.x()
                    .iter()
                    .zip(det.y())
                    .rev()
                    .filter(|(&x, _)| x < a)
                    .map(|(_, &y)| y),
            );
            if approach.windows(2).any(|w| w[1] < w[0]) {
                return None;
            }
        }
        let k = (0..points.len()).min_by(|&i, &j| points[i].1.total_cmp(&points[j].1))?;
        let falls = points[..=k].windows(2).all(|w| w[1].1 <= w[0].1);
        let rises = points[k..].windows(2).all(|w| w[1].1 >= w[0].1);
        (falls && rises && points[points.len() - 1].1 <= 0.0).then_some(points[k])
    }

    /// The dimensionless table.
    pub fn table(&self) -> &CurveTable {
        &self.table
    }

    /// `(Pbar, A)` on one branch at `Dbar`.
    #[inline]
    fn eval(&self, it: &Interp, d: f64) -> (f64, f64) {
        let mut bisect = usize::MAX;
        self.eval_near(it, d, &mut bisect)
    }

    /// [`eval`](Self::eval) with the PCHIP piece found by walking from
    /// `*hint` (updated; the same piece, so the same value), one search for
    /// the load and the radius (they share their nodes).
    #[inline]
    fn eval_near(&self, it: &Interp, d: f64, hint: &mut usize) -> (f64, f64) {
        let xs = it.load.x();
        let (first, last) = (xs[0], xs[xs.len() - 1]);
        if d < first {
            let h1 = it.far_h1;
            if h1 > 1.0 {
                let p = far_field_bar(
                    self.table.far_field_scale,
                    d,
                    h1,
                    it.far_sqrt_h1,
                    it.far_excess,
                );
                return (p, 0.0);
            }
            return (it.load.y()[0], it.radius.y()[0]);
        }
        if d > last {
            let (p1, a1) = (it.load.y()[xs.len() - 1], it.radius.y()[xs.len() - 1]);
            let p = p1 + d.max(0.0).powf(1.5) - last.max(0.0).powf(1.5);
            return (p, (a1 * a1 + d - last).sqrt());
        }
        // (as `Pchip::eval`: the end values at the ends, and for NaN)
        if !(d > first) {
            return (it.load.y()[0], it.radius.y()[0].max(0.0));
        }
        if d >= last {
            let n = xs.len() - 1;
            return (it.load.y()[n], it.radius.y()[n].max(0.0));
        }
        let k = it.load.piece_near(d, hint);
        (
            it.load.eval_piece(k, d),
            it.radius.eval_piece(k, d).max(0.0),
        )
    }

    /// The branch table of a state and its index (`0` attached, `1`
    /// detached), as [`state`](AsperityLaw::state) chooses it.
    #[inline]
    fn branch_table(&self, d: f64, branch: Branch) -> (&Interp, usize) {
        let on_attached = match branch {
            Branch::Approach => self.table.attach_bar.is_none_or(|a| d >= a),
            Branch::Retract => self.table.detach_bar.is_none_or(|a| d >= a),
        };
        if on_attached {
            (&self.attached, 0)
        } else {
            (&self.detached, 1)
        }
    }

    /// [`state`](AsperityLaw::state) with a walking search from `hints`.
    #[inline]
    fn state_hinted(&self, delta: f64, branch: Branch, hints: &mut [usize; 2]) -> ContactState {
        let d = delta * self.inv_interference;
        let (it, k) = self.branch_table(d, branch);
        let (p, a) = self.eval_near(it, d, &mut hints[k]);
        ContactState {
            load: p * self.scales.load,
            radius: a * self.scales.radius,
        }
    }

    /// The branch of [`state_after`](AsperityLaw::state_after) (the
    /// trait's rule: retraction once the jump-in was reached).
    #[inline]
    fn branch_after(&self, delta_max: f64) -> Branch {
        if delta_max >= self.attach_interference() {
            Branch::Retract
        } else {
            Branch::Approach
        }
    }
}

/// `Pbar` below the table's first node (`h1 = 1 - s Dbar_1 > 1`):
/// `Pbar = Bradley(h) [1 + (E_1 - 1) (h1/h)^(7/2)]`, `h = 1 - s Dbar`,
/// `Bradley(h) = -(8/3)(h^-2 - h^-8/4)`, all from `y = 1/sqrt(h)`
/// ([`inverse_sqrt`]: Newton steps, no division and no root, which bound
/// the far-field sums where every summit is in range): `1/h = y^2` and
/// `(h1/h)^(7/2) = (h1 y^2)^3 sqrt(h1) y` (`sqrt_h1` given; a tenth of
/// `powf`'s cost). The scalar law and the block evaluation share it, so
/// they agree bit for bit.
#[inline(always)]
fn far_field_bar(scale: f64, d: f64, h1: f64, sqrt_h1: f64, excess: f64) -> f64 {
    // A gap beyond the largest double (a separation near 1e300 m) is taken
    // at the largest: the attraction there is 0, where `inverse_sqrt(inf)`
    // would give NaN (a select: the loop stays in vector lanes).
    let h = 1.0 - scale * d;
    let h = if h == f64::INFINITY { f64::MAX } else { h };
    let y = inverse_sqrt(h);
    let inv = y * y;
    let x2 = inv * inv;
    let b = x2 - 0.25 * x2 * x2 * x2 * x2;
    let r = h1 * inv;
    let decay = r * r * r * (sqrt_h1 * y);
    -BRADLEY * b * (1.0 + excess * decay)
}

/// `1/sqrt(h)` for `h >= 1` without the divider: the exponent-halving
/// integer guess (relative error < 3.5 %) and four Newton steps
/// `y <- y (3/2 - h y^2 / 2)` (the error squares each step: 1e-3, 1e-6,
/// 1e-12, then roundoff, a few ulp). Meaningless (but finite or NaN) for
/// `h < 1`, which the far field never takes (`h > h1 > 1`).
#[inline(always)]
fn inverse_sqrt(h: f64) -> f64 {
    let mut y = f64::from_bits(0x5FE6_EB50_C7B5_37A9u64.wrapping_sub(h.to_bits() >> 1));
    let half = 0.5 * h;
    for _ in 0..4 {
        y *= 1.5 - half * y * y;
    }
    y
}

/// The constants of [`Tabulated::eval_near`]'s far field for a block
/// evaluation ([`far_field_bar`] with the branch table chosen by selects).
#[derive(Clone, Copy)]
struct FarField {
    /// `Dbar` from which a state is on the attached table, on approach and
    /// on retraction (`-inf` where the table has no such threshold).
    attach_bar: f64,
    detach_bar: f64,
    /// `[attached, detached]`: first node, `h1`, `sqrt(h1)`, `E_1 - 1`.
    first: [f64; 2],
    h1: [f64; 2],
    sqrt_h1: [f64; 2],
    excess: [f64; 2],
    far_field_scale: f64,
    /// Interference scale (m), its inverse, load and radius scales.
    interference: f64,
    inv_interference: f64,
    load: f64,
    radius: f64,
}

impl FarField {
    fn of(law: &Tabulated) -> Self {
        let its = [&law.attached, &law.detached];
        FarField {
            attach_bar: law.table.attach_bar.unwrap_or(f64::NEG_INFINITY),
            detach_bar: law.table.detach_bar.unwrap_or(f64::NEG_INFINITY),
            first: its.map(|it| it.load.x()[0]),
            h1: its.map(|it| it.far_h1),
            sqrt_h1: its.map(|it| it.far_sqrt_h1),
            excess: its.map(|it| it.far_excess),
            far_field_scale: law.table.far_field_scale,
            interference: law.scales.interference,
            inv_interference: law.inv_interference,
            load: law.scales.load,
            radius: law.scales.radius,
        }
    }

    /// `(load, radius)` (N, m) of the far field at `delta` (m), the radius
    /// NaN where `delta` is not in the far field (the load is then
    /// meaningless).
    #[inline(always)]
    fn state(&self, delta: f64, retract: bool) -> (f64, f64) {
        let d = delta * self.inv_interference;
        let threshold = if retract {
            self.detach_bar
        } else {
            self.attach_bar
        };
        // (selects, not indexing: the loop stays in vector lanes)
        let detached = d < threshold;
        let first = if detached {
            self.first[1]
        } else {
            self.first[0]
        };
        let h1 = if detached { self.h1[1] } else { self.h1[0] };
        let sqrt_h1 = if detached {
            self.sqrt_h1[1]
        } else {
            self.sqrt_h1[0]
        };
        let excess = if detached {
            self.excess[1]
        } else {
            self.excess[0]
        };
        let p = far_field_bar(self.far_field_scale, d, h1, sqrt_h1, excess);
        // NaN marks a state outside the far field (for the scalar pass).
        let far = d < first && h1 > 1.0;
        (
            p * self.load,
            if far { 0.0 * self.radius } else { f64::NAN },
        )
    }
}

/// Every state of a block as if it were in the far field (the others are
/// overwritten after), compiled for the CPU's widest vectors.
struct FarFieldBatch<'a> {
    far: &'a FarField,
    delta: &'a [f64],
    delta_max: Option<&'a [f64]>,
    load: &'a mut [f64],
    radius: &'a mut [f64],
}

impl pulp::WithSimd for FarFieldBatch<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        // A copy of the constants on the stack: kept in registers.
        let far = &{ *self.far };
        let attach = far.attach_bar;
        let out = self.load.iter_mut().zip(self.radius.iter_mut());
        match self.delta_max {
            None => {
                for (&d, (l, r)) in self.delta.iter().zip(out) {
                    (*l, *r) = far.state(d, false);
                }
            }
            Some(m) => {
                // Retraction once the jump-in was reached (`branch_after`).
                let reach = attach * far.interference;
                for ((&d, &m), (l, r)) in self.delta.iter().zip(m).zip(out) {
                    (*l, *r) = far.state(d, m >= reach);
                }
            }
        }
    }
}

impl AsperityLaw for Tabulated {
    fn name(&self) -> &'static str {
        "tabulated"
    }

    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        self.state_hinted(delta, branch, &mut [usize::MAX; 2])
    }

    fn attach_interference(&self) -> f64 {
        self.table
            .attach_bar
            .map_or(f64::NEG_INFINITY, |a| a * self.scales.interference)
    }

    fn detach_interference(&self) -> f64 {
        self.table
            .detach_bar
            .map_or(f64::NEG_INFINITY, |a| a * self.scales.interference)
    }

    /// `-inf`: the Lennard-Jones far field is never cut.
    fn cutoff_interference(&self) -> f64 {
        f64::NEG_INFINITY
    }

    /// The interference at the rigid gap [`RANGE_GAP`].
    fn interaction_range(&self) -> f64 {
        self.table.range_bar() * self.scales.interference
    }

    fn breakpoints(&self, branch: Branch) -> Vec<f64> {
        let b = match branch {
            Branch::Approach => self.table.attach_bar,
            Branch::Retract => self.table.detach_bar,
        };
        b.map(|x| x * self.scales.interference)
            .into_iter()
            .collect()
    }

    fn pull_off(&self, control: Control) -> Option<Instability> {
        let p = match control {
            Control::Load => Some(self.table.pull_off),
            Control::Displacement => self.table.jump_out,
        }?;
        Some(p.to_si(&self.scales))
    }

    fn zero_load_radius(&self) -> Option<f64> {
        self.table
            .zero_load_radius_bar
            .map(|a| a * self.scales.radius)
    }
}

impl LawKernels for Tabulated {
    /// The far field in vector lanes, the walking search for the rest:
    /// 3.5-3.9 ns per evaluation on the `mems-gold` and `calibrated-gold`
    /// populations (`examples/population_cost.rs`), 5.1 on `dmt-stiff`.
    fn batch_cost_ns(&self) -> f64 {
        4.0
    }

    /// The PCHIP piece search walks from the cursor (the same piece as
    /// [`state`](AsperityLaw::state)'s bisection, so the same value).
    #[inline]
    fn state_near(
        &self,
        delta: f64,
        delta_max: Option<f64>,
        cursor: &mut LawCursor,
    ) -> ContactState {
        let branch = delta_max.map_or(Branch::Approach, |m| self.branch_after(m));
        self.state_hinted(delta, branch, &mut cursor.panels)
    }

    /// One walking search per branch table over the whole block (a sorted
    /// population moves a piece or two between summits); bit for bit
    /// [`state`](AsperityLaw::state) / [`state_after`](AsperityLaw::state_after).
    fn state_batch(
        &self,
        delta: &[f64],
        delta_max: Option<&[f64]>,
        load: &mut [f64],
        radius: &mut [f64],
    ) {
        // The far field (every summit below the table, all of them with a
        // long-range law) in vector lanes, the rest (radius NaN after the
        // first pass) by the walking search.
        let far = FarField::of(self);
        crate::numeric::simd::arch().dispatch(FarFieldBatch {
            far: &far,
            delta,
            delta_max,
            load: &mut *load,
            radius: &mut *radius,
        });
        let mut hints = [usize::MAX; 2];
        let out = load.iter_mut().zip(radius.iter_mut());
        match delta_max {
            None => {
                for (&d, (l, r)) in delta.iter().zip(out) {
                    if !r.is_nan() {
                        continue; // in the far field, done
                    }
                    let s = self.state_hinted(d, Branch::Approach, &mut hints);
                    (*l, *r) = (s.load, s.radius);
                }
            }
            Some(m) => {
                for ((&d, &m), (l, r)) in delta.iter().zip(m).zip(out) {
                    if !r.is_nan() {
                        continue; // in the far field, done
                    }
                    let branch = self.branch_after(m);
                    let s = self.state_hinted(d, branch, &mut hints);
                    (*l, *r) = (s.load, s.radius);
                }
            }
        }
    }

    /// The table's retraction is the same for every `delta_max` reaching
    /// the jump-in (no memory); unimodal when the table's nodes say so
    /// (checked when the law is built: see the module notes).
    /// A summit that never reached the jump-in retracts along the detached
    /// branch, whose load rises as the interference falls: its minimum is
    /// at (or above) `delta_max` (`+inf`: the upper end of every window).
    fn retraction_minimum(&self, delta_max: f64) -> Option<RetractionMinimum> {
        let (d, p) = self.retraction_minimum?;
        if delta_max < self.attach_interference() {
            return Some(RetractionMinimum {
                interference: f64::INFINITY,
                load: 0.0,
            });
        }
        Some(RetractionMinimum {
            interference: d * self.scales.interference,
            load: p * self.scales.load,
        })
    }

    /// The far field below the retraction branch's first node (and below
    /// the jump-out): `Pbar = -(8/3)[H^-2 - H^-8/4 + E h1^(7/2) (H^-11/2 -
    /// H^-23/2/4)]` (`E = E_1 - 1`), whose second derivative in `H` is
    /// `-(8/3)[6 H^-4 (1 - 3 H^-6) + 35.75 E h1^(7/2) H^-15/2 (1 - 1.0053
    /// H^-6)]`: negative for `H > 3^(1/6) = 1.2009` when `E >= 0`, so the
    /// load is concave in `H`, hence in the interference (`H = 1 - s Dbar`
    /// is linear). `None` when the table's first gap `h1` is below 1.21 or
    /// the enhancement is negative.
    fn concave_tail(&self) -> Option<f64> {
        let far = if self.table.detach_bar.is_some() {
            &self.detached
        } else {
            &self.attached
        };
        let first = far.load.x()[0];
        let below = self.table.detach_bar.map_or(first, |a| a.min(first));
        (far.far_h1 >= 1.21 && far.far_excess >= 0.0).then_some(below * self.scales.interference)
    }
}

#[cfg(test)]
mod tests {

    #[test]
    fn inverse_sqrt_is_within_four_ulp_of_the_division() {
        let mut worst = 0.0f64;
        let mut h = 1.0f64;
        while h < 1e12 {
            for x in [h, h * 1.000_000_1, h * 1.37, h * 1.999_999_9] {
                let e = (inverse_sqrt(x) * x.sqrt() - 1.0).abs();
                worst = worst.max(e);
            }
            h *= 1.01;
        }
        assert!(worst <= 4.0 * f64::EPSILON, "{worst:e}");
    }

    use super::*;

    fn jkr_table() -> CurveTable {
        // The JKR curve tabulated from its parametric form (attached branch)
        // with an (artificial) detached branch of zero force.
        let a: Vec<f64> = (0..200)
            .map(|k| crate::law::jkr::JUMP_OUT_RADIUS + 0.02 * k as f64)
            .collect();
        let attached = BranchTable {
            interference_bar: a
                .iter()
                .map(|&x| super::super::jkr::interference_bar(x))
                .collect(),
            load_bar: a.iter().map(|&x| super::super::jkr::load_bar(x)).collect(),
            radius_bar: a,
        };
        let detached = BranchTable {
            interference_bar: vec![-3.0, 0.0],
            load_bar: vec![-1e-9, -1e-9],
            radius_bar: vec![0.0, 0.0],
        };
        CurveTable {
            source: "jkr test".into(),
            detached,
            attached,
            attach_bar: Some(0.0),
            detach_bar: Some(crate::law::jkr::JUMP_OUT_INTERFERENCE),
            pull_off: InstabilityBar {
                load_bar: -1.5,
                interference_bar: -0.4,
                radius_bar: 1.14,
            },
            jump_out: None,
            zero_load_radius_bar: Some(crate::law::jkr::ZERO_LOAD_RADIUS),
            far_field_scale: 1.77,
        }
    }

    /// The block evaluation and the cursor walk give the bits of `state`
    /// and `state_after` (the same PCHIP piece as the bisection), on sorted
    /// and shuffled interferences from the far field to beyond the last
    /// node, the nodes themselves and NaN included.
    #[test]
    fn batch_and_cursor_equal_the_scalar_law_bit_for_bit() {
        let tab = Tabulated::new(Arc::new(jkr_table()), 1e-6, 5e10, 0.5).unwrap();
        let z = tab.scales.interference;
        let nodes = tab.attached.load.x().to_vec();
        let mut d: Vec<f64> = (0..700).map(|k| z * (-12.0 + 0.03 * k as f64)).collect();
        d.extend(nodes.iter().map(|x| x * z));
        d.extend([0.0, -3.0 * z, f64::NAN, 1e3 * z]);
        let n = d.len();
        let mut shuffled = d.clone();
        for i in 0..n {
            shuffled.swap(i, (i * 7919 + 13) % n);
        }
        d.extend(shuffled);
        let m: Vec<f64> = d
            .iter()
            .enumerate()
            .map(|(i, &x)| x + z * (i % 3) as f64)
            .collect();
        let (mut load, mut radius) = (vec![0.0; d.len()], vec![0.0; d.len()]);
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
        tab.state_batch(&d, None, &mut load, &mut radius);
        let mut cursor = LawCursor::default();
        for (i, &x) in d.iter().enumerate() {
            let s = tab.state(x, Branch::Approach);
            assert!(same(load[i], s.load) && same(radius[i], s.radius), "{x:e}");
            let c = tab.state_near(x, None, &mut cursor);
            assert!(same(c.load, s.load) && same(c.radius, s.radius), "{x:e}");
        }
        tab.state_batch(&d, Some(&m), &mut load, &mut radius);
        for (i, (&x, &mx)) in d.iter().zip(&m).enumerate() {
            let s = tab.state_after(x, mx);
            assert!(same(load[i], s.load) && same(radius[i], s.radius), "{x:e}");
            let c = tab.state_near(x, Some(mx), &mut cursor);
            assert!(same(c.load, s.load) && same(c.radius, s.radius), "{x:e}");
        }
    }

    /// A table of the JKR curve reproduces the JKR law between its nodes
    /// (PCHIP error O(h^3) on the smooth part; steep near the fold).
    #[test]
    fn tabulated_jkr_matches_jkr() {
        let (r, e, w) = (1e-6, 5e10, 0.5);
        let tab = Tabulated::new(Arc::new(jkr_table()), r, e, w).unwrap();
        let jkr = crate::law::Jkr::new(r, e, w).unwrap();
        let s = jkr.scales();
        for d in [-0.5, 0.0, 0.3, 1.0, 3.0, 8.0] {
            let delta = d * s.interference;
            let a = tab.state(delta, Branch::Retract);
            let b = jkr.state(delta, Branch::Retract);
            assert!((a.load - b.load).abs() < 1e-4 * s.load, "{d}: {a:?} {b:?}");
            assert!((a.radius - b.radius).abs() < 1e-4 * s.radius);
        }
        // approach below attach: detached branch
        let st = tab.state(-0.5 * s.interference, Branch::Approach);
        assert_eq!(st.radius, 0.0);
        assert!(st.load.abs() < 1e-8 * s.load);
        assert_eq!(tab.detach_interference(), jkr.detach_interference());
        assert!(
            (tab.zero_load_radius().unwrap() / jkr.zero_load_radius().unwrap() - 1.0).abs() < 1e-15
        );
        assert!(tab.pull_off(Control::Displacement).is_none());
        // beyond the table: continuous
        let last = *jkr_table().attached.interference_bar.last().unwrap();
        let below = tab
            .state(last * s.interference * (1.0 - 1e-12), Branch::Retract)
            .load;
        let above = tab
            .state(last * s.interference * (1.0 + 1e-12), Branch::Retract)
            .load;
        assert!((below - above).abs() < 1e-6 * below.abs());
    }

    #[test]
    fn bad_tables_and_inputs_are_rejected() {
        let mut t = jkr_table();
        t.attached.interference_bar[3] = t.attached.interference_bar[2];
        let e = Tabulated::new(Arc::new(t), 1e-6, 5e10, 0.5).unwrap_err();
        assert_eq!(e.field(), Some("table.attached"));
        let mut t = jkr_table();
        t.detached.load_bar[0] = f64::NAN;
        let e = Tabulated::new(Arc::new(t), 1e-6, 5e10, 0.5).unwrap_err();
        assert_eq!(e.field(), Some("table.detached"));
        let e = Tabulated::new(Arc::new(jkr_table()), -1.0, 5e10, 0.5).unwrap_err();
        assert_eq!(e.field(), Some("radius"));
        let mut t = jkr_table();
        t.far_field_scale = 0.0;
        let e = Tabulated::new(Arc::new(t), 1e-6, 5e10, 0.5).unwrap_err();
        assert_eq!(e.field(), Some("table.far_field_scale"));
        let e = Tabulated::new(Arc::new(jkr_table()), 1e-6, 5e10, f64::NAN).unwrap_err();
        assert_eq!(e.field(), Some("work_of_adhesion"));
    }
}
