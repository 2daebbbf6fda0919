//! FFT boundary elements: an elastic half-space (contact modulus `E*`)
//! against a rigid rough surface given as a height map (equivalently two
//! rough elastic bodies with the composite surface and the composite
//! modulus).
//!
//! - [`operator`]: the half-space compliance by FFT, periodic or padded
//!   (non-periodic).
//! - `contact`: load control without adhesion, Polonsky & Keer's (1999)
//!   constrained conjugate gradients in the pressure, preconditioned by
//!   the stiffness `K^-1` on periodic maps.
//! - `full_contact`: load control on a periodic map at and near full
//!   contact: the exact full-contact state `p = K^-1 h + P` at once when
//!   every pixel of it is pressed, else, when few are not, conjugate
//!   gradients in the gap on the small non-contact set.
//! - `gap_control`: mean-gap control on a periodic map, with or without the
//!   exponential adhesion of Rey, Anciaux & Molinari (2017).
//! - [`challenge`]: the contact-mechanics challenge's spectrum, material,
//!   interaction and generated surface.
//! - [`clusters`]: connected contact spots and their size distribution;
//!   [`resistance`]: their constriction resistance.
//! - `roughness`: the map's RMS gradient, curvature and full-contact
//!   energy, the scales of the stickiness criteria ([`Problem::roughness`]).
//! - [`compare`]: the exact states of a map beside GW (its moments) and
//!   Persson (its radial spectrum) at the same mean pressures, with their
//!   relative differences and warnings as data.
//!
//! The remaining combinations are outer monotone root-finds around these
//! two solvers (Brent's method of [`crate::numeric::roots`] in the log of
//! the control variable): mean-gap control on a padded map (the pressure
//! that gives the gap) and load control with adhesion (the gap that gives
//! the pressure).
//!
//! Sign conventions: heights `h` of the rigid surface point towards the
//! elastic body; the gap is `g = u - h + const >= 0`; pressure is positive
//! when compressive; a pixel is in (hard) contact when its gap is exactly 0.
//!
//! Memory is stated before anything is allocated ([`memory_estimate`]) and
//! bounded by [`Options::memory_limit`] (1 GiB by default: a 2048 x 2048 map
//! needs about 0.43 GiB periodic, 0.77 GiB padded).

pub mod challenge;
pub mod clusters;
pub mod compare;
mod contact;
pub(crate) mod fft;
mod full_contact;
mod gap_control;
pub mod operator;
mod passes;
mod plastic;
pub mod resistance;
mod roughness;

pub use clusters::{Cluster, SizeBin};
pub use gap_control::Exponential;

use crate::error::{positive, Allowed, Error, Result};
use crate::numeric::roots::try_brent;
use crate::surface::{HeightMap, Plane};
use operator::HalfSpace;

/// Solver options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Stop when the residual of the contact conditions is below this
    /// (dimensionless, see the solvers' documentation). Default `1e-10`.
    pub tolerance: f64,
    /// Most conjugate-gradient iterations per solve. Default 10000.
    pub max_iterations: usize,
    /// Bytes the solver may use (checked before allocating). Default 1 GiB.
    pub memory_limit: usize,
    /// At the iteration cap, return the last iterate with
    /// [`Solution::converged`] `false` (its residual measured) instead of
    /// [`Error::NoConvergence`]. Default `false`.
    pub allow_unconverged: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            tolerance: 1e-10,
            max_iterations: 10_000,
            memory_limit: 1 << 30,
            allow_unconverged: false,
        }
    }
}

/// The words every solver's [`Error::NoConvergence`] at its iteration cap
/// ends its `what` with (a front end tells a cap from a breakdown by them).
pub const AT_CAP: &str = "stopped at the iteration cap";

/// The end of a solve at the iteration cap with the last iterate `s` (its
/// residual measured): `s` flagged unconverged when
/// [`Options::allow_unconverged`], else [`Error::NoConvergence`] naming
/// `solver`, the iterations and the residual.
pub(crate) fn at_cap(mut s: Solution, options: &Options, solver: &str) -> Result<Solution> {
    if options.allow_unconverged {
        s.converged = false;
        return Ok(s);
    }
    Err(Error::NoConvergence {
        what: format!("{solver}: {AT_CAP}"),
        iterations: s.iterations,
        residual: s.residual,
    })
}

