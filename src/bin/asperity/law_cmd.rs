//! `asperity law`: dimensionless pull-off facts of one law, in Maugis units.

use crate::CliError;
use asperity::law::LawKind;
use asperity::named::Named;
use asperity::prelude::*;
use clap::Args;
use serde::Serialize;
use std::f64::consts::PI;

/// Arguments of `asperity law`.
#[derive(Args, Debug)]
pub struct LawArgs {
    /// The law: hertz, bradley, dmt, jkr, maugis, cos.
    #[arg(long)]
    law: String,
    /// Maugis parameter lambda (> 0) for laws that depend on it (maugis,
    /// cos); default 1.
    #[arg(long, allow_negative_numbers = true)]
    lambda: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
}

/// The facts printed, in Maugis units; `None` prints as JSON `null`.
#[derive(Serialize, Debug)]
struct LawFacts {
    law: &'static str,
    lambda: Option<f64>,
    /// Most tensile load on the curve, units of `pi w R`.
    pull_off_load_control: f64,
    /// Load where the contact snaps off under displacement control,
    /// units of `pi w R`; null when nothing snaps.
    jump_out_load: Option<f64>,
    /// Interference of that snap, units of `(pi^2 w^2 R / K^2)^(1/3)`.
    jump_out_interference: Option<f64>,
    /// Zero-load contact radius, units of `(pi w R^2 / K)^(1/3)`.
    contact_radius_zero_load: Option<f64>,
}

pub fn run(args: &LawArgs) -> crate::CliResult {
    let kind = LawKind::parse(&args.law)?;
    if let Some(l) = args.lambda {
        asperity::error::positive("--lambda", l)?;
    }
    let lambda = args.lambda.unwrap_or(1.0);
    // Units where every Maugis scale is 1: R = 1, K = 1 (E* = 3/4),
    // pi w R = 1; the Dugdale stress sigma0 = lambda/2 then gives lambda,
    // and z0 follows from sigma0 = 1.0264 w / z0.
    let w = 1.0 / PI;
    let sigma0 = lambda / 2.0;
    let z0 = asperity::material::LJ_MAX_TENSION_FACTOR * w / sigma0;
    let contact = AsperityContact::new(1.0, 0.75, Adhesion::new(w, z0)?)?;
    let scales = contact.scales()?;
    let law = kind.build(&contact)?;
    let load_pull = law
        .pull_off(Control::Load)
        .map(|p| p.load / scales.load)
        .unwrap_or(0.0);
    let jump = law.pull_off(Control::Displacement);
    let facts = LawFacts {
        law: kind.name(),
        lambda: args.lambda,
        pull_off_load_control: load_pull,
        jump_out_load: jump.map(|j| j.load / scales.load),
        jump_out_interference: jump.map(|j| j.interference / scales.interference),
        contact_radius_zero_load: law.zero_load_radius().map(|a| a / scales.radius),
    };
    if args.json {
        let s = serde_json::to_string(&facts).map_err(|e| CliError::Failed(e.to_string()))?;
        crate::outln!("{s}");
    } else {
        let show =
            |x: Option<f64>| x.map_or("none (nothing snaps)".to_string(), |v| format!("{v:.6}"));
        crate::outln!("law                          {}", facts.law);
        crate::outln!(
            "pull-off, load control       {:.6}  [pi w R]",
            facts.pull_off_load_control
        );
        crate::outln!(
            "jump-out load                {}  [pi w R]",
            show(facts.jump_out_load)
        );
        crate::outln!(
            "jump-out interference        {}  [(pi^2 w^2 R/K^2)^(1/3)]",
            show(facts.jump_out_interference)
        );
        crate::outln!(
            "contact radius at zero load  {}  [(pi w R^2/K)^(1/3)]",
            facts
                .contact_radius_zero_load
                .map_or("none".to_string(), |v| format!("{v:.6}"))
        );
    }
    Ok(())
}
