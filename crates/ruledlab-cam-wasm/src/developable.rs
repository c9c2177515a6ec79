//! Developable strips for JavaScript (Section 3, beyond its approximate development): the discrete
//! tangent surface, cone, cylinder and rectifying developable of a directrix polygon, and the
//! repair that makes an edited strip developable again (the core's `developable`). Each returns the
//! strip's segments (6 numbers per ruling: a.x a.y a.z b.x b.y b.z; the teaching module's
//! `RuledSurface.fromSegments` takes them), its consecutive rulings coplanar (δ = 0 to rounding).
//! In the CAM module, the module for making things, with the flat patterns cut from them: the
//! teaching module stays within its size.

use glam::DVec3;
use js_sys::Float64Array;
use ruledlab::{points_from_flat, RuledSurface, Span};
use ruledlab_js::args::{fail, number, numbers};
use ruledlab_js::timing::Measure;
use wasm_bindgen::prelude::*;

/// The directrix (3 numbers per point) and the span [from, to] of the rulings.
fn directrix(f: &str, points: &JsValue, from: &JsValue, to: &JsValue) -> Result<(Vec<DVec3>, Span), JsValue> {
    let flat = numbers(f, "points", points)?;
    let points = points_from_flat(&flat).map_err(|e| fail(f, e))?;
    Ok((points, Span { from: number(f, "from", from)?, to: number(f, "to", to)? }))
}

/// The strip's segments for JavaScript.
fn segments(f: &str, made: ruledlab::Result<RuledSurface>) -> Result<Float64Array, JsValue> {
    made.map(|s| Float64Array::from(s.flat())).map_err(|e| fail(f, e))
}

/// A strip from its segments (6 numbers per ruling).
pub(crate) fn strip(f: &str, value: &JsValue) -> Result<RuledSurface, JsValue> {
    let coords = numbers(f, "segments", value)?;
    RuledSurface::from_flat(&coords).map_err(|e| fail(f, e))
}

/// A vector of three finite numbers.
fn vector(f: &str, name: &str, value: &JsValue) -> Result<DVec3, JsValue> {
    let v = numbers(f, name, value)?;
    if v.len() != 3 {
        return Err(fail(f, format!("{name} must be 3 numbers, got {}", v.len())));
    }
    Ok(DVec3::new(v[0], v[1], v[2]))
}

/// The discrete tangent surface of a directrix polygon (3 numbers per point, at least 3 points,
/// turning at every interior point): the ruling of edge i is the line of c_i c_{i+1}, from
/// c_{i+1} + from·t_i to c_{i+1} + to·t_i (t_i its unit direction, 0 ≤ from < to). Throws with
/// the core's reason (`span-crosses-regression`, `directrix-no-turn-at`, …).
#[wasm_bindgen(js_name = tangentSurface)]
pub fn tangent_surface(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] points: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] from: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] to: JsValue,
) -> Result<Float64Array, JsValue> {
    const F: &str = "tangentSurface";
    let (points, span) = directrix(F, &points, &from, &to)?;
    segments(F, ruledlab::tangent_surface(&points, span))
}

/// The cone over a directrix polygon with its apex (3 numbers): rulings A + s (c_i − A),
/// s ∈ [from, to], 0 ≤ from < to (s = 1 on the directrix, 0 at the apex).
#[wasm_bindgen(js_name = coneSurface)]
pub fn cone_surface(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] points: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] apex: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] from: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] to: JsValue,
) -> Result<Float64Array, JsValue> {
    const F: &str = "coneSurface";
    let (points, span) = directrix(F, &points, &from, &to)?;
    let apex = vector(F, "apex", &apex)?;
    segments(F, ruledlab::cone(&points, apex, span))
}

/// The cylinder over a directrix polygon with rulings along `direction` (3 numbers, not zero):
/// c_i + v d, v ∈ [from, to], d the unit direction.
#[wasm_bindgen(js_name = cylinderSurface)]
pub fn cylinder_surface(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] points: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] direction: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] from: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] to: JsValue,
) -> Result<Float64Array, JsValue> {
    const F: &str = "cylinderSurface";
    let (points, span) = directrix(F, &points, &from, &to)?;
    let direction = vector(F, "direction", &direction)?;
    segments(F, ruledlab::cylinder(&points, direction, span))
}

/// The rectifying developable of a directrix polygon: the strip that holds it as a geodesic (it
/// unfolds onto a straight line), rulings c_i + v r_i, v ∈ [from, to].
#[wasm_bindgen(js_name = rectifyingDevelopable)]
pub fn rectifying_developable(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] points: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] from: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] to: JsValue,
) -> Result<Float64Array, JsValue> {
    const F: &str = "rectifyingDevelopable";
    let (points, span) = directrix(F, &points, &from, &to)?;
    segments(F, ruledlab::rectifying_developable(&points, span))
}

/// The strip (its segments, 6 numbers per ruling) made developable after an edit: the runs of
/// pairs that are not coplanar found, one ruling of each kept as given (the dragged one), the ends
/// b of the others moved as little as possible until every pair is coplanar; the ends a and every
/// ruling's length stay. A strip that is developable comes back unchanged.
#[wasm_bindgen(js_name = makeDevelopable)]
pub fn make_developable(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] segments: JsValue,
) -> Result<Float64Array, JsValue> {
    const F: &str = "makeDevelopable";
    let _measure = Measure::start(F);
    let s = strip(F, &segments)?;
    Ok(Float64Array::from(ruledlab::make_developable(&s).surface.flat()))
}

/// The largest |δ| (1) of the strip's pairs of consecutive rulings that are not coplanar, 0 for a
/// developable strip (see `maxOffPlane`: where rulings meet at small angles, δ computed from
/// rounded ends is noise of the order of ε|d|/φ², so a coplanar pair reads 0); the strip as its
/// segments.
#[wasm_bindgen(js_name = maxAbsDelta)]
pub fn max_abs_delta(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] segments: JsValue,
) -> Result<f64, JsValue> {
    Ok(ruledlab::max_abs_delta(&strip("maxAbsDelta", &segments)?).0)
}

/// How far the strip is from developable, as a length: over its pairs of consecutive rulings, the
/// largest height of the tetrahedron of the pair's four ends over its largest face (the distance
/// of one end from the plane the other three define best; 0 exactly for coplanar rulings). A pair counts as coplanar when this is at
/// most 1e-12 of the strip's size (the diagonal of its bounding box, at least 1).
#[wasm_bindgen(js_name = maxOffPlane)]
pub fn max_off_plane(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] segments: JsValue,
) -> Result<f64, JsValue> {
    Ok(ruledlab::max_off_plane(&strip("maxOffPlane", &segments)?).0)
}
