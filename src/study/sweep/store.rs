//! The results file of a sweep (`DIR/results.csv`) with its description
//! (`DIR/sweep.json`): resume, finish, merge.

use super::spec::{Shard, SweepSpec};
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};

/// What a results directory holds: enough to refuse mixing two different
/// sweeps and to check a merge for gaps.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepMeta {
    /// The base scene, normalised TOML.
    pub scene: String,
    /// The sweep.
    pub spec: SweepSpec,
    /// Points in the whole sweep.
    pub total: usize,
    /// The slice this directory holds (`None`: all of it).
    pub shard: Option<Shard>,
    /// The CSV header.
    pub header: String,
}

impl SweepMeta {
    fn same_sweep(&self, other: &SweepMeta) -> bool {
        self.scene == other.scene
            && self.spec == other.spec
            && self.total == other.total
            && self.header == other.header
    }
}

/// An open results file: the rows already done, appending the rest.
#[derive(Debug)]
pub struct ResultsFile {
    path: PathBuf,
    file: File,
    /// The directory lock, held until this value is dropped.
    _lock: DirLock,
    done: BTreeMap<usize, String>,
    /// Whether a half-written last line was found and dropped on opening.
    pub repaired: bool,
    /// Rows found on opening that are recomputed, and why: a checksum that
    /// does not match its row (edited or damaged), or a file of an older
    /// release without checksums. Empty when every row was kept.
    pub notes: Vec<String>,
}

/// The name of the last column of `results.csv`: FNV-1a (64-bit, 16 hex
/// digits) of the rest of its row, so an edited or damaged row is
/// recomputed on resume, never trusted.
pub const CHECKSUM_COLUMN: &str = "checksum";

/// A result row as written: `row,checksum`.
fn with_checksum(row: &str) -> String {
    format!(
        "{row},{:016x}",
        crate::study::cache::fnv1a64(row.as_bytes())
    )
}

/// The header line of a results file for the sweep's `header`.
fn file_header(header: &str) -> String {
    format!("{header},{CHECKSUM_COLUMN}")
}

/// The rows a results file holds, read and checked ([`read_rows`]).
struct ReadRows {
    /// Complete rows whose checksum matches, by point index (without
    /// the checksum).
    rows: BTreeMap<usize, String>,
    /// Whether the last line was torn.
    torn: bool,
    /// Byte length of the intact part (up to a torn line).
    intact: usize,
    /// Line numbers (1-based) of rows whose checksum does not match.
    mismatched: Vec<usize>,
    /// Rows of an older release's file without checksums.
    unchecked: usize,
}

/// An exclusive OS lock on `DIR/sweep.lock` (`flock` on Unix), held while
/// a sweep or a merge writes into `DIR`, so two runs never interleave
/// their rows or their `sweep.json`. The operating system releases it when
/// the process ends, however it ends (`kill -9` included), so a stale lock
/// never blocks a later run. The (empty) lock file is left in place:
/// removing it would let a third run lock a fresh file while a second still
/// holds the old one.
#[derive(Debug)]
pub struct DirLock {
    _file: File,
}

/// Name of the lock file inside a results directory.
pub const LOCK_FILE: &str = "sweep.lock";

impl DirLock {
    /// Creates `dir` if needed and takes its lock without waiting.
    ///
    /// # Errors
    /// [`Error::Io`] naming the directory when another process holds the
    /// lock (the message says so) or the lock file cannot be opened.
    pub fn acquire(dir: &Path) -> Result<DirLock> {
        std::fs::create_dir_all(dir).map_err(|e| io_err(dir, e))?;
        let path = dir.join(LOCK_FILE);
        let file = OpenOptions::new()
            .create(true)
            .truncate(false)
            .write(true)
            .open(&path)
            .map_err(|e| io_err(&path, e))?;
        match file.try_lock() {
            Ok(()) => Ok(DirLock { _file: file }),
            Err(std::fs::TryLockError::WouldBlock) => Err(io_err(
                dir,
                "another asperity sweep or merge is writing into this directory \
                 (it holds sweep.lock); wait for it to finish or use another --out",
            )),
            Err(std::fs::TryLockError::Error(e)) => Err(io_err(&path, e)),
        }
    }
}

