//! The catalogue: the analytic surfaces and congruences ruledlab knows — the paper's examples
//! in closed form, ruledlab's own for the figures the paper gives no data for, and surfaces and
//! congruences typed as formulas — each with its formula texts, so the page's formula presets
//! are these (one source of truth). The top of the core: it implements the smooth surfaces and
//! congruences the algorithms are written against ([`crate::ruled::SmoothRuled`],
//! [`crate::congruence::SmoothCongruence`]); nothing in the algorithms imports it.

pub mod congruences;
pub mod formula_surface;
pub mod surfaces;
pub mod texts;

pub use congruences::{AnalyticCongruence, CongruenceSpec, FormulaCongruence};
pub use formula_surface::{FormulaSpec, FormulaSurface};
pub use surfaces::{AnalyticSurface, ORTHOGONAL_SLOPE};
pub use texts::{CongruenceTexts, SurfaceTexts, CONGRUENCES as CONGRUENCE_FORMULAS, SURFACES as SURFACE_FORMULAS};
