//! The full single-sphere adhesive solver (Greenwood 1997, Feng 2000,
//! Greenwood 2009 appendix 1).
pub mod compliance;
mod quadrature;
