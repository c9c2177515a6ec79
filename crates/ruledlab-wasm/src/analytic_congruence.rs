//! `AnalyticCongruence` for JavaScript: the line congruences of the catalogue, known in closed
//! form (Section 5, Examples 4 and 5), and those typed as formulas; listed, sampled as grids,
//! compared with refined grids, and their exact focal geometry.

use super::catalogue_entry::CatalogueEntry;
use super::focal::focal_js;
use super::formula::{congruence_presets, congruence_spec};
use super::line_congruence::LineCongruence;
use ruledlab::tolerance::{MAX_REACH, MAX_RULINGS};
use ruledlab::SmoothCongruence;
use ruledlab_js::args::{self, fail, to_js, to_js_with};
use ruledlab_js::live::Live;
use ruledlab_js::timing::Measure;
use serde::Serialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// One congruence as listed by `AnalyticCongruence.list()`: its domain and the grid size of
/// the paper's figure.
#[derive(Tsify)]
#[allow(dead_code)] // the type is for TypeScript: `list` sets `rows` and `cols` on the entry
struct AnalyticCongruenceInfo {
    /// Name, title and domain.
    #[serde(flatten)]
    entry: CatalogueEntry,
    /// The rows of the paper's grid.
    rows: usize,
    /// Its columns.
    cols: usize,
}

/// Errors of a refined congruence against the exact one, over its new lines.
#[derive(Serialize, Tsify)]
struct CongruenceErrors {
    /// The largest distance of the d₁ points.
    distance: f64,
    /// The largest angle of the directions (radians).
    angle: f64,
}

/// The congruences of Examples 4 and 5 in closed form.
#[wasm_bindgen]
pub struct AnalyticCongruence {
    inner: ruledlab::AnalyticCongruence,
    _live: Live,
}

impl AnalyticCongruence {
    /// Wraps a core congruence.
    pub(crate) fn from_core(inner: ruledlab::AnalyticCongruence) -> Self {
        AnalyticCongruence { inner, _live: Live::new() }
    }

    /// The core congruence.
    pub fn core(&self) -> &ruledlab::AnalyticCongruence {
        &self.inner
    }
}

#[wasm_bindgen]
impl AnalyticCongruence {
    // --- the catalogue, and congruences typed as formulas

    /// Every congruence: name, title, domain and the grid size of the paper's figure.
    #[wasm_bindgen(unchecked_return_type = "AnalyticCongruenceInfo[]")]
    pub fn list() -> Result<JsValue, JsValue> {
        let list: js_sys::Array = ruledlab::AnalyticCongruence::ALL
            .iter()
            .map(|c| {
                let ((u_min, u_max), (v_min, v_max), rows, cols) = c.domain();
                let entry = CatalogueEntry { name: c.name(), title: c.title(), u_min, u_max, v_min, v_max };
                to_js_with("AnalyticCongruence.list", &entry, &[("rows", rows.into()), ("cols", cols.into())])
            })
            .collect::<Result<_, _>>()?;
        Ok(list.into())
    }

    /// The congruence named `name` ("sphere", "hyperbolic-paraboloid", "example5").
    #[wasm_bindgen(js_name = byName)]
    pub fn by_name(
        #[wasm_bindgen(unchecked_param_type = "string")] name: JsValue,
    ) -> Result<AnalyticCongruence, JsValue> {
        let inner = args::by_name("AnalyticCongruence.byName", &name, ruledlab::AnalyticCongruence::by_name)?;
        Ok(AnalyticCongruence { inner, _live: Live::new() })
    }

    /// Every congruence of the catalogue as formulas, in menu order: the presets of "Your
    /// congruence" and the focal scene's congruences.
    #[wasm_bindgen(js_name = formulaPresets, unchecked_return_type = "CongruencePreset[]")]
    pub fn formula_presets() -> Result<JsValue, JsValue> {
        to_js("AnalyticCongruence.formulaPresets", &congruence_presets())
    }

