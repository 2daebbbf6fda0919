//! `asperity` with no arguments: the built-in default study, a gold-on-gold
//! microswitch asperity compared under every law.

use asperity::law::LawKind;
use asperity::prelude::*;

pub fn run() -> crate::CliResult {
    let c = AsperityContact::gold_microswitch();
    println!("asperity default study: gold-on-gold microswitch asperity");
    println!(
        "  R = {:.3e} m, E* = {:.4e} Pa (E = 79 GPa, nu = 0.42 both sides), w = {} J/m^2, z0 = {:.2e} m",
        c.radius,
        c.contact_modulus,
        c.adhesion.work(),
        c.adhesion.range()
    );
    println!(
        "  Tabor mu = {:.4}, Maugis lambda = {:.4} (= 1.1570 mu)",
        c.tabor(),
        c.lambda()
    );
    println!();
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
