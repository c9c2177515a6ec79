//! Formulas typed by a reader (the core's `formula`): the surfaces and congruences of
//! `AnalyticSurface.from_formulas` and `AnalyticCongruence.from_formulas` read into the core's
//! specs, the catalogue's formulas as presets (`formula_presets()` of both), and
//! `evaluate_formulas`, the values of a reader's formulas — as `crates/ruledlab-wasm/src/formula.rs`
//! reads JavaScript's: bounds may be formulas ("2*pi"), decimal commas are read as asked, unknown
//! parameter names refused.

use crate::args::{self, describe};
use crate::arrays;
use crate::error::{fail, fail_option};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};
use ruledlab::tolerance::{MAX_GRID_SIDE, MAX_SAMPLES};
use ruledlab::{CongruenceSpec, Formula, FormulaSpec, PARAMETERS};

/// How decimal commas are read (`decimal_comma`: False, True or "unambiguous").
#[derive(Clone, Copy)]
enum Comma {
    /// Commas only separate the arguments of atan2.
    Off,
    /// Decimal commas outside atan2's arguments; inside, a comma separates.
    Unambiguous,
    /// Decimal commas; one between digits inside atan2's arguments is refused as ambiguous.
    Strict,
}

impl Comma {
    fn of(func: &str, value: Option<&Bound<'_, PyAny>>) -> PyResult<Comma> {
        let Some(v) = value.filter(|v| !v.is_none()) else { return Ok(Comma::Off) };
        if let Ok(s) = v.cast::<PyString>() {
            if *s == "unambiguous" {
                return Ok(Comma::Unambiguous);
            }
        }
        match args::flag(func, "decimal_comma", Some(v), false) {
            Ok(true) => Ok(Comma::Strict),
            Ok(false) => Ok(Comma::Off),
            Err(_) => Err(fail_option(
                func,
                "decimal_comma",
                format!("decimal_comma must be True, False or \"unambiguous\", got {}", describe(v)),
            )),
        }
    }

    /// `text` (the formula called `source`) in the grammar's spelling.
    fn read(self, func: &str, source: &str, text: &str) -> PyResult<String> {
        match self {
            Comma::Off => Ok(text.to_string()),
            Comma::Unambiguous => ruledlab::decimal_commas(source, text, false).map_err(|e| fail(func, e)),
            Comma::Strict => ruledlab::decimal_commas(source, text, true).map_err(|e| fail(func, e)),
        }
    }
}

/// The three formulas of field `name` (a sequence of three strings).
fn texts(func: &str, name: &str, value: &Bound<'_, PyAny>, comma: Comma) -> PyResult<[String; 3]> {
    let bad = || fail_option(func, name, format!("{name} must be three formulas (strings), got {}", describe(value)));
    if value.is_instance_of::<PyString>() {
        return Err(bad());
    }
    let items: Vec<Bound<'_, PyAny>> = value.try_iter().map_err(|_| bad())?.collect::<PyResult<_>>()?;
    if items.len() != 3 {
        return Err(bad());
    }
    let mut out: [String; 3] = Default::default();
    for (k, item) in items.iter().enumerate() {
        let text = args::text(func, &format!("{name}[{k}]"), item)?;
        out[k] = comma.read(func, &format!("{name}[{k}]"), &text)?;
    }
    Ok(out)
}

/// The values of the parameters a, b, c (a dict; each defaults to 1; other keys refused).
fn parameters(func: &str, value: Option<&Bound<'_, PyAny>>) -> PyResult<[f64; 3]> {
    let mut out = [1.0; 3];
    let Some(v) = value.filter(|v| !v.is_none()) else { return Ok(out) };
    let dict = v.cast::<PyDict>().map_err(|_| {
        fail_option(func, "parameters", format!("parameters must be a dict {{a, b, c}}, got {}", describe(v)))
    })?;
    for (key, x) in dict.iter() {
        let key = key.str()?.to_string();
        let Some(k) = PARAMETERS.iter().position(|p| *p == key) else {
            return Err(fail_option(
                func,
                &format!("parameters.{key}"),
                format!("unknown parameter \"{key}\"; the parameters are a, b, c"),
            ));
        };
        out[k] = args::number(func, &format!("parameters.{key}"), &x)?;
    }
    Ok(out)
}

