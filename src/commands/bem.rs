//! `asperity bem`: the exact elastic contact of a measured map by FFT
//! boundary elements, with GW (from the map's moments, as `asperity
//! surface`) and Persson (from the map's radial spectrum) at the same mean
//! pressures.

use super::persson::positive_list;
use super::surface::read_map;
use super::{CommandError as CliError, Report};
use crate::bem::resistance::cluster_resistance;
use crate::bem::{
    clusters::size_distribution, memory_estimate, Options, Problem, SizeBin, Solution,
};
use crate::electrical::{Interaction, ResistanceObservables, SpotResistance, Spreading};
use crate::error::positive;
use crate::gw::{GwModel, RoughSurface};
use crate::heights::Gaussian;
use crate::law::Hertz;
use crate::loading::{Derived, History, LoadingModel, Observables};
use crate::persson::gw::GwOnSpectrum;
use crate::persson::Persson;
use crate::spectrum::radial::radial_psd;
use crate::surface::{npy, HeightMap, Topography};
use crate::Error;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

/// Arguments of `asperity bem`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct BemArgs {
    /// The rigid rough surface: NumPy `.npy` or a text matrix, as for
    /// `asperity surface` (heights in the file's unit, see --scale).
    pub map: PathBuf,
    /// Pixel size (m), the same along x and y.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub pixel_size: f64,
    /// Factor from the file's height unit to metres.
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_negative_numbers = true, default_value_t = 1.0)
    )]
    pub scale: f64,
    /// Contact modulus E* (Pa).
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub estar: f64,
    /// Comma-separated mean pressures (Pa): load control.
    #[cfg_attr(
        feature = "cli",
        arg(
            long,
            allow_negative_numbers = true,
            conflicts_with = "gaps",
            required_unless_present = "gaps"
        )
    )]
    pub pressures: Option<String>,
    /// Comma-separated mean gaps (m): mean-gap control.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub gaps: Option<String>,
    /// Treat the map as periodic (otherwise padded to twice its size, a
    /// non-periodic half-space; the mean plane is removed either way, only
    /// the mean when periodic).
    #[cfg_attr(feature = "cli", arg(long))]
    pub periodic: bool,
    /// Work of adhesion w (J/m^2) of the exponential interaction -w exp(-g/rho).
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_negative_numbers = true, requires = "adhesion_range")
    )]
    pub adhesion_energy: Option<f64>,
    /// Range rho (m) of the exponential interaction.
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_negative_numbers = true, requires = "adhesion_energy")
    )]
    pub adhesion_range: Option<f64>,
    /// Yang–Persson factor gamma in [0, 1] for Persson's mean gap.
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_negative_numbers = true, default_value_t = 1.0)
    )]
    pub gamma: f64,
    /// Resistivity (Ohm m, both bodies): adds the contact resistance of the
    /// clusters (Holm/Maxwell spots + Greenwood interaction) and GW's.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub resistivity: Option<f64>,
    /// Residual at which the solver stops (dimensionless), in [1e-15, 1e-2].
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_negative_numbers = true, default_value_t = 1e-10)
    )]
    pub tolerance: f64,
    /// Most iterations per solve, at least 1.
    #[cfg_attr(feature = "cli", arg(long, default_value_t = 10_000))]
    pub max_iterations: usize,
    /// Memory the solver may use (MiB); larger maps are refused.
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_negative_numbers = true, default_value_t = 1024.0)
    )]
    pub memory_limit_mib: f64,
    /// Write contact.npy/pressure.npy/gap.npy per state, bem.json and charts here.
    #[cfg_attr(feature = "cli", arg(long))]
    pub out: Option<PathBuf>,
    /// Print one JSON object instead of a table.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
}

#[derive(Serialize, Clone)]
struct ResistanceJson {
    bem_parallel_ohm: f64,
    bem_greenwood_ohm: f64,
    gw_ohm: Option<f64>,
}

#[derive(Serialize)]
struct StateJson {
    #[serde(rename = "pressure_Pa")]
    pressure: f64,
    mean_gap_m: f64,
    area_fraction: f64,
    clusters: usize,
    iterations: usize,
    residual: f64,
    cluster_sizes_px: Vec<SizeBin>,
    #[serde(skip_serializing_if = "Option::is_none")]
    resistance: Option<ResistanceJson>,
}

