//! The Klein quadric view for JavaScript (beyond the paper): `kleinView(segments, options)`, the
//! lines of a discrete ruled surface as points of the Klein quadric M in the reader's 3D image of
//! P⁵ (the core's `klein` module; the book's chapter "The Klein quadric"), with the drawing's
//! f32 buffers ready for WebGL.

use glam::DVec3;
use js_sys::{Float32Array, Float64Array};
use ruledlab::tolerance::{KLEIN_OUTLINE_CIRCLES, KLEIN_OUTLINE_SAMPLES};
use ruledlab::{complex_residuals, fit_linear_complex, KleinPolygon, Projection, RegulusPlane, RuledSurface};
use ruledlab_js::args::{self, fail, fail_option, to_js};
use ruledlab_js::buffers::points_f32;
use serde::Serialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// Options of `kleinView` (read key by key: the teaching module's size).
#[derive(Tsify)]
#[serde(rename_all = "camelCase")]
#[allow(dead_code)] // the type is for TypeScript; the options are read by `option`
struct KleinViewOptions {
    /// α of the image q = cos α x + sin α R_β y, in degrees from 0 (the x-sphere) to 90 (the
    /// y-sphere); default 45.
    mix: Option<f64>,
    /// β, the turn of the y-sphere about the z-axis, in degrees; default 0.
    turn: Option<f64>,
    /// ℓ, the unit of length that makes moments comparable with directions; default 1.
    unit: Option<f64>,
    /// The last ruling and the first are a step too (a closed surface); default false.
    closed: Option<bool>,
}

/// What `kleinView` returns: the drawing's buffers and the readouts.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
struct KleinView {
    /// The image of each ruling's point L_i = (e_i, a_i × e_i), 3 floats each.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    points: Float32Array,
    /// The polygon's steps where Ω(L_i, L_{i+1}) > 0 (6 floats each: the chord of the two images).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    positive: Float32Array,
    /// The steps where Ω < 0.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    negative: Float32Array,
    /// The torsal steps (Ω = 0 to rounding: consecutive rulings meet); their chord lies on M.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    torsal: Float32Array,
    /// Ω(L_i, L_{i+1}) of each step (= −h sin φ).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    omega: Float64Array,
    /// How many steps are torsal.
    torsal_steps: usize,
    /// The step of least |Ω| (−1 without steps) and its Ω (NaN without steps).
    least_step: i64,
    /// See `leastStep`.
    least_omega: f64,
    /// The largest Klein residual |Ω(L, L)|/2 of the rulings' points.
    max_residual: f64,
    /// The outline of M's image: circles on the spheres bounding it, as one polyline (3 floats a
    /// point) broken by NaN points between the circles.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    outline: Float32Array,
    /// The radii of the shell that is M's image: [inner, outer].
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    radii: Float64Array,
    /// The conic in which the plane of the first, middle and last ruling cuts M (a closed
    /// polyline, 3 floats a point; empty when the three span no such plane).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    conic: Float32Array,
    /// The largest distance of a ruling's point from that plane (the sine of an angle in R⁶):
    /// 0 when the rulings are one regulus; NaN without a plane.
    plane_distance: f64,
    /// The largest |Ω(C, L)| of the rulings for the linear complex C that fits them best: 0 when
    /// their points lie in one hyperplane section of M.
    complex_residual: f64,
}

