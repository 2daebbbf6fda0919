//! A zip member of binary heights read whole, straight from the archive's
//! bytes (the memory-mapped file) into the heights' buffer: a stored member
//! is copied there, a deflated one (raw deflate, RFC 1951) inflated there
//! in one call, then its CRC-32 checked and its values decoded in place,
//! one pass over the buffer in blocks that stay in the cache.
//!
//! Against streaming the member through the `zip` crate's reader 64 KiB at
//! a time into a second buffer this saves the reader's copies and one pass
//! over the heights; the inflate itself (about three quarters of reading a
//! deflated float64 X3P) is the same `zlib-rs` code (`docs/performance.md`,
//! "Reading measured maps").

use super::Bad;
use rayon::prelude::*;
use std::io::Cursor;

/// Values per block of the checking and decoding pass (64 KiB of float64).
const BLOCK: usize = 1 << 13;

/// Bytes handed to the inflater per call (its counters are 32-bit).
const STEP: usize = 1 << 30;

/// The `rows x cols` values of `N` bytes each, little-endian, of the zip
/// member `name` of the archive `bytes` (opened as `zip`), each turned into
/// a height by `f`, when the member is stored or deflated, not encrypted,
/// and declares exactly `rows x cols x N` bytes; `Ok(None)` otherwise (the
/// caller streams it). The member must inflate to exactly its declared
/// size and match its CRC-32.
///
/// The heights' buffer (`rows x cols` float64) receives the member's bytes
/// in its last `rows x cols x N` bytes; value `k` is decoded from there
/// into place `k`, forward, which never overwrites a value not yet read
/// (`8 (k + 1) <= (8 - N) rows cols + N (k + 1)` for `k < rows cols`).
///
/// # Errors
/// `Bad` naming the member: no such member, a damaged deflate stream, one
/// that ends before or runs past the declared size (truncated), or a CRC-32
/// mismatch.
pub(super) fn whole_member<const N: usize>(
    bytes: &[u8],
    zip: &mut zip::ZipArchive<Cursor<&[u8]>>,
    name: &str,
    rows: usize,
    cols: usize,
    f: impl Fn([u8; N]) -> f64 + Sync,
) -> Result<Option<Vec<f64>>, Bad> {
    const { assert!(N >= 1 && N <= 8) };
    let n = super::grid(rows, cols)?;
    let want = n * N;
    let file = zip
        .by_name(name)
        .map_err(|e| Bad::corrupt(format!("no member '{name}' in the archive ({e})")))?;
    let method = file.compression();
    let (size, packed, crc) = (file.size(), file.compressed_size(), file.crc32());
    let start = file.data_start();
    let kind = match method {
        zip::CompressionMethod::Stored => packed == want as u64,
        zip::CompressionMethod::Deflated => true,
        _ => false,
    };
    let plain = kind && !file.encrypted() && size == want as u64;
    drop(file);
    let src = match start.and_then(|s| {
        let end = s.checked_add(packed)?;
        bytes.get(usize::try_from(s).ok()?..usize::try_from(end).ok()?)
    }) {
        Some(src) if plain => src,
        _ => return Ok(None),
    };
    let mut z = vec![0f64; n];
    let buf: &mut [u8] = bytemuck::cast_slice_mut(&mut z);
    let off = buf.len() - want;
    let dst = &mut buf[off..];
    match method {
        zip::CompressionMethod::Stored => dst.copy_from_slice(src),
        zip::CompressionMethod::Deflated => inflate(src, dst, name, (rows, cols, N))?,
        _ => return Ok(None),
    }
    let got = if N == 8 {
        // In place, value by value: the blocks are independent.
        buf.par_chunks_mut(8 * BLOCK)
            .map(|b| check_decode::<N>(b, 0, b.len() / 8, &f))
            .collect::<Vec<_>>()
            .into_iter()
            .fold(crc32fast::Hasher::new(), |mut all, h| {
                all.combine(&h);
                all
            })
    } else {
        check_decode::<N>(buf, off, n, &f)
    }
    .finalize();
    if got != crc {
        return Err(Bad::corrupt(format!(
            "member '{name}' fails its CRC-32 check (the archive says {crc:08x}, its bytes give \
             {got:08x})"
        )));
    }
    Ok(Some(z))
}

