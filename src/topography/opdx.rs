//! Bruker Dektak Vision64 `.opdx` files (stylus profilometers).
//!
//! Layout (reverse-documented by Gwyddion's `dektakvca.c` and
//! SurfaceTopography's `OPDx.py`, little-endian): the 12-byte magic
//! `VCA DATA\x01\x00\x00\x55`, then a tree of items, each a name (u32 length
//! and UTF-8 bytes), a type byte and a value: containers (0x7d, 0x46,
//! 0x47: a variable length, then items up to a terminator 0x7f and 2 bytes),
//! scalars (0x01 bool, 0x04/0x05 i16/u16, 0x06/0x07 i32/u32, 0x0a/0x0b
//! i64/u64, 0x0c f32, 0x0d f64), strings (0x12), quantities (0x13: a
//! length, f64 value, name, symbol), units (0x18: a length, name, symbol,
//! f64 value, 12 bytes), time stamps (0x15, 9 bytes), type ids (0x0e),
//! string lists (0x42), double arrays (0x40), matrices (0x00 named, 0x45
//! anonymous: type name, [u32, name,] a length, y points and x points as
//! u32, then float32 values row by row) and position data (0x7c). A
//! variable length is one byte giving its own size (1, 2 or 4) then the
//! length. The map of `/2D_Data/NAME` has `Dimension1Points` (y),
//! `Dimension2Points` (x), their `Dimension1Extent`, `Dimension2Extent`
//! (first to last point: the pixel is extent / (points - 1)), `DataScale`
//! (a unit: height per value) and the `Matrix`; the channels are
//! `/MetaData/2D_Channels/Height` with `/MetaData/PrimaryData2D` first. A
//! profile (`/1D_Data/NAME`: `NumPoints`, `Extent`, `DataScale`, `Array` of
//! f64 after 5 bytes) reads as one row.

use super::bytes::Cursor;
use super::{pick, Bad, Channel, Format, Measured};
use std::collections::HashMap;

const MAGIC: &[u8] = b"VCA DATA\x01\x00\x00\x55";

#[derive(Debug, Clone)]
enum Item {
    Int(i64),
    Real(f64),
    Text(String),
    List(Vec<String>),
    Unit {
        symbol: String,
        value: f64,
    },
    /// A double array: offset and length of its bytes.
    Doubles(usize, usize),
    /// A matrix: offset and length of its float32s, x and y points.
    Matrix(usize, usize, usize, usize),
}

fn name(c: &mut Cursor) -> Result<String, Bad> {
    let n = c.u32_le()? as usize;
    Ok(String::from_utf8_lossy(c.take(n)?).into_owned())
}

fn varlen(c: &mut Cursor) -> Result<usize, Bad> {
    Ok(match c.u8()? {
        1 => c.u8()? as usize,
        2 => c.u16_le()? as usize,
        4 => c.u32_le()? as usize,
        n => return Err(Bad::corrupt(format!("a variable length of {n} bytes"))),
    })
}

/// Reads the items of a container (type 0x7d, 0x46 or 0x47) `key` into
/// `out`, up to its terminator.
fn container(
    c: &mut Cursor,
    out: &mut HashMap<String, Item>,
    key: &str,
    depth: usize,
) -> Result<(), Bad> {
    let len = varlen(c)?;
    let end = c.pos() + len;
    if end > c.pos() + c.remaining() {
        return Err(Bad::truncated(format!("container '{key}' of {len} bytes")));
    }
    while item(c, out, key, depth + 1)? {}
    c.skip(2)?;
    if c.pos() != end {
        return Err(Bad::corrupt(format!(
            "container '{key}' ends at byte {}, not {end}",
            c.pos()
        )));
    }
    Ok(())
}

/// A quantity (type 0x13): a length, the f64 value, a name and a symbol.
fn quantity(c: &mut Cursor, key: &str) -> Result<Item, Bad> {
    let len = varlen(c)?;
    let end = c.pos() + len;
    let value = c.f64_le()?;
    let _name = name(c)?;
    let symbol = name(c)?;
    if end < c.pos() {
        return Err(Bad::corrupt(format!(
            "quantity '{key}' overruns its length"
        )));
    }
    c.seek(end);
    Ok(Item::Unit { symbol, value })
}

/// A unit (type 0x18): a length, a name, a symbol, the f64 value and 12
/// bytes.
fn unit(c: &mut Cursor, key: &str) -> Result<Item, Bad> {
    let len = varlen(c)?;
    let end = c.pos() + len;
    let _name = name(c)?;
    let symbol = name(c)?;
    let value = c.f64_le()?;
    c.skip(12)?;
    if c.pos() != end {
        return Err(Bad::corrupt(format!(
            "unit '{key}' does not fill its length"
        )));
    }
    Ok(Item::Unit { symbol, value })
}

