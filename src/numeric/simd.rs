//! The SIMD instruction set every vectorised pass dispatches to: the widest
//! the CPU has (`pulp::Arch::new()`: AVX-512, else AVX2 + FMA, else
//! scalar), or a narrower one named by the environment variable
//! `ASPERITY_SIMD` (`avx2` or `scalar`; `avx512` and `native` ask for the
//! widest; read once per process; a value not followed is reported in the
//! run's warnings, [`ignored_request`]), so that a
//! machine with AVX-512 can measure the AVX2 code and check that every
//! width gives the same bits (the passes never reorder additions across
//! lanes: `tests/it/simd_widths.rs`).

use std::sync::OnceLock;

/// Name of the environment variable that narrows the instruction set.
pub const SIMD_VARIABLE: &str = "ASPERITY_SIMD";

/// The instruction set to dispatch to (see the module notes). An unknown
/// value of `ASPERITY_SIMD`, or a set the CPU lacks, leaves the widest.
#[inline]
pub fn arch() -> pulp::Arch {
    static ARCH: OnceLock<pulp::Arch> = OnceLock::new();
    *ARCH.get_or_init(|| {
        let wanted = std::env::var(SIMD_VARIABLE).unwrap_or_default();
        match wanted.to_ascii_lowercase().as_str() {
            "scalar" => pulp::Arch::Scalar,
            "avx2" => pulp::x86::V3::try_new().map_or_else(pulp::Arch::new, pulp::Arch::V3),
            _ => pulp::Arch::new(),
        }
    })
}

/// An `ASPERITY_SIMD` value that was not followed: the value asked for and
/// the instruction set the vector passes ran on instead. `Display` words the
/// warning.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IgnoredRequest {
    /// The variable's value, as given.
    pub wanted: String,
    /// The set used ([`arch_name`]).
    pub used: &'static str,
}

impl std::fmt::Display for IgnoredRequest {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{SIMD_VARIABLE}={} not followed (allowed: avx2, scalar, avx512, native, or \
             unset for the widest set the CPU has): the vector passes ran on {} (the numbers are \
             the same at every width, only the time differs)",
            self.wanted, self.used
        )
    }
}

/// Why `ASPERITY_SIMD` was not followed, when it is set to a value that
/// is not `avx2`, `scalar`, `avx512` or `native` (any case), or names a set
/// the CPU lacks: the run then uses [`arch_name`]'s set, and says so.
pub fn ignored_request() -> Option<IgnoredRequest> {
    let wanted = std::env::var(SIMD_VARIABLE).ok()?;
    let lower = wanted.to_ascii_lowercase();
    let followed = match lower.as_str() {
        "scalar" => true,
        "avx2" => arch_name() == "avx2",
        "avx512" => arch_name() == "avx512",
        "" | "native" => return None,
        _ => false,
    };
    (!followed).then(|| IgnoredRequest {
        wanted,
        used: arch_name(),
    })
}

/// The name of the instruction set [`arch`] dispatches to: `avx512`,
/// `avx2` or `scalar`.
pub fn arch_name() -> &'static str {
    match arch() {
        pulp::Arch::V4(_) => "avx512",
        pulp::Arch::V3(_) => "avx2",
        _ => "scalar",
    }
}
