//! The Klein quadric view for JavaScript (beyond the paper): `kleinView(segments, options)`, the
//! lines of a discrete ruled surface as points of the Klein quadric M in the reader's 3D image of
//! P⁵ (the core's `klein` module; the book's chapter "The Klein quadric"), with the drawing's
//! f32 buffers ready for WebGL.

use glam::DVec3;
use js_sys::{Float32Array, Float64Array};
use ruledlab::tolerance::{KLEIN_OUTLINE_CIRCLES, KLEIN_OUTLINE_SAMPLES, MAX_RULINGS};
use ruledlab::{
    complex_residuals, fit_linear_complex, KleinNet, KleinPolygon, LineCongruence, Projection, RegulusPlane,
    RuledSurface,
};
use ruledlab_js::args::{self, fail, fail_option, to_js};
use ruledlab_js::buffers::points_f32;
use serde::Serialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// The 3D image of P⁵ a Klein image is drawn in (K5): `kleinView`'s and `kleinDeparture`'s
/// (read key by key: the teaching module's size).
#[derive(Tsify)]
#[serde(rename_all = "camelCase")]
#[allow(dead_code)] // the type is for TypeScript; the options are read by `read_option`
pub(crate) struct KleinImageOptions {
    /// α of the image q = cos α x + sin α R_β y, in degrees from 0 (the x-sphere) to 90 (the
    /// y-sphere); default 45.
    #[tsify(optional)]
    mix: Option<f64>,
    /// β, the turn of the y-sphere about the z-axis, in degrees; default 0.
    #[tsify(optional)]
    turn: Option<f64>,
    /// ℓ, the unit of length that makes moments comparable with directions; default 1.
    #[tsify(optional)]
    unit: Option<f64>,
}

/// Options of `kleinView`: the image (`KleinImageOptions`) and how the lines are joined (read key
/// by key: the teaching module's size).
#[derive(Tsify)]
#[serde(rename_all = "camelCase")]
#[allow(dead_code)] // the type is for TypeScript; the options are read by `option`
struct KleinViewOptions {
    /// α, β and ℓ of the image.
    #[serde(flatten)]
    image: KleinImageOptions,
    /// The last ruling and the first are a step too (a closed surface); default false.
    #[tsify(optional)]
    closed: Option<bool>,
    /// The lines are a congruence's rows × cols grid, row-major (with `cols`): the edges are the
    /// grid's, along its rows then its columns, instead of the steps of a polygon.
    #[tsify(optional)]
    rows: Option<usize>,
    /// See `rows`.
    #[tsify(optional)]
    cols: Option<usize>,
}

