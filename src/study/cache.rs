//! The on-disk cache of sphere-solver calibrations: JSON files in one
//! directory, named by [`Calibration::key`], so scenes and sweeps never
//! recompute a calibration. Each entry carries the FNV-1a 64-bit checksum
//! of its calibration's canonical JSON (`{"fnv1a64": "...", "calibration":
//! {...}}`): an entry altered by hand or damaged (a parseable file with
//! loads x1.5 was trusted silently before) fails it and is recomputed, with
//! a note ([`Lookup::Bad`]).

use crate::error::{Error, Result};
use crate::sphere::{Calibration, Shape, SolverOptions, SphereProblem};
use std::path::{Path, PathBuf};

/// What the cache holds for a problem.
#[derive(Debug, Clone, PartialEq)]
pub enum Lookup {
    /// An intact entry for these parameters.
    Found(Box<Calibration>),
    /// No entry.
    Missing,
    /// An entry that cannot be used (unreadable, not text, not an entry,
    /// failing its checksum, or for other parameters): the note to show.
    Bad(BadEntry),
}

/// A cache entry that could not be used and is recomputed: its file and
/// why; `Display` words the note (`calibration cache entry FILE is not
/// text (damaged): recomputed and stored again`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BadEntry {
    /// The entry's file.
    pub path: PathBuf,
    /// What is wrong with it.
    pub why: BadReason,
}

/// Why a cache entry cannot be used.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum BadReason {
    /// Its bytes are not UTF-8 text.
    NotText,
    /// It cannot be read (the operating system's message).
    Unreadable(String),
    /// It is not a calibration entry with a checksum.
    NotAnEntry,
    /// Its calibration cannot be serialised again for the checksum.
    NotReserialisable,
    /// Its checksum fails.
    Checksum,
    /// It holds another problem's calibration, or another solver
    /// version's.
    OtherParameters,
}

impl std::fmt::Display for BadEntry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let unreadable;
        let why = match &self.why {
            BadReason::NotText => "is not text (damaged)",
            BadReason::Unreadable(e) => {
                unreadable = format!("cannot be read ({e})");
                &unreadable
            }
            BadReason::NotAnEntry => {
                "is not a calibration entry with a checksum (damaged, or an older format)"
            }
            BadReason::NotReserialisable => "cannot be re-serialised",
            BadReason::Checksum => "fails its checksum (altered or damaged)",
            BadReason::OtherParameters => {
                "holds the calibration of other parameters or another solver version"
            }
        };
        write!(
            f,
            "calibration cache entry {} {why}: recomputed and stored again",
            self.path.display()
        )
    }
}

/// One stored entry: the calibration and the checksum of its canonical
/// JSON.
#[derive(serde::Serialize, serde::Deserialize)]
struct Entry {
    fnv1a64: String,
    calibration: Calibration,
}

/// FNV-1a, 64 bits (Fowler–Noll–Vo): a checksum against accidental or
/// hand-made changes, not an authentication.
/// FNV-1a (64-bit) of `bytes`: the checksum of cache entries and of a
/// sweep's result rows.
pub(crate) fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// Calibrations stored as JSON files in one directory.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CalibrationCache {
    dir: PathBuf,
}

impl CalibrationCache {
    /// A cache in `dir` (created on first store).
    pub fn new(dir: impl Into<PathBuf>) -> Self {
        CalibrationCache { dir: dir.into() }
    }

    /// `$ASPERITY_CACHE`, else `$HOME/.cache/asperity`, else a directory
    /// under the system temporary directory.
    pub fn default_location() -> Self {
        if let Some(d) = std::env::var_os("ASPERITY_CACHE").filter(|d| !d.is_empty()) {
            return Self::new(d);
        }
        if let Some(h) = std::env::var_os("HOME").filter(|d| !d.is_empty()) {
            return Self::new(Path::new(&h).join(".cache").join("asperity"));
        }
        Self::new(std::env::temp_dir().join("asperity-cache"))
    }

    /// The directory.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// File of a problem's calibration.
    pub fn path_for(&self, problem: &SphereProblem) -> PathBuf {
        self.dir.join(format!("{}.json", Calibration::key(problem)))
    }

    /// The stored calibration of `problem`, if present, intact (its
    /// checksum holds) and made by this solver version for these
    /// parameters.
    pub fn load(&self, problem: &SphereProblem) -> Option<Calibration> {
        match self.lookup(problem) {
            Lookup::Found(c) => Some(*c),
            _ => None,
        }
    }

    /// The stored entry of `problem`: found, absent (or for other
    /// parameters or another solver version), or present but bad (not the
    /// cache's format, or its checksum fails), with the reason.
    pub fn lookup(&self, problem: &SphereProblem) -> Lookup {
        let path = self.path_for(problem);
        let bad = |why| {
            Lookup::Bad(BadEntry {
                path: path.clone(),
                why,
            })
        };
        let text = match std::fs::read(&path) {
            Ok(bytes) => match String::from_utf8(bytes) {
                Ok(text) => text,
                Err(_) => return bad(BadReason::NotText),
            },
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Lookup::Missing,
            Err(e) => return bad(BadReason::Unreadable(e.to_string())),
        };
        let Ok(entry) = serde_json::from_str::<Entry>(&text) else {
            return bad(BadReason::NotAnEntry);
        };
        let Ok(canonical) = serde_json::to_string(&entry.calibration) else {
            return bad(BadReason::NotReserialisable);
        };
        if format!("{:016x}", fnv1a64(canonical.as_bytes())) != entry.fnv1a64 {
            return bad(BadReason::Checksum);
        }
        // The file's name holds the versions and parameters: an intact entry
        // for others was copied or renamed there.
        if entry.calibration.matches(problem) {
            Lookup::Found(Box::new(entry.calibration))
        } else {
            bad(BadReason::OtherParameters)
        }
    }