/// An interval of two bounds, each a number or a formula of a, b, c and pi, e.
fn interval(func: &str, name: &str, value: &Bound<'_, PyAny>, p: &[f64; 3], comma: Comma) -> PyResult<(f64, f64)> {
    let bad = || {
        fail_option(
            func,
            name,
            format!("{name} must be two bounds, each a number or a formula such as \"2*pi\", got {}", describe(value)),
        )
    };
    if value.is_instance_of::<PyString>() {
        return Err(bad());
    }
    let items: Vec<Bound<'_, PyAny>> = value.try_iter().map_err(|_| bad())?.collect::<PyResult<_>>()?;
    if items.len() != 2 {
        return Err(bad());
    }
    let bound = |k: usize| -> PyResult<f64> {
        let source = format!("{name}[{k}]");
        if let Ok(s) = items[k].cast::<PyString>() {
            let text = comma.read(func, &source, &s.to_string())?;
            let f = Formula::parse(&source, &text, &PARAMETERS).map_err(|e| fail(func, e))?;
            return Ok(f.value(p));
        }
        args::real(func, &source, &items[k])
    };
    Ok((bound(0)?, bound(1)?))
}

/// The surface x(u, v) = a(u) + v·e(u) of formulas (the arguments of `from_formulas`).
#[allow(clippy::too_many_arguments)]
pub fn surface_spec(
    func: &str,
    a: &Bound<'_, PyAny>,
    e: &Bound<'_, PyAny>,
    u: &Bound<'_, PyAny>,
    v: Option<&Bound<'_, PyAny>>,
    closed: Option<&Bound<'_, PyAny>>,
    params: Option<&Bound<'_, PyAny>>,
    decimal_comma: Option<&Bound<'_, PyAny>>,
) -> PyResult<FormulaSpec> {
    let comma = Comma::of(func, decimal_comma)?;
    let p = parameters(func, params)?;
    Ok(FormulaSpec {
        u: interval(func, "u", u, &p, comma)?,
        v: match v.filter(|v| !v.is_none()) {
            Some(v) => interval(func, "v", v, &p, comma)?,
            None => (-1.0, 1.0),
        },
        a: texts(func, "a", a, comma)?,
        e: texts(func, "e", e, comma)?,
        closed: args::flag(func, "closed", closed, false)?,
        parameters: p,
    })
}

/// The congruence p(u, v) + t·e(u, v) of formulas (the arguments of `from_formulas`).
#[allow(clippy::too_many_arguments)]
pub fn congruence_spec(
    func: &str,
    p: &Bound<'_, PyAny>,
    e: &Bound<'_, PyAny>,
    u: &Bound<'_, PyAny>,
    v: &Bound<'_, PyAny>,
    params: Option<&Bound<'_, PyAny>>,
    rows: Option<&Bound<'_, PyAny>>,
    cols: Option<&Bound<'_, PyAny>>,
    decimal_comma: Option<&Bound<'_, PyAny>>,
) -> PyResult<CongruenceSpec> {
    let comma = Comma::of(func, decimal_comma)?;
    let values = parameters(func, params)?;
    Ok(CongruenceSpec {
        u: interval(func, "u", u, &values, comma)?,
        v: interval(func, "v", v, &values, comma)?,
        grid: (
            args::optional_integer(func, "rows", rows, 2, MAX_GRID_SIDE, 8)?,
            args::optional_integer(func, "cols", cols, 2, MAX_GRID_SIDE, 8)?,
        ),
        p: texts(func, "p", p, comma)?,
        e: texts(func, "e", e, comma)?,
        parameters: values,
    })
}

/// `{"a": …, "b": …, "c": …}`.
fn parameter_dict<'py>(py: Python<'py>, values: &[f64; 3]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (name, x) in PARAMETERS.iter().zip(values) {
        d.set_item(*name, *x)?;
    }
    Ok(d)
}

/// Every surface of the catalogue as formulas, in menu order: dicts with `name`, `a`, `e`, `u`,
/// `v`, `closed`, `parameters` (`from_formulas(**preset)` without `name` is that surface).
pub fn surface_presets(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for t in ruledlab::SURFACE_FORMULAS {
        let d = PyDict::new(py);
        d.set_item("name", t.name)?;
        d.set_item("a", t.a.to_vec())?;
        d.set_item("e", t.e.to_vec())?;
        d.set_item("u", t.u.to_vec())?;
        d.set_item("v", t.v.to_vec())?;
        d.set_item("closed", t.closed)?;
        d.set_item("parameters", parameter_dict(py, &t.parameters)?)?;
        list.append(d)?;
    }
    Ok(list)
}