/// One converged state's fields (row-major, the map's shape).
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// Pressure (Pa), compressive > 0 (tensile where adhesion pulls).
    pub pressure: Vec<f64>,
    /// Gap (m), exactly 0 in contact.
    pub gap: Vec<f64>,
    /// Mean pressure (Pa).
    pub mean_pressure: f64,
    /// Mean gap (m): the separation of the mean planes.
    pub mean_gap: f64,
    /// Pixels in contact.
    pub contact_pixels: usize,
    /// Conjugate-gradient iterations of the last solve.
    pub iterations: usize,
    /// Final residual (see the solver).
    pub residual: f64,
    /// Whether the residual fell below the tolerance (`false` only for a
    /// solve stopped at the iteration cap with
    /// [`Options::allow_unconverged`]).
    pub converged: bool,
    /// Pixels at the hardness `p = H` (plastic; 0 without a hardness).
    pub plastic_pixels: usize,
    /// Plastically displaced volume per nominal area (m): the mean over
    /// the map of the interpenetration `-g >= 0` the elastic field leaves
    /// on the plastic pixels, `(1/N) sum_{p = H} (h + c - u)`; times the
    /// nominal area it is the volume of material displaced (m^3). 0
    /// without a hardness.
    pub plastic_volume_per_area: f64,
    /// Elastic energy stored per nominal area (J/m^2),
    /// `U/A0 = (1/2) mean(p u)` with `u = K p` the displacement of the
    /// returned pressure (periodic: the zero-mean displacement, so in full
    /// contact `U/A0 = (1/2) mean(h K^-1 h)`, Persson's `U_full/A0` of the
    /// map, [`crate::stickiness::Roughness::full_contact_energy`]).
    pub elastic_energy_per_area: f64,
}

/// How one boundary-element solve ended, as the outputs state it (the
/// keys `iterations`, `residual`, `converged` of `asperity bem --json`'s
/// states and of a scene's map states).
#[derive(serde::Serialize, Debug, Clone, Copy, PartialEq)]
pub struct SolveReport {
    /// Solver iterations (of the last solve).
    pub iterations: usize,
    /// Final residual (dimensionless; see the solver).
    pub residual: f64,
    /// Whether the residual fell below the tolerance.
    pub converged: bool,
}

impl Solution {
    /// Its [`SolveReport`]: iterations, residual, convergence.
    pub fn report(&self) -> SolveReport {
        SolveReport {
            iterations: self.iterations,
            residual: self.residual,
            converged: self.converged,
        }
    }

    /// From the pressure solver: contact where `p > 0`; gaps clipped at 0;
    /// plastic where `p >= hardness` (`inf`: none).
    fn from_fields(p: Vec<f64>, g: Vec<f64>, hardness: f64, it: usize, residual: f64) -> Self {
        let n = p.len() as f64;
        let (mut plastic_pixels, mut depth) = (0, 0.0);
        for (pi, gi) in p.iter().zip(&g) {
            if *pi >= hardness {
                plastic_pixels += 1;
                depth += (-gi).max(0.0);
            }
        }
        let gap: Vec<f64> = p
            .iter()
            .zip(&g)
            .map(|(pi, gi)| if *pi > 0.0 { 0.0 } else { gi.max(0.0) })
            .collect();
        let contact_pixels = p.iter().filter(|v| **v > 0.0).count();
        Solution {
            mean_pressure: p.iter().sum::<f64>() / n,
            mean_gap: gap.iter().sum::<f64>() / n,
            pressure: p,
            gap,
            contact_pixels,
            iterations: it,
            residual,
            converged: true,
            plastic_pixels,
            plastic_volume_per_area: depth / n,
            elastic_energy_per_area: 0.0,
        }
    }

