//! CPU nanoseconds per summit of `MonteCarlo::state` on one thread, per law:
//! `cargo run --release --example mc_ns_per_summit [repeats] [law] [summits]`
//! (one law by name, e.g. `hertz`, for profiling, or `all`, the default;
//! 1e6 summits by default).
//!
//! Summits with exponential heights (sigma = 5 nm, R = 1 um), every summit
//! in range (`d = -sigma`), load + area + count, on a 1-thread rayon pool.
//! Process CPU time from `/proc/self/stat` (Linux; utime + stime) around
//! the repeated states, so other processes' load does not count; the
//! population is drawn before the clock starts. The same work as
//! `benches/peers/montecarlo_numpy.py`.
use asperity::heights::Exponential;
use asperity::law::plastic::build;
use asperity::law::{Hertz, Jkr, LawKind, RadiusScaling};
use asperity::loading::{History, LoadingModel, Observables};
use asperity::material::plastic::{Plasticity, Variant};
use asperity::material::{Adhesion, AsperityContact};
use asperity::montecarlo::*;
use std::hint::black_box;
use std::sync::Arc;
use std::time::Instant;

const R: f64 = 1e-6;
const SIGMA: f64 = 5e-9;

/// utime + stime of this process (s), from /proc/self/stat.
fn cpu_seconds() -> f64 {
    asperity::study::cpu_time::process_cpu_seconds().unwrap_or(f64::NAN)
}

fn main() {
    let repeats: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1);
    let n_summits: usize = std::env::args()
        .nth(3)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let spec = PopulationSpec::new(n_summits, SIGMA, RadiusSpec::Fixed(R), 1).unwrap();
    let pop = Arc::new(Population::sample(&spec, &Exponential::new()).unwrap());
    let contact = AsperityContact::new(R, 4.8e10, Adhesion::new(0.5, 3e-10).unwrap()).unwrap();
    let laws: Vec<(&str, SummitLaw, usize)> = vec![
        (
            "hertz",
            SummitLaw::scaled(
                Arc::new(Hertz::new(R, 4.8e10).unwrap()),
                R,
                RadiusScaling::MAUGIS,
            )
            .unwrap(),
            400,
        ),
        (
            "jkr",
            SummitLaw::scaled(
                Arc::new(Jkr::new(R, 4.8e10, 0.5).unwrap()),
                R,
                RadiusScaling::MAUGIS,
            )
            .unwrap(),
            10,
        ),
        (
            "tabulated-md",
            SummitLaw::from_kind(LawKind::Maugis, &contact).unwrap(),
            40,
        ),
        (
            "kogut-etsion",
            SummitLaw::fixed(
                build(Variant::KogutEtsion, R, 4.8e10, Plasticity::gold())
                    .unwrap()
                    .as_law(),
                R,
            )
            .unwrap(),
            40,
        ),
    ];
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    println!(
        "law, history, CPU ns/summit (1 thread), wall ns/summit ({} SIMD)",
        asperity::numeric::simd::arch_name()
    );
    let only = std::env::args().nth(2);
    if only
        .as_deref()
        .is_none_or(|o| o == "all" || o == "hertz" || o == "floor")
    {
        // The square-root floor: one pass over the heights, sqrt(max(z - d, 0))
        // summed, the only work no Hertz sum can avoid.
        let z = pop.heights();
        let k = (400 * repeats * 1_000_000).div_ceil(n_summits);
        let c0 = cpu_seconds();
        let mut total = 0.0;
        for _ in 0..k {
            total += black_box(sqrt_floor(z, black_box(-SIGMA)));
        }
        black_box(total);
        let per = 1e9 / (k * n_summits) as f64;
        println!(
            "{:14} {:9} {:8.2}",
            "sqrt-floor",
            "-",
            (cpu_seconds() - c0) * per
        );
    }
    for (name, law, k) in laws {
        if only.as_deref().is_some_and(|o| o != name && o != "all") {
            continue;
        }
        let mc = MonteCarlo::new(pop.clone(), law).unwrap();
        let k = (k * repeats * 1_000_000).div_ceil(n_summits);
        for (hname, history) in [
            ("approach", History::Approach),
            (
                "retract",
                History::Retract {
                    closest: -2.0 * SIGMA,
                },
            ),
        ] {
            pool.install(|| {
                black_box(mc.state(-SIGMA, history, &Observables::ALL).unwrap());
                let (c0, t0) = (cpu_seconds(), Instant::now());
                for _ in 0..k {
                    black_box(
                        mc.state(black_box(-SIGMA), history, &Observables::ALL)
                            .unwrap(),
                    );
                }
                let (cpu, wall) = (cpu_seconds() - c0, t0.elapsed().as_secs_f64());
                let per = 1e9 / (k * n_summits) as f64;
                println!("{name:14} {hname:9} {:8.2} {:8.2}", cpu * per, wall * per);
            });
        }
    }
}

/// `sum sqrt(max(z - d, 0))` over the heights in 8 lanes, compiled for the
/// instruction set [`asperity::numeric::simd::arch`] picks.
fn sqrt_floor(z: &[f64], d: f64) -> f64 {
    struct Floor<'a>(&'a [f64], f64);
    impl pulp::WithSimd for Floor<'_> {
        type Output = f64;
        #[inline(always)]
        fn with_simd<S: pulp::Simd>(self, _simd: S) -> f64 {
            let mut acc = [0.0f64; 8];
            for c in self.0.chunks_exact(8) {
                for j in 0..8 {
                    let x = c[j] - self.1;
                    acc[j] += (if x > 0.0 { x } else { 0.0 }).sqrt();
                }
            }
            acc.iter().sum()
        }
    }
    asperity::numeric::simd::arch().dispatch(Floor(z, d))
}
