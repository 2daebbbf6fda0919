//! ISO 25178-72 (formerly ISO 5436-2) XML 3D surface profiles (`.x3p`):
//! a zip archive holding `main.xml` and the binary heights.
//!
//! Layout (ISO 5436-2 and its openGPS reference schema `ISO5436_2.xsd`, as
//! Gwyddion's `opengps.c` and SurfaceTopography's `X3P.py` read it):
//! `Record1` gives `Revision` (`ISO5436 - 2000`), `FeatureType` (`SUR` for
//! an areal map), the axes `CX`, `CY` (`AxisType` `I`: incremental, with
//! `Increment` in m) and `CZ` (`AxisType` `A`, `DataType` `I` int16, `L`
//! int32, `F` float32 or `D` float64, optional `Increment` and `Offset`:
//! heights are `value x Increment + Offset` m); `Record3` gives
//! `MatrixDimension` (`SizeX`, `SizeY`, `SizeZ` = 1) and the `DataLink`:
//! `PointDataLink`, the archive member with the `SizeY` rows of `SizeX`
//! little-endian values, x fastest, and optionally `ValidPointsLink`, one
//! bit per point (least-significant first, 1 = valid). NaN heights are
//! missing too.

use super::{pick, pixel, Bad, Channel, Format, Measured};
use std::collections::HashMap;
use std::io::{Read, Write};

/// The text of every leaf element of the XML document `xml` (the archive
/// member `what`, for messages) by its path below the root
/// (`Record1/Axes/CX/Increment`), namespace prefixes dropped.
fn leaves(xml: &str, what: &str) -> Result<HashMap<String, String>, Bad> {
    use quick_xml::events::Event;
    let mut reader = quick_xml::Reader::from_str(xml);
    let mut path: Vec<String> = Vec::new();
    let mut out = HashMap::new();
    let mut text = String::new();
    loop {
        match reader.read_event() {
            Ok(Event::Start(e)) => {
                path.push(e.local_name().as_ref().to_string());
                text.clear();
            }
            Ok(Event::Text(t)) => text.push_str(t.as_ref()),
            Ok(Event::CData(t)) => text.push_str(t.as_ref()),
            Ok(Event::End(_)) => {
                if path.len() > 1 {
                    out.entry(path[1..].join("/"))
                        .or_insert_with(|| text.trim().to_string());
                }
                path.pop();
                text.clear();
            }
            Ok(Event::Eof) => break,
            Ok(_) => {}
            Err(e) => {
                return Err(Bad::corrupt(format!(
                    "{what} is not well-formed XML at byte {}: {e}",
                    reader.buffer_position()
                )))
            }
        }
        if path.len() > 64 {
            return Err(Bad::corrupt(format!(
                "{what} nests deeper than 64 elements"
            )));
        }
    }
    Ok(out)
}

/// A zip archive's bytes opened, after checking its magic number.
pub(super) fn open_zip(bytes: &[u8]) -> Result<zip::ZipArchive<std::io::Cursor<&[u8]>>, Bad> {
    if !bytes.starts_with(b"PK\x03\x04") {
        return Err(Bad::magic("PK\\x03\\x04 (a zip archive)"));
    }
    zip::ZipArchive::new(std::io::Cursor::new(bytes))
        .map_err(|e| Bad::corrupt(format!("not a readable zip archive: {e}")))
}

/// The leaf elements of an XML member of an archive ([`leaves`]), read by
/// path with errors naming the member.
pub(super) struct Leaves {
    map: HashMap<String, String>,
    what: &'static str,
}

impl Leaves {
    /// The member `what` of `zip` (at most 16 MiB), UTF-8 XML, read.
    pub(super) fn read<R: Read + std::io::Seek>(
        zip: &mut zip::ZipArchive<R>,
        what: &'static str,
    ) -> Result<Leaves, Bad> {
        let xml = member(zip, what, 1 << 24)?;
        let xml =
            String::from_utf8(xml).map_err(|_| Bad::corrupt(format!("{what} is not UTF-8")))?;
        Ok(Leaves {
            map: leaves(&xml, what)?,
            what,
        })
    }

