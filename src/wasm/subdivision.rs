//! Subdivision for JavaScript (Section 4): `surface.subdivide(options)`, `surface.recut()`,
//! `subdividePolygon(points, options)` and `turningAngles(points, options)`.

use super::args::{self, fail, fail_option, finite_option, integer, integer_option, interval, numbers, only_for};
use super::catalogue::AnalyticSurface;
use super::surface::RuledSurface;
use super::timing::Measure;
use crate::ruled::surface::points_from_flat;
use crate::subdivision::{self, Scheme, Variant};
use crate::tolerance::{MAX_BSPLINE_DEGREE, MAX_PARTS, MAX_STRIDE, MAX_SUBDIVISION_STEPS};
use js_sys::Float64Array;
use serde::Deserialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// Options of `RuledSurface.subdivide`, `subdividePolygon` and `turningAngles` (Section 4).
#[derive(Deserialize, Default, Tsify)]
struct SubdivideOptions {
    /// "chaikin" (corner cutting), "bspline" (uniform B-spline of `degree`), "bezier" (de
    /// Casteljau), "four-point" (Dyn–Levin–Gregory (8), interpolatory) or "variational" (ruled
    /// strips only, interpolatory).
    scheme: Option<SubdivisionScheme>,
    /// Number of steps, 0 … 24 (default 1); the output may hold at most 4 194 304 rulings.
    #[serde(default)]
    steps: Option<f64>,
    /// Four-point tension w ∈ [−1/4, 1/4] (default 1/16; the limit is C¹ at least for
    /// 0 < w < (√5 − 1)/8 ≈ 0.155, more than the paper's 0 < w < 1/8).
    #[serde(default)]
    w: Option<f64>,
    /// Variational: each segment divided into n parts, 3 … 1000 (default 12).
    #[serde(default)]
    n: Option<f64>,
    /// Variational energy (default "coupled"): umbrellas (13)/(14) at every interior vertex;
    /// "literal": at the new vertices only (equals the midpoint rule); "averaged": the averaged
    /// umbrella of the two triangulations, without the twist term (more accurate inside).
    #[serde(default)]
    variant: Option<SubdivisionVariant>,
    /// B-spline degree 1 … 7 (default 3).
    #[serde(default)]
    degree: Option<f64>,
    /// Closed polygon / strip (default false); not for "bezier" and "variational".
    #[serde(default)]
    closed: Option<bool>,
    /// Strips only. "points" (default): the scheme acts on the endpoints a_i, b_i. "lines": it
    /// acts on the lines themselves (dual unit vectors), so the result depends only on the
    /// input lines and commutes with rigid motions; for "chaikin", "bspline", "four-point".
    #[serde(default)]
    space: Option<SubdivisionSpace>,
    /// With space "lines": length of the output segments, cut symmetric to the striction
    /// points (default: mean input length).
    #[serde(default)]
    length: Option<f64>,
}

/// The curve and strip schemes of Section 4.
#[derive(Deserialize, Clone, Copy, PartialEq, Tsify)]
#[serde(
    rename_all = "kebab-case",
    expecting = "one of \"chaikin\", \"bspline\", \"bezier\", \"four-point\", \"variational\""
)]
enum SubdivisionScheme {
    /// Corner cutting.
    Chaikin,
    /// The uniform B-spline of `degree`.
    Bspline,
    /// De Casteljau.
    Bezier,
    /// Dyn–Levin–Gregory (8), interpolatory.
    FourPoint,
    /// The variational strip scheme (13)/(14), interpolatory.
    Variational,
}

impl SubdivisionScheme {
    fn name(self) -> &'static str {
        match self {
            SubdivisionScheme::Chaikin => "chaikin",
            SubdivisionScheme::Bspline => "bspline",
            SubdivisionScheme::Bezier => "bezier",
            SubdivisionScheme::FourPoint => "four-point",
            SubdivisionScheme::Variational => "variational",
        }
    }
}

/// The energies of the variational strip scheme.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "one of \"coupled\", \"literal\", \"averaged\"")]
enum SubdivisionVariant {
    /// Umbrellas (13)/(14) at every interior vertex.
    Coupled,
    /// At the new vertices only (the midpoint rule).
    Literal,
    /// The averaged umbrella of the two triangulations.
    Averaged,
}

/// Where a scheme acts (`space` of the strip and congruence options).
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"points\" or \"lines\"")]
pub(crate) enum SubdivisionSpace {
    /// On the endpoints.
    Points,
    /// On the lines (dual unit vectors).
    Lines,
}

/// Where a strip scheme acts: on the endpoints, or on the lines (with the output length).
pub(crate) enum Space {
    Points,
    Lines(Option<f64>),
}

