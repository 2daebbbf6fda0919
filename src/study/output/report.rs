//! The text report of a run (what `asperity run` prints): the summary's
//! numbers with their units, one line each; the states' quantities follow
//! the plan's quantity set.

use super::summary::{McSummary, PopulationSummary, Summary};
use super::{fixed, format};
use crate::study::plan::Plan;
use std::fmt::Write as _;
use std::path::PathBuf;

/// A value with its unit, SI-prefixed ([`format::si`]); `-` when absent.
fn show(x: Option<f64>, unit: &str) -> String {
    x.map_or("-".into(), |v| {
        if unit.is_empty() {
            format::count(v)
        } else {
            format::si(v, unit)
        }
    })
}

/// The report of `summary` (a run of `plan`) and the files it wrote.
pub fn text_report(plan: &Plan, summary: &Summary, files: &[PathBuf]) -> String {
    let mut out = String::new();
    let num = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.4}"));
    let _ = writeln!(
        out,
        "{} — law {}, mu = {}, lambda = {}, {}",
        summary.title.as_deref().unwrap_or("scene"),
        summary.law,
        num(summary.tabor_mu),
        num(summary.maugis_lambda),
        match (summary.summits, &plan.sphere) {
            (_, Some(s)) => format!("rough sphere R = {:e} m", s.radius),
            (Some(n), None) => format!("{n} summits"),
            (None, None) => "- summits".into(),
        }
    );
    if let Some(s) = &summary.rough_sphere {
        let _ = writeln!(
            out,
            "  bump at the closest approach: load {}, radius holding 95 % of the load {} \
             (Hertz {}), approach {}, contacts {}",
            show(Some(s.load.value), "N"),
            show(s.radius_95.map(|e| e.value), "m"),
            show(s.hertz_radius_95, "m"),
            show(Some(s.approach.value), "m"),
            num(s.contacts.map(|e| e.value))
        );
    }
    let _ = writeln!(
        out,
        "  separations {:.3e} .. {:.3e} m, {} points per leg, rtol {:e}",
        summary.closest_separation, summary.start_separation, summary.points, summary.rtol
    );
    model_error(&mut out, summary);
    headlines(&mut out, plan, summary);
    let pull = match (summary.pull_off_load, plan.pull_off) {
        (Some(p), _) => format::si(p, "N"),
        (None, true) => "none: no tensile load on retraction".into(),
        (None, false) => "-".into(),
    };
    let _ = writeln!(out, "  pull-off force     {pull}");
    if let Some(p) = &summary.pull_off_population {
        population(&mut out, p);
    }
    let _ = writeln!(
        out,
        "  hysteresis energy  {}",
        show(summary.hysteresis_energy, "J")
    );
    let _ = writeln!(
        out,
        "  run time           {:.3} s ({} law evaluations)",
        summary.seconds, summary.evaluations
    );
    if let Some(m) = &summary.montecarlo {
        montecarlo(&mut out, m);
    }
    features(&mut out, summary);
    states(&mut out, plan, summary);
    topography(&mut out, summary);
    if !summary.warnings.is_empty() {
        let _ = writeln!(out, "  warnings:");
        for w in &summary.warnings {
            let _ = writeln!(out, "    {w}");
        }
    }
    let _ = writeln!(out, "  wrote:");
    for f in files {
        let _ = writeln!(out, "    {}", f.display());
    }
    out
}

/// The measured map's line, and the other model's headline numbers.
fn topography(out: &mut String, summary: &Summary) {
    if let Some(t) = &summary.topography {
        let _ = writeln!(
            out,
            "  topography         {} ({} x {}), {} summits, model {}",
            t.file, t.rows, t.cols, t.summits.count, t.model
        );
        if let Some(o) = &t.other {
            let _ = writeln!(
                out,
                "    {} model: max load {}, contacts {}, pull-off {}",
                o.model,
                show(o.headlines.get("max_load").flatten(), "N"),
                show(o.headlines.get("max_count").flatten(), ""),
                show(o.pull_off_load, "N")
            );
        }
    }
}

/// One line per headline quantity that has a value or was asked for.
fn headlines(out: &mut String, plan: &Plan, summary: &Summary) {
    for (q, (h, v)) in plan
        .quantities
        .iter()
        .filter(|q| q.headline.is_some())
        .zip(&summary.headlines.0)
    {
        let at = h.qualifier;
        if v.is_some() || q.asked {
            let _ = writeln!(out, "  {:<18} {}{at}", h.label, show(*v, &q.unit_text()));
        }
    }
}

/// GW against the exact elastic solution of the map, one line per load.
fn map_model_error(out: &mut String, m: &super::summary::ModelErrorSummary) {
    let pct = |x: Option<f64>| x.map_or("-".into(), |v| format!("{:+.1} %", 100.0 * v));
    let _ = writeln!(
        out,
        "    GW on this map against the exact elastic solution ({} s):",
        m.exact_seconds.map_or("-".into(), |s| format!("{s:.2}"))
    );
    for (k, s) in m.states.iter().enumerate() {
        let _ = writeln!(
            out,
            "    {:<16} area {} (A/A0 {:.4} exact {:.4}), mean gap {} ({} exact {}), load at the same mean gap {}",
            format::si(s.load_n, "N"),
            pct(m.area.get(k).copied().flatten()),
            s.gw_area_fraction,
            s.exact_area_fraction,
            pct(m.mean_gap.get(k).copied().flatten()),
            format::si(s.gw_mean_gap_m, "m"),
            format::si(s.exact_mean_gap_m, "m"),
            pct(m.load.get(k).copied().flatten()),
        );
    }
}