/// Every congruence of the catalogue as formulas, in menu order: dicts with `name`, `p`, `e`,
/// `u`, `v`, `rows`, `cols`, `parameters` and `reach` (the segment length along e that passes
/// the focal points).
pub fn congruence_presets(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for t in ruledlab::CONGRUENCE_FORMULAS {
        let d = PyDict::new(py);
        d.set_item("name", t.name)?;
        d.set_item("p", t.p.to_vec())?;
        d.set_item("e", t.e.to_vec())?;
        d.set_item("u", t.u.to_vec())?;
        d.set_item("v", t.v.to_vec())?;
        d.set_item("rows", t.grid.0)?;
        d.set_item("cols", t.grid.1)?;
        d.set_item("parameters", parameter_dict(py, &t.parameters)?)?;
        d.set_item("reach", t.reach)?;
        list.append(d)?;
    }
    Ok(list)
}

/// The values of one to three formulas of one variable (``variable`` "u", "v" or "t", and the
/// parameters a, b, c) at each of ``at``: an (M, K) array for K formulas, NaN where a formula is
/// undefined (sqrt(−1)). A mistake is a ``RuledlabError`` naming the formula (``name[k]``, default
/// ``f[k]``) and the column, as ``from_formulas`` gives it.
#[pyfunction]
#[pyo3(signature = (formulas, at, *, variable=None, name=None, parameters=None, decimal_comma=None))]
pub fn evaluate_formulas<'py>(
    py: Python<'py>,
    formulas: &Bound<'py, PyAny>,
    at: &Bound<'py, PyAny>,
    variable: Option<&Bound<'py, PyAny>>,
    name: Option<&Bound<'py, PyAny>>,
    parameters: Option<&Bound<'py, PyAny>>,
    decimal_comma: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "evaluate_formulas";
    let bad =
        || fail_option(F, "formulas", format!("formulas must be one to three strings, got {}", describe(formulas)));
    if formulas.is_instance_of::<PyString>() {
        return Err(bad());
    }
    let texts: Vec<Bound<'_, PyAny>> = formulas.try_iter().map_err(|_| bad())?.collect::<PyResult<_>>()?;
    if texts.is_empty() || texts.len() > 3 {
        return Err(fail_option(F, "formulas", format!("one to three formulas, got {}", texts.len())));
    }
    let known = ["u", "v", "t"];
    let variable = known[args::choice(F, "variable", variable, &known)?.unwrap_or(0)];
    let name = args::optional_text(F, "name", name)?.unwrap_or_else(|| "f".to_string());
    if name.len() > 32 || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(fail_option(F, "name", "name must be at most 32 letters, digits or _"));
    }
    let values = self::parameters(F, parameters)?;
    let comma = Comma::of(F, decimal_comma)?;
    let x = arrays::numbers(F, "at", at)?;
    let count = arrays::vector(F, "at", &x)?;
    if count > MAX_SAMPLES {
        return Err(fail_option(F, "at", format!("at most {MAX_SAMPLES} values, got {count}")));
    }
    let variables = [variable, PARAMETERS[0], PARAMETERS[1], PARAMETERS[2]];
    let parsed = texts
        .iter()
        .enumerate()
        .map(|(k, t)| {
            let source = format!("{name}[{k}]");
            let text = comma.read(F, &source, &args::text(F, &source, t)?)?;
            Formula::parse(&source, &text, &variables).map_err(|e| fail(F, e))
        })
        .collect::<PyResult<Vec<_>>>()?;
    let xs = x.slice();
    let out: Vec<f64> = py.detach(|| {
        let mut out = Vec::with_capacity(xs.len() * parsed.len());
        for &x in xs {
            let vars = [x, values[0], values[1], values[2]];
            out.extend(parsed.iter().map(|f| f.value(&vars)));
        }
        out
    });
    let k = parsed.len();
    arrays::array(py, out, &[count, k])
}
