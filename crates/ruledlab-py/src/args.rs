//! Checking the numbers, integers, flags and names passed from Python, as
//! `crates/ruledlab-js/src/args.rs` checks JavaScript's: a wrong type or a value out of range is a
//! `RuledlabError` with code `invalid-argument` naming the argument and what was given.
//!
//! Every argument is taken as a Python object and checked here (never by PyO3's conversions,
//! whose `TypeError` carries no code). A number is an instance of `numbers.Real` (Python's int
//! and float, NumPy's integer and floating scalars, `Fraction`) that is not a `bool`; `None`
//! stands for an argument left out.

use crate::error::fail_option;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBool, PyDict, PyString, PyType};

static REAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static INTEGRAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();

/// What a Python value is, for messages: "a str", "a complex", "None".
pub fn describe(value: &Bound<'_, PyAny>) -> String {
    if value.is_none() {
        return "None".into();
    }
    let name = value.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "object".into());
    let article = if name.starts_with(['a', 'e', 'i', 'o', 'u', 'A', 'E', 'I', 'O', 'U']) { "an" } else { "a" };
    match value.repr() {
        Ok(r) if r.to_string().len() <= 40 => format!("{article} {name} ({r})"),
        _ => format!("{article} {name}"),
    }
}

/// Whether `value` is a real number (not a bool).
fn is_real(value: &Bound<'_, PyAny>) -> PyResult<bool> {
    if value.is_instance_of::<PyBool>() || value.get_type().name()? == "bool" {
        return Ok(false);
    }
    let real = REAL.import(value.py(), "numbers", "Real")?;
    value.is_instance(real)
}

/// A real number (any, NaN and infinities included).
pub fn real(func: &str, name: &str, value: &Bound<'_, PyAny>) -> PyResult<f64> {
    if is_real(value)? {
        if let Ok(x) = value.extract::<f64>() {
            return Ok(x);
        }
    }
    Err(fail_option(func, name, format!("{name} must be a number, got {}", describe(value))))
}

/// A finite number.
pub fn number(func: &str, name: &str, value: &Bound<'_, PyAny>) -> PyResult<f64> {
    let x = real(func, name, value)?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(fail_option(func, name, format!("{name} must be a finite number, got {x}")))
    }
}

/// A finite number, `None` when left out.
pub fn optional_number(func: &str, name: &str, value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<f64>> {
    value.filter(|v| !v.is_none()).map(|v| number(func, name, v)).transpose()
}

/// An integer in [min, max] (an int, a NumPy integer, or a float with an integral value, as
/// JavaScript's numbers are).
pub fn integer(func: &str, name: &str, value: &Bound<'_, PyAny>, min: usize, max: usize) -> PyResult<usize> {
    let bad =
        || fail_option(func, name, format!("{name} must be an integer from {min} to {max}, got {}", describe(value)));
    if !is_real(value)? {
        return Err(bad());
    }
    let integral = INTEGRAL.import(value.py(), "numbers", "Integral")?;
    if value.is_instance(integral)? {
        // (an int beyond i128 is surely out of range)
        return match value.extract::<i128>() {
            Ok(k) if k >= min as i128 && k <= max as i128 => Ok(k as usize),
            _ => Err(bad()),
        };
    }
    match value.extract::<f64>() {
        Ok(x) if x.fract() == 0.0 && x >= min as f64 && x <= max as f64 => Ok(x as usize),
        _ => Err(bad()),
    }
}

/// An integer in [min, max], `default` when left out.
pub fn optional_integer(
    func: &str,
    name: &str,
    value: Option<&Bound<'_, PyAny>>,
    min: usize,
    max: usize,
    default: usize,
) -> PyResult<usize> {
    match value.filter(|v| !v.is_none()) {
        Some(v) => integer(func, name, v, min, max),
        None => Ok(default),
    }
}

/// True or False (a NumPy bool too), `default` when left out.
pub fn flag(func: &str, name: &str, value: Option<&Bound<'_, PyAny>>, default: bool) -> PyResult<bool> {
    let Some(v) = value.filter(|v| !v.is_none()) else { return Ok(default) };
    if v.is_instance_of::<PyBool>() || matches!(v.get_type().name()?.to_string().as_str(), "bool" | "bool_") {
        return v.is_truthy();
    }
    Err(fail_option(func, name, format!("{name} must be True or False, got {}", describe(v))))
}

/// A string.
pub fn text(func: &str, name: &str, value: &Bound<'_, PyAny>) -> PyResult<String> {
    match value.cast::<PyString>() {
        Ok(s) => Ok(s.to_string()),
        Err(_) => Err(fail_option(func, name, format!("{name} must be a string, got {}", describe(value)))),
    }
}

/// A string, `None` when left out.
pub fn optional_text(func: &str, name: &str, value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<String>> {
    value.filter(|v| !v.is_none()).map(|v| text(func, name, v)).transpose()
}

/// One of `known` (its index), `None` when left out.
pub fn choice(func: &str, name: &str, value: Option<&Bound<'_, PyAny>>, known: &[&str]) -> PyResult<Option<usize>> {
    let Some(v) = value.filter(|v| !v.is_none()) else { return Ok(None) };
    let list = || known.iter().map(|k| format!("\"{k}\"")).collect::<Vec<_>>().join(", ");
    let given = text(func, name, v)
        .map_err(|_| fail_option(func, name, format!("{name} must be one of {}, got {}", list(), describe(v))))?;
    match known.iter().position(|k| *k == given) {
        Some(k) => Ok(Some(k)),
        None => Err(fail_option(func, name, format!("{name} must be one of {}, got \"{given}\"", list()))),
    }
}

/// Refuses option `name` (given: `present`) unless the scheme chosen is `scheme`: an option of
/// another scheme would otherwise be ignored silently.
pub fn only_for(func: &str, name: &str, present: bool, scheme: &str, chosen: Option<&str>) -> PyResult<()> {
    if present && chosen != Some(scheme) {
        let chosen = chosen.map(|c| format!(", not to \"{c}\"")).unwrap_or_default();
        return Err(fail_option(func, name, format!("{name} applies to the \"{scheme}\" scheme only{chosen}")));
    }
    Ok(())
}

/// Whether an optional argument was given (not left out, not None).
pub fn given(value: Option<&Bound<'_, PyAny>>) -> bool {
    value.is_some_and(|v| !v.is_none())
}

/// The keyword arguments `kwargs` read by name: each of `names` given (a `None` counts as left
/// out) or left out, in the order of `names`; a keyword not among them is refused with the list.
/// For a set of options several methods share (a program's options, a surface's ranges): one
/// list of names instead of the same parameters in each signature.
pub fn keywords<'py>(
    func: &str,
    kwargs: Option<&Bound<'py, PyDict>>,
    names: &[&str],
) -> PyResult<Vec<Option<Bound<'py, PyAny>>>> {
    let mut values = vec![None; names.len()];
    for (key, value) in kwargs.into_iter().flat_map(|d| d.iter()) {
        let key = key.str()?.to_string();
        let Some(i) = names.iter().position(|k| *k == key) else {
            return Err(fail_option(
                func,
                &key,
                format!("unknown option \"{key}\"; the options are {}", names.join(", ")),
            ));
        };
        values[i] = Some(value).filter(|v| !v.is_none());
    }
    Ok(values)
}
