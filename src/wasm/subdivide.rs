//! Subdivision for JavaScript (Section 4): `surface.subdivide(options)`, `surface.recut()`
//! and `subdividePolygon(points, options)`.

use super::args::{self, fail, fail_option, finite_option, integer_option, numbers, only_for};
use super::surface::RuledSurface;
use crate::ruled::surface::points_from_flat;
use crate::subdivision::{self, Scheme, Variant, MAX_STEPS};
use js_sys::Float64Array;
use serde::Deserialize;
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** Options of `RuledSurface.subdivide` and `subdividePolygon` (Section 4). */
export interface SubdivideOptions {
  /**
   * "chaikin" (corner cutting), "bspline" (uniform B-spline of `degree`), "bezier"
   * (de Casteljau), "four-point" (Dyn–Levin–Gregory (8), interpolatory) or "variational"
   * (ruled strips only, interpolatory).
   */
  scheme: "chaikin" | "bspline" | "bezier" | "four-point" | "variational";
  /** Number of steps, 0 … 24 (default 1); the output may hold at most 4 194 304 rulings. */
  steps?: number;
  /** Four-point tension w ∈ [−1/4, 1/4] (default 1/16; C¹ for 0 < w < 1/8). */
  w?: number;
  /** Variational: each segment divided into n parts, 3 … 1000 (default 12). */
  n?: number;
  /**
   * Variational energy (default "coupled"): umbrellas (13)/(14) at every interior vertex;
   * "literal": at the new vertices only (equals the midpoint rule); "averaged": the averaged
   * umbrella of the two triangulations, without the twist term (more accurate inside).
   */
  variant?: "coupled" | "literal" | "averaged";
  /** B-spline degree 1 … 7 (default 3). */
  degree?: number;
  /** Closed polygon / strip (default false); not for "bezier" and "variational". */
  closed?: boolean;
  /**
   * Strips only. "points" (default): the scheme acts on the endpoints a_i, b_i. "lines": it acts
   * on the lines themselves (dual unit vectors), so the result depends only on the input lines
   * and commutes with rigid motions; for "chaikin", "bspline", "four-point".
   */
  space?: "points" | "lines";
  /** With space "lines": length of the output segments, cut symmetric to the striction points (default: mean input length). */
  length?: number;
}
"#;

/// `SubdivideOptions`, read by serde.
#[derive(Deserialize, Default)]
struct SubdivideOptions {
    scheme: Option<SchemeName>,
    steps: Option<f64>,
    w: Option<f64>,
    n: Option<f64>,
    variant: Option<VariantName>,
    degree: Option<f64>,
    closed: Option<bool>,
    space: Option<SpaceName>,
    length: Option<f64>,
}

#[derive(Deserialize, Clone, Copy, PartialEq)]
#[serde(
    rename_all = "kebab-case",
    expecting = "one of \"chaikin\", \"bspline\", \"bezier\", \"four-point\", \"variational\""
)]
enum SchemeName {
    Chaikin,
    Bspline,
    Bezier,
    FourPoint,
    Variational,
}

impl SchemeName {
    fn name(self) -> &'static str {
        match self {
            SchemeName::Chaikin => "chaikin",
            SchemeName::Bspline => "bspline",
            SchemeName::Bezier => "bezier",
            SchemeName::FourPoint => "four-point",
            SchemeName::Variational => "variational",
        }
    }
}

#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case", expecting = "one of \"coupled\", \"literal\", \"averaged\"")]
enum VariantName {
    Coupled,
    Literal,
    Averaged,
}

/// `space` of the strip and congruence options.
#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case", expecting = "\"points\" or \"lines\"")]
pub(crate) enum SpaceName {
    Points,
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
        None | Some(SpaceName::Points) => {
            if length.is_some() {
                return Err(fail_option(func, "length", "options.length applies to space \"lines\" only"));
            }
            Space::Points
        }
        Some(SpaceName::Lines) => Space::Lines(length),
    };
    let Some(name) = o.scheme.map(SchemeName::name).or(default_scheme) else {
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
        "bspline" => Scheme::BSpline {
            degree: integer_option(func, "degree", o.degree, 1, subdivision::bspline::MAX_DEGREE)?.unwrap_or(3),
        },
        "bezier" => Scheme::Bezier,
        "four-point" => Scheme::FourPoint { w: finite_option(func, "w", o.w)?.unwrap_or(1.0 / 16.0) },
        _ => Scheme::Variational {
            n: integer_option(func, "n", o.n, 3, 1000)?.unwrap_or(12),
            variant: match o.variant.unwrap_or(VariantName::Coupled) {
                VariantName::Coupled => Variant::Coupled,
                VariantName::Literal => Variant::Literal,
                VariantName::Averaged => Variant::Averaged,
            },
        },
    };
    scheme.validate().map_err(|e| fail(func, e))?;
    let steps = integer_option(func, "steps", o.steps, 0, MAX_STEPS)?.unwrap_or(1);
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
    let flat = numbers(F, "points", &points)?;
    let points = points_from_flat(&flat).map_err(|e| fail(F, e))?;
    let (scheme, closed, steps, space) = read(F, options, None)?;
    if matches!(space, Space::Lines(_)) {
        return Err(fail(F, "options.space \"lines\" refines ruled surfaces, not polygons"));
    }
    let out = subdivision::subdivide_polygon(&points, scheme, closed, steps).map_err(|e| fail(F, e))?;
    Ok(Float64Array::from(bytemuck::cast_slice::<_, f64>(&out)))
}
