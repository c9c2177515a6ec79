//! Formulas typed by a reader (see [`crate::formula`]): the surfaces and congruences of
//! `AnalyticSurface.fromFormulas` and `AnalyticCongruence.fromFormulas` read into the core's
//! specs, the catalogue's formulas as presets (`formulaPresets()` of both), and
//! `evaluateFormulas`, the values of a reader's formulas. The options objects are read by
//! serde-wasm-bindgen, unknown keys refused.

use ruledlab::tolerance::{MAX_GRID_SIDE, MAX_SAMPLES};
use ruledlab::{CongruenceSpec, FormulaSpec};
use ruledlab::{Formula, PARAMETERS};
use ruledlab_js::args::{numbers, required};
use ruledlab_js::error::{fail, fail_option};
use ruledlab_js::timing::Measure;
use serde::de::{self, Deserializer, Visitor};
use serde::{Deserialize, Serialize};
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_BOUND: &str = r#"
/**
 * A number, or a formula of the named parameters a, b, c and the constants pi, e
 * (e.g. "2*pi"), for the ends of a parameter interval.
 */
export type Bound = number | string;
"#;

/// An interval end: a number, or a formula in the parameters.
enum Bound {
    Number(f64),
    Text(String),
}

impl<'de> Deserialize<'de> for Bound {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Expect;
        impl Visitor<'_> for Expect {
            type Value = Bound;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a number or a formula such as \"2*pi\"")
            }
            fn visit_f64<E: de::Error>(self, x: f64) -> Result<Bound, E> {
                Ok(Bound::Number(x))
            }
            fn visit_i64<E: de::Error>(self, x: i64) -> Result<Bound, E> {
                Ok(Bound::Number(x as f64))
            }
            fn visit_u64<E: de::Error>(self, x: u64) -> Result<Bound, E> {
                Ok(Bound::Number(x as f64))
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<Bound, E> {
                Ok(Bound::Text(s.to_string()))
            }
        }
        d.deserialize_any(Expect)
    }
}

/// Values of the named parameters a, b, c a formula may use (each defaults to 1).
#[derive(Deserialize, Default, Tsify)]
#[serde(default)]
struct FormulaParameters {
    a: Option<f64>,
    b: Option<f64>,
    c: Option<f64>,
}

impl FormulaParameters {
    fn values(&self) -> [f64; 3] {
        [self.a.unwrap_or(1.0), self.b.unwrap_or(1.0), self.c.unwrap_or(1.0)]
    }
}

/// A ruled surface x(u, v) = a(u) + v·e(u) typed as formulas in u (and a, b, c): e.g.
/// `{ a: ["cos(u)", "2*sin(u)", "0"], e: ["-sin(u)", "2*cos(u)", "3"], u: [0, "2*pi"], closed:
/// true }`. Functions: + − * / ^, sin cos tan asin acos atan atan2 sinh cosh tanh exp ln log
/// sqrt abs; constants pi, e. At most 1000 characters and 64 levels of parentheses per formula.
#[derive(Deserialize, Tsify)]
struct SurfaceFormulas {
    a: [String; 3],
    e: [String; 3],
    #[tsify(type = "[Bound, Bound]")]
    u: [Bound; 2],
    /// Segment ends along e (default [−1, 1]).
    #[serde(default)]
    #[tsify(optional, type = "[Bound, Bound]")]
    v: Option<[Bound; 2]>,
    /// Whether u wraps around, as on a closed surface (default false).
    #[serde(default)]
    closed: bool,
    #[serde(default)]
    parameters: FormulaParameters,
    /// Whether numbers may be written with a decimal comma ("0,5*u"; default false). true (a
    /// German reader): a comma between two digits is a decimal point, except in the arguments
    /// of atan2, where "atan2(1,5)" is refused as ambiguous (write 1.5, or "1, 5" for two
    /// arguments); "unambiguous" (an English reader of a German link): the same outside atan2,
    /// a separator inside it.
    #[serde(default, rename = "decimalComma")]
    #[tsify(type = "boolean | \"unambiguous\"")]
    decimal_comma: Comma,
}