/// A string list (type 0x42): a type name, a length and the strings.
fn string_list(c: &mut Cursor, key: &str) -> Result<Item, Bad> {
    let _type = name(c)?;
    let len = varlen(c)?;
    let end = c.pos() + len;
    let mut list = Vec::new();
    while c.pos() < end {
        list.push(name(c)?);
    }
    if c.pos() != end {
        return Err(Bad::corrupt(format!(
            "string list '{key}' overruns its length"
        )));
    }
    Ok(Item::List(list))
}

/// A matrix (type 0x00 when `named`, else 0x45): its float32s' place and
/// its points.
fn matrix(c: &mut Cursor, key: &str, named: bool) -> Result<Item, Bad> {
    let _type = name(c)?;
    if named {
        let _ = c.u32_le()?;
        let _ = name(c)?;
    }
    let len = varlen(c)?;
    let ny = c.u32_le()? as usize;
    let nx = c.u32_le()? as usize;
    let len = len
        .checked_sub(8)
        .ok_or_else(|| Bad::corrupt(format!("matrix '{key}' of {len} bytes")))?;
    let at = c.pos();
    c.skip(len)?;
    Ok(Item::Matrix(at, len, nx, ny))
}

/// Reads the next item into `out` under `prefix`; `false` at a terminator.
fn item(
    c: &mut Cursor,
    out: &mut HashMap<String, Item>,
    prefix: &str,
    depth: usize,
) -> Result<bool, Bad> {
    if depth > 32 {
        return Err(Bad::corrupt("containers nest deeper than 32"));
    }
    if c.remaining() == 0 {
        return Ok(false);
    }
    let key = format!("{prefix}/{}", name(c)?);
    let ty = c.u8()?;
    let value = match ty {
        0x7d | 0x46 | 0x47 => {
            container(c, out, &key, depth)?;
            return Ok(true);
        }
        0x7f => return Ok(false),
        0x7c => {
            let _type = name(c)?;
            let len = varlen(c)?;
            c.skip(len)?;
            return Ok(true);
        }
        0x01 => Item::Int(i64::from(c.u8()?)),
        0x04 => Item::Int(i64::from(c.i16_le()?)),
        0x05 => Item::Int(i64::from(c.u16_le()?)),
        0x06 => Item::Int(i64::from(c.i32_le()?)),
        0x07 => Item::Int(i64::from(c.u32_le()?)),
        0x0a => Item::Int(c.i64_le()?),
        0x0b => Item::Int(i64::try_from(c.u64_le()?).unwrap_or(i64::MAX)),
        0x0c => Item::Real(f64::from(c.f32_le()?)),
        0x0d => Item::Real(c.f64_le()?),
        0x0e => {
            let _type = name(c)?;
            let len = varlen(c)?;
            c.skip(len)?;
            return Ok(true);
        }
        0x12 => {
            let len = varlen(c)?;
            Item::Text(String::from_utf8_lossy(c.take(len)?).into_owned())
        }
        0x13 => quantity(c, &key)?,
        0x15 => {
            c.skip(9)?;
            return Ok(true);
        }
        0x18 => unit(c, &key)?,
        0x40 => {
            let _type = name(c)?;
            let len = varlen(c)?;
            let at = c.pos();
            c.skip(len)?;
            Item::Doubles(at, len)
        }
        0x42 => string_list(c, &key)?,
        0x00 | 0x45 => matrix(c, &key, ty == 0x00)?,
        t => {
            return Err(Bad::corrupt(format!(
                "unknown item type {t:#x} at byte {}",
                c.pos()
            )))
        }
    };
    out.insert(key, value);
    Ok(true)
}

/// The items of a file by their paths.
struct Tree(HashMap<String, Item>);

impl Tree {
    fn get(&self, k: &str) -> Result<&Item, Bad> {
        self.0
            .get(k)
            .ok_or_else(|| Bad::corrupt(format!("no '{k}'")))
    }

    fn unit(&self, k: &str) -> Result<(f64, String), Bad> {
        match self.get(k)? {
            Item::Unit { symbol, value } => Ok((*value, symbol.clone())),
            _ => Err(Bad::corrupt(format!("'{k}' is not a quantity"))),
        }
    }

    fn count(&self, k: &str) -> Result<usize, Bad> {
        match self.get(k)? {
            Item::Int(v) => usize::try_from(*v).map_err(|_| Bad::corrupt(format!("'{k}' = {v}"))),
            Item::Real(v) if *v >= 0.0 && v.fract() == 0.0 => Ok(*v as usize),
            _ => Err(Bad::corrupt(format!("'{k}' is not a count"))),
        }
    }

    fn list(&self, k: &str) -> Vec<String> {
        match self.0.get(k) {
            Some(Item::List(l)) => l.clone(),
            _ => Vec::new(),
        }
    }

    /// The text at `k`, if it is one.
    fn text(&self, k: &str) -> Option<String> {
        match self.0.get(k) {
            Some(Item::Text(t)) => Some(t.clone()),
            _ => None,
        }
    }
}

