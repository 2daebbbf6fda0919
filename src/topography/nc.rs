//! NetCDF-3 (`.nc`, classic and 64-bit offset), in SurfaceTopography's
//! layout, read in pure Rust (no HDF5: NetCDF-4 files are refused).
//!
//! Container (Unidata's "NetCDF Classic and 64-bit Offset Format"
//! specification, big-endian throughout): `CDF` and version 1 (32-bit
//! offsets) or 2 (64-bit), the record count, then the dimension list
//! (`NC_DIMENSION` = 10, names padded to 4 bytes and lengths), the global
//! attributes (`NC_ATTRIBUTE` = 12) and the variables (`NC_VARIABLE` = 11:
//! name, dimension ids, attributes, type 1 byte, 2 char, 3 short, 4 int,
//! 5 float, 6 double, size, begin offset). Layout (SurfaceTopography's
//! `NC.py`): a variable `heights(x, y)` (x the slow index), optional
//! variables `x` and `y` whose attribute `length` is the physical size, `unit`
//! the unit (of lengths and heights alike) and `periodic` (non-zero:
//! periodic); an optional variable `mask` (non-zero: missing). As netCDF's
//! conventions ask, values equal to `_FillValue` or `missing_value` are
//! missing and `scale_factor`, `add_offset` apply.

use super::bytes::Cursor;
use super::{pick, Bad, Channel, Format, Measured};

#[derive(Debug, Clone)]
enum Attr {
    Text(String),
    Num(Vec<f64>),
}

#[derive(Debug)]
struct Var {
    name: String,
    dims: Vec<usize>,
    attrs: Vec<(String, Attr)>,
    ty: u32,
    begin: u64,
}

impl Var {
    fn attr(&self, name: &str) -> Option<&Attr> {
        self.attrs.iter().find(|(n, _)| n == name).map(|(_, a)| a)
    }
    fn num(&self, name: &str) -> Option<f64> {
        match self.attr(name) {
            Some(Attr::Num(v)) => v.first().copied(),
            Some(Attr::Text(t)) => t.trim().parse().ok(),
            None => None,
        }
    }
    fn text(&self, name: &str) -> Option<String> {
        match self.attr(name) {
            Some(Attr::Text(t)) => Some(t.clone()),
            _ => None,
        }
    }
}

fn type_size(t: u32) -> Result<usize, Bad> {
    Ok(match t {
        1 | 2 => 1,
        3 => 2,
        4 | 5 => 4,
        6 => 8,
        _ => return Err(Bad::corrupt(format!("unknown NetCDF type {t}"))),
    })
}

fn name(c: &mut Cursor) -> Result<String, Bad> {
    let n = c.u32_be()? as usize;
    let b = c.take(n)?;
    let s = String::from_utf8_lossy(b).into_owned();
    c.skip((4 - n % 4) % 4)?;
    Ok(s)
}

/// `n` values of type `t` as `f64`.
fn values(c: &mut Cursor, t: u32, n: usize) -> Result<Vec<f64>, Bad> {
    let size = type_size(t)?;
    let b = c.take(
        n.checked_mul(size)
            .ok_or_else(|| Bad::corrupt("size overflows"))?,
    )?;
    Ok(match t {
        1 => b.iter().map(|x| f64::from(*x as i8)).collect(),
        2 => b.iter().map(|x| f64::from(*x)).collect(),
        3 => super::bytes::decode(b, |a| f64::from(i16::from_be_bytes(a))),
        4 => super::bytes::decode(b, |a| f64::from(i32::from_be_bytes(a))),
        5 => super::bytes::decode(b, |a| f64::from(f32::from_be_bytes(a))),
        _ => super::bytes::decode(b, f64::from_be_bytes),
    })
}

