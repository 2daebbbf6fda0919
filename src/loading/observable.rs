//! Per-asperity observables and their totals.
//!
//! An observable is a quantity each asperity contributes to a total over the
//! surface: its load `P_i` (N), its contact area `pi a_i^2` (m^2), whether
//! it is in contact (`[a_i > 0]`), or anything else computable from its
//! [`ContactState`] (a spot conductance, a perimeter, ...). The
//! Greenwood–Williamson integral of an observable `g` over heights is
//! `eta A_n int g(state(sigma s - d)) phi(s) ds`; its Monte Carlo sum over a
//! population is `sum_i g(state_i)`. Both integrators evaluate the same
//! [`Observables::evaluate`], so a new observable is one variant plus one
//! per-asperity function (or, outside the crate, one [`PerAsperity`] type in
//! [`Observable::Custom`]).
//!
//! An observable that is a sum of powers of the interference for a law
//! that is one ([`PerAsperity::power_terms`]) is integrated over heights
//! with closed-form `F_n` like the load and area
//! ([`GwModel`](crate::gw::GwModel)); GW's summit caps
//! ([`CapVolume`](crate::gw::CapVolume)) are one.
//!
//! Totals live in fixed slots (no allocation in hot loops): load, area and
//! count in slots 0, 1, 2, further observables after them in the order they
//! were added.

use crate::error::{Error, Result};
use crate::law::{ContactState, PowerForm};
use std::fmt;
use std::sync::Arc;

/// Slots per total: load, area, count and [`EXTRA_SLOTS`] further observables.
pub const SLOTS: usize = 5;
/// Observables beyond load, area and count that one computation can carry.
pub const EXTRA_SLOTS: usize = SLOTS - 3;

/// A per-asperity quantity defined outside the crate.
pub trait PerAsperity: Send + Sync + fmt::Debug {
    /// Short name (a CSV column stem, e.g. `"perimeter_m"`).
    fn name(&self) -> &str;
    /// The asperity's contribution, from its state (SI units of the total).
    fn value(&self, state: &ContactState) -> f64;

    /// [`value`](PerAsperity::value) of the states `(load[i], radius[i])`
    /// into `out[i]` (the shortest slice bounds the work), bit for bit: a
    /// quadrature panel's nodes in one call. Default: one `value` after
    /// another; implement it with a loop the compiler vectorises.
    fn value_batch(&self, load: &[f64], radius: &[f64], out: &mut [f64]) {
        for ((o, &load), &radius) in out.iter_mut().zip(load).zip(radius) {
            *o = self.value(&ContactState { load, radius });
        }
    }

    /// The contribution as a sum of powers of the interference past the
    /// onset of a law whose own sums of powers are `law`
    /// ([`AsperityLaw::power_form`](crate::law::AsperityLaw::power_form)):
    /// terms `(c, n)` of `sum c (delta - onset)^n` (`c` in the total's unit
    /// per m^n), exactly [`value`](PerAsperity::value) of that law's state
    /// at every interference past the onset (and 0 before it). Over heights
    /// `z = sigma s` at separation `d` each term then integrates to
    /// `c sigma^n F_n((d + onset)/sigma)` (Greenwood & Williamson 1966), so
    /// [`GwModel`](crate::gw::GwModel) sums the observable in closed form
    /// where the distribution has closed-form `F_n`. Default `None`:
    /// integrated by quadrature.
    fn power_terms(&self, law: &PowerForm) -> Option<Vec<(f64, f64)>> {
        let _ = law;
        None
    }
}

/// One observable.
#[derive(Clone, Debug)]
pub enum Observable {
    /// Load `P_i` (N), > 0 compressive.
    Load,
    /// Real contact area `pi a_i^2` (m^2).
    Area,
    /// Contact count: 1 when `a_i > 0`, else 0.
    Count,
    /// Any other per-asperity function.
    Custom(Arc<dyn PerAsperity>),
}

impl PartialEq for Observable {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (Observable::Load, Observable::Load)
            | (Observable::Area, Observable::Area)
            | (Observable::Count, Observable::Count) => true,
            (Observable::Custom(a), Observable::Custom(b)) => Arc::ptr_eq(a, b),
            _ => false,
        }
    }
}