/// What `kleinView` returns: the drawing's buffers and the readouts.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
struct KleinView {
    /// The image of each ruling's point L_i = (e_i, a_i × e_i), 3 floats each.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    points: Float32Array,
    /// The steps (or, for a grid, the edges) where Ω(L_i, L_{i+1}) > 0 (6 floats each: the chord
    /// of the two images).
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
    /// Ω(L_i, L_{i+1}) of each step (= −h sin φ); for a grid, of each edge.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    omega: Float64Array,
    /// How many steps (edges) are torsal.
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
/// in the image `options` chooses (`KleinViewOptions`), with Ω of consecutive rulings (or of the
/// edges of a congruence's grid), the conic of the first, middle and last line and the complex's
/// residual.
#[wasm_bindgen(js_name = kleinView, unchecked_return_type = "KleinView")]
pub fn klein_view(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] segments: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "KleinViewOptions")] options: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "kleinView";
    let coords = args::numbers(F, "segments", &segments)?;
    let surface = RuledSurface::from_flat(&coords).map_err(|e| fail(F, e))?;
    let projection = projection_of(F, |key| option(&options, key))?;
    let closed = match options.is_object().then(|| js_sys::Reflect::get(&options, &"closed".into())) {
        Some(Ok(v)) => args::optional_bool(F, "options.closed", &v, false)?,
        _ => false,
    };
    let outline = projection.outline(KLEIN_OUTLINE_CIRCLES, KLEIN_OUTLINE_SAMPLES).map_err(|e| fail(F, e))?;

    let rows = args::integer_option(F, "rows", option(&options, "rows")?, 2, MAX_RULINGS)?;
    let cols = args::integer_option(F, "cols", option(&options, "cols")?, 2, MAX_RULINGS)?;
    let net = match (rows, cols) {
        (None, None) => KleinNet::of_polygon(KleinPolygon::of(&surface, closed)),
        (Some(_), Some(_)) if closed => {
            return Err(fail_option(F, "closed", "options.closed is for a polygon of rulings, not a grid (rows, cols)"))
        }
        (Some(rows), Some(cols)) => {
            KleinNet::of(&LineCongruence::from_flat(rows, cols, &coords).map_err(|e| fail(F, e))?)
        }
        (_, None) => return Err(fail_option(F, "cols", "options.rows and options.cols go together")),
        (None, _) => return Err(fail_option(F, "rows", "options.rows and options.cols go together")),
    };
    let image: Vec<_> = net.points.iter().map(|p| projection.image(p)).collect();
    let n = image.len();
    let (mut positive, mut negative, mut torsal) = (Vec::new(), Vec::new(), Vec::new());
    for (k, &[a, b]) in net.edges.iter().enumerate() {
        let chord = [image[a], image[b]];
        match (net.torsal[k], net.omega[k] > 0.0) {
            (true, _) => torsal.extend(chord),
            (false, true) => positive.extend(chord),
            (false, false) => negative.extend(chord),
        }
    }
    let least = net.least_omega();

    let three = [&net.points[0], &net.points[n / 2], &net.points[n - 1]];
    let (conic, plane_distance) = match RegulusPlane::through(three) {
        Ok(plane) => (
            plane
                .conic(KLEIN_OUTLINE_SAMPLES)
                .map(|c| c.iter().map(|p| projection.image(p)).collect())
                .unwrap_or_default(),
            net.points.iter().map(|p| plane.distance(p)).fold(0.0, f64::max),
        ),
        Err(_) => (Vec::new(), f64::NAN),
    };
    let segments: Vec<_> = surface.segments().collect();
    let complex = fit_linear_complex(&segments, None);
    let complex_residual = complex_residuals(complex.plucker, &net.points).iter().fold(0.0f64, |m, r| m.max(r.abs()));

    let (inner, outer) = projection.radii();
    to_js(
        F,
        &KleinView {
            points: points_f32(&image),
            positive: points_f32(&positive),
            negative: points_f32(&negative),
            torsal: points_f32(&torsal),
            omega: Float64Array::from(&net.omega[..]),
            torsal_steps: net.torsal_edges(),
            least_step: least.map_or(-1, |(i, _)| i as i64),
            least_omega: least.map_or(f64::NAN, |(_, w)| w),
            max_residual: net.max_residual,
            outline: points_f32(&outline.join(&DVec3::NAN)),
            radii: Float64Array::from(&[inner, outer][..]),
            conic: points_f32(&conic),
            plane_distance,
            complex_residual,
        },
    )
}

/// The image of P⁵ that `func`'s options choose (`mix` and `turn` in degrees, `unit`; by default
/// 45°, 0°, 1), each read by `get`.
pub(crate) fn projection_of(
    func: &str,
    get: impl Fn(&str) -> Result<Option<f64>, JsValue>,
) -> Result<Projection, JsValue> {
    let mix = get("mix")?.unwrap_or(45.0);
    if !(0.0..=90.0).contains(&mix) {
        return Err(fail_option(func, "mix", format!("options.mix must be from 0 to 90 (degrees), got {mix}")));
    }
    let (turn, unit) = (get("turn")?.unwrap_or(0.0), get("unit")?.unwrap_or(1.0));
    Projection::new(mix.to_radians(), turn.to_radians(), unit).map_err(|e| fail(func, e))
}

/// The number `options[key]` of `kleinView`'s options (None when the options or the key are left
/// out); an error for a key it does not know, or a value that is not a finite number.
fn option(options: &JsValue, key: &str) -> Result<Option<f64>, JsValue> {
    read_option("kleinView", &["mix", "turn", "unit", "closed", "rows", "cols"], options, key)
}

/// The number `options[key]` of `func`'s options, whose keys are `keys` (None when the options or
/// the key are left out); the first key read checks that the options have no other.
pub(crate) fn read_option(func: &str, keys: &[&str], options: &JsValue, key: &str) -> Result<Option<f64>, JsValue> {
    if options.is_undefined() || options.is_null() {
        return Ok(None);
    }
    if !options.is_object() {
        return Err(fail(func, "options must be an object"));
    }
    if key == keys[0] {
        // the first key read checks them all
        for k in js_sys::Object::keys(options.unchecked_ref::<js_sys::Object>()).iter().filter_map(|k| k.as_string()) {
            if !keys.contains(&k.as_str()) {
                return Err(fail_option(func, &k, format!("options.{k} is not an option; known: {}", keys.join(", "))));
            }
        }
    }
    match js_sys::Reflect::get(options, &key.into()) {
        Ok(v) if v.is_undefined() => Ok(None),
        Ok(v) => args::number(func, &format!("options.{key}"), &v).map(Some),
        Err(_) => Ok(None),
    }
}
