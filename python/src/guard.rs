//! Every call into the library runs here: never a crash, never a hang.
//!
//! - The library runs with the GIL released, on a worker thread, under a
//!   cancellation token (`asperity::cancel`). The calling thread waits for
//!   it and, every [`POLL`], takes the GIL to run Python's signal handlers
//!   (`Python::check_signals`): Ctrl-C cancels the token, the worker stops at
//!   its next step (a boundary-element iteration, a curve's chunk, a sweep's
//!   point), and `KeyboardInterrupt` is raised once it has returned, so no
//!   thread is left computing.
//! - A Rust panic never reaches Python as `PanicException`: it is caught
//!   and raised as `RuntimeError("internal error in asperity.NAME: ...")`.
//! - Errors are worded in Python's vocabulary (`Vocabulary::python`):
//!   parameter names, not flags; bad input is `ValueError`, memory beyond
//!   what is available `MemoryError`, the rest `RuntimeError`.

use asperity::cancel::Token;
use asperity::commands::Vocabulary;
use pyo3::exceptions::{PyKeyboardInterrupt, PyMemoryError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::mpsc;
use std::time::Duration;

/// How often a waiting call looks at Python's signals (and its progress).
pub const POLL: Duration = Duration::from_millis(50);

/// A library error as the Python exception it is, worded with `words`.
pub fn py_err(e: asperity::Error, words: &Vocabulary) -> PyErr {
    let message = words.render(&e);
    match e {
        asperity::Error::Cancelled => PyKeyboardInterrupt::new_err(message),
        asperity::Error::OutOfMemory { .. } => PyMemoryError::new_err(message),
        e if e.is_bad_input() => PyValueError::new_err(message),
        _ => PyRuntimeError::new_err(message),
    }
}

/// The text of a panic's payload.
fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
        .unwrap_or_else(|| "a panic without a message".into())
}

/// The `RuntimeError` of a panic in `asperity.NAME`.
fn internal_error(name: &str, payload: &(dyn std::any::Any + Send)) -> PyErr {
    PyRuntimeError::new_err(format!(
        "internal error in asperity.{name}: {}; this is a bug in asperity, not in your input: \
         please report it with the call that raised it",
        panic_text(payload)
    ))
}

/// The environment variable that makes `asperity.NAME` panic inside its
/// guard, so the tests can check that no panic crosses into Python.
pub const TEST_PANIC: &str = "ASPERITY_TEST_PANIC";

/// Panics when the tests asked `asperity.NAME` to (see [`TEST_PANIC`]).
fn test_panic(name: &str) {
    if std::env::var_os(TEST_PANIC).is_some_and(|v| v == name) {
        panic!("a panic asked for by {TEST_PANIC}={name}");
    }
}

/// Runs `work` (short: well under a second) without the GIL on this
/// thread (no worker, no signal polling), with its panics caught and its
/// errors raised in Python's words.
pub fn quick<T: Send>(
    py: Python<'_>,
    name: &str,
    words: &Vocabulary,
    work: impl FnOnce() -> asperity::Result<T> + Send,
) -> PyResult<T> {
    let outcome = py.detach(|| {
        catch_unwind(AssertUnwindSafe(|| {
            test_panic(name);
            work()
        }))
    });
    match outcome {
        Ok(r) => r.map_err(|e| py_err(e, words)),
        Err(payload) => Err(internal_error(name, payload.as_ref())),
    }
}

/// Runs `work` without the GIL on a worker thread and waits for it,
/// honouring Ctrl-C (see the module). `tick` runs with the GIL every
/// [`POLL`] while the worker computes and once after it has finished (a
/// progress display, a callback); an error it returns (or
/// `KeyboardInterrupt`) cancels the work and is raised once the worker has
/// stopped.
pub fn watched<T: Send>(
    py: Python<'_>,
    name: &str,
    words: &Vocabulary,
    work: impl FnOnce() -> asperity::Result<T> + Send,
    mut tick: impl FnMut(Python<'_>) -> PyResult<()> + Send,
) -> PyResult<T> {
    let token = Token::new();
    let (outcome, raised) = py.detach(|| {
        let (tx, rx) = mpsc::channel();
        std::thread::scope(|s| {
            let worker = std::thread::Builder::new()
                .name(format!("asperity.{name}"))
                .spawn_scoped(s, || {
                    let r = catch_unwind(AssertUnwindSafe(|| {
                        test_panic(name);
                        token.scope(work)
                    }));
                    let _ = tx.send(());
                    r
                });
            let worker = match worker {
                Ok(w) => w,
                Err(e) => {
                    let err = PyRuntimeError::new_err(format!(
                        "asperity.{name}: cannot start a worker thread: {e}"
                    ));
                    return (None, Some(err));
                }
            };
            let mut raised: Option<PyErr> = None;
            loop {
                let finished = match rx.recv_timeout(POLL) {
                    Ok(()) | Err(mpsc::RecvTimeoutError::Disconnected) => true,
                    Err(mpsc::RecvTimeoutError::Timeout) => false,
                };
                // Once an error is raised the work is cancelled and `tick`
                // (a user's callback) is not called again.
                let polled =
                    Python::attach(|py| {
                        py.check_signals().and_then(|()| {
                            if raised.is_none() {
                                tick(py)
                            } else {
                                Ok(())
                            }
                        })
                    });
                if let Err(e) = polled {
                    token.cancel();
                    raised.get_or_insert(e);
                }
                if finished {
                    break;
                }
            }
            (Some(worker.join()), raised)
        })
    });
    if let Some(e) = raised {
        return Err(e);
    }
    match outcome {
        Some(Ok(Ok(r))) => r.map_err(|e| py_err(e, words)),
        Some(Ok(Err(payload))) | Some(Err(payload)) => Err(internal_error(name, payload.as_ref())),
        None => Err(PyRuntimeError::new_err(format!(
            "asperity.{name}: the worker did not start"
        ))),
    }
}

/// [`watched`] without a tick.
pub fn long<T: Send>(
    py: Python<'_>,
    name: &str,
    words: &Vocabulary,
    work: impl FnOnce() -> asperity::Result<T> + Send,
) -> PyResult<T> {
    watched(py, name, words, work, |_| Ok(()))
}
