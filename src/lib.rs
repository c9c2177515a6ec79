//! # ruledlab
//!
//! Discrete models of ruled surfaces and line congruences, after B. Odehnal and
//! H. Pottmann, *Computing with Discrete Models of Ruled Surfaces and Line Congruences*.
//!
//! A discrete ruled surface is a sequence of lines R_0, R_1, …, each given as a segment
//! a_i → b_i ([`RuledSurface`]). From it ruledlab computes the discrete counterparts of the
//! differential invariants (Section 2: angles, signed distances, common perpendiculars and
//! their footpoints, the distribution parameter, the striction polygon), with the
//! convergence orders of Propositions 1 and 2 measured in [`ruled::convergence`].
//!
//! The core is pure Rust on `f64` and glam's `DVec3`; it knows nothing of JavaScript. The
//! WebAssembly bindings live in `wasm` (compiled for wasm32 only) and take and return
//! flat typed arrays. Conventions and corrections to the paper: `ERRATA.md` of the paper
//! notes, summarised in each module's documentation.
//!
//! ```
//! use ruledlab::{AnalyticSurface, RuledSurface};
//! let hyperboloid = AnalyticSurface::by_name("hyperboloid").unwrap();
//! let surface: RuledSurface = hyperboloid.sample(64, hyperboloid.ranges()).unwrap();
//! let inv = surface.invariants();
//! assert_eq!(inv.striction.len(), 62);
//! ```

pub mod congruence;
pub mod error;
pub mod examples;
pub mod formula;
pub mod io;
pub mod linalg;
pub mod line;
pub mod linear_complex;
pub mod mesh;
pub mod milling;
pub mod ruled;
pub mod subdivision;
pub mod tolerance;

#[cfg(target_family = "wasm")]
pub mod wasm;

pub use error::{Error, Result};
pub use examples::AnalyticSurface;
pub use line::{Line, Segment};
pub use ruled::{Invariants, RuledSurface};
