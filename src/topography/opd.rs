//! Wyko/Bruker Vision `.opd` files (white-light interferometers).
//!
//! Layout (reverse-documented by Gwyddion's `opdfile.c` and
//! SurfaceTopography's `OPD.py`, little-endian): 2 bytes, then the
//! directory: 24-byte entries (name, 16 bytes; type, i16; length, i32;
//! attributes, u16), the first named `Directory` with the directory's own
//! length. The blocks follow in the directory's order, each `length` bytes.
//! Type 3 is an array (`RAW DATA`, `RAW_DATA`, `OPD`, `Raw` or
//! `SAMPLE_DATA` for heights: u16 points along x, u16 along y, u16 bytes per
//! point: 1 u8, 2 i16, 4 f32; the values x-major, y fastest, the map flipped
//! along y); 5 text, 6 short, 7 float, 8 double, 12 long are scalars, of
//! which `Wavelength` (nm), `Mult` (default 1), `Aspect` (default 1) and
//! `Pixel_size` (mm) matter. A height is `value x Wavelength / Mult` nm; the
//! pixel is `Pixel_size` mm along x and `Pixel_size x Aspect` along y;
//! values of 32766 and more (i16), or 1e38 and more (f32), are missing.

use super::bytes::{decode, Cursor};
use super::{pick, raster, Bad, Channel, Format, Measured};

const HEIGHT_ARRAYS: [&str; 5] = ["RAW DATA", "RAW_DATA", "OPD", "Raw", "SAMPLE_DATA"];

struct Array {
    name: String,
    nx: usize,
    ny: usize,
    size: usize,
    data: usize,
}

/// What the directory's blocks hold: the height arrays and the scalars
/// that scale them.
struct Blocks {
    arrays: Vec<Array>,
    wavelength: Option<f64>,
    mult: f64,
    aspect: f64,
    pixel: Option<f64>,
}

/// The directory and its blocks, each checked where it is read.
fn blocks(bytes: &[u8]) -> Result<Blocks, Bad> {
    if bytes.get(2..11) != Some(b"Directory".as_slice()) {
        return Err(Bad::magic("a 'Directory' block at byte 2"));
    }
    let mut c = Cursor::at(bytes, 2);
    let entry = |c: &mut Cursor| -> Result<(String, i16, i32), Bad> {
        let name = c.fixed_str(16)?;
        let ty = c.i16_le()?;
        let len = c.i32_le()?;
        let _attr = c.u16_le()?;
        Ok((name, ty, len))
    };
    let (_, _, dir_len) = entry(&mut c)?;
    if dir_len <= 0 || dir_len % 24 != 0 {
        return Err(Bad::corrupt(format!(
            "a directory of {dir_len} bytes (a multiple of 24 is expected)"
        )));
    }
    let count = dir_len as usize / 24 - 1;
    if count > c.remaining() / 24 {
        return Err(Bad::truncated(format!("a directory of {count} entries")));
    }
    let mut entries = Vec::with_capacity(count);
    for _ in 0..count {
        entries.push(entry(&mut c)?);
    }
    let mut pos = c.pos();
    let mut arrays = Vec::new();
    let (mut wavelength, mut mult, mut aspect, mut pixel) = (None, 1.0, 1.0, None);
    for (name, ty, len) in entries {
        if len <= 0 {
            continue;
        }
        let len = len as usize;
        let start = pos;
        pos = pos.saturating_add(len);
        let mut b = Cursor::at(bytes, start);
        let scalar = |b: &mut Cursor| -> Result<Option<f64>, Bad> {
            Ok(match (ty, len) {
                (6, 2) | (7, 2) => Some(f64::from(b.i16_le()?)),
                (6, 4) | (12, 4..) => Some(f64::from(b.i32_le()?)),
                (7, 4..) => Some(f64::from(b.f32_le()?)),
                (8, 8..) => Some(b.f64_le()?),
                _ => None,
            })
        };
        if ty == 3 {
            if HEIGHT_ARRAYS.contains(&name.as_str()) && start < bytes.len() {
                let nx = b.u16_le()? as usize;
                let ny = b.u16_le()? as usize;
                let size = b.u16_le()? as usize;
                if nx == 0 || ny == 0 {
                    return Err(Bad::corrupt(format!(
                        "array '{name}' of {nx} x {ny} points"
                    )));
                }
                if ![1, 2, 4].contains(&size) {
                    return Err(Bad::unsupported(format!("{size} bytes per point")));
                }
                arrays.push(Array {
                    name,
                    nx,
                    ny,
                    size,
                    data: b.pos(),
                });
            }
        } else if start < bytes.len() {
            let v = match scalar(&mut b) {
                Ok(v) => v,
                Err(_) if pos > bytes.len() => None,
                Err(e) => return Err(e),
            };
            match (name.as_str(), v) {
                ("Wavelength", Some(v)) => wavelength = Some(v),
                ("Mult", Some(v)) => mult = v,
                ("Aspect", Some(v)) => aspect = v,
                ("Pixel_size", Some(v)) => pixel = Some(v),
                _ => {}
            }
        }
    }
    // The directory's blocks end where the file ends: a file cut short is
    // refused whichever block it loses.
    if pos > bytes.len() {
        return Err(Bad::truncated(format!(
            "the directory's blocks end at byte {pos}, the file has {}",
            bytes.len()
        )));
    }
    Ok(Blocks {
        arrays,
        wavelength,
        mult,
        aspect,
        pixel,
    })
}

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    let Blocks {
        arrays,
        wavelength,
        mult,
        aspect,
        pixel,
    } = blocks(bytes)?;
    if arrays.is_empty() {
        return Err(Bad::corrupt("no height array (RAW DATA, OPD, Raw, ...)"));
    }
    let wavelength = wavelength
        .ok_or_else(|| Bad::corrupt("no 'Wavelength' block: the height scale is unknown"))?;
    let names: Vec<String> = arrays.iter().map(|a| a.name.clone()).collect();
    let a = &arrays[pick(&names, 0, channel)?];
    let data = raster(bytes.get(a.data..).unwrap_or(&[]), a.nx, a.ny, a.size)?;
    let scale = wavelength / mult * 1e-6 * 1e-3;
    let raw: Vec<f64> = match a.size {
        1 => data.iter().map(|v| f64::from(*v)).collect(),
        2 => decode(data, |b| f64::from(i16::from_le_bytes(b))),
        _ => decode(data, |b| f64::from(f32::from_le_bytes(b))),
    };
    let limit = match a.size {
        1 => f64::INFINITY,
        2 => 32766.0,
        _ => 1e38,
    };
    let z: Vec<f64> = raw
        .iter()
        .map(|&v| {
            if a.size > 1 && !(v.is_finite() && v < limit) {
                f64::NAN
            } else {
                v * scale
            }
        })
        .collect();
    // x-major with y fastest, flipped along y: row i of the map is column
    // ny-1-i of the file's array.
    let mut out = super::transpose(&z, a.nx, a.ny);
    super::flip_rows(&mut out, a.ny, a.nx);
    let pixel_size = match pixel {
        Some(p) => Some((
            super::pixel(p * 1e-3, "x")?,
            super::pixel(p * aspect * 1e-3, "y")?,
        )),
        None => None,
    };
    Ok(Measured {
        format: Format::Opd,
        channel: a.name.clone(),
        channels: names,
        unit: "mm".into(),
        rows: a.ny,
        cols: a.nx,
        heights: out,
        pixel_size,
        periodic: false,
    })
}
