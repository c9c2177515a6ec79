//! What ruledlab's two WebAssembly modules share (the teaching module `ruledlab-wasm` and the CAM
//! module `ruledlab-cam-wasm`): argument checks that say what was given, JavaScript `Error`s
//! with the core's message, a stable `code` and `details`, flat buffers for WebGL, the count of
//! live objects, and User Timing marks. It exports nothing to JavaScript itself: each module
//! declares its own classes and functions, so that neither carries the other's.
//!
//! Nothing here panics on any input: no trap crosses the boundary, and a module stays usable
//! after an error.

pub mod args;
pub mod buffers;
pub mod error;
pub mod live;
pub mod subdivide_options;
pub mod text;
pub mod timing;
