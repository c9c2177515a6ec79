//! # ruledlab-cam
//!
//! Five-axis milling with the strips of ruledlab: Example 6 of B. Odehnal and H. Pottmann,
//! *Computing with Discrete Models of Ruled Surfaces and Line Congruences* (Section 4, Figs.
//! 16–18) — a few tool poses refined by the paper's strip schemes into a smooth tool path — and
//! beyond it: the quality of the path (deviation of the tool's envelope from the part), five-axis
//! machines and their kinematics, the G-code posts for LinuxCNC, Heidenhain and Sinumerik with
//! the controller's interpolation checked, and tool poses and target curves read from the files
//! CAM systems write.
//!
//! It builds on the geometry crate `ruledlab` (the strip schemes, ruled surfaces, meshes, the
//! readers of JSON and tables) and adds nothing to it: `ruledlab` compiles without this crate.
//! Its limits are in [`tolerance`], its messages in [`CAM_MESSAGES`].
//!
//! ```
//! use ruledlab_cam::{example_tool_path, gcode, Machine, PostOptions};
//! let path = example_tool_path(8).unwrap();
//! let options = PostOptions { machine: Machine::preset("table-table-ac").unwrap(), ..PostOptions::default() };
//! let program = gcode(&path, &options).unwrap();
//! assert!(program.text.contains("G93"));
//! ```

mod example;
mod flip;
mod kinematics;
mod linearise;
mod machine;
mod messages;
mod motion;
mod optimise;
mod poses;
mod post;
mod quality;
mod solve;
mod stock;
mod sweep;
mod target_curve;
pub mod tolerance;
mod tool_path;
mod units;

pub use messages::CAM_MESSAGES;

// Example 6: tool poses, the tool, the refined path and its meshes
pub use example::{
    example_pose, example_profile, example_tool_path, example_tool_path_for, part_height, part_mesh, EXAMPLE_RANGE,
};
pub use tool_path::{Pose, Tool, ToolEnd, ToolPath};

// how well the path machines the part
pub use quality::{deviation, deviation_per_pose, Quality};
// the sweep of a path or a program as the controller moves the tool, and the part's deviation from it
pub use sweep::{
    envelope_deviation, path_blocks, pose_at, sweep_deviation, tool_distance, EnvelopeDeviation, Move, SweptBlock,
};

// tool poses fitted to the part: the ruling-aligned start and the optimisation
pub use optimise::{optimise_poses, ruling_aligned, OptimiseOptions, Optimised};

// five-axis machines and their kinematics
pub use kinematics::{at_pole, forward_kinematics, orientations, pole_angle, tool_axis, Joints};
pub use machine::{AxisName, Carrier, Machine, RotaryAxis, MACHINE_PRESETS};
pub use solve::{inverse_kinematics, solve, SolveOptions, Solved};

// the G-code post: the controller's interpolation, the axes' motion, the program
pub use linearise::{BlockDeviation, Interpolation, Linearisation};
pub use motion::{BlockMotion, Limit};
pub use post::{
    gcode, gcode_reporting, gcode_with, Coolant, Dialect, Holder, Mode, Numbering, PostOptions, Program,
    SpindleDirection, Units, Warning,
};
// a controller's language: the trait a dialect implements, what it is given, the ISO writer
pub use post::controller;

// tool poses and target curves read from files, tool paths written
pub use poses::{read_tool_poses, read_tool_poses_for, tool_path_csv, tool_path_json, ImportedPoses};
pub use target_curve::{read_target, TargetCurve};
