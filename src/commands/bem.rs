//! `asperity bem`: the exact elastic contact of a measured map by FFT
//! boundary elements, with GW (from the map's moments, as `asperity
//! surface`) and Persson (from the map's radial spectrum) at the same mean
//! pressures.

use super::criteria::{Assessment, CriteriaOutput};
use super::persson::positive_values;
use super::wet_map::{wet_states, Liquid, WetOutput};
use super::{param, CommandResult};
use crate::bem::compare::{compare, CompareError, CompareInput, Comparison, Control, Step};
use crate::bem::{memory_estimate, Exponential, Options, SizeBin, Solution, SolveReport};
use crate::error::positive;
use crate::surface::{npy, HeightMap};
use crate::Error;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

pub use crate::bem::compare::{
    Difference as BemDifference, Prediction as BemModel, Resistance as BemResistance,
};

/// What the solves hold fixed.
#[derive(Debug, Clone, PartialEq)]
pub enum BemTargets {
    /// Mean pressures (Pa), each > 0: load control.
    Pressures(Vec<f64>),
    /// Mean gaps (m), each > 0: mean-gap control.
    Gaps(Vec<f64>),
}

impl BemTargets {
    /// The targets from the two optional inputs, exactly one of which is
    /// given.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `{pressures}` and `{gaps}`.
    pub fn from_options(
        pressures: Option<Vec<f64>>,
        gaps: Option<Vec<f64>>,
    ) -> CommandResult<Self> {
        match (pressures, gaps) {
            (Some(p), None) => Ok(BemTargets::Pressures(p)),
            (None, Some(g)) => Ok(BemTargets::Gaps(g)),
            (Some(_), Some(_)) => Err(Error::invalid(
                format!("{}, {}", param("pressures"), param("gaps")),
                "give only one of them",
            )),
            (None, None) => Err(Error::invalid(
                format!("{} or {}", param("pressures"), param("gaps")),
                "one is needed",
            )),
        }
    }
}

/// The exponential adhesive interaction `-w exp(-g/rho)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BemAdhesion {
    /// Work of adhesion w (J/m^2).
    pub energy: f64,
    /// Range rho (m).
    pub range: f64,
}

impl BemAdhesion {
    /// The interaction from the two optional inputs, both or neither given.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `{adhesion_energy}` and `{adhesion_range}`.
    pub fn from_options(energy: Option<f64>, range: Option<f64>) -> CommandResult<Option<Self>> {
        match (energy, range) {
            (Some(energy), Some(range)) => Ok(Some(BemAdhesion { energy, range })),
            (None, None) => Ok(None),
            _ => Err(Error::invalid(
                format!("{}, {}", param("adhesion_energy"), param("adhesion_range")),
                "give both or neither",
            )),
        }
    }
}

/// The input of [`bem`] besides the map.
#[derive(Debug, Clone)]
pub struct BemInput {
    /// Pixel size (m) along x (a row), and along y unless `pixel_size_y`.
    pub pixel_size: f64,
    /// Pixel size (m) along y (a column) when it differs from x
    /// (rectangular pixels: [`crate::bem::Problem::with_pixels`]).
    pub pixel_size_y: Option<f64>,
    /// Contact modulus E* (Pa).
    pub estar: f64,
    /// Mean pressures or mean gaps.
    pub targets: BemTargets,
    /// Treat the map as periodic (otherwise padded to twice its size, a
    /// non-periodic half-space; the mean plane is removed either way, only
    /// the mean when periodic).
    pub periodic: bool,
    /// The adhesive interaction, if any.
    pub adhesion: Option<BemAdhesion>,
    /// Hardness `H` (Pa, finite, > 0): the contact pressure capped at `H`
    /// (elastic–perfectly-plastic, [`crate::bem::Problem::with_hardness`]);
    /// mean pressures at most `H`; with an adhesion (periodic maps) the
    /// adhesive solver with the pressure capped at `H`.
    pub hardness: Option<f64>,
    /// Yang–Persson factor gamma in [0, 1] for Persson's mean gap
    /// (default 1).
    pub gamma: f64,
    /// Resistivity (Ohm m, both bodies): adds the contact resistance of the
    /// clusters (Holm/Maxwell spots + Greenwood interaction) and GW's.
    pub resistivity: Option<f64>,
    /// Residual at which the solver stops (dimensionless), in [1e-15, 1e-2];
    /// default 1e-10.
    pub tolerance: f64,
    /// Most iterations per solve, at least 1; default 10,000.
    pub max_iterations: usize,
    /// Memory the solver may use (MiB); larger maps are refused. Default
    /// 1024.
    pub memory_limit_mib: f64,
    /// A solve stopped at the iteration cap gives its last iterate flagged
    /// `converged: false` with a warning, instead of failing. Default
    /// `false`.
    pub allow_unconverged: bool,
    /// The condensing liquid and humidity: adds the flooded capillary
    /// attraction of every state beside per-summit menisci.
    pub liquid: Option<Liquid>,
    /// Write contact/pressure/gap `.npy` per state, `bem.json` and charts
    /// here.
    pub out: Option<PathBuf>,
}

