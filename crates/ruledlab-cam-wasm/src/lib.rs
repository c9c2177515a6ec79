//! The CAM module's JavaScript bindings (`pkg/cam/ruledlab_cam.js`), the module for making things:
//! tool paths (Example 6), their quality and meshes, five-axis machines and the G-code posts, tool
//! poses and target curves read from files; and developable strips with their flat patterns for
//! paper, a plotter or a laser cutter (SVG, DXF). The page loads it when the milling or the
//! paper-models scene opens or tool poses are imported, never before; the teaching module (`ruledlab-wasm`) carries none of it. Its objects
//! take and give plain arrays, so that no object crosses from one module to the other.
//!
//! The same rules as the teaching module's: every export validates its arguments and throws a JS
//! `Error` with a stable `code` (the helpers are `ruledlab-js`'s); nothing panics across the
//! boundary; one file per JavaScript class.

// the classes
mod flat_pattern;
mod tool_path;

// the free functions
mod developable;
mod import;
mod module_info;
mod optimise;

// what they share
mod gcode_options;

pub use developable::{
    cone_surface, cylinder_surface, make_developable, max_abs_delta, rectifying_developable, tangent_surface,
};
pub use flat_pattern::FlatPattern;
pub use import::{import_target, import_tool_poses};
pub use module_info::{live_objects, version};
pub use optimise::optimise_poses;
pub use tool_path::ToolPath;
