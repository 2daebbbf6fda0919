//! [`LawKernels`]: the speed machinery of the laws, an extension of
//! [`AsperityLaw`] with default implementations.

use super::{AsperityLaw, Branch, ContactState, LawCursor, RetractionMinimum, TABULATE_ABOVE_NS};

/// Per-summit words of a loading history that do not depend on the current
/// interference ([`LawKernels::prepare_after`]).
pub type Prepared = [f64; 4];

/// Cost (ns) of one evaluation of a tabulated law (Chebyshev panel or
/// cubic table): the default [`LawKernels::cost_ns`].
pub const TABLE_LOOKUP_NS: f64 = 20.0;

/// The speed machinery of a law. Object-safe; `Send + Sync` through
/// [`AsperityLaw`].
///
/// [`AsperityLaw`] states the physics of one summit (its states, critical
/// points, validity and capabilities). What is here only makes evaluating
/// it cheaper and never changes a number: batches and SIMD lanes, cursors
/// for nearby interferences, per-summit preparation of a history, states
/// fused into lane sums, the bounds of the pruned pull-off search, and cost
/// estimates. Every default is the law's own scalar evaluation (or "no
/// shortcut"), so `impl LawKernels for X {}` is always correct; a law
/// overrides a kernel only to be faster, bit for bit the defaults
/// (`tests/it/simd_widths.rs`, `tests/it/retraction_minimum.rs`,
/// `tests/it/law_properties.rs`), or to state a bound or a cost.
///
/// Integrators that call the kernels ([`GwModel`](crate::gw::GwModel),
/// [`SummitLaw`](crate::montecarlo::SummitLaw) and so
/// [`MonteCarlo`](crate::montecarlo::MonteCarlo)) hold `Arc<dyn LawKernels>`;
/// a `dyn LawKernels` upcasts to `dyn AsperityLaw` where only the physics
/// is needed ([`InterpolatedLaw::new`](super::interpolated::InterpolatedLaw::new)
/// tabulates any `Arc<dyn AsperityLaw>`).
pub trait LawKernels: AsperityLaw {
    /// [`state`](AsperityLaw::state) on approach (`delta_max = None`) or
    /// [`state_after`](AsperityLaw::state_after) on retraction from
    /// `delta_max` (m), bit for bit, for a sequence of nearby interferences
    /// (the nodes of one quadrature panel): tabulated laws start their
    /// panel search at `cursor` (updated) instead of bisecting the whole
    /// table. Default: ignores the cursor.
    fn state_near(
        &self,
        delta: f64,
        delta_max: Option<f64>,
        cursor: &mut LawCursor,
    ) -> ContactState {
        let _ = cursor;
        match delta_max {
            None => self.state(delta, Branch::Approach),
            Some(m) => self.state_after(delta, m),
        }
    }

    /// Load only (N) of [`state_near`](LawKernels::state_near), as
    /// [`load`](AsperityLaw::load) / [`load_after`](AsperityLaw::load_after)
    /// bit for bit.
    fn load_near(&self, delta: f64, delta_max: Option<f64>, cursor: &mut LawCursor) -> f64 {
        let _ = cursor;
        match delta_max {
            None => self.load(delta, Branch::Approach),
            Some(m) => self.load_after(delta, m),
        }
    }

    /// [`load_near`](LawKernels::load_near) for each `delta[i]` (m), with
    /// `delta_max[i]` (m) on retraction, into `load[i]` (N), bit for bit;
    /// the slices have the same length (the shortest bounds the work).
    /// Ascending `delta` (a quadrature panel's nodes) lets a tabulated law
    /// find its panels by one walk and keep several evaluations in flight.
    /// Default: one [`load_near`](LawKernels::load_near) after another.
    fn load_near_batch(
        &self,
        delta: &[f64],
        delta_max: Option<&[f64]>,
        load: &mut [f64],
        cursor: &mut LawCursor,
    ) {
        match delta_max {
            None => {
                for (&d, l) in delta.iter().zip(load.iter_mut()) {
                    *l = self.load_near(d, None, cursor);
                }
            }
            Some(m) => {
                for ((&d, &m), l) in delta.iter().zip(m).zip(load.iter_mut()) {
                    *l = self.load_near(d, Some(m), cursor);
                }
            }
        }
    }