impl BemInput {
    /// Checks every input but the map (before a map is read).
    ///
    /// # Errors
    /// Naming the input and its range.
    pub fn validate(&self) -> CommandResult<()> {
        positive(&param("pixel_size"), self.pixel_size)?;
        if let Some(dy) = self.pixel_size_y {
            positive(&param("pixel_size_y"), dy)?;
        }
        positive(&param("estar"), self.estar)?;
        crate::error::Allowed::closed(1e-15, 1e-2).check(&param("tolerance"), self.tolerance)?;
        if self.max_iterations == 0 {
            return Err(Error::invalid(
                param("max_iterations"),
                "0: give at least 1",
            ));
        }
        positive(&param("memory_limit_mib"), self.memory_limit_mib)?;
        match &self.targets {
            BemTargets::Pressures(p) => positive_values("pressures", p)?,
            BemTargets::Gaps(g) => positive_values("gaps", g)?,
        }
        self.validate_scales()?;
        self.validate_hardness()
    }

    /// Physical scales: no mean pressure above E* (strains of order one,
    /// outside the linear elasticity of the half-space); a work of adhesion
    /// up to 10 J/m^2 (twice the surface energy of the most cohesive
    /// metals) and a range from 0.01 nm to 1 um (surface forces to
    /// capillary and electrostatic tails). Beyond them the solver ran to
    /// its iteration cap (exit 1) or the criteria overflowed to null.
    fn validate_scales(&self) -> CommandResult<()> {
        if let BemTargets::Pressures(p) = &self.targets {
            if let Some((i, v)) = p.iter().enumerate().find(|(_, v)| **v > self.estar) {
                return Err(Error::invalid(
                    param(&format!("pressures[{i}]")),
                    format!(
                        "{v:e} Pa is above {} = {:e} Pa: a mean pressure above the contact \
                         modulus means strains of order one, outside the linear elasticity the \
                         half-space solution assumes; allowed (0, {:e}] Pa",
                        param("estar"),
                        self.estar,
                        self.estar
                    ),
                ));
            }
        }
        if let Some(a) = self.adhesion {
            crate::error::Allowed::open_closed(0.0, 10.0)
                .check(&param("adhesion_energy"), a.energy)?;
            crate::error::Allowed::closed(1e-11, 1e-6).check(&param("adhesion_range"), a.range)?;
        }
        Ok(())
    }

    /// The hardness: finite and > 0, and no mean pressure above it.
    fn validate_hardness(&self) -> CommandResult<()> {
        let Some(h) = self.hardness else {
            return Ok(());
        };
        positive(&param("hardness"), h)?;
        if let BemTargets::Pressures(p) = &self.targets {
            for (i, &v) in p.iter().enumerate() {
                if v > h {
                    return Err(Error::invalid(
                        param(&format!("pressures[{i}]")),
                        format!(
                            "{v:e} Pa is above {} = {h:e} Pa: a mean pressure above the hardness \
                             has no solution (at the hardness every pixel is plastic)",
                            param("hardness")
                        ),
                    ));
                }
            }
        }
        Ok(())
    }

