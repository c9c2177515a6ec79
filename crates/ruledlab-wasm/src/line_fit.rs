//! The least-squares line of points for JavaScript (beyond the paper): `fitLine(points)`.

use ruledlab_js::args::{fail, numbers, to_js};

use js_sys::Float64Array;
use ruledlab::points_from_flat;
use serde::Serialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// The least-squares line of points and how far they stray from it.
#[derive(Serialize, Tsify)]
struct LineFit {
    /// The centroid of the points, on the line.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    point: Float64Array,
    /// Unit direction of the line.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    direction: Float64Array,
    /// The largest distance of a point from the line: 0 exactly when the points are collinear.
    deviation: f64,
    /// The length of the points' shadow on the line: deviation / extent is scale-free.
    extent: f64,
}

/// The line that fits `points` (3 numbers each, at least two, not all equal) best in the least
/// squares sense, and the largest distance of a point from it (F1 of the core's `line_fit`).
#[wasm_bindgen(js_name = fitLine, unchecked_return_type = "LineFit")]
pub fn fit_line(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] points: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "fitLine";
    let coords = numbers(F, "points", &points)?;
    let points = points_from_flat(&coords).map_err(|e| fail(F, e))?;
    let fit = ruledlab::fit_line(&points).map_err(|e| fail(F, e))?;
    to_js(
        F,
        &LineFit {
            point: Float64Array::from(&fit.point.to_array()[..]),
            direction: Float64Array::from(&fit.direction.to_array()[..]),
            deviation: fit.deviation,
            extent: fit.extent,
        },
    )
}
