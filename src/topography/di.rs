//! Bruker/Veeco/Digital Instruments Nanoscope files (`.di`, `.spm`,
//! `.001`...), version 4.3 and later, scaled by the header's sensitivities.
//!
//! Layout (Bruker's Nanoscope file description, as Gwyddion's `nanoscope.c`
//! and SurfaceTopography's `DI.py` read it): a text header of lines `\Key:
//! value` in sections `\*Name`, from `\*File list` to `\*File list end`.
//! Every `\*Ciao image list` (or AFM/STM image list) section is a channel:
//! `Data offset`, `Data length`, `Bytes/pixel` (2 or 4; 4 also when the
//! version is at least 0x09200000 and the length holds 4 bytes a pixel),
//! `Samps/line` (x), `Number of lines` (y), `Scan Size: SX SY UNIT`, the
//! channel name in the brackets of `@2:Image Data: S [Height] "Height"`, and
//! `@2:Z scale: V [Sens. Zsens] (0.0050354 V/LSB) 2.910461 V`: the hard
//! value 2.910461 V spans the 2^(8 x bytes per pixel) steps of the raw
//! integers, and the soft scale `Sens. Zsens` names the sensitivity
//! `\@Sens. Zsens: V 20.83 nm/V` of the scanner or scan list. A height is
//! `raw x hard value / 256^bytes per pixel x sensitivity`, in the
//! sensitivity's length unit (nm). The data are little-endian signed
//! integers, the first line at the bottom of the image (the map is flipped
//! along y). Force curves and text data are refused.

use super::bytes::decode;
use super::{pick, pixel, raster, Bad, Channel, Format, Measured};
use std::collections::HashMap;

type Section = HashMap<String, String>;

const VERSION_32BIT: u64 = 0x0920_0000;

/// `(type, soft scale, hard scale, rest)` of a value such as `V [Sens.
/// Zsens] (0.005 V/LSB) 2.91 V`.
fn parse_value(v: &str) -> Result<(char, Option<String>, Option<String>, String), Bad> {
    let v = v.trim();
    let mut chars = v.chars();
    let kind = chars
        .next()
        .ok_or_else(|| Bad::corrupt("an empty header value"))?;
    let mut rest = chars.as_str().trim();
    let mut soft = None;
    if let Some(r) = rest.strip_prefix('[') {
        let end = r
            .find(']')
            .ok_or_else(|| Bad::corrupt(format!("unclosed '[' in '{v}'")))?;
        soft = Some(r[..end].trim().to_string()).filter(|s| !s.is_empty());
        rest = r[end + 1..].trim();
    }
    let mut hard = None;
    if rest.starts_with('(') {
        let mut level = 0;
        let mut end = None;
        for (i, ch) in rest.char_indices() {
            match ch {
                '(' => level += 1,
                ')' => {
                    level -= 1;
                    if level == 0 {
                        end = Some(i);
                        break;
                    }
                }
                _ => {}
            }
        }
        let end = end.ok_or_else(|| Bad::corrupt(format!("unclosed '(' in '{v}'")))?;
        hard = Some(rest[1..end].trim().to_string());
        rest = rest[end + 1..].trim();
    }
    Ok((kind, soft, hard, rest.to_string()))
}

/// A number and its unit (`2.91 V`).
fn number_unit(v: &str) -> Result<(f64, String), Bad> {
    let mut it = v.trim().splitn(2, char::is_whitespace);
    let n = it
        .next()
        .unwrap_or_default()
        .parse::<f64>()
        .map_err(|_| Bad::corrupt(format!("'{v}' is not a number with a unit")))?;
    Ok((n, it.next().unwrap_or_default().trim().to_string()))
}

/// The factor from unit `a` to unit `b` when they differ only by an SI
/// prefix (`mV` to `V`: 1e-3).
fn factor(a: &str, b: &str) -> Option<f64> {
    if a == b {
        return Some(1.0);
    }
    let split = |u: &str| -> (f64, String) {
        let prefixes = [
            ("p", 1e-12),
            ("n", 1e-9),
            ("u", 1e-6),
            ("µ", 1e-6),
            ("~", 1e-6),
            ("m", 1e-3),
            ("k", 1e3),
        ];
        for (p, f) in prefixes {
            if let Some(base) = u.strip_prefix(p) {
                if !base.is_empty() {
                    return (f, base.to_string());
                }
            }
        }
        (1.0, u.to_string())
    };
    let ((fa, ba), (fb, bb)) = (split(a), split(b));
    (ba == bb).then_some(fa / fb)
}

