//! Errors raised to Python: `ruledlab.RuledlabError` (a `ValueError`, defined in
//! `python/ruledlab/_errors.py`), with the message naming the function and the problem, the
//! stable `code` of the core ([`ruledlab::Error::code`], the book's "Errors and their codes") and
//! `details` as a dict (`option`, `index`, `line`, `column`, `limit`, `reason`, `args`, `hint`),
//! as the JavaScript bindings give them (`crates/ruledlab-js/src/error.rs`).
//!
//! One difference, for NumPy: a coordinate that is NaN, infinite or too large is named by the
//! argument and the NumPy index the caller wrote (`b[2, 1] (ruling 2, b.y) is nan`), and
//! `details.index` counts what the message counts — the ruling, the point, or the (row, column)
//! of a grid's line — not the numbers of a flat array, which Python never sees;
//! `details.array` names the argument and `details.at` is the index into it.

use crate::layout::Layout;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyDict, PyType};
pub use ruledlab::Problem;
use ruledlab::{Arg, Details, Error, Message};

/// The class `ruledlab._errors.RuledlabError`, imported once.
static RULEDLAB_ERROR: PyOnceLock<Py<PyType>> = PyOnceLock::new();

/// The `RuledlabError` for `problem`, its message prefixed by `func` (e.g.
/// "RuledSurface.from_segments").
pub fn fail(func: &str, problem: impl Into<Problem>) -> PyErr {
    let (message, code, details) = problem.into().parts();
    raise(func, &message, code, |py| details_dict(py, &details))
}

/// A problem with the option or argument `option` (its name goes into `details.option`).
pub fn fail_option(func: &str, option: &str, message: impl Into<String>) -> PyErr {
    fail(func, Problem::Argument { option: Some(option.to_string()), message: message.into() })
}

/// The core's error `e` about input laid out as `layout` says: a coordinate named by the
/// caller's argument and NumPy index (see the module documentation), any other error as
/// [`fail`] gives it.
pub fn fail_input(func: &str, e: Error, layout: &Layout) -> PyErr {
    // the coordinate's record named as the caller's arrays hold it (a grid's line by its row and
    // column)
    let e = match e {
        Error::NonFinite { index, value, record } => Error::NonFinite { index, value, record: layout.record(record) },
        Error::OutOfRange { index, value, max, record } => {
            Error::OutOfRange { index, value, max, record: layout.record(record) }
        }
        other => return fail(func, other),
    };
    let (index, value) = match &e {
        Error::NonFinite { index, value, .. } | Error::OutOfRange { index, value, .. } => (*index, *value),
        _ => unreachable!("only coordinates get here"),
    };
    let (array, at) = layout.locate(index);
    let written = format!("{array}[{}]", at.iter().map(usize::to_string).collect::<Vec<_>>().join(", "));
    // the core's message with the coordinate named as the caller wrote it
    let core = e.message();
    let args: Vec<(&'static str, Arg)> = core
        .args
        .iter()
        .map(|(name, arg)| if *name == "index" { (*name, Arg::Text(written.clone())) } else { (*name, arg.clone()) })
        .collect();
    let message = Message { reason: core.reason, args, catalogue: core.catalogue };
    let counted = layout.record_of(index);
    let limit = match &e {
        Error::OutOfRange { max, .. } => Some(*max),
        _ => None,
    };
    raise(func, &message.english(), e.code(), |py| {
        let d = PyDict::new(py);
        if counted.len() == 1 {
            d.set_item("index", counted[0])?;
        } else {
            d.set_item("index", counted.clone())?;
        }
        d.set_item("array", array)?;
        d.set_item("at", at.clone())?;
        if let Some(limit) = limit {
            d.set_item("limit", limit)?;
        }
        d.set_item("value", value)?;
        d.set_item("reason", message.reason)?;
        d.set_item("args", args_dict(py, &message.args)?)?;
        Ok(d)
    })
}

/// The `details` of an error as a dict.
fn details_dict<'py>(py: Python<'py>, details: &Details) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    if let Some(option) = &details.option {
        d.set_item("option", option)?;
    }
    if let Some(index) = details.index {
        d.set_item("index", index)?;
    }
    if let Some(line) = details.line {
        d.set_item("line", line)?;
    }
    if let Some(column) = details.column {
        d.set_item("column", column)?;
    }
    if let Some(limit) = details.limit {
        d.set_item("limit", limit)?;
    }
    if let Some(reason) = details.reason {
        d.set_item("reason", reason)?;
    }
    if let Some(args) = &details.args {
        d.set_item("args", args_dict(py, &args.0)?)?;
    }
    if let Some(hint) = &details.hint {
        let h = PyDict::new(py);
        h.set_item("reason", hint.reason)?;
        h.set_item("args", args_dict(py, &hint.args.0)?)?;
        d.set_item("hint", h)?;
    }
    Ok(d)
}

/// A message's arguments as a dict (numbers stay numbers).
fn args_dict<'py>(py: Python<'py>, args: &[(&'static str, Arg)]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (name, value) in args {
        match value {
            Arg::Text(s) => d.set_item(*name, s)?,
            Arg::Number(x) => d.set_item(*name, *x)?,
        }
    }
    Ok(d)
}

/// `RuledlabError(f"{func}: {message}", code, details)`; a `ValueError` with the message should
/// the class not import (it always does inside the package).
fn raise(
    func: &str,
    message: &str,
    code: &str,
    details: impl for<'py> FnOnce(Python<'py>) -> PyResult<Bound<'py, PyDict>>,
) -> PyErr {
    let text = format!("{func}: {message}");
    Python::attach(|py| {
        let made = (|| -> PyResult<PyErr> {
            let class = RULEDLAB_ERROR.import(py, "ruledlab._errors", "RuledlabError")?;
            let value = class.call1((text.as_str(), code, details(py)?))?;
            Ok(PyErr::from_value(value))
        })();
        made.unwrap_or_else(|_| pyo3::exceptions::PyValueError::new_err(text.clone()))
    })
}
