//! Gwyddion native files (`.gwy`).
//!
//! Layout (the GWY file format of Gwyddion's user guide, "Gwyddion Native
//! File Format", as `libgwyfile` and SurfaceTopography's `GWY.py` read it,
//! little-endian): the magic `GWYP`, then one serialised object: its type
//! name (NUL-terminated), its size (u32) and its components, each a name
//! (NUL-terminated), a type character and a value: `b` bool and `c` char (1
//! byte), `i` i32, `q` i64, `d` f64, `s` a NUL-terminated string, `o` an
//! object; the upper-case letters are arrays (a u32 count, then the
//! items). The top `GwyContainer` holds the channels as `/N/data`
//! (`GwyDataField`: `xres`, `yres` (i32), `xreal`, `yreal` (f64, the
//! physical sizes), `si_unit_xy`, `si_unit_z` (`GwySIUnit` objects whose
//! `unitstr` is the unit) and `data`, `yres` rows of `xres` f64, x fastest),
//! their titles `/N/data/title` and optional masks `/N/mask` (a data field,
//! values above 0.5 missing). Channels are those whose lateral and height
//! units are lengths, in the file's order; a zero size is 1 and a negative
//! one its magnitude, as Gwyddion does.

use super::bytes::Cursor;
use super::{pick, Bad, Channel, Format, Measured};

#[derive(Debug, Clone)]
enum Value {
    Num(f64),
    Text(String),
    Object(String, Vec<(String, Value)>),
    /// An f64 array: offset of its first value and count.
    Doubles(usize, usize),
    Other,
}

fn object(c: &mut Cursor, depth: usize) -> Result<(String, Vec<(String, Value)>), Bad> {
    if depth > 32 {
        return Err(Bad::corrupt("objects nest deeper than 32"));
    }
    let name = c.c_str()?;
    let size = c.u32_le()? as usize;
    let end = c
        .pos()
        .checked_add(size)
        .filter(|e| *e <= c.pos() + c.remaining())
        .ok_or_else(|| Bad::truncated(format!("object '{name}' of {size} bytes")))?;
    let mut parts = Vec::new();
    while c.pos() < end {
        let key = c.c_str()?;
        let ty = c.u8()?;
        let v = match ty {
            b'b' | b'c' => Value::Num(f64::from(c.u8()?)),
            b'i' => Value::Num(f64::from(c.i32_le()?)),
            b'q' => Value::Num(c.i64_le()? as f64),
            b'd' => Value::Num(c.f64_le()?),
            b's' => Value::Text(c.c_str()?),
            b'o' => {
                let (n, p) = object(c, depth + 1)?;
                Value::Object(n, p)
            }
            b'C' | b'I' | b'Q' | b'D' => {
                let n = c.u32_le()? as usize;
                let size = match ty {
                    b'C' => 1,
                    b'I' => 4,
                    _ => 8,
                };
                let at = c.pos();
                c.skip(
                    n.checked_mul(size)
                        .ok_or_else(|| Bad::corrupt("an array overflows"))?,
                )?;
                if ty == b'D' {
                    Value::Doubles(at, n)
                } else {
                    Value::Other
                }
            }
            b'S' => {
                let n = c.u32_le()?;
                for _ in 0..n {
                    c.c_str()?;
                }
                Value::Other
            }
            b'O' => {
                let n = c.u32_le()?;
                for _ in 0..n {
                    object(c, depth + 1)?;
                }
                Value::Other
            }
            t => {
                return Err(Bad::corrupt(format!(
                    "component '{key}' of unknown type '{}'",
                    t as char
                )))
            }
        };
        parts.push((key, v));
    }
    if c.pos() != end {
        return Err(Bad::corrupt(format!("object '{name}' overruns its size")));
    }
    Ok((name, parts))
}

fn get<'a>(parts: &'a [(String, Value)], key: &str) -> Option<&'a Value> {
    parts.iter().find(|(k, _)| k == key).map(|(_, v)| v)
}

fn num(parts: &[(String, Value)], key: &str) -> Result<f64, Bad> {
    match get(parts, key) {
        Some(Value::Num(v)) => Ok(*v),
        _ => Err(Bad::corrupt(format!("a data field has no '{key}'"))),
    }
}

