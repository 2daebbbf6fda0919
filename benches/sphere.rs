//! Full LJ sphere solver timings (criterion, 10 samples):
//! `cargo bench --bench sphere -- --warm-up-time 1 --measurement-time 3`.
//! `pull_off_mu10` (facts: pull-off, jump-out, jump-in,
//! zero-load radius at the default resolution) in <= 0.5 s; `pull_off_mu30`
//! and `pull_off_mu100` the same facts at larger mu (solver version 5: about
//! 0.6 s and 1.2 s, docs/performance.md).
use asperity::sphere::{Shape, SolverOptions, SphereProblem};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Instant;

fn bench_sphere(c: &mut Criterion) {
    let mut group = c.benchmark_group("sphere");
    group.sample_size(10);
    for mu in [1.0, 5.0, 10.0, 30.0, 100.0] {
        let p = SphereProblem::new(mu, Shape::Paraboloid, SolverOptions::default()).unwrap();
        let t = Instant::now();
        let f = p.facts().unwrap();
        eprintln!(
            "mu {mu}: pull-off {:.6} ({} nodes) in {:.3} s",
            f.pull_off.load_bar,
            f.nodes,
            t.elapsed().as_secs_f64()
        );
        group.bench_function(format!("pull_off_mu{mu}"), |b| {
            b.iter(|| black_box(p.facts().unwrap()))
        });
    }
    let o = {
        let mut o = SolverOptions::default();
        o.arc_step = 0.027;
        o
    };
    let p = SphereProblem::new(1.0, Shape::Paraboloid, o).unwrap();
    let t = Instant::now();
    let n = p.trace().unwrap().len();
    eprintln!(
        "mu 1: whole curve, {n} points in {:.3} s",
        t.elapsed().as_secs_f64()
    );
    group.bench_function("trace_mu1_300pts", |b| {
        b.iter(|| black_box(p.trace().unwrap()))
    });
    group.finish();
}

criterion_group!(benches, bench_sphere);
criterion_main!(benches);
