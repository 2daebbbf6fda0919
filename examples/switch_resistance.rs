//! Contact resistance against actuation force of an ohmic MEMS switch, and
//! its stiction margin, from the library: gold summits (JKR adhesion) on
//! the default switch surface, Wexler spots with Greenwood's interaction;
//! each force's separation is solved, then the resistance formed from the
//! spot-conductance totals of that state.
//!
//! `cargo run --release --example switch_resistance`
use asperity::prelude::*;
use std::sync::Arc;

fn main() -> asperity::Result<()> {
    let surface = RoughSurface::gold_microswitch();
    let contact = AsperityContact::gold_microswitch();
    let law: Arc<dyn LawKernels> = Arc::from(LawKind::Jkr.build(&contact)?);
    let model =
        GwModel::new(surface, Arc::new(Gaussian::new()), law)?.with_accuracy(Accuracy::new(1e-6)?);
    let spot = SpotResistance::new(Spreading::Wexler, Conductor::GOLD, Conductor::GOLD, 0.0)?;
    let resistance =
        ResistanceObservables::new(spot, Interaction::Greenwood, surface.nominal_area.sqrt());
    let outputs = resistance.add_to(Observables::LOAD)?;
    let start = model.start_separation(1e-8);
    println!(
        "{:>12} {:>16} {:>16}",
        "force (N)", "separation (m)", "resistance (Ohm)"
    );
    for force in [1e-5, 3e-5, 1e-4, 3e-4, 1e-3] {
        let d = model.separation_at_load(force, start)?;
        let s = model.state(d, History::Approach, &outputs)?;
        let r = resistance.value(&outputs, &s.totals);
        println!(
            "{force:>12.1e} {d:>16.4e} {:>16}",
            r.map_or("no contact".into(), |r| format!("{r:.4e}"))
        );
    }
    // Stiction: the pull-off of the same surface after pressing to 1 mN,
    // against a 10 N/m spring over 2 um of travel.
    let closest = model.separation_at_load(1e-3, start)?;
    let pull = model.pull_off(closest, start, 64)?.map_or(0.0, |p| p.load);
    let verdict = Switch::new(10.0, 2e-6)?.stiction(pull)?;
    println!(
        "pull-off {pull:.4e} N, restoring force {:.4e} N, margin {:.4e} N: {}",
        verdict.restoring_force,
        verdict.margin,
        if verdict.sticks { "sticks" } else { "reopens" }
    );
    Ok(())
}
