//! What `AnalyticSurface.list()` and `AnalyticCongruence.list()` say of each entry of the
//! catalogue (Sections 3 and 5's examples): its name, title and default domain.

use serde::Serialize;
use tsify_next::Tsify;

/// A catalogue entry's name, title and default domain [u_min, u_max] × [v_min, v_max]
/// (`#[serde(flatten)]` into each class's info).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct CatalogueEntry {
    /// Machine name, e.g. "hyperboloid".
    pub name: &'static str,
    /// Human title.
    pub title: &'static str,
    /// The least u.
    pub u_min: f64,
    /// The greatest u.
    pub u_max: f64,
    /// The least v.
    pub v_min: f64,
    /// The greatest v.
    pub v_max: f64,
}
