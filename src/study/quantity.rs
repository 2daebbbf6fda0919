//! The quantities of a run: every column of `curve.csv`, every key of a
//! listed state, every headline number of the summary (its JSON key, its
//! sweep column and its line in the text report) comes from one
//! [`QuantitySet`], so a new quantity is one [`Quantity`] value and the
//! writers follow.
//!
//! A quantity is either a total of the loading model (load, area, count, or
//! any [`PerAsperity`](crate::loading::PerAsperity) observable) or
//! [`Derived`] from totals (the contact resistance from the spot
//! conductances). Each state of a run is turned once into a [`Record`]
//! holding every quantity's value.

use crate::electrical::{ContactHeating, Heating, ResistanceObservables};
use crate::error::Result;
use crate::loading::{Derived, Observable, Observables, State};
use serde::ser::{Serialize, SerializeMap, Serializer};
use std::sync::Arc;

/// How a quantity is formed from a state's totals.
#[derive(Debug, Clone)]
pub enum Source {
    /// A total of the loading model.
    Total(Observable),
    /// A function of several totals.
    Derived(Arc<dyn Derived>),
}

/// How the summary reduces a quantity over the program to one number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reduce {
    /// Its largest value on approach.
    MaxOnApproach,
    /// Its value at the closest approach (the first approach state).
    AtClosest,
}

/// A quantity's headline number: the summary key, the sweep column, the
/// text report's label and the reduction.
#[derive(Debug, Clone, PartialEq)]
pub struct Headline {
    /// The previous release's key in `summary.json` (e.g. `max_load`),
    /// still written there as a deprecated alias, and the name
    /// [`Headlines::get`] takes.
    pub key: String,
    /// Column of a sweep's `results.csv` and key in `summary.json` (e.g.
    /// `max_load_N`).
    pub sweep: String,
    /// Label in the text report (e.g. `max load`).
    pub label: String,
    /// How the program's states are reduced to it.
    pub reduce: Reduce,
    /// What the text report adds after the value (e.g. `" at the closest
    /// approach"` where the label does not say which state it is).
    pub qualifier: &'static str,
}

/// One quantity of a run's states.
#[derive(Debug, Clone)]
pub struct Quantity {
    /// Short name (`load`, `area`, `count`, `resistance`): the Monte Carlo
    /// table's `<name>_se<unit>` and `z_<name>` columns.
    pub name: String,
    /// Unit as written in column names (`N`, `m2`, `ohm`; empty for
    /// numbers).
    pub unit: String,
    /// Column of `curve.csv` and `montecarlo.csv` (e.g. `load_N`).
    pub column: String,
    /// Key of a listed state in the summary (e.g. `load_N`).
    pub state_key: String,
    /// The summary's headline number, if it has one.
    pub headline: Option<Headline>,
    /// How it is formed.
    pub source: Source,
    /// Whether the scene asked for it (a sweep has a column only for asked
    /// quantities; the standard columns of `curve.csv` are always there,
    /// empty where not computed).
    pub asked: bool,
}

fn with_unit(name: &str, unit: &str) -> String {
    if unit.is_empty() {
        name.to_string()
    } else {
        format!("{name}_{unit}")
    }
}

impl Quantity {
    /// A total named `name` with column unit `unit`: column and state key
    /// `<name>_<unit>`, headline at the closest approach under the same
    /// key and sweep column.
    pub fn total(name: &str, unit: &str, observable: Observable) -> Quantity {
        Quantity::new(name, unit, Source::Total(observable))
    }

    /// A derived quantity, named as [`Quantity::total`].
    pub fn derived(name: &str, unit: &str, derived: Arc<dyn Derived>) -> Quantity {
        Quantity::new(name, unit, Source::Derived(derived))
    }

    fn new(name: &str, unit: &str, source: Source) -> Quantity {
        let column = with_unit(name, unit);
        Quantity {
            name: name.into(),
            unit: unit.into(),
            state_key: column.clone(),
            headline: Some(Headline {
                key: column.clone(),
                sweep: column.clone(),
                label: name.replace('_', " "),
                reduce: Reduce::AtClosest,
                qualifier: "",
            }),
            column,
            source,
            asked: true,
        }
    }

    /// With another key for listed states.
    pub fn state_key(mut self, key: &str) -> Quantity {
        self.state_key = key.into();
        self
    }

    /// With another headline (`None`: no headline number).
    pub fn headline(mut self, headline: Option<Headline>) -> Quantity {
        self.headline = headline;
        self
    }

    /// The observables its value is formed from.
    pub fn needs(&self) -> Vec<Observable> {
        match &self.source {
            Source::Total(o) => vec![o.clone()],
            Source::Derived(d) => d.needs(),
        }
    }

    /// Its value in `state`, whose totals were computed for `observables`.
    pub fn value(&self, observables: &Observables, state: &State) -> Option<f64> {
        match &self.source {
            Source::Total(o) => state.totals.get(observables.slot(o)?),
            Source::Derived(d) => d.value(observables, &state.totals),
        }
    }