    /// The text at path `k`, if the document has it.
    pub(super) fn optional(&self, k: &str) -> Option<&str> {
        self.map.get(k).map(String::as_str)
    }

    /// The text at path `k`; an error naming the member and `k` without it.
    pub(super) fn get(&self, k: &str) -> Result<&str, Bad> {
        self.optional(k)
            .ok_or_else(|| Bad::corrupt(format!("{} has no {k}", self.what)))
    }

    /// The number at path `k`.
    pub(super) fn num(&self, k: &str) -> Result<f64, Bad> {
        self.get(k)?
            .parse::<f64>()
            .map_err(|_| Bad::corrupt(format!("{}: {k} is not a number", self.what)))
    }

    /// The count at path `k`.
    pub(super) fn count(&self, k: &str) -> Result<usize, Bad> {
        self.get(k)?
            .parse::<usize>()
            .map_err(|_| Bad::corrupt(format!("{}: {k} is not a count", self.what)))
    }
}

/// A member of the archive, read whole if its declared size is at most
/// `limit` bytes.
pub(super) fn member<R: Read + std::io::Seek>(
    zip: &mut zip::ZipArchive<R>,
    name: &str,
    limit: u64,
) -> Result<Vec<u8>, Bad> {
    let mut f = zip
        .by_name(name)
        .map_err(|e| Bad::corrupt(format!("no member '{name}' in the archive ({e})")))?;
    if f.size() > limit {
        return Err(Bad::corrupt(format!(
            "member '{name}' declares {} bytes, more than the {limit} the header describes",
            f.size()
        )));
    }
    let mut out = Vec::with_capacity(f.size() as usize);
    f.by_ref()
        .take(limit)
        .read_to_end(&mut out)
        .map_err(|e| Bad::corrupt(format!("member '{name}' cannot be read: {e}")))?;
    Ok(out)
}

/// Refuses all but an areal map: `FeatureType` `SUR`, incremental x and y
/// axes and an absolute z axis (`x`: the leaves of `main.xml`).
fn check_areal(x: &Leaves) -> Result<(), Bad> {
    if x.get("Record1/FeatureType")? != "SUR" {
        return Err(Bad::unsupported(format!(
            "FeatureType {} (only SUR, an areal map)",
            x.get("Record1/FeatureType")?
        )));
    }
    for (axis, kind) in [("CX", "I"), ("CY", "I"), ("CZ", "A")] {
        let t = x.get(&format!("Record1/Axes/{axis}/AxisType"))?;
        if t != kind {
            return Err(Bad::unsupported(format!(
                "{axis} AxisType {t} (expected {kind})"
            )));
        }
    }
    Ok(())
}

/// Sets to NaN the heights `z` whose bit in the archive member `valid`
/// (one bit a point, least-significant first, 1 = valid) is 0.
fn mask_invalid<R: Read + std::io::Seek>(
    zip: &mut zip::ZipArchive<R>,
    valid: &str,
    z: &mut [f64],
) -> Result<(), Bad> {
    let n = z.len();
    let bits = member(zip, valid, n.div_ceil(8) as u64)?;
    if bits.len() < n.div_ceil(8) {
        return Err(Bad::truncated(format!(
            "'{valid}' has {} bytes for {n} points",
            bits.len()
        )));
    }
    for (k, v) in z.iter_mut().enumerate() {
        if bits[k / 8] >> (k % 8) & 1 == 0 {
            *v = f64::NAN;
        }
    }
    Ok(())
}

