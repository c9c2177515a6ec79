//! The analytic surfaces and congruences of the paper's examples, in closed form.

pub mod congruences;
pub mod surfaces;

pub use congruences::AnalyticCongruence;
pub use surfaces::{AnalyticSurface, Jet, Ranges};