/// The header: sections in order, with lower-case keys.
fn header(bytes: &[u8]) -> Result<(Vec<(String, Section)>, usize), Bad> {
    if bytes.starts_with(b"?*") {
        return Err(Bad::unsupported("a Nanoscope file with text data"));
    }
    if !bytes.starts_with(b"\\*File list") && !bytes.starts_with(b"\\*EC File list") {
        return Err(Bad::magic("\\*File list"));
    }
    let mut sections: Vec<(String, Section)> = Vec::new();
    let mut pos = 0;
    loop {
        let Some(len) = bytes[pos..].iter().position(|b| *b == b'\n') else {
            return Err(Bad::truncated("the header has no '\\*File list end'"));
        };
        let line: String = bytes[pos..pos + len].iter().map(|&c| c as char).collect();
        pos += len + 1;
        let line = line.trim();
        if line.eq_ignore_ascii_case("\\*File list end") {
            break;
        }
        if let Some(name) = line.strip_prefix("\\*") {
            sections.push((name.to_lowercase(), Section::new()));
        } else if let Some(kv) = line.strip_prefix('\\') {
            let (k, v) = kv.split_once(": ").unwrap_or((kv, ""));
            if let Some((_, s)) = sections.last_mut() {
                s.insert(k.to_lowercase(), v.trim().to_string());
            }
        } else if !line.is_empty() {
            return Err(Bad::corrupt(format!(
                "a header line does not start with '\\': '{}'",
                line.chars().take(40).collect::<String>()
            )));
        }
    }
    Ok((sections, pos))
}

struct Image<'a> {
    name: String,
    section: &'a Section,
}

/// The image sections of a header in order, each with its channel name.
fn images(sections: &[(String, Section)]) -> Result<Vec<Image<'_>>, Bad> {
    let images: Vec<Image> = sections
        .iter()
        .filter(|(n, _)| {
            matches!(
                n.as_str(),
                "ciao image list"
                    | "afm image list"
                    | "stm image list"
                    | "ncafm image list"
                    | "image list"
            )
        })
        .map(|(_, s)| {
            let mut name = s.get("image data").cloned().unwrap_or_default();
            for key in ["@2:image data", "@3:image data", "@4:image data"] {
                if let Some(v) = s.get(key) {
                    if let Ok((_, soft, _, hard)) = parse_value(v) {
                        name = soft.unwrap_or_else(|| hard.trim_matches('"').to_string());
                    }
                    break;
                }
            }
            Image { name, section: s }
        })
        .collect();
    if images.is_empty() {
        return Err(Bad::corrupt("no image section"));
    }
    Ok(images)
}

/// Refuses a file that ends before one of the images its header lists:
/// a file cut short is refused whichever channel is asked for.
fn check_present(images: &[Image], file_len: usize) -> Result<(), Bad> {
    for (k, im) in images.iter().enumerate() {
        let at = |key: &str| {
            im.section
                .get(key)
                .and_then(|v| v.trim().parse::<usize>().ok())
        };
        if let (Some(offset), Some(length)) = (at("data offset"), at("data length")) {
            if offset.saturating_add(length) > file_len {
                return Err(Bad::truncated(format!(
                    "image {k} '{}' ends at byte {}, the file has {}",
                    im.name,
                    offset.saturating_add(length),
                    file_len
                )));
            }
        }
    }
    Ok(())
}

/// A count of an image or scan section.
fn int(key: &str, s: &Section) -> Result<usize, Bad> {
    s.get(key)
        .ok_or_else(|| Bad::corrupt(format!("no '{key}' in the image section")))?
        .trim()
        .parse::<usize>()
        .map_err(|_| Bad::corrupt(format!("'{key}' is not a count")))
}

/// Where and how one image's integers lie, and the scan's extent.
struct Layout {
    nx: usize,
    ny: usize,
    offset: usize,
    length: usize,
    /// The bytes a pixel by the header (the scale's 256^bpp).
    bpp: usize,
    /// The bytes a pixel as stored.
    size: usize,
    /// The scan size along x and y, in `xy_unit`.
    sx: f64,
    sy: f64,
    xy_unit: String,
}