/// The `rows x cols` values of `N` bytes each in member `name`, decoded by
/// `f` while the member inflates, 64 KiB at a time: a deflated member never
/// exists whole in memory beside the heights (one copy, not two). For the
/// members [`super::inflate::whole_member`] does not take (encrypted,
/// another method, a declared size other than the values').
pub(super) fn member_values<R: Read + std::io::Seek, const N: usize>(
    zip: &mut zip::ZipArchive<R>,
    name: &str,
    rows: usize,
    cols: usize,
    f: impl Fn([u8; N]) -> f64,
) -> Result<Vec<f64>, Bad> {
    let n = super::grid(rows, cols)?;
    let want = (n as u64).saturating_mul(N as u64);
    let mut file = zip
        .by_name(name)
        .map_err(|e| Bad::corrupt(format!("no member '{name}' in the archive ({e})")))?;
    if file.size() > want {
        return Err(Bad::corrupt(format!(
            "member '{name}' declares {} bytes, more than the {want} the header describes",
            file.size()
        )));
    }
    let mut z = Vec::with_capacity(n);
    let mut buf = vec![0u8; 1 << 16];
    let mut have = 0;
    let mut total = 0u64;
    let mut reader = file.by_ref().take(want);
    loop {
        let k = match reader.read(&mut buf[have..]) {
            Ok(0) => break,
            Ok(k) => k,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(Bad::corrupt(format!("member '{name}' cannot be read: {e}"))),
        };
        have += k;
        total += k as u64;
        let whole = have / N * N;
        z.extend(buf[..whole].chunks_exact(N).map(|c| {
            let mut a = [0u8; N];
            a.copy_from_slice(c);
            f(a)
        }));
        buf.copy_within(whole..have, 0);
        have -= whole;
    }
    if z.len() < n {
        return Err(Bad::truncated(format!(
            "{rows} x {cols} values of {N} bytes need {want} bytes, {total} are left"
        )));
    }
    Ok(z)
}

/// The `rows x cols` values of `N` bytes each in member `name` of the
/// archive `bytes` (opened as `zip`), decoded by `f`: read whole into the
/// heights' buffer when the member is stored or deflated with its exact
/// size declared ([`super::inflate::whole_member`]), else streamed
/// ([`member_values`]).
pub(super) fn heights<const N: usize>(
    bytes: &[u8],
    zip: &mut zip::ZipArchive<std::io::Cursor<&[u8]>>,
    name: &str,
    rows: usize,
    cols: usize,
    f: impl Fn([u8; N]) -> f64 + Sync,
) -> Result<Vec<f64>, Bad> {
    match super::inflate::whole_member(bytes, zip, name, rows, cols, &f)? {
        Some(z) => Ok(z),
        None => member_values(zip, name, rows, cols, f),
    }
}

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    pick(&["Default".to_string()], 0, channel)?;
    let mut zip = open_zip(bytes)?;
    let x = Leaves::read(&mut zip, "main.xml")?;
    check_areal(&x)?;
    let (nx, ny) = (
        x.count("Record3/MatrixDimension/SizeX")?,
        x.count("Record3/MatrixDimension/SizeY")?,
    );
    if x.count("Record3/MatrixDimension/SizeZ")? != 1 {
        return Err(Bad::unsupported("SizeZ other than 1 (volume data)"));
    }
    super::grid(ny, nx)?;
    let (dx, dy) = (
        x.num("Record1/Axes/CX/Increment")?,
        x.num("Record1/Axes/CY/Increment")?,
    );
    let t = x.get("Record1/Axes/CZ/DataType")?;
    if !matches!(t, "I" | "L" | "F" | "D") {
        return Err(Bad::unsupported(format!("CZ DataType {t}")));
    }
    let inc = x
        .optional("Record1/Axes/CZ/Increment")
        .map_or(Ok(1.0), |_| x.num("Record1/Axes/CZ/Increment"))?;
    let off = x
        .optional("Record1/Axes/CZ/Offset")
        .map_or(Ok(0.0), |_| x.num("Record1/Axes/CZ/Offset"))?;
    let link = x
        .get("Record3/DataLink/PointDataLink")
        .map_err(|_| Bad::unsupported("no Record3/DataLink/PointDataLink (inline DataList)"))?;
    // Scaled by the increment and offset; non-finite values are missing.
    let plain = inc == 1.0 && off == 0.0;
    let scale = move |v: f64| {
        let v = if plain { v } else { v * inc + off };
        if v.is_finite() {
            v
        } else {
            f64::NAN
        }
    };
    let (rows, cols) = (ny, nx);
    let mut z: Vec<f64> = match t {
        "I" => heights(bytes, &mut zip, link, rows, cols, |b| {
            scale(f64::from(i16::from_le_bytes(b)))
        })?,
        "L" => heights(bytes, &mut zip, link, rows, cols, |b| {
            scale(f64::from(i32::from_le_bytes(b)))
        })?,
        "F" => heights(bytes, &mut zip, link, rows, cols, |b| {
            scale(f64::from(f32::from_le_bytes(b)))
        })?,
        _ => heights(bytes, &mut zip, link, rows, cols, |b| {
            scale(f64::from_le_bytes(b))
        })?,
    };
    if let Some(valid) = x.optional("Record3/DataLink/ValidPointsLink") {
        mask_invalid(&mut zip, valid, &mut z)?;
    }
    Ok(Measured {
        format: Format::X3p,
        channel: "Default".into(),
        channels: vec!["Default".into()],
        unit: "m".into(),
        rows: ny,
        cols: nx,
        heights: z,
        pixel_size: Some((pixel(dx, "x")?, pixel(dy, "y")?)),
        periodic: false,
    })
}