    /// The defaults with the required inputs.
    pub fn new(pixel_size: f64, estar: f64, targets: BemTargets) -> Self {
        BemInput {
            pixel_size,
            pixel_size_y: None,
            estar,
            targets,
            periodic: false,
            adhesion: None,
            hardness: None,
            gamma: 1.0,
            resistivity: None,
            tolerance: 1e-10,
            max_iterations: 10_000,
            memory_limit_mib: 1024.0,
            allow_unconverged: false,
            liquid: None,
            out: None,
        }
    }
}

/// One solve: the exact boundary-element state.
#[derive(Serialize, Debug, Clone)]
pub struct BemState {
    /// Mean pressure (Pa).
    #[serde(rename = "pressure_Pa")]
    pub pressure: f64,
    /// Mean gap (m).
    pub mean_gap_m: f64,
    /// Real-area fraction `A/A0` (exactly 1 only when every pixel is in
    /// contact).
    pub area_fraction: f64,
    /// Whether every pixel is in contact (`area_fraction` exactly 1).
    pub full_contact: bool,
    /// Elastic energy stored per nominal area (J/m^2), `(1/2) mean(p u)`
    /// with `u = K p`; in full contact on a periodic map Persson's
    /// `U_full/A0 = (E*/4) sum_q |q| |h_q|^2` of the map.
    #[serde(rename = "elastic_energy_J_per_m2")]
    pub elastic_energy: f64,
    /// Contact clusters (8-connected pixels in contact).
    pub clusters: usize,
    /// The solve's iterations, final residual (dimensionless) and
    /// whether it fell below the tolerance (`converged: false` only with
    /// `allow_unconverged`, with a warning); its keys inline.
    #[serde(flatten)]
    pub solve: SolveReport,
    /// With a hardness: the fraction of the pixels at `p = H` (plastic).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_area_fraction: Option<f64>,
    /// With a hardness: the plastically displaced volume (m^3), the
    /// interpenetration on the plastic pixels times the pixel area.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_volume_m3: Option<f64>,
    /// With a hardness: that volume per nominal area (m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_volume_per_area_m: Option<f64>,
    /// Cluster sizes (pixels) in logarithmic bins.
    pub cluster_sizes_px: Vec<SizeBin>,
    /// Contact resistance, with a resistivity.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resistance: Option<BemResistance>,
}

/// What `asperity bem --json` prints.
#[derive(Serialize, Debug, Clone)]
pub struct BemOutput {
    /// The exact states, in the order of the targets.
    pub states: Vec<BemState>,
    /// GW (from the map's moments) at the same mean pressures.
    pub gw: Vec<BemModel>,
    /// Persson (from the map's radial spectrum) at the same mean pressures.
    pub persson: Vec<BemModel>,
    /// The models against the exact states.
    pub relative_differences: Vec<BemDifference>,
    /// Rows of the map.
    pub rows: usize,
    /// Columns of the map.
    pub cols: usize,
    /// Whether the map was taken as periodic.
    pub periodic: bool,
    /// The hardness (Pa) capping the contact pressure, if any.
    #[serde(rename = "hardness_Pa", skip_serializing_if = "Option::is_none")]
    pub hardness: Option<f64>,
    /// The solver's memory estimate (bytes).
    pub memory_estimate_bytes: usize,
    /// The Yang–Persson factor used.
    pub gamma: f64,
    /// Wall-clock time of the solves (s).
    pub solve_wall_s: f64,
    /// The errors in words, the warnings, the map's stickiness criteria
    /// with an adhesion, and with a liquid the capillary attraction of every
    /// state, flooded and per-summit; its keys inline.
    #[serde(flatten)]
    pub assessment: Assessment<WetOutput>,
}

impl BemInput {
    /// The core's inputs ([`compare`]).
    fn compare_input(&self) -> CompareInput {
        let (control, targets) = match &self.targets {
            BemTargets::Pressures(p) => (Control::Pressure, p.clone()),
            BemTargets::Gaps(g) => (Control::Gap, g.clone()),
        };
        CompareInput {
            pixel_size: self.pixel_size,
            pixel_size_y: self.pixel_size_y,
            contact_modulus: self.estar,
            periodic: self.periodic,
            control,
            targets,
            adhesion: self.adhesion.map(|a| Exponential {
                energy: a.energy,
                range: a.range,
            }),
            hardness: self.hardness,
            gamma: self.gamma,
            resistivity: self.resistivity,
            options: Options {
                tolerance: self.tolerance,
                max_iterations: self.max_iterations,
                memory_limit: (self.memory_limit_mib * 1048576.0) as usize,
                allow_unconverged: self.allow_unconverged,
            },
        }
    }
}