    /// Stores a calibration (atomically: temp file then rename).
    ///
    /// # Errors
    /// [`Error::Io`] when the directory or file cannot be written.
    pub fn store(&self, problem: &SphereProblem, c: &Calibration) -> Result<PathBuf> {
        let io = |e: std::io::Error| Error::io(self.dir.display(), e);
        std::fs::create_dir_all(&self.dir).map_err(io)?;
        let path = self.path_for(problem);
        let canonical = serde_json::to_string(c).map_err(|e| Error::io(path.display(), e))?;
        let entry = Entry {
            fnv1a64: format!("{:016x}", fnv1a64(canonical.as_bytes())),
            calibration: c.clone(),
        };
        let text = serde_json::to_string(&entry).map_err(|e| Error::io(path.display(), e))?;
        crate::study::atomic::write(&path, text).map_err(io)?;
        Ok(path)
    }

    /// The cached calibration, or computes and stores it. A cache that
    /// cannot be written does not fail the computation.
    ///
    /// # Errors
    /// As [`Calibration::compute`].
    pub fn get_or_compute(&self, problem: &SphereProblem) -> Result<Calibration> {
        if let Some(c) = self.load(problem) {
            return Ok(c);
        }
        let c = Calibration::compute(problem)?;
        let _ = self.store(problem, &c);
        Ok(c)
    }

    /// As [`CalibrationCache::get_or_compute`], with whether the entry was
    /// in the cache and the note of a bad entry that was recomputed.
    ///
    /// # Errors
    /// As [`Calibration::compute`].
    pub fn get_or_compute_noted(
        &self,
        problem: &SphereProblem,
    ) -> Result<(Calibration, bool, Option<BadEntry>)> {
        let note = match self.lookup(problem) {
            Lookup::Found(c) => return Ok((*c, true, None)),
            Lookup::Missing => None,
            Lookup::Bad(note) => Some(note),
        };
        let c = Calibration::compute(problem)?;
        let _ = self.store(problem, &c);
        Ok((c, false, note))
    }
}

/// Convenience: the calibration of `mu` (paraboloid, default options) from
/// the default cache.
///
/// # Errors
/// As [`SphereProblem::new`] and [`Calibration::compute`].
pub fn calibrate(mu: f64) -> Result<Calibration> {
    let p = SphereProblem::new(mu, Shape::Paraboloid, SolverOptions::default())?;
    CalibrationCache::default_location().get_or_compute(&p)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn problem() -> SphereProblem {
        SphereProblem::new(1.0, Shape::Paraboloid, SolverOptions::coarse()).unwrap()
    }

    fn temp_dir(tag: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("asperity-cal-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn cache_round_trip_and_no_recompute() {
        let dir = temp_dir("rt");
        let cache = CalibrationCache::new(&dir);
        let p = problem();
        assert!(cache.load(&p).is_none());
        let c = cache.get_or_compute(&p).unwrap();
        let path = cache.path_for(&p);
        assert!(path.exists());
        assert_eq!(cache.load(&p).unwrap(), c);
        // An entry stored through the cache is returned as is: proof that
        // nothing is recomputed.
        let mut t = c.clone();
        t.lambda_equivalent = 42.0;
        cache.store(&p, &t).unwrap();
        assert_eq!(cache.get_or_compute(&p).unwrap().lambda_equivalent, 42.0);
        // The same change made in the file fails the checksum: recomputed,
        // with a note naming the file.
        let text = std::fs::read_to_string(&path).unwrap();
        std::fs::write(&path, text.replacen("42.0", "63.0", 1)).unwrap();
        assert!(matches!(
            cache.lookup(&p),
            Lookup::Bad(BadEntry {
                why: BadReason::Checksum,
                ..
            })
        ));
        let (again, cached, note) = cache.get_or_compute_noted(&p).unwrap();
        assert_eq!(again, c);
        assert!(!cached);
        assert_eq!(
            note.unwrap().to_string(),
            format!(
                "calibration cache entry {} fails its checksum (altered or damaged): recomputed \
                 and stored again",
                path.display()
            )
        );
        assert_eq!(cache.load(&p).unwrap(), c);
        // Other parameters, other files.
        let q =
            SphereProblem::new(1.0, Shape::Sphere { rho: 100.0 }, SolverOptions::coarse()).unwrap();
        assert_ne!(cache.path_for(&q), path);
        let r = SphereProblem::new(1.0, Shape::Paraboloid, SolverOptions::default()).unwrap();
        assert_ne!(cache.path_for(&r), path);
        // A corrupt file is ignored (and would be recomputed).
        std::fs::write(&path, "{not json").unwrap();
        assert!(cache.load(&p).is_none());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn unwritable_cache_still_computes() {
        let dir = temp_dir("ro");
        std::fs::write(&dir, "a file, not a directory").unwrap();
        let cache = CalibrationCache::new(dir.join("sub"));
        let p = problem();
        assert!(cache.store(&p, &Calibration::compute(&p).unwrap()).is_err());
        assert!(cache.get_or_compute(&p).is_ok());
        std::fs::remove_file(&dir).unwrap();
    }
}
