//! Linear algebra for the variational schemes: a banded symmetric solver. The dense linear
//! algebra of the core (the 6 × 6 eigenproblem of the linear-complex fit, linear_complex.rs)
//! uses nalgebra, which is also the reference the banded solver is checked against.

pub mod banded;

pub use banded::SymmetricBanded;