#[derive(Serialize, Clone, Copy)]
struct ModelJson {
    #[serde(rename = "pressure_Pa")]
    pressure: f64,
    area_fraction: Option<f64>,
    mean_gap_m: Option<f64>,
}

#[derive(Serialize)]
struct DiffJson {
    #[serde(rename = "pressure_Pa")]
    pressure: f64,
    gw_area: Option<f64>,
    gw_mean_gap: Option<f64>,
    persson_area: Option<f64>,
    persson_mean_gap: Option<f64>,
}

#[derive(Serialize)]
struct BemJson {
    states: Vec<StateJson>,
    gw: Vec<ModelJson>,
    persson: Vec<ModelJson>,
    relative_differences: Vec<DiffJson>,
    rows: usize,
    cols: usize,
    periodic: bool,
    memory_estimate_bytes: usize,
    gamma: f64,
    solve_wall_s: f64,
    numerical_error: String,
    model_error: String,
    warnings: Vec<String>,
}

fn opt_rel(model: Option<f64>, exact: f64) -> Option<f64> {
    model.filter(|_| exact != 0.0).map(|m| m / exact - 1.0)
}

/// Runs `asperity bem` on the map file `args.map` (and writes `--out`).
pub fn run(args: &BemArgs) -> super::CommandResult<Report> {
    run_map(args, None)
}

