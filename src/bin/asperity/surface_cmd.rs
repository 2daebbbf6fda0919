//! `asperity surface`: characterise a measured height map (moments,
//! summits, GW parameters from the moments, plasticity index), computed by
//! [`asperity::commands::surface`].

use crate::CliError;
use asperity::commands::measured::unit_warnings;
use asperity::commands::surface::{
    characterise, map_name, write_outputs, SurfaceInput, SurfaceJson,
};
use asperity::commands::Vocabulary;
use clap::Args;
use std::path::PathBuf;

/// Arguments of `asperity surface`.
#[derive(Args, Debug)]
pub struct SurfaceArgs {
    /// The height map: an instrument file (`.x3p`, `.sdf`, `.gwy`, `.sur`,
    /// `.di`/`.spm`/`.001`, `.ibw`, `.opd`, `.opdx`, `.nc`, `.frt`, `.plux`: heights,
    /// pixel sizes and unit from the file), NumPy `.npy` (2-D float64/float32,
    /// C order) or a text matrix (`.txt`, `.csv`, `.asc`).
    file: PathBuf,
    #[command(flatten)]
    read: crate::map_read::MapArgs,
    /// Treat the map as periodic: remove only the mean, wrap differences and
    /// summit neighbours around every edge (also when the file says so).
    #[arg(long)]
    periodic: bool,
    /// Contact modulus E* (Pa), with --hardness for the plasticity index.
    #[arg(long, allow_hyphen_values = true)]
    estar: Option<f64>,
    /// Hardness H (Pa), with --estar for the plasticity index.
    #[arg(long, allow_hyphen_values = true)]
    hardness: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
    /// Also write `surface.json`, `summit_heights.svg` and `summit_map.svg`
    /// into this directory.
    #[arg(long)]
    out: Option<PathBuf>,
}

pub fn run(args: &SurfaceArgs) -> crate::CliResult {
    // The map's content is named by its file (and the scale).
    let words = Vocabulary::cli().with("heights", map_name(&args.file, args.read.scale));
    let failed = |e| CliError::with(e, &words);
    let (read, pixels, mut warnings) =
        crate::map_read::read_map(&args.file, &args.read).map_err(failed)?;
    let input = SurfaceInput {
        pixel_size: pixels.0,
        pixel_size_y: Some(pixels.1),
        periodic: args.periodic || read.periodic,
        estar: args.estar,
        hardness: args.hardness,
    };
    let source = read.source(pixels);
    let (mut out, c) = characterise(read.map, &input).map_err(failed)?;
    out.source = Some(source);
    warnings.extend(
        unit_warnings(out.rms_height_m, pixels)
            .iter()
            .map(ToString::to_string),
    );
    warnings.extend(std::mem::take(&mut out.warnings));
    out.warnings = warnings.iter().map(|w| words.words_in(w)).collect();
    if let Some(dir) = &args.out {
        write_outputs(dir, &out, &c).map_err(failed)?;
    }
    if args.json {
        crate::outln!("{}", asperity::commands::json_line(&out)?);
    } else {
        print_table(&out)?;
    }
    Ok(())
}

fn print_table(o: &SurfaceJson) -> crate::CliResult {
    let opt = |x: Option<f64>| x.map_or("none".to_string(), |v| format!("{v:.6e}"));
    crate::outln!("map                        {} x {} pixels", o.rows, o.cols);
    if let Some(s) = &o.source {
        crate::outln!(
            "source                     {} channel '{}' (unit {}), pixels {:.6e} x {:.6e} m, {} missing",
            s.format,
            s.channel,
            if s.unit.is_empty() { "none" } else { &s.unit },
            s.pixel_size_m[0],
            s.pixel_size_m[1],
            s.missing
        );
    }
    crate::outln!("rms height                 {:.6e} m", o.rms_height_m);
    crate::outln!(
        "m0, m2, m4                 {:.6e} m^2, {:.6e}, {:.6e} 1/m^2",
        o.m0,
        o.m2,
        o.m4
    );
    crate::outln!(
        "rms slope (profile)        {:.6e}  = sqrt(m2); surface rms gradient sqrt(2 m2) = {:.6e}",
        o.rms_slope,
        o.rms_gradient
    );
    crate::outln!(
        "rms curvature (profile)    {:.6e} 1/m = sqrt(m4)",
        o.rms_curvature_per_m
    );
    crate::outln!("bandwidth alpha            {:.6}", o.bandwidth_alpha);
    let s = &o.summits;
    crate::outln!("summits                    {}", s.count);
    crate::outln!("  density                  {:.6e} 1/m^2", s.density_per_m2);
    crate::outln!(
        "  mean curvature           {} 1/m",
        opt(s.mean_curvature_per_m)
    );
    crate::outln!("  radius                   {} m", opt(s.radius_m));
    crate::outln!(
        "  height std, mean         {} m, {} m",
        opt(s.height_std_m),
        opt(s.mean_height_m)
    );
    let g = &o.gw_from_moments;
    crate::outln!(
        "GW from moments            eta {:.6e} 1/m^2, R {:.6e} m, sigma {} m",
        g.density_per_m2,
        g.radius_m,
        opt(g.sigma_m)
    );
    crate::outln!(
        "plasticity index           {}",
        o.plasticity_index
            .map_or("none (give --estar and --hardness)".into(), |p| format!(
                "{p:.6}"
            ))
    );
    let m = &o.model_error;
    crate::outln!("model error                {}", m.reference);
    let pct = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{:+.1} %", 100.0 * v));
    for (k, p) in m.pressure_over_estar.iter().enumerate() {
        let at = |v: &[Option<f64>]| pct(v.get(k).copied().flatten());
        crate::outln!(
            "  p/E* = {p:<8e}         exact A/A0 {:.4}: GW area {}, load at the same gap {}, gap {}; Persson area {}, gap {}",
            m.exact_area_fraction[k],
            at(&m.area),
            at(&m.load),
            at(&m.mean_gap),
            at(&m.persson_area),
            at(&m.persson_mean_gap)
        );
    }
    for w in &o.warnings {
        crate::outln!("warning: {w}");
    }
    Ok(())
}
