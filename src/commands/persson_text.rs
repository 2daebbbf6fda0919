//! The table `asperity persson` prints ([`PerssonOutput::text`]).

use super::persson::PerssonOutput;
use std::fmt::Write as _;

impl PerssonOutput {
    /// The table `asperity persson` prints.
    pub fn text(&self) -> String {
        print_table(self)
    }
}

fn print_table(o: &PerssonOutput) -> String {
    let mut t = String::new();
    let _ = writeln!(t,
        "spectrum        h_rms {:.4e} m, slope_rms {:.4e}, m0 {:.4e} m^2, m2 {:.4e}, m4 {:.4e} 1/m^2",
        o.h_rms_m, o.slope_rms, o.m0, o.m2, o.m4
    );
    let _ = writeln!(
        t,
        "Persson         gamma {}, u0 {:.4e} m, full-contact energy {:.4e} J/m^2",
        o.gamma, o.mean_gap_slope_m, o.full_contact_energy
    );
    if let Some(pt) = o.persson_tosatti_number {
        let _ =
            writeln!(t,
            "Persson-Tosatti U_full/w = {pt:.4e} (below 1: adhesion can pull into full contact)"
        );
    }
    let _ = writeln!(
        t,
        "GW (McCool)     eta {:.4e} 1/m^2, R {:.4e} m, sigma {:.4e} m",
        o.gw.density_per_m2, o.gw.radius_m, o.gw.sigma_m
    );
    let _ = writeln!(
        t,
        "{:>14} {:>14} {:>14} {:>14} {:>14} {:>10} {:>10}",
        "p (Pa)", "A/A0", "u (m)", "GW A/A0", "GW u (m)", "GW/P A", "GW/P u"
    );
    let pct = |v: f64| {
        if v.is_finite() {
            format!("{:+.1}%", 100.0 * v)
        } else {
            "-".to_string()
        }
    };
    for s in &o.states {
        let _ = writeln!(
            t,
            "{:>14.6e} {:>14.6e} {:>14.6e} {:>14.6e} {:>14.6e} {:>10} {:>10}",
            s.pressure,
            s.area_fraction,
            s.mean_gap_m,
            s.gw_area_fraction,
            s.gw_mean_gap_m,
            pct(s.gw_vs_persson_area),
            pct(s.gw_vs_persson_mean_gap)
        );
    }
    let _ = writeln!(
        t,
        "(GW/P A, GW/P u: GW's area fraction and mean gap against Persson's, GW/Persson - 1)"
    );
    if let Some(c) = &o.assessment.adhesion_criteria {
        t.push_str(&c.criteria.text());
    }
    if let Some(c) = &o.assessment.capillary {
        t.push_str(&super::wet_persson::text(c));
    }
    o.assessment.closing_lines(&mut t);
    t
}