/// The exact elastic contact of `map` (heights in m) by FFT boundary
/// elements, beside GW and Persson at the same mean pressures (`asperity
/// bem`, [`compare`]), and its outputs written to `input.out`.
///
/// # Errors
/// Naming an input (`{pressures[i]}`, `{estar}`, `{heights}` for the map:
/// flat, too small); a map beyond `{memory_limit_mib}` or the memory
/// available; a solve that fails at the inputs names the target;
/// [`Error::Cancelled`].
pub fn bem(map: &HeightMap, args: &BemInput) -> CommandResult<BemOutput> {
    args.validate()?;
    let memory = check_memory(map, args)?;
    if let Some(l) = &args.liquid {
        l.meniscus()?;
    }
    let cmp = compare(map, &args.compare_input()).map_err(|e| named_failure(e, args))?;
    let mut out = output(map, args, &cmp, memory);
    if let Some(l) = &args.liquid {
        let pixels = (
            args.pixel_size,
            args.pixel_size_y.unwrap_or(args.pixel_size),
        );
        // Persson on the map's radial spectrum, as the comparison has it:
        // its gap distribution beside the exact gap fields.
        let persson = crate::spectrum::radial::radial_psd_xy(map, pixels, args.periodic)
            .and_then(|psd| crate::persson::Persson::new(psd, args.estar, args.gamma))
            .ok();
        let a = &mut out.assessment;
        a.capillary = wet_states(l, &cmp, persson.as_ref(), (map.rows(), map.cols()), pixels)?;
        if let Some(w) = &a.capillary {
            a.warnings.extend(super::wet_map::warnings(w));
        }
    }
    if let Some(dir) = &args.out {
        crate::cancel::check()?;
        let solutions: Vec<&Solution> = cmp.states.iter().map(|s| &s.solution).collect();
        write_outputs(dir, &out, &solutions, (map.rows(), map.cols()))?;
    }
    Ok(out)
}

/// The solver's memory estimate (bytes) for `map`, checked against
/// `{memory_limit_mib}` and the memory available.
fn check_memory(map: &HeightMap, args: &BemInput) -> CommandResult<usize> {
    let memory = memory_estimate(map.rows(), map.cols(), args.periodic);
    let layout = format!(
        "{} x {} pixels{}",
        map.rows(),
        map.cols(),
        if args.periodic {
            ""
        } else {
            ", padded to twice the size"
        }
    );
    let shown = param("heights");
    if memory as f64 > args.memory_limit_mib * 1048576.0 {
        return Err(Error::invalid(
            param("memory_limit_mib"),
            format!(
                "{}: {shown} ({layout}) needs about {:.1} MiB",
                args.memory_limit_mib,
                memory as f64 / 1048576.0
            ),
        ));
    }
    crate::study::memory::ensure(
        &shown,
        &format!("the boundary elements of {layout}"),
        memory as f64,
        "crop or downsample the map",
    )?;
    Ok(memory)
}

/// A failure of [`compare`] named by the command's inputs.
fn named_failure(e: CompareError, args: &BemInput) -> Error {
    let CompareError { step, error } = e;
    match step {
        Step::Problem => super::named(
            error,
            &[
                ("topography", "heights"),
                ("pixel_size", "pixel_size"),
                ("pixel_size_y", "pixel_size_y"),
                ("contact_modulus", "estar"),
                ("hardness", "hardness"),
            ],
        ),
        Step::Adhesion => match error.field().map(str::to_string) {
            Some(f) => error.renamed(&param(&f)),
            None => error,
        },
        Step::Resistivity => error.renamed(&param("resistivity")),
        Step::Topography => match error.field() {
            Some("heights") => error.renamed(&param("scale")),
            Some("pixel_size_y") => error.renamed(&param("pixel_size_y")),
            _ => error.renamed(&param("pixel_size")),
        },
        Step::Characterise | Step::Spectrum => error.renamed(&param("heights")),
        Step::Persson => error.renamed(&param("gamma")),
        Step::Solve { target, .. } => solve_failure(error, target, args),
        Step::Resistance => error,
    }
}

