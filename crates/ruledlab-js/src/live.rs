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

/// Declares a module's `version()` and `liveObjects()` where it is invoked (each wasm module
/// exports its own: this crate exports nothing), `$objects` naming in words the classes whose
/// objects the count covers. The version is the invoking crate's (the modules are built together).
#[macro_export]
macro_rules! module_info {
    ($objects:literal) => {
        /// The crate version, e.g. "0.1.0".
        #[::wasm_bindgen::prelude::wasm_bindgen]
        pub fn version() -> String {
            env!("CARGO_PKG_VERSION").to_string()
        }

        #[doc = concat!("How many objects of ", $objects, " exist, i.e. have been made and not yet freed.")]
        #[::wasm_bindgen::prelude::wasm_bindgen(js_name = liveObjects)]
        pub fn live_objects() -> usize {
            $crate::live::count()
        }
    };
}