/// GW's pull-off on the map against the adhesive boundary elements', or why
/// it is not measured.
fn map_pull_off(out: &mut String, p: &crate::study::map_pull_off::MapPullOff) {
    match (p.gw, p.exact) {
        (Some(gw), Some(exact)) => {
            let _ = writeln!(
                out,
                "    pull-off on this map: GW {}, adhesive boundary elements {}, difference {} ({:.2} s; what differs: {})",
                format::si(gw, "N"),
                format::si(exact, "N"),
                p.relative
                    .map_or("-".into(), |v| format!("{:+.1} %", 100.0 * v)),
                p.seconds,
                p.differences
            );
        }
        _ => {
            let _ = writeln!(out, "    pull-off on this map: {}", p.reference);
        }
    }
}

/// The model error lines: on this surface, per output, and for one summit.
fn model_error(out: &mut String, summary: &Summary) {
    let pct = |x: Option<f64>| x.map_or("-".into(), |v| format!("{:+.2} %", 100.0 * v));
    match &summary.model_error {
        Some(m) if m.pull_off.is_some() || m.max_load.is_some() => {
            let _ = writeln!(
                out,
                "  model error        on this surface: pull-off {}, max load {}, hysteresis energy {} \
                 (against {}; rtol {:e} bounds only the numerics)",
                pct(m.pull_off),
                pct(m.max_load),
                pct(m.hysteresis_energy),
                m.reference,
                summary.rtol
            );
        }
        Some(m) => {
            let _ = writeln!(out, "  model error        {}", m.reference);
        }
        None => {}
    }
    if let Some(m) = summary
        .model_error
        .as_ref()
        .filter(|m| !m.states.is_empty())
    {
        map_model_error(out, m);
    }
    if let Some(p) = summary
        .model_error
        .as_ref()
        .and_then(|m| m.pull_off_map.as_ref())
    {
        map_pull_off(out, p);
    }
    if let Some(e) = summary.law_model_error {
        let _ = writeln!(
            out,
            "                     (one summit: law {} differs from the full Lennard-Jones solution by {:.2} %)",
            summary.law,
            100.0 * e
        );
    }
}

fn population(out: &mut String, p: &PopulationSummary) {
    if let (Some(mean), Some(p05), Some(p95)) = (p.mean_n, p.p05_n, p.p95_n) {
        {
            let _ = writeln!(
                out,
                "    one switch       {} +- {} (mean over {} populations of {} summits; 5 %-95 %: {} .. {}; {} summits carry the integral's pull-off)",
                format::si(mean, "N"),
                format::si(p.mean_se_n.unwrap_or(f64::NAN), "N"),
                p.seeds,
                p.summits,
                format::si(p05, "N"),
                format::si(p95, "N"),
                p.carriers.map_or("no".into(), format::count)
            );
        }
    }
    if let Some(n) = &p.note {
        let _ = writeln!(out, "    ({n})");
    }
}

fn montecarlo(out: &mut String, m: &McSummary) {
    let _ = writeln!(
        out,
        "  Monte Carlo        {} summits (seed {}), {:.3} s",
        m.summits, m.seed, m.seconds
    );
    if let (Some(p), Some(se)) = (m.max_load, m.max_load_standard_error) {
        let _ = writeln!(
            out,
            "    max load         {p:.4e} N +- {se:.2e} N (standard error)"
        );
    }
    let _ = writeln!(
        out,
        "    sampled pull-off {} (this realisation: the minimum of its own load curve)",
        show(m.pull_off_load, "N")
    );
    if let Some(s) = &m.spots {
        let _ = writeln!(
            out,
            "    sample's spots   {} at random positions in a {:.3e} m square: parallel {:.4e} Ohm, Greenwood {:.4e} Ohm, exact {}",
            s.count,
            s.side_m,
            s.parallel_ohm,
            s.greenwood_ohm,
            s.exact_ohm
                .map_or("- (more than 3000 spots)".into(), |r| format!("{r:.4e} Ohm"))
        );
    }
    let _ = writeln!(
        out,
        "    integral         {} (minimum of the mean load at the same separations, \
         not the mean of the realisations' minima)",
        show(m.integral_sampled_pull_off_load, "N")
    );
    let _ = match (m.pull_off_seed_mean, m.pull_off_seed_std) {
        (Some(mean), Some(sd)) => writeln!(
            out,
            "    one switch's pull-off over {} seeds: mean {mean:.4e} N, std {sd:.2e} N",
            1 + m.pull_off_other_seeds.len()
        ),
        _ => writeln!(
            out,
            "    pull-off scatter over seeds: not computed (population too large)"
        ),
    };
    if m.states_without_standard_error > 0 {
        let _ = writeln!(
            out,
            "    {} states with fewer than {} summits in contact: no standard error there",
            m.states_without_standard_error,
            crate::study::run::MIN_SUMMITS_FOR_Z
        );
    }
    let _ = writeln!(
        out,
        "    worst deviation of the curve from the integral: {} standard errors (< 5 expected)",
        m.max_abs_z.map_or("-".into(), |z| format!("{z:.2}"))
    );
}