    /// From the gap solver: contact where `g <= 0` (freed pixels may keep
    /// a gap a rounding below 0: they are in contact too).
    fn from_gap_fields(p: Vec<f64>, g: Vec<f64>, p_mean: f64, it: usize, residual: f64) -> Self {
        let n = g.len() as f64;
        Solution {
            mean_pressure: p_mean,
            mean_gap: g.iter().sum::<f64>() / n,
            contact_pixels: g.iter().filter(|v| **v <= 0.0).count(),
            pressure: p,
            gap: g,
            iterations: it,
            residual,
            converged: true,
            plastic_pixels: 0,
            plastic_volume_per_area: 0.0,
            elastic_energy_per_area: 0.0,
        }
    }

    /// From the gap solver with a hardness `hard`: `g` the signed gap
    /// (`g < 0` plastic, its pressure exactly `hard`); the returned gap is
    /// clipped at 0; `p_mean` the solver's mean pressure (the multiplier).
    fn from_capped_gap_fields(
        mut p: Vec<f64>,
        g: &[f64],
        (hard, p_mean): (f64, f64),
        it: usize,
        residual: f64,
    ) -> Self {
        let n = g.len() as f64;
        let (mut plastic_pixels, mut depth) = (0, 0.0);
        for (pi, gi) in p.iter_mut().zip(g) {
            if *gi < 0.0 {
                *pi = hard;
                plastic_pixels += 1;
                depth -= gi;
            }
        }
        let gap: Vec<f64> = g.iter().map(|v| v.max(0.0)).collect();
        Solution {
            mean_pressure: p_mean,
            mean_gap: gap.iter().sum::<f64>() / n,
            contact_pixels: g.iter().filter(|v| **v <= 0.0).count(),
            pressure: p,
            gap,
            iterations: it,
            residual,
            converged: true,
            plastic_pixels,
            plastic_volume_per_area: depth / n,
            elastic_energy_per_area: 0.0,
        }
    }

    /// Whether every pixel is in contact (then [`Solution::area_fraction`]
    /// is exactly 1; it is below 1 whenever one pixel is open).
    pub fn full_contact(&self) -> bool {
        self.contact_pixels == self.gap.len()
    }

    /// Fraction of the pixels in contact.
    pub fn area_fraction(&self) -> f64 {
        self.contact_pixels as f64 / self.gap.len() as f64
    }

    /// Fraction of the pixels at the hardness (plastic).
    pub fn plastic_fraction(&self) -> f64 {
        self.plastic_pixels as f64 / self.gap.len() as f64
    }

    /// The contact map (`true` where the gap is 0, or a rounding below it).
    pub fn contact(&self) -> Vec<bool> {
        self.gap.iter().map(|g| *g <= 0.0).collect()
    }
}

/// Bytes a solve on `rows x cols` needs: the operator's kernels and FFT
/// buffers (`HalfSpace::bytes`) plus 10 fields of `rows cols` f64 (heights,
/// pressure, gap, search direction, its image, displacement, the previous
/// state for warm starts, the returned fields) and the cluster labels.
pub fn memory_estimate(rows: usize, cols: usize, periodic: bool) -> usize {
    HalfSpace::bytes(rows, cols, periodic) + (10 * 8 + 4 + 1) * rows * cols
}

/// A map, a material and the half-space operator: everything but the load.
#[derive(Debug)]
pub struct Problem {
    rows: usize,
    cols: usize,
    pixel_size: f64,
    pixel_size_y: f64,
    contact_modulus: f64,
    periodic: bool,
    heights: Vec<f64>,
    h_rms: f64,
    p_ref: f64,
    op: HalfSpace,
    adhesion: Option<Exponential>,
    hardness: Option<f64>,
}

/// Pixel sizes (m) of any measured or synthetic map, 1 pm to 1 km: named
/// when a modulus is out of [`modulus_range`] because the pixel is absurd.
const PIXEL_SIZES: Allowed = Allowed::open(1e-12, 1e3);