/// A line congruence p(u, v) + t·e(u, v) typed as formulas in u, v (and a, b, c).
#[derive(Deserialize, Tsify)]
struct CongruenceFormulas {
    p: [String; 3],
    e: [String; 3],
    #[tsify(type = "[Bound, Bound]")]
    u: [Bound; 2],
    #[tsify(type = "[Bound, Bound]")]
    v: [Bound; 2],
    #[serde(default)]
    parameters: FormulaParameters,
    /// Default grid of `grid()`: rows along u (default 8), 2 … 1000.
    #[serde(default)]
    #[tsify(optional)]
    rows: Option<f64>,
    /// Columns along v (default 8), 2 … 1000.
    #[serde(default)]
    #[tsify(optional)]
    cols: Option<f64>,
    /// As in `SurfaceFormulas`.
    #[serde(default, rename = "decimalComma")]
    #[tsify(type = "boolean | \"unambiguous\"")]
    decimal_comma: Comma,
}

/// How decimal commas are read (`decimalComma`: false, true or "unambiguous").
#[derive(Default, Clone, Copy)]
enum Comma {
    /// Commas only separate the arguments of atan2.
    #[default]
    Off,
    /// Decimal commas outside atan2's arguments; inside, a comma separates.
    Unambiguous,
    /// Decimal commas; one between digits inside atan2's arguments is refused as ambiguous.
    Strict,
}

impl<'de> Deserialize<'de> for Comma {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Expect;
        impl Visitor<'_> for Expect {
            type Value = Comma;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("true, false or \"unambiguous\"")
            }
            fn visit_bool<E: de::Error>(self, b: bool) -> Result<Comma, E> {
                Ok(if b { Comma::Strict } else { Comma::Off })
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<Comma, E> {
                match s {
                    "unambiguous" => Ok(Comma::Unambiguous),
                    _ => Err(E::invalid_value(de::Unexpected::Str(s), &self)),
                }
            }
        }
        d.deserialize_any(Expect)
    }
}

impl Comma {
    /// `text` (the formula called `source`) in the grammar's spelling.
    fn read(self, func: &str, source: &str, text: &str) -> Result<String, JsValue> {
        match self {
            Comma::Off => Ok(text.to_string()),
            Comma::Unambiguous => ruledlab::decimal_commas(source, text, false).map_err(|e| fail(func, e)),
            Comma::Strict => ruledlab::decimal_commas(source, text, true).map_err(|e| fail(func, e)),
        }
    }
}

/// The three formulas of a field called `name`, with decimal commas read as asked.
fn texts(func: &str, name: &str, texts: [String; 3], comma: Comma) -> Result<[String; 3], JsValue> {
    let [x, y, z] = texts;
    let read = |k: usize, t: String| comma.read(func, &format!("{name}[{k}]"), &t);
    Ok([read(0, x)?, read(1, y)?, read(2, z)?])
}

const PARAMETER_KEYS: (&str, &[&str]) = ("parameters", &PARAMETERS);

/// An interval from two bounds (formulas evaluated with the parameters' values; decimal
/// commas read as points if `comma`).
fn interval(
    func: &str,
    name: &str,
    bounds: &[Bound; 2],
    parameters: &[f64; 3],
    comma: Comma,
) -> Result<(f64, f64), JsValue> {
    let value = |k: usize| -> Result<f64, JsValue> {
        match &bounds[k] {
            Bound::Number(x) => Ok(*x),
            Bound::Text(t) => {
                let source = format!("{name}[{k}]");
                let text = comma.read(func, &source, t)?;
                let f = Formula::parse(&source, &text, &PARAMETERS).map_err(|e| fail(func, e))?;
                Ok(f.value(parameters))
            }
        }
    };
    Ok((value(0)?, value(1)?))
}

