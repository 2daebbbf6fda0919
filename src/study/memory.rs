//! What work may cost in memory before it starts: estimates from the input
//! sizes (a map from its file's size, an array from its length) against the
//! memory this process may still use (the least of `MemAvailable` in
//! `/proc/meminfo`, the cgroup's `memory.max` less its `memory.current`, and
//! the address-space limit in `/proc/self/limits` less the address space
//! already mapped, `VmSize`; no bound where none is readable). Work beyond
//! it is refused with the estimate ([`Error::OutOfMemory`]: exit 2 on the
//! command line, `MemoryError` in Python) instead of aborting on allocation
//! (a 20000 x 20000 `.npy` map did under an 8 GB limit).

use crate::error::{Error, Result};
use std::path::Path;

/// Peak memory of characterising a map, per byte of a `.npy` file: the
/// bytes read, the heights, and the detrended copy with its difference
/// grids (measured: 2.8 x the file size on a 10000 x 10000 map).
pub const NPY_BYTES_PER_FILE_BYTE: f64 = 3.0;

/// The same per byte of a text map: the text, then at most one height of
/// 8 bytes per 2 characters (`0,`) and its copies.
pub const TEXT_BYTES_PER_FILE_BYTE: f64 = 13.0;

/// Memory (bytes) this process may still allocate, when known.
pub fn available() -> Option<f64> {
    let mut best: Option<f64> = None;
    let mut take = |x: f64| {
        if x.is_finite() && x > 0.0 {
            best = Some(best.map_or(x, |b: f64| b.min(x)));
        }
    };
    if let Ok(t) = std::fs::read_to_string("/proc/meminfo") {
        if let Some(kb) = t
            .lines()
            .find(|l| l.starts_with("MemAvailable:"))
            .and_then(|l| l.split_whitespace().nth(1))
            .and_then(|v| v.parse::<f64>().ok())
        {
            take(kb * 1024.0);
        }
    }
    let read = |p: &str| {
        std::fs::read_to_string(p)
            .ok()
            .and_then(|t| t.trim().parse::<f64>().ok())
    };
    if let Some(max) = read("/sys/fs/cgroup/memory.max") {
        take(max - read("/sys/fs/cgroup/memory.current").unwrap_or(0.0));
    }
    if let Ok(t) = std::fs::read_to_string("/proc/self/limits") {
        if let Some(v) = t
            .lines()
            .find(|l| l.starts_with("Max address space"))
            .and_then(|l| l.split_whitespace().nth(3))
            .and_then(|v| v.parse::<f64>().ok())
        {
            // The limit counts the address space already mapped (the
            // interpreter, libraries, thread stacks).
            let mapped = std::fs::read_to_string("/proc/self/status")
                .ok()
                .and_then(|s| {
                    s.lines()
                        .find(|l| l.starts_with("VmSize:"))
                        .and_then(|l| l.split_whitespace().nth(1))
                        .and_then(|v| v.parse::<f64>().ok())
                })
                .map_or(0.0, |kb| kb * 1024.0);
            take((v - mapped).max(1.0));
        }
    }
    best
}

/// `Ok` when `bytes` fit in the memory [`available`] (or no bound is
/// known), otherwise [`Error::OutOfMemory`] about `what` (the input that is
/// too large), saying what needs the memory (`doing`) and with `hint`
/// (advice, or empty).
///
/// # Errors
/// [`Error::OutOfMemory`].
pub fn ensure(what: &str, doing: &str, bytes: f64, hint: &str) -> Result<()> {
    match available() {
        Some(have) if bytes > have => Err(Error::OutOfMemory {
            what: what.to_string(),
            doing: doing.to_string(),
            needed: bytes,
            available: have,
            hint: if hint.is_empty() {
                String::new()
            } else {
                format!(": {hint}")
            },
        }),
        _ => Ok(()),
    }
}

/// A vector of `n` zeros allocated without aborting: `Err` naming `what`
/// when the allocation fails (the memory estimate of the caller missed).
///
/// # Errors
/// [`Error::OutOfMemory`].
pub fn try_zeros(what: &str, n: usize) -> Result<Vec<f64>> {
    let mut v: Vec<f64> = Vec::new();
    v.try_reserve_exact(n).map_err(|_| Error::OutOfMemory {
        what: what.to_string(),
        doing: format!("a copy of {n} numbers"),
        needed: n as f64 * 8.0,
        available: available().unwrap_or(0.0),
        hint: String::new(),
    })?;
    v.resize(n, 0.0);
    Ok(v)
}

/// The estimated peak memory (bytes) of reading and characterising the
/// map in `path` of `len` bytes, by its extension.
pub fn map_estimate(path: &Path, len: u64) -> f64 {
    let npy = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("npy"));
    let per = if npy {
        NPY_BYTES_PER_FILE_BYTE
    } else {
        TEXT_BYTES_PER_FILE_BYTE
    };
    per * len as f64
}

/// `Ok` when the map in `path` fits in the memory available, when its size
/// cannot be read (the read reports that), or when no bound is known.
///
/// # Errors
/// [`Error::OutOfMemory`] naming the file, with the estimate and the bound.
pub fn check_map(path: &Path) -> Result<()> {
    let Ok(meta) = std::fs::metadata(path) else {
        return Ok(());
    };
    ensure(
        &path.display().to_string(),
        &format!(
            "reading and characterising a map of {:.3e} bytes",
            meta.len() as f64
        ),
        map_estimate(path, meta.len()),
        "crop or downsample it",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_estimate_follows_the_file_and_the_bound_is_positive() {
        let e = map_estimate(Path::new("m.npy"), 1000);
        assert_eq!(e, 3000.0);
        assert_eq!(map_estimate(Path::new("m.txt"), 1000), 13000.0);
        if let Some(a) = available() {
            assert!(a > 0.0);
        }
    }
}
