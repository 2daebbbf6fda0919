//! The crate's one error type.
//!
//! Every constructor that takes physical input validates it and returns
//! [`Error::OutOfRange`] naming the field, the offending value and the allowed
//! range. Inner evaluation (a law at an interference, a distribution at a
//! height) is infallible once the object exists: validation happens where
//! input enters, not in hot loops.

use std::fmt;

/// Result with the crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// Everything that can go wrong in `asperity`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A numeric input is NaN, infinite or outside its physical range.
    #[error("{name} = {} is out of range: allowed {allowed}", show(*value))]
    OutOfRange {
        /// The field or argument, e.g. `poisson_ratio` or `surface.sigma`.
        name: String,
        /// The value given.
        value: f64,
        /// The allowed range, e.g. `[0, 0.5)` or `finite and > 0`.
        allowed: Allowed,
    },
    /// Inputs that are individually valid but inconsistent, or empty.
    #[error("{name}: {reason}")]
    Invalid {
        /// The field or argument.
        name: String,
        /// What is wrong with it.
        reason: String,
    },
    /// An iterative method did not reach its tolerance.
    #[error("{what}: no convergence after {iterations} iterations (residual {residual:e})")]
    NoConvergence {
        /// Which computation.
        what: String,
        /// Iterations spent.
        iterations: usize,
        /// Last residual (method-specific norm).
        residual: f64,
    },
    /// Reading or writing a file failed for a reason that is not the
    /// input's content (missing permission, full disk, a lock held by
    /// another run). Not bad input: the CLI exits 1.
    #[error("{path}: {reason}")]
    Io {
        /// The file or directory.
        path: String,
        /// What went wrong (the operating system's message).
        reason: String,
    },
    /// The work needs more memory than the process may still use (estimated
    /// before anything is allocated). Bad input (the input is too large: the
    /// CLI exits 2); Python raises `MemoryError`.
    #[error(
        "{what}: {doing} needs about {:.1} GB, more than the {:.1} GB of memory available{hint}",
        needed / 1e9,
        available / 1e9
    )]
    OutOfMemory {
        /// The input that is too large (an argument, a file).
        what: String,
        /// What needs the memory (`reading and characterising a map of ...`).
        doing: String,
        /// The estimate (bytes).
        needed: f64,
        /// The memory available (bytes).
        available: f64,
        /// Advice, starting with `: ` (or empty).
        hint: String,
    },
    /// The computation was cancelled by its caller (Ctrl-C; see
    /// [`crate::cancel`]). Not bad input: the CLI exits 130, Python raises
    /// `KeyboardInterrupt`.
    #[error("interrupted")]
    Cancelled,
}

/// A value as a person reads it: plain for moderate magnitudes,
/// scientific (`-5e-9`) otherwise; full precision either way.
fn show(x: f64) -> String {
    let a = x.abs();
    if a == 0.0 || !x.is_finite() || (1e-3..1e6).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// An allowed range for a scalar, printed in interval notation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Allowed {
    /// Lower bound (may be `-inf`).
    pub lo: f64,
    /// Whether `lo` itself is allowed.
    pub lo_inclusive: bool,
    /// Upper bound (may be `+inf`).
    pub hi: f64,
    /// Whether `hi` itself is allowed.
    pub hi_inclusive: bool,
}

impl Allowed {
    /// `(0, inf)`: finite and strictly positive.
    pub const POSITIVE: Allowed = Allowed::open(0.0, f64::INFINITY);
    /// `[0, inf)`: finite and non-negative.
    pub const NON_NEGATIVE: Allowed = Allowed {
        lo: 0.0,
        lo_inclusive: true,
        hi: f64::INFINITY,
        hi_inclusive: false,
    };
    /// `(-inf, inf)`: any finite number.
    pub const FINITE: Allowed = Allowed::open(f64::NEG_INFINITY, f64::INFINITY);

    /// The open interval `(lo, hi)`.
    pub const fn open(lo: f64, hi: f64) -> Self {
        Allowed {
            lo,
            lo_inclusive: false,
            hi,
            hi_inclusive: false,
        }
    }

    /// The closed interval `[lo, hi]`.
    pub const fn closed(lo: f64, hi: f64) -> Self {
        Allowed {
            lo,
            lo_inclusive: true,
            hi,
            hi_inclusive: true,
        }
    }

    /// The half-open interval `(lo, hi]`.
    pub const fn open_closed(lo: f64, hi: f64) -> Self {
        Allowed {
            lo,
            lo_inclusive: false,
            hi,
            hi_inclusive: true,
        }
    }

    /// The half-open interval `[lo, hi)`.
    pub const fn closed_open(lo: f64, hi: f64) -> Self {
        Allowed {
            lo,
            lo_inclusive: true,
            hi,
            hi_inclusive: false,
        }
    }

    /// Whether `x` is finite and inside the interval.
    pub fn contains(&self, x: f64) -> bool {
        if !x.is_finite() {
            return false;
        }
        let above = if self.lo_inclusive {
            x >= self.lo
        } else {
            x > self.lo
        };
        let below = if self.hi_inclusive {
            x <= self.hi
        } else {
            x < self.hi
        };
        above && below
    }

    /// Returns `Ok(x)` when `x` is allowed, otherwise [`Error::OutOfRange`] naming `name`.
    pub fn check(self, name: &str, x: f64) -> Result<f64> {
        if self.contains(x) {
            Ok(x)
        } else {
            Err(Error::OutOfRange {
                name: name.to_string(),
                value: x,
                allowed: self,
            })
        }
    }
}

