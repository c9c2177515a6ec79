//! The shared vocabulary at the bottom of the core: what every layer above speaks of and
//! nothing here depends on — jets of smooth surfaces and congruences (what the exact
//! invariants of Sections 2 and 5 are computed from), parameter intervals and their samplings,
//! the checks every input's coordinates pass, and the two-lane `f64` arithmetic of the SIMD
//! kernels (`lanes`, with the angle φ of Section 2 computed in its lanes: `angle`). Above it: the discrete models (`ruled`,
//! `subdivision`, `congruence`, `milling`), and at the top the catalogue of analytic surfaces
//! and congruences, which nothing below imports (ARCHITECTURE.md; `tests/architecture.rs`).

pub(crate) mod angle;
mod coordinates;
mod interval;
mod jet;
pub(crate) mod lanes;

pub use angle::atan2_x2;
pub use coordinates::check_coordinates;
pub use interval::{check_interval, sample_parameters, Ranges};
pub use jet::{CongruenceJet, Jet};
