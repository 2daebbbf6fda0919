//! Bad instrument files through `asperity surface`: for every format, a
//! truncated file, a file with the wrong magic and a header with a huge
//! dimension exit 2 with one line naming the file, the format and what is
//! wrong; never a panic, never a map.
#![cfg(feature = "study")]

use std::io::{Read, Write};
use std::path::PathBuf;
use std::process::Command;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/topography");

fn sample(name: &str) -> Vec<u8> {
    std::fs::read(format!("{DIR}/{name}")).unwrap()
}

fn scratch() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("asperity-topo-errors-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `asperity surface FILE --json --pixel-size 1e-7` on `bytes` written
/// to `name` and checks exit 2 with one line naming the file and the format
/// (and `what` when given).
fn refused(name: &str, bytes: &[u8], format: &str, what: &[&str]) {
    let path = scratch().join(name);
    std::fs::write(&path, bytes).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .arg("surface")
        .arg(&path)
        .args(["--json", "--fill-missing"])
        .output()
        .expect("run asperity");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{name}: {err}");
    assert!(out.stdout.is_empty(), "{name}: no output on failure");
    assert_eq!(err.trim().lines().count(), 1, "{name}: {err}");
    assert!(!err.contains("panicked"), "{name}: {err}");
    assert!(err.contains(&path.display().to_string()), "{name}: {err}");
    assert!(err.contains(format), "{name}: {err}");
    for w in what {
        assert!(err.contains(w), "{name}: expected '{w}' in {err}");
    }
    let _ = std::fs::remove_file(&path);
}

fn put_u16(b: &mut [u8], at: usize, v: u16) {
    b[at..at + 2].copy_from_slice(&v.to_le_bytes());
}

fn put_u32(b: &mut [u8], at: usize, v: u32) {
    b[at..at + 4].copy_from_slice(&v.to_le_bytes());
}

fn find(b: &[u8], what: &[u8]) -> usize {
    b.windows(what.len())
        .position(|w| w == what)
        .unwrap_or_else(|| panic!("{} not found", String::from_utf8_lossy(what)))
}

/// Replaces the value of every line starting with `key` (up to the line's
/// end) by `value`, byte for byte elsewhere (binary data after a text
/// header shift, which the refusal never reaches).
fn text_value(b: &[u8], key: &str, value: &str) -> Vec<u8> {
    let key = key.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut k = 0;
    let mut hit = false;
    while k < b.len() {
        let line_start = k == 0 || b[k - 1] == b'\n';
        if line_start && b[k..].starts_with(key) {
            out.extend_from_slice(key);
            out.extend_from_slice(value.as_bytes());
            k += key.len();
            while k < b.len() && b[k] != b'\r' && b[k] != b'\n' {
                k += 1;
            }
            hit = true;
        } else {
            out.push(b[k]);
            k += 1;
        }
    }
    assert!(hit, "{}", String::from_utf8_lossy(key));
    out
}

/// The same archive with `main.xml` rewritten by `edit`.
fn x3p_with(bytes: &[u8], edit: impl Fn(&str) -> String) -> Vec<u8> {
    zip_with(bytes, "main.xml", edit)
}

/// The same archive with its member `member` rewritten by `edit`.
fn zip_with(bytes: &[u8], member: &str, edit: impl Fn(&str) -> String) -> Vec<u8> {
    let mut zin = zip::ZipArchive::new(std::io::Cursor::new(bytes)).unwrap();
    let mut out = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let opts =
        zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Stored);
    for k in 0..zin.len() {
        let mut f = zin.by_index(k).unwrap();
        let name = f.name().unwrap().to_string();
        let mut data = Vec::new();
        f.read_to_end(&mut data).unwrap();
        if name == member {
            data = edit(&String::from_utf8(data).unwrap()).into_bytes();
        }
        out.start_file(name, opts).unwrap();
        out.write_all(&data).unwrap();
    }
    out.finish().unwrap().into_inner()
}

/// One format: its sample, the extension, how the format is named in
/// messages, and the sample with a huge dimension in its header.
struct Case {
    sample: &'static str,
    ext: &'static str,
    format: &'static str,
    huge: fn(&[u8]) -> Vec<u8>,
}

