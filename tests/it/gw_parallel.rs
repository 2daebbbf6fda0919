//! the states of a curve are computed in parallel and the
//! tabulated law's panel search walks from the previous node
//! (`LawKernels::state_near`); neither changes a single bit of the results.
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::interpolated::InterpolatedLaw;
use asperity::law::{Branch, LawCursor, LawKernels, Maugis};
use asperity::loading::{Curve, LoadingModel, LoadingProgram, Observables};
use std::sync::Arc;

fn exact() -> Arc<dyn LawKernels> {
    let s = RoughSurface::gold_microswitch();
    Arc::new(Maugis::new(s.radius, 1.0e11, 0.5, 1.0).unwrap())
}

fn table() -> InterpolatedLaw {
    let s = RoughSurface::gold_microswitch();
    let law = exact();
    InterpolatedLaw::new(law.clone(), law.cutoff_interference(), 40.0 * s.sigma, 1e-7).unwrap()
}

fn curve(threads: usize, obs: &Observables) -> Curve {
    let s = RoughSurface::gold_microswitch();
    let m = GwModel::new(s, Arc::new(Gaussian::new()), Arc::new(table()))
        .unwrap()
        .with_accuracy(Accuracy::new(1e-6).unwrap());
    let program = LoadingProgram::new(6.0 * s.sigma, 0.0, 120).unwrap();
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(|| m.curve(&program, obs).unwrap())
}

fn bits(c: &Curve) -> Vec<u64> {
    c.approach
        .iter()
        .chain(&c.retract)
        .flat_map(|s| [s.load(), s.area(), s.count()])
        .flatten()
        .map(f64::to_bits)
        .collect()
}

#[test]
fn curves_are_bit_identical_for_any_thread_count() {
    for obs in [Observables::LOAD, Observables::ALL] {
        let one = bits(&curve(1, &obs));
        assert!(!one.is_empty());
        for threads in [2, 3, 8] {
            assert_eq!(one, bits(&curve(threads, &obs)), "{threads} threads");
        }
    }
}

#[test]
fn state_near_is_state_bit_for_bit_from_any_cursor() {
    let s = RoughSurface::gold_microswitch();
    let (t, e) = (table(), exact());
    let (lo, hi) = (e.cutoff_interference(), 40.0 * s.sigma);
    let laws: [&dyn LawKernels; 2] = [&t, e.as_ref()];
    for law in laws {
        // Cursors left anywhere: fresh, far beyond the table, mid-way.
        for start in [0, 7, usize::MAX / 2] {
            let mut cursor = LawCursor { panels: [start; 2] };
            for i in 0..=3000 {
                // Jumping back and forth, and beyond both ends.
                let x = (i * 7919 % 3001) as f64 / 3000.0;
                let d = lo - 0.1 * (hi - lo) + 1.2 * (hi - lo) * x;
                let dm = d + 0.3 * (hi - lo) * x;
                let a = law.state_near(d, None, &mut cursor);
                let b = law.state(d, Branch::Approach);
                assert_eq!(
                    (a.load.to_bits(), a.radius.to_bits()),
                    (b.load.to_bits(), b.radius.to_bits())
                );
                let a = law.state_near(d, Some(dm), &mut cursor);
                let b = law.state_after(d, dm);
                assert_eq!(
                    (a.load.to_bits(), a.radius.to_bits()),
                    (b.load.to_bits(), b.radius.to_bits())
                );
                assert_eq!(
                    law.load_near(d, Some(dm), &mut cursor).to_bits(),
                    law.load_after(d, dm).to_bits()
                );
                assert_eq!(
                    law.load_near(d, None, &mut cursor).to_bits(),
                    law.load(d, Branch::Approach).to_bits()
                );
            }
        }
    }
}

#[test]
fn load_near_batch_is_load_bit_for_bit() {
    let s = RoughSurface::gold_microswitch();
    let (t, e) = (table(), exact());
    let (lo, hi) = (e.cutoff_interference(), 40.0 * s.sigma);
    let laws: [&dyn LawKernels; 2] = [&t, e.as_ref()];
    for law in laws {
        // Batches of every length up to 3 lanes' worth, ascending (a
        // quadrature panel), shuffled, and reaching beyond both ends.
        for n in [1, 5, 8, 9, 21, 24] {
            for shuffled in [false, true] {
                let x: Vec<f64> = (0..n)
                    .map(|i| {
                        let k = if shuffled { i * 7 % n } else { i };
                        (k as f64 + 0.5) / n as f64
                    })
                    .collect();
                let d: Vec<f64> = x
                    .iter()
                    .map(|x| lo - 0.1 * (hi - lo) + 1.2 * (hi - lo) * x)
                    .collect();
                // Both branches on retraction: a maximum either side of attach.
                let dm: Vec<f64> = d
                    .iter()
                    .enumerate()
                    .map(|(i, &d)| if i % 3 == 0 { d } else { d + 0.3 * (hi - lo) })
                    .collect();
                let mut cursor = LawCursor { panels: [n; 2] };
                let mut got = vec![f64::NAN; n];
                law.load_near_batch(&d, None, &mut got, &mut cursor);
                for (g, &d) in got.iter().zip(&d) {
                    assert_eq!(g.to_bits(), law.load(d, Branch::Approach).to_bits());
                }
                law.load_near_batch(&d, Some(&dm), &mut got, &mut cursor);
                for ((g, &d), &m) in got.iter().zip(&d).zip(&dm) {
                    assert_eq!(g.to_bits(), law.load_after(d, m).to_bits());
                }
            }
        }
    }
}