fn attrs(c: &mut Cursor) -> Result<Vec<(String, Attr)>, Bad> {
    let tag = c.u32_be()?;
    let n = c.u32_be()? as usize;
    if tag == 0 {
        return Ok(Vec::new());
    }
    if tag != 12 {
        return Err(Bad::corrupt(format!("attribute list tag {tag}")));
    }
    let mut out = Vec::new();
    for _ in 0..n {
        let key = name(c)?;
        let t = c.u32_be()?;
        let m = c.u32_be()? as usize;
        let size = type_size(t)?;
        let a = if t == 2 {
            let b = c.take(m)?;
            Attr::Text(
                String::from_utf8_lossy(b)
                    .trim_end_matches('\0')
                    .to_string(),
            )
        } else {
            Attr::Num(values(c, t, m)?)
        };
        c.skip((4 - (m * size) % 4) % 4)?;
        out.push((key, a));
    }
    Ok(out)
}

/// The dimensions (names and lengths) and the variables of a file's header.
#[allow(clippy::type_complexity)]
fn header(bytes: &[u8]) -> Result<(Vec<(String, usize)>, Vec<Var>), Bad> {
    if bytes.starts_with(b"\x89HDF") {
        return Err(Bad::unsupported(
            "NetCDF-4 (HDF5): save it as NetCDF-3 (classic)",
        ));
    }
    if !bytes.starts_with(b"CDF") {
        return Err(Bad::magic("CDF"));
    }
    let mut c = Cursor::at(bytes, 3);
    let version = c.u8()?;
    if version != 1 && version != 2 {
        return Err(Bad::unsupported(format!(
            "NetCDF version {version} (1 and 2 are read)"
        )));
    }
    let _records = c.u32_be()?;
    let tag = c.u32_be()?;
    let n = c.u32_be()? as usize;
    if tag != 0 && tag != 10 {
        return Err(Bad::corrupt(format!("dimension list tag {tag}")));
    }
    let mut dims = Vec::new();
    for _ in 0..if tag == 0 { 0 } else { n } {
        let d = name(&mut c)?;
        dims.push((d, c.u32_be()? as usize));
    }
    let _global = attrs(&mut c)?;
    let tag = c.u32_be()?;
    let n = c.u32_be()? as usize;
    if tag != 0 && tag != 11 {
        return Err(Bad::corrupt(format!("variable list tag {tag}")));
    }
    let vars = variables(&mut c, if tag == 0 { 0 } else { n }, dims.len(), version)?;
    Ok((dims, vars))
}

/// The `n` variables of the variable list at `c`, whose ids of dimensions
/// are below `ndims`; `version` 1 holds 32-bit offsets, 2 64-bit ones.
fn variables(c: &mut Cursor, n: usize, ndims: usize, version: u8) -> Result<Vec<Var>, Bad> {
    let mut vars = Vec::new();
    for _ in 0..n {
        let vname = name(c)?;
        let k = c.u32_be()? as usize;
        if k > 16 {
            return Err(Bad::corrupt(format!(
                "variable '{vname}' has {k} dimensions"
            )));
        }
        let mut ids = Vec::new();
        for _ in 0..k {
            let id = c.u32_be()? as usize;
            if id >= ndims {
                return Err(Bad::corrupt(format!(
                    "variable '{vname}' uses dimension {id}"
                )));
            }
            ids.push(id);
        }
        let a = attrs(c)?;
        let ty = c.u32_be()?;
        let _vsize = c.u32_be()?;
        let begin = if version == 1 {
            u64::from(c.u32_be()?)
        } else {
            c.u64_be()?
        };
        vars.push(Var {
            name: vname,
            dims: ids,
            attrs: a,
            ty,
            begin,
        });
    }
    Ok(vars)
}

