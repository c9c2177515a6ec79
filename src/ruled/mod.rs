//! Discrete ruled surfaces (Sections 2–4).

pub mod accuracy;
pub mod convergence;
pub mod development;
pub mod invariants;
pub mod isometry;
pub(crate) mod kernel;
pub mod smooth;
pub mod surface;

pub use development::{envelope_radii, Development};
pub use invariants::{Invariants, InvariantsBlock, PairInvariants};
pub use isometry::HingeChain;
pub use smooth::SmoothRuled;
pub use surface::RuledSurface;