/// A file-system failure: not the input's fault.
fn io_err(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::io(path.display(), e)
}

/// A results directory whose content is not what a sweep writes.
fn bad_dir(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::invalid("out", format!("{}: {e}", path.display()))
}

/// The point index at the start of a complete row, if it parses and the
/// row has as many fields as the header.
fn row_index(line: &str, fields: usize) -> Option<usize> {
    if line.split(',').count() != fields {
        return None;
    }
    line.split(',').next()?.parse().ok()
}

/// A checksummed line split into its row and whether the checksum
/// matches; `None` without a checksum field.
fn checked(line: &str) -> Option<(&str, bool)> {
    let (row, sum) = line.rsplit_once(',')?;
    let ok = u64::from_str_radix(sum, 16)
        .is_ok_and(|s| sum.len() == 16 && s == crate::study::cache::fnv1a64(row.as_bytes()));
    Some((row, ok))
}

/// Reads complete rows of a results file whose first line must be
/// `header` with the checksum column (or, from an older release, without
/// it) and whose indices must be below `total`: the rows by index whose
/// checksum matches, whether a torn last line was found (and the byte
/// length of the intact part), the lines whose checksum does not match
/// and how many rows carried none. Content errors are [`Error::Invalid`]
/// about `field` (`out` for the directory being resumed, `merge` for an
/// input shard), naming the file.
fn read_rows(path: &Path, header: &str, total: usize, field: &str) -> Result<ReadRows> {
    let text = std::fs::read_to_string(path).map_err(|e| io_err(path, e))?;
    let bad = |why: String| Error::invalid(field, format!("{}: {why}", path.display()));
    let mut out = ReadRows {
        rows: BTreeMap::new(),
        torn: false,
        intact: 0,
        mismatched: Vec::new(),
        unchecked: 0,
    };
    let mut summed = true;
    let fields = header.split(',').count();
    for (i, chunk) in text.split_inclusive('\n').enumerate() {
        let complete = chunk.ends_with('\n');
        let mut line = chunk.trim_end_matches('\n');
        if i == 0 {
            summed = line == file_header(header);
            if !summed && line != header {
                return Err(bad(format!(
                    "header {line:?} differs from this sweep's {:?}",
                    file_header(header)
                )));
            }
        } else {
            let mut trusted = !summed;
            if summed && complete {
                match checked(line) {
                    Some((row, ok)) => {
                        line = row;
                        trusted = ok;
                    }
                    None => {
                        return Err(bad(format!("line {} is not a result row: {line:?}", i + 1)))
                    }
                }
            }
            match (complete, row_index(line, fields)) {
                (true, Some(idx)) if idx >= total => {
                    return Err(bad(format!(
                        "line {}: point {idx} lies outside the sweep (points 0 ..= {})",
                        i + 1,
                        total.saturating_sub(1)
                    )))
                }
                (true, Some(_)) if !summed => out.unchecked += 1,
                (true, Some(_)) if !trusted => out.mismatched.push(i + 1),
                (true, Some(idx)) => {
                    out.rows.entry(idx).or_insert_with(|| line.to_string());
                }
                (false, _) => {
                    out.torn = true;
                    break;
                }
                (true, None) => {
                    return Err(bad(format!("line {} is not a result row: {line:?}", i + 1)))
                }
            }
        }
        out.intact += chunk.len();
    }
    Ok(out)
}

/// The notes of rows that a resume recomputes (checksums that do not
/// match, a file without checksums) in the results file `path`.
fn recompute_notes(path: &Path, read: &ReadRows) -> Vec<String> {
    let mut notes = Vec::new();
    if !read.mismatched.is_empty() {
        let lines: Vec<String> = read.mismatched.iter().map(|l| l.to_string()).collect();
        notes.push(format!(
            "{}: {} row(s) whose checksum does not match (edited or damaged; lines {}) are \
             recomputed",
            path.display(),
            read.mismatched.len(),
            lines.join(", ")
        ));
    }
    if read.unchecked > 0 {
        notes.push(format!(
            "{}: {} row(s) written without a checksum (an older asperity) are recomputed",
            path.display(),
            read.unchecked
        ));
    }
    notes
}