    /// The slot of its total (its standard error and deviation in a Monte
    /// Carlo table); `None` for derived quantities.
    pub fn slot(&self, observables: &Observables) -> Option<usize> {
        match &self.source {
            Source::Total(o) => observables.slot(o),
            Source::Derived(_) => None,
        }
    }

    /// Whether it is a total (with a standard error in a population).
    pub fn is_total(&self) -> bool {
        matches!(self.source, Source::Total(_))
    }

    /// The column of its standard error (`<name>_se_<unit>`).
    pub fn se_column(&self) -> String {
        with_unit(&format!("{}_se", self.name), &self.unit)
    }

    /// The unit as people read it (`m^2` for `m2`).
    pub fn unit_text(&self) -> String {
        match self.unit.as_str() {
            "m2" => "m^2".into(),
            "ohm" => "Ohm".into(),
            u => u.into(),
        }
    }
}

/// A state with every quantity's value, in [`QuantitySet`] order.
#[derive(Debug, Clone)]
pub struct Record {
    /// The state.
    pub state: State,
    /// Each quantity's value (`None` where not computed or undefined).
    pub values: Vec<Option<f64>>,
}

/// The quantities of a run and the observables the curve totals for them.
#[derive(Debug, Clone)]
pub struct QuantitySet {
    quantities: Vec<Quantity>,
    observables: Observables,
}

/// Named headline values, serialised as a map in order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Headlines(pub Vec<(Headline, Option<f64>)>);

impl Serialize for Headlines {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.len()))?;
        // Under the key with its unit (the sweep column); the old key is a
        // deprecated alias the summary writes at its end.
        for (h, v) in &self.0 {
            m.serialize_entry(&h.sweep, v)?;
        }
        m.end()
    }
}

impl Headlines {
    /// The value under `key`, if the key is there.
    pub fn get(&self, key: &str) -> Option<Option<f64>> {
        self.0.iter().find(|(h, _)| h.key == key).map(|(_, v)| *v)
    }
}

/// The values of a listed state (or any record), serialised as
/// `{separation_m, <state keys>...}` in order.
#[derive(Debug, Clone, PartialEq)]
pub struct StateRow {
    /// Separation of the flat from the height origin (m).
    pub separation_m: f64,
    /// Each quantity's state key and value.
    pub values: Vec<(String, Option<f64>)>,
}

impl StateRow {
    /// The value under `key`, if the key is there.
    pub fn get(&self, key: &str) -> Option<Option<f64>> {
        self.values.iter().find(|(k, _)| k == key).map(|(_, v)| *v)
    }
}