/// A solve that fails at target `t`: bad input names the targets; a solve
/// stopped at the iteration cap is the program's failure (not bad input:
/// the CLI exits 1) with its residual and the inputs that change it; any
/// other failure is the inputs' (the target, the modulus and the adhesion
/// the user wrote, named with the failure).
fn solve_failure(e: Error, t: f64, args: &BemInput) -> Error {
    let target = param(match args.targets {
        BemTargets::Gaps(_) => "gaps",
        BemTargets::Pressures(_) => "pressures",
    });
    if e.is_bad_input() {
        return e.renamed(&target);
    }
    if matches!(e, Error::Cancelled) {
        return e;
    }
    if let Error::NoConvergence {
        what,
        iterations,
        residual,
    } = &e
    {
        if what.ends_with(crate::bem::AT_CAP) {
            return Error::NoConvergence {
                what: format!(
                    "{target} {t:e}: {what} ({} {}, {} {:e}; {} gives the last iterate flagged \
                     converged: false)",
                    param("max_iterations"),
                    args.max_iterations,
                    param("tolerance"),
                    args.tolerance,
                    param("allow_unconverged")
                ),
                iterations: *iterations,
                residual: *residual,
            };
        }
    }
    let adhesion = match args.adhesion {
        Some(a) => format!(
            ", {} {:e} J/m^2, {} {:e} m",
            param("adhesion_energy"),
            a.energy,
            param("adhesion_range"),
            a.range
        ),
        None => String::new(),
    };
    Error::invalid(
        &target,
        format!(
            "{t:e} with {} {:e} Pa{adhesion}: {e}; the inputs are outside what the solver \
             reaches (try a target nearer the map's scales, or {} / {})",
            param("estar"),
            args.estar,
            param("tolerance"),
            param("max_iterations")
        ),
    )
}

/// The JSON record of a comparison.
fn output(map: &HeightMap, args: &BemInput, cmp: &Comparison, memory: usize) -> BemOutput {
    let (dx, dy) = (
        args.pixel_size,
        args.pixel_size_y.unwrap_or(args.pixel_size),
    );
    let nominal = (map.rows() * map.cols()) as f64 * dx * dy;
    let plastic = |v: f64| args.hardness.map(|_| v);
    let states = cmp
        .states
        .iter()
        .map(|st| {
            let s = &st.solution;
            BemState {
                plastic_area_fraction: plastic(s.plastic_fraction()),
                plastic_volume_m3: plastic(s.plastic_volume_per_area * nominal),
                plastic_volume_per_area_m: plastic(s.plastic_volume_per_area),
                pressure: s.mean_pressure,
                mean_gap_m: s.mean_gap,
                area_fraction: s.area_fraction(),
                full_contact: s.full_contact(),
                elastic_energy: s.elastic_energy_per_area,
                clusters: st.clusters,
                solve: s.report(),
                cluster_sizes_px: st.cluster_sizes.clone(),
                resistance: st.resistance,
            }
        })
        .collect();
    BemOutput {
        states,
        gw: cmp.gw.clone(),
        persson: cmp.persson.clone(),
        relative_differences: cmp.differences.clone(),
        rows: map.rows(),
        cols: map.cols(),
        periodic: args.periodic,
        hardness: args.hardness,
        memory_estimate_bytes: memory,
        gamma: args.gamma,
        solve_wall_s: cmp.solve_wall_s,
        assessment: Assessment {
            numerical_error: format!(
                "{}boundary elements: each state converged to the stated residual (< {:e}; gap residual over h_rms under load control, KKT residual over the full-contact RMS pressure under gap control); on a 256^2 self-affine map the area fraction moves by < 1e-5 from 1e-8 to 1e-12; discretisation: Hertz on 512^2 within 0.2 % (docs/performance.md). Persson: quadrature 1e-12 relative on the map's radial spectrum",
                unconverged_note(cmp),
                args.tolerance
            ),
            model_error: measured_model_error(cmp),
            warnings: cmp
                .warnings
                .iter()
                .map(ToString::to_string)
                .chain(cmp.criteria.iter().flat_map(|c| c.warnings(true)))
                .collect(),
            adhesion_criteria: cmp.criteria.zip(cmp.roughness).map(|(c, r)| CriteriaOutput {
                criteria: c,
                roughness: r.into(),
            }),
            capillary: None,
        },
    }
}