/// The contact moduli (Pa) whose Fourier kernels stay far inside the
/// normal range of f64 on a `rows x cols` map of `dx x dy` pixels: the
/// compliance `~ dx/(E* N)` and the stiffness `~ E* L/N` (`N` the FFT
/// size, `L` the map's side) between 1e-290 and 1e290, so
/// `E*` in `(1e-290 L N, 1e290 min(dx, dy)/N)`. Beyond it the kernels
/// would be subnormal (digits lost: the iterations stall at their cap)
/// or overflow; every physical modulus is far inside.
fn modulus_range(rows: usize, cols: usize, (dx, dy): (f64, f64), periodic: bool) -> Allowed {
    let n = (rows * cols) as f64 * if periodic { 1.0 } else { 4.0 };
    let side = (cols as f64 * dx).max(rows as f64 * dy);
    Allowed::open(1e-290 * side * n, 1e290 * dx.min(dy) / n)
}

impl Problem {
    /// The problem for `map` (heights in m, mean plane removed here, only
    /// the mean when `periodic`), square pixels of `pixel_size` m and
    /// contact modulus `contact_modulus` Pa.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `pixel_size` or `contact_modulus` (also
    /// beyond the range whose kernels f64 holds, `modulus_range`);
    /// [`Error::Invalid`] named `topography` when the map is flat or when
    /// [`memory_estimate`] exceeds `options.memory_limit` (the message gives
    /// both).
    pub fn new(
        map: &HeightMap,
        pixel_size: f64,
        contact_modulus: f64,
        periodic: bool,
        options: &Options,
    ) -> Result<Self> {
        positive("pixel_size", pixel_size)?;
        Problem::with_pixels(
            map,
            (pixel_size, pixel_size),
            contact_modulus,
            periodic,
            options,
        )
    }

    /// As [`Problem::new`] with rectangular pixels of `dx` along x (a row)
    /// by `dy` along y (a column) (m): the Love coefficient of a rectangle
    /// ([`operator::love_rect`]), the periodic wavenumbers
    /// `2 pi (kx/(cols dx), ky/(rows dy))`, the plane and gradients in
    /// physical coordinates; square pixels give [`Problem::new`]'s bits.
    ///
    /// # Errors
    /// As [`Problem::new`]; `pixel_size_y` for a bad `dy`.
    pub fn with_pixels(
        map: &HeightMap,
        (pixel_size, pixel_size_y): (f64, f64),
        contact_modulus: f64,
        periodic: bool,
        options: &Options,
    ) -> Result<Self> {
        positive("pixel_size", pixel_size)?;
        positive("pixel_size_y", pixel_size_y)?;
        positive("contact_modulus", contact_modulus)?;
        let (rows, cols) = (map.rows(), map.cols());
        let moduli = modulus_range(rows, cols, (pixel_size, pixel_size_y), periodic);
        if !moduli.contains(contact_modulus) {
            // The product decides; an absurd pixel size is the one named.
            PIXEL_SIZES.check("pixel_size", pixel_size)?;
            PIXEL_SIZES.check("pixel_size_y", pixel_size_y)?;
            moduli.check("contact_modulus", contact_modulus)?;
        }
        let need = memory_estimate(rows, cols, periodic);
        if need > options.memory_limit {
            return Err(Error::invalid(
                "topography",
                format!(
                    "{rows} x {cols} pixels ({}) need about {:.0} MiB, above the limit of {:.0} MiB",
                    if periodic { "periodic" } else { "padded to twice the size" },
                    need as f64 / 1048576.0,
                    options.memory_limit as f64 / 1048576.0
                ),
            ));
        }
        let plane = Plane::fit_xy(
            map.heights(),
            rows,
            cols,
            (pixel_size, pixel_size_y),
            periodic,
        );
        let heights = plane.residual(map.heights(), cols);
        let n = heights.len() as f64;
        let h_rms = (heights.iter().map(|v| v * v).sum::<f64>() / n).sqrt();
        if !(h_rms > 0.0) {
            return Err(Error::invalid(
                "topography",
                "flat: no contact problem to solve",
            ));
        }
        let op = HalfSpace::with_pixels(
            rows,
            cols,
            (pixel_size, pixel_size_y),
            contact_modulus,
            periodic,
        );
        // Full-contact RMS pressure E* g/2, g from the discrete gradient
        // (differences down a column in units of dx: (dx/dy)^2 = 1 exactly
        // for square pixels).
        let ry = (pixel_size / pixel_size_y).powi(2);
        let mut g2 = 0.0;
        for i in 0..rows {
            for j in 0..cols {
                let k = i * cols + j;
                if j + 1 < cols {
                    g2 += (heights[k + 1] - heights[k]).powi(2);
                }
                if i + 1 < rows {
                    g2 += ry * (heights[k + cols] - heights[k]).powi(2);
                }
            }
        }
        let slope = (g2 / n).sqrt() / pixel_size;
        Ok(Problem {
            rows,
            cols,
            pixel_size,
            pixel_size_y,
            contact_modulus,
            periodic,
            heights,
            h_rms,
            p_ref: 0.5 * contact_modulus * slope,
            op,
            adhesion: None,
            hardness: None,
        })
    }