/// The bytes of an X3P file holding the row-major `rows x cols` heights
/// `z` (m; NaN = missing, written as NaN and as an invalid point) with pixel
/// sizes `dx`, `dy` (m): float64 data (`CZ` `DataType` `D`, no increment),
/// the increments in Rust's shortest round-trip form, MD5 checksums of the
/// data and of `main.xml` (`md5checksum.hex`), as ISO 5436-2 asks. Reading
/// it back gives the same bits.
///
/// # Errors
/// [`crate::Error::Invalid`] named `topography` when `z` is not `rows x
/// cols`, [`crate::Error::Io`] when the archive cannot be assembled.
pub fn to_x3p(
    z: &[f64],
    rows: usize,
    cols: usize,
    dx: f64,
    dy: f64,
    software: &str,
) -> crate::Result<Vec<u8>> {
    if z.len() != rows * cols {
        return Err(crate::Error::invalid(
            "topography",
            format!("{} heights for {rows} x {cols} pixels", z.len()),
        ));
    }
    let data: Vec<u8> = z.iter().flat_map(|v| v.to_le_bytes()).collect();
    let missing = z.iter().any(|v| v.is_nan());
    let valid: Option<Vec<u8>> = missing.then(|| {
        let mut b = vec![0u8; z.len().div_ceil(8)];
        for (k, v) in z.iter().enumerate() {
            if !v.is_nan() {
                b[k / 8] |= 1 << (k % 8);
            }
        }
        b
    });
    let valid_link = valid.as_ref().map_or(String::new(), |b| {
        format!(
            "\n      <ValidPointsLink>bindata/valid.bin</ValidPointsLink>\n      \
             <MD5ChecksumValidPoints>{}</MD5ChecksumValidPoints>",
            super::md5::hex(b)
        )
    });
    let xml = main_xml(
        rows,
        cols,
        dx,
        dy,
        software,
        &super::md5::hex(&data),
        &valid_link,
    );
    let io = |e: &dyn std::fmt::Display| crate::Error::io("X3P archive", e);
    let mut w = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let opts = zip::write::SimpleFileOptions::default()
        // Stored: reading is then a copy (about the cost of a .npy), where
        // inflating float64 heights, which barely compress, costs 5x
        // (docs/performance.md, "Reading measured maps").
        .compression_method(zip::CompressionMethod::Stored)
        .large_file(data.len() >= u32::MAX as usize);
    let mut put = |name: &str, b: &[u8]| -> crate::Result<()> {
        w.start_file(name, opts).map_err(|e| io(&e))?;
        w.write_all(b).map_err(|e| io(&e))
    };
    put("main.xml", xml.as_bytes())?;
    put("bindata/data.bin", &data)?;
    if let Some(b) = &valid {
        put("bindata/valid.bin", b)?;
    }
    let sum = format!("{} *main.xml\n", super::md5::hex(xml.as_bytes()));
    put("md5checksum.hex", sum.as_bytes())?;
    let out = w.finish().map_err(|e| io(&e))?;
    Ok(out.into_inner())
}

