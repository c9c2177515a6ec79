//! A count of the wasm objects JavaScript holds (surfaces, congruences, tool paths): each
//! carries a [`Live`] token, counted when made and uncounted when freed, so tests can show that
//! a page frees what it makes (`liveObjects()`, in `module_info.rs`, stays flat while every
//! slider moves). No JS class.

use std::sync::atomic::{AtomicUsize, Ordering};

static LIVE: AtomicUsize = AtomicUsize::new(0);

/// Counted while it exists.
#[derive(Debug)]
pub struct Live(());

impl Live {
    /// A new token (the count goes up by one).
    pub fn new() -> Self {
        LIVE.fetch_add(1, Ordering::Relaxed);
        Live(())
    }
}

impl Default for Live {
    fn default() -> Self {
        Live::new()
    }
}

impl Drop for Live {
    fn drop(&mut self) {
        LIVE.fetch_sub(1, Ordering::Relaxed);
    }
}

/// How many tokens exist: objects made and not yet freed.
pub fn count() -> usize {
    LIVE.load(Ordering::Relaxed)
}
