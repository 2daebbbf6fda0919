//! `asperity` with no arguments: the built-in default study of a gold-on-gold
//! ohmic RF-MEMS switch — every single-asperity law compared for one summit,
//! then the embedded default study (examples/scenes/rf-mems-switch.toml:
//! elastic-plastic summits with adhesion after yield, contact resistance
//! against force, the pull-off distribution of one switch and its stiction
//! probability) run on the rough surface, with its outputs written to
//! `./asperity-out/`.

use asperity::law::LawKind;
use asperity::material::gold;
use asperity::prelude::*;
use asperity::study::{output::si_prefix, Plan, PlanMode, Results, Scene, DEFAULT_STUDY};
use std::path::Path;

/// Rows of the printed load–separation table.
const TABLE_ROWS: usize = 12;

pub fn run() -> crate::CliResult {
    laws_table()?;
    println!();
    let scene = Scene::from_toml(DEFAULT_STUDY)?;
    let plan = crate::run_cmd::planning(|| Plan::new(&scene, PlanMode::Planned))?;
    let results = plan.run()?;
    separation_table(&scene, &results);
    println!();
    crate::run_cmd::report(&plan, &results, Path::new("asperity-out"), false)
}

fn laws_table() -> crate::CliResult {
    let c = AsperityContact::gold_microswitch();
    println!("asperity default study: gold-on-gold ohmic RF-MEMS switch");
    println!();
    println!("One summit:");
    println!(
        "  R = {:.3e} m, E* = {:.4e} Pa (E = {} GPa, nu = {} both sides), w = {} J/m^2, z0 = {:.2e} m",
        c.radius,
        c.contact_modulus,
        gold::YOUNGS_MODULUS / 1e9,
        gold::POISSON_RATIO,
        c.adhesion.work(),
        c.adhesion.range()
    );
    println!(
        "  Tabor mu = {:.4}, Maugis lambda = {:.4} (= 1.1570 mu)",
        c.tabor(),
        c.lambda()
    );
    println!(
        "  {:<10} {:>22} {:>24} {:>22}",
        "law", "pull-off, load ctl [N]", "jump-out, displ. ctl [N]", "a at zero load [m]"
    );
    for kind in LawKind::ALL {
        let law = kind.build(&c)?;
        let fmt = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.4e}"));
        println!(
            "  {:<10} {:>22} {:>24} {:>22}",
            kind.name(),
            fmt(law.pull_off(Control::Load).map(|p| p.load)),
            fmt(law.pull_off(Control::Displacement).map(|p| p.load)),
            fmt(law.zero_load_radius()),
        );
    }
    Ok(())
}

/// A compact load–separation table: every k-th point of both legs.
fn separation_table(scene: &Scene, results: &Results) {
    let c = &results.curve;
    let (ls, lp) = si_prefix(c.approach.iter().chain(&c.retract).filter_map(|s| s.load()));
    let s = &scene.surface;
    println!(
        "Rough surface (A_n = {:.3e} m^2, eta = {:.3e} m^-2, sigma = {:.3e} m, R = {:.3e} m):",
        s.nominal_area, s.density, s.sigma, s.radius
    );
    println!(
        "  {:>16} {:>18} {:>18} {:>14} {:>14}",
        "separation [nm]",
        format!("approach P [{lp}N]"),
        format!("retract P [{lp}N]"),
        "area [um^2]",
        "contacts"
    );
    let n = c.approach.len();
    let step = (n / TABLE_ROWS).max(1);
    // Fixed point in the column's unit: values below its last digit are 0.
    let show = |x: Option<f64>, s: f64| {
        x.map_or("-".into(), |v| {
            let v = v / s;
            if v.abs() < 5e-4 {
                "0".into()
            } else {
                format!("{v:.3}")
            }
        })
    };
    for i in (0..n).rev().step_by(step) {
        let (a, r) = (&c.approach[i], &c.retract[i]);
        println!(
            "  {:>16.3} {:>18} {:>18} {:>14} {:>14}",
            a.separation * 1e9,
            show(a.load(), ls),
            show(r.load(), ls),
            show(a.area(), 1e-12),
            a.count().map_or("-".into(), |v| format!("{v:.2}"))
        );
    }
}