/// Runs `asperity bem` on `map` (heights in m, named `name` in errors;
/// `args.map` and `args.scale` are then not used), or on the file
/// `args.map` when `map` is `None`.
pub fn run_map(args: &BemArgs, map: Option<(HeightMap, &str)>) -> super::CommandResult<Report> {
    positive("--pixel-size", args.pixel_size)?;
    positive("--scale", args.scale)?;
    positive("--estar", args.estar)?;
    crate::error::Allowed::closed(1e-15, 1e-2).check("--tolerance", args.tolerance)?;
    if args.max_iterations == 0 {
        return Err(CliError::Usage(
            "--max-iterations = 0: give at least 1".into(),
        ));
    }
    positive("--memory-limit-mib", args.memory_limit_mib)?;
    // The command line refuses these combinations while parsing; other
    // callers get the same errors here.
    if args.pressures.is_some() && args.gaps.is_some() {
        return Err(CliError::Usage(
            "--pressures, --gaps: give only one of them".into(),
        ));
    }
    if args.adhesion_energy.is_some() != args.adhesion_range.is_some() {
        return Err(CliError::Usage(
            "--adhesion-energy, --adhesion-range: give both or neither".into(),
        ));
    }
    let (targets, by_gap) = match (&args.pressures, &args.gaps) {
        (Some(p), _) => (positive_list("--pressures", p)?, false),
        (None, Some(g)) => (positive_list("--gaps", g)?, true),
        (None, None) => {
            return Err(CliError::Usage(
                "--pressures or --gaps: one is needed".into(),
            ))
        }
    };
    let (map, shown) = match map {
        Some((m, name)) => (m, name.to_string()),
        None => (
            read_map(&args.map)?
                .scaled(args.scale)
                .map_err(|e| e.renamed("--scale"))?,
            super::surface::scaled_name(&args.map, args.scale),
        ),
    };
    let options = Options {
        tolerance: args.tolerance,
        max_iterations: args.max_iterations,
        memory_limit: (args.memory_limit_mib * 1048576.0) as usize,
    };
    let memory = memory_estimate(map.rows(), map.cols(), args.periodic);
    if memory as f64 > args.memory_limit_mib * 1048576.0 {
        return Err(CliError::Usage(format!(
            "--memory-limit-mib = {}: {shown} ({} x {} pixels{}) needs about {:.1} MiB",
            args.memory_limit_mib,
            map.rows(),
            map.cols(),
            if args.periodic {
                ""
            } else {
                ", padded to twice the size"
            },
            memory as f64 / 1048576.0
        )));
    }
    let mut problem = Problem::new(&map, args.pixel_size, args.estar, args.periodic, &options)
        .map_err(|e| match e.field() {
            Some("topography") => e.renamed(&shown),
            Some("pixel_size") => e.renamed("--pixel-size"),
            Some("contact_modulus") => e.renamed("--estar"),
            _ => e,
        })?;
    if let (Some(w), Some(rho)) = (args.adhesion_energy, args.adhesion_range) {
        problem = problem.with_adhesion(w, rho).map_err(|e| match e.field() {
            Some("periodic") => e.renamed("--periodic"),
            Some(f) => {
                let f = format!("--{}", f.replace('_', "-"));
                e.renamed(&f)
            }
            None => e,
        })?;
    }
    let spot = args
        .resistivity
        .map(|r| {
            SpotResistance::same_metal(Spreading::Maxwell, r, None)
                .map_err(|e| e.renamed("--resistivity"))
        })
        .transpose()?;
    // GW from the finite-difference moments (as `asperity surface`), Persson from the PSD.
    let topo = Topography::new(map.clone(), args.pixel_size).map_err(|e| match e.field() {
        Some("heights") => e.renamed("--scale"),
        _ => e.renamed("--pixel-size"),
    })?;
    let charac = topo
        .characterise(args.periodic)
        .map_err(|e| e.renamed(&shown))?;
    let gw = GwOnSpectrum::from_moments(&charac.moments, args.estar).ok();
    let psd = radial_psd(&map, args.pixel_size, args.periodic).map_err(|e| e.renamed(&shown))?;
    let persson = Persson::new(psd, args.estar, args.gamma).map_err(|e| e.renamed("--gamma"))?;
    let nominal_area = charac.nominal_area_m2();

    let start = Instant::now();
    let mut warnings = Vec::new();
    let mut solutions: Vec<Solution> = Vec::new();
    let mut states = Vec::new();
    let (mut gw_list, mut persson_list, mut diffs) = (Vec::new(), Vec::new(), Vec::new());
    for &t in &targets {
        let warm = solutions.last();
        let target = if by_gap { "--gaps" } else { "--pressures" };
        let solved = if by_gap {
            problem.solve_gap(t, &options, warm)
        } else {
            problem.solve_pressure(t, &options, warm)
        };
        let s = solved.map_err(|e| -> CliError {
            if e.is_bad_input() {
                return e.renamed(target).into();
            }
            // A solve that fails at these inputs: the target, the modulus
            // and the adhesion the user wrote, named with the failure.
            CliError::Usage(format!(
                "{target}: {t:e} with --estar {:e} Pa{}: {e}; the inputs are outside what the \
                 solver reaches (try a target nearer the map's scales, or --tolerance / \
                 --max-iterations)",
                args.estar,
                match (args.adhesion_energy, args.adhesion_range) {
                    (Some(w), Some(r)) =>
                        format!(", --adhesion-energy {w:e} J/m^2, --adhesion-range {r:e} m"),
                    _ => String::new(),
                }
            ))
        })?;
        let cl = problem.clusters(&s);
        let singles = cl.iter().filter(|c| c.pixels == 1).count();
        if cl.len() >= 10 && singles * 2 > cl.len() {
            warnings.push(format!(
                "state {}: {singles} of {} clusters are single pixels: the contact spots are not resolved (use a finer map)",
                states.len(),
                cl.len()
            ));
        }
        let p = s.mean_pressure;
        let gw_state = gw
            .as_ref()
            .filter(|_| p > 0.0)
            .and_then(|g| g.state(p).ok());
        let pe_state = (p > 0.0).then(|| persson.state(p).ok()).flatten();
        for (model, missing) in [("GW", gw_state.is_none()), ("Persson", pe_state.is_none())] {
            if missing {
                warnings.push(format!(
                    "state {}: {model} gives no state at the mean pressure {p:e} Pa (none without \
                     contact pressure, or outside its range): its values are null",
                    states.len()
                ));
            }
        }
        if let Some(g) = gw_state.filter(|g| g.area_fraction > 0.1) {
            warnings.push(format!(
                "GW at p = {p:e} Pa: area fraction {:.3} > 0.1, outside GW's light-load validity",
                g.area_fraction
            ));
        }
        let resistance = match &spot {
            Some(sp) => {
                let bem = cluster_resistance(&problem, &cl, sp)
                    .map_err(|e| CliError::Failed(e.to_string()))?;
                let gw_r = match (&gw, gw_state) {
                    (Some(g), Some(st)) => {
                        // The engine's one GW integrator: Hertz summits, the
                        // spot conductance as an observable, Greenwood's term.
                        let surface = RoughSurface::new(
                            g.params.density_per_m2,
                            g.params.radius_m,
                            g.sigma,
                            nominal_area,
                        )?;
                        let law = Arc::new(Hertz::new(g.params.radius_m, args.estar)?);
                        let model = GwModel::new(surface, Arc::new(Gaussian::new()), law)?;
                        let r = ResistanceObservables::new(
                            *sp,
                            Interaction::Greenwood,
                            nominal_area.sqrt(),
                        );
                        let outputs = r.add_to(Observables::LOAD)?;
                        let state = model.state(st.h * g.sigma, History::Approach, &outputs)?;
                        r.value(&outputs, &state.totals)
                    }
                    _ => None,
                };
                bem.map(|b| ResistanceJson {
                    bem_parallel_ohm: b.parallel,
                    bem_greenwood_ohm: b.greenwood,
                    gw_ohm: gw_r,
                })
            }
            None => None,
        };
        let gw_json = ModelJson {
            pressure: p,
            area_fraction: gw_state.map(|g| g.area_fraction),
            mean_gap_m: gw_state.map(|g| g.mean_gap),
        };
        let pe_json = ModelJson {
            pressure: p,
            area_fraction: pe_state.map(|g| g.area_fraction),
            mean_gap_m: pe_state.map(|g| g.mean_gap),
        };
        diffs.push(DiffJson {
            pressure: p,
            gw_area: opt_rel(gw_json.area_fraction, s.area_fraction()),
            gw_mean_gap: opt_rel(gw_json.mean_gap_m, s.mean_gap),
            persson_area: opt_rel(pe_json.area_fraction, s.area_fraction()),
            persson_mean_gap: opt_rel(pe_json.mean_gap_m, s.mean_gap),
        });
        gw_list.push(gw_json);
        persson_list.push(pe_json);
        states.push(StateJson {
            pressure: p,
            mean_gap_m: s.mean_gap,
            area_fraction: s.area_fraction(),
            clusters: cl.len(),
            iterations: s.iterations,
            residual: s.residual,
            cluster_sizes_px: size_distribution(&cl),
            resistance,
        });
        solutions.push(s);
    }
    if gw.is_none() {
        warnings.push(
            "GW: the map's bandwidth leaves McCool's summit heights no variance; no GW prediction"
                .into(),
        );
    }
    if args.adhesion_energy.is_some() {
        warnings.push(
            "GW and Persson columns are the non-adhesive theories at the same mean pressure".into(),
        );
    }
    let out = BemJson {
        states,
        gw: gw_list,
        persson: persson_list,
        relative_differences: diffs,
        rows: map.rows(),
        cols: map.cols(),
        periodic: args.periodic,
        memory_estimate_bytes: memory,
        gamma: args.gamma,
        solve_wall_s: start.elapsed().as_secs_f64(),
        numerical_error: format!(
            "boundary elements: each state converged to the stated residual (< {:e}; gap residual over h_rms under load control, KKT residual over the full-contact RMS pressure under gap control); on a 256^2 self-affine map the area fraction moves by < 1e-5 from 1e-8 to 1e-12; discretisation: Hertz on 512^2 within 0.2 % (docs/performance.md). Persson: quadrature 1e-12 relative on the map's radial spectrum",
            args.tolerance
        ),
        model_error: "boundary elements: exact linear-elastic, frictionless, small-slope half-space solution of the pixel map (the only error is the discretisation); GW and Persson are approximations of the same problem, see relative_differences".into(),
        warnings,
    };
    let json = serde_json::to_string(&out).map_err(|e| CliError::Failed(e.to_string()))?;
    if let Some(dir) = &args.out {
        write_outputs(dir, &json, &out, &solutions, &problem)?;
    }
    Report::new(&out, print_table(&out))
}

