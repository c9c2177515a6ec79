//! The analytic surfaces and congruences of the paper's examples, in closed form.

pub mod congruences;
pub mod formula_surface;
pub mod surfaces;

pub use congruences::{AnalyticCongruence, CongruenceJet, CongruenceSpec, FormulaCongruence};
pub use formula_surface::{FormulaSpec, FormulaSurface};
pub use surfaces::{AnalyticSurface, Jet, Ranges};
