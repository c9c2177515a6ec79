//! ruledlab's Python bindings: the extension module `ruledlab._core` of the Python package
//! `ruledlab` (`python/`), built by maturin into one wheel with the notebook widget. The geometry
//! of Odehnal & Pottmann (Sections 2–5, line space, focal geometry, linear complexes, formulas)
//! and the CAM of `ruledlab-cam` (tool paths, machines, the G-code posts) on NumPy arrays: the
//! computations of the JavaScript API (`crates/ruledlab-wasm`, `crates/ruledlab-cam-wasm`) with
//! its argument checks and its error codes, raised as `ruledlab.RuledlabError`.
//!
//! float64 arrays in and out, shapes checked, no copy where the layout allows (`arrays.rs`);
//! every argument checked here, not by PyO3's conversions (`args.rs`); the GIL released while
//! the core computes. One file per Python class, named after it, the free functions in files
//! named for what they do, the helpers in files that define neither. Only this crate uses PyO3;
//! it builds nothing for wasm32 (the bindings there are the wasm crates').
#![cfg(not(target_family = "wasm"))]

// the classes
mod analytic_congruence;
mod analytic_surface;
mod line_congruence;
mod ruled_surface;
mod tool_path;

// the free functions
mod cam_import;
mod formula;
mod import;
mod line_fit;
mod linear_complex;
mod module_info;
mod polygon;

// what they share
mod allocator;
mod args;
mod arrays;
mod catalogue_entry;
mod convert;
mod error;
mod export;
mod focal;
mod gcode_options;
mod invariants;
mod layout;
mod scheme_options;

use pyo3::prelude::*;

/// Large blocks on transparent huge pages, as NumPy's (`allocator.rs`).
#[global_allocator]
static ALLOCATOR: allocator::Allocator = allocator::Allocator;

/// The compiled core of the Python package ``ruledlab`` (import ``ruledlab``, not this module).
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<ruled_surface::RuledSurface>()?;
    m.add_class::<analytic_surface::AnalyticSurface>()?;
    m.add_class::<line_congruence::LineCongruence>()?;
    m.add_class::<analytic_congruence::AnalyticCongruence>()?;
    m.add_class::<tool_path::ToolPath>()?;
    m.add_function(wrap_pyfunction!(linear_complex::linear_complex, m)?)?;
    m.add_function(wrap_pyfunction!(polygon::subdivide_polygon, m)?)?;
    m.add_function(wrap_pyfunction!(polygon::turning_angles, m)?)?;
    m.add_function(wrap_pyfunction!(line_fit::fit_line, m)?)?;
    m.add_function(wrap_pyfunction!(import::import_segments, m)?)?;
    m.add_function(wrap_pyfunction!(import::detect_import, m)?)?;
    m.add_function(wrap_pyfunction!(formula::evaluate_formulas, m)?)?;
    m.add_function(wrap_pyfunction!(cam_import::import_tool_poses, m)?)?;
    m.add_function(wrap_pyfunction!(cam_import::import_target, m)?)?;
    m.add_function(wrap_pyfunction!(module_info::version, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
