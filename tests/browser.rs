//! The integration tests that run in the browser too (Sections 2–5, the kernels, line space, the
//! formulas, focal geometry, visibility, snapping, developables), gathered into one wasm test
//! binary: one link, one pass of wasm-bindgen and one browser per run instead of one per file.
//! Natively each file is its own test binary, as cargo finds them; this one is empty there.

#![cfg(target_family = "wasm")]

#[path = "developable.rs"]
mod developable;
#[path = "focal.rs"]
mod focal;
#[path = "formula.rs"]
mod formula;
#[path = "kernels.rs"]
mod kernels;
#[path = "line_space.rs"]
mod line_space;
#[path = "section2.rs"]
mod section2;
#[path = "section3.rs"]
mod section3;
#[path = "section4.rs"]
mod section4;
#[path = "section5.rs"]
mod section5;
#[path = "snap.rs"]
mod snap;
#[path = "visibility.rs"]
mod visibility;
