//! FRT MicroProf `.frt` files (optical profilometers by FRT, now
//! FormFactor).
//!
//! Layout (reverse-documented by Gwyddion's `frtfile.c` and
//! SurfaceTopography's `FRT.py`, little-endian): `FRTM_GLIDERV` and the
//! version `1.00` or `1.01` (4 characters), the number of blocks (u16),
//! then tag-length-value blocks: a u16 tag, a length (u32 for 1.00, u64 for
//! 1.01) and the value. Block 0x66 gives the points along x and y and the
//! bits per point (u32 each: 16 unsigned or 32 signed); 0x67 the physical
//! sizes along x and y (f64, m); 0x6c the measuring range (u32) and the
//! height of one step (f64, m); 0x0b the heights, row by row (x fastest), the
//! map flipped along y, the value 1 marking a missing point. Without 0x0b,
//! block 0x7d holds several images (4 u16 buffer ids, then images of a u32
//! data type, points along x and y and bits per point, and their values);
//! those whose type has a height bit (topography 0x4, thickness 0x80,
//! sample thickness 0x800, AFM 0x1000) are the channels.

use super::bytes::{decode, Cursor};
use super::{pick, raster, Bad, Channel, Format, Measured};

struct Image<'a> {
    name: String,
    nx: usize,
    ny: usize,
    bits: u32,
    data: &'a [u8],
}

fn image_name(t: u32) -> String {
    let kind = match t & 0xFFDF {
        4 => "Topography",
        128 => "Thickness",
        2048 => "Sample thickness",
        4096 => "AFM",
        _ => "Unknown",
    };
    let sensor = if t & 0x1000_0000 != 0 {
        " (bottom sensor) "
    } else {
        " (top sensor) "
    };
    format!("{kind}{sensor}{}", ((t & 0x0F00_0000) >> 24) + 1)
}

/// The images of a block 0x7d whose type has a height bit.
fn height_images(value: &[u8]) -> Result<Vec<Image<'_>>, Bad> {
    let mut v = Cursor::new(value);
    let mut out = Vec::new();
    v.skip(8)?;
    while v.remaining() > 0 {
        let t = v.u32_le()?;
        let (nx, ny, bits) = (v.u32_le()? as usize, v.u32_le()? as usize, v.u32_le()?);
        let size = match bits {
            16 => 2,
            32 => 4,
            b => return Err(Bad::unsupported(format!("{b} bits per point"))),
        };
        let n = super::grid(ny, nx)?;
        let data = v.take(n * size)?;
        if t & (0x4 | 0x80 | 0x800 | 0x1000) != 0 {
            out.push(Image {
                name: image_name(t),
                nx,
                ny,
                bits,
                data,
            });
        }
    }
    Ok(out)
}

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    if !bytes.starts_with(b"FRTM_GLIDERV") {
        return Err(Bad::magic("FRTM_GLIDERV"));
    }
    let mut c = Cursor::at(bytes, 12);
    let version = c.fixed_str(4)?;
    let wide = match version.as_str() {
        "1.00" => false,
        "1.01" => true,
        v => return Err(Bad::unsupported(format!("version '{v}'"))),
    };
    let blocks = c.u16_le()?;
    let mut grid = None;
    let mut sizes = None;
    let mut step = None;
    let mut single = None;
    let mut multi: Vec<Image> = Vec::new();
    for _ in 0..blocks {
        if c.remaining() == 0 {
            break;
        }
        let tag = c.u16_le()?;
        let len = if wide {
            c.u64_le()?
        } else {
            u64::from(c.u32_le()?)
        };
        let len = usize::try_from(len).map_err(|_| Bad::corrupt("a block length overflows"))?;
        let value = c.take(len)?;
        let mut v = Cursor::new(value);
        match tag {
            0x66 => grid = Some((v.u32_le()? as usize, v.u32_le()? as usize, v.u32_le()?)),
            0x67 => sizes = Some((v.f64_le()?, v.f64_le()?)),
            0x6c => {
                let _range = v.u32_le()?;
                step = Some(v.f64_le()?);
            }
            0x0b => single = Some(value),
            0x7d => multi.extend(height_images(value)?),
            _ => {}
        }
    }
    let (sx, sy) = sizes.ok_or_else(|| Bad::corrupt("no block 0x67 (physical sizes)"))?;
    let step = step.ok_or_else(|| Bad::corrupt("no block 0x6c (height scale)"))?;
    let images = match single {
        Some(data) => {
            let (nx, ny, bits) = grid.ok_or_else(|| Bad::corrupt("no block 0x66 (grid)"))?;
            if bits != 16 && bits != 32 {
                return Err(Bad::unsupported(format!("{bits} bits per point")));
            }
            vec![Image {
                name: "default".into(),
                nx,
                ny,
                bits,
                data,
            }]
        }
        None if multi.is_empty() => return Err(Bad::corrupt("no topography data")),
        None => multi,
    };
    let names: Vec<String> = images.iter().map(|i| i.name.clone()).collect();
    let im = &images[pick(&names, 0, channel)?];
    let size = if im.bits == 16 { 2 } else { 4 };
    let data = raster(im.data, im.ny, im.nx, size)?;
    let raw: Vec<f64> = if size == 2 {
        decode(data, |b| f64::from(u16::from_le_bytes(b)))
    } else {
        decode(data, |b| f64::from(i32::from_le_bytes(b)))
    };
    let mut z: Vec<f64> = raw
        .iter()
        .map(|&v| if v == 1.0 { f64::NAN } else { v * step })
        .collect();
    super::flip_rows(&mut z, im.ny, im.nx);
    Ok(Measured {
        format: Format::Frt,
        channel: im.name.clone(),
        channels: names,
        unit: "m".into(),
        rows: im.ny,
        cols: im.nx,
        heights: z,
        pixel_size: Some((
            super::pixel(sx / im.nx as f64, "x")?,
            super::pixel(sy / im.ny as f64, "y")?,
        )),
        periodic: false,
    })
}
