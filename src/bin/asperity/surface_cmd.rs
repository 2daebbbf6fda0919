//! `asperity surface`: characterise a measured height map (moments,
//! summits, GW parameters from the moments, plasticity index), computed by
//! [`asperity::commands::surface`].

use crate::CliError;
pub use asperity::commands::surface::SurfaceArgs;
use asperity::commands::surface::SurfaceJson;

pub fn run(args: &SurfaceArgs) -> crate::CliResult {
    let out = asperity::commands::surface::run(args)?;
    if args.json {
        let json = serde_json::to_string(&out).map_err(|e| CliError::Failed(e.to_string()))?;
        println!("{json}");
    } else {
        print_table(&out);
    }
    Ok(())
}

fn print_table(o: &SurfaceJson) {
    let opt = |x: Option<f64>| x.map_or("none".to_string(), |v| format!("{v:.6e}"));
    println!("map                        {} x {} pixels", o.rows, o.cols);
    println!("rms height                 {:.6e} m", o.rms_height_m);
    println!(
        "m0, m2, m4                 {:.6e} m^2, {:.6e}, {:.6e} 1/m^2",
        o.m0, o.m2, o.m4
    );
    println!(
        "rms slope (profile)        {:.6e}  = sqrt(m2); surface rms gradient sqrt(2 m2) = {:.6e}",
        o.rms_slope, o.rms_gradient
    );
    println!(
        "rms curvature (profile)    {:.6e} 1/m = sqrt(m4)",
        o.rms_curvature_per_m
    );
    println!("bandwidth alpha            {:.6}", o.bandwidth_alpha);
    let s = &o.summits;
    println!("summits                    {}", s.count);
    println!("  density                  {:.6e} 1/m^2", s.density_per_m2);
    println!(
        "  mean curvature           {} 1/m",
        opt(s.mean_curvature_per_m)
    );
    println!("  radius                   {} m", opt(s.radius_m));
    println!(
        "  height std, mean         {} m, {} m",
        opt(s.height_std_m),
        opt(s.mean_height_m)
    );
    let g = &o.gw_from_moments;
    println!(
        "GW from moments            eta {:.6e} 1/m^2, R {:.6e} m, sigma {} m",
        g.density_per_m2,
        g.radius_m,
        opt(g.sigma_m)
    );
    println!(
        "plasticity index           {}",
        o.plasticity_index
            .map_or("none (give --estar and --hardness)".into(), |p| format!(
                "{p:.6}"
            ))
    );
}
