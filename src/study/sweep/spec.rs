//! What a sweep varies and which points it visits.

use crate::error::{Allowed, Error, Result};
use crate::numeric::mix::{derive_seed, Stream};
use rand::rngs::StdRng;
use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use serde::{Deserialize, Serialize};

/// One varied scene field: `PATH=FROM:TO:N`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Vary {
    /// Dotted scene path, e.g. `surface.sigma`.
    pub path: String,
    /// First value (scene units).
    pub from: f64,
    /// Last value.
    pub to: f64,
    /// Grid points; 0 when `N` was not given (allowed only in
    /// Latin-hypercube designs, which do not use it).
    pub n: usize,
}

impl Vary {
    /// Parses `PATH=FROM:TO:N` (or `PATH=FROM:TO` for Latin-hypercube
    /// designs, where `N` is not used: it is then recorded as 0, and
    /// [`SweepSpec::validate`] refuses it in a grid).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `--vary` with the text and what is wrong.
    pub fn parse(text: &str) -> Result<Vary> {
        let bad = |why: &str| {
            Error::invalid("vary", format!("{text:?}: {why} (expected PATH=FROM:TO:N)"))
        };
        let (path, range) = text.split_once('=').ok_or_else(|| bad("no '='"))?;
        let parts: Vec<&str> = range.split(':').collect();
        if path.trim().is_empty() || !(2..=3).contains(&parts.len()) {
            return Err(bad("malformed"));
        }
        let num = |s: &str| -> Result<f64> {
            let x: f64 = s
                .trim()
                .parse()
                .map_err(|_| bad(&format!("{s:?} is not a number")))?;
            Allowed::FINITE.check("vary", x)
        };
        let n = match parts.get(2) {
            Some(s) => s
                .trim()
                .parse::<usize>()
                .ok()
                .filter(|&n| n >= 1)
                .ok_or_else(|| bad(&format!("N = {s:?} must be a whole number >= 1")))?,
            None => 0,
        };
        Ok(Vary {
            path: path.trim().to_string(),
            from: num(parts[0])?,
            to: num(parts[1])?,
            n,
        })
    }

    /// Value at fraction `t` in `[0, 1]` of the range, linear or geometric.
    fn at(&self, t: f64, log: bool) -> f64 {
        if log {
            (self.from.ln() + t * (self.to.ln() - self.from.ln())).exp()
        } else {
            self.from + t * (self.to - self.from)
        }
    }
}

/// How points are placed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Design {
    /// Full grid: every combination of each field's `N` values, the first
    /// `--vary` slowest.
    Grid,
    /// Latin-hypercube sample of `samples` points drawn with `seed`: each
    /// field's range split into `samples` strata, each stratum used once,
    /// a uniform jitter inside it.
    Latin {
        /// Number of points.
        samples: usize,
    },
}

/// A whole sweep: fields, design, spacing and the base seed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepSpec {
    /// The varied fields.
    pub vary: Vec<Vary>,
    /// Grid or Latin hypercube.
    pub design: Design,
    /// Geometric (log) spacing for every field (ranges must be > 0).
    pub log: bool,
    /// Base seed: Latin-hypercube draws and each point's own seed.
    pub seed: u64,
}

/// One point of a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepPoint {
    /// Position in the sweep (0-based); rows are sorted by it.
    pub index: usize,
    /// Values of the varied fields, in `--vary` order.
    pub values: Vec<f64>,
    /// The point's own seed (for Monte Carlo scenes), from the base seed
    /// and the index (SplitMix64), so it does not depend on threads or
    /// shards.
    pub seed: u64,
}

impl SweepPoint {
    /// The seed of point `index` of a sweep with base seed `seed`:
    /// [`derive_seed`] of [`Stream::SweepPoint`].
    pub fn seed_of(seed: u64, index: usize) -> u64 {
        derive_seed(seed, Stream::SweepPoint(index as u64))
    }
}

/// `x` rounded to 15 significant digits, so grid values that are short
/// decimals print as such (`3.2e-9`, not `3.2000000000000005e-9`); the
/// change is below 1e-15 relative.
fn round15(x: f64) -> f64 {
    format!("{x:.14e}").parse().unwrap_or(x)
}

/// Most points a sweep may have (and the memory available: see
/// [`SweepSpec::memory_estimate`]).
pub const MAX_POINTS: usize = 100_000_000;

/// Bytes per point of a sweep's bookkeeping besides its values: the point
/// (index, seed, its values' vector), the shard's and the to-do lists,
/// and the distinct-value check (measured: 944 MB peak for 1e7 points of
/// one varied field, 94 bytes per point, so 9.4 GB at [`MAX_POINTS`]).
pub const BYTES_PER_POINT: f64 = 88.0;