impl ResultsFile {
    /// Opens (or creates) `dir/results.csv` for the sweep `meta`; refuses a
    /// directory holding a different sweep; drops a half-written last line.
    /// The directory stays locked (an advisory lock file) until the file is dropped.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `out` (a different sweep, a row that is not
    /// this sweep's); [`Error::Io`] when another process holds the lock or
    /// a file cannot be read or written.
    pub fn open(dir: &Path, meta: &SweepMeta) -> Result<ResultsFile> {
        let lock = DirLock::acquire(dir)?;
        let meta_path = dir.join("sweep.json");
        if meta_path.exists() {
            let old: SweepMeta = serde_json::from_str(
                &std::fs::read_to_string(&meta_path).map_err(|e| io_err(&meta_path, e))?,
            )
            .map_err(|e| bad_dir(&meta_path, e))?;
            if !old.same_sweep(meta) || old.shard != meta.shard {
                return Err(bad_dir(
                    dir,
                    "holds a different sweep (scene, --vary, design or shard differ); use another --out",
                ));
            }
        } else {
            let text = serde_json::to_string_pretty(meta).map_err(|e| io_err(&meta_path, e))?;
            std::fs::write(&meta_path, text + "\n").map_err(|e| io_err(&meta_path, e))?;
        }
        let path = dir.join("results.csv");
        let (done, repaired, notes) = if path.exists() {
            let read = read_rows(&path, &meta.header, meta.total, "out")?;
            let notes = recompute_notes(&path, &read);
            if !notes.is_empty() {
                // Only the trusted rows stay, under the current header.
                write_sorted(&path, &meta.header, &read.rows)?;
            } else if read.torn {
                let f = OpenOptions::new()
                    .write(true)
                    .open(&path)
                    .map_err(|e| io_err(&path, e))?;
                f.set_len(read.intact as u64)
                    .map_err(|e| io_err(&path, e))?;
            }
            (read.rows, read.torn, notes)
        } else {
            std::fs::write(&path, format!("{}\n", file_header(&meta.header)))
                .map_err(|e| io_err(&path, e))?;
            (BTreeMap::new(), false, Vec::new())
        };
        let file = OpenOptions::new()
            .append(true)
            .open(&path)
            .map_err(|e| io_err(&path, e))?;
        Ok(ResultsFile {
            path,
            file,
            _lock: lock,
            done,
            repaired,
            notes,
        })
    }

    /// Whether point `index` is already in the file.
    pub fn is_done(&self, index: usize) -> bool {
        self.done.contains_key(&index)
    }

    /// The rows present (already done or appended), by point index.
    pub fn rows(&self) -> impl Iterator<Item = (usize, &str)> {
        self.done.iter().map(|(i, r)| (*i, r.as_str()))
    }

    /// Rows already present.
    pub fn done_count(&self) -> usize {
        self.done.len()
    }

    /// Appends one finished row (no newline) and syncs it to disk.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `--out` on I/O failure.
    pub fn append(&mut self, index: usize, row: &str) -> Result<()> {
        let line = format!("{}\n", with_checksum(row));
        self.file
            .write_all(line.as_bytes())
            .and_then(|_| self.file.sync_data())
            .map_err(|e| io_err(&self.path, e))?;
        self.done.insert(index, row.to_string());
        Ok(())
    }

    /// Rewrites the file sorted by index (write a temporary, then rename).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `--out` on I/O failure.
    pub fn finish(self, header: &str) -> Result<PathBuf> {
        write_sorted(&self.path, header, &self.done)?;
        Ok(self.path)
    }
}

fn write_sorted(path: &Path, header: &str, rows: &BTreeMap<usize, String>) -> Result<()> {
    let mut text = String::with_capacity(64 * (rows.len() + 1));
    text.push_str(&file_header(header));
    text.push('\n');
    for r in rows.values() {
        text.push_str(&with_checksum(r));
        text.push('\n');
    }
    crate::study::atomic::write(path, text).map_err(|e| io_err(path, e))
}