/// The layout of image section `p`, with the scan list `scan` (its global
/// sizes and slow-axis size) and the file's `version`.
fn layout(p: &Section, scan: &Section, version: u64) -> Result<Layout, Bad> {
    let mut nx = int("samps/line", p)?;
    let mut ny = int("number of lines", p)?;
    let offset = int("data offset", p)?;
    let length = int("data length", p)?;
    let bpp = p
        .get("bytes/pixel")
        .map_or(Ok(2), |_| int("bytes/pixel", p))?;
    if bpp != 2 && bpp != 4 {
        return Err(Bad::unsupported(format!("{bpp} bytes per pixel")));
    }
    let mut size = bpp;
    let npx = super::grid(ny, nx)?;
    if version >= VERSION_32BIT && length >= 4 * npx {
        size = 4;
    }
    let scan_size = p
        .get("scan size")
        .ok_or_else(|| Bad::corrupt("no 'Scan Size' in the image section"))?;
    let parts: Vec<&str> = scan_size.split_whitespace().collect();
    let sx: f64 = parts
        .first()
        .and_then(|s| s.parse().ok())
        .ok_or_else(|| Bad::corrupt(format!("Scan Size '{scan_size}'")))?;
    let (mut sx, mut sy, mut xy_unit) = match parts.get(1).and_then(|s| s.parse::<f64>().ok()) {
        Some(sy) => (sx, sy, parts[2..].join(" ")),
        None => (sx, sx, parts[1..].join(" ")),
    };
    let slow = match (scan.get("slow axis size"), scan.get("scan size")) {
        (Some(slow), Some(fast)) => {
            let (f, fu) = number_unit(fast)?;
            let (s, su) = number_unit(slow)?;
            let c = super::units::metres_per(&su, false)
                .zip(super::units::metres_per(&fu, false))
                .map(|(a, b)| a / b);
            c.map(|c| (f, s * c, fu))
        }
        _ => None,
    };
    if let Some((f, s, fu)) = &slow {
        let c = super::units::metres_per(fu, false)
            .zip(super::units::metres_per(&xy_unit, false))
            .map(|(a, b)| a / b);
        match c {
            Some(c) => (sx, sy) = (f * c, s * c),
            None => (sx, sy, xy_unit) = (*f, *s, fu.clone()),
        }
    }
    let global = int("samps/line", scan).ok().zip(int("lines", scan).ok());
    if let Some((gx, gy)) = global {
        let use_global = length != nx * ny * size
            && (length == gx * gy * size || (nx * ny * size > length && length >= gx * gy * size));
        if use_global {
            if slow.is_none() {
                sx *= gx as f64 / nx as f64;
                sy *= gy as f64 / ny as f64;
            }
            (nx, ny) = (gx, gy);
        } else if slow.is_some() && nonsquare(p) && ny < gy {
            sy *= ny as f64 / gy as f64;
        }
    }
    Ok(Layout {
        nx,
        ny,
        offset,
        length,
        bpp,
        size,
        sx,
        sy,
        xy_unit,
    })
}

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    let (sections, _) = header(bytes)?;
    let merged = |names: &[&str]| {
        let mut out = Section::new();
        for (n, s) in &sections {
            if names.contains(&n.as_str()) {
                out.extend(s.iter().map(|(k, v)| (k.clone(), v.clone())));
            }
        }
        out
    };
    let files = merged(&["file list", "ec file list"]);
    let scanner = merged(&["scanner list", "microscope list"]);
    let scan = merged(&["ciao scan list", "afm list", "stm list", "nc afm list"]);
    let mode = sections
        .iter()
        .filter_map(|(_, s)| s.get("operating mode"))
        .next_back()
        .map(|s| s.trim().to_string());
    let version = files
        .get("version")
        .and_then(|v| u64::from_str_radix(v.trim().trim_start_matches("0x"), 16).ok())
        .unwrap_or(0);
    let context = files.get("start context").map_or("", |s| s.trim());
    if mode.as_deref() == Some("Force") || context == "FOL" {
        return Err(Bad::unsupported("force curves"));
    }
    let images = images(&sections)?;
    check_present(&images, bytes.len())?;
    let names: Vec<String> = images.iter().map(|i| i.name.clone()).collect();
    // The first channel with a length unit; else the first.
    let scales: Vec<Result<(f64, String), Bad>> = images
        .iter()
        .map(|im| z_scale(im.section, &scanner, &scan))
        .collect();
    let default = scales
        .iter()
        .position(|s| {
            s.as_ref()
                .is_ok_and(|(_, u)| super::units::metres_per(u, false).is_some())
        })
        .unwrap_or(0);
    let k = pick(&names, default, channel)?;
    let im = &images[k];
    let (scale, unit) = match &scales[k] {
        Ok(s) => s.clone(),
        Err(e) => return Err(e.clone()),
    };
    let to_m = super::units::metres_per(&unit, false).ok_or_else(|| {
        Bad::unsupported(format!(
            "channel {k} '{}' holds no heights (its unit is '{unit}')",
            im.name
        ))
    })?;
    let l = layout(im.section, &scan, version)?;
    let (nx, ny, length, size) = (l.nx, l.ny, l.length, l.size);
    let n = super::grid(ny, nx)?;
    if n * size > length {
        return Err(Bad::corrupt(format!(
            "a data length of {length} bytes for {nx} x {ny} points of {size} bytes"
        )));
    }
    let data = raster(bytes.get(l.offset..).unwrap_or(&[]), ny, nx, size)?;
    let step = scale / 256f64.powi(l.bpp as i32);
    let mut z: Vec<f64> = if size == 2 {
        decode(data, |b| f64::from(i16::from_le_bytes(b)) * step * to_m)
    } else {
        decode(data, |b| f64::from(i32::from_le_bytes(b)) * step * to_m)
    };
    super::flip_rows(&mut z, ny, nx);
    let xy = super::metres(&l.xy_unit, "the scan size")?;
    Ok(Measured {
        format: Format::Nanoscope,
        channel: im.name.clone(),
        channels: names,
        unit: super::units::canonical(&unit, false),
        rows: ny,
        cols: nx,
        heights: z,
        pixel_size: Some((
            pixel(l.sx * xy / nx as f64, "x")?,
            pixel(l.sy * xy / ny as f64, "y")?,
        )),
        periodic: false,
    })
}