fn write_outputs(
    dir: &Path,
    json: &str,
    out: &BemJson,
    sols: &[Solution],
    problem: &Problem,
) -> super::CommandResult<()> {
    let io = |p: &Path, e: std::io::Error| CliError::from(Error::io(p.display(), e));
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let p = dir.join("bem.json");
    crate::study::atomic::write(&p, format!("{json}\n")).map_err(|e| io(&p, e))?;
    let (rows, cols) = problem.shape();
    for (k, s) in sols.iter().enumerate() {
        let fields: [(&str, Vec<f64>); 3] = [
            (
                "contact",
                s.contact()
                    .iter()
                    .map(|c| f64::from(u8::from(*c)))
                    .collect(),
            ),
            ("pressure", s.pressure.clone()),
            ("gap", s.gap.clone()),
        ];
        for (name, v) in fields {
            let m = HeightMap::new(rows, cols, v).map_err(|e| CliError::Failed(e.to_string()))?;
            let p = dir.join(format!("{name}_{k}.npy"));
            crate::study::atomic::write(&p, npy::to_bytes(&m)).map_err(|e| io(&p, e))?;
        }
    }
    use crate::study::plot::{Chart, Series};
    let series = |label: &str, pts: Vec<(f64, f64)>| Series::leg(label, pts);
    let pick = |l: &[ModelJson], f: fn(&ModelJson) -> Option<f64>| -> Vec<(f64, f64)> {
        l.iter()
            .filter_map(|m| f(m).map(|v| (m.pressure, v)))
            .collect()
    };
    let area = Chart {
        title: "Contact area against mean pressure".into(),
        x_label: "mean pressure p (Pa)".into(),
        y_label: "A/A0".into(),
        series: vec![
            series(
                "boundary elements",
                out.states
                    .iter()
                    .map(|s| (s.pressure, s.area_fraction))
                    .collect(),
            ),
            series("GW", pick(&out.gw, |m| m.area_fraction)),
            series("Persson", pick(&out.persson, |m| m.area_fraction)),
        ],
        y_range: None,
        y_symlog: false,
    };
    let gap = Chart {
        title: "Mean gap against mean pressure".into(),
        x_label: "mean pressure p (Pa)".into(),
        y_label: "mean gap (m)".into(),
        series: vec![
            series(
                "boundary elements",
                out.states
                    .iter()
                    .map(|s| (s.pressure, s.mean_gap_m))
                    .collect(),
            ),
            series("GW", pick(&out.gw, |m| m.mean_gap_m)),
            series("Persson", pick(&out.persson, |m| m.mean_gap_m)),
        ],
        y_range: None,
        y_symlog: false,
    };
    let chart = |e: Error| CliError::Failed(e.to_string());
    area.write_svg_loglog(&dir.join("area_vs_pressure.svg"), 800, 560)
        .map_err(chart)?;
    gap.write_svg(&dir.join("gap_vs_pressure.svg"), 800, 560)
        .map_err(chart)
}