impl Observable {
    /// Short name.
    pub fn name(&self) -> &str {
        match self {
            Observable::Load => "load",
            Observable::Area => "area",
            Observable::Count => "count",
            Observable::Custom(c) => c.name(),
        }
    }

    /// The contribution as a sum of powers `(c, n)` of the interference
    /// past the onset of a law of power form `law`: its load and area
    /// terms, `(1, 0)` for the count (every asperity past the onset is in
    /// contact), [`PerAsperity::power_terms`] otherwise.
    pub fn power_terms(&self, law: &PowerForm) -> Option<Vec<(f64, f64)>> {
        match self {
            Observable::Load => Some(law.load.clone()),
            Observable::Area => Some(law.area.clone()),
            Observable::Count => Some(vec![(1.0, 0.0)]),
            Observable::Custom(c) => c.power_terms(law),
        }
    }

    /// The asperity's contribution from its state.
    #[inline(always)]
    pub fn value(&self, s: &ContactState) -> f64 {
        match self {
            Observable::Load => s.load,
            Observable::Area => s.area(),
            Observable::Count => f64::from(u8::from(s.radius > 0.0)),
            Observable::Custom(c) => c.value(s),
        }
    }

    /// [`value`](Observable::value) of the states `(load[k], radius[k])`
    /// into `out[k]`, bit for bit: a custom observable's own
    /// [`PerAsperity::value_batch`], the others one state after another.
    #[inline(always)]
    pub(crate) fn values(&self, load: &[f64], radius: &[f64], out: &mut [f64]) {
        match self {
            Observable::Custom(c) => c.value_batch(load, radius, out),
            other => {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = other.value(&ContactState {
                        load: load[k],
                        radius: radius[k],
                    });
                }
            }
        }
    }
}

/// A quantity of a state formed from its totals, not itself a sum over
/// asperities: the contact resistance from the spot-conductance sums and
/// the contact count, the contact voltage `I R`, ... . Integrators total
/// the observables it [needs](Derived::needs); the value is formed once per
/// state from those totals.
pub trait Derived: Send + Sync + fmt::Debug {
    /// The observables whose totals it is formed from.
    fn needs(&self) -> Vec<Observable>;
    /// Its value from `totals` computed for `observables` (which include
    /// [`Derived::needs`]); `None` where it is undefined (a resistance
    /// without contact) or its totals were not computed.
    fn value(&self, observables: &Observables, totals: &Totals) -> Option<f64>;
}

/// The observables a computation totals: load, area, count (each on or off)
/// and up to [`EXTRA_SLOTS`] more.
#[derive(Clone, Debug, PartialEq)]
pub struct Observables {
    /// Total load (N).
    pub load: bool,
    /// Real contact area (m^2).
    pub area: bool,
    /// Number of contacts.
    pub count: bool,
    extras: Vec<Observable>,
}

impl Observables {
    /// Load, area and count.
    pub const ALL: Observables = Observables::standard(true, true, true);
    /// Load only.
    pub const LOAD: Observables = Observables::standard(true, false, false);

    /// Load, area and count, each on or off; nothing else.
    pub const fn standard(load: bool, area: bool, count: bool) -> Self {
        Observables {
            load,
            area,
            count,
            extras: Vec::new(),
        }
    }

    /// These observables and `o` (no change if already present).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `observables` when all extra slots are taken.
    pub fn with(mut self, o: Observable) -> Result<Self> {
        match o {
            Observable::Load => self.load = true,
            Observable::Area => self.area = true,
            Observable::Count => self.count = true,
            extra => {
                if !self.extras.contains(&extra) {
                    if self.extras.len() == EXTRA_SLOTS {
                        return Err(Error::invalid(
                            "observables",
                            format!(
                                "at most {EXTRA_SLOTS} observables beyond load, area and count"
                            ),
                        ));
                    }
                    self.extras.push(extra);
                }
            }
        }
        Ok(self)
    }

    /// The slot of `o`, if it is one of these observables.
    pub fn slot(&self, o: &Observable) -> Option<usize> {
        match o {
            Observable::Load => self.load.then_some(0),
            Observable::Area => self.area.then_some(1),
            Observable::Count => self.count.then_some(2),
            extra => self.extras.iter().position(|e| e == extra).map(|i| 3 + i),
        }
    }

