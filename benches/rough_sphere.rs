//! Rough-sphere (Greenwood–Tripp) timings (criterion, 10 samples):
//! `cargo bench --bench rough_sphere -- --warm-up-time 1 --measurement-time 3`.
//! Goal: a 100-point load–approach curve (`curve_mu1_100pts`: mu = 1, d
//! from 3 down to -1 sigma, every point to the default tolerance 1e-6 on
//! the load) in <= 50 ms. Also: the same curve at mu = 0.1 and 10, and one
//! state from far apart (no continuation) at the points of the
//! ContactMechanics comparison (`benches/peers/greenwood_tripp_cm.py`).
//! Each curve also prints the process CPU time per curve (from
//! /proc/self/stat, over 20 curves), since the machine is shared.
use asperity::roughsphere::GreenwoodTripp;
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

/// User + system CPU time of this process (s), from /proc/self/stat
/// (clock ticks of 10 ms; `None` off Linux).
fn cpu_seconds() -> Option<f64> {
    asperity::study::cpu_time::process_cpu_seconds()
}

fn bench_rough_sphere(c: &mut Criterion) {
    let mut group = c.benchmark_group("rough_sphere");
    group.sample_size(10);
    let ds: Vec<f64> = (0..100).map(|k| 3.0 - 4.0 * k as f64 / 99.0).collect();
    for mu in [0.1, 1.0, 10.0] {
        let gt = GreenwoodTripp::new(mu).unwrap();
        let states = gt.states(&ds, &[]).unwrap();
        let worst = states
            .iter()
            .map(|s| s.load.error / s.load.value)
            .fold(0.0, f64::max);
        let nodes = states.iter().map(|s| s.nodes).max().unwrap();
        if let Some(t0) = cpu_seconds() {
            for _ in 0..20 {
                black_box(gt.states(&ds, &[]).unwrap());
            }
            let t1 = cpu_seconds().unwrap();
            eprintln!(
                "mu {mu}: 100-point curve, CPU {:.1} ms per curve, worst load error estimate \
                 {worst:.1e} (relative), finest mesh {nodes} nodes",
                1e3 * (t1 - t0) / 20.0
            );
        }
        group.bench_function(format!("curve_mu{mu}_100pts"), |b| {
            b.iter(|| black_box(gt.states(&ds, &[]).unwrap()))
        });
    }
    for (mu, d) in [(1.0, 0.0), (10.0, -1.0), (100.0, 0.5)] {
        let gt = GreenwoodTripp::new(mu).unwrap();
        group.bench_function(format!("state_mu{mu}_d{d}"), |b| {
            b.iter(|| black_box(gt.state(d, &[0.5]).unwrap()))
        });
    }
    group.finish();
}

/// The plastic adhesive bump, `examples/scenes/switch-bump-plastic.toml`
/// as shipped (one load, 10 points per leg, pull-off, resistance): the
/// whole run, whose retraction table dominates (docs/performance.md,
/// "Round three: curves and the bump"). About 8 s a run: 10 samples.
fn bench_plastic_bump(c: &mut Criterion) {
    use asperity::study::{Plan, PlanMode, Scene};
    let text = include_str!("../examples/scenes/switch-bump-plastic.toml");
    let scene = Scene::from_toml(text).unwrap();
    let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
    let mut group = c.benchmark_group("rough_sphere");
    group.sample_size(10);
    group.bench_function("plastic_bump_scene", |b| {
        b.iter(|| black_box(plan.run().unwrap().curve.approach.len()))
    });
    group.finish();
}

criterion_group!(benches, bench_rough_sphere, bench_plastic_bump);
criterion_main!(benches);
