//! Special functions whose accuracy we promise, each tested against mpmath.
pub mod elliptic;
