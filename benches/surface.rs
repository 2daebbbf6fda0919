//! Characterising a 4096 x 4096 height map (target <= 2 s on this 2-core
//! machine): mean plane, moments, summits, statistics; and reading
//! it from `.npy` bytes.
//!
//! `cargo bench --bench surface -- --warm-up-time 1 --measurement-time 3`

use asperity::surface::synthetic::GaussianSurface;
use asperity::surface::{npy, Topography};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn characterise(c: &mut Criterion) {
    let dx = 1e-7;
    let map = GaussianSurface::new(4096, 4096, 4.0, 1e-9, dx, 1)
        .unwrap()
        .generate();
    let bytes = npy::to_bytes(&map);
    let topo = Topography::new(map, dx).unwrap();
    let mut g = c.benchmark_group("surface_4096");
    g.sample_size(10);
    g.bench_function("characterise", |b| {
        b.iter(|| black_box(topo.characterise(false).unwrap().stats.count))
    });
    g.bench_function("characterise_periodic", |b| {
        b.iter(|| black_box(topo.characterise(true).unwrap().stats.count))
    });
    g.bench_function("parse_npy", |b| {
        b.iter(|| black_box(npy::parse(black_box(&bytes)).unwrap().rows()))
    });
    g.finish();
}

criterion_group!(benches, characterise);
criterion_main!(benches);