/// Whether an image section's aspect ratio is not 1:1.
fn nonsquare(p: &Section) -> bool {
    match p.get("aspect ratio") {
        None => false,
        Some(a) if a.trim() == "1:1" => false,
        Some(a) => a
            .split(':')
            .next()
            .and_then(|r| r.trim().parse::<f64>().ok())
            .is_some_and(|r| r > 0.0 && r != 1.0),
    }
}

/// The height of one raw step times 256^bytes per pixel (the hard value
/// times the sensitivity) and its unit, from `@2:Z scale` and the soft
/// scale it names.
fn z_scale(p: &Section, scanner: &Section, scan: &Section) -> Result<(f64, String), Bad> {
    let z = p
        .get("@4:z scale")
        .or_else(|| p.get("@2:z scale"))
        .ok_or_else(|| Bad::unsupported("no '@2:Z scale' (Nanoscope 4.2 and earlier)"))?;
    let (_, quantity, _, hard) = parse_value(z)?;
    let (hard, hard_unit) = number_unit(&hard)?;
    let Some(q) = quantity else {
        return Ok((hard, hard_unit));
    };
    let key = format!("@{}", q.to_lowercase());
    let Some(soft) = scanner.get(&key).or_else(|| scan.get(&key)) else {
        return Ok((hard, hard_unit));
    };
    let (kind, _, _, value) = parse_value(soft)?;
    if kind != 'V' {
        return Err(Bad::corrupt(format!(
            "the sensitivity '{q}' is not a value"
        )));
    }
    let (s, su) = number_unit(&value)?;
    let Some((height_unit, per)) = su.split_once('/') else {
        return Ok((hard, hard_unit));
    };
    let c = factor(&hard_unit, per).ok_or_else(|| {
        Bad::corrupt(format!(
            "the Z scale's unit '{hard_unit}' and the sensitivity's '{su}' do not match"
        ))
    })?;
    Ok((hard * c * s, height_unit.to_string()))
}
