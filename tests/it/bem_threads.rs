//! The boundary-element solves give the same bits on any number of threads:
//! the transforms split by independent lines and every sum is taken in a
//! fixed order of fixed chunks (`src/bem/fft.rs`, `src/bem/passes.rs`).
//! Maps above the size where the transforms go parallel (2^17 grid points).

use asperity::bem::{Options, Problem, Solution};
use asperity::spectrum::synthesis::random_phase_map;
use asperity::spectrum::{Normalisation, Spectrum};
use std::f64::consts::PI;

fn solve(n: usize, periodic: bool, threads: usize) -> Solution {
    let l = 1e-4;
    let q0 = 2.0 * PI / l;
    let s = Spectrum::self_affine(
        0.8,
        4.0 * q0,
        4.0 * q0,
        (n / 4) as f64 * q0,
        Normalisation::SlopeRms(0.1),
    )
    .unwrap();
    let map = random_phase_map(&s, n, n, l / n as f64, 7).unwrap();
    let opts = Options {
        tolerance: 1e-8,
        ..Default::default()
    };
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(|| {
            let prob = Problem::new(&map, l / n as f64, 1e9, periodic, &opts).unwrap();
            prob.solve_pressure(1e6, &opts, None).unwrap()
        })
}

#[test]
fn periodic_and_padded_solves_are_bit_identical_on_one_two_and_three_threads() {
    for (n, periodic) in [(512, true), (192, false)] {
        let one = solve(n, periodic, 1);
        assert!(
            one.converged && one.iterations > 10,
            "{n}: {}",
            one.iterations
        );
        // A real contact problem: some but not all pixels touch.
        assert!(one.area_fraction() > 0.001 && one.area_fraction() < 0.5);
        for threads in [2, 3] {
            let other = solve(n, periodic, threads);
            assert!(
                one == other,
                "{n}^2 periodic {periodic}: {threads} threads differ"
            );
        }
    }
}
