//! Run time against error of every Greenwood–Williamson method, single
//! thread, written into `docs/performance.md` between the markers
//! `<!-- gw-report:start -->` and `<!-- gw-report:end -->`.
//!
//! `cargo run --release --example gw_report`
//!
//! Two studies on the default gold microswitch surface (eta = 1e12 m^-2,
//! R = 1 um, sigma = 5 nm, 100 um x 100 um, Gaussian heights):
//! 1. Hertz asperities, a 1000-point approach curve (load, area, count)
//!    from d = 6 sigma down to d = -3 sigma. Reference: the closed forms
//!    (F_n to ~1e-15 against mpmath, tests/it/gaussian_fn.rs).
//! 2. Maugis–Dugdale asperities at lambda = 1 (z0 chosen so), approach to
//!    d = 0 and retraction, 1000 points per leg, load only. Reference:
//!    adaptive quadrature of the exact law at rtol 1e-12 (its own error
//!    estimates are below 1e-12 of the curve's scale).
//!
//! Error = max over the curve of |value - reference| / max |reference|
//! (per output; the worst output is reported). Time = median of repeated
//! runs, each a whole curve.

use asperity::gw::{Accuracy, GwModel, Method, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::interpolated::InterpolatedLaw;
use asperity::law::{Hertz, LawKernels, Maugis};
use asperity::loading::{Curve, History, LoadingModel, LoadingProgram, Observables};
use asperity::material::{contact_modulus, Material};
use std::fmt::Write as _;
use std::sync::Arc;
use std::time::Instant;

const POINTS: usize = 1000;

/// Median seconds of `f` over enough repeats to fill ~0.3 s (3 to 50).
fn time<T>(mut f: impl FnMut() -> T) -> (f64, T) {
    let mut times = Vec::new();
    let t_all = Instant::now();
    let mut last;
    loop {
        let t0 = Instant::now();
        last = f();
        times.push(t0.elapsed().as_secs_f64());
        if times.len() >= 50 || (times.len() >= 3 && t_all.elapsed().as_secs_f64() > 0.3) {
            break;
        }
    }
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], last)
}

/// Per-output values of a curve: both legs, in order.
fn values(c: &Curve, outputs: Observables) -> Vec<Vec<f64>> {
    let legs = || c.approach.iter().chain(c.retract.iter());
    let mut v = Vec::new();
    if outputs.load {
        v.push(legs().map(|s| s.load().unwrap()).collect());
    }
    if outputs.area {
        v.push(legs().map(|s| s.area().unwrap()).collect());
    }
    if outputs.count {
        v.push(legs().map(|s| s.count().unwrap()).collect());
    }
    v
}