    /// The same problem with the exponential adhesion `-w exp(-g/rho)`
    /// (`energy` `w` J/m^2, `range` `rho` m).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `adhesion_energy` or `adhesion_range`;
    /// [`Error::Invalid`] named `periodic` on a padded map (the gap solver
    /// needs the periodic stiffness). With a hardness
    /// ([`Problem::with_hardness`]) the compressive pressure is capped at
    /// `H` as well (the gap solver's plastic extension, `docs/physics.md`).
    pub fn with_adhesion(mut self, energy: f64, range: f64) -> Result<Self> {
        positive("adhesion_energy", energy)?;
        positive("adhesion_range", range)?;
        if !self.periodic {
            return Err(Error::invalid(
                "periodic",
                "adhesion is solved on periodic maps only (the gap solver needs the periodic stiffness)",
            ));
        }
        self.adhesion = Some(Exponential { energy, range });
        Ok(self)
    }

    /// The same problem, elastic–perfectly-plastic: the contact pressure
    /// capped at the hardness `H` (`hardness`, Pa). The pressure is the
    /// minimiser of the complementary energy `(1/2) p.K p - p.h` over
    /// `0 <= p <= H` at the imposed mean; on the plastic pixels (`p = H`)
    /// the rigid surface passes through the elastic one by the
    /// interpenetration `-g` (the material displaced plastically,
    /// [`Solution::plastic_volume_per_area`]) (Almqvist, Sahlin, Larsson &
    /// Glavatskih 2007, Tribol. Int. 40, 574; `docs/physics.md`). A mean
    /// pressure above `H` has no solution.
    ///
    /// With adhesion ([`Problem::with_adhesion`], periodic maps) the
    /// exponential interaction acts where the gap is open and the
    /// compressive contact pressure is capped at `H`: the gap solver with
    /// the interaction extended below `g = 0` by `phi(0) - H g`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `hardness` (finite, > 0).
    pub fn with_hardness(mut self, hardness: f64) -> Result<Self> {
        positive("hardness", hardness)?;
        self.hardness = Some(hardness);
        Ok(self)
    }

    /// The hardness `H` (Pa), if the problem is elastic–perfectly-plastic.
    pub fn hardness(&self) -> Option<f64> {
        self.hardness
    }

    /// Rows, columns.
    pub fn shape(&self) -> (usize, usize) {
        (self.rows, self.cols)
    }

    /// Pixel size (m) along x (a row).
    pub fn pixel_size(&self) -> f64 {
        self.pixel_size
    }

    /// Pixel sizes `(dx, dy)` (m) along x (a row) and y (a column).
    pub fn pixel_sizes(&self) -> (f64, f64) {
        (self.pixel_size, self.pixel_size_y)
    }

    /// Contact modulus (Pa).
    pub fn contact_modulus(&self) -> f64 {
        self.contact_modulus
    }

    /// Whether the map is periodic.
    pub fn periodic(&self) -> bool {
        self.periodic
    }

