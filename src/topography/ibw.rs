//! Igor binary waves (`.ibw`, version 5), as Asylum Research AFMs write
//! them.
//!
//! Layout (WaveMetrics' Igor Technical Note PTN003, as the `igor2` package
//! and SurfaceTopography's `IBW.py` read it): a 64-byte `BinHeader5`
//! (`version` 5 as i16, whose byte order is the file's, checksum, then the
//! sizes of the wave, formula, note, extended data units, the 4 extended
//! dimension units, the 4 dimension labels, string indices and options),
//! the 320-byte `WaveHeader5` (`npnts` at 12, `type` at 16: 2 float32,
//! 4 float64, 8/16/32 signed integers, +64 unsigned, +1 complex; `nDim` at
//! 68, `sfA` (the pixel size of each dimension) at 84, `dataUnits` at 148
//! and `dimUnits` at 152, 4 characters each), then the data in column-major
//! order (the first dimension, x, fastest), then the formula, the note, the
//! extended units and the dimension labels (32 bytes each, the first the
//! dimension's own name). A map has `nDim[0] = nDim[1]` (or a third
//! dimension of channels, whose labels name them: `HeightTrace`,
//! `AmplitudeRetrace`, ...). The unit of a channel is Asylum's `NameUnit`
//! entry of the note (`key:value` lines) or its name's prefix (`Height`,
//! `ZSensor`, `Deflection`, `Amplitude` are in m, `Phase` in degrees,
//! ...); without a note, the wave's data unit. Igor uses SI symbols (`A`
//! is the ampere). As SurfaceTopography does, the map is flipped along y.

use super::bytes::Cursor;
use super::{pick, raster, Bad, Channel, Format, Measured};

/// The unit of an Asylum channel named `title` (after its `Trace` /
/// `Retrace` and `Mod` suffixes), from the note or the name.
fn asylum_unit(title: &str, note: &[(String, String)]) -> Option<String> {
    let mut base = title.to_string();
    if let Some(k) = base.rfind("Mod") {
        if base[k + 3..].bytes().all(|b| b.is_ascii_digit()) {
            base.truncate(k);
        }
    }
    for s in ["Trace", "Retrace"] {
        if let Some(b) = base.strip_suffix(s) {
            base = b.to_string();
            break;
        }
    }
    let key = format!("{base}Unit");
    if let Some((_, u)) = note.iter().find(|(k, _)| *k == key) {
        return Some(u.clone());
    }
    let mut b = base.as_str();
    for p in ["DAC", "Nap"] {
        if let Some(r) = b.strip_prefix(p) {
            b = r;
            break;
        }
    }
    let table = [
        ("Height", Some("m")),
        ("ZSensor", Some("m")),
        ("Deflection", Some("m")),
        ("Amplitude", Some("m")),
        ("Phase", Some("deg")),
        ("Current", Some("A")),
        ("Frequency", Some("Hz")),
        ("Capacitance", Some("F")),
        ("Potential", Some("V")),
        ("Count", None),
        ("QFactor", None),
    ];
    for (p, u) in table {
        if b.starts_with(p) {
            return u.map(str::to_string);
        }
    }
    Some("V".into())
}

fn unit4(b: &[u8]) -> String {
    let end = b.iter().position(|c| *c == 0).unwrap_or(b.len());
    b[..end]
        .iter()
        .map(|&c| c as char)
        .collect::<String>()
        .trim()
        .to_string()
}

/// The bytes of one value and its kind (`f` float, `i` signed, `u`
/// unsigned) of a wave of type `ty`.
fn wave_type(ty: i16) -> Result<(usize, char), Bad> {
    if ty & 1 != 0 {
        return Err(Bad::unsupported("complex waves"));
    }
    Ok(match ty & !1 {
        2 => (4, 'f'),
        4 => (8, 'f'),
        8 => (1, 'i'),
        0x10 => (2, 'i'),
        0x20 => (4, 'i'),
        0x48 => (1, 'u'),
        0x50 => (2, 'u'),
        0x60 => (4, 'u'),
        0 => return Err(Bad::unsupported("text waves")),
        t => return Err(Bad::corrupt(format!("wave type {t}"))),
    })
}

