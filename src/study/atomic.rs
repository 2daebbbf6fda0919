//! Whole-or-nothing file writes: the content goes to a temporary file
//! beside the target (`.NAME.tmpPID`), which is renamed over the target
//! only when completely written, and removed when anything fails. A full
//! disk or a killed run leaves the previous file (or none), never a
//! truncated `curve.csv` or a stray `*.tmp`. A target that exists and is
//! not a regular file (a named pipe, `/dev/stdout`) is written directly:
//! renaming over it would replace the pipe its reader waits on.

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
    let special = std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir());
    if special {
        let mut f = std::fs::OpenOptions::new().write(true).open(path)?;
        fill(&mut f)?;
        return f.flush();
    }
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

    /// A named pipe is written through, not replaced: its reader gets the
    /// contents and the pipe stays a pipe.
    #[cfg(unix)]
    #[test]
    fn a_named_pipe_is_written_through() {
        use std::os::unix::fs::FileTypeExt;
        let d = dir("fifo");
        let p = d.join("pipe");
        let made = std::process::Command::new("mkfifo").arg(&p).status();
        if !made.is_ok_and(|s| s.success()) {
            return; // no mkfifo here: nothing to check
        }
        let reader = {
            let p = p.clone();
            std::thread::spawn(move || std::fs::read_to_string(p).unwrap())
        };
        write(&p, "through\n").unwrap();
        assert_eq!(reader.join().unwrap(), "through\n");
        assert!(std::fs::metadata(&p).unwrap().file_type().is_fifo());
        assert_eq!(entries(&d), vec!["pipe".to_string()]);
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