/// The `main.xml` of [`to_x3p`]: the axes, the matrix of `rows x cols`
/// float64 heights and its data links (`md5` the data's checksum,
/// `valid_link` the valid points' link or empty).
fn main_xml(
    rows: usize,
    cols: usize,
    dx: f64,
    dy: f64,
    software: &str,
    md5: &str,
    valid_link: &str,
) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8" standalone="no" ?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.opengps.eu/2008/ISO5436_2 http://www.opengps.eu/2008/ISO5436_2/ISO5436_2.xsd">
  <Record1>
    <Revision>ISO5436 - 2000</Revision>
    <FeatureType>SUR</FeatureType>
    <Axes>
      <CX>
        <AxisType>I</AxisType>
        <DataType>D</DataType>
        <Increment>{dx:e}</Increment>
        <Offset>0</Offset>
      </CX>
      <CY>
        <AxisType>I</AxisType>
        <DataType>D</DataType>
        <Increment>{dy:e}</Increment>
        <Offset>0</Offset>
      </CY>
      <CZ>
        <AxisType>A</AxisType>
        <DataType>D</DataType>
      </CZ>
    </Axes>
  </Record1>
  <Record2>
    <Date>1970-01-01T00:00:00</Date>
    <Instrument>
      <Manufacturer>asperity</Manufacturer>
      <Model>{software}</Model>
      <Serial>not available</Serial>
      <Version>{version}</Version>
    </Instrument>
    <CalibrationDate>1970-01-01T00:00:00</CalibrationDate>
    <ProbingSystem>
      <Type>Software</Type>
      <Identification>asperity</Identification>
    </ProbingSystem>
    <Comment>heights in m</Comment>
  </Record2>
  <Record3>
    <MatrixDimension>
      <SizeX>{cols}</SizeX>
      <SizeY>{rows}</SizeY>
      <SizeZ>1</SizeZ>
    </MatrixDimension>
    <DataLink>
      <PointDataLink>bindata/data.bin</PointDataLink>
      <MD5ChecksumPointData>{md5}</MD5ChecksumPointData>{valid_link}
    </DataLink>
  </Record3>
  <Record4>
    <ChecksumFile>md5checksum.hex</ChecksumFile>
  </Record4>
</p:ISO5436_2>
"#,
        version = env!("CARGO_PKG_VERSION"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_and_reads_back_bit_for_bit() {
        let mut z: Vec<f64> = (0..35).map(|k| (k as f64 * 0.37).sin() * 1e-7).collect();
        z[9] = f64::NAN;
        let bytes = to_x3p(&z, 5, 7, 1.234567890123e-7, 3.3e-7, "test").unwrap();
        let m = read(&bytes, &Channel::Default).unwrap();
        assert_eq!((m.rows, m.cols), (5, 7));
        assert_eq!(m.pixel_size, Some((1.234567890123e-7, 3.3e-7)));
        assert_eq!(m.missing(), 1);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&m.heights), bits(&z));
        let err = read(b"PK\x03\x04 not really", &Channel::Default).unwrap_err();
        assert!(err.to_string().contains("zip"), "{err}");
    }
}