const BEYOND: &str = "refused before allocating";

fn cases() -> Vec<Case> {
    vec![
        Case {
            sample: "generated-float.x3p",
            ext: "x3p",
            format: "X3P (ISO 25178-72)",
            huge: |b| {
                x3p_with(b, |x| {
                    x.replace("<SizeX>25</SizeX>", "<SizeX>65536</SizeX>")
                        .replace("<SizeY>20</SizeY>", "<SizeY>65536</SizeY>")
                })
            },
        },
        Case {
            sample: "sdf-1.sdf",
            ext: "sdf",
            format: "SDF (ISO 25178-71)",
            huge: |b| {
                let b = text_value(b, "NumPoints", " = 99999");
                text_value(&b, "NumProfiles", " = 99999")
            },
        },
        Case {
            sample: "generated-1.gwy",
            ext: "gwy",
            format: "Gwyddion .gwy",
            huge: |b| {
                let mut b = b.to_vec();
                for key in [b"xres\0i".as_slice(), b"yres\0i".as_slice()] {
                    let at = find(&b, key) + key.len();
                    put_u32(&mut b, at, 0x7fff_ffff);
                }
                b
            },
        },
        Case {
            sample: "sur-2.sur",
            ext: "sur",
            format: "Digital Surf .sur",
            // nx = ny = 46340 (their product, 2.1e9, the i32 total): more
            // than the file holds.
            huge: |b| {
                let mut b = b.to_vec();
                put_u32(&mut b, 108, 46340);
                put_u32(&mut b, 112, 46340);
                put_u32(&mut b, 116, 46340 * 46340);
                b
            },
        },
        Case {
            sample: "di-3.di",
            ext: "di",
            format: "Nanoscope (Bruker/DI)",
            huge: |b| {
                let b = text_value(b, "\\Samps/line:", " 99999");
                text_value(&b, "\\Number of lines:", " 99999")
            },
        },
        Case {
            sample: "spot_1-1000nm.ibw",
            ext: "ibw",
            format: "Igor binary wave",
            huge: |b| {
                let mut b = b.to_vec();
                put_u32(&mut b, 64 + 68, 46341);
                put_u32(&mut b, 64 + 72, 46341);
                b
            },
        },
        Case {
            sample: "opd-1.opd",
            ext: "opd",
            format: "Wyko OPD",
            huge: |b| {
                // The directory's entries (24 bytes from byte 2) give each
                // block's length; the height array starts with nx, ny (u16).
                let mut b = b.to_vec();
                let dir = u32::from_le_bytes(b[20..24].try_into().unwrap()) as usize;
                let mut pos = 2 + dir;
                for k in 1..dir / 24 {
                    let e = 2 + 24 * k;
                    let ty = u16::from_le_bytes([b[e + 16], b[e + 17]]);
                    let len = i32::from_le_bytes(b[e + 18..e + 22].try_into().unwrap());
                    if ty == 3 && len > 0 {
                        put_u16(&mut b, pos, 0xffff);
                        put_u16(&mut b, pos + 2, 0xffff);
                        return b;
                    }
                    pos += len.max(0) as usize;
                }
                panic!("no array in the OPD sample")
            },
        },
        Case {
            sample: "opdx-3.opdx",
            ext: "opdx",
            format: "Dektak OPDx",
            huge: |b| {
                let mut b = b.to_vec();
                let at = find(&b, b"NumPoints\x0b") + 10;
                b[at..at + 8].copy_from_slice(&(1u64 << 32).to_le_bytes());
                b
            },
        },
        Case {
            sample: "nc-1.nc",
            ext: "nc",
            format: "NetCDF-3",
            huge: |b| {
                // magic, numrecs, NC_DIMENSION, 2 dimensions: (name length,
                // name padded to 4, length) each, names of one letter.
                let mut b = b.to_vec();
                put_u32(&mut b, 24, 0x7fff_ffffu32.to_be());
                put_u32(&mut b, 36, 0x7fff_ffffu32.to_be());
                b
            },
        },
        Case {
            sample: "frt-2.frt",
            ext: "frt",
            format: "FRT MicroProf",
            huge: |b| {
                // Blocks from byte 18: tag (u16), length (u32), value;
                // block 0x66 holds nx, ny (u32).
                let mut b = b.to_vec();
                let mut p = 18;
                loop {
                    let tag = u16::from_le_bytes([b[p], b[p + 1]]);
                    let len = u32::from_le_bytes(b[p + 2..p + 6].try_into().unwrap()) as usize;
                    if tag == 0x66 {
                        put_u32(&mut b, p + 6, 0x10000);
                        put_u32(&mut b, p + 10, 0x10000);
                        return b;
                    }
                    p += 6 + len;
                }
            },
        },
        Case {
            sample: "generated-1.plux",
            ext: "plux",
            format: "Sensofar .plux",
            huge: |b| {
                zip_with(b, "index.xml", |x| {
                    x.replace("<IMAGE_SIZE_X>27<", "<IMAGE_SIZE_X>99999<")
                        .replace("<IMAGE_SIZE_Y>14<", "<IMAGE_SIZE_Y>99999<")
                })
            },
        },
    ]
}

