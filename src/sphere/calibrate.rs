//! Calibrated asperity laws from solver curves (placeholder).

/// A calibration.
#[derive(Debug, Clone)]
pub struct Calibration;

/// A cache.
#[derive(Debug, Clone)]
pub struct CalibrationCache;