    /// A congruence typed as formulas (`CongruenceFormulas`), with exact derivatives.
    #[wasm_bindgen(js_name = fromFormulas)]
    pub fn from_formulas(
        #[wasm_bindgen(unchecked_param_type = "CongruenceFormulas")] spec: JsValue,
    ) -> Result<AnalyticCongruence, JsValue> {
        const F: &str = "AnalyticCongruence.fromFormulas";
        let _measure = Measure::start(F);
        let spec = congruence_spec(F, spec)?;
        ruledlab::AnalyticCongruence::from_formulas(&spec).map(AnalyticCongruence::from_core).map_err(|e| fail(F, e))
    }

    // --- grids of its lines, and how far refined grids are from it

    /// A rows × cols grid of its lines (default: the paper's grid size), each the segment
    /// from p to p + reach·d (`reach` default 1: the paper gives no length: docs/src/conventions.md, choices;
    /// shorter segments are the same lines, and every scheme refines them to the same lines).
    pub fn grid(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] rows: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] cols: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] reach: JsValue,
    ) -> Result<LineCongruence, JsValue> {
        const F: &str = "AnalyticCongruence.grid";
        let _measure = Measure::start(F);
        let (_, _, r0, c0) = self.inner.domain();
        let rows = args::optional_integer(F, "rows", &rows, 2, MAX_RULINGS, r0)?;
        let cols = args::optional_integer(F, "cols", &cols, 2, MAX_RULINGS, c0)?;
        let reach = if reach.is_undefined() { 1.0 } else { args::number(F, "reach", &reach)? };
        if !(reach > 0.0 && reach <= MAX_REACH) {
            return Err(fail(F, format!("reach must be a number in (0, {MAX_REACH:e}], got {reach}")));
        }
        self.inner.grid_reaching(rows, cols, reach).map(LineCongruence::from_core).map_err(|e| fail(F, e))
    }

    /// Errors of `refined` (refined from one of its grids) against the exact lines at the
    /// same parameters, over the new lines: the largest distance of the d₁ points and the
    /// largest angle of the directions (radians).
    #[wasm_bindgen(unchecked_return_type = "CongruenceErrors")]
    pub fn errors(&self, refined: &LineCongruence) -> Result<JsValue, JsValue> {
        let _measure = Measure::start("AnalyticCongruence.errors");
        let (distance, angle) = self.inner.errors(refined.core());
        to_js("AnalyticCongruence.errors", &CongruenceErrors { distance, angle })
    }

    /// Errors of the paper's diagonal insertion (`subdivide({ scheme: 'butterfly', diagonalOnly:
    /// true })` of one of its grids: the (rows − 1) × (cols − 1) lines on the diagonals, Fig. 13)
    /// against the exact lines at the grid cells' centres: the largest distance of the d₁
    /// points and the largest angle of the directions (radians).
    #[wasm_bindgen(js_name = diagonalErrors, unchecked_return_type = "CongruenceErrors")]
    pub fn diagonal_errors(&self, diagonal: &LineCongruence) -> Result<JsValue, JsValue> {
        let _measure = Measure::start("AnalyticCongruence.diagonalErrors");
        let (distance, angle) = self.inner.diagonal_errors(diagonal.core());
        to_js("AnalyticCongruence.diagonalErrors", &CongruenceErrors { distance, angle })
    }

    // --- focal geometry (beyond the paper)

    /// The exact focal geometry at the lines of its rows × cols grid (default: the paper's
    /// grid size), from the exact derivatives, torsal directions in grid steps: comparable
    /// line by line with `grid(rows, cols).focal()`.
    #[wasm_bindgen(unchecked_return_type = "FocalGeometry")]
    pub fn focal(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] rows: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] cols: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "AnalyticCongruence.focal";
        let _measure = Measure::start(F);
        let (_, _, r0, c0) = self.core().domain();
        let rows = args::optional_integer(F, "rows", &rows, 2, MAX_RULINGS, r0)?;
        let cols = args::optional_integer(F, "cols", &cols, 2, MAX_RULINGS, c0)?;
        if rows.saturating_mul(cols) > MAX_RULINGS {
            let got = rows.saturating_mul(cols);
            return Err(fail(F, ruledlab::Error::TooMany { what: "lines", got, max: MAX_RULINGS }));
        }
        focal_js(F, rows, cols, &ruledlab::focal_analytic(self.core(), rows, cols))
    }
}
