//! NumPy `.npy` height maps (format versions 1.0, 2.0 and 3.0): a 2-D
//! array of float64 (`<f8`, `>f8`) or float32 (`<f4`, `>f4`) in C order.
//!
//! The format (NumPy Enhancement Proposal 1): the magic `\x93NUMPY`, a
//! major and minor version byte, the header length (little-endian `u16`
//! for version 1, `u32` for 2 and 3), the header (a Python dict literal
//! `{'descr': '<f8', 'fortran_order': False, 'shape': (rows, cols), }`)
//! and the raw data. Fortran order, other dtypes and other ranks are
//! rejected with the reason; float32 heights are widened exactly.

use super::map::{HeightMap, NAME};
use crate::error::{Error, Result};

const MAGIC: &[u8] = b"\x93NUMPY";

fn bad(reason: impl Into<String>) -> Error {
    Error::invalid(NAME, reason)
}

/// What a `.npy` header says of its array, checked against the file's
/// length: where the data start and how to read them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// Rows of the array.
    pub rows: usize,
    /// Columns.
    pub cols: usize,
    /// Bytes per value: 8 (float64) or 4 (float32).
    pub size: usize,
    /// Whether the values are big-endian.
    pub big_endian: bool,
    /// The byte offset of the data in the file.
    pub offset: usize,
}

/// Parses a `.npy` file's bytes into a height map.
///
/// # Errors
/// [`Error::Invalid`] named `topography` for an empty file, a file that is
/// not `.npy`, an unsupported version, dtype (anything but float64 or
/// float32), Fortran order, a rank other than 2, truncated data, or any
/// reason [`HeightMap::new`] gives (too small, NaN or infinite heights).
pub fn parse(bytes: &[u8]) -> Result<HeightMap> {
    let l = layout(bytes)?;
    let want = l.rows * l.cols * l.size;
    let heights = decode(&bytes[l.offset..l.offset + want], l.size, l.big_endian);
    HeightMap::new(l.rows, l.cols, heights)
}

/// The [`Layout`] of a `.npy` file's bytes: the header parsed and the data
/// checked to be exactly the `rows x cols` values it describes.
///
/// # Errors
/// As [`parse`], except the reasons of [`HeightMap::new`] (the values are
/// not read).
pub fn layout(bytes: &[u8]) -> Result<Layout> {
    if bytes.is_empty() {
        return Err(bad("empty file"));
    }
    if bytes.len() < 10 || &bytes[..6] != MAGIC {
        return Err(bad("not a NumPy .npy file (no \\x93NUMPY magic)"));
    }
    let (len, start) = match bytes[6] {
        1 => (u16::from_le_bytes([bytes[8], bytes[9]]) as usize, 10),
        2 | 3 if bytes.len() >= 12 => (
            u32::from_le_bytes([bytes[8], bytes[9], bytes[10], bytes[11]]) as usize,
            12,
        ),
        v => return Err(bad(format!("unsupported .npy format version {v}"))),
    };
    let header = bytes
        .get(start..start + len)
        .ok_or_else(|| bad("truncated .npy header"))?;
    let header = std::str::from_utf8(header).map_err(|_| bad("the .npy header is not text"))?;
    let descr = quoted_value(header, "descr")?;
    let fortran = raw_value(header, "fortran_order")?;
    let shape = shape(header)?;
    let (size, big_endian) = match descr.as_str() {
        "<f8" => (8, false),
        ">f8" => (8, true),
        "<f4" => (4, false),
        ">f4" => (4, true),
        other => {
            return Err(bad(format!(
                "unsupported dtype '{other}': heights must be float64 ('<f8') or float32 ('<f4')"
            )))
        }
    };
    if fortran.starts_with("True") {
        return Err(bad(
            "Fortran-ordered array: save it in C order (numpy.ascontiguousarray)",
        ));
    }
    let (rows, cols) = two_dims(&shape)?;
    let n = rows
        .checked_mul(cols)
        .ok_or_else(|| bad("the shape overflows"))?;
    let data = &bytes[start + len..];
    let want = n
        .checked_mul(size)
        .ok_or_else(|| bad("the shape overflows"))?;
    if data.len() < want {
        return Err(bad(format!(
            "truncated data: {} bytes for {rows} x {cols} values of {size} bytes",
            data.len()
        )));
    }
    if data.len() > want {
        // Stray bytes after the array: a damaged or mislabelled file (the
        // shape in the header does not describe the data).
        return Err(bad(format!(
            "{} stray bytes after the {rows} x {cols} values of {size} bytes (the header's \
             shape does not describe the data)",
            data.len() - want
        )));
    }
    Ok(Layout {
        rows,
        cols,
        size,
        big_endian,
        offset: start + len,
    })
}