    /// Many asperities in one call (the Monte Carlo hot loop): for each `i`,
    /// `(load[i], radius[i])` (N, m) is `state(delta[i], Approach)` when
    /// `delta_max` is `None` and `state_after(delta[i], delta_max[i])`
    /// otherwise, bit for bit. The law is dispatched once per block instead
    /// of once per asperity; the default loop calls the law's own `state`
    /// statically (inlined), and laws override it with loops the compiler
    /// vectorises ([`Hertz`](super::Hertz)) or searches that exploit sorted input
    /// ([`InterpolatedLaw`](super::interpolated::InterpolatedLaw)). All slices have the same length
    /// (the shortest bounds the work).
    fn state_batch(
        &self,
        delta: &[f64],
        delta_max: Option<&[f64]>,
        load: &mut [f64],
        radius: &mut [f64],
    ) {
        let out = load.iter_mut().zip(radius.iter_mut());
        match delta_max {
            None => {
                for (&d, (l, r)) in delta.iter().zip(out) {
                    let s = self.state(d, Branch::Approach);
                    (*l, *r) = (s.load, s.radius);
                }
            }
            Some(m) => {
                for ((&d, &m), (l, r)) in delta.iter().zip(m).zip(out) {
                    let s = self.state_after(d, m);
                    (*l, *r) = (s.load, s.radius);
                }
            }
        }
    }

    /// Whether [`prepare_after`](LawKernels::prepare_after) saves work
    /// (a plastic summit's unloading shape): sums over many separations
    /// after the same peaks then call it once per summit and
    /// [`state_batch_prepared`](LawKernels::state_batch_prepared) per
    /// separation. Default `false`.
    fn prepares_history(&self) -> bool {
        false
    }

    /// What [`state_after`](AsperityLaw::state_after)`(delta, delta_max[i])`
    /// needs of `delta_max[i]` (m) alone, into `prepared[i]` (the law's own
    /// words: for [`AdhesivePlastic`](super::plastic::AdhesivePlastic) the residual interference and
    /// the JKR scales of the flattened shape). The default leaves it alone.
    fn prepare_after(&self, delta_max: &[f64], prepared: &mut [Prepared]) {
        let _ = (delta_max, prepared);
    }

    /// [`retraction_minimum`](LawKernels::retraction_minimum)`(delta_max)`
    /// bit for bit, from `prepared` = [`prepare_after`](LawKernels::prepare_after)`(delta_max)`.
    /// The default ignores `prepared`.
    fn retraction_minimum_prepared(
        &self,
        delta_max: f64,
        prepared: &Prepared,
    ) -> Option<RetractionMinimum> {
        let _ = prepared;
        self.retraction_minimum(delta_max)
    }

    /// [`state_batch`](LawKernels::state_batch)`(delta, Some(delta_max))`
    /// bit for bit, from `prepared` = [`prepare_after`](LawKernels::prepare_after)`(delta_max)`.
    /// The default ignores `prepared`.
    fn state_batch_prepared(
        &self,
        delta: &[f64],
        delta_max: &[f64],
        prepared: &[Prepared],
        load: &mut [f64],
        radius: &mut [f64],
    ) {
        let _ = prepared;
        self.state_batch(delta, Some(delta_max), load, radius);
    }