/// Whether a wave of dimensions `n_dim` is a map, its number of channels
/// and the dimension whose labels name them.
fn shape(n_dim: &[usize; 4]) -> (bool, usize, usize) {
    if n_dim[2] != 0 {
        (true, n_dim[2], 2)
    } else if n_dim[1] != 0 && n_dim[1] == n_dim[0] {
        (true, 1, 2)
    } else if n_dim[1] != 0 {
        (false, n_dim[1], 1)
    } else {
        (false, 1, 1)
    }
}

/// The value of one stored number `b` (its length the type's size) of
/// kind `kind`, big-endian when `big`.
fn value(b: &[u8], kind: char, big: bool) -> f64 {
    let size = b.len();
    let mut a = [0u8; 8];
    a[..size].copy_from_slice(b);
    if big {
        a[..size].reverse();
    }
    match (kind, size) {
        ('f', 4) => f64::from(f32::from_le_bytes([a[0], a[1], a[2], a[3]])),
        ('f', _) => f64::from_le_bytes(a),
        ('i', 1) => f64::from(a[0] as i8),
        ('i', 2) => f64::from(i16::from_le_bytes([a[0], a[1]])),
        ('i', _) => f64::from(i32::from_le_bytes([a[0], a[1], a[2], a[3]])),
        (_, 1) => f64::from(a[0]),
        (_, 2) => f64::from(u16::from_le_bytes([a[0], a[1]])),
        _ => f64::from(u32::from_le_bytes([a[0], a[1], a[2], a[3]])),
    }
}

/// The note (`key:value` lines) and the labels of dimension `label_dim`,
/// from the blocks after the wave (formula, note, units, labels) whose
/// sizes the binary header lists in `sizes`.
#[allow(clippy::type_complexity)]
fn note_and_labels(
    bytes: &[u8],
    sizes: &[usize; 15],
    label_dim: usize,
) -> Result<(Vec<(String, String)>, Vec<String>), Bad> {
    let [wfm, formula, note_size, data_e_units, de0, de1, de2, de3, dl0, dl1, dl2, dl3, ..] =
        *sizes;
    let mut c = Cursor::at(bytes, 64 + wfm);
    c.skip(formula)?;
    let note_text: String = c.take(note_size)?.iter().map(|&b| b as char).collect();
    let note: Vec<(String, String)> = note_text
        .split(['\r', '\n'])
        .filter_map(|l| l.split_once(':'))
        .map(|(k, v)| (k.trim().to_string(), v.trim().to_string()))
        .collect();
    c.skip(data_e_units)?;
    c.skip(de0 + de1 + de2 + de3)?;
    let mut labels = Vec::new();
    for (d, s) in [dl0, dl1, dl2, dl3].into_iter().enumerate() {
        let b = c.take(s)?;
        if d == label_dim {
            labels = b.chunks(32).map(unit4).collect();
        }
    }
    Ok((note, labels))
}

/// The names of `channels` channels (the labels after the dimension's own
/// name, else `no name (k)`) and their units (Asylum's, from the note or
/// the name, else the wave's `data_unit`).
fn channel_units(
    labels: &[String],
    note: &[(String, String)],
    channels: usize,
    data_unit: &str,
) -> (Vec<String>, Vec<String>) {
    let mut names: Vec<String> = labels.iter().skip(1).take(channels).cloned().collect();
    let named = names.len();
    let mut k = 1;
    while names.len() < channels {
        names.push(format!("no name ({k})"));
        k += 1;
    }
    let units: Vec<String> = (0..channels)
        .map(|i| {
            if !note.is_empty() && i < named {
                asylum_unit(&names[i], note).unwrap_or_default()
            } else {
                data_unit.to_string()
            }
        })
        .collect();
    (names, units)
}

