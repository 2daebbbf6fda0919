//! Files as their pages: a file is memory-mapped read-only, so its bytes
//! are the page cache's and are never copied into the process; the heights
//! of a float64 `.npy` in the machine's byte order are read where they lie
//! ([`npy_map`]). A file that cannot be mapped (empty, a pipe, a file
//! system without mapping) is read instead.
//!
//! The one `unsafe` block of the crate is the mapping: the bytes of a
//! mapped file may change if another process writes or truncates the file
//! while it is read (a truncation ends the process with `SIGBUS`), the risk
//! every memory-mapped reader takes (NumPy's `mmap_mode`); the bytes are
//! only ever read as bytes or as `f64`, every bit pattern of which is a
//! value, and each height is validated before use.

#![allow(unsafe_code)]

use crate::error::{Error, Result};
use crate::surface::{npy, HeightMap, HeightSource, Heights};
use std::path::Path;
use std::sync::Arc;

/// A file's bytes: mapped, or read when mapping fails.
#[derive(Debug)]
pub(crate) enum FileBytes {
    /// The file mapped read-only.
    Mapped(Arc<memmap2::Mmap>),
    /// The file read into memory.
    Read(Vec<u8>),
}

impl std::ops::Deref for FileBytes {
    type Target = [u8];
    fn deref(&self) -> &[u8] {
        match self {
            FileBytes::Mapped(m) => m,
            FileBytes::Read(v) => v,
        }
    }
}

/// The bytes of the file at `path` (named `shown` in errors), mapped when
/// it is a non-empty regular file: all its pages at once (every reader
/// reads the whole file) when the file takes at most half the memory
/// available, lazily otherwise, so that a reader refusing the map from its
/// header touches no page (an 80 GB `.npy` was paged in, 16 s of system
/// time and 22 GB resident, before its header was read and refused).
///
/// # Errors
/// [`Error::Invalid`](crate::Error::Invalid) naming `shown` when the file
/// cannot be opened or read; [`Error::OutOfMemory`](crate::Error::OutOfMemory)
/// when it cannot be mapped and is larger than the memory available (it
/// would be read whole).
pub(crate) fn open(path: &Path, shown: &str) -> Result<FileBytes> {
    let unreadable = |e: std::io::Error| Error::invalid(shown, format!("cannot read: {e}"));
    let mut file = std::fs::File::open(path).map_err(unreadable)?;
    let meta = file.metadata().map_err(unreadable)?;
    let have = crate::study::memory::available();
    let size = meta.len() as f64;
    if meta.is_file() && meta.len() > 0 {
        let mut options = memmap2::MmapOptions::new();
        if have.is_none_or(|have| size <= 0.5 * have) {
            options.populate();
        }
        // SAFETY: a private read-only mapping, read only as bytes or f64
        // (see the module's documentation for a file changed meanwhile).
        let mapped = unsafe { options.map(&file) };
        if let Ok(m) = mapped {
            return Ok(FileBytes::Mapped(Arc::new(m)));
        }
    }
    if let Some(have) = have.filter(|&have| size > have) {
        return Err(Error::OutOfMemory {
            what: shown.into(),
            doing: "reading the file, which cannot be memory-mapped, into memory".into(),
            needed: size,
            available: have,
            hint: String::new(),
        });
    }
    let mut v = Vec::new();
    std::io::Read::read_to_end(&mut file, &mut v).map_err(unreadable)?;
    Ok(FileBytes::Read(v))
}

/// `len` float64 values at `offset` of a mapped file, in the machine's
/// byte order and aligned to 8 bytes (checked by [`npy_map`]).
#[derive(Debug)]
struct MappedF64 {
    map: Arc<memmap2::Mmap>,
    offset: usize,
    len: usize,
}

impl MappedF64 {
    fn slice(&self) -> Option<&[f64]> {
        let bytes = self.map.get(self.offset..self.offset + 8 * self.len)?;
        bytemuck::try_cast_slice(bytes).ok()
    }
}

impl HeightSource for MappedF64 {
    fn heights(&self) -> &[f64] {
        self.slice().unwrap_or(&[])
    }
}

/// The height map of a `.npy` file's bytes: float64 values in the
/// machine's byte order at an offset that is a multiple of 8 (what
/// `numpy.save` writes: its header is padded to 64 bytes) stay in the
/// mapped file, validated in one pass and never copied; other dtypes, byte
/// orders and read files are decoded into one `Vec`.
///
/// # Errors
/// As [`npy::parse`] (named `topography`); [`crate::Error::OutOfMemory`]
/// when the header declares more than the memory available.
pub(crate) fn npy_map(bytes: &FileBytes) -> Result<HeightMap> {
    let l = npy::layout(bytes)?;
    let n = l.rows * l.cols;
    let too_large =
        |per_pixel| super::fits(l.rows, l.cols, per_pixel).map_err(|b| b.error(super::Format::Npy));
    if let FileBytes::Mapped(map) = bytes {
        let native = l.big_endian == cfg!(target_endian = "big");
        let held = MappedF64 {
            map: Arc::clone(map),
            offset: l.offset,
            len: n,
        };
        if l.size == 8 && native && held.slice().is_some() {
            too_large(super::NPY_MAPPED_BYTES_PER_PIXEL)?;
            return HeightMap::from_heights(l.rows, l.cols, Heights::Shared(Arc::new(held)));
        }
    }
    too_large(super::BYTES_PER_PIXEL)?;
    let data = &bytes[l.offset..l.offset + n * l.size];
    HeightMap::new(l.rows, l.cols, npy::decode(data, l.size, l.big_endian))
}
