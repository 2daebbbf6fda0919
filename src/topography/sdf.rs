//! ISO 25178-71 surface data files (`.sdf`), ASCII (`aISO-1.0`) and binary
//! (`bISO-1.0`).
//!
//! Layout (ISO 25178-71, as Gwyddion's `sdfile.c` and SurfaceTopography's
//! `SDF.py` read it): the 8-byte magic, then the header. ASCII: lines
//! `Key = value` up to a line `*` (`NumPoints` along x, `NumProfiles` along
//! y, `Xscale`, `Yscale` (m per pixel), `Zscale` (m per unit),
//! `DataType`, `Compression` 0), then `NumProfiles` profiles of `NumPoints`
//! numbers (`BAD` marks a missing point), then `*` and an optional trailer.
//! Binary: `ManufacID` (10 bytes), `CreateDate` and `ModDate` (12 each),
//! `NumPoints`, `NumProfiles` (u16), `Xscale`, `Yscale`, `Zscale`,
//! `Zresolution` (f64), `Compression`, `DataType`, `CheckType` (u8), then
//! the data, little-endian, profile by profile. Data types: 0 u8, 1 u16,
//! 2 u32, 3 f32, 4 i8, 5 i16, 6 i32, 7 f64; 16- and 32-bit integers mark a
//! missing point with the type's minimum (signed) or maximum (unsigned), any
//! type with NaN. Heights are `value x Zscale` metres.

use super::bytes::{decode, Cursor};
use super::{pick, pixel, raster, Bad, Channel, Format, Measured};

/// Byte size of data type `t`, with its missing-point marker.
fn dtype(t: u8) -> Result<(usize, Option<f64>), Bad> {
    Ok(match t {
        0 | 4 => (1, None),
        1 => (2, Some(65535.0)),
        5 => (2, Some(-32768.0)),
        2 => (4, Some(4294967295.0)),
        6 => (4, Some(-2147483648.0)),
        3 => (4, None),
        7 => (8, None),
        _ => return Err(Bad::unsupported(format!("DataType {t}"))),
    })
}

struct Header {
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
    dz: f64,
}

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    pick(&["Default".to_string()], 0, channel)?;
    let magic = bytes.get(..8).unwrap_or(bytes);
    let (h, mut z) = match magic {
        b"aISO-1.0" => ascii(bytes)?,
        b"bISO-1.0" => binary(bytes)?,
        _ => return Err(Bad::magic("aISO-1.0 or bISO-1.0")),
    };
    if !(h.dz.is_finite() && h.dz != 0.0) {
        return Err(Bad::corrupt(format!("Zscale = {:e}", h.dz)));
    }
    z.iter_mut().for_each(|v| *v *= h.dz);
    Ok(Measured {
        format: Format::Sdf,
        channel: "Default".into(),
        channels: vec!["Default".into()],
        unit: "m".into(),
        rows: h.ny,
        cols: h.nx,
        heights: z,
        pixel_size: Some((pixel(h.dx, "x")?, pixel(h.dy, "y")?)),
        periodic: false,
    })
}

fn binary(bytes: &[u8]) -> Result<(Header, Vec<f64>), Bad> {
    let mut c = Cursor::at(bytes, 8);
    c.skip(34)?;
    let nx = c.u16_le()? as usize;
    let ny = c.u16_le()? as usize;
    let (dx, dy, dz) = (c.f64_le()?, c.f64_le()?, c.f64_le()?);
    let _resolution = c.f64_le()?;
    let compression = c.u8()?;
    let t = c.u8()?;
    let _check = c.u8()?;
    if compression != 0 {
        return Err(Bad::unsupported(format!("Compression {compression}")));
    }
    let (size, marker) = dtype(t)?;
    let start = c.pos();
    let data = raster(&bytes[start..], ny, nx, size)?;
    let mut z = match t {
        0 => data.iter().map(|b| f64::from(*b)).collect(),
        4 => data.iter().map(|b| f64::from(*b as i8)).collect(),
        1 => decode(data, |b| f64::from(u16::from_le_bytes(b))),
        5 => decode(data, |b| f64::from(i16::from_le_bytes(b))),
        2 => decode(data, |b| f64::from(u32::from_le_bytes(b))),
        6 => decode(data, |b| f64::from(i32::from_le_bytes(b))),
        3 => decode(data, |b| f64::from(f32::from_le_bytes(b))),
        _ => decode(data, f64::from_le_bytes),
    };
    mark(&mut z, marker);
    let h = Header { nx, ny, dx, dy, dz };
    Ok((h, z))
}

