//! The core's structured results (serde `Serialize`, camelCase keys, as JavaScript gets them) as
//! Python dicts and lists: with snake_case keys for results (`sampling_errors`, `convergence`,
//! …), with the keys as written for data in a documented JSON form (a machine description). No
//! class.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
use serde::Serialize;

/// `parallelPairs` → `parallel_pairs`.
pub fn snake(key: &str) -> String {
    let mut out = String::with_capacity(key.len() + 4);
    for c in key.chars() {
        if c.is_ascii_uppercase() {
            out.push('_');
            out.push(c.to_ascii_lowercase());
        } else {
            out.push(c);
        }
    }
    out
}

/// `value` as Python objects (pythonize), every dict key in snake_case, sequences as lists.
pub fn to_python<'py, T: Serialize>(py: Python<'py>, value: &T) -> PyResult<Bound<'py, PyAny>> {
    let object = pythonize::pythonize(py, value).map_err(PyErr::from)?;
    plain(py, object, true)
}

/// `value` as the Python of its JSON (`json.dumps` of it is the JSON): dicts with the keys as
/// serde writes them, sequences as lists.
pub fn to_json_like<'py, T: Serialize>(py: Python<'py>, value: &T) -> PyResult<Bound<'py, PyAny>> {
    let object = pythonize::pythonize(py, value).map_err(PyErr::from)?;
    plain(py, object, false)
}

fn plain<'py>(py: Python<'py>, object: Bound<'py, PyAny>, snake_keys: bool) -> PyResult<Bound<'py, PyAny>> {
    if let Ok(d) = object.cast::<PyDict>() {
        let out = PyDict::new(py);
        for (k, v) in d.iter() {
            let key = k.str()?.to_string();
            out.set_item(if snake_keys { snake(&key) } else { key }, plain(py, v, snake_keys)?)?;
        }
        return Ok(out.into_any());
    }
    if object.is_instance_of::<PyList>() || object.is_instance_of::<PyTuple>() {
        let items = object.try_iter()?.map(|v| plain(py, v?, snake_keys)).collect::<PyResult<Vec<_>>>()?;
        return Ok(PyList::new(py, items)?.into_any());
    }
    Ok(object)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_written_as_python_writes_them() {
        assert_eq!(snake("parallelPairs"), "parallel_pairs");
        assert_eq!(snake("distributionMean"), "distribution_mean");
        assert_eq!(snake("u"), "u");
    }
}
