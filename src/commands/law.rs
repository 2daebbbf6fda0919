//! `asperity law`: dimensionless pull-off facts of one single-asperity law,
//! in Maugis units (load `pi w R`, interference `(pi^2 w^2 R / K^2)^(1/3)`,
//! radius `(pi w R^2 / K)^(1/3)`).

use super::CommandResult;
use crate::law::LawKind;
use crate::named::Named;
use crate::prelude::*;
use serde::Serialize;
use std::f64::consts::PI;

/// Arguments of `asperity law`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct LawArgs {
    /// The law: hertz, bradley, dmt, jkr, maugis, cos.
    #[cfg_attr(feature = "cli", arg(long))]
    pub law: String,
    /// Maugis parameter lambda (> 0) for laws that depend on it (maugis,
    /// cos); default 1.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub lambda: Option<f64>,
    /// Print one JSON object instead of a table.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
}

/// The facts printed, in Maugis units; `None` prints as JSON `null`.
#[derive(Serialize, Debug, Clone)]
pub struct LawFacts {
    /// The law's name.
    pub law: &'static str,
    /// The Maugis parameter given.
    pub lambda: Option<f64>,
    /// Most tensile load on the curve, units of `pi w R`.
    pub pull_off_load_control: f64,
    /// Load where the contact snaps off under displacement control,
    /// units of `pi w R`; null when nothing snaps.
    pub jump_out_load: Option<f64>,
    /// Interference of that snap, units of `(pi^2 w^2 R / K^2)^(1/3)`.
    pub jump_out_interference: Option<f64>,
    /// Zero-load contact radius, units of `(pi w R^2 / K)^(1/3)`.
    pub contact_radius_zero_load: Option<f64>,
}

/// Runs `asperity law`.
pub fn run(args: &LawArgs) -> CommandResult<LawFacts> {
    let kind = LawKind::parse(&args.law).map_err(|e| super::flagged(e, &[("law", "--law")]))?;
    if let Some(l) = args.lambda {
        crate::error::positive("--lambda", l)?;
    }
    let lambda = args.lambda.unwrap_or(1.0);
    // Units where every Maugis scale is 1: R = 1, K = 1 (E* = 3/4),
    // pi w R = 1; the Dugdale stress sigma0 = lambda/2 then gives lambda,
    // and z0 follows from sigma0 = 1.0264 w / z0.
    let w = 1.0 / PI;
    let sigma0 = lambda / 2.0;
    let z0 = crate::material::LJ_MAX_TENSION_FACTOR * w / sigma0;
    let contact = AsperityContact::new(1.0, 0.75, Adhesion::new(w, z0)?)?;
    let scales = contact.scales()?;
    let law = kind
        .build(&contact)
        .map_err(|e| super::flagged(e, &[("lambda", "--lambda")]))?;
    let load_pull = law
        .pull_off(Control::Load)
        .map(|p| p.load / scales.load)
        .unwrap_or(0.0);
    let jump = law.pull_off(Control::Displacement);
    Ok(LawFacts {
        law: kind.name(),
        lambda: args.lambda,
        pull_off_load_control: load_pull,
        jump_out_load: jump.map(|j| j.load / scales.load),
        jump_out_interference: jump.map(|j| j.interference / scales.interference),
        contact_radius_zero_load: law.zero_load_radius().map(|a| a / scales.radius),
    })
}
