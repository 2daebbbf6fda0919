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
    done: BTreeMap<usize, String>,
    /// Whether a half-written last line was found and dropped on opening.
    pub repaired: bool,
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

/// Reads complete rows of a results file whose first line must be
/// `header`; returns them by index and whether a torn last line was found
/// (and the byte length of the intact part).
fn read_rows(path: &Path, header: &str) -> Result<(BTreeMap<usize, String>, bool, usize)> {
    let text = std::fs::read_to_string(path).map_err(|e| io_err(path, e))?;
    let mut rows = BTreeMap::new();
    let fields = header.split(',').count();
    let mut intact = 0;
    let mut torn = false;
    for (i, chunk) in text.split_inclusive('\n').enumerate() {
        let complete = chunk.ends_with('\n');
        let line = chunk.trim_end_matches('\n');
        if i == 0 {
            if line != header {
                return Err(bad_dir(
                    path,
                    format!("header {line:?} differs from this sweep's {header:?}"),
                ));
            }
        } else {
            match (complete, row_index(line, fields)) {
                (true, Some(idx)) => {
                    rows.entry(idx).or_insert_with(|| line.to_string());
                }
                (false, _) => {
                    torn = true;
                    break;
                }
                (true, None) => {
                    return Err(bad_dir(
                        path,
                        format!("line {} is not a result row: {line:?}", i + 1),
                    ))
                }
            }
        }
        intact += chunk.len();
    }
    Ok((rows, torn, intact))
}

impl ResultsFile {
    /// Opens (or creates) `dir/results.csv` for the sweep `meta`; refuses a
    /// directory holding a different sweep; drops a half-written last line.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `--out`.
    pub fn open(dir: &Path, meta: &SweepMeta) -> Result<ResultsFile> {
        std::fs::create_dir_all(dir).map_err(|e| io_err(dir, e))?;
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
        let (done, repaired) = if path.exists() {
            let (rows, torn, intact) = read_rows(&path, &meta.header)?;
            if torn {
                let f = OpenOptions::new()
                    .write(true)
                    .open(&path)
                    .map_err(|e| io_err(&path, e))?;
                f.set_len(intact as u64).map_err(|e| io_err(&path, e))?;
            }
            (rows, torn)
        } else {
            std::fs::write(&path, format!("{}\n", meta.header)).map_err(|e| io_err(&path, e))?;
            (BTreeMap::new(), false)
        };
        let file = OpenOptions::new()
            .append(true)
            .open(&path)
            .map_err(|e| io_err(&path, e))?;
        Ok(ResultsFile {
            path,
            file,
            done,
            repaired,
        })
    }

    /// Whether point `index` is already in the file.
    pub fn is_done(&self, index: usize) -> bool {
        self.done.contains_key(&index)
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
        let line = format!("{row}\n");
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
    text.push_str(header);
    text.push('\n');
    for r in rows.values() {
        text.push_str(r);
        text.push('\n');
    }
    let tmp = path.with_extension("csv.tmp");
    std::fs::write(&tmp, text).map_err(|e| io_err(&tmp, e))?;
    std::fs::rename(&tmp, path).map_err(|e| io_err(path, e))
}

/// Joins the results of shard directories into `out`, checking that they
/// belong to one sweep, that no point appears twice and none is missing.
/// The merged `results.csv` equals the file of an unsharded run.
///
/// # Errors
/// [`Error::Invalid`] naming `merge` with the duplicate or missing points,
/// or `--out` on I/O failure.
pub fn merge(dirs: &[PathBuf], out: &Path) -> Result<PathBuf> {
    if dirs.is_empty() {
        return Err(Error::invalid("merge", "no directories to merge"));
    }
    let mut first: Option<SweepMeta> = None;
    let mut rows: BTreeMap<usize, (String, &Path)> = BTreeMap::new();
    for dir in dirs {
        let meta_path = dir.join("sweep.json");
        let meta: SweepMeta = serde_json::from_str(
            &std::fs::read_to_string(&meta_path).map_err(|e| io_err(&meta_path, e))?,
        )
        .map_err(|e| bad_dir(&meta_path, e))?;
        if let Some(f) = &first {
            if !f.same_sweep(&meta) {
                return Err(Error::invalid(
                    "merge",
                    format!(
                        "{} holds a different sweep from {}",
                        dir.display(),
                        dirs[0].display()
                    ),
                ));
            }
        }
        let (part, torn, _) = read_rows(&dir.join("results.csv"), &meta.header)?;
        if torn {
            return Err(Error::invalid(
                "merge",
                format!(
                    "{} ends with a half-written row: rerun that shard first",
                    dir.display()
                ),
            ));
        }
        for (idx, row) in part {
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
    std::fs::create_dir_all(out).map_err(|e| io_err(out, e))?;
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

    #[test]
    fn resume_drops_a_torn_line_and_keeps_complete_rows() {
        let dir = tmp("torn");
        let m = meta(None);
        let mut f = ResultsFile::open(&dir, &m).unwrap();
        f.append(2, "2,0.6,9,ok,1e0").unwrap();
        f.append(0, "0,0,7,ok,2e0").unwrap();
        drop(f);
        // A kill in the middle of a write leaves a partial line.
        let path = dir.join("results.csv");
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
        assert_eq!(
            done,
            "index,a,seed,status,x\n0,0,7,ok,2e0\n1,0.3,8,ok,3e0\n2,0.6,9,ok,1e0\n3,1,6,ok,4e0\n"
        );
        // A different sweep in the same directory is refused.
        let mut other = meta(None);
        other.scene = "t".into();
        assert_eq!(
            ResultsFile::open(&dir, &other).unwrap_err().field(),
            Some("out")
        );
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
        for d in [a, b, out] {
            std::fs::remove_dir_all(d).ok();
        }
    }
}