/// The CRC-32 of the `n` values of `N` bytes held from byte `off` of `buf`,
/// each replaced by `f` of it as the native bytes of a float64 at `8 k`,
/// block by block: a block's bytes are hashed, and copied aside when they
/// are narrower than float64, before any is overwritten.
fn check_decode<const N: usize>(
    buf: &mut [u8],
    off: usize,
    n: usize,
    f: &impl Fn([u8; N]) -> f64,
) -> crc32fast::Hasher {
    let mut h = crc32fast::Hasher::new();
    let mut aside = vec![0u8; if N < 8 { N * BLOCK.min(n) } else { 0 }];
    for k0 in (0..n).step_by(BLOCK) {
        let k1 = (k0 + BLOCK).min(n);
        let src = off + N * k0..off + N * k1;
        h.update(&buf[src.clone()]);
        if N == 8 {
            for c in buf[8 * k0..8 * k1].chunks_exact_mut(8) {
                let mut a = [0u8; N];
                a.copy_from_slice(&c[..N]);
                c.copy_from_slice(&f(a).to_ne_bytes());
            }
        } else {
            let aside = &mut aside[..src.len()];
            aside.copy_from_slice(&buf[src]);
            let out = &mut buf[8 * k0..8 * k1];
            for (c, a) in out.chunks_exact_mut(8).zip(aside.chunks_exact(N)) {
                let mut v = [0u8; N];
                v.copy_from_slice(a);
                c.copy_from_slice(&f(v).to_ne_bytes());
            }
        }
    }
    h
}

/// Inflates the raw deflate stream `src` of member `name` into `dst`, which
/// it must fill exactly (`shape`: rows, columns and bytes per value, for
/// the message).
fn inflate(
    src: &[u8],
    dst: &mut [u8],
    name: &str,
    (rows, cols, size): (usize, usize, usize),
) -> Result<(), Bad> {
    use flate2::{Decompress, FlushDecompress, Status};
    let bad =
        |e: flate2::DecompressError| Bad::corrupt(format!("member '{name}' cannot be read: {e}"));
    let mut d = Decompress::new(false);
    let (mut i, mut o) = (0usize, 0usize);
    let (mut end, len) = (false, dst.len());
    while !end && o < len {
        let status = d
            .decompress(
                &src[i..(i + STEP).min(src.len())],
                &mut dst[o..(o + STEP).min(len)],
                FlushDecompress::None,
            )
            .map_err(bad)?;
        let (i2, o2) = (d.total_in() as usize, d.total_out() as usize);
        end = status == Status::StreamEnd;
        if (i2, o2) == (i, o) {
            break;
        }
        (i, o) = (i2, o2);
    }
    if o < dst.len() {
        return Err(Bad::truncated(format!(
            "member '{name}' inflates to {o} bytes; {rows} x {cols} values of {size} bytes need {}",
            dst.len()
        )));
    }
    if !end {
        // The output is full: the stream must end here, with no more bytes.
        let mut more = [0u8; 1];
        let status = d
            .decompress(&src[i..], &mut more, FlushDecompress::Finish)
            .map_err(bad)?;
        if d.total_out() as usize > o {
            return Err(Bad::corrupt(format!(
                "member '{name}' inflates to more than the {} bytes it declares",
                dst.len()
            )));
        }
        if status != Status::StreamEnd {
            return Err(Bad::truncated(format!(
                "member '{name}' ends before its deflate stream does"
            )));
        }
    }
    Ok(())
}
