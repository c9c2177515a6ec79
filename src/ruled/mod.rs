//! Discrete ruled surfaces (Sections 2–4).

pub mod convergence;
pub mod invariants;
pub mod surface;

pub use invariants::{Invariants, PairInvariants};
pub use surface::RuledSurface;
