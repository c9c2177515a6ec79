//! The shared vocabulary at the bottom of the core: what every layer above speaks of and
//! nothing here depends on — jets of smooth surfaces and congruences (what the exact
//! invariants of Sections 2 and 5 are computed from), parameter intervals and their samplings,
//! and the checks every input's coordinates pass. Above it: the discrete models (`ruled`,
//! `subdivision`, `congruence`, `milling`), and at the top the catalogue of analytic surfaces
//! and congruences, which nothing below imports (ARCHITECTURE.md; `tests/architecture.rs`).

mod coordinates;
mod interval;
mod jet;

pub use coordinates::check_coordinates;
pub use interval::{check_interval, parameters, Ranges};
pub use jet::{CongruenceJet, Jet};
