//! What every benchmark shares: the sizes it runs.

/// All sizes under `cargo bench`; only the smallest when `cargo test` runs the bench once
/// as a test (criterion passes `--bench` only in the former).
pub fn sizes<T>(all: &[T]) -> &[T] {
    if std::env::args().any(|a| a == "--bench") {
        all
    } else {
        &all[..1]
    }
}