    /// Adds to `sums` the states of asperities at interferences
    /// `delta_i = (z_i - sep) scale` (m) on approach, or, after
    /// `closest`, on retraction from `delta_max_i = (z_i - closest) scale`:
    /// state `i` is [`state_batch`](LawKernels::state_batch)'s (bit for
    /// bit, interferences computed in that order), added by
    /// [`StateSums::add`](crate::numeric::lanes::StateSums::add) to lane
    /// `i mod STATE_LANES`, in order; returns `true`. The Monte Carlo
    /// sums of a population (heights `z`, flat at `sep`) call it first: a
    /// law that computes its states inside the sums
    /// ([`InterpolatedLaw`](super::interpolated::InterpolatedLaw): no interference, load or radius
    /// arrays) overrides it. The default adds nothing and returns `false`:
    /// the caller then calls `state_batch` and sums the arrays itself.
    fn add_state_sums(
        &self,
        z: &[f64],
        sep: f64,
        closest: Option<f64>,
        scale: f64,
        sums: &mut crate::numeric::lanes::StateSums,
    ) -> bool {
        let _ = (z, sep, closest, scale, sums);
        false
    }

    /// `Some((k, c))` when the state is `P = k d sqrt(d)`, `a = c sqrt(d)`
    /// with `d = max(delta, 0)` on both branches, evaluated in exactly that
    /// order ([`Hertz`](super::Hertz)): the Monte Carlo sums then fuse the state into
    /// their lane sums (one pass over the heights). Default `None`.
    fn root_monomials(&self) -> Option<(f64, f64)> {
        None
    }

    /// The most tensile point of the retraction curve
    /// `state_after(delta, delta_max).load` over `delta <= delta_max`
    /// (`delta_max` in m), for laws whose retraction load is unimodal in
    /// the interference ([`RetractionMinimum`]); sums over many separations
    /// then bound the load between two separations from its values at
    /// them. Default `None` (shape not known: every separation is
    /// evaluated). Checked for each law that answers by
    /// `tests/it/retraction_minimum.rs` on dense grids.
    ///
    /// A kernel, not physics: only the pruned pull-off search
    /// (`montecarlo::pull_off`, `summation/bounds.rs`) asks, to skip
    /// separations; `None` is always correct, only slower. The physics of
    /// the retraction curve's extremes is
    /// [`pull_off`](AsperityLaw::pull_off).
    fn retraction_minimum(&self, delta_max: f64) -> Option<RetractionMinimum> {
        let _ = delta_max;
        None
    }

    /// An interference (m) below which the load is a concave function of
    /// the interference on every branch, whatever the history: the far
    /// field of a long-range law, where a summit's load between two
    /// separations lies above the chord of its loads there (interference
    /// is linear in the separation). The pruned pull-off search then bounds
    /// the sum of these summits' loads inside a window by the chord of the
    /// sums at its ends, instead of by their least end
    /// ([`RetractionMinimum::window_minimum`]). Default `None`, always
    /// correct: like [`retraction_minimum`](LawKernels::retraction_minimum)
    /// a bound that only prunes work.
    fn concave_tail(&self) -> Option<f64> {
        None
    }

    /// Cost of one evaluation on the approach branch (ns; criterion medians
    /// of `cargo bench --bench laws`, docs/performance.md). The default is
    /// a table lookup, [`TABLE_LOOKUP_NS`].
    fn cost_ns(&self) -> f64 {
        TABLE_LOOKUP_NS
    }

    /// Cost (ns) of one evaluation inside a Monte Carlo sum over sorted
    /// summits ([`state_batch`](LawKernels::state_batch) and the retraction
    /// bounds), which prices a pull-off population. Default
    /// [`cost_ns`](LawKernels::cost_ns); laws with vectorised or walking
    /// batches state theirs, measured by `examples/population_cost.rs`
    /// (docs/performance.md).
    fn batch_cost_ns(&self) -> f64 {
        self.cost_ns()
    }

    /// Whether a loading program should evaluate a Chebyshev table of the
    /// law instead ([`LawKernels::cost_ns`] above [`TABULATE_ABOVE_NS`]);
    /// never for laws that remember their maximum interference (a table
    /// holds one retraction branch).
    fn worth_tabulating(&self) -> bool {
        self.cost_ns() > TABULATE_ABOVE_NS && !self.remembers_maximum()
    }
}
