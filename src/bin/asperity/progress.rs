//! Progress of long work on stderr: an indicatif bar when stderr is a
//! terminal, plain periodic lines otherwise (cluster logs, `2> file`).
//!
//! Plain lines are printed at most once per 10 % of the work and at least
//! every [`PERIOD`] while work finishes, and once at the end, so a log
//! gets at most about a dozen lines per task. Nothing is shown before
//! `after` has elapsed (so quick work stays quiet); the environment
//! variable `ASPERITY_PROGRESS_AFTER` (seconds) overrides that delay.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Longest gap between two plain progress lines while work finishes.
pub const PERIOD: Duration = Duration::from_secs(10);

/// Work shorter than this shows no progress (`asperity run`).
pub const QUIET_FOR: Duration = Duration::from_secs(2);

/// A progress reporter for `total` units of work named `what`.
pub struct Progress {
    what: &'static str,
    unit: &'static str,
    after: Duration,
    t0: Instant,
    bar: Option<ProgressBar>,
    plain: Mutex<Plain>,
}

/// What the plain reporter last printed.
struct Plain {
    printed: bool,
    last: Instant,
    tenth: usize,
}

impl Progress {
    /// A reporter that stays silent for `after` (or
    /// `ASPERITY_PROGRESS_AFTER` seconds when set).
    pub fn new(what: &'static str, unit: &'static str, after: Duration) -> Progress {
        let after = std::env::var("ASPERITY_PROGRESS_AFTER")
            .ok()
            .and_then(|s| s.trim().parse::<f64>().ok())
            .filter(|s| s.is_finite() && *s >= 0.0)
            .map_or(after, Duration::from_secs_f64);
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::hidden());
            let template = format!(
                "{what}: {{bar:40}} {{pos}}/{{len}} {unit}  elapsed {{elapsed}}  eta {{eta}}"
            );
            if let Ok(style) = ProgressStyle::with_template(&template) {
                bar.set_style(style);
            }
            bar
        });
        let now = Instant::now();
        Progress {
            what,
            unit,
            after,
            t0: now,
            bar,
            plain: Mutex::new(Plain {
                printed: false,
                last: now,
                tenth: 0,
            }),
        }
    }

    /// Reports `done` of `total` units finished.
    pub fn update(&self, done: usize, total: usize) {
        let elapsed = self.t0.elapsed();
        if let Some(bar) = &self.bar {
            bar.set_length(total as u64);
            bar.set_position(done as u64);
            if elapsed >= self.after && bar.is_hidden() {
                bar.set_draw_target(ProgressDrawTarget::stderr());
            }
            return;
        }
        let Ok(mut p) = self.plain.lock() else {
            return;
        };
        let tenth = (done * 10).checked_div(total).unwrap_or(10);
        let due = tenth > p.tenth || p.last.elapsed() >= PERIOD || (done == total && !p.printed);
        if elapsed < self.after || !due || done == 0 {
            return;
        }
        p.printed = true;
        p.last = Instant::now();
        p.tenth = tenth;
        let secs = elapsed.as_secs_f64();
        let eta = if done < total {
            format!(", eta {:.0} s", secs / done as f64 * (total - done) as f64)
        } else {
            String::new()
        };
        eprintln!(
            "{}: {done}/{total} {} ({:.0} %), elapsed {secs:.1} s{eta}",
            self.what,
            self.unit,
            100.0 * done as f64 / total.max(1) as f64
        );
    }

    /// Removes the bar (plain lines stay in the log).
    pub fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

/// Runs `work`, saying on stderr that `what` is still going once it has
/// taken longer than `after` (or `ASPERITY_PROGRESS_AFTER` seconds): `note`
/// says why it can take a while; then an elapsed-time spinner on a
/// terminal, or a plain line every [`PERIOD`], and one line with its time
/// when it ends. Work that has no count of units (planning, which may solve
/// the full sphere law for a first-time calibration) gets this instead of a
/// bar.
pub fn waiting<T>(what: &'static str, note: &str, after: Duration, work: impl FnOnce() -> T) -> T {
    let after = std::env::var("ASPERITY_PROGRESS_AFTER")
        .ok()
        .and_then(|s| s.trim().parse::<f64>().ok())
        .filter(|s| s.is_finite() && *s >= 0.0)
        .map_or(after, Duration::from_secs_f64);
    let t0 = Instant::now();
    let (done, wait) = std::sync::mpsc::channel::<()>();
    let out = std::thread::scope(|s| {
        s.spawn(move || {
            use std::sync::mpsc::RecvTimeoutError::Timeout;
            if !matches!(wait.recv_timeout(after), Err(Timeout)) {
                return;
            }
            eprintln!(
                "{what}: still running after {:.1} s ({note})",
                t0.elapsed().as_secs_f64()
            );
            let spinner = std::io::stderr().is_terminal().then(|| {
                let bar = ProgressBar::new_spinner();
                if let Ok(style) = ProgressStyle::with_template(&format!(
                    "{what}: {{spinner}} elapsed {{elapsed}}"
                )) {
                    bar.set_style(style);
                }
                bar
            });
            let tick = if spinner.is_some() {
                Duration::from_millis(100)
            } else {
                PERIOD
            };
            while matches!(wait.recv_timeout(tick), Err(Timeout)) {
                match &spinner {
                    Some(bar) => bar.tick(),
                    None => eprintln!(
                        "{what}: still running, elapsed {:.0} s",
                        t0.elapsed().as_secs_f64()
                    ),
                }
            }
            if let Some(bar) = spinner {
                bar.finish_and_clear();
            }
        });
        let out = work();
        drop(done);
        out
    });
    let elapsed = t0.elapsed();
    if elapsed >= after {
        eprintln!("{what}: done in {:.1} s", elapsed.as_secs_f64());
    }
    out
}