    /// Which slots are in use.
    pub fn mask(&self) -> [bool; SLOTS] {
        std::array::from_fn(|i| match i {
            0 => self.load,
            1 => self.area,
            2 => self.count,
            k => k - 3 < self.extras.len(),
        })
    }

    /// The observables beyond load, area and count, in slot order.
    pub fn extras(&self) -> &[Observable] {
        &self.extras
    }

    /// Whether only the load is asked for (laws can then skip the contact
    /// radius: [`AsperityLaw::load_after`](crate::law::AsperityLaw::load_after)).
    pub fn load_only(&self) -> bool {
        self.load && !self.area && !self.count && self.extras.is_empty()
    }

    /// [`evaluate`](Observables::evaluate) of the states `(load[k],
    /// radius[k])` times `weight[k]` into `out[k]`, bit for bit the same
    /// products: a quadrature panel in one call, each observable over all
    /// nodes at once ([`PerAsperity::value_batch`]).
    pub fn evaluate_batch<const N: usize>(
        &self,
        load: &[f64; N],
        radius: &[f64; N],
        weight: &[f64; N],
        out: &mut [[f64; SLOTS]; N],
    ) {
        for k in 0..N {
            let s = ContactState {
                load: load[k],
                radius: radius[k],
            };
            let w = weight[k];
            let mut v = [0.0; SLOTS];
            if self.load {
                v[0] = s.load * w;
            }
            if self.area {
                v[1] = s.area() * w;
            }
            if self.count {
                v[2] = f64::from(u8::from(s.radius > 0.0)) * w;
            }
            out[k] = v;
        }
        let mut extra = [0.0; N];
        for (j, e) in self.extras.iter().enumerate() {
            e.values(load, radius, &mut extra);
            for k in 0..N {
                out[k][3 + j] = extra[k] * weight[k];
            }
        }
    }

    /// [`evaluate_batch`](Observables::evaluate_batch) over slices, one
    /// column per slot: `out[j][k]` is slot `j` of the state `(load[k],
    /// radius[k])` times `weight[k]`, the same products bit for bit; only
    /// the slots in use are written (each column resized to
    /// `weight.len()`). Long columns (many states' quadrature nodes) keep
    /// every loop in vector registers (inlined into the caller's SIMD
    /// variant).
    #[inline(always)]
    pub fn evaluate_columns(
        &self,
        load: &[f64],
        radius: &[f64],
        weight: &[f64],
        out: &mut [Vec<f64>; SLOTS],
    ) {
        let n = weight.len();
        let (load, radius) = (&load[..n], &radius[..n]);
        for col in out.iter_mut() {
            col.resize(n, 0.0);
        }
        let [c0, c1, c2, extras @ ..] = out;
        if self.load {
            for k in 0..n {
                c0[k] = load[k] * weight[k];
            }
        }
        if self.area {
            for k in 0..n {
                c1[k] = ContactState {
                    load: load[k],
                    radius: radius[k],
                }
                .area()
                    * weight[k];
            }
        }
        if self.count {
            for k in 0..n {
                c2[k] = f64::from(u8::from(radius[k] > 0.0)) * weight[k];
            }
        }
        for (e, col) in self.extras.iter().zip(extras.iter_mut()) {
            e.values(load, radius, col);
            for k in 0..n {
                col[k] *= weight[k];
            }
        }
    }

    /// Every slot's value for one asperity; unused slots are 0.
    #[inline(always)]
    pub fn evaluate(&self, s: &ContactState) -> [f64; SLOTS] {
        let mut v = [0.0; SLOTS];
        if self.load {
            v[0] = s.load;
        }
        if self.area {
            v[1] = s.area();
        }
        if self.count {
            v[2] = f64::from(u8::from(s.radius > 0.0));
        }
        for (k, e) in self.extras.iter().enumerate() {
            v[3 + k] = e.value(s);
        }
        v
    }
}

