//! Cooperative cancellation (Ctrl-C).
//!
//! A front end (the command line's SIGINT handler, the Python binding's
//! signal watcher) holds a [`Token`] and cancels it; long computations poll
//! [`check`] between their steps (a boundary-element iteration, a curve's
//! state, a sweep's point, a pull-off population) and return
//! [`Error::Cancelled`], so the caller gets control back within one step and
//! no thread is left computing. The token in force is per thread:
//! [`Token::scope`] installs it for a closure, and a parallel loop hands it
//! to its workers with [`current`] and [`scope`]. Outside any scope
//! [`check`] always passes, so library callers that never cancel pay one
//! thread-local read per step.

use crate::error::{Error, Result};
use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// A cancellation flag shared between the front end that sets it and the
/// computation that polls it (clones share the flag).
#[derive(Clone, Debug, Default)]
pub struct Token(Arc<AtomicBool>);

thread_local! {
    static CURRENT: RefCell<Option<Token>> = const { RefCell::new(None) };
}

/// Restores the previous token of the thread when a scope ends (also when
/// it unwinds).
struct Restore(Option<Token>);

impl Drop for Restore {
    fn drop(&mut self) {
        let previous = self.0.take();
        CURRENT.with(|c| *c.borrow_mut() = previous);
    }
}

impl Token {
    /// A token not cancelled.
    pub fn new() -> Self {
        Token::default()
    }

    /// Asks every computation polling this token to stop.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// Whether [`Token::cancel`] was called.
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }

    /// Runs `f` on this thread with this token in force for [`check`].
    pub fn scope<R>(&self, f: impl FnOnce() -> R) -> R {
        scope(Some(self), f)
    }
}

/// The token in force on this thread, to hand to the workers of a parallel
/// loop.
pub fn current() -> Option<Token> {
    CURRENT.with(|c| c.borrow().clone())
}

/// Runs `f` with `token` in force on this thread (none: [`check`] always
/// passes), restoring the previous one afterwards.
pub fn scope<R>(token: Option<&Token>, f: impl FnOnce() -> R) -> R {
    let previous = CURRENT.with(|c| c.replace(token.cloned()));
    let _restore = Restore(previous);
    f()
}

/// `Err(Error::Cancelled)` once the token in force on this thread is
/// cancelled.
///
/// # Errors
/// [`Error::Cancelled`].
pub fn check() -> Result<()> {
    let cancelled = CURRENT.with(|c| c.borrow().as_ref().is_some_and(Token::is_cancelled));
    if cancelled {
        Err(Error::Cancelled)
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cancelled_token_fails_checks_only_inside_its_scope() {
        let t = Token::new();
        assert!(check().is_ok());
        t.scope(|| assert!(check().is_ok()));
        t.cancel();
        assert!(check().is_ok(), "no token in force outside a scope");
        let inside = t.scope(check);
        assert!(matches!(inside, Err(Error::Cancelled)));
        // Scopes nest and restore the outer token, also on a panic.
        let other = Token::new();
        t.scope(|| {
            other.scope(|| assert!(check().is_ok()));
            assert!(check().is_err());
            let _ = std::panic::catch_unwind(|| other.scope(|| panic!("unwinds")));
            assert!(check().is_err(), "the outer token is back after a panic");
        });
        assert!(check().is_ok());
    }

    #[test]
    fn workers_get_the_token_they_are_handed() {
        let t = Token::new();
        t.cancel();
        let seen = t.scope(|| {
            let handed = current();
            std::thread::scope(|s| {
                let plain = s.spawn(check).join().unwrap();
                let given = s.spawn(|| scope(handed.as_ref(), check)).join().unwrap();
                (plain.is_ok(), given.is_err())
            })
        });
        assert_eq!(seen, (true, true));
    }
}