/// Refuses a file whose `y` or `heights` unit is another length than `x`'s
/// (`unit`): one unit serves them all.
fn same_units(unit: Option<&str>, y: Option<&Var>, h: &Var) -> Result<(), Bad> {
    for (what, u) in [
        ("y", y.and_then(|v| v.text("unit"))),
        ("heights", h.text("unit")),
    ] {
        if let (Some(u), Some(x)) = (&u, &unit) {
            if super::units::metres_per(u, false) != super::units::metres_per(x, false) {
                return Err(Bad::corrupt(format!(
                    "the units of x ('{x}') and {what} ('{u}') differ"
                )));
            }
        }
    }
    Ok(())
}

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    pick(&["Default".to_string()], 0, channel)?;
    let (dims, vars) = header(bytes)?;
    let var = |n: &str| vars.iter().find(|v| v.name == n);
    let h = var("heights").ok_or_else(|| Bad::corrupt("no variable 'heights'"))?;
    let names: Vec<&str> = h.dims.iter().map(|&d| dims[d].0.as_str()).collect();
    let lens: Vec<usize> = h.dims.iter().map(|&d| dims[d].1).collect();
    if lens.contains(&0) {
        return Err(Bad::unsupported(
            "'heights' along the unlimited (record) dimension",
        ));
    }
    // (x, y) as SurfaceTopography writes it, x the slow index; (y, x) kept.
    let (nx, ny, x_slow) = match (names.as_slice(), lens.as_slice()) {
        (["y", "x"], [a, b]) => (*b, *a, false),
        (_, [a, b]) => (*a, *b, true),
        (_, [a]) => (*a, 1, true),
        _ => {
            return Err(Bad::unsupported(format!(
                "'heights' has {} dimensions",
                lens.len()
            )))
        }
    };
    let data = |v: &Var, n: usize| -> Result<Vec<f64>, Bad> {
        let mut c = Cursor::at(bytes, usize::try_from(v.begin).unwrap_or(usize::MAX));
        values(&mut c, v.ty, n)
    };
    let n = super::grid(ny, nx)?;
    let mut z = data(h, n)?;
    for key in ["_FillValue", "missing_value"] {
        if let Some(f) = h.num(key) {
            z.iter_mut()
                .filter(|v| **v == f)
                .for_each(|v| *v = f64::NAN);
        }
    }
    let scale = h.num("scale_factor").unwrap_or(1.0);
    let offset = h.num("add_offset").unwrap_or(0.0);
    if let Some(m) = var("mask") {
        if m.dims != h.dims {
            return Err(Bad::corrupt(
                "'mask' and 'heights' have different dimensions",
            ));
        }
        for (v, bad) in z.iter_mut().zip(data(m, n)?) {
            if bad != 0.0 {
                *v = f64::NAN;
            }
        }
    }
    let xv = var("x");
    let unit = xv.and_then(|v| v.text("unit"));
    let periodic = xv.and_then(|v| v.num("periodic")).is_some_and(|p| p != 0.0);
    same_units(unit.as_deref(), var("y"), h)?;
    let to_m = match &unit {
        Some(u) => super::metres(u, "the")?,
        None => 1.0,
    };
    for v in z.iter_mut() {
        *v = (*v * scale + offset) * to_m;
        if !v.is_finite() {
            *v = f64::NAN;
        }
    }
    let sizes = (
        xv.and_then(|v| v.num("length")),
        var("y").and_then(|v| v.num("length")),
    );
    let pixel_size = match sizes {
        (Some(sx), Some(sy)) if ny > 1 => Some((
            super::pixel(sx * to_m / nx as f64, "x")?,
            super::pixel(sy * to_m / ny as f64, "y")?,
        )),
        _ => None,
    };
    let z = if x_slow && ny > 1 {
        super::transpose(&z, nx, ny)
    } else {
        z
    };
    Ok(Measured {
        format: Format::NetCdf,
        channel: "Default".into(),
        channels: vec!["Default".into()],
        unit: unit.map_or_else(String::new, |u| super::units::canonical(&u, false)),
        rows: ny,
        cols: nx,
        heights: z,
        pixel_size,
        periodic,
    })
}
