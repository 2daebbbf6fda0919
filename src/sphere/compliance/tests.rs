use super::*;

#[derive(serde::Deserialize)]
struct Ring {
    r: f64,
    s: f64,
    d: String,
}

#[derive(serde::Deserialize)]
struct Data {
    mesh: Vec<f64>,
    c: Vec<Vec<String>>,
    ring: Vec<Ring>,
}

fn data() -> Data {
    serde_json::from_str(include_str!("../../../tests/data/compliance.json")).unwrap()
}

/// Entries against mpmath's tanh-sinh quadrature (30 digits) on a
/// non-uniform mesh with neighbours 0.05 apart next to intervals 0.7 long:
/// the analytic log split must give ~1e-15; 1e-13 of the row scale allows
/// for cancellation in `right - left`.
#[test]
fn matrix_matches_mpmath() {
    let d = data();
    let n = d.mesh.len();
    let c = compliance_matrix(&d.mesh);
    let mut worst = 0.0f64;
    for i in 0..n {
        let scale = d.c[i]
            .iter()
            .map(|x| x.parse::<f64>().unwrap().abs())
            .fold(0.0, f64::max);
        for j in 0..n {
            let expect: f64 = d.c[i][j].parse().unwrap();
            let err = (c[i * n + j] - expect).abs() / scale;
            worst = worst.max(err);
            assert!(err < 1e-13, "C[{i}][{j}] = {} vs {expect}", c[i * n + j]);
        }
    }
    eprintln!("worst relative entry error {worst:e}");
}

/// The closed-form disc displacement against direct quadrature of the ring
/// Green's function of physics.md (mpmath).
#[test]
fn disc_matches_ring_green_function() {
    for ring in data().ring {
        let expect: f64 = ring.d.parse().unwrap();
        let got = disc(ring.r, ring.s);
        assert!(
            (got - expect).abs() < 1e-13 * expect,
            "{} {}",
            ring.r,
            ring.s
        );
    }
    // Continuity at r = s: both branches give 4 s/pi.
    let s = 0.7;
    assert!((disc(s, s) - 4.0 * s / PI).abs() < 1e-15);
    assert!((disc(s * (1.0 + 1e-12), s) - disc(s, s)).abs() < 1e-10);
}

/// A pressure of 1 at every node is a uniform disc of the outer radius:
/// the rows telescope to `D(r_i, r_last)`.
#[test]
fn uniform_pressure_is_a_disc() {
    let r: Vec<f64> = (0..30).map(|k| (k as f64 / 29.0).powf(1.5) * 2.0).collect();
    let n = r.len();
    let c = compliance_matrix(&r);
    for i in 0..n {
        let u: f64 = c[i * n..(i + 1) * n].iter().sum();
        let d = disc(r[i], r[n - 1]);
        assert!((u - d).abs() < 1e-13 * d.max(1.0), "{i}: {u} vs {d}");
    }
}

/// Hertz pressure `p = sqrt(1 - r^2/a^2)` displaces the contact by
/// `u = pi (2 a^2 - r^2)/(4 a)` (Johnson eq. 3.41). The piecewise-linear
/// interpolation of the square-root edge converges like `h^(3/2)`: on a mesh
/// graded towards `a` the error must fall with refinement and be < 2e-4.
#[test]
fn hertz_pressure_gives_hertz_displacement() {
    let a = 1.3;
    let mut errs = vec![];
    for n in [40usize, 160] {
        // nodes r = a (1 - (1 - t)^2) inside, then outwards
        let mut r: Vec<f64> = (0..=n)
            .map(|k| {
                let t = k as f64 / n as f64;
                a * (1.0 - (1.0 - t).powi(2))
            })
            .collect();
        r.extend((1..=n / 4).map(|k| a + 0.02 * a * k as f64));
        let m = r.len();
        let c = compliance_matrix(&r);
        let p: Vec<f64> = r
            .iter()
            .map(|&x| (1.0 - (x / a).powi(2)).max(0.0).sqrt())
            .collect();
        let mut worst = 0.0f64;
        for i in 0..m {
            if r[i] > a {
                continue;
            }
            let u: f64 = (0..m).map(|j| c[i * m + j] * p[j]).sum();
            let exact = PI * (2.0 * a * a - r[i] * r[i]) / (4.0 * a);
            worst = worst.max((u - exact).abs() / exact);
        }
        errs.push(worst);
    }
    assert!(errs[1] < errs[0] / 3.0, "{errs:?}");
    assert!(errs[1] < 2e-4, "{errs:?}");
}

#[test]
fn load_weights_integrate_linear_pressure_exactly() {
    // p = 1 - r/2 on [0, 2]: int p r dr = 2 - 8/6 = 2/3
    let r = [0.0, 0.3, 0.35, 1.0, 1.7, 2.0];
    let w = load_weights(&r);
    let s: f64 = r.iter().zip(&w).map(|(x, w)| w * (1.0 - x / 2.0)).sum();
    assert!((s - 2.0 / 3.0).abs() < 1e-15);
}

/// The four-radius disc gives the one-radius bits on both branches, at the
/// centre, at `s = r` and where the elliptic integrals switch method.
#[test]
fn disc_lanes_are_the_scalar_bits() {
    let r = 1.3;
    let mut s: Vec<f64> = vec![0.0, -1.0, r, r * (1.0 - 0.1f64).sqrt(), 1e-9, 1e3];
    s.extend((0..398).map(|i| 0.013 * i as f64));
    for chunk in s.chunks(4).filter(|c| c.len() == 4) {
        let four: [f64; 4] = chunk.try_into().unwrap();
        for (got, &si) in disc_lanes(r, &four).iter().zip(&four) {
            assert_eq!(got.to_bits(), disc(r, si).to_bits(), "s = {si}");
        }
    }
}
