//! Writing to stdout when its reader may go away (`asperity ... | head`).
//!
//! `println!` panics when stdout is a closed pipe (Rust ignores SIGPIPE,
//! so the write fails with `EPIPE`). Commands print through [`out!`] and
//! [`outln!`] instead, which return [`CliError::ClosedPipe`]; `main` then
//! exits quietly with status [`CLOSED_PIPE_EXIT`] = 141 (128 + SIGPIPE,
//! what a shell reports for a program killed by SIGPIPE, as `yes | head`
//! does; files the command writes are written before it prints). A panic
//! hook does the same for any remaining `println!`.

use crate::CliError;
use std::io::Write;

/// Exit status when the reader of stdout has gone away: 128 + SIGPIPE (13).
pub const CLOSED_PIPE_EXIT: u8 = 141;

/// Writes formatted text to stdout, mapping a closed pipe to
/// [`CliError::ClosedPipe`] and other failures to [`CliError::Failed`].
pub fn write(args: std::fmt::Arguments) -> Result<(), CliError> {
    let mut out = std::io::stdout().lock();
    out.write_fmt(args).map_err(|e| {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            CliError::ClosedPipe
        } else {
            CliError::Failed(format!("stdout: {e}"))
        }
    })
}

/// `print!` that returns `Err(CliError)` instead of panicking.
#[macro_export]
macro_rules! out {
    ($($arg:tt)*) => { $crate::pipe::write(format_args!($($arg)*))? };
}

/// `println!` that returns `Err(CliError)` instead of panicking.
#[macro_export]
macro_rules! outln {
    () => { $crate::pipe::write(format_args!("\n"))? };
    ($($arg:tt)*) => { $crate::pipe::write(format_args!("{}\n", format_args!($($arg)*)))? };
}

/// Installs a panic hook that turns the panic of a `println!` (or
/// `eprintln!`) on a closed pipe into a quiet exit with
/// [`CLOSED_PIPE_EXIT`]; every other panic is reported as before.
pub fn quiet_on_closed_pipe() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let payload = info
            .payload()
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| info.payload().downcast_ref::<&str>().copied())
            .unwrap_or("");
        if payload.starts_with("failed printing to std") && payload.contains("Broken pipe") {
            std::process::exit(i32::from(CLOSED_PIPE_EXIT));
        }
        default(info);
    }));
}