impl fmt::Display for Allowed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let l = if self.lo_inclusive { '[' } else { '(' };
        let r = if self.hi_inclusive { ']' } else { ')' };
        write!(f, "finite, in {l}{}, {}{r}", show(self.lo), show(self.hi))
    }
}

impl Error {
    /// Shorthand for [`Error::Invalid`].
    pub fn invalid(name: impl Into<String>, reason: impl Into<String>) -> Self {
        Error::Invalid {
            name: name.into(),
            reason: reason.into(),
        }
    }

    /// The same error about field `name` instead (value, range and reason
    /// kept); errors without a field are returned unchanged.
    pub fn renamed(self, name: &str) -> Self {
        match self {
            Error::OutOfRange { value, allowed, .. } => Error::OutOfRange {
                name: name.into(),
                value,
                allowed,
            },
            Error::Invalid { reason, .. } => Error::Invalid {
                name: name.into(),
                reason,
            },
            Error::OutOfMemory {
                doing,
                needed,
                available,
                hint,
                ..
            } => Error::OutOfMemory {
                what: name.into(),
                doing,
                needed,
                available,
                hint,
            },
            other => other,
        }
    }

    /// The same error with its field placed under `table` (`sigma` ->
    /// `surface.sigma`), so messages point into a scene file.
    pub fn in_table(self, table: &str) -> Self {
        match self.field() {
            Some(f) if !f.starts_with(&format!("{table}.")) => {
                let name = format!("{table}.{f}");
                self.renamed(&name)
            }
            _ => self,
        }
    }

    /// The field this error is about, if it names one.
    pub fn field(&self) -> Option<&str> {
        match self {
            Error::OutOfRange { name, .. } | Error::Invalid { name, .. } => Some(name),
            Error::OutOfMemory { what, .. } => Some(what),
            Error::NoConvergence { .. } | Error::Io { .. } | Error::Cancelled => None,
        }
    }

    /// Whether the error is the input's fault (CLI exit 2) rather than a
    /// failure of the computation or the system (exit 1).
    pub fn is_bad_input(&self) -> bool {
        matches!(
            self,
            Error::OutOfRange { .. } | Error::Invalid { .. } | Error::OutOfMemory { .. }
        )
    }

    /// An [`Error::Io`] about `path` from an operating-system error.
    pub fn io(path: impl std::fmt::Display, e: impl std::fmt::Display) -> Self {
        Error::Io {
            path: path.to_string(),
            reason: e.to_string(),
        }
    }
}

/// `x` must be finite and > 0.
pub fn positive(name: &str, x: f64) -> Result<f64> {
    Allowed::POSITIVE.check(name, x)
}

/// `x` must be finite and >= 0.
pub fn non_negative(name: &str, x: f64) -> Result<f64> {
    Allowed::NON_NEGATIVE.check(name, x)
}

/// `x` must be finite.
pub fn finite(name: &str, x: f64) -> Result<f64> {
    Allowed::FINITE.check(name, x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn message_names_field_value_and_range() {
        let e = positive("radius", -1.0).unwrap_err();
        let s = e.to_string();
        assert!(s.contains("radius"), "{s}");
        assert!(s.contains("-1"), "{s}");
        assert!(s.contains("(0, inf)"), "{s}");
        assert_eq!(e.field(), Some("radius"));
    }

    #[test]
    fn renaming_keeps_value_range_and_reason() {
        let e = positive("sigma", -1.0).unwrap_err().in_table("surface");
        assert_eq!(e.field(), Some("surface.sigma"));
        assert!(e.to_string().contains("-1 is out of range"));
        // Already in the table: unchanged.
        assert_eq!(e.clone().in_table("surface"), e);
        let e = Error::invalid("law", "unknown").renamed("law.kind");
        assert_eq!(e.to_string(), "law.kind: unknown");
        let n = Error::NoConvergence {
            what: "x".into(),
            iterations: 1,
            residual: 0.0,
        };
        assert_eq!(n.clone().renamed("y"), n);
    }

    #[test]
    fn small_values_print_in_scientific_notation() {
        let e = positive("surface.sigma", -5e-9).unwrap_err();
        assert!(
            e.to_string().contains("surface.sigma = -5e-9 is out"),
            "{e}"
        );
        let e = Allowed::closed(1e-12, 0.1).check("rtol", 0.5).unwrap_err();
        assert!(e.to_string().contains("[1e-12, 0.1]"), "{e}");
    }

    #[test]
    fn nan_and_infinities_are_rejected_everywhere() {
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            assert!(positive("x", x).is_err());
            assert!(non_negative("x", x).is_err());
            assert!(finite("x", x).is_err());
        }
    }

    #[test]
    fn bounds_respect_inclusivity() {
        let nu = Allowed::closed_open(0.0, 0.5);
        assert!(nu.contains(0.0));
        assert!(nu.contains(0.4999));
        assert!(!nu.contains(0.5));
        assert!(!nu.contains(-1e-300));
        assert!(positive("x", 0.0).is_err());
        assert!(non_negative("x", 0.0).is_ok());
    }

    #[test]
    fn errors_are_send_sync() {
        fn assert_send_sync<T: Send + Sync + 'static>() {}
        assert_send_sync::<Error>();
    }
}
