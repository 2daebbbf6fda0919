//! Digital Surf `.sur` (MountainsMap's native format, written by many
//! profilometers).
//!
//! Layout (Digital Surf's published SUR description, as Gwyddion's
//! `surffile.c` and SurfaceTopography's `SUR.py` read it), a 512-byte
//! little-endian header: `DIGITAL SURF` (12 bytes), format, object count,
//! version, type (u16 each), object name and operator name (30 bytes each),
//! material code, acquisition type, range type, special points, absolute
//! (u16 each), 8 reserved bytes, bits per point (u16: 16 or 32), z min and z
//! max (i32), points along x and y (i32), total points (i32 = x times y),
//! spacings along x and y and the z scale (f32), the names of x, y and z
//! (16 bytes each), the units of the spacings along x, y and z and the units
//! of x, y and z (16 bytes each), three unit ratios (f32), imprint,
//! inversion, levelling (u16), 12 reserved bytes, the time (seven u16),
//! the measurement duration (f32), 10 reserved bytes, the comment size and
//! private size (u16), 128 bytes of client zone, offsets along x, y, z
//! (f32) and 34 reserved bytes; then the comment, the private zone and the
//! points, row by row (x fastest), i16 or i32. Heights are `value x zscale`
//! in the z spacing unit, negated when `inversion` is 1, 2 or 3 (2 and 3
//! also flip the map along x or y); with `special points` = 1 the value
//! `zmin - 2` marks a missing point. The lateral spacing is converted from
//! its unit to the z spacing unit (as SurfaceTopography does); the offsets
//! are not applied.

use super::bytes::{decode, Cursor};
use super::{pick, pixel, raster, Bad, Channel, Format, Measured};

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    pick(&["Default".to_string()], 0, channel)?;
    if !bytes.starts_with(b"DIGITAL SURF") {
        return Err(Bad::magic("DIGITAL SURF"));
    }
    if bytes.len() < 512 {
        return Err(Bad::truncated(format!(
            "{} bytes, the header alone has 512",
            bytes.len()
        )));
    }
    let mut c = Cursor::at(bytes, 12);
    let _format = c.u16_le()?;
    let _objects = c.u16_le()?;
    let _version = c.u16_le()?;
    let _type = c.u16_le()?;
    let _object = c.fixed_str(30)?;
    let _operator = c.fixed_str(30)?;
    c.skip(6)?;
    let special = c.u16_le()?;
    c.skip(2 + 8)?;
    let bits = c.u16_le()?;
    let zmin = c.i32_le()?;
    let _zmax = c.i32_le()?;
    let nx = c.i32_le()?;
    let ny = c.i32_le()?;
    let total = c.i32_le()?;
    let (sx, sy, sz) = (c.f32_le()?, c.f32_le()?, c.f32_le()?);
    c.skip(48)?;
    let unit = |u: String| if u == "\u{e6}m" { "um".to_string() } else { u };
    let (ux, uy, uz) = (
        unit(c.fixed_str(16)?),
        unit(c.fixed_str(16)?),
        unit(c.fixed_str(16)?),
    );
    c.skip(48 + 12)?;
    let _imprint = c.u16_le()?;
    let inversion = c.u16_le()?;
    let _levelling = c.u16_le()?;
    c.skip(12 + 14 + 4 + 10)?;
    let comment = c.u16_le()? as usize;
    let private = c.u16_le()? as usize;
    if nx <= 0 || ny <= 0 || i64::from(nx) * i64::from(ny) != i64::from(total) {
        return Err(Bad::corrupt(format!("{nx} x {ny} points, total {total}")));
    }
    let (nx, ny) = (nx as usize, ny as usize);
    let size = match bits {
        16 => 2,
        32 => 4,
        b => return Err(Bad::unsupported(format!("{b} bits per point"))),
    };
    let start = 512 + comment + private;
    let data = raster(bytes.get(start..).unwrap_or(&[]), ny, nx, size)?;
    let raw: Vec<f64> = if size == 2 {
        decode(data, |b| f64::from(i16::from_le_bytes(b)))
    } else {
        decode(data, |b| f64::from(i32::from_le_bytes(b)))
    };
    let missing = f64::from(zmin) - 2.0;
    let to_m = super::metres(&uz, "the height")?;
    let ratio = |u: &str| -> Result<f64, Bad> { Ok(super::metres(u, "a lateral")? / to_m) };
    let sign = if matches!(inversion, 1..=3) {
        -1.0
    } else {
        1.0
    };
    let dz = sign * f64::from(sz);
    let mut z: Vec<f64> = raw
        .iter()
        .map(|&v| {
            if special == 1 && v == missing {
                f64::NAN
            } else {
                v * dz * to_m
            }
        })
        .collect();
    match inversion {
        // SurfaceTopography flips its axis 0 (x) for 2 and axis 1 (y) for 3.
        2 => z.chunks_mut(nx).for_each(<[f64]>::reverse),
        3 => super::flip_rows(&mut z, ny, nx),
        _ => {}
    }
    // SurfaceTopography's physical size: spacing x points in the z unit,
    // then converted to m.
    let dx = ratio(&ux)? * f64::from(sx) * nx as f64 * to_m / nx as f64;
    let dy = ratio(&uy)? * f64::from(sy) * ny as f64 * to_m / ny as f64;
    Ok(Measured {
        format: Format::Sur,
        channel: "Default".into(),
        channels: vec!["Default".into()],
        unit: super::units::canonical(&uz, false),
        rows: ny,
        cols: nx,
        heights: z,
        pixel_size: Some((pixel(dx, "x")?, pixel(dy, "y")?)),
        periodic: false,
    })
}
