//! Grid bias of measured summit statistics on synthetic isotropic Gaussian
//! surfaces (Gaussian autocorrelation of length `l` pixels, `alpha = 3`),
//! against Nayak's continuum predictions from the known spectrum.
//!
//! For each `l`, `SEEDS` periodic maps of `n x n` pixels (`n` grows with `l`
//! so that each map holds about 6000 summits or more) are characterised with
//! `--periodic` rules. Each ratio is measured / predicted, averaged over the
//! seeds, with its standard error `sd / sqrt(seeds)` from the seed-to-seed
//! scatter (the maps are independent; summits within one map are not).
//!
//! Run: `cargo run --release --example surface_bias` (prints the markdown
//! table of `docs/surface.md`).

use asperity::surface::synthetic::GaussianSurface;
use asperity::surface::{GwParameters, NayakPrediction, Topography};

const SEEDS: u64 = 8;

fn mean_se(v: &[f64]) -> (f64, f64) {
    let n = v.len() as f64;
    let m = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0);
    (m, (var / n).sqrt())
}

/// The table's header and delimiter rows.
pub const HEADER: &str = "| l (px) | map | summits/map | m2 FD/cont. | m4 FD/cont. | density | mean curvature | mean height | height std | density / GW from FD moments |\n|---|---|---|---|---|---|---|---|---|---|";

/// The correlation lengths of the table's rows (pixels).
pub const LENGTHS: [f64; 8] = [1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0];

/// The table's row at correlation length `l` pixels: `SEEDS` maps of
/// `n x n` pixels, `n = 256 l` within [1024, 4096].
pub fn row(l: f64) -> asperity::Result<String> {
    let dx = 1e-7;
    let n = ((256.0 * l) as usize).clamp(1024, 4096);
    let mut cols: Vec<Vec<f64>> = vec![Vec::new(); 7];
    let mut count = 0.0;
    for seed in 0..SEEDS {
        let spec = GaussianSurface::new(n, n, l, 1e-9, dx, seed)?;
        let cont = spec.continuum_moments();
        let pred = NayakPrediction::from_moments(&cont);
        let c = Topography::new(spec.generate(), dx)?.characterise(true)?;
        let s = &c.stats;
        let fd = GwParameters::from_moments(&c.moments);
        count += s.count as f64 / SEEDS as f64;
        let ratios = [
            c.moments.m2 / cont.m2,
            c.moments.m4 / cont.m4,
            s.density_per_m2 / pred.density_per_m2,
            s.mean_curvature_per_m.unwrap_or(f64::NAN) / pred.mean_curvature_per_m,
            s.mean_height_m.unwrap_or(f64::NAN) / pred.mean_height_m,
            s.height_std_m.unwrap_or(f64::NAN) / pred.height_std_m,
            s.density_per_m2 / fd.density_per_m2,
        ];
        for (col, v) in cols.iter_mut().zip(ratios) {
            col.push(v);
        }
    }
    let cells: Vec<String> = cols
        .iter()
        .map(|v| {
            let (m, se) = mean_se(v);
            format!("{m:.4} ± {se:.4}")
        })
        .collect();
    Ok(format!(
        "| {l} | {n}² | {count:.0} | {} |",
        cells.join(" | ")
    ))
}

#[allow(dead_code)] // the tests use `row` alone
fn main() -> asperity::Result<()> {
    println!("{HEADER}");
    for l in LENGTHS {
        println!("{}", row(l)?);
    }
    Ok(())
}