/// Joins the results of shard directories into `out`, checking that they
/// belong to one sweep, that every row lies inside the sweep and inside
/// the shard its directory says it holds, that no point appears twice and
/// none is missing. The merged `results.csv` equals the file of an
/// unsharded run. `out` is locked (an advisory lock file) while it is written.
///
/// # Errors
/// [`Error::Invalid`] naming `merge` and the offending shard directory
/// (bad, foreign, duplicate or missing rows); [`Error::Io`] when a file
/// cannot be read or written (or `out` is locked by another run).
pub fn merge(dirs: &[PathBuf], out: &Path) -> Result<PathBuf> {
    if dirs.is_empty() {
        return Err(Error::invalid("merge", "no directories to merge"));
    }
    let shard_err = |dir: &Path, why: String| {
        Error::invalid("merge", format!("shard {}: {why}", dir.display()))
    };
    let mut first: Option<SweepMeta> = None;
    let mut rows: BTreeMap<usize, (String, &Path)> = BTreeMap::new();
    for dir in dirs {
        let meta_path = dir.join("sweep.json");
        let text = std::fs::read_to_string(&meta_path).map_err(|e| {
            shard_err(
                dir,
                format!("cannot read sweep.json ({e}): not a sweep directory"),
            )
        })?;
        let meta: SweepMeta =
            serde_json::from_str(&text).map_err(|e| shard_err(dir, format!("sweep.json: {e}")))?;
        if let Some(f) = &first {
            if !f.same_sweep(&meta) {
                return Err(shard_err(
                    dir,
                    format!("holds a different sweep from {}", dirs[0].display()),
                ));
            }
        }
        let read = read_rows(&dir.join("results.csv"), &meta.header, meta.total, "merge").map_err(
            |e| match e {
                Error::Invalid { reason, .. } => shard_err(dir, reason),
                other => other,
            },
        )?;
        if let Some(note) = recompute_notes(&dir.join("results.csv"), &read).first() {
            // A merge cannot recompute: the shard's own resume does.
            return Err(shard_err(
                dir,
                format!("{note} when that shard is run again: rerun it first"),
            ));
        }
        let (part, torn) = (read.rows, read.torn);
        if torn {
            return Err(shard_err(
                dir,
                "ends with a half-written row: rerun that shard first".into(),
            ));
        }
        for (idx, row) in part {
            if let Some(s) = meta.shard.filter(|s| !s.contains(idx)) {
                return Err(shard_err(
                    dir,
                    format!("point {idx} does not belong to its shard {}/{}", s.k, s.n),
                ));
            }
            if let Some((_, other)) = rows.get(&idx) {
                return Err(Error::invalid(
                    "merge",
                    format!(
                        "point {idx} is in both {} and {}",
                        other.display(),
                        dir.display()
                    ),
                ));
            }
            rows.insert(idx, (row, dir.as_path()));
        }
        first.get_or_insert(meta);
    }
    let meta = first.expect("at least one directory");
    let missing: Vec<usize> = (0..meta.total).filter(|i| !rows.contains_key(i)).collect();
    if !missing.is_empty() {
        let head: Vec<String> = missing.iter().take(10).map(|i| i.to_string()).collect();
        return Err(Error::invalid(
            "merge",
            format!(
                "{} of {} points missing (first: {}); run the shards that hold them",
                missing.len(),
                meta.total,
                head.join(", ")
            ),
        ));
    }
    let _lock = DirLock::acquire(out)?;
    let merged = SweepMeta {
        shard: None,
        ..meta.clone()
    };
    let meta_path = out.join("sweep.json");
    let text = serde_json::to_string_pretty(&merged).map_err(|e| io_err(&meta_path, e))?;
    std::fs::write(&meta_path, text + "\n").map_err(|e| io_err(&meta_path, e))?;
    let path = out.join("results.csv");
    let sorted: BTreeMap<usize, String> = rows.into_iter().map(|(i, (r, _))| (i, r)).collect();
    write_sorted(&path, &meta.header, &sorted)?;
    Ok(path)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::sweep::spec::{Design, Vary};

    fn meta(shard: Option<Shard>) -> SweepMeta {
        SweepMeta {
            scene: "s".into(),
            spec: SweepSpec {
                vary: vec![Vary::parse("a=0:1:4").unwrap()],
                design: Design::Grid,
                log: false,
                seed: 0,
            },
            total: 4,
            shard,
            header: "index,a,seed,status,x".into(),
        }
    }

    fn tmp(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("asperity-store-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        d
    }

    /// A results file of [`meta`]`(None)` in a fresh temporary directory
    /// `name` with the `rows` (index, row) appended, closed: the directory,
    /// the meta and the file's path.
    fn written(name: &str, rows: &[(usize, &str)]) -> (PathBuf, SweepMeta, PathBuf) {
        let dir = tmp(name);
        let m = meta(None);
        let mut f = ResultsFile::open(&dir, &m).unwrap();
        for &(k, row) in rows {
            f.append(k, row).unwrap();
        }
        drop(f);
        let path = dir.join("results.csv");
        (dir, m, path)
    }

    #[test]
    fn resume_drops_a_torn_line_and_keeps_complete_rows() {
        let (dir, m, path) = written("torn", &[(2, "2,0.6,9,ok,1e0"), (0, "0,0,7,ok,2e0")]);
        // A kill in the middle of a write leaves a partial line.
        let mut text = std::fs::read_to_string(&path).unwrap();
        text.push_str("1,0.3,8,o");
        std::fs::write(&path, &text).unwrap();
        let mut f = ResultsFile::open(&dir, &m).unwrap();
        assert!(f.repaired);
        assert_eq!(f.done_count(), 2);
        assert!(f.is_done(0) && f.is_done(2) && !f.is_done(1));
        f.append(1, "1,0.3,8,ok,3e0").unwrap();
        f.append(3, "3,1,6,ok,4e0").unwrap();
        f.finish(&m.header).unwrap();
        let done = std::fs::read_to_string(&path).unwrap();
        let want: String = [
            "0,0,7,ok,2e0",
            "1,0.3,8,ok,3e0",
            "2,0.6,9,ok,1e0",
            "3,1,6,ok,4e0",
        ]
        .iter()
        .map(|r| with_checksum(r) + "\n")
        .collect();
        assert_eq!(done, format!("index,a,seed,status,x,checksum\n{want}"));
        // A different sweep in the same directory is refused.
        let mut other = meta(None);
        other.scene = "t".into();
        assert_eq!(
            ResultsFile::open(&dir, &other).unwrap_err().field(),
            Some("out")
        );
        std::fs::remove_dir_all(&dir).ok();
    }

    /// A hand-edited row was trusted on resume: rows carry a checksum now,
    /// and one that does not match is recomputed with a note naming the
    /// file and the line; a file of an older release without checksums
    /// has all its rows recomputed, with a note.
    #[test]
    fn resume_recomputes_edited_rows_and_rows_without_checksums() {
        let (dir, m, path) = written("edited", &[(0, "0,0,7,ok,2e0"), (1, "1,0.3,8,ok,3e0")]);
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(
            text.starts_with("index,a,seed,status,x,checksum\n"),
            "{text}"
        );
        // (the row and the comma before its checksum: a checksum's hex
        // digits never hold a comma)
        std::fs::write(&path, text.replace("0,0,7,ok,2e0,", "0,0,7,ok,5e0,")).unwrap();
        let f = ResultsFile::open(&dir, &m).unwrap();
        assert!(!f.is_done(0) && f.is_done(1));
        assert_eq!(f.notes.len(), 1, "{:?}", f.notes);
        assert!(
            f.notes[0].contains("checksum does not match"),
            "{:?}",
            f.notes
        );
        assert!(f.notes[0].contains("lines 2"), "{:?}", f.notes);
        assert!(f.notes[0].contains("results.csv"), "{:?}", f.notes);
        drop(f);
        // The file now holds only the trusted row: no note on the next open.
        assert!(ResultsFile::open(&dir, &m).unwrap().notes.is_empty());
        // An older release's file: the header without the checksum column.
        std::fs::write(
            &path,
            "index,a,seed,status,x\n0,0,7,ok,2e0\n1,0.3,8,ok,3e0\n",
        )
        .unwrap();
        let f = ResultsFile::open(&dir, &m).unwrap();
        assert_eq!(f.done_count(), 0);
        assert!(
            f.notes[0].contains("2 row(s) written without a checksum"),
            "{:?}",
            f.notes
        );
        drop(f);
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(text, "index,a,seed,status,x,checksum\n");
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_locked_directory_is_refused_and_released_on_drop() {
        let dir = tmp("lock");
        let m = meta(None);
        let f = ResultsFile::open(&dir, &m).unwrap();
        // flock locks belong to the open file, so a second open in this
        // process conflicts exactly as another process would.
        let e = ResultsFile::open(&dir, &m).unwrap_err();
        assert!(matches!(e, Error::Io { .. }), "{e}");
        assert!(e.to_string().contains("another asperity sweep"), "{e}");
        drop(f);
        ResultsFile::open(&dir, &m).unwrap();
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn resume_refuses_a_row_outside_the_sweep() {
        let dir = tmp("outside");
        let m = meta(None);
        drop(ResultsFile::open(&dir, &m).unwrap());
        let path = dir.join("results.csv");
        let text = std::fs::read_to_string(&path).unwrap() + &with_checksum("4,1,6,ok,4e0") + "\n";
        std::fs::write(&path, text).unwrap();
        let e = ResultsFile::open(&dir, &m).unwrap_err();
        assert_eq!(e.field(), Some("out"));
        assert!(e.to_string().contains("point 4 lies outside"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn merge_checks_gaps_and_duplicates() {
        let (a, b, out) = (tmp("a"), tmp("b"), tmp("out"));
        for (dir, k, rows) in [(&a, 1, [0usize, 2]), (&b, 2, [1, 3])] {
            let m = meta(Some(Shard { k, n: 2 }));
            let mut f = ResultsFile::open(dir, &m).unwrap();
            for i in rows {
                f.append(i, &format!("{i},0,0,ok,1e0")).unwrap();
            }
            f.finish(&m.header).unwrap();
        }
        let path = merge(&[a.clone(), b.clone()], &out).unwrap();
        let text = std::fs::read_to_string(path).unwrap();
        assert_eq!(text.lines().count(), 5);
        let e = merge(std::slice::from_ref(&a), &out).unwrap_err();
        assert!(e.to_string().contains("2 of 4 points missing"), "{e}");
        let e = merge(&[a.clone(), a.clone()], &out).unwrap_err();
        assert!(e.to_string().contains("point 0 is in both"), "{e}");
        assert!(merge(&[], &out).is_err());
        // A row outside the sweep, or outside its shard, names its shard
        // (not --out).
        let csv = b.join("results.csv");
        let good = std::fs::read_to_string(&csv).unwrap();
        std::fs::write(&csv, format!("{good}{}\n", with_checksum("9,0,0,ok,1e0"))).unwrap();
        let e = merge(&[a.clone(), b.clone()], &out).unwrap_err();
        assert_eq!(e.field(), Some("merge"), "{e}");
        assert!(
            e.to_string().contains(&format!("shard {}", b.display())),
            "{e}"
        );
        assert!(
            e.to_string().contains("point 9 lies outside the sweep"),
            "{e}"
        );
        // An edited row: its checksum no longer matches.
        std::fs::write(&csv, good.replace("1,0,0,ok", "2,0,0,ok")).unwrap();
        let e = merge(&[a.clone(), b.clone()], &out).unwrap_err();
        assert!(e.to_string().contains("checksum does not match"), "{e}");
        assert!(e.to_string().contains("rerun it first"), "{e}");
        let one = with_checksum("1,0,0,ok,1e0");
        std::fs::write(&csv, good.replace(&one, &with_checksum("2,0,0,ok,1e0"))).unwrap();
        let e = merge(&[a.clone(), b.clone()], &out).unwrap_err();
        assert!(
            e.to_string()
                .contains("point 2 does not belong to its shard 2/2"),
            "{e}"
        );
        std::fs::remove_file(b.join("sweep.json")).unwrap();
        let e = merge(&[a.clone(), b.clone()], &out).unwrap_err();
        assert_eq!(e.field(), Some("merge"), "{e}");
        assert!(e.to_string().contains("not a sweep directory"), "{e}");
        for d in [a, b, out] {
            std::fs::remove_dir_all(d).ok();
        }
    }
}