    /// The heights the solver uses (mean plane removed), row-major (m).
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }

    /// RMS of the heights (m).
    pub fn h_rms(&self) -> f64 {
        self.h_rms
    }

    /// The mean gap at first touch, `max h - mean h` (m).
    pub fn zero_load_gap(&self) -> f64 {
        self.heights
            .iter()
            .cloned()
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// The state at mean pressure `pressure > 0` (Pa; at most the hardness
    /// when there is one), warm-started from `warm` (a previous solution)
    /// if given.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `pressure`; [`Error::NoConvergence`].
    pub fn solve_pressure(
        &self,
        pressure: f64,
        options: &Options,
        warm: Option<&Solution>,
    ) -> Result<Solution> {
        self.solve_pressure_fields(pressure, options, warm)
            .map(|s| self.with_energy(s))
    }

    /// The elastic energy per nominal area of `s`'s pressure,
    /// [`Solution::elastic_energy_per_area`].
    fn with_energy(&self, mut s: Solution) -> Solution {
        let mut u = vec![0.0; s.pressure.len()];
        self.op.displacement(&s.pressure, &mut u);
        let n = u.len() as f64;
        s.elastic_energy_per_area =
            0.5 * s.pressure.iter().zip(&u).map(|(p, u)| p * u).sum::<f64>() / n;
        s
    }

    /// [`Problem::solve_pressure`] without the energy.
    fn solve_pressure_fields(
        &self,
        pressure: f64,
        options: &Options,
        warm: Option<&Solution>,
    ) -> Result<Solution> {
        positive("pressure", pressure)?;
        if let Some(h) = self.hardness {
            crate::error::Allowed::open_closed(0.0, h).check("pressure", pressure)?;
        }
        if self.adhesion.is_some() {
            // The gap that gives the pressure (P decreases with the gap).
            let start = warm.map_or(self.h_rms, |w| w.mean_gap.max(1e-6 * self.h_rms));
            let mut last: Option<Solution> = warm.cloned();
            let tol = options.tolerance.max(1e-12) * pressure.abs().max(1e-3 * self.p_ref);
            let s = monotone_root(start, pressure, tol, true, |g| {
                let s = self.solve_gap_fields(g, options, last.as_ref())?;
                let v = s.mean_pressure;
                last = Some(s.clone());
                Ok((v, s))
            })?;
            // Strong short-range adhesion makes the mean pressure jump with
            // the mean gap (a region snaps into contact): the root search
            // then ends at the jump, on a state of another pressure. (A
            // steep but continuous curve misses by its slope times the
            // search's 1e-14 in ln g: far below 1e-8.)
            if (s.mean_pressure - pressure).abs() > tol.max(1e-8 * pressure.abs()) {
                return Err(Error::invalid(
                    "pressure",
                    format!(
                        "no state with a mean pressure of {pressure:e} Pa on the mean-gap \
                         path: near a mean gap of {:e} m the mean pressure jumps across it \
                         (the closest state found has {:e} Pa): adhesion makes part of the \
                         surface snap into contact there; ask for the state by its mean gap, \
                         or for a pressure outside the jump",
                        s.mean_gap, s.mean_pressure
                    ),
                ));
            }
            return Ok(s);
        }
        let warm_gap = warm.map(|w| w.gap.as_slice());
        let warm = warm.map(|w| w.pressure.as_slice());
        match self.hardness {
            Some(hardness) => plastic::solve_load(
                &self.op,
                &self.heights,
                self.h_rms,
                pressure,
                hardness,
                options,
                warm,
            ),
            None if self.periodic => {
                // At or near full contact (module `full_contact`).
                let p_full = full_contact::full_pressure(&self.op, &self.heights, pressure);
                if let Some(s) =
                    full_contact::exact(&self.op, &self.heights, self.h_rms, &p_full, options)
                {
                    return Ok(s);
                }
                if full_contact::open_fraction(&p_full) < full_contact::NEAR_FULL {
                    let warm_gap = warm_gap.filter(|w| w.iter().any(|g| *g > 0.0));
                    return full_contact::solve_load(
                        &self.op,
                        (&self.heights, self.h_rms, self.p_ref),
                        pressure,
                        &p_full,
                        options,
                        warm_gap,
                    );
                }
                contact::solve_load(&self.op, &self.heights, self.h_rms, pressure, options, warm)
            }
            None => {
                contact::solve_load(&self.op, &self.heights, self.h_rms, pressure, options, warm)
            }
        }
    }

    /// The state at mean gap `gap > 0` (m).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `gap`; [`Error::NoConvergence`].
    pub fn solve_gap(
        &self,
        gap: f64,
        options: &Options,
        warm: Option<&Solution>,
    ) -> Result<Solution> {
        self.solve_gap_fields(gap, options, warm)
            .map(|s| self.with_energy(s))
    }

    /// [`Problem::solve_gap`] without the energy.
    fn solve_gap_fields(
        &self,
        gap: f64,
        options: &Options,
        warm: Option<&Solution>,
    ) -> Result<Solution> {
        positive("gap", gap)?;
        if let Some(s) = self.separated(gap, options) {
            return Ok(s);
        }
        if let (true, Some(_), Some(_)) = (self.periodic, self.adhesion, self.hardness) {
            return self.solve_adhesive_plastic_gap(gap, options, warm);
        }
        if self.periodic && self.hardness.is_none() {
            return gap_control::solve_gap(
                &self.op,
                &self.heights,
                self.p_ref,
                gap,
                self.adhesion,
                options,
                warm.map(|w| w.gap.as_slice())
                    .filter(|w| w.iter().sum::<f64>() > 0.0),
            );
        }
        // Padded or plastic: the pressure that gives the gap (the gap
        // decreases with p; above the hardness it is the fully plastic 0).
        let cap = self.hardness.unwrap_or(f64::INFINITY);
        let start = warm.map_or((1e-2 * self.p_ref).min(0.5 * cap), |w| {
            w.mean_pressure.max(1e-9 * self.p_ref)
        });
        let mut last: Option<Solution> = warm.cloned();
        let tol = (10.0 * options.tolerance).max(1e-12) * self.h_rms;
        monotone_root(start, gap, tol, true, |p| {
            let s = self.solve_pressure_fields(p.min(cap), options, last.as_ref())?;
            let v = s.mean_gap;
            last = Some(s.clone());
            Ok((v, s))
        })
    }

    /// Adhesion with a hardness at mean (clipped) gap `gap`: the gap
    /// solver imposes the mean `m` of the signed gap (the approach), and the
    /// mean separation is `m + V_pl/A0` (the displaced volume per area), so
    /// the state is found at `m = gap` first and, if it has plastic pixels,
    /// by [`monotone_root`] on `x = gap - m > 0` (the separation decreases
    /// with `x`) from `x` = that state's displaced volume per area; every
    /// solve warm-starts from the previous signed gap.
    fn solve_adhesive_plastic_gap(
        &self,
        gap: f64,
        options: &Options,
        warm: Option<&Solution>,
    ) -> Result<Solution> {
        let mut last: Option<Vec<f64>> = warm
            .map(|w| w.gap.clone())
            .filter(|w| w.iter().any(|v| *v != 0.0));
        let mut solve = |m: f64| -> Result<Solution> {
            let (s, g) = gap_control::solve_gap_capped(
                &self.op,
                &self.heights,
                self.p_ref,
                m,
                (self.adhesion, self.hardness),
                options,
                last.as_deref(),
            )?;
            last = Some(g);
            Ok(s)
        };
        let s = solve(gap)?;
        let tol = (10.0 * options.tolerance).max(1e-12) * self.h_rms;
        if (s.mean_gap - gap).abs() <= tol {
            return Ok(s);
        }
        let x0 = s.mean_gap - gap;
        monotone_root(x0, gap, tol, true, |x| {
            let s = solve(gap - x)?;
            Ok((s.mean_gap, s))
        })
    }

    /// The state at mean gap `gap` (m) when the surfaces stay apart, at
    /// once (no iteration): the rigid surface untouched, the gap
    /// `g = c - h` with `c` giving the mean `gap`. Without adhesion that is
    /// exact once `gap >= max h` ([`Problem::zero_load_gap`]), with zero
    /// pressure and residual. With the exponential adhesion the pixels
    /// carry the tension `-phi'(g) = -(w/rho) exp(-g/rho)`; the rigid state
    /// is returned when its residual, the RMS of that tension about its
    /// mean over `p_ref` (the gap solver's, with `K^-1 u = 0` for the
    /// uniform displacement), is below the tolerance. `None` otherwise
    /// (the solver is needed). Iterating there instead would only add
    /// rounding: `u = g + h` loses the heights' digits when `g >> h`.
    fn separated(&self, gap: f64, options: &Options) -> Option<Solution> {
        if gap < self.zero_load_gap() {
            return None;
        }
        let g = gap_control::rigid_gap(&self.heights, gap);
        let n = g.len() as f64;
        let Some(a) = self.adhesion else {
            return Some(Solution::from_gap_fields(
                vec![0.0; g.len()],
                g,
                0.0,
                0,
                0.0,
            ));
        };
        let tension: Vec<f64> = g
            .iter()
            .map(|gi| a.energy / a.range * (-gi / a.range).exp())
            .collect();
        let mean = tension.iter().sum::<f64>() / n;
        let rms = (tension.iter().map(|t| (t - mean).powi(2)).sum::<f64>() / n).sqrt();
        let residual = rms / self.p_ref;
        (residual < options.tolerance).then(|| {
            let p = tension.iter().map(|t| -t).collect();
            Solution::from_gap_fields(p, g, -mean, 0, residual)
        })
    }

    /// Contact clusters of a solution, largest first.
    pub fn clusters(&self, s: &Solution) -> Vec<Cluster> {
        clusters::clusters(&s.contact(), self.rows, self.cols, self.periodic)
    }
}

