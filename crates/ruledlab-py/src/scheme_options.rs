//! The options of the curve and strip schemes of Section 4 as Python passes them (keyword
//! arguments of `RuledSurface.subdivide`, `subdivide_polygon`, `turning_angles`,
//! `ToolPath.refine`), read into the core's [`Scheme`], as `crates/ruledlab-js/src/subdivide_options.rs`
//! reads JavaScript's `SubdivideOptions`: an option of another scheme is refused, not ignored.

use crate::args::{self, given, only_for};
use crate::error::{fail, fail_option};
use pyo3::prelude::*;
use ruledlab::tolerance::{MAX_BSPLINE_DEGREE, MAX_PARTS, MAX_SUBDIVISION_STEPS};
use ruledlab::{Scheme, Variant};

/// The schemes by name.
pub const SCHEMES: [&str; 5] = ["chaikin", "bspline", "bezier", "four-point", "variational"];

/// Where a strip scheme acts.
pub enum Space {
    /// On the endpoints a_i, b_i (the paper's schemes).
    Points,
    /// On the lines themselves (dual unit vectors), the output segments `length` long (default:
    /// the mean input length).
    Lines(Option<f64>),
}

/// The keyword arguments of a scheme, as given (None: left out).
pub struct SchemeArgs<'a, 'py> {
    /// "chaikin", "bspline", "bezier", "four-point" or "variational".
    pub scheme: Option<&'a Bound<'py, PyAny>>,
    /// Steps, 0 … 24 (default 1).
    pub steps: Option<&'a Bound<'py, PyAny>>,
    /// Four-point tension w ∈ [−1/4, 1/4] (default 1/16).
    pub w: Option<&'a Bound<'py, PyAny>>,
    /// Variational: parts per segment, 3 … 1000 (default 12).
    pub n: Option<&'a Bound<'py, PyAny>>,
    /// Variational energy: "coupled" (default), "literal", "averaged".
    pub variant: Option<&'a Bound<'py, PyAny>>,
    /// B-spline degree 1 … 7 (default 3).
    pub degree: Option<&'a Bound<'py, PyAny>>,
    /// A closed polygon or strip (default False).
    pub closed: Option<&'a Bound<'py, PyAny>>,
    /// "points" (default) or "lines".
    pub space: Option<&'a Bound<'py, PyAny>>,
    /// With space "lines": the output segments' length.
    pub length: Option<&'a Bound<'py, PyAny>>,
}

/// Reads the arguments into a scheme, `closed`, `steps` and the space it acts in;
/// `default_scheme` stands in when `scheme` is left out (otherwise it is required).
pub fn read(
    func: &str,
    a: &SchemeArgs<'_, '_>,
    default_scheme: Option<&str>,
) -> PyResult<(Scheme, bool, usize, Space)> {
    let length = args::optional_number(func, "length", a.length)?;
    let space = match args::choice(func, "space", a.space, &["points", "lines"])? {
        None | Some(0) => {
            if length.is_some() {
                return Err(fail_option(func, "length", "length applies to space=\"lines\" only"));
            }
            Space::Points
        }
        _ => Space::Lines(length),
    };
    let chosen = args::choice(func, "scheme", a.scheme, &SCHEMES)?.map(|k| SCHEMES[k]);
    let Some(name) = chosen.or(default_scheme) else {
        return Err(fail_option(
            func,
            "scheme",
            "scheme is required: \"chaikin\", \"bspline\", \"bezier\", \"four-point\" or \"variational\"",
        ));
    };
    for (key, present, scheme) in [
        ("w", given(a.w), "four-point"),
        ("n", given(a.n), "variational"),
        ("variant", given(a.variant), "variational"),
        ("degree", given(a.degree), "bspline"),
    ] {
        only_for(func, key, present, scheme, Some(name))?;
    }
    let scheme = match name {
        "chaikin" => Scheme::Chaikin,
        "bspline" => {
            Scheme::BSpline { degree: args::optional_integer(func, "degree", a.degree, 1, MAX_BSPLINE_DEGREE, 3)? }
        }
        "bezier" => Scheme::Bezier,
        "four-point" => Scheme::FourPoint { w: args::optional_number(func, "w", a.w)?.unwrap_or(1.0 / 16.0) },
        _ => Scheme::Variational {
            n: args::optional_integer(func, "n", a.n, 3, MAX_PARTS, 12)?,
            variant: match args::choice(func, "variant", a.variant, &["coupled", "literal", "averaged"])? {
                None | Some(0) => Variant::Coupled,
                Some(1) => Variant::Literal,
                _ => Variant::Averaged,
            },
        },
    };
    scheme.validate().map_err(|e| fail(func, e))?;
    let steps = args::optional_integer(func, "steps", a.steps, 0, MAX_SUBDIVISION_STEPS, 1)?;
    Ok((scheme, args::flag(func, "closed", a.closed, false)?, steps, space))
}
