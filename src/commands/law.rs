//! `asperity law`: dimensionless pull-off facts of one single-asperity law,
//! in Maugis units (load `pi w R`, interference `(pi^2 w^2 R / K^2)^(1/3)`,
//! radius `(pi w R^2 / K)^(1/3)`).

use super::{named, param, CommandResult};
use crate::law::LawKind;
use crate::prelude::*;
use serde::Serialize;
use std::f64::consts::PI;

/// The input of [`facts`].
#[derive(Debug, Clone, Copy)]
pub struct LawInput {
    /// The law (an analytic law of [`LawKind`]).
    pub law: LawKind,
    /// Maugis parameter `lambda` (> 0) for laws that depend on it (maugis,
    /// cos); `None`: 1.
    pub lambda: Option<f64>,
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

/// The pull-off facts of one law in Maugis units (`asperity law`).
///
/// # Errors
/// [`crate::Error::OutOfRange`] naming `{lambda}`.
pub fn facts(input: &LawInput) -> CommandResult<LawFacts> {
    let kind = input.law;
    if let Some(l) = input.lambda {
        crate::error::positive(&param("lambda"), l)?;
    }
    let lambda = input.lambda.unwrap_or(1.0);
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
        .map_err(|e| named(e, &[("lambda", "lambda")]))?;
    let load_pull = law
        .pull_off(Control::Load)
        .map(|p| p.load / scales.load)
        .unwrap_or(0.0);
    let jump = law.pull_off(Control::Displacement);
    Ok(LawFacts {
        law: kind.name(),
        lambda: input.lambda,
        pull_off_load_control: load_pull,
        jump_out_load: jump.map(|j| j.load / scales.load),
        jump_out_interference: jump.map(|j| j.interference / scales.interference),
        contact_radius_zero_load: law.zero_load_radius().map(|a| a / scales.radius),
    })
}
