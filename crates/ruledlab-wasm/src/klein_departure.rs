//! How far the line-space subdivision's points leave the Klein quadric M before they are
//! projected back, for JavaScript (beyond the paper; Section 4 in line space; the core's
//! `klein::departure`): `kleinDeparture(segments, subdivide, image)`, the largest residual
//! ρ = a·a₀/|a|² (K3) of each step's points before and after N, and the last step's points in the
//! reader's 3D image of P⁵ (K5), before and after N.

use super::klein_view::{projection_of, read_option};
use js_sys::{Float32Array, Float64Array, Object, Reflect};
use ruledlab::{line_space_departure, KleinPoint, RuledSurface};
use ruledlab_js::args::{self, fail};
use ruledlab_js::buffers::points_f32;
use ruledlab_js::subdivide_options::read;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// What `kleinDeparture` returns.
#[derive(Tsify)]
#[serde(rename_all = "camelCase")]
#[allow(dead_code)] // the type is for TypeScript; the object is made field by field
struct KleinDeparture {
    /// For each step, the largest |ρ| of the combined points before N (K3): how far they leave M.
    #[tsify(type = "Float64Array")]
    before: Float64Array,
    /// For each step, the largest |ρ| of the lines after N: 0 to rounding.
    #[tsify(type = "Float64Array")]
    after: Float64Array,
    /// The image of each of the last step's combined points before N (3 floats each).
    #[tsify(type = "Float32Array")]
    points: Float32Array,
    /// The image of each of the last step's lines after N (3 floats each), point for point.
    #[tsify(type = "Float32Array")]
    lines: Float32Array,
}

/// `subdivide.steps` steps of a linear scheme ("chaikin", "bspline", "four-point": see
/// `SubdivideOptions`) on the lines of `segments` (6 numbers each: a then b; at least 2), with
/// how far each step's points leave M before N projects them back, and the last step's points
/// in the image `image` chooses.
#[wasm_bindgen(js_name = kleinDeparture, unchecked_return_type = "KleinDeparture")]
pub fn klein_departure(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] segments: JsValue,
    #[wasm_bindgen(unchecked_param_type = "SubdivideOptions")] subdivide: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "KleinImageOptions")] image: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "kleinDeparture";
    let coords = args::numbers(F, "segments", &segments)?;
    let surface = RuledSurface::from_flat(&coords).map_err(|e| fail(F, e))?;
    let (scheme, closed, steps, _) = read(F, subdivide, None)?;
    let projection = projection_of(F, |key| read_option(F, &["mix", "turn", "unit"], &image, key))?;
    let d = line_space_departure(&surface, scheme, closed, steps).map_err(|e| fail(F, e))?;
    let image = |points: &[KleinPoint]| points_f32(&points.iter().map(|p| projection.image(p)).collect::<Vec<_>>());
    let out = Object::new();
    for (key, value) in [
        ("before", Float64Array::from(&d.before[..]).into()),
        ("after", Float64Array::from(&d.after[..]).into()),
        ("points", image(&d.combined).into()),
        ("lines", image(&d.lines).into()),
    ] {
        Reflect::set(&out, &key.into(), &value)?;
    }
    Ok(out.into())
}