/// `(rows, cols)` of a 2-D shape.
///
/// # Errors
/// [`Error::Invalid`] named `topography` for any other rank.
fn two_dims(shape: &[usize]) -> Result<(usize, usize)> {
    match shape {
        [r, c] => Ok((*r, *c)),
        [] => Err(bad(
            "a 0-D array (a single number); a height map must be 2-D",
        )),
        [n] => Err(bad(format!(
            "a 1-D array of shape ({n},); a height map must be 2-D"
        ))),
        s => Err(bad(format!(
            "a {}-D array of shape {s:?}; a height map must be 2-D",
            s.len()
        ))),
    }
}

/// The values of `data` (float64 when `size` is 8, else float32; little-
/// or big-endian) as `f64`.
pub fn decode(data: &[u8], size: usize, big_endian: bool) -> Vec<f64> {
    if size == 8 {
        data.chunks_exact(8)
            .map(|b| {
                let b: [u8; 8] = b.try_into().expect("chunk of 8");
                if big_endian {
                    f64::from_be_bytes(b)
                } else {
                    f64::from_le_bytes(b)
                }
            })
            .collect()
    } else {
        data.chunks_exact(4)
            .map(|b| {
                let b: [u8; 4] = b.try_into().expect("chunk of 4");
                f64::from(if big_endian {
                    f32::from_be_bytes(b)
                } else {
                    f32::from_le_bytes(b)
                })
            })
            .collect()
    }
}

/// The text after `'key':` in the header dict.
fn raw_value<'a>(header: &'a str, key: &str) -> Result<&'a str> {
    for q in ['\'', '"'] {
        let pat = format!("{q}{key}{q}");
        if let Some(k) = header.find(&pat) {
            let rest = header[k + pat.len()..].trim_start();
            if let Some(rest) = rest.strip_prefix(':') {
                return Ok(rest.trim_start());
            }
        }
    }
    Err(bad(format!("the .npy header has no '{key}'")))
}

/// A quoted string value, e.g. `descr`.
fn quoted_value(header: &str, key: &str) -> Result<String> {
    let rest = raw_value(header, key)?;
    let q = rest.chars().next().filter(|c| *c == '\'' || *c == '"');
    let q = q.ok_or_else(|| bad(format!("the .npy '{key}' is not a string")))?;
    let body = &rest[1..];
    let end = body
        .find(q)
        .ok_or_else(|| bad(format!("the .npy '{key}' is not a string")))?;
    Ok(body[..end].to_string())
}

/// The `shape` tuple, e.g. `(3, 4)` or `(5,)` or `()`.
fn shape(header: &str) -> Result<Vec<usize>> {
    let rest = raw_value(header, "shape")?;
    let inner = rest
        .strip_prefix('(')
        .and_then(|r| r.find(')').map(|e| &r[..e]))
        .ok_or_else(|| bad("the .npy 'shape' is not a tuple"))?;
    inner
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| {
            s.trim_end_matches('L')
                .parse::<usize>()
                .map_err(|_| bad(format!("the .npy 'shape' has a bad dimension '{s}'")))
        })
        .collect()
}