/// The values of the parameters a, b, c.
#[derive(Serialize, Tsify)]
struct ParameterValues {
    a: f64,
    b: f64,
    c: f64,
}

impl From<[f64; 3]> for ParameterValues {
    fn from([a, b, c]: [f64; 3]) -> Self {
        ParameterValues { a, b, c }
    }
}

/// A surface of the catalogue as formulas (`AnalyticSurface.formulaPresets()`): `fromFormulas`
/// of it is that surface.
#[derive(Serialize, Tsify)]
pub(super) struct SurfacePreset {
    name: &'static str,
    a: [&'static str; 3],
    e: [&'static str; 3],
    u: [&'static str; 2],
    v: [&'static str; 2],
    closed: bool,
    parameters: ParameterValues,
}

/// A congruence of the catalogue as formulas (`AnalyticCongruence.formulaPresets()`).
#[derive(Serialize, Tsify)]
pub(super) struct CongruencePreset {
    name: &'static str,
    p: [&'static str; 3],
    e: [&'static str; 3],
    u: [&'static str; 2],
    v: [&'static str; 2],
    rows: usize,
    cols: usize,
    parameters: ParameterValues,
    /// Segment length along e that passes the focal points (the focal scene's lines).
    reach: f64,
}

/// Every surface of the catalogue as formulas, in menu order.
pub(super) fn surface_presets() -> Vec<SurfacePreset> {
    ruledlab::SURFACE_FORMULAS
        .iter()
        .map(|t| SurfacePreset {
            name: t.name,
            a: t.a,
            e: t.e,
            u: t.u,
            v: t.v,
            closed: t.closed,
            parameters: t.parameters.into(),
        })
        .collect()
}

/// The surface of `spec` (`SurfaceFormulas`), its bounds evaluated and decimal commas read;
/// `func` names the export in messages.
pub(super) fn surface_spec(func: &str, spec: JsValue) -> Result<FormulaSpec, JsValue> {
    let s: SurfaceFormulas = required(func, "spec", spec, &[PARAMETER_KEYS])?;
    let parameters = s.parameters.values();
    let comma = s.decimal_comma;
    Ok(FormulaSpec {
        u: interval(func, "u", &s.u, &parameters, comma)?,
        v: match &s.v {
            Some(v) => interval(func, "v", v, &parameters, comma)?,
            None => (-1.0, 1.0),
        },
        a: texts(func, "a", s.a, comma)?,
        e: texts(func, "e", s.e, comma)?,
        closed: s.closed,
        parameters,
    })
}

/// Every congruence of the catalogue as formulas, in menu order.
pub(super) fn congruence_presets() -> Vec<CongruencePreset> {
    ruledlab::CONGRUENCE_FORMULAS
        .iter()
        .map(|t| CongruencePreset {
            name: t.name,
            p: t.p,
            e: t.e,
            u: t.u,
            v: t.v,
            rows: t.grid.0,
            cols: t.grid.1,
            parameters: t.parameters.into(),
            reach: t.reach,
        })
        .collect()
}

/// The congruence of `spec` (`CongruenceFormulas`), its bounds evaluated, its grid size
/// checked and decimal commas read; `func` names the export in messages.
pub(super) fn congruence_spec(func: &str, spec: JsValue) -> Result<CongruenceSpec, JsValue> {
    let s: CongruenceFormulas = required(func, "spec", spec, &[PARAMETER_KEYS])?;
    let parameters = s.parameters.values();
    let size = |name: &str, x: Option<f64>| -> Result<usize, JsValue> {
        match x {
            None => Ok(8),
            Some(x) if x.fract() == 0.0 && (2.0..=MAX_GRID_SIDE as f64).contains(&x) => Ok(x as usize),
            Some(x) => {
                Err(fail_option(func, name, format!("{name} must be an integer from 2 to {MAX_GRID_SIDE}, got {x}")))
            }
        }
    };
    let comma = s.decimal_comma;
    Ok(CongruenceSpec {
        u: interval(func, "u", &s.u, &parameters, comma)?,
        v: interval(func, "v", &s.v, &parameters, comma)?,
        grid: (size("rows", s.rows)?, size("cols", s.cols)?),
        p: texts(func, "p", s.p, comma)?,
        e: texts(func, "e", s.e, comma)?,
        parameters,
    })
}

/// Formulas of one variable to evaluate (`evaluateFormulas`): a reader's answer, such as the
/// striction curve s(u) typed as three formulas, or δ(u) as one.
#[derive(Deserialize, Tsify)]
struct FormulaValues {
    /// One to three formulas in the variable and a, b, c, e.g. `["u", "0", "0"]`.
    formulas: Vec<String>,
    /// The variable: "u" (default), "v" or "t".
    #[serde(default)]
    #[tsify(optional, type = "\"u\" | \"v\" | \"t\"")]
    variable: Option<String>,
    /// What the field is called in messages (default "f"): an error names "f[1]", the second
    /// formula.
    #[serde(default)]
    #[tsify(optional)]
    name: Option<String>,
    #[serde(default)]
    parameters: FormulaParameters,
    /// As in `SurfaceFormulas`.
    #[serde(default, rename = "decimalComma")]
    #[tsify(type = "boolean | \"unambiguous\"")]
    decimal_comma: Comma,
}

/// The values of one to three formulas of one variable at each of `at` (the variable's values):
/// `formulas.length` numbers per value, NaN where a formula is undefined there (sqrt(−1)). Throws
/// with the formula and column of a mistake, as `fromFormulas` does.
#[wasm_bindgen(js_name = evaluateFormulas)]
pub fn evaluate_formulas(
    #[wasm_bindgen(unchecked_param_type = "FormulaValues")] options: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] at: JsValue,
) -> Result<js_sys::Float64Array, JsValue> {
    const F: &str = "evaluateFormulas";
    let _measure = Measure::start(F);
    let o: FormulaValues = required(F, "options", options, &[PARAMETER_KEYS])?;
    if o.formulas.is_empty() || o.formulas.len() > 3 {
        return Err(fail_option(F, "formulas", format!("one to three formulas, got {}", o.formulas.len())));
    }
    let variable = o.variable.unwrap_or_else(|| "u".to_string());
    if !["u", "v", "t"].contains(&variable.as_str()) {
        return Err(fail_option(F, "variable", format!("\"u\", \"v\" or \"t\", got \"{variable}\"")));
    }
    let name = o.name.unwrap_or_else(|| "f".to_string());
    if name.len() > 32 || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(fail_option(F, "name", "a name of at most 32 letters, digits or _"));
    }
    let at = numbers(F, "at", &at)?;
    if at.len() > MAX_SAMPLES {
        return Err(fail_option(F, "at", format!("at most {MAX_SAMPLES} values, got {}", at.len())));
    }
    let parameters = o.parameters.values();
    if let Some(k) = parameters.iter().position(|x| !x.is_finite()) {
        return Err(fail_option(F, &format!("parameters.{}", PARAMETERS[k]), "must be a finite number"));
    }
    let variables = [variable.as_str(), PARAMETERS[0], PARAMETERS[1], PARAMETERS[2]];
    let formulas = o
        .formulas
        .iter()
        .enumerate()
        .map(|(k, text)| {
            let source = format!("{name}[{k}]");
            let text = o.decimal_comma.read(F, &source, text)?;
            Formula::parse(&source, &text, &variables).map_err(|e| fail(F, e))
        })
        .collect::<Result<Vec<_>, JsValue>>()?;
    let mut out = Vec::with_capacity(at.len() * formulas.len());
    for &x in &at {
        let vars = [x, parameters[0], parameters[1], parameters[2]];
        out.extend(formulas.iter().map(|f| f.value(&vars)));
    }
    Ok(js_sys::Float64Array::from(&out[..]))
}