/// Whether the file is big-endian, from its version (5) read both ways;
/// a file shorter than its two headers is refused.
fn big_endian(bytes: &[u8]) -> Result<bool, Bad> {
    if bytes.len() < 64 + 320 {
        return Err(Bad::truncated(format!(
            "{} bytes, the headers alone have 384",
            bytes.len()
        )));
    }
    match (
        i16::from_le_bytes([bytes[0], bytes[1]]),
        i16::from_be_bytes([bytes[0], bytes[1]]),
    ) {
        (5, _) => Ok(false),
        (_, 5) => Ok(true),
        (1..=3, _) | (_, 1..=3) => Err(Bad::unsupported(
            "Igor binary wave versions 1 to 3 (only 5 is read)",
        )),
        _ => Err(Bad::magic("the version 5 of an Igor binary wave")),
    }
}

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    let big = big_endian(bytes)?;
    let i32_at = |c: &mut Cursor| if big { c.i32_be() } else { c.i32_le() };
    let mut c = Cursor::at(bytes, 4);
    let mut sizes = [0usize; 15];
    for s in sizes.iter_mut() {
        let v = i32_at(&mut c)?;
        *s = usize::try_from(v).map_err(|_| Bad::corrupt(format!("a block size of {v}")))?;
    }
    let mut c = Cursor::at(bytes, 64 + 12);
    let npnts = i32_at(&mut c)?;
    let ty = if big { c.i16_be()? } else { c.i16_le()? };
    let mut c = Cursor::at(bytes, 64 + 68);
    let mut n_dim = [0usize; 4];
    for d in n_dim.iter_mut() {
        *d = usize::try_from(i32_at(&mut c)?).map_err(|_| Bad::corrupt("a negative dimension"))?;
    }
    let mut sf_a = [0.0; 4];
    for s in sf_a.iter_mut() {
        *s = if big { c.f64_be()? } else { c.f64_le()? };
    }
    let data_unit = unit4(&bytes[64 + 148..64 + 152]);
    let dim_unit = unit4(&bytes[64 + 152..64 + 156]);
    let (size, kind) = wave_type(ty)?;
    if n_dim[3] != 0 {
        return Err(Bad::unsupported("waves of four dimensions"));
    }
    let (dim2, channels, label_dim) = shape(&n_dim);
    let (nx, ny) = if dim2 {
        (n_dim[0], n_dim[1])
    } else {
        (n_dim[0], 1)
    };
    let per = super::grid(ny, nx)?;
    let total = per
        .checked_mul(channels)
        .filter(|t| *t <= super::MAX_PIXELS)
        .ok_or_else(|| Bad::corrupt("the dimensions overflow"))?;
    if npnts < 0 || npnts as usize != total {
        return Err(Bad::corrupt(format!(
            "npnts = {npnts} for dimensions {n_dim:?}"
        )));
    }
    let data_start = 64 + 320;
    let data = raster(bytes.get(data_start..).unwrap_or(&[]), total, 1, size)?;
    let (note, labels) = note_and_labels(bytes, &sizes, label_dim)?;
    let (names, units) = channel_units(&labels, &note, channels, &data_unit);
    let length = |u: &str| super::units::metres_per(u, true);
    let default = units.iter().position(|u| length(u).is_some()).unwrap_or(0);
    let ch = pick(&names, default, channel)?;
    let unit = &units[ch];
    let to_m = match length(unit) {
        Some(f) => f,
        None if unit.is_empty() => 1.0,
        None => {
            return Err(Bad::unsupported(format!(
                "channel {ch} '{}' holds no heights (its unit is '{unit}')",
                names[ch]
            )))
        }
    };
    let at = ch * per * size;
    let raw = &data[at..at + per * size];
    // Column-major (x fastest): row y of the map is contiguous.
    let mut z: Vec<f64> = raw
        .chunks_exact(size)
        .map(|b| {
            let v = value(b, kind, big) * to_m;
            if v.is_finite() {
                v
            } else {
                f64::NAN
            }
        })
        .collect();
    if dim2 {
        super::flip_rows(&mut z, ny, nx);
    }
    let lateral = length(&dim_unit);
    let pixel_size = match lateral {
        Some(f) if dim2 => Some((
            super::pixel(sf_a[0] * f, "x")?,
            super::pixel(sf_a[1] * f, "y")?,
        )),
        _ => None,
    };
    Ok(Measured {
        format: Format::Ibw,
        channel: names[ch].clone(),
        channels: names,
        unit: super::units::canonical(unit, true),
        rows: ny,
        cols: nx,
        heights: z,
        pixel_size,
        periodic: false,
    })
}
