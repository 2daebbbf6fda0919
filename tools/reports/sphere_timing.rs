//! Times `SphereProblem::facts` for the Tabor parameters given on the command
//! line (default 1 5 10): `cargo run --release --example sphere_timing -- 1 10 30`.
use asperity::sphere::{Shape, SolverOptions, SphereProblem};
use std::time::Instant;

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let mus = if args.is_empty() {
        vec![1.0, 5.0, 10.0]
    } else {
        args
    };
    let res: f64 = std::env::var("RES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1.0);
    for mu in mus {
        let o = {
            let mut o = SolverOptions::default();
            o.resolution = res;
            o
        };
        let p = SphereProblem::new(mu, Shape::Paraboloid, o).unwrap();
        let t = Instant::now();
        match p.facts() {
            Ok(f) => println!(
                "mu {mu}: pull-off {:.6} jump-out {:?} A0 {:?} nodes {} in {:.3} s",
                f.pull_off.load_bar,
                f.jump_out.map(|j| (j.load_bar, j.interference_bar)),
                f.zero_load_radius_bar,
                f.nodes,
                t.elapsed().as_secs_f64()
            ),
            Err(e) => println!(
                "mu {mu}: error {e} after {:.3} s",
                t.elapsed().as_secs_f64()
            ),
        }
    }
}