/// The lines of `segments` (6 numbers each: a then b; at least 2) as points of the Klein quadric
/// in the image `options` chooses (`KleinViewOptions`), with Ω of consecutive rulings, the
/// regulus's conic and the complex's residual.
#[wasm_bindgen(js_name = kleinView, unchecked_return_type = "KleinView")]
pub fn klein_view(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] segments: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "KleinViewOptions")] options: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "kleinView";
    let coords = args::numbers(F, "segments", &segments)?;
    let surface = RuledSurface::from_flat(&coords).map_err(|e| fail(F, e))?;
    let (mix, turn) = (option(&options, "mix")?.unwrap_or(45.0), option(&options, "turn")?.unwrap_or(0.0));
    let unit = option(&options, "unit")?.unwrap_or(1.0);
    if !(0.0..=90.0).contains(&mix) {
        return Err(fail_option(F, "mix", format!("options.mix must be from 0 to 90 (degrees), got {mix}")));
    }
    let projection = Projection::new(mix.to_radians(), turn.to_radians(), unit).map_err(|e| fail(F, e))?;
    let closed = match options.is_object().then(|| js_sys::Reflect::get(&options, &"closed".into())) {
        Some(Ok(v)) => args::optional_bool(F, "options.closed", &v, false)?,
        _ => false,
    };
    let outline = projection.outline(KLEIN_OUTLINE_CIRCLES, KLEIN_OUTLINE_SAMPLES).map_err(|e| fail(F, e))?;

    let polygon = KleinPolygon::of(&surface, closed);
    let image: Vec<_> = polygon.points.iter().map(|p| projection.image(p)).collect();
    let n = image.len();
    let (mut positive, mut negative, mut torsal) = (Vec::new(), Vec::new(), Vec::new());
    for (i, w) in polygon.omega.iter().enumerate() {
        let chord = [image[i], image[(i + 1) % n]];
        match (polygon.torsal[i], *w > 0.0) {
            (true, _) => torsal.extend(chord),
            (false, true) => positive.extend(chord),
            (false, false) => negative.extend(chord),
        }
    }
    let least = polygon.least_omega();

    let three = [&polygon.points[0], &polygon.points[n / 2], &polygon.points[n - 1]];
    let (conic, plane_distance) = match RegulusPlane::through(three) {
        Ok(plane) => (
            plane
                .conic(KLEIN_OUTLINE_SAMPLES)
                .map(|c| c.iter().map(|p| projection.image(p)).collect())
                .unwrap_or_default(),
            polygon.points.iter().map(|p| plane.distance(p)).fold(0.0, f64::max),
        ),
        Err(_) => (Vec::new(), f64::NAN),
    };
    let segments: Vec<_> = surface.segments().collect();
    let complex = fit_linear_complex(&segments, None);
    let complex_residual =
        complex_residuals(complex.plucker, &polygon.points).iter().fold(0.0f64, |m, r| m.max(r.abs()));

    let (inner, outer) = projection.radii();
    to_js(
        F,
        &KleinView {
            points: points_f32(&image),
            positive: points_f32(&positive),
            negative: points_f32(&negative),
            torsal: points_f32(&torsal),
            omega: Float64Array::from(&polygon.omega[..]),
            torsal_steps: polygon.torsal.iter().filter(|&&t| t).count(),
            least_step: least.map_or(-1, |(i, _)| i as i64),
            least_omega: least.map_or(f64::NAN, |(_, w)| w),
            max_residual: polygon.max_residual,
            outline: points_f32(&outline.join(&DVec3::NAN)),
            radii: Float64Array::from(&[inner, outer][..]),
            conic: points_f32(&conic),
            plane_distance,
            complex_residual,
        },
    )
}

/// The number `options[key]` of `kleinView`'s options (None when the options or the key are left
/// out); an error for a key it does not know, or a value that is not a finite number.
fn option(options: &JsValue, key: &str) -> Result<Option<f64>, JsValue> {
    const F: &str = "kleinView";
    const KEYS: [&str; 4] = ["mix", "turn", "unit", "closed"];
    if options.is_undefined() || options.is_null() {
        return Ok(None);
    }
    if !options.is_object() {
        return Err(fail(F, "options must be an object"));
    }
    if key == KEYS[0] {
        // the first key read checks them all
        for k in js_sys::Object::keys(options.unchecked_ref::<js_sys::Object>()).iter().filter_map(|k| k.as_string()) {
            if !KEYS.contains(&k.as_str()) {
                return Err(fail_option(F, &k, format!("options.{k} is not an option; known: {}", KEYS.join(", "))));
            }
        }
    }
    match js_sys::Reflect::get(options, &key.into()) {
        Ok(v) if v.is_undefined() => Ok(None),
        Ok(v) => args::number(F, &format!("options.{key}"), &v).map(Some),
        Err(_) => Ok(None),
    }
}
