//! Whole-or-nothing file writes: the content goes to a temporary file
//! beside the target (`.NAME.tmpPID`), which is renamed over the target
//! only when completely written, and removed when anything fails. A full
//! disk or a killed run leaves the previous file (or none), never a
//! truncated `curve.csv` or a stray `*.tmp`.

use std::io::Write;
use std::path::{Path, PathBuf};

/// The temporary file beside `path` this process writes.
fn temporary(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(".{name}.tmp{}", std::process::id()))
}

/// Writes `contents` to `path` atomically (see the module notes).
///
/// # Errors
/// The I/O error of creating, writing, syncing or renaming; the temporary
/// file is removed first.
pub fn write(path: &Path, contents: impl AsRef<[u8]>) -> std::io::Result<()> {
    write_with(path, |f| f.write_all(contents.as_ref()))
}

/// Writes through `fill` to `path` atomically (see the module notes).
///
/// # Errors
/// As [`write()`], or `fill`'s error.
pub fn write_with(
    path: &Path,
    fill: impl FnOnce(&mut std::fs::File) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let tmp = temporary(path);
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        fill(&mut f)?;
        f.flush()?;
        drop(f);
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("asperity-atomic-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn entries(d: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    /// A write that fails half-way (as on a full disk) keeps the previous
    /// file whole and leaves no temporary file; `std::fs::write` would
    /// have truncated it first.
    #[test]
    fn a_failed_write_keeps_the_old_file_and_no_temporary() {
        let d = dir("fail");
        let p = d.join("curve.csv");
        write(&p, "old\n").unwrap();
        let e = write_with(&p, |f| {
            f.write_all(b"half")?;
            Err(std::io::Error::other("no space left on device"))
        })
        .unwrap_err();
        assert!(e.to_string().contains("no space"));
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "old\n");
        assert_eq!(entries(&d), vec!["curve.csv".to_string()]);
        // A target that cannot be replaced (a directory): no leftovers.
        let q = d.join("summary.json");
        std::fs::create_dir_all(q.join("x")).unwrap();
        assert!(write(&q, "{}").is_err());
        assert_eq!(
            entries(&d),
            vec!["curve.csv".to_string(), "summary.json".to_string()]
        );
        write(&p, "new\n").unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "new\n");
    }
}
