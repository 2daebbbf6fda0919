//! The run's tables: `curve.csv` and `montecarlo.csv`, one column per
//! quantity of the plan's [`QuantitySet`](crate::study::quantity::QuantitySet).

use super::sci::{push_sci, sci};
use crate::study::plan::Plan;
use crate::study::quantity::Record;
use crate::study::run::{Results, MIN_SUMMITS_FOR_Z};
use std::fmt::Write as _;

fn cell(x: Option<f64>) -> String {
    x.map_or(String::new(), sci)
}

/// Rows in program order: approach from far to near, then retraction from
/// near to far, with each record's index in `approach ++ retract`.
fn program_order<'a>(
    approach: &'a [Record],
    retract: &'a [Record],
) -> impl Iterator<Item = (&'static str, &'a Record, usize)> {
    let n = approach.len();
    approach
        .iter()
        .enumerate()
        .rev()
        .map(|(i, r)| ("approach", r, i))
        .chain(
            retract
                .iter()
                .enumerate()
                .map(move |(i, r)| ("retract", r, n + i)),
        )
}

/// The curve as CSV: `leg,separation_m` and one column per quantity
/// (`load_N,area_m2,count`, then `resistance_ohm`, ... as the scene has
/// them; empty cells where not computed), approach rows from far to near,
/// then retraction rows from near to far (the order of the program).
pub fn curve_csv(results: &Results, plan: &Plan) -> String {
    let mut out = String::from("leg,separation_m");
    for q in plan.quantities.iter() {
        let _ = write!(out, ",{}", q.column);
    }
    out.push('\n');
    let r = &results.records;
    for (leg, rec, _) in program_order(&r.approach, &r.retract) {
        out.push_str(leg);
        out.push(',');
        push_sci(&mut out, rec.state.separation);
        for v in &rec.values {
            out.push(',');
            if let Some(v) = v {
                push_sci(&mut out, *v);
            }
        }
        out.push('\n');
    }
    out
}

/// The population's curve as CSV: `leg,separation_m`, then per quantity
/// its value and, for totals, its standard error (`load_N,load_se_N,
/// area_m2,area_se_m2,count,count_se`), then each total's deviation from
/// the integral in standard errors (`z_load,z_area,z_count`), `contacts`
/// (the population's summits in contact) and `note`, in the order of
/// [`curve_csv`]. Where fewer than [`MIN_SUMMITS_FOR_Z`] summits are in
/// contact the standard-error and deviation cells are empty and `note`
/// says why: a standard error estimated from so few summits is not one
/// (the central limit does not hold; deviations of 30 "standard errors"
/// appear).
pub fn montecarlo_csv(results: &Results, plan: &Plan) -> Option<String> {
    let m = results.montecarlo.as_ref()?;
    let set = &plan.quantities;
    let observables = set.observables();
    // Totals have a standard error and a deviation (slot `None` where not
    // computed: empty cells); derived quantities only a value.
    let slots: Vec<Option<Option<usize>>> = set
        .iter()
        .map(|q| q.is_total().then(|| q.slot(observables)))
        .collect();
    let mut out = String::from("leg,separation_m");
    for (q, slot) in set.iter().zip(&slots) {
        let _ = write!(out, ",{}", q.column);
        if slot.is_some() {
            let _ = write!(out, ",{}", q.se_column());
        }
    }
    for (q, slot) in set.iter().zip(&slots) {
        if slot.is_some() {
            let _ = write!(out, ",z_{}", q.name);
        }
    }
    out.push_str(",contacts,note\n");
    let min = MIN_SUMMITS_FOR_Z;
    for (leg, rec, k) in program_order(&m.records.approach, &m.records.retract) {
        let contacts = m.contacts.get(k).copied().unwrap_or(0.0);
        let honest = contacts >= min as f64;
        let _ = write!(out, "{leg},{:e}", rec.state.separation);
        for (v, slot) in rec.values.iter().zip(&slots) {
            let _ = write!(out, ",{}", cell(*v));
            if let Some(slot) = slot {
                let se = slot
                    .and_then(|i| v.and(rec.state.totals.error(i)))
                    .filter(|e| honest && e.is_finite());
                let _ = write!(out, ",{}", cell(se));
            }
        }
        for slot in slots.iter().flatten() {
            let z = slot
                .and_then(|i| m.z[k].get(i).copied().flatten())
                .filter(|_| honest);
            let _ = write!(out, ",{}", cell(z));
        }
        let note = if honest {
            String::new()
        } else {
            format!("no standard error: fewer than {min} summits in contact")
        };
        let _ = writeln!(out, ",{contacts},{note}");
    }
    Some(out)
}
