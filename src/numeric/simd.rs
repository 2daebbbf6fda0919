//! The SIMD instruction set every vectorised pass dispatches to: the widest
//! the CPU has (`pulp::Arch::new()`: AVX-512, else AVX2 + FMA, else
//! scalar), or a narrower one named by the environment variable
//! `ASPERITY_SIMD` (`avx2` or `scalar`; read once per process), so that a
//! machine with AVX-512 can measure the AVX2 code and check that every
//! width gives the same bits (the passes never reorder additions across
//! lanes: `tests/simd_widths.rs`).

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

/// The name of the instruction set [`arch`] dispatches to: `avx512`,
/// `avx2` or `scalar`.
pub fn arch_name() -> &'static str {
    match arch() {
        pulp::Arch::V4(_) => "avx512",
        pulp::Arch::V3(_) => "avx2",
        _ => "scalar",
    }
}
