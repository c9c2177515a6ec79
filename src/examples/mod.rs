//! The analytic surfaces and congruences of the paper's examples, in closed form.

pub mod surfaces;

pub use surfaces::{AnalyticSurface, Jet, Ranges};
