//! Ctrl-C: the first SIGINT cancels the running computation (the library
//! polls the token between its steps, see `asperity::cancel`), so the
//! command stops within a step, keeps whatever it wrote whole (files are
//! written whole or not at all, a sweep's finished rows are kept for its
//! rerun) and exits 130; a second SIGINT exits at once.

use asperity::cancel::Token;
use std::sync::atomic::{AtomicBool, Ordering};

/// Exit status of an interrupted command (128 + SIGINT, as shells report).
pub const EXIT: u8 = 130;

/// Installs the SIGINT handler and returns the token it cancels. Without a
/// handler (one could not be installed) the token is never cancelled and
/// SIGINT keeps its default action.
pub fn install() -> Token {
    let token = Token::new();
    let handed = token.clone();
    let pressed = AtomicBool::new(false);
    let _ = ctrlc::set_handler(move || {
        if pressed.swap(true, Ordering::SeqCst) {
            std::process::exit(i32::from(EXIT));
        }
        eprintln!("interrupting: stopping at the next step (Ctrl-C again to quit at once)");
        handed.cancel();
    });
    token
}
