//! `asperity surface`: characterise a measured height map (moments,
//! summits, GW parameters from the moments, plasticity index).

use crate::CliError;
use asperity::error::positive;
use asperity::surface::{npy, text, Characterisation, HeightMap, Topography};
use asperity::Error;
use clap::Args;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Arguments of `asperity surface`.
#[derive(Args, Debug)]
pub struct SurfaceArgs {
    /// The height map: NumPy `.npy` (2-D float64/float32, C order) or a text
    /// matrix (`.txt`, `.csv`, `.asc`; whitespace or comma separated).
    file: PathBuf,
    /// Pixel size (m), the same along x and y.
    #[arg(long, allow_negative_numbers = true)]
    pixel_size: f64,
    /// Factor from the file's height unit to metres (e.g. 1e-9 for nm).
    #[arg(long, allow_negative_numbers = true, default_value_t = 1.0)]
    scale: f64,
    /// Treat the map as periodic: remove only the mean, wrap differences and
    /// summit neighbours around every edge.
    #[arg(long)]
    periodic: bool,
    /// Contact modulus E* (Pa), with --hardness for the plasticity index.
    #[arg(long, allow_negative_numbers = true)]
    estar: Option<f64>,
    /// Hardness H (Pa), with --estar for the plasticity index.
    #[arg(long, allow_negative_numbers = true)]
    hardness: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
    /// Also write `surface.json`, `summit_heights.svg` and `summit_map.svg`
    /// into this directory.
    #[arg(long)]
    out: Option<PathBuf>,
}

#[derive(Serialize)]
struct SummitsJson {
    count: usize,
    density_per_m2: f64,
    mean_curvature_per_m: Option<f64>,
    radius_m: Option<f64>,
    height_std_m: Option<f64>,
    mean_height_m: Option<f64>,
}

#[derive(Serialize)]
struct GwJson {
    density_per_m2: f64,
    radius_m: f64,
    sigma_m: Option<f64>,
}

/// The contract of `asperity surface --json` (keys exactly as the issue).
#[derive(Serialize)]
struct SurfaceJson {
    rows: usize,
    cols: usize,
    rms_height_m: f64,
    m0: f64,
    m2: f64,
    m4: f64,
    /// `sqrt(m2)`: a profile's rms slope.
    rms_slope: f64,
    /// `sqrt(2 m2)`: the surface's rms gradient.
    rms_gradient: f64,
    /// `sqrt(m4)` (1/m): a profile's rms curvature.
    rms_curvature_per_m: f64,
    bandwidth_alpha: f64,
    summits: SummitsJson,
    gw_from_moments: GwJson,
    plasticity_index: Option<f64>,
}

/// Reads the map by extension; every content error names the file.
pub(crate) fn read_map(path: &Path) -> Result<HeightMap, CliError> {
    let shown = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    let bytes =
        std::fs::read(path).map_err(|e| CliError::Usage(format!("{shown}: cannot read: {e}")))?;
    let map = match ext.as_str() {
        "npy" => npy::parse(&bytes),
        "txt" | "csv" | "asc" => match std::str::from_utf8(&bytes) {
            Ok(t) => text::parse(t),
            Err(_) => Err(Error::invalid("topography", "not UTF-8 text")),
        },
        _ => Err(Error::invalid(
            "topography",
            format!("unknown extension '{ext}': expected .npy, .txt, .csv or .asc"),
        )),
    };
    Ok(map.map_err(|e| e.renamed(&shown))?)
}

fn plasticity(args: &SurfaceArgs, c: &Characterisation) -> Result<Option<f64>, CliError> {
    match (args.estar, args.hardness) {
        (None, None) => Ok(None),
        (Some(_), None) => Err(CliError::Usage("--hardness: needed with --estar".into())),
        (None, Some(_)) => Err(CliError::Usage("--estar: needed with --hardness".into())),
        (Some(e), Some(h)) => {
            positive("--estar", e)?;
            positive("--hardness", h)?;
            Ok(c.gw_from_moments().plasticity_index(e, h)?)
        }
    }
}

pub fn run(args: &SurfaceArgs) -> crate::CliResult {
    positive("--pixel-size", args.pixel_size)?;
    positive("--scale", args.scale)?;
    let map = read_map(&args.file)?
        .scaled(args.scale)
        .map_err(|e| e.renamed("--scale"))?;
    let topo = Topography::new(map, args.pixel_size).map_err(|e| match e.field() {
        Some("heights") => e.renamed("--scale"),
        _ => e.renamed("--pixel-size"),
    })?;
    let c = topo
        .characterise(args.periodic)
        .map_err(|e| e.renamed(&args.file.display().to_string()))?;
    let psi = plasticity(args, &c)?;
    let (s, gw) = (&c.stats, c.gw_from_moments());
    let out = SurfaceJson {
        rows: c.rows,
        cols: c.cols,
        rms_height_m: c.moments.rms_height(),
        m0: c.moments.m0,
        m2: c.moments.m2,
        m4: c.moments.m4,
        rms_slope: c.moments.rms_slope(),
        rms_gradient: c.moments.rms_gradient(),
        rms_curvature_per_m: c.moments.rms_curvature(),
        bandwidth_alpha: c.bandwidth_alpha(),
        summits: SummitsJson {
            count: s.count,
            density_per_m2: s.density_per_m2,
            mean_curvature_per_m: s.mean_curvature_per_m,
            radius_m: s.radius_m,
            height_std_m: s.height_std_m,
            mean_height_m: s.mean_height_m,
        },
        gw_from_moments: GwJson {
            density_per_m2: gw.density_per_m2,
            radius_m: gw.radius_m,
            sigma_m: gw.sigma_m,
        },
        plasticity_index: psi,
    };
    let json = serde_json::to_string(&out).map_err(|e| CliError::Failed(e.to_string()))?;
    if let Some(dir) = &args.out {
        write_outputs(dir, &json, &c)?;
    }
    if args.json {
        println!("{json}");
    } else {
        print_table(&out);
    }
    Ok(())
}

fn write_outputs(dir: &Path, json: &str, c: &Characterisation) -> crate::CliResult {
    let io = |p: &Path, e: std::io::Error| CliError::from(Error::io(p.display(), e));
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let p = dir.join("surface.json");
    std::fs::write(&p, format!("{json}\n")).map_err(|e| io(&p, e))?;
    if c.summits.len() < 2 {
        eprintln!("note: fewer than 2 summits, no charts written");
        return Ok(());
    }
    let chart = |e: Error| CliError::Failed(e.to_string());
    asperity::study::plot::surface::write_summit_heights(&dir.join("summit_heights.svg"), c)
        .map_err(chart)?;
    asperity::study::plot::surface::write_summit_map(&dir.join("summit_map.svg"), c).map_err(chart)
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
