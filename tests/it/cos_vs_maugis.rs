//! COS (a0, Pc from exact MD) against exact Maugis–Dugdale: the error table
//! of docs/performance.md ("COS against exact Maugis–Dugdale"), with
//! asserted bounds. Print it with
//! `cargo test --test cos_vs_maugis -- --nocapture`.
use asperity::law::cos::CosCurve;
use asperity::law::maugis::MaugisCurve;

struct Row {
    lambda: f64,
    alpha: f64,
    /// Radius error at the pull-off Pc (absolute, units of the radius
    /// scale: the MD radius there tends to 0 as lambda -> 0), then relative
    /// at loads -|Pc|/2, |Pc|, 10 |Pc|.
    radius: [f64; 4],
    /// Interference error (units of the interference scale) at P = 0, |Pc|.
    interference: [f64; 2],
    /// Displacement-controlled jump-out load error (units of pi w R).
    jump_out_load: f64,
}

fn row(lambda: f64) -> Row {
    let md = MaugisCurve::new(lambda).unwrap();
    let cos = CosCurve::new(lambda).unwrap();
    let pc = md.pull_off_bar().load_bar;
    let mut radius = [0.0; 4];
    for (k, f) in [1.0, 0.5, -1.0, -10.0].into_iter().enumerate() {
        let p = f * pc;
        let exact = if k == 0 {
            md.pull_off_bar().radius_bar
        } else {
            md.point_at_load(p).unwrap().radius_bar
        };
        let fit = cos.radius_at_load(p).unwrap();
        radius[k] = if k == 0 {
            fit - exact
        } else {
            (fit - exact) / exact
        };
    }
    let mut interference = [0.0; 2];
    for (k, p) in [0.0, -pc].into_iter().enumerate() {
        let exact = md.point_at_load(p).unwrap().interference_bar;
        let fit = cos.interference_at_radius(cos.radius_at_load(p).unwrap());
        interference[k] = fit - exact;
    }
    let j = cos.jump_out_radius_bar();
    Row {
        lambda,
        alpha: cos.alpha(),
        radius,
        interference,
        jump_out_load: cos.load_at_radius(j) - md.jump_out_bar().load_bar,
    }
}

#[test]
fn cos_error_table_against_exact_md() {
    let lambdas = [0.01, 0.1, 0.3, 1.0, 3.0, 10.0, 100.0];
    println!("| lambda | alpha | A at pull-off (abs.) | a at P = Pc/2 | a at P = -Pc | a at P = -10 Pc | Dbar at P = 0 (abs.) | Dbar at P = -Pc (abs.) | jump-out Pbar (abs.) |");
    println!("|---|---|---|---|---|---|---|---|---|");
    let rows: Vec<Row> = lambdas.iter().map(|&l| row(l)).collect();
    for r in &rows {
        println!(
            "| {} | {:.4} | {:+.3} | {:+.2}% | {:+.2}% | {:+.2}% | {:+.3} | {:+.3} | {:+.3} |",
            r.lambda,
            r.alpha,
            r.radius[0],
            100.0 * r.radius[1],
            100.0 * r.radius[2],
            100.0 * r.radius[3],
            r.interference[0],
            r.interference[1],
            r.jump_out_load
        );
    }
    // Bounds: the measured errors (see the table) with a margin; the point
    // is to notice if either law changes, not to bless the fit.
    for r in &rows {
        let worst_radius = r.radius[1..].iter().fold(0.0f64, |m, e| m.max(e.abs()));
        assert!(
            worst_radius < 0.01,
            "lambda {}: radius error {worst_radius}",
            r.lambda
        );
        assert!(
            r.radius[0].abs() < 0.1,
            "lambda {}: {}",
            r.lambda,
            r.radius[0]
        );
        assert!(
            r.interference.iter().all(|e| e.abs() < 0.35),
            "lambda {}",
            r.lambda
        );
        // COS has no non-contact branch: it snaps from contact, MD (for
        // lambda < 0.938) from its Dugdale zone, so this error is O(1) at
        // small lambda and small only in the JKR regime.
        assert!(r.jump_out_load.abs() < 2.0);
        if r.lambda >= 3.0 {
            assert!(r.jump_out_load.abs() < 0.1, "lambda {}", r.lambda);
        }
    }
    // Exact at the ends where COS coincides with its limit: DMT-like small
    // lambda and JKR-like large lambda are both within 1% in radius.
    assert!(rows[0].radius[1..].iter().all(|e| e.abs() < 0.01));
    assert!(rows[6].radius[1..].iter().all(|e| e.abs() < 0.01));
}