/// Totals of the requested observables with their uncertainties, by slot.
///
/// The uncertainty is the numerical error estimate for an integral and the
/// standard error (as an estimate of the expectation) for a population sum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Totals {
    values: [f64; SLOTS],
    errors: [f64; SLOTS],
    present: [bool; SLOTS],
    inverse_distance: Option<f64>,
}

impl Totals {
    /// Totals from slot values, errors and the slots in use (unused slots
    /// read as `None`).
    pub fn new(values: [f64; SLOTS], errors: [f64; SLOTS], present: [bool; SLOTS]) -> Self {
        Totals {
            values,
            errors,
            present,
            inverse_distance: None,
        }
    }

    /// These totals with the spots' conductance-weighted mean inverse
    /// distance `I = int int g(x) g(y)/|x - y| dA dA / G^2` (1/m, `g` the
    /// spot conductance per area, `G` its total), for a model that knows
    /// where its spots lie: a rough sphere's bump
    /// ([`crate::roughsphere`], by Boussinesq through its compliance).
    /// Greenwood's interaction then uses the square whose mean inverse
    /// distance is the same, of side `c_sq / I`
    /// ([`crate::electrical::ResistanceObservables::resistance`]).
    pub fn with_inverse_distance(mut self, inverse_distance: f64) -> Totals {
        self.inverse_distance = Some(inverse_distance);
        self
    }

    /// The spots' conductance-weighted mean inverse distance (1/m), when
    /// the model placed its spots ([`Totals::with_inverse_distance`]);
    /// `None` where they are spread uniformly over the nominal area (a
    /// flat's integral or population).
    pub fn inverse_distance(&self) -> Option<f64> {
        self.inverse_distance
    }

    /// The value in `slot`, if computed.
    pub fn get(&self, slot: usize) -> Option<f64> {
        (slot < SLOTS && self.present[slot]).then(|| self.values[slot])
    }

    /// The uncertainty of `slot`, if computed and defined (`None` for an
    /// undefined one, stored as NaN: e.g. the standard error of a
    /// one-summit population).
    pub fn error(&self, slot: usize) -> Option<f64> {
        (slot < SLOTS && self.present[slot] && !self.errors[slot].is_nan())
            .then(|| self.errors[slot])
    }

    /// Total load (N).
    pub fn load(&self) -> Option<f64> {
        self.get(0)
    }

    /// Real contact area (m^2).
    pub fn area(&self) -> Option<f64> {
        self.get(1)
    }

    /// Number of contacts.
    pub fn count(&self) -> Option<f64> {
        self.get(2)
    }

    /// Every value and error multiplied by `factor`.
    pub fn scaled(&self, factor: f64) -> Totals {
        Totals {
            values: self.values.map(|x| x * factor),
            errors: self.errors.map(|x| x * factor),
            present: self.present,
            // a mean over the spots: the same at any scale of the totals
            inverse_distance: self.inverse_distance,
        }
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A custom per-asperity observable for tests: the contact perimeter
    /// `2 pi a` (m).
    #[derive(Debug)]
    pub(crate) struct Perimeter;
    impl PerAsperity for Perimeter {
        fn name(&self) -> &str {
            "perimeter_m"
        }
        fn value(&self, s: &ContactState) -> f64 {
            2.0 * std::f64::consts::PI * s.radius
        }
    }

    #[test]
    fn slots_follow_the_request() {
        let p = Observable::Custom(Arc::new(Perimeter));
        let o = Observables::standard(true, false, true)
            .with(p.clone())
            .unwrap();
        assert_eq!(o.slot(&Observable::Load), Some(0));
        assert_eq!(o.slot(&Observable::Area), None);
        assert_eq!(o.slot(&p), Some(3));
        let v = o.evaluate(&ContactState {
            load: 2.0,
            radius: 1.0,
        });
        assert_eq!(v, [2.0, 0.0, 1.0, 2.0 * std::f64::consts::PI, 0.0]);
        assert_eq!(o.mask(), [true, false, true, true, false]);
        let full = o
            .with(Observable::Custom(Arc::new(Perimeter)))
            .unwrap()
            .with(Observable::Custom(Arc::new(Perimeter)));
        assert_eq!(full.unwrap_err().field(), Some("observables"));
    }
}