fn error(got: &[Vec<f64>], reference: &[Vec<f64>]) -> f64 {
    got.iter()
        .zip(reference)
        .map(|(g, r)| {
            let scale = r.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            g.iter()
                .zip(r)
                .map(|(a, b)| (a - b).abs() / scale)
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

fn row(out: &mut String, method: &str, secs: f64, err: f64, evals: usize) {
    let _ = writeln!(
        out,
        "| {method} | {:.3} | {} | {} |",
        secs * 1e3,
        if err == 0.0 {
            "reference".to_string()
        } else {
            format!("{err:.1e}")
        },
        evals
    );
}

fn evaluations(c: &Curve) -> usize {
    c.approach
        .iter()
        .chain(&c.retract)
        .map(|s| s.evaluations)
        .sum()
}

fn main() {
    let surface = RoughSurface::gold_microswitch();
    let gold = Material::gold();
    let es = contact_modulus(&gold, &gold);
    let gauss = Arc::new(Gaussian::new());
    let sigma = surface.sigma;
    let mut md = String::new();

    // 1. Hertz, approach only (the retraction leg equals it).
    let hertz: Arc<dyn LawKernels> = Arc::new(Hertz::new(surface.radius, es).unwrap());
    let model = GwModel::new(surface, gauss.clone(), hertz).unwrap();
    let program = LoadingProgram::new(6.0 * sigma, -3.0 * sigma, POINTS).unwrap();
    let approach_only = |acc: &Accuracy| {
        let seps = program.separations();
        let model = model.clone().with_accuracy(*acc);
        let states: Vec<_> = seps
            .iter()
            .map(|&d| {
                model
                    .state(d, History::Approach, &Observables::ALL)
                    .unwrap()
            })
            .collect();
        Curve {
            program,
            approach: states,
            retract: Vec::new(),
        }
    };
    let closed = Accuracy::new(1e-12)
        .unwrap()
        .with_method(Method::ClosedForm);
    let (t, reference) = time(|| approach_only(&closed));
    let reference = values(&reference, Observables::ALL);
    let _ = writeln!(
        md,
        "### Hertz asperities, Gaussian heights: {POINTS}-point curve (load, area, count)\n"
    );
    let _ = writeln!(
        md,
        "| method | ms per curve | max error | law evaluations |\n|---|---|---|---|"
    );
    row(&mut md, "closed forms F_n", t, 0.0, 0);
    for tol in [1e-3, 1e-6, 1e-9, 1e-12] {
        let acc = Accuracy::new(tol).unwrap().with_method(Method::Quadrature);
        let (t, c) = time(|| approach_only(&acc));
        row(
            &mut md,
            &format!("adaptive Gauss–Kronrod, rtol {tol:e}"),
            t,
            error(&values(&c, Observables::ALL), &reference),
            evaluations(&c),
        );
    }
    for panels in [1, 2, 4, 8, 16] {
        let acc = Accuracy::new(1e-12)
            .unwrap()
            .with_method(Method::Fixed { panels });
        let (t, c) = time(|| approach_only(&acc));
        row(
            &mut md,
            &format!("fixed K21, {panels} panel(s) per piece"),
            t,
            error(&values(&c, Observables::ALL), &reference),
            evaluations(&c),
        );
    }

    // 2. Maugis–Dugdale at lambda = 1: approach and retraction.
    let lambda = 1.0;
    let w = 0.5;
    let exact: Arc<dyn LawKernels> = Arc::new(Maugis::new(surface.radius, es, w, lambda).unwrap());
    let program = LoadingProgram::new(6.0 * sigma, 0.0, POINTS).unwrap();
    let curve_of = |law: Arc<dyn LawKernels>, acc: &Accuracy| {
        GwModel::new(surface, gauss.clone(), law)
            .unwrap()
            .with_accuracy(*acc)
            .curve(&program, &Observables::LOAD)
            .unwrap()
    };
    let t0 = Instant::now();
    let reference = values(
        &curve_of(exact.clone(), &Accuracy::new(1e-12).unwrap()),
        Observables::LOAD,
    );
    eprintln!("MD reference: {:.1} s", t0.elapsed().as_secs_f64());
    let _ = writeln!(
        md,
        "\n### Maugis–Dugdale asperities (lambda = 1), Gaussian heights: approach + retraction, {POINTS} points per leg (load)\n"
    );
    let _ = writeln!(
        md,
        "| method | ms per curve | max error | law evaluations |\n|---|---|---|---|"
    );
    for tol in [1e-4, 1e-6, 1e-8] {
        let acc = Accuracy::new(tol).unwrap().with_method(Method::Quadrature);
        let (t, c) = time(|| curve_of(exact.clone(), &acc));
        row(
            &mut md,
            &format!("exact law, adaptive, rtol {tol:e}"),
            t,
            error(&values(&c, Observables::LOAD), &reference),
            evaluations(&c),
        );
    }
    for panels in [1, 4, 16] {
        let acc = Accuracy::new(1e-12)
            .unwrap()
            .with_method(Method::Fixed { panels });
        let (t, c) = time(|| curve_of(exact.clone(), &acc));
        row(
            &mut md,
            &format!("exact law, fixed K21, {panels} panel(s) per piece"),
            t,
            error(&values(&c, Observables::LOAD), &reference),
            evaluations(&c),
        );
    }
    let lo = exact.cutoff_interference();
    let hi = 40.0 * sigma;
    for rtol in [1e-4, 1e-6, 1e-8, 1e-10] {
        let acc = Accuracy::new(rtol).unwrap().with_method(Method::Quadrature);
        let (t, (c, panels)) = time(|| {
            let table = InterpolatedLaw::new(exact.clone(), lo, hi, rtol / 10.0).unwrap();
            let panels = table.panels();
            (curve_of(Arc::new(table), &acc), panels)
        });
        row(
            &mut md,
            &format!(
                "Chebyshev table to rtol/10 ({} + {} panels, build included), adaptive rtol {rtol:e}",
                panels.0, panels.1
            ),
            t,
            error(&values(&c, Observables::LOAD), &reference),
            evaluations(&c),
        );
    }
    let _ = writeln!(
        md,
        "\nThe planner (`asperity run`) uses closed forms where they exist, and for Maugis–Dugdale \
         the Chebyshev table to rtol/10 with adaptive quadrature at rtol."
    );

    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/performance.md");
    let doc = std::fs::read_to_string(path).unwrap_or_default();
    let (start, end) = ("<!-- gw-report:start -->", "<!-- gw-report:end -->");
    let section = format!(
        "{start}\n## Greenwood–Williamson integration: run time against error\n\n\
         Regenerate: `cargo run --release --example gw_report` (single thread; default gold \
         surface; error = max |value - reference| / max |reference| over the curve).\n\n{md}{end}"
    );
    let new = match (doc.find(start), doc.find(end)) {
        (Some(a), Some(b)) => format!("{}{section}{}", &doc[..a], &doc[b + end.len()..]),
        _ => format!("{}\n{section}\n", doc.trim_end()),
    };
    std::fs::write(path, new).unwrap();
    println!("{md}");
}