fn unit(parts: &[(String, Value)], key: &str) -> String {
    match get(parts, key) {
        Some(Value::Object(_, u)) => match get(u, "unitstr") {
            Some(Value::Text(t)) => t.clone(),
            _ => String::new(),
        },
        _ => String::new(),
    }
}

fn field(v: &Value) -> Option<&[(String, Value)]> {
    match v {
        Value::Object(n, p) if n == "GwyDataField" => Some(p),
        _ => None,
    }
}

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    if !bytes.starts_with(b"GWYP") {
        if bytes.starts_with(b"GWYO") || bytes.starts_with(b"GWYQ") {
            return Err(Bad::unsupported(
                "GWY format versions 1 and 3 (only GWYP is read)",
            ));
        }
        return Err(Bad::magic("GWYP"));
    }
    let mut c = Cursor::at(bytes, 4);
    let (_, top) = object(&mut c, 0)?;
    let index = |k: &str, suffix: &str| -> Option<usize> {
        k.strip_prefix('/')?.strip_suffix(suffix)?.parse().ok()
    };
    let mut chans = Vec::new();
    for (k, v) in &top {
        let (Some(i), Some(p)) = (index(k, "/data"), field(v)) else {
            continue;
        };
        if get(p, "si_unit_z").is_none() {
            continue;
        }
        let (uxy, uz) = (unit(p, "si_unit_xy"), unit(p, "si_unit_z"));
        let (Some(fxy), Some(fz)) = (
            super::units::metres_per(&uxy, false),
            super::units::metres_per(&uz, false),
        ) else {
            continue;
        };
        let title = match get(&top, &format!("/{i}/data/title")) {
            Some(Value::Text(t)) => t.clone(),
            _ => format!("channel {i}"),
        };
        chans.push((i, p, title, fxy, fz, uz));
    }
    if chans.is_empty() {
        return Err(Bad::corrupt(
            "no channel of heights (a data field in length units)",
        ));
    }
    let names: Vec<String> = chans.iter().map(|c| c.2.clone()).collect();
    let (i, p, title, fxy, fz, uz) = &chans[pick(&names, 0, channel)?];
    let (nx, ny) = (num(p, "xres")?, num(p, "yres")?);
    if !(nx >= 1.0 && ny >= 1.0) {
        return Err(Bad::corrupt(format!("{nx} x {ny} points")));
    }
    let (nx, ny) = (nx as usize, ny as usize);
    let n = super::grid(ny, nx)?;
    let sane = |s: f64| if s == 0.0 { 1.0 } else { s.abs() };
    let (sx, sy) = (sane(num(p, "xreal")?), sane(num(p, "yreal")?));
    let doubles = |v: Option<&Value>, what: &str| -> Result<Vec<f64>, Bad> {
        match v {
            Some(Value::Doubles(at, count)) if *count == n => Ok(super::bytes::decode(
                &bytes[*at..*at + 8 * count],
                f64::from_le_bytes,
            )),
            Some(Value::Doubles(_, count)) => Err(Bad::corrupt(format!(
                "{what} has {count} values for {nx} x {ny} points"
            ))),
            _ => Err(Bad::corrupt(format!("{what} has no data"))),
        }
    };
    let mut z = doubles(get(p, "data"), "the data field")?;
    for v in z.iter_mut() {
        *v = if v.is_finite() { *v * fz } else { f64::NAN };
    }
    if let Some(m) = get(&top, &format!("/{i}/mask")).and_then(field) {
        let mask = doubles(get(m, "data"), "the mask")?;
        for (v, k) in z.iter_mut().zip(mask) {
            if k > 0.5 {
                *v = f64::NAN;
            }
        }
    }
    Ok(Measured {
        format: Format::Gwy,
        channel: title.clone(),
        channels: names.clone(),
        unit: super::units::canonical(uz, false),
        rows: ny,
        cols: nx,
        heights: z,
        pixel_size: Some((
            super::pixel(sx * fxy / nx as f64, "x")?,
            super::pixel(sy * fxy / ny as f64, "y")?,
        )),
        periodic: false,
    })
}