/// Reads `options` into a scheme, `closed`, `steps` and the space the scheme acts in;
/// `default_scheme` stands in when `options.scheme` is absent (otherwise it is required), and
/// then the options object may be left out.
pub(crate) fn read(
    func: &'static str,
    options: JsValue,
    default_scheme: Option<&str>,
) -> Result<(Scheme, bool, usize, Space), JsValue> {
    let o: SubdivideOptions = args::options(func, options)?;
    let length = finite_option(func, "length", o.length)?;
    let space = match o.space {
        None | Some(SubdivisionSpace::Points) => {
            if length.is_some() {
                return Err(fail_option(func, "length", "options.length applies to space \"lines\" only"));
            }
            Space::Points
        }
        Some(SubdivisionSpace::Lines) => Space::Lines(length),
    };
    let Some(name) = o.scheme.map(SubdivisionScheme::name).or(default_scheme) else {
        return Err(fail_option(
            func,
            "scheme",
            "options.scheme is required: \"chaikin\", \"bspline\", \"bezier\", \"four-point\" or \"variational\"",
        ));
    };
    for (key, present, scheme) in [
        ("w", o.w.is_some(), "four-point"),
        ("n", o.n.is_some(), "variational"),
        ("variant", o.variant.is_some(), "variational"),
        ("degree", o.degree.is_some(), "bspline"),
    ] {
        only_for(func, key, present, scheme, Some(name))?;
    }
    let scheme = match name {
        "chaikin" => Scheme::Chaikin,
        "bspline" => {
            Scheme::BSpline { degree: integer_option(func, "degree", o.degree, 1, MAX_BSPLINE_DEGREE)?.unwrap_or(3) }
        }
        "bezier" => Scheme::Bezier,
        "four-point" => Scheme::FourPoint { w: finite_option(func, "w", o.w)?.unwrap_or(1.0 / 16.0) },
        _ => Scheme::Variational {
            n: integer_option(func, "n", o.n, 3, MAX_PARTS)?.unwrap_or(12),
            variant: match o.variant.unwrap_or(SubdivisionVariant::Coupled) {
                SubdivisionVariant::Coupled => Variant::Coupled,
                SubdivisionVariant::Literal => Variant::Literal,
                SubdivisionVariant::Averaged => Variant::Averaged,
            },
        },
    };
    scheme.validate().map_err(|e| fail(func, e))?;
    let steps = integer_option(func, "steps", o.steps, 0, MAX_SUBDIVISION_STEPS)?.unwrap_or(1);
    Ok((scheme, o.closed.unwrap_or(false), steps, space))
}

#[wasm_bindgen]
impl RuledSurface {
    /// The surface refined by a subdivision scheme (see `SubdivideOptions`). Interpolatory
    /// schemes ("four-point", "variational") return 2N − 1 rulings per step (2N closed) with
    /// the old ones at even indices, unchanged.
    pub fn subdivide(
        &self,
        #[wasm_bindgen(unchecked_param_type = "SubdivideOptions")] options: JsValue,
    ) -> Result<RuledSurface, JsValue> {
        const F: &str = "RuledSurface.subdivide";
        let _measure = Measure::start(F);
        let (scheme, closed, steps, space) = read(F, options, None)?;
        match space {
            Space::Points => subdivision::subdivide_strip(self.core(), scheme, closed, steps),
            Space::Lines(length) => {
                subdivision::line_space::subdivide_lines(self.core(), scheme, closed, steps, length)
            }
        }
        .map(RuledSurface::from_core)
        .map_err(|e| fail(F, e))
    }

    /// The rulings re-cut to segments of one length (default: the mean length), centred on
    /// the striction points: for data given as lines, before subdividing.
    pub fn recut(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] length: JsValue,
    ) -> Result<RuledSurface, JsValue> {
        const F: &str = "RuledSurface.recut";
        let length = if length.is_undefined() { None } else { Some(args::number(F, "length", &length)?) };
        subdivision::recut(self.core(), length).map(RuledSurface::from_core).map_err(|e| fail(F, e))
    }
}

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
    let out = subdivision::subdivide_polygon(&points, scheme, closed, steps).map_err(|e| fail(F, e))?;
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
    let out = subdivision::turning::turning_angles(&points, scheme, closed, steps).map_err(|e| fail(F, e))?;
    Ok(Float64Array::from(&out[..]))
}

#[wasm_bindgen]
impl AnalyticSurface {
    /// Largest distance from this surface of the rulings of `refined` whose index is not a
    /// multiple of `stride` (the inserted ones), sampled at 9 points each; `refined` was
    /// refined from a sampling of the parameter interval [uMin, uMax].
    #[wasm_bindgen(js_name = insertedDistance)]
    pub fn inserted_distance(
        &self,
        refined: &RuledSurface,
        #[wasm_bindgen(unchecked_param_type = "number")] stride: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] u_min: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] u_max: JsValue,
    ) -> Result<f64, JsValue> {
        const F: &str = "AnalyticSurface.insertedDistance";
        let stride = integer(F, "stride", &stride, 2, MAX_STRIDE)?;
        let (u_min, u_max) = interval(F, &u_min, &u_max)?;
        let which = (0..refined.length()).filter(|i| i % stride != 0);
        Ok(crate::subdivision::accuracy::max_distance(self.core(), refined.core(), u_min, u_max, which))
    }
}