impl Serialize for StateRow {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.values.len() + 1))?;
        m.serialize_entry("separation_m", &self.separation_m)?;
        for (k, v) in &self.values {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

impl QuantitySet {
    /// Load, area and count, each computed when its flag says so (their
    /// columns are always there, empty where not computed).
    pub fn standard(load: bool, area: bool, count: bool) -> QuantitySet {
        let head = |key: &str, sweep: &str, label: &str, reduce| {
            Some(Headline {
                key: key.into(),
                sweep: sweep.into(),
                label: label.into(),
                reduce,
                qualifier: "",
            })
        };
        let asked = |mut q: Quantity, on: bool| {
            q.asked = on;
            q
        };
        QuantitySet {
            quantities: vec![
                asked(Quantity::total("load", "N", Observable::Load), load).headline(head(
                    "max_load",
                    "max_load_N",
                    "max load",
                    Reduce::MaxOnApproach,
                )),
                asked(Quantity::total("area", "m2", Observable::Area), area)
                    .state_key("real_area_m2")
                    .headline(head(
                        "max_area",
                        "max_area_m2",
                        "max real area",
                        Reduce::AtClosest,
                    )),
                asked(Quantity::total("count", "", Observable::Count), count)
                    .state_key("contacts")
                    .headline(head(
                        "max_count",
                        "max_count",
                        "max contacts",
                        Reduce::AtClosest,
                    )),
            ],
            observables: Observables::standard(load, area, count),
        }
    }

    /// These quantities and `q`, whose observables are added to the
    /// curve's.
    ///
    /// # Errors
    /// When the observables' extra slots are all taken
    /// ([`Observables::with`]).
    pub fn with(mut self, q: Quantity) -> Result<QuantitySet> {
        for o in q.needs() {
            self.observables = self.observables.with(o)?;
        }
        self.quantities.push(q);
        Ok(self)
    }

    /// The contact resistance (`resistance_ohm`; `asked` when the scene's
    /// outputs ask for it) and, with a current, the contact voltage and
    /// peak temperature.
    ///
    /// # Errors
    /// As [`QuantitySet::with`].
    pub fn with_electrical(
        self,
        resistance: &ResistanceObservables,
        asked: bool,
        current: Option<(f64, Heating)>,
    ) -> Result<QuantitySet> {
        let mut r = Quantity::derived("resistance", "ohm", Arc::new(resistance.clone())).headline(
            Some(Headline {
                key: "resistance_ohm".into(),
                sweep: "resistance_ohm".into(),
                label: "resistance".into(),
                reduce: Reduce::AtClosest,
                qualifier: " at the closest approach",
            }),
        );
        r.asked = asked;
        let mut set = self.with(r)?;
        if let Some((i, h)) = current {
            let v = ContactHeating::voltage(resistance.clone(), i);
            let t = ContactHeating::temperature(resistance.clone(), i, h);
            set = set
                .with(Quantity::derived("contact_voltage", "V", Arc::new(v)).headline(None))?
                .with(Quantity::derived("max_temperature", "K", Arc::new(t)).headline(None))?;
        }
        Ok(set)
    }

    /// The observables the curve totals.
    pub fn observables(&self) -> &Observables {
        &self.observables
    }

    /// The same quantities over other observables (everything-on mode
    /// computes more totals than asked).
    ///
    /// # Errors
    /// As [`QuantitySet::with`].
    pub fn over(&self, observables: Observables) -> Result<QuantitySet> {
        let mut o = observables;
        // Load, area and count are computed as `observables` says; every
        // other quantity's totals are added.
        let standard = |q: &Quantity| {
            matches!(
                q.source,
                Source::Total(Observable::Load | Observable::Area | Observable::Count)
            )
        };
        for q in self.quantities.iter().filter(|q| !standard(q)) {
            for n in q.needs() {
                o = o.with(n)?;
            }
        }
        Ok(QuantitySet {
            quantities: self.quantities.clone(),
            observables: o,
        })
    }

    /// The quantities, in column order.
    pub fn iter(&self) -> impl Iterator<Item = &Quantity> {
        self.quantities.iter()
    }

    /// The quantity whose [`Quantity::name`] is `name`, with its index.
    pub fn find(&self, name: &str) -> Option<(usize, &Quantity)> {
        self.quantities
            .iter()
            .enumerate()
            .find(|(_, q)| q.name == name)
    }

    /// `state` with every quantity's value.
    pub fn record(&self, state: &State) -> Record {
        Record {
            state: *state,
            values: self
                .quantities
                .iter()
                .map(|q| q.value(&self.observables, state))
                .collect(),
        }
    }

    /// Every state of `states` as a record.
    pub fn records(&self, states: &[State]) -> Vec<Record> {
        states.iter().map(|s| self.record(s)).collect()
    }

    /// A record's values by state key.
    pub fn row(&self, r: &Record) -> StateRow {
        StateRow {
            separation_m: r.state.separation,
            values: self
                .quantities
                .iter()
                .zip(&r.values)
                .map(|(q, v)| (q.state_key.clone(), *v))
                .collect(),
        }
    }

    /// The headline numbers of approach records `approach` (index 0 the
    /// closest approach), in set order.
    pub fn headlines(&self, approach: &[Record]) -> Headlines {
        Headlines(
            self.quantities
                .iter()
                .enumerate()
                .filter_map(|(i, q)| {
                    let h = q.headline.clone()?;
                    let v = match h.reduce {
                        Reduce::AtClosest => approach.first().and_then(|r| r.values[i]),
                        Reduce::MaxOnApproach => {
                            approach.iter().filter_map(|r| r.values[i]).reduce(f64::max)
                        }
                    };
                    Some((h, v))
                })
                .collect(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::loading::observable::tests::Perimeter;
    use crate::loading::{MethodUsed, Totals, SLOTS};

    fn state(values: [f64; SLOTS], present: [bool; SLOTS], d: f64) -> State {
        State {
            separation: d,
            totals: Totals::new(values, [0.0; SLOTS], present),
            method: MethodUsed::ClosedForm,
            evaluations: 0,
        }
    }

    #[test]
    fn records_and_headlines_follow_the_set() {
        let set = QuantitySet::standard(true, false, true)
            .with(Quantity::total(
                "perimeter",
                "m",
                Observable::Custom(Arc::new(Perimeter)),
            ))
            .unwrap();
        let present = [true, false, true, true, false];
        let near = state([3.0, 0.0, 2.0, 7.0, 0.0], present, 1.0);
        let far = state([5.0, 0.0, 1.0, 4.0, 0.0], present, 2.0);
        let records = set.records(&[near, far]);
        assert_eq!(records[0].values, [Some(3.0), None, Some(2.0), Some(7.0)]);
        let h = set.headlines(&records);
        assert_eq!(h.get("max_load"), Some(Some(5.0)));
        assert_eq!(h.get("max_area"), Some(None));
        assert_eq!(h.get("perimeter_m"), Some(Some(7.0)));
        let row = serde_json::to_string(&set.row(&records[1])).unwrap();
        assert_eq!(
            row,
            r#"{"separation_m":2.0,"load_N":5.0,"real_area_m2":null,"contacts":1.0,"perimeter_m":4.0}"#
        );
    }
}