/// The bytes of a version-1.0 `.npy` file holding `map` as C-order
/// float64: what `numpy.save` writes (header padded to a multiple of 64).
pub fn to_bytes(map: &HeightMap) -> Vec<u8> {
    let mut header = format!(
        "{{'descr': '<f8', 'fortran_order': False, 'shape': ({}, {}), }}",
        map.rows(),
        map.cols()
    );
    // Magic (6) + version (2) + length (2) + header + '\n' to a multiple of 64.
    let total = (10 + header.len() + 1).div_ceil(64) * 64;
    header.push_str(&" ".repeat(total - 10 - header.len() - 1));
    header.push('\n');
    let mut out = Vec::with_capacity(total + 8 * map.heights().len());
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&[1, 0]);
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(header.as_bytes());
    for z in map.heights() {
        out.extend_from_slice(&z.to_le_bytes());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn npy(descr: &str, fortran: bool, shape: &str, data: &[u8]) -> Vec<u8> {
        let f = if fortran { "True" } else { "False" };
        let h = format!("{{'descr': '{descr}', 'fortran_order': {f}, 'shape': {shape}, }}\n");
        let mut out = MAGIC.to_vec();
        out.extend_from_slice(&[1, 0]);
        out.extend_from_slice(&(h.len() as u16).to_le_bytes());
        out.extend_from_slice(h.as_bytes());
        out.extend_from_slice(data);
        out
    }

    fn f64s(v: &[f64]) -> Vec<u8> {
        v.iter().flat_map(|x| x.to_le_bytes()).collect()
    }

    #[test]
    fn round_trips_float64_and_widens_float32() {
        let z: Vec<f64> = (0..12).map(|k| k as f64 * 0.25 - 1.0).collect();
        let map = HeightMap::new(3, 4, z.clone()).unwrap();
        let bytes = to_bytes(&map);
        assert_eq!((bytes.len() - 8 * 12) % 64, 0);
        assert_eq!(parse(&bytes).unwrap(), map);
        let f32s: Vec<u8> = z.iter().flat_map(|x| (*x as f32).to_le_bytes()).collect();
        assert_eq!(parse(&npy("<f4", false, "(3, 4)", &f32s)).unwrap(), map);
        let be: Vec<u8> = z.iter().flat_map(|x| x.to_be_bytes()).collect();
        assert_eq!(parse(&npy(">f8", false, "(3, 4)", &be)).unwrap(), map);
    }

    #[test]
    fn rejects_each_bad_file_with_its_reason() {
        let err = |b: &[u8]| parse(b).unwrap_err().to_string();
        let d = f64s(&[0.5; 12]);
        assert!(err(&[]).contains("empty file"));
        assert!(err(b"hello world, not numpy").contains("not a NumPy"));
        assert!(err(&npy("<f8", false, "(12,)", &d)).contains("1-D array of shape (12,)"));
        assert!(err(&npy("<f8", false, "()", &d)).contains("0-D"));
        assert!(err(&npy("<f8", false, "(2, 2, 3)", &d)).contains("3-D"));
        assert!(err(&npy("<i8", false, "(3, 4)", &d)).contains("unsupported dtype '<i8'"));
        assert!(err(&npy("<f8", true, "(3, 4)", &d)).contains("Fortran"));
        assert!(err(&npy("<f8", false, "(3, 5)", &d)).contains("truncated data"));
        assert!(err(&npy("<f8", false, "(0, 4)", &[])).contains("empty"));
        let mut nan = vec![0.5; 12];
        nan[7] = f64::NAN;
        assert!(err(&npy("<f8", false, "(3, 4)", &f64s(&nan))).contains("NaN height at row 1"));
        nan[7] = f64::INFINITY;
        assert!(err(&npy("<f8", false, "(3, 4)", &f64s(&nan))).contains("infinite height"));
    }
}