/// Finds `x > 0` with `f(x) = target` for `f` monotone (decreasing when
/// `decreasing`): bracket by factors of 4 from `x0`, then Brent's method
/// ([`try_brent`]) in `ln x`, stopped at the first evaluation with
/// `|f - target| <= tol` (it counts as an exact root) or when the bracket
/// is [`LN_X_TOL`] wide. Returns the solution at the root; every solve
/// warm-starts from the previous one (`f` keeps it).
fn monotone_root<F>(x0: f64, target: f64, tol: f64, decreasing: bool, mut f: F) -> Result<Solution>
where
    F: FnMut(f64) -> Result<(f64, Solution)>,
{
    let sign = if decreasing { -1.0 } else { 1.0 };
    let mut eval = |x: f64| -> Result<(f64, Solution)> {
        let (v, s) = f(x)?;
        Ok((sign * (v - target), s))
    };
    let (mut a, (mut fa, sa)) = (x0, eval(x0)?);
    if fa.abs() <= tol {
        return Ok(sa);
    }
    // fa > 0: x too large (increasing form); step down, else up.
    let step = if fa > 0.0 { 0.25 } else { 4.0 };
    let (mut b, mut fb, mut sb);
    let mut k = 0;
    loop {
        b = a * step;
        (fb, sb) = eval(b)?;
        if fb.abs() <= tol {
            return Ok(sb);
        }
        if fb.signum() != fa.signum() {
            break;
        }
        a = b;
        fa = fb;
        k += 1;
        if k > 60 {
            return Err(Error::NoConvergence {
                what: "boundary elements: bracketing the control variable".into(),
                iterations: k,
                residual: fb.abs(),
            });
        }
    }
    // The bracket's ends are known: Brent asks for them first.
    let (la, lb) = (a.ln(), b.ln());
    let mut best = (lb, fb.abs(), sb);
    let mut solves = 0;
    let root = try_brent(
        |lx| {
            if lx == la {
                return Ok(fa);
            }
            if lx == lb {
                return Ok(fb);
            }
            solves += 1;
            let (v, s) = eval(lx.exp())?;
            if v.abs() < best.1 {
                best = (lx, v.abs(), s);
            }
            Ok(if v.abs() <= tol { 0.0 } else { v })
        },
        la,
        lb,
        LN_X_TOL,
    )?;
    let Some(root) = root else {
        return Err(Error::NoConvergence {
            what: "boundary elements: the control variable".into(),
            iterations: solves,
            residual: best.1,
        });
    };
    if root == best.0 {
        return Ok(best.2);
    }
    // Brent ended on another point than the best evaluated one.
    eval(root.exp()).map(|(_, s)| s)
}

/// Width in `ln x` at which [`monotone_root`] stops: the control variable
/// to 1e-14 relative.
const LN_X_TOL: f64 = 1e-14;
