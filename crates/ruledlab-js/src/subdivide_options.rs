//! The options of the subdivision schemes (Section 4) as JavaScript passes them
//! (`SubdivideOptions`), read into the core's scheme: for `RuledSurface.subdivide`,
//! `subdividePolygon`, `turningAngles` and `ToolPath.refine`, and the `space` option of
//! `LineCongruence.subdivide`. No JS class.

use crate::args::{self, fail, fail_option, finite_option, integer_option, only_for};
use ruledlab::tolerance::{MAX_BSPLINE_DEGREE, MAX_PARTS, MAX_SUBDIVISION_STEPS};
use ruledlab::{Scheme, Variant};
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
pub enum SubdivisionScheme {
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
pub enum SubdivisionVariant {
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
pub enum SubdivisionSpace {
    /// On the endpoints.
    Points,
    /// On the lines (dual unit vectors).
    Lines,
}

/// Where a strip scheme acts: on the endpoints, or on the lines (with the output length).
pub enum Space {
    /// On the endpoints (the paper's schemes).
    Points,
    /// On the lines, their segments given the length asked for (or kept).
    Lines(Option<f64>),
}

/// Reads `options` into a scheme, `closed`, `steps` and the space the scheme acts in;
/// `default_scheme` stands in when `options.scheme` is absent (otherwise it is required), and
/// then the options object may be left out.
pub fn read(
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