#[test]
fn truncated_files_exit_2_naming_the_file_and_the_format() {
    for c in cases() {
        let b = sample(c.sample);
        for keep in [b.len() / 2, 100.min(b.len() / 3)] {
            let name = format!("truncated-{keep}-{}.{}", c.sample, c.ext);
            refused(&name, &b[..keep], c.format, &[]);
        }
    }
}

#[test]
fn wrong_magic_exits_2_naming_the_file_and_the_format() {
    for c in cases() {
        let mut b = sample(c.sample);
        b[..8].copy_from_slice(b"GARBAGE!");
        let name = format!("magic-{}.{}", c.sample, c.ext);
        refused(&name, &b, c.format, &[]);
    }
}

#[test]
fn huge_dimensions_are_refused_before_allocating() {
    for c in cases() {
        let b = (c.huge)(&sample(c.sample));
        let name = format!("huge-{}.{}", c.sample, c.ext);
        let what: &[&str] = match c.ext {
            // The i32 total cannot exceed the bound: the data are missing.
            "sur" => &["truncated"],
            _ => &[BEYOND],
        };
        refused(&name, &b, c.format, what);
    }
}

#[test]
fn an_unknown_extension_names_the_file_and_the_known_ones() {
    let path = scratch().join("map.xyz");
    std::fs::write(&path, b"1 2 3\n").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .arg("surface")
        .arg(&path)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("map.xyz") && err.contains("unknown extension 'xyz'") && err.contains(".x3p"),
        "{err}"
    );
    let _ = std::fs::remove_file(&path);
}

/// A header that declares a map beyond the memory available (an X3P of
/// 20000 x 20000 pixels, 24 bytes a pixel: 9.6 GB) is refused from its
/// declared dimensions before the heights are allocated, naming the file,
/// the dimensions and the estimate; under an address-space limit of 3 GB
/// (`ulimit -v`, which the check reads) the 3.2 GB of heights alone would
/// abort the process.
#[test]
fn a_header_beyond_the_memory_is_refused_by_its_declared_dimensions() {
    let b = x3p_with(&sample("generated-float.x3p"), |x| {
        x.replace("<SizeX>25</SizeX>", "<SizeX>20000</SizeX>")
            .replace("<SizeY>20</SizeY>", "<SizeY>20000</SizeY>")
    });
    let path = scratch().join("beyond-memory.x3p");
    std::fs::write(&path, &b).unwrap();
    let out = Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 3000000 && exec \"$0\" \"$@\"")
        .arg(env!("CARGO_BIN_EXE_asperity"))
        .arg("surface")
        .arg(&path)
        .arg("--json")
        .output()
        .expect("run asperity");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty(), "{err}");
    for word in [
        path.display().to_string().as_str(),
        "20000 x 20000 map its header declares",
        "X3P (ISO 25178-72)",
        "needs about 9.6 GB",
        "refused before allocating",
    ] {
        assert!(err.contains(word), "'{word}' in {err}");
    }
    let _ = std::fs::remove_file(&path);
}