/// The length of `n` points spaced `e / (n - 1)` apart.
fn extent(e: f64, n: usize) -> f64 {
    if n > 1 {
        e * n as f64 / (n - 1) as f64
    } else {
        e
    }
}

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    if !bytes.starts_with(MAGIC) {
        return Err(Bad::magic("VCA DATA"));
    }
    let mut c = Cursor::at(bytes, MAGIC.len());
    let mut m = HashMap::new();
    while item(&mut c, &mut m, "", 0)? {}
    let t = Tree(m);
    let kind = t.text("/MetaData/DataKind").unwrap_or_default();
    let two = kind == "Surface Height"
        || (kind != "Surface Profile" && t.0.keys().any(|k| k.starts_with("/2D_Data/")));
    if two {
        surface(bytes, &t, channel)
    } else {
        profile(bytes, &t, &kind, channel)
    }
}

/// The map of a surface file (`/2D_Data/NAME`).
fn surface(bytes: &[u8], t: &Tree, channel: &Channel) -> Result<Measured, Bad> {
    let mut names = t.list("/MetaData/2D_Channels/Height");
    if let Some(p) = t.text("/MetaData/PrimaryData2D") {
        names.retain(|n| *n != p);
        names.insert(0, p);
    }
    names.retain(|n| t.0.contains_key(&format!("/2D_Data/{n}/Matrix")));
    if names.is_empty() {
        return Err(Bad::corrupt("no 2-D height data"));
    }
    let k = pick(&names, 0, channel)?;
    let p = format!("/2D_Data/{}", names[k]);
    let ny = t.count(&format!("{p}/Dimension1Points"))?;
    let nx = t.count(&format!("{p}/Dimension2Points"))?;
    let (ey, uy) = t.unit(&format!("{p}/Dimension1Extent"))?;
    let (ex, ux) = t.unit(&format!("{p}/Dimension2Extent"))?;
    let (scale, uz) = t.unit(&format!("{p}/DataScale"))?;
    let Item::Matrix(at, len, mx, my) = t.get(&format!("{p}/Matrix"))?.clone() else {
        return Err(Bad::corrupt(format!("'{p}/Matrix' is not a matrix")));
    };
    if (mx, my) != (nx, ny) || len != 4 * super::grid(ny, nx)? {
        return Err(Bad::corrupt(format!(
            "the matrix of {mx} x {my} ({len} bytes) is not the {nx} x {ny} points"
        )));
    }
    let to_m = super::metres(&uz, "the height")?;
    let z = super::bytes::decode(&bytes[at..at + len], |b| {
        let v = f64::from(f32::from_le_bytes(b)) * scale * to_m;
        if v.is_finite() {
            v
        } else {
            f64::NAN
        }
    });
    let dx = extent(ex, nx) * super::metres(&ux, "x")? / nx as f64;
    let dy = extent(ey, ny) * super::metres(&uy, "y")? / ny as f64;
    measured(t, &p, (names, k), &uz, (ny, nx), z, (dx, dy))
}

/// The one row of a profile file (`/1D_Data/NAME`) of data kind `kind`.
fn profile(bytes: &[u8], t: &Tree, kind: &str, channel: &Channel) -> Result<Measured, Bad> {
    let names = t.list("/MetaData/1D_Channels/Height");
    if names.is_empty() {
        return Err(Bad::unsupported(format!("data of kind '{kind}'")));
    }
    let k = pick(&names, 0, channel)?;
    let p = format!("/1D_Data/{}", names[k]);
    let n = t.count(&format!("{p}/NumPoints"))?;
    let (e, ux) = t.unit(&format!("{p}/Extent"))?;
    let (scale, uz) = t.unit(&format!("{p}/DataScale"))?;
    let Item::Doubles(at, len) = t.get(&format!("{p}/Array"))?.clone() else {
        return Err(Bad::corrupt(format!("'{p}/Array' is not an array")));
    };
    super::grid(1, n)?;
    if len != 8 * n + 5 {
        return Err(Bad::corrupt(format!(
            "an array of {len} bytes for {n} points"
        )));
    }
    let to_m = super::metres(&uz, "the height")?;
    let z = super::bytes::decode(&bytes[at + 5..at + len], |b| {
        f64::from_le_bytes(b) * scale * to_m
    });
    let dx = extent(e, n) * super::metres(&ux, "x")? / n as f64;
    measured(t, &p, (names, k), &uz, (1, n), z, (dx, dx))
}

/// The map read at path `p` of the tree: channel `k` of `names` (named by
/// its `DataKind` when it has one), heights in `unit`, `rows x cols` of
/// them, pixels of `dx x dy` (m).
fn measured(
    t: &Tree,
    p: &str,
    (names, k): (Vec<String>, usize),
    unit: &str,
    (rows, cols): (usize, usize),
    heights: Vec<f64>,
    (dx, dy): (f64, f64),
) -> Result<Measured, Bad> {
    let channel = t
        .text(&format!("{p}/DataKind"))
        .unwrap_or_else(|| names[k].clone());
    Ok(Measured {
        format: Format::Opdx,
        channel,
        channels: names,
        unit: super::units::canonical(unit, false),
        rows,
        cols,
        heights,
        pixel_size: Some((super::pixel(dx, "x")?, super::pixel(dy, "y")?)),
        periodic: false,
    })
}