/// Bytes per varied value of each point.
pub const BYTES_PER_VALUE: f64 = 8.0;

impl SweepSpec {
    /// Checks the fields are distinct, the grid is not empty or huge, and
    /// log ranges are positive.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `--vary`, `--samples` or `--log`.
    pub fn validate(&self) -> Result<()> {
        if self.vary.is_empty() {
            return Err(Error::invalid(
                "vary",
                "give at least one --vary PATH=FROM:TO:N",
            ));
        }
        for (i, v) in self.vary.iter().enumerate() {
            if self.vary[..i].iter().any(|w| w.path == v.path) {
                return Err(Error::invalid(
                    "vary",
                    format!("{} is varied twice", v.path),
                ));
            }
            if v.n == 0 && matches!(self.design, Design::Grid) {
                return Err(Error::invalid(
                    "vary",
                    format!(
                        "{}={}:{} has no N: a grid needs PATH=FROM:TO:N \
                         (or give --samples K for a Latin hypercube)",
                        v.path, v.from, v.to
                    ),
                ));
            }
            if self.log && !(v.from > 0.0 && v.to > 0.0) {
                return Err(Error::invalid(
                    "log",
                    format!(
                        "{}: a log range needs FROM and TO > 0, got {}:{}",
                        v.path, v.from, v.to
                    ),
                ));
            }
        }
        let total = self.total();
        if total == 0 || total > MAX_POINTS {
            return Err(Error::invalid(
                self.count_name(),
                format!("{total} points; allowed 1 ..= {MAX_POINTS}"),
            ));
        }
        let bytes = self.memory_estimate();
        if let Some(free) = crate::study::memory::available() {
            if bytes > free {
                return Err(Error::invalid(
                    self.count_name(),
                    format!(
                        "{total} points: the point list needs an estimated {:.3} GB ({} bytes \
                         per point with {} varied fields) before the first row, more than the \
                         {:.3} GB this process may still use; split the sweep (fewer points, or \
                         separate sweeps over parts of the range)",
                        bytes / 1e9,
                        BYTES_PER_POINT + BYTES_PER_VALUE * self.vary.len() as f64,
                        self.vary.len(),
                        free / 1e9
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The parameter that sets the number of points: `vary` for a grid,
    /// `samples` for a Latin hypercube.
    fn count_name(&self) -> &'static str {
        match self.design {
            Design::Grid => "vary",
            Design::Latin { .. } => "samples",
        }
    }

    /// How many points (saturating at `usize::MAX`).
    pub fn total(&self) -> usize {
        match self.design {
            Design::Grid => self
                .vary
                .iter()
                .try_fold(1usize, |acc, v| acc.checked_mul(v.n))
                .unwrap_or(usize::MAX),
            Design::Latin { samples } => samples,
        }
    }

    /// The estimated peak memory (bytes) of the sweep's bookkeeping, held
    /// before the first point runs: [`BYTES_PER_POINT`]` +
    /// `[`BYTES_PER_VALUE`]` x (varied fields)` per point.
    pub fn memory_estimate(&self) -> f64 {
        self.total() as f64 * (BYTES_PER_POINT + BYTES_PER_VALUE * self.vary.len() as f64)
    }

    /// Every point, in index order.
    pub fn points(&self) -> Vec<SweepPoint> {
        let values: Vec<Vec<f64>> = match self.design {
            Design::Grid => {
                let total: usize = self.vary.iter().map(|v| v.n).product();
                (0..total)
                    .map(|mut i| {
                        let mut vals = vec![0.0; self.vary.len()];
                        for (k, v) in self.vary.iter().enumerate().rev() {
                            let j = i % v.n;
                            i /= v.n;
                            let t = if v.n == 1 {
                                0.0
                            } else {
                                j as f64 / (v.n - 1) as f64
                            };
                            vals[k] = round15(v.at(t, self.log));
                        }
                        vals
                    })
                    .collect()
            }
            Design::Latin { samples } => {
                let mut rng = StdRng::seed_from_u64(self.seed);
                let mut cols = Vec::with_capacity(self.vary.len());
                for v in &self.vary {
                    let mut strata: Vec<usize> = (0..samples).collect();
                    strata.shuffle(&mut rng);
                    let col: Vec<f64> = strata
                        .iter()
                        .map(|&s| {
                            let u: f64 = rng.random();
                            v.at((s as f64 + u) / samples as f64, self.log)
                        })
                        .collect();
                    cols.push(col);
                }
                (0..samples)
                    .map(|i| cols.iter().map(|c| c[i]).collect())
                    .collect()
            }
        };
        values
            .into_iter()
            .enumerate()
            .map(|(index, values)| SweepPoint {
                index,
                values,
                seed: SweepPoint::seed_of(self.seed, index),
            })
            .collect()
    }
}

/// One slice of a sweep, `K/N`: the points whose index `i` has
/// `i mod N = K - 1`, so `N` slices cover the sweep exactly once.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    /// Which slice, 1-based.
    pub k: usize,
    /// How many slices.
    pub n: usize,
}

impl Shard {
    /// Parses `K/N` with `1 <= K <= N`.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `--shard`.
    pub fn parse(text: &str) -> Result<Shard> {
        let bad = || Error::invalid("shard", format!("{text:?}: expected K/N with 1 <= K <= N"));
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let k: usize = k.trim().parse().map_err(|_| bad())?;
        let n: usize = n.trim().parse().map_err(|_| bad())?;
        if k == 0 || k > n {
            return Err(bad());
        }
        Ok(Shard { k, n })
    }

    /// The slice of a Slurm job array task from its environment (`get`
    /// looks a variable up): `K = SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN
    /// + 1`, `N = SLURM_ARRAY_TASK_COUNT`, so arrays numbered from 0, 1 or
    /// any start use every slice. Stepped (`--array=0-15:2`) or sparse
    /// (`--array=1,3,8`) arrays are refused: their ids do not map onto
    /// `1..=N`.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `shard-from-env` when a variable is missing
    /// or not an integer, or the array is stepped or sparse.
    pub fn from_slurm(get: impl Fn(&str) -> Option<String>) -> Result<Shard> {
        let var = |name: &str| -> Result<usize> {
            let v = get(name).ok_or_else(|| {
                Error::invalid(
                    "shard-from-env",
                    format!("{name} is not set (not a Slurm job array task?)"),
                )
            })?;
            v.trim().parse().map_err(|_| {
                Error::invalid(
                    "shard-from-env",
                    format!("{name} = {v:?} is not a non-negative integer"),
                )
            })
        };
        let (id, min, max, count) = (
            var("SLURM_ARRAY_TASK_ID")?,
            var("SLURM_ARRAY_TASK_MIN")?,
            var("SLURM_ARRAY_TASK_MAX")?,
            var("SLURM_ARRAY_TASK_COUNT")?,
        );
        let step = match get("SLURM_ARRAY_TASK_STEP") {
            Some(_) => var("SLURM_ARRAY_TASK_STEP")?,
            None => 1,
        };
        if step != 1 || max < min || max - min + 1 != count || id < min || id > max {
            return Err(Error::invalid(
                "shard-from-env",
                format!(
                    "array ids {min}..={max} step {step} with {count} tasks (this one {id}): \
                     only contiguous arrays with step 1 map onto slices 1..=N; use --shard K/N"
                ),
            ));
        }
        Ok(Shard {
            k: id - min + 1,
            n: count,
        })
    }

    /// Whether point `index` belongs to this slice.
    pub fn contains(&self, index: usize) -> bool {
        index % self.n == self.k - 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `--array=1-16` with `$((SLURM_ARRAY_TASK_ID+1))/$SLURM_ARRAY_TASK_COUNT`
    /// asked for shard 17/16 and left slice 1 undone; from the environment
    /// the slices are 1..=16 whatever the array's first id.
    #[test]
    fn slurm_arrays_map_onto_every_slice() {
        let env = |id: usize, min: usize, max: usize, step: Option<usize>| {
            move |name: &str| match name {
                "SLURM_ARRAY_TASK_ID" => Some(id.to_string()),
                "SLURM_ARRAY_TASK_MIN" => Some(min.to_string()),
                "SLURM_ARRAY_TASK_MAX" => Some(max.to_string()),
                "SLURM_ARRAY_TASK_COUNT" => Some(((max - min) / step.unwrap_or(1) + 1).to_string()),
                "SLURM_ARRAY_TASK_STEP" => step.map(|s| s.to_string()),
                _ => None,
            }
        };
        for min in [0, 1, 7] {
            let ks: Vec<usize> = (min..min + 16)
                .map(|id| Shard::from_slurm(env(id, min, min + 15, None)).unwrap().k)
                .collect();
            assert_eq!(ks, (1..=16).collect::<Vec<_>>());
            assert_eq!(
                Shard::from_slurm(env(min, min, min + 15, None)).unwrap().n,
                16
            );
        }
        let e = Shard::from_slurm(env(2, 0, 14, Some(2))).unwrap_err();
        assert_eq!(e.field(), Some("shard-from-env"));
        let e = Shard::from_slurm(|_: &str| None).unwrap_err();
        assert!(
            e.to_string().contains("SLURM_ARRAY_TASK_ID is not set"),
            "{e}"
        );
    }

    #[test]
    fn vary_parses_and_rejects() {
        let v = Vary::parse("surface.sigma=2e-9:8e-9:6").unwrap();
        assert_eq!(
            (v.path.as_str(), v.from, v.to, v.n),
            ("surface.sigma", 2e-9, 8e-9, 6)
        );
        for bad in [
            "sigma",
            "a=1:2:0",
            "a=1:x:3",
            "a=1",
            "=1:2:3",
            "a=nan:1:2",
            "a=1:2:3:4",
        ] {
            assert_eq!(Vary::parse(bad).unwrap_err().field(), Some("vary"), "{bad}");
        }
    }

    #[test]
    fn grid_is_row_major_and_log_is_geometric() {
        let spec = SweepSpec {
            vary: vec![
                Vary::parse("a=1:3:3").unwrap(),
                Vary::parse("b=10:1000:3").unwrap(),
            ],
            design: Design::Grid,
            log: true,
            seed: 7,
        };
        spec.validate().unwrap();
        let p = spec.points();
        assert_eq!(p.len(), 9);
        assert_eq!(p[1].values[0], 1.0);
        assert!((p[1].values[1] - 100.0).abs() < 1e-12);
        assert!((p[3].values[0] - 3f64.sqrt()).abs() < 1e-12);
        assert_ne!(p[0].seed, p[1].seed);
        let lin = SweepSpec {
            vary: vec![Vary::parse("s=2e-9:8e-9:6").unwrap()],
            design: Design::Grid,
            log: false,
            seed: 0,
        };
        let v: Vec<f64> = lin.points().iter().map(|p| p.values[0]).collect();
        assert_eq!(v, vec![2e-9, 3.2e-9, 4.4e-9, 5.6e-9, 6.8e-9, 8e-9]);
    }

    #[test]
    fn latin_hypercube_uses_each_stratum_once_and_is_seeded() {
        let spec = SweepSpec {
            vary: vec![
                Vary::parse("a=0:1").unwrap(),
                Vary::parse("b=0:10").unwrap(),
            ],
            design: Design::Latin { samples: 50 },
            log: false,
            seed: 3,
        };
        let p = spec.points();
        for (k, scale) in [(0, 1.0), (1, 10.0)] {
            let mut strata: Vec<usize> = p
                .iter()
                .map(|q| (q.values[k] / scale * 50.0) as usize)
                .collect();
            strata.sort_unstable();
            assert_eq!(strata, (0..50).collect::<Vec<_>>());
        }
        assert_eq!(spec.points(), p);
        let other = SweepSpec {
            seed: 4,
            ..spec.clone()
        }
        .points();
        assert_ne!(other, p);
    }

    #[test]
    fn bad_specs_and_shards_are_rejected() {
        let mut spec = SweepSpec {
            vary: vec![],
            design: Design::Grid,
            log: false,
            seed: 0,
        };
        assert_eq!(spec.validate().unwrap_err().field(), Some("vary"));
        spec.vary = vec![Vary::parse("a=-1:1:3").unwrap()];
        spec.log = true;
        assert_eq!(spec.validate().unwrap_err().field(), Some("log"));
        spec.log = false;
        spec.vary.push(Vary::parse("a=0:1:2").unwrap());
        assert_eq!(spec.validate().unwrap_err().field(), Some("vary"));
        spec.vary.pop();
        // A grid field without N would silently run one point.
        spec.vary = vec![Vary::parse("a=0:1").unwrap()];
        let e = spec.validate().unwrap_err();
        assert_eq!(e.field(), Some("vary"));
        assert!(e.to_string().contains("has no N"), "{e}");
        spec.design = Design::Latin { samples: 3 };
        spec.validate().unwrap();
        spec.design = Design::Latin { samples: 0 };
        assert_eq!(spec.validate().unwrap_err().field(), Some("samples"));
        for bad in ["0/3", "4/3", "x/2", "1"] {
            assert_eq!(Shard::parse(bad).unwrap_err().field(), Some("shard"));
        }
        let s = Shard::parse("2/3").unwrap();
        assert!(s.contains(1) && s.contains(4) && !s.contains(0));
    }
}