/// The states that stopped at the iteration cap, in words (empty when
/// every state converged).
fn unconverged_note(cmp: &Comparison) -> String {
    let n = cmp.states.iter().filter(|s| !s.solution.converged).count();
    if n == 0 {
        return String::new();
    }
    format!(
        "{n} of {} states NOT converged (stopped at the iteration cap, converged: false: their \
         error is not bounded by the tolerance); otherwise ",
        cmp.states.len()
    )
}

impl BemOutput {
    /// The table `asperity bem` prints.
    pub fn text(&self) -> String {
        print_table(self)
    }
}

/// `bem.json`, the fields of every state as `.npy` maps of `shape` (rows,
/// columns) and the two charts, in `dir`.
fn write_outputs(
    dir: &Path,
    out: &BemOutput,
    sols: &[&Solution],
    shape: (usize, usize),
) -> CommandResult<()> {
    super::create_dir(dir)?;
    super::write_file(
        &dir.join("bem.json"),
        format!("{}\n", super::json_line(out)?),
    )?;
    let (rows, cols) = shape;
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
            let m = HeightMap::new(rows, cols, v)?;
            super::write_file(&dir.join(format!("{name}_{k}.npy")), npy::to_bytes(&m))?;
        }
    }
    use crate::study::plot::{Chart, Series};
    // One quantity of the three models against the mean pressure: the
    // exact states' `exact`, the theories' `theory` where they have one.
    let chart = |title: &str,
                 y_label: &str,
                 exact: fn(&BemState) -> f64,
                 theory: fn(&BemModel) -> Option<f64>| {
        let pick = |l: &[BemModel]| -> Vec<(f64, f64)> {
            l.iter()
                .filter_map(|m| theory(m).map(|v| (m.pressure, v)))
                .collect()
        };
        let exact = out.states.iter().map(|s| (s.pressure, exact(s))).collect();
        Chart {
            title: title.into(),
            x_label: "mean pressure p (Pa)".into(),
            y_label: y_label.into(),
            series: vec![
                Series::leg("boundary elements", exact),
                Series::leg("GW", pick(&out.gw)),
                Series::leg("Persson", pick(&out.persson)),
            ],
            y_range: None,
            y_symlog: false,
        }
    };
    let area = chart(
        "Contact area against mean pressure",
        "A/A0",
        |s| s.area_fraction,
        |m| m.area_fraction,
    );
    let gap = chart(
        "Mean gap against mean pressure",
        "mean gap (m)",
        |s| s.mean_gap_m,
        |m| m.mean_gap_m,
    );
    area.write_svg_loglog(&dir.join("area_vs_pressure.svg"), 800, 560)?;
    gap.write_svg(&dir.join("gap_vs_pressure.svg"), 800, 560)
}

