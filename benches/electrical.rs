//! Speed targets (criterion):
//! `cargo bench --bench electrical -- --warm-up-time 1 --measurement-time 3`.
//! - a 1000-point resistance-force curve of Hertz summits over Gaussian
//!   heights with Wexler spots and Greenwood's mean-field term (<= 50 ms);
//! - the exact equal-potential solution for 2000 explicit spots (<= 2 s).
use asperity::electrical::{Interaction, ResistanceObservables, SpotResistance, Spots, Spreading};
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::Hertz;
use asperity::loading::{Derived, History, LoadingModel, Observables};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::sync::Arc;

/// Gold microswitch: 10^4 summits of radius 1 um, sigma 5 nm, in
/// (100 um)^2; E* = 48 GPa; gold rho and l. The engine's one GW
/// integrator with the spot conductance as a per-asperity observable, at
/// its default accuracy (`Accuracy::DEFAULT`, rtol 1e-8): the root rule of
/// `GwModel` (Hertz is smooth in `sqrt(delta)`), 59 evaluations per state.
fn curve(c: &mut Criterion) {
    let surface = RoughSurface::new(1e12, 1e-6, 5e-9, 1e-8).unwrap();
    let model = GwModel::new(
        surface,
        Arc::new(Gaussian::new()),
        Arc::new(Hertz::new(1e-6, 48e9).unwrap()),
    )
    .unwrap()
    .with_accuracy(Accuracy::DEFAULT);
    let spot = SpotResistance::same_metal(Spreading::Wexler, 2.44e-8, Some(3.46e-8)).unwrap();
    let res = ResistanceObservables::new(spot, Interaction::Greenwood, 1e-4);
    let outputs = res.add_to(Observables::LOAD).unwrap();
    let steps: Vec<(f64, History)> = (0..1000)
        .map(|i| ((-1.0 + 5.0 * i as f64 / 999.0) * 5e-9, History::Approach))
        .collect();
    let mut group = c.benchmark_group("electrical");
    group.bench_function("curve 1000 points wexler+greenwood", |b| {
        b.iter(|| {
            model
                .states(black_box(&steps), &outputs)
                .unwrap()
                .iter()
                .map(|s| s.load().unwrap() + res.value(&outputs, &s.totals).unwrap_or(0.0))
                .sum::<f64>()
        })
    });
    group.finish();
}

/// 2000 spots of radius 0.1-1 um, uniform in a (1 mm)^2 square
/// (deterministic LCG positions), Maxwell self terms.
fn exact(c: &mut Criterion) {
    let mut state: u64 = 15;
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let n = 2000;
    let (mut x, mut y, mut a) = (vec![], vec![], vec![]);
    for _ in 0..n {
        x.push(1e-3 * next());
        y.push(1e-3 * next());
        a.push(1e-7 + 9e-7 * next());
    }
    let spots = Spots::new(x, y, a).unwrap();
    let spot = SpotResistance::same_metal(Spreading::Maxwell, 2.44e-8, None).unwrap();
    let mut group = c.benchmark_group("electrical");
    group.sample_size(10);
    group.bench_function("exact 2000 spots", |b| {
        b.iter(|| black_box(spots.exact(&spot).unwrap()))
    });
    group.finish();
}

/// The same curve through a scene (`examples/scenes/rf-mems-switch.toml`,
/// 10^2 summits), the general path every law takes: the spot conductance and
/// its square as observables of the GW integral. The whole run: a 1000-point
/// approach leg (and for JKR and Kogut–Etsion the 1000-point retraction
/// leg), the six listed loads solved for; no pull-off search.
fn scene_curve(c: &mut Criterion) {
    use asperity::study::{Plan, PlanMode, Scene};
    let base = include_str!("../examples/scenes/rf-mems-switch.toml")
        .replace("points = 200 ", "points = 1000 ")
        .replace("pull_off = true", "pull_off = false");
    let mut group = c.benchmark_group("electrical");
    group.sample_size(10);
    for (name, law, w) in [
        ("hertz", "hertz", "0.0"),
        ("jkr", "jkr", "0.5"),
        ("kogut-etsion", "kogut-etsion", "0.5"),
    ] {
        let text = base
            .replace("kind = \"kogut-etsion\"", &format!("kind = \"{law}\""))
            .replace("w = 0.5 ", &format!("w = {w} "));
        let scene = Scene::from_toml(&text).unwrap();
        let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
        group.bench_function(
            format!("scene curve 1000 points wexler+greenwood {name}"),
            |b| b.iter(|| plan.run().unwrap().curve.approach.len()),
        );
    }
    group.finish();
}

criterion_group!(benches, curve, exact, scene_curve);
criterion_main!(benches);
