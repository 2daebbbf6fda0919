//! X3P archives whose members are deflated (as most instruments write
//! them) read the same heights, bit for bit, as the stored archive, through
//! the path that inflates the heights' member straight into the heights'
//! buffer (`src/topography/inflate.rs`); a member that is damaged, ends
//! early, runs past its declared size or fails its CRC-32 is refused naming
//! the member and what is wrong, never read as a partial map.
#![cfg(feature = "study")]

use asperity::topography::{read_bytes, to_x3p, Channel, Format, Measured};
use std::io::{Read, Write};

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/topography");

/// The same archive with every member deflated (or stored), members
/// rewritten by `edit` on the way.
fn rezip(x3p: &[u8], method: zip::CompressionMethod, edit: impl Fn(&str, &mut Vec<u8>)) -> Vec<u8> {
    let mut zin = zip::ZipArchive::new(std::io::Cursor::new(x3p)).unwrap();
    let mut out = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let opts = zip::write::SimpleFileOptions::default().compression_method(method);
    for k in 0..zin.len() {
        let mut f = zin.by_index(k).unwrap();
        let name = f.name().unwrap().to_string();
        let mut data = Vec::new();
        f.read_to_end(&mut data).unwrap();
        edit(&name, &mut data);
        out.start_file(name, opts).unwrap();
        out.write_all(&data).unwrap();
    }
    out.finish().unwrap().into_inner()
}

fn deflated(x3p: &[u8]) -> Vec<u8> {
    rezip(x3p, zip::CompressionMethod::Deflated, |_, _| {})
}

fn x3p(bytes: &[u8]) -> asperity::Result<Measured> {
    read_bytes(bytes, Format::X3p, &Channel::Default)
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// Heights of every kind a float64 member can hold: ordinary values over
/// many binades, subnormals, both zeros, infinities and NaN with payloads
/// (non-finite values read as the one quiet NaN), on a grid whose size is
/// not a multiple of the reader's blocks.
fn awkward(rows: usize, cols: usize) -> Vec<f64> {
    let mut s: u64 = 0x2545_f491_4f6c_dd1d;
    (0..rows * cols)
        .map(|k| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            match k % 97 {
                0 => f64::INFINITY,
                1 => f64::NEG_INFINITY,
                2 => f64::from_bits(0x7ff0_0000_0000_0001),
                3 => -0.0,
                4 => f64::from_bits(s >> 12),
                _ => {
                    ((s >> 11) as f64 / (1u64 << 53) as f64 - 0.5)
                        * 10f64.powi((k % 40) as i32 - 20)
                }
            }
        })
        .collect()
}

#[test]
fn a_deflated_float64_map_reads_bit_for_bit_as_the_stored_one_and_as_written() {
    let (rows, cols) = (211, 173);
    let z = awkward(rows, cols);
    let stored = to_x3p(&z, rows, cols, 1e-7, 2e-7, "test").unwrap();
    let deflated = deflated(&stored);
    // The reference, computed here: non-finite heights are the quiet NaN.
    let want: Vec<u64> = z
        .iter()
        .map(|&v| if v.is_finite() { v } else { f64::NAN }.to_bits())
        .collect();
    for bytes in [&stored, &deflated] {
        let m = x3p(bytes).unwrap();
        assert_eq!((m.rows, m.cols), (rows, cols));
        assert_eq!(bits(&m.heights), want);
    }
    // The archive has four members (main.xml, the heights, the valid
    // points, the checksums): the heights' member is not the first.
    let zin = zip::ZipArchive::new(std::io::Cursor::new(&deflated[..])).unwrap();
    assert_eq!(zin.len(), 4);
}

/// The integer and float32 samples (checked against SurfaceTopography in
/// `topography_reference`), deflated, read the same bits as stored.
#[test]
fn deflated_int16_int32_and_float32_samples_read_as_the_stored_ones() {
    for name in [
        "generated-int16.x3p",
        "generated-int32.x3p",
        "generated-float.x3p",
        "x3p-2.x3p",
    ] {
        let file = std::fs::read(format!("{DIR}/{name}")).unwrap();
        let stored = rezip(&file, zip::CompressionMethod::Stored, |_, _| {});
        let a = x3p(&stored).unwrap();
        let b = x3p(&deflated(&file)).unwrap();
        let c = x3p(&file).unwrap();
        assert_eq!(bits(&a.heights), bits(&b.heights), "{name}");
        assert_eq!(bits(&a.heights), bits(&c.heights), "{name}");
        assert_eq!(a.missing(), b.missing(), "{name}");
    }
}

/// `bytes` with the uncompressed size of member `name` declared as `size`
/// in its local header and in the central directory (zip32 fields).
fn declare_size(bytes: &[u8], name: &str, size: u32) -> Vec<u8> {
    let mut b = bytes.to_vec();
    let mut hits = 0;
    for k in 0..b.len() - 4 {
        let at = match &b[k..k + 4] {
            b"PK\x03\x04" if b[k + 30..].starts_with(name.as_bytes()) => k + 22,
            b"PK\x01\x02" if b[k + 46..].starts_with(name.as_bytes()) => k + 24,
            _ => continue,
        };
        b[at..at + 4].copy_from_slice(&size.to_le_bytes());
        hits += 1;
    }
    assert_eq!(hits, 2, "{name}");
    b
}

fn refused(bytes: &[u8], words: &[&str]) {
    let err = x3p(bytes).map(|m| m.heights.len()).unwrap_err().to_string();
    for w in words {
        assert!(err.contains(w), "'{w}' in {err}");
    }
}

#[test]
fn a_damaged_deflated_member_is_refused_naming_it() {
    let (rows, cols) = (64, 50);
    let z: Vec<f64> = (0..rows * cols)
        .map(|k| (k as f64 * 0.37).sin() * 1e-7)
        .collect();
    let stored = to_x3p(&z, rows, cols, 1e-7, 1e-7, "test").unwrap();
    let want = (rows * cols * 8) as u32;
    let member = "bindata/data.bin";

    // One value short, declared full: the stream ends early.
    let short = rezip(&stored, zip::CompressionMethod::Deflated, |n, d| {
        if n == member {
            d.truncate(d.len() - 8);
        }
    });
    refused(
        &declare_size(&short, member, want),
        &["truncated", member, "inflates to 25592 bytes", "need 25600"],
    );

    // One value more, declared exact: the stream runs past its size.
    let long = rezip(&stored, zip::CompressionMethod::Deflated, |n, d| {
        if n == member {
            d.extend_from_slice(&1f64.to_le_bytes());
        }
    });
    refused(
        &declare_size(&long, member, want),
        &[member, "inflates to more than the 25600 bytes it declares"],
    );

    // A flipped bit inside the data, stored or deflated: the CRC-32 fails
    // (or, deflated, the stream itself breaks).
    let mut bad = stored.clone();
    let at = bad
        .windows(8)
        .position(|w| w == z[100].to_le_bytes())
        .unwrap();
    bad[at + 3] ^= 0x10;
    refused(&bad, &[member, "fails its CRC-32 check"]);
    let deflated = deflated(&stored);
    let start = deflated
        .windows(member.len())
        .position(|w| w == member.as_bytes())
        .unwrap();
    let mut bad = deflated.clone();
    bad[start + member.len() + 400] ^= 0x10;
    refused(&bad, &[member]);
}
