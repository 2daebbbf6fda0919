//! Wavy punch speed targets: a 10,000-point exact curve (target <= 10 ms) and a
//! fit (target <= 1 s); also one Struve pair, an evolution with its energy loss, and the
//! gelatin fit on 800 points.
//! `cargo bench --bench punch -- --warm-up-time 1 --measurement-time 3`.
use asperity::punch::{fit_envelopes, Envelope, Evolution, FitPoint, Phase, WavyPunch};
use asperity::special::struve::struve_h0_h1;
use criterion::{criterion_group, criterion_main, Criterion};
use std::f64::consts::PI;
use std::hint::black_box;

fn gelatin() -> WavyPunch {
    WavyPunch::new(17.08e3, 80.4e-3, 0.25, 1.1e-4 / 5e-5f64.sqrt(), 5e-5).unwrap()
}

fn bench_punch(c: &mut Criterion) {
    let p = gelatin();
    let radii: Vec<f64> = (1..=10_000).map(|i| 0.026 * i as f64 / 10_000.0).collect();
    c.bench_function("exact curve 10000 points (gelatin, a/l up to 520)", |b| {
        b.iter(|| {
            let v: Vec<_> = radii.iter().map(|&a| p.state(black_box(a))).collect();
            black_box(v)
        })
    });
    c.bench_function("struve H0,H1 pair at x = 1234.5", |b| {
        b.iter(|| black_box(struve_h0_h1(black_box(1234.5))))
    });
    let fig3 = WavyPunch::new(1.0, 0.05 / (2.0 * PI), 1.0, 0.1, 0.03).unwrap();
    c.bench_function("evolution + energy loss (fig. 3, l/R = 0.03)", |b| {
        b.iter(|| {
            let ev = Evolution::new(&fig3, black_box(0.12)).unwrap();
            black_box(ev.energy_loss(-0.12))
        })
    });
    let data: Vec<FitPoint> = (0..400)
        .flat_map(|i| {
            let a = 0.008 + 0.018 * i as f64 / 399.0;
            [
                FitPoint {
                    phase: Phase::Loading,
                    radius: a,
                    load: p.envelope(a, Envelope::Loading).load,
                },
                FitPoint {
                    phase: Phase::Unloading,
                    radius: a,
                    load: p.envelope(a, Envelope::Unloading).load,
                },
            ]
        })
        .collect();
    c.bench_function("fit of 800 points", |b| {
        b.iter(|| black_box(fit_envelopes(0.25, black_box(&data)).unwrap()))
    });
}

criterion_group!(benches, bench_punch);
criterion_main!(benches);
