//! Polygons refined by the curve schemes of Section 4 for JavaScript: `subdividePolygon` and
//! `turningAngles` (how much the refined polygons turn, step by step).

use js_sys::Float64Array;
use ruledlab::points_from_flat;
use ruledlab_js::args::{fail, numbers};
use ruledlab_js::subdivide_options::{read, Space};
use ruledlab_js::timing::Measure;
use wasm_bindgen::prelude::*;

/// A polygon (3 numbers per point) refined by a curve scheme (see `SubdivideOptions`;
/// "variational" is for ruled strips only).
#[wasm_bindgen(js_name = subdividePolygon)]
pub fn subdivide_polygon(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] points: JsValue,
    #[wasm_bindgen(unchecked_param_type = "SubdivideOptions")] options: JsValue,
) -> Result<Float64Array, JsValue> {
    const F: &str = "subdividePolygon";
    let _measure = Measure::start(F);
    let flat = numbers(F, "points", &points)?;
    let points = points_from_flat(&flat).map_err(|e| fail(F, e))?;
    let (scheme, closed, steps, space) = read(F, options, None)?;
    if matches!(space, Space::Lines(_)) {
        return Err(fail(F, "options.space \"lines\" refines ruled surfaces, not polygons"));
    }
    let out = ruledlab::subdivide_polygon(&points, scheme, closed, steps).map_err(|e| fail(F, e))?;
    Ok(Float64Array::from(bytemuck::cast_slice::<_, f64>(&out)))
}

/// The largest turning angle (radians, 0 … π: the largest angle between an edge and the
/// next) of a polygon (3 numbers per point) and of each of its refinements by a curve scheme
/// (see `SubdivideOptions`; "variational" is for ruled strips only): `steps + 1` numbers, the
/// first for the polygon itself. Where the limit is a regular C¹ curve the polygons turn less
/// and less from step to step; where the angle stops falling the limit has a corner or a cusp,
/// or is approached slowly.
#[wasm_bindgen(js_name = turningAngles)]
pub fn turning_angles(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] points: JsValue,
    #[wasm_bindgen(unchecked_param_type = "SubdivideOptions")] options: JsValue,
) -> Result<Float64Array, JsValue> {
    const F: &str = "turningAngles";
    let flat = numbers(F, "points", &points)?;
    let points = points_from_flat(&flat).map_err(|e| fail(F, e))?;
    let (scheme, closed, steps, space) = read(F, options, None)?;
    if matches!(space, Space::Lines(_)) {
        return Err(fail(F, "options.space \"lines\" refines ruled surfaces, not polygons"));
    }
    let out = ruledlab::turning_angles(&points, scheme, closed, steps).map_err(|e| fail(F, e))?;
    Ok(Float64Array::from(&out[..]))
}
