//! Reading a 4096 x 4096 map (float64 heights, 128 MiB) from an instrument
//! file against the same heights from `.npy`, through the one reader
//! (`asperity::topography::read`, as `asperity surface FILE` reads): X3P as
//! asperity exports it (members stored), the same archive deflated (as
//! most instruments write it), and binary SDF. Target: at most 2x the
//! `.npy` read.
//!
//! The map read at the memory floor: `read_npy` (the `.npy` memory-mapped
//! and validated in one pass, the buffer the characterisation uses) alone
//! and followed by the characterisation, as `asperity surface MAP.npy`
//! does (`docs/performance.md`, "Round three": at most 0.15 s of CPU for
//! both, whole process).
//!
//! Criterion times CPU (user + system of the process, from
//! `/proc/self/stat`, so both cores' work counts) per read; the ratios to
//! `.npy` are printed at the end.
//!
//! `cargo bench --bench topography`

use asperity::surface::synthetic::GaussianSurface;
use asperity::surface::{npy, HeightMap, Topography};
use asperity::topography::{read, read_npy, to_x3p, Channel};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::time::Duration;

const N: usize = 4096;
const DX: f64 = 1e-7;

/// CPU time of this process so far (user + system, clock ticks of 10 ms).
fn cpu_time() -> Duration {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    // Fields after the command name's closing parenthesis: utime and stime
    // are the 12th and 13th.
    let rest = stat.rsplit_once(')').map_or("", |(_, r)| r);
    let f: Vec<u64> = rest
        .split_whitespace()
        .skip(11)
        .take(2)
        .filter_map(|v| v.parse().ok())
        .collect();
    let ticks = f.iter().sum::<u64>();
    Duration::from_millis(ticks * 10)
}

/// A binary SDF (ISO 25178-71 `bISO-1.0`) of float64 heights (m).
fn sdf(map: &HeightMap) -> Vec<u8> {
    let mut out = b"bISO-1.0".to_vec();
    out.extend_from_slice(&[b' '; 34]);
    out.extend_from_slice(&(map.cols() as u16).to_le_bytes());
    out.extend_from_slice(&(map.rows() as u16).to_le_bytes());
    for v in [DX, DX, 1.0, 1e-12] {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.extend_from_slice(&[0, 7, 0]);
    for v in map.heights() {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out
}

/// The same archive with every member deflated.
fn deflated(x3p: &[u8]) -> Vec<u8> {
    let mut zin = zip::ZipArchive::new(std::io::Cursor::new(x3p)).unwrap();
    let mut out = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let opts = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated)
        .large_file(true);
    for k in 0..zin.len() {
        let mut f = zin.by_index(k).unwrap();
        let name = f.name().unwrap().to_string();
        let mut data = Vec::new();
        f.read_to_end(&mut data).unwrap();
        out.start_file(name, opts).unwrap();
        out.write_all(&data).unwrap();
    }
    out.finish().unwrap().into_inner()
}

fn files() -> (PathBuf, Vec<(&'static str, PathBuf)>) {
    let map = GaussianSurface::new(N, N, 4.0, 1e-9, DX, 1)
        .unwrap()
        .generate();
    let dir = std::env::temp_dir().join(format!("asperity-bench-topo-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let x3p = to_x3p(map.heights(), N, N, DX, DX, "bench").unwrap();
    let files = vec![
        ("npy", npy::to_bytes(&map), "map.npy"),
        ("x3p_deflated", deflated(&x3p), "deflated.x3p"),
        ("x3p_stored", x3p, "stored.x3p"),
        ("sdf", sdf(&map), "map.sdf"),
    ];
    let paths = files
        .into_iter()
        .map(|(name, bytes, file)| {
            let p = dir.join(file);
            std::fs::write(&p, bytes).unwrap();
            // Each file reads the same heights.
            let m = read(&p, &Channel::Default).unwrap();
            assert!(m.heights.iter().zip(map.heights()).all(|(a, b)| a == b));
            (name, p)
        })
        .collect();
    (dir, paths)
}

fn read_cpu(path: &Path, iters: u64) -> Duration {
    let t0 = cpu_time();
    for _ in 0..iters {
        black_box(
            read(black_box(path), &Channel::Default)
                .unwrap()
                .heights
                .len(),
        );
    }
    cpu_time() - t0
}

fn reading(c: &mut Criterion) {
    let (dir, paths) = files();
    let mut g = c.benchmark_group("read_4096");
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(20));
    g.warm_up_time(Duration::from_secs(2));
    for (name, p) in &paths {
        g.bench_function(format!("{name}_cpu"), |b| b.iter_custom(|n| read_cpu(p, n)));
        g.bench_function(format!("{name}_wall"), |b| {
            b.iter(|| black_box(read(black_box(p), &Channel::Default).unwrap().heights.len()))
        });
    }
    g.finish();
    // CPU per read over 10 reads each, and the ratios to .npy.
    let per: Vec<(&str, f64)> = paths
        .iter()
        .map(|(n, p)| (*n, read_cpu(p, 10).as_secs_f64() / 10.0))
        .collect();
    let npy = per[0].1;
    for (n, t) in &per {
        println!("cpu per read {n:>13}: {t:.3} s, {:.2}x npy", t / npy);
    }
    let _ = std::fs::remove_dir_all(dir);
}

/// CPU of `iters` runs of `f`.
fn cpu_of(iters: u64, mut f: impl FnMut()) -> Duration {
    let t0 = cpu_time();
    for _ in 0..iters {
        f();
    }
    cpu_time() - t0
}

fn npy_floor(c: &mut Criterion) {
    let (dir, paths) = files();
    let p = &paths[0].1;
    let map = read_npy(p).unwrap();
    assert!(
        map.is_shared(),
        "a native float64 .npy is read where it lies"
    );
    drop(map);
    let read_only = || {
        black_box(read_npy(black_box(p)).unwrap().heights().len());
    };
    let characterised = || {
        let topo = Topography::new(read_npy(black_box(p)).unwrap(), DX).unwrap();
        black_box(topo.characterise(false).unwrap().summits.len());
    };
    let mut g = c.benchmark_group("npy_4096");
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(10));
    g.warm_up_time(Duration::from_secs(2));
    g.bench_function("read_npy_cpu", |b| b.iter_custom(|n| cpu_of(n, read_only)));
    g.bench_function("read_npy_characterise_cpu", |b| {
        b.iter_custom(|n| cpu_of(n, characterised))
    });
    g.finish();
    let _ = std::fs::remove_dir_all(dir);
}

criterion_group!(benches, reading, npy_floor);
criterion_main!(benches);
