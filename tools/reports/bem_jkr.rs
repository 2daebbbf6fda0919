//! JKR check of the adhesive boundary-element solver: a sphere of radius
//! R = 1 in a periodic unit cell (E* = 1), exponential adhesion of work `w`
//! and range `rho`, stepped in mean gap from `zero-load gap + G0` by `DG`
//! (`COUNT` states, warm-started). Prints, per state, the mean pressure P
//! (= the force on the unit cell), the contact radius from the contact pixels
//! `a = sqrt(n/pi) dx`, JKR's force at that radius
//! `P_JKR(a) = 4 E* a^3/(3R) - sqrt(8 pi w E* a^3)` and the difference in units
//! of the JKR pull-off `1.5 pi w R`; then the smallest P against `-1.5 pi w R`.
//!
//! ```text
//! cargo run --release --example bem_jkr -- N RHO W G0 DG COUNT
//! cargo run --release --example bem_jkr -- 1024 1.868e-3 5.66e-4 -0.004 0.0008 8
//! ```
//! (`a0 = 0.2`, Maugis `lambda = 2 (w/rho) (R/(pi w K^2))^(1/3) = 4.1`, `K = 4E*/3`.)
use asperity::bem::{Options, Problem};
use asperity::surface::HeightMap;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args[1].parse().unwrap();
    let rho: f64 = args[2].parse().unwrap();
    let w: f64 = args[3].parse().unwrap();
    let dx = 1.0 / n as f64;
    let h: Vec<f64> = (0..n * n)
        .map(|k| {
            let (i, j) = (
                (k / n) as f64 - n as f64 / 2.0,
                (k % n) as f64 - n as f64 / 2.0,
            );
            -(i * i + j * j) * dx * dx / 2.0
        })
        .collect();
    let map = HeightMap::new(n, n, h).unwrap();
    let opts = Options {
        tolerance: 1e-9,
        ..Default::default()
    };
    let prob = Problem::new(&map, dx, 1.0, true, &opts)
        .unwrap()
        .with_adhesion(w, rho)
        .unwrap();
    let pi = std::f64::consts::PI;
    let a0 = (9.0 * pi * w / 2.0f64).powf(1.0 / 3.0);
    println!("a0 JKR = {a0}, a0/dx = {}", a0 / dx);
    let mut warm = None;
    let zero = prob.zero_load_gap();
    let (g0, dg, cnt): (f64, f64, usize) = (
        args[4].parse().unwrap(),
        args[5].parse().unwrap(),
        args[6].parse().unwrap(),
    );
    let mut pmin = 0.0f64;
    for k in 0..cnt {
        let g = zero + g0 + dg * k as f64;
        let t = std::time::Instant::now();
        let s = match prob.solve_gap(g, &opts, warm.as_ref()) {
            Ok(s) => s,
            Err(e) => {
                println!("{e}");
                break;
            }
        };
        let a = (s.contact_pixels as f64 / pi).sqrt() * dx;
        let p = s.mean_pressure; // L = 1
        let pj = 4.0 * a.powi(3) / 3.0 - (8.0 * pi * w * a.powi(3)).sqrt();
        println!(
            "gap {g:.5}: P {p:.5e} a {a:.5} (px {:.1}) P_JKR(a) {pj:.5e} dP/Pc {:.4} it {} {:.2}s",
            a / dx,
            (p - pj) / (1.5 * pi * w),
            s.iterations,
            t.elapsed().as_secs_f64()
        );
        pmin = pmin.min(p);
        warm = Some(s);
    }
    println!(
        "pull-off {pmin:.5e} / JKR {:.5e} = {:.4}",
        -1.5 * pi * w,
        pmin / (-1.5 * pi * w)
    );
}
