//! Linear algebra for the variational schemes. nalgebra is used only here (and in tests,
//! as the reference the banded solver is checked against).

pub mod banded;

pub use banded::{CholeskyBanded, SymmetricBanded};