fn print_table(o: &BemOutput) -> String {
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
        "{:>12} {:>12} {:>12} {:>8} {:>6} {:>9} {:>4} | {:>12} {:>12} {:>8} {:>8} | {:>12} {:>12} {:>8} {:>8}",
        "p (Pa)",
        "gap (m)",
        "A/A0",
        "clusters",
        "iter",
        "residual",
        "conv",
        "GW A/A0",
        "GW gap",
        "dA/A",
        "du/u",
        "Persson A/A0",
        "Persson gap",
        "dA/A",
        "du/u"
    );
    let f = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.5e}"));
    let pct = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{:+.1}%", 100.0 * v));
    for (((s, g), p), d) in o
        .states
        .iter()
        .zip(&o.gw)
        .zip(&o.persson)
        .zip(&o.relative_differences)
    {
        let _ = writeln!(
            t,
            "{:>12.5e} {:>12.5e} {:>12} {:>8} {:>6} {:>9.2e} {:>4} | {:>12} {:>12} {:>8} {:>8} | {:>12} {:>12} {:>8} {:>8}",
            s.pressure,
            s.mean_gap_m,
            area_text(s.area_fraction),
            s.clusters,
            s.solve.iterations,
            s.solve.residual,
            if s.solve.converged { "yes" } else { "NO" },
            f(g.area_fraction),
            f(g.mean_gap_m),
            pct(d.gw_area),
            pct(d.gw_mean_gap),
            f(p.area_fraction),
            f(p.mean_gap_m),
            pct(d.persson_area),
            pct(d.persson_mean_gap)
        );
    }
    let _ = writeln!(
        t,
        "(iter, residual, conv: the solver's iterations, final residual and whether it fell below the tolerance; dA/A, du/u: the model's area fraction and mean gap against the exact ones, model/exact - 1)"
    );
    full_contact_lines(o, &mut t);
    if let Some(c) = &o.assessment.adhesion_criteria {
        t.push_str(&c.criteria.text());
    }
    if let Some(w) = &o.assessment.capillary {
        t.push_str(&super::wet_map::text(w));
    }
    if let Some(h) = o.hardness {
        let _ = writeln!(
            t,
            "elastic-perfectly-plastic, hardness {h:.5e} Pa: {:>12} {:>16} {:>16}",
            "plastic A/A0", "volume (m^3)", "per area (m)"
        );
        for (k, s) in o.states.iter().enumerate() {
            let f = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.5e}"));
            let _ = writeln!(
                t,
                "  state {k}, p = {:.5e} Pa: {:>12} {:>16} {:>16}",
                s.pressure,
                f(s.plastic_area_fraction),
                f(s.plastic_volume_m3),
                f(s.plastic_volume_per_area_m)
            );
        }
    }
    o.assessment.closing_lines(&mut t);
    t
}

/// A line for each state in full contact, with its elastic energy.
fn full_contact_lines(o: &BemOutput, t: &mut String) {
    for (k, s) in o.states.iter().enumerate().filter(|(_, s)| s.full_contact) {
        let _ = writeln!(
            t,
            "state {k}, p = {:.5e} Pa: full contact (every pixel, A/A0 = 1 exactly), elastic energy {:.9e} J/m^2",
            s.pressure, s.elastic_energy
        );
    }
}

/// `A/A0` for the table: five significant digits, and never rounded up
/// to 1 (a fraction below 1 shows as many digits as it needs, up to 1 -
/// 1e-12; above that `< 1`), so `1` means every pixel in contact.
fn area_text(a: f64) -> String {
    if a == 1.0 {
        return "1".to_string();
    }
    let short = format!("{a:.5e}");
    if short.parse::<f64>().map_or(true, |v| v < 1.0) {
        return short;
    }
    // 1 - a in five digits, written as a decimal with enough places.
    let open = 1.0 - a;
    let places = (-open.log10()).ceil() as usize + 1;
    if places > 12 {
        return "< 1".to_string();
    }
    format!("{a:.places$}")
}

/// The measured model error of the theories on this map: the range of
/// each one's relative differences over the states, in words.
fn measured_model_error(cmp: &Comparison) -> String {
    type Pick = fn(&BemDifference) -> Option<f64>;
    let range = |pick: Pick| -> String {
        let v: Vec<f64> = cmp.differences.iter().filter_map(pick).collect();
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        match v.len() {
            0 => "not measured (no prediction)".to_string(),
            _ if lo == hi => format!("{:+.1} %", 100.0 * lo),
            _ => format!("{:+.1} % to {:+.1} %", 100.0 * lo, 100.0 * hi),
        }
    };
    let pressures = cmp.differences.iter().map(|d| d.pressure);
    let (plo, phi) = pressures.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
        (a.min(p), b.max(p))
    });
    format!(
        "boundary elements: exact linear-elastic, frictionless, small-slope half-space solution of \
         the pixel map (the only error is the discretisation). Measured here against it, at the {} \
         states from p = {plo:.4e} to {phi:.4e} Pa: GW's area fraction {}, mean gap {}; \
         Persson's area fraction {}, mean gap {} (relative_differences, model/exact - 1)",
        cmp.differences.len(),
        range(|d| d.gw_area),
        range(|d| d.gw_mean_gap),
        range(|d| d.persson_area),
        range(|d| d.persson_mean_gap),
    )
}