/// Heating, plasticity and stiction lines.
fn features(out: &mut String, summary: &Summary) {
    if let Some(h) = &summary.heating {
        let show =
            |x: Option<f64>, unit: &str| x.map_or("- (no contact)".into(), |v| format::si(v, unit));
        let _ = writeln!(
            out,
            "  heating            {}: contact voltage {}, peak temperature {} (bulk {:.2} K)",
            format::si(h.current_a, "A"),
            show(h.contact_voltage_v, "V"),
            match (h.contact_voltage_v, h.max_temperature_k) {
                (Some(_), None) => "none (the spot melts)".to_string(),
                (_, t) => show(t, "K"),
            },
            h.bulk_temperature_k
        );
    }
    if let Some(p) = &summary.plasticity {
        let pct = |x: Option<f64>| x.map_or("-".into(), |v| format!("{:.1} %", 100.0 * v));
        let _ = writeln!(
            out,
            "  plasticity index   {:.3} (H = {}); contacts at the closest approach: elastic {}, elastic-plastic {}, fully plastic {}",
            p.plasticity_index,
            format::si(p.hardness_pa, "Pa"),
            pct(p.elastic_fraction),
            pct(p.elastic_plastic_fraction),
            pct(p.fully_plastic_fraction)
        );
    }
    if let Some(s) = &summary.stiction {
        let _ = writeln!(
            out,
            "  stiction           pull-off {} ({}), spring k x travel {}, margin {}: {}",
            format::si(s.pull_off_n, "N"),
            if s.pull_off_basis == "population" {
                format!(
                    "exceeded by {:.0} % of the populations",
                    100.0 * (1.0 - s.confidence)
                )
            } else {
                "the integral's".into()
            },
            format::si(s.restoring_force_n, "N"),
            format::si(s.margin_n, "N"),
            if s.sticks {
                "STICKS (margin < 0)"
            } else {
                "reopens"
            }
        );
        if let Some((lo, hi)) = s.sticks_probability_interval {
            let _ = writeln!(
                out,
                "                     probability that a switch sticks {:.3} (95 %: {lo:.3} .. {hi:.3})",
                s.sticks_probability
            );
        }
    }
}

/// The listed states as a table, one column per quantity, each in one
/// unit (the SI prefix of its largest value) with three decimals; counts
/// as [`format::count`].
fn states(out: &mut String, plan: &Plan, summary: &Summary) {
    let Some(states) = &summary.states else {
        return;
    };
    let _ = writeln!(out, "  listed states (approach):");
    let mut columns: Vec<(String, String, Vec<Option<f64>>)> = vec![(
        "separation".into(),
        "m".into(),
        states.iter().map(|s| Some(s.separation_m)).collect(),
    )];
    for (k, q) in plan.quantities.iter().enumerate() {
        columns.push((
            q.name.replace('_', " "),
            q.unit_text(),
            states
                .iter()
                .map(|s| s.values.get(k).and_then(|v| v.1))
                .collect(),
        ));
    }
    // Each column's heading and scale (the SI prefix of its largest value).
    let mut head = Vec::new();
    let mut scales = Vec::new();
    for (name, unit, values) in &columns {
        let finite = || values.iter().flatten().copied().filter(|v| v.is_finite());
        let (scale, prefix) = match unit.as_str() {
            "m^2" => super::si_prefix_area(finite()),
            "N" | "m" | "J" | "Ohm" | "V" | "A" => super::si_prefix(finite()),
            _ => (1.0, ""),
        };
        head.push(if unit.is_empty() {
            name.clone()
        } else {
            format!("{name} {prefix}{unit}")
        });
        scales.push((scale, unit.is_empty()));
    }
    let width = head.iter().map(|h| h.len()).max().unwrap_or(13).max(13);
    let _ = write!(out, "    ");
    for (i, h) in head.iter().enumerate() {
        let sep = if i == 0 { "" } else { " " };
        let _ = write!(out, "{sep}{h:>width$}");
    }
    out.push('\n');
    // The rows written in place (a thousand listed states are a thousand
    // lines: no cell is its own string but the counts').
    for row in 0..states.len() {
        out.push_str("    ");
        for (i, ((_, _, values), (scale, is_count))) in columns.iter().zip(&scales).enumerate() {
            let sep = if i == 0 { "" } else { " " };
            out.push_str(sep);
            match values[row] {
                None => {
                    let _ = write!(out, "{:>width$}", "-");
                }
                Some(x) if *is_count => format::push_count(out, x, width),
                Some(x) => fixed::push_fixed(out, x / scale, 3, width),
            }
        }
        out.push('\n');
    }
}
