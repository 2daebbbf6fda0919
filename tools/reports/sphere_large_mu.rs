//! The large-mu table of docs/performance.md: `SphereProblem::facts` (paraboloid)
//! at each Tabor parameter and resolution, one markdown row each, against
//! JKR's -1.5, -5/6, -0.9086, 6^(1/3):
//! `cargo run --release --example sphere_large_mu -- --res 1,2,4 10 30 100`.
//! With `--raw`, one line of tests/data/sphere_converged.raw per run instead
//! (`--res 4,8 --raw 10 30 100` makes the large-mu references).
use asperity::sphere::{Shape, SolverOptions, SphereProblem};
use std::time::Instant;

fn main() {
    let mut res = vec![1.0];
    let mut mus = vec![];
    let mut raw = false;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if a == "--raw" {
            raw = true;
        } else if a == "--res" {
            let list = args.next().expect("--res 1,2,4");
            res = list
                .split(',')
                .map(|x| x.parse().expect("resolution"))
                .collect();
        } else {
            mus.push(a.parse::<f64>().expect("mu"));
        }
    }
    if mus.is_empty() {
        mus = vec![10.0, 15.0, 20.0, 30.0, 50.0, 70.0, 100.0];
    }
    if !raw {
        println!("| mu | resolution | nodes | time (s) | pull-off | jump-out load | jump-out Dbar | A at zero load |");
        println!("|---|---|---|---|---|---|---|---|");
    }
    for &mu in &mus {
        for &r in &res {
            let o = {
                let mut o = SolverOptions::default();
                o.resolution = r;
                o
            };
            let p = SphereProblem::new(mu, Shape::Paraboloid, o).unwrap();
            let t = Instant::now();
            match p.facts() {
                Ok(f) if raw => println!(
                    "{{\"case\":\"{mu}\",\"resolution\":{r},\"facts\":{{\"mu\":{mu:?},\"rho\":null,\
                     \"pull_off_load_control\":{:?},\"jump_out_load\":{:?},\
                     \"jump_out_interference\":{:?},\"contact_radius_zero_load\":{:?},\"nodes\":{}}}}}",
                    f.pull_off.load_bar,
                    f.jump_out.map_or(f64::NAN, |j| j.load_bar),
                    f.jump_out.map_or(f64::NAN, |j| j.interference_bar),
                    f.zero_load_radius_bar.unwrap_or(f64::NAN),
                    f.nodes
                ),
                Ok(f) => {
                    let jo = f.jump_out.unwrap_or(f.pull_off);
                    println!(
                        "| {mu} | {r} | {} | {:.3} | {:.6} | {:.6} | {:.6} | {:.6} |",
                        f.nodes,
                        t.elapsed().as_secs_f64(),
                        f.pull_off.load_bar,
                        jo.load_bar,
                        jo.interference_bar,
                        f.zero_load_radius_bar.unwrap_or(f64::NAN)
                    );
                }
                Err(e) => println!("| {mu} | {r} | error: {e} |"),
            }
        }
    }
    if !raw {
        println!(
            "| JKR | | | | -1.5 | -0.833333 | -0.908560 | {:.6} |",
            6f64.cbrt()
        );
    }
}