/// Missing points: NaN, infinite, or the type's marker.
fn mark(z: &mut [f64], marker: Option<f64>) {
    for v in z.iter_mut() {
        if !v.is_finite() || Some(*v) == marker {
            *v = f64::NAN;
        }
    }
}

fn ascii(bytes: &[u8]) -> Result<(Header, Vec<f64>), Bad> {
    let text = String::from_utf8_lossy(&bytes[8..]);
    let mut lines = text.lines();
    let mut get = std::collections::HashMap::new();
    loop {
        let Some(line) = lines.next() else {
            return Err(Bad::truncated("the header has no end line '*'"));
        };
        let line = line.trim();
        if line == "*" {
            break;
        }
        if let Some((k, v)) = line.split_once('=') {
            get.insert(k.trim().to_string(), v.trim().to_string());
        }
    }
    let field = |k: &str| {
        get.get(k)
            .ok_or_else(|| Bad::corrupt(format!("the header has no {k}")))
    };
    let int = |k: &str| {
        field(k)?
            .parse::<usize>()
            .map_err(|_| Bad::corrupt(format!("{k} is not a count")))
    };
    let real = |k: &str| {
        field(k)?
            .parse::<f64>()
            .map_err(|_| Bad::corrupt(format!("{k} is not a number")))
    };
    let (nx, ny) = (int("NumPoints")?, int("NumProfiles")?);
    let t = int("DataType")?;
    let t = u8::try_from(t).map_err(|_| Bad::unsupported(format!("DataType {t}")))?;
    let (_, marker) = dtype(t)?;
    if get.get("Compression").is_some_and(|v| v.trim() != "0") {
        return Err(Bad::unsupported("compressed data"));
    }
    let n = super::grid(ny, nx)?;
    // A count larger than the text can hold is refused before allocating:
    // each value takes at least 2 characters.
    if n > text.len() / 2 + 1 {
        return Err(Bad::truncated(format!(
            "{ny} x {nx} points cannot fit in {} bytes",
            bytes.len()
        )));
    }
    let mut z = Vec::with_capacity(n);
    for line in lines.by_ref() {
        if line.trim() == "*" {
            break;
        }
        for f in line.split_whitespace() {
            if z.len() == n {
                return Err(Bad::corrupt(format!(
                    "more than {ny} x {nx} values before the closing '*'"
                )));
            }
            z.push(if f == "BAD" {
                f64::NAN
            } else {
                f.parse::<f64>()
                    .map_err(|_| Bad::corrupt(format!("'{f}' is not a number")))?
            });
        }
    }
    if z.len() < n {
        return Err(Bad::truncated(format!(
            "{} values for {ny} x {nx} points",
            z.len()
        )));
    }
    mark(&mut z, marker);
    let h = Header {
        nx,
        ny,
        dx: real("Xscale")?,
        dy: real("Yscale")?,
        dz: real("Zscale")?,
    };
    Ok((h, z))
}

/// The bytes of a binary SDF file holding `z` (m, row-major
/// `rows x cols`) as float64 with pixel sizes `dx`, `dy` (m).
#[cfg(test)]
pub(super) fn to_binary(z: &[f64], rows: usize, cols: usize, dx: f64, dy: f64) -> Vec<u8> {
    let mut out = b"bISO-1.0".to_vec();
    out.extend_from_slice(&[b' '; 34]);
    out.extend_from_slice(&(cols as u16).to_le_bytes());
    out.extend_from_slice(&(rows as u16).to_le_bytes());
    for v in [dx, dy, 1.0, 1e-12] {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.extend_from_slice(&[0, 7, 0]);
    for v in z {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binary_and_ascii_give_the_same_map() {
        let z: Vec<f64> = (0..12).map(|k| k as f64 * 1e-9).collect();
        let m = read(&to_binary(&z, 3, 4, 1e-6, 2e-6), &Channel::Default).unwrap();
        assert_eq!((m.rows, m.cols, m.pixel_size), (3, 4, Some((1e-6, 2e-6))));
        assert_eq!(m.heights, z);
        let text = "aISO-1.0\nNumPoints = 4\nNumProfiles = 3\nXscale = 1e-6\nYscale = 2e-6\n\
                    Zscale = 1e-9\nDataType = 7\n*\n0 1 2 3\n4 5 BAD 7\n8 9 10 11\n*\n";
        let a = read(text.as_bytes(), &Channel::Default).unwrap();
        assert_eq!(a.missing(), 1);
        assert!(a.heights[6].is_nan());
        assert_eq!(a.heights[11], z[11]);
        let short = text.replace("8 9 10 11\n", "");
        assert!(read(short.as_bytes(), &Channel::Default)
            .unwrap_err()
            .to_string()
            .contains("truncated"));
    }
}