fn print_table(o: &BemJson) -> String {
    let mut t = String::new();
    let _ = writeln!(
        t,
        "map {} x {} ({}), memory estimate {:.1} MiB, solved in {:.3} s (wall)",
        o.rows,
        o.cols,
        if o.periodic { "periodic" } else { "padded" },
        o.memory_estimate_bytes as f64 / 1048576.0,
        o.solve_wall_s
    );
    let _ = writeln!(
        t,
        "{:>12} {:>12} {:>12} {:>8} {:>6} {:>9} | {:>12} {:>12} | {:>12} {:>12}",
        "p (Pa)",
        "gap (m)",
        "A/A0",
        "clusters",
        "iter",
        "residual",
        "GW A/A0",
        "GW gap",
        "Persson A/A0",
        "Persson gap"
    );
    let f = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.5e}"));
    for ((s, g), p) in o.states.iter().zip(&o.gw).zip(&o.persson) {
        let _ =
            writeln!(t,
            "{:>12.5e} {:>12.5e} {:>12.5e} {:>8} {:>6} {:>9.2e} | {:>12} {:>12} | {:>12} {:>12}",
            s.pressure,
            s.mean_gap_m,
            s.area_fraction,
            s.clusters,
            s.iterations,
            s.residual,
            f(g.area_fraction),
            f(g.mean_gap_m),
            f(p.area_fraction),
            f(p.mean_gap_m)
        );
    }
    for w in &o.warnings {
        let _ = writeln!(t, "warning: {w}");
    }
    let _ = writeln!(t, "numerical error: {}", o.numerical_error);
    let _ = writeln!(t, "model error: {}", o.model_error);
    t
}
