//! NumPy arrays in and out.
//!
//! **In**: every coordinate argument is read as float64. An array that is float64 in the
//! machine's byte order and C order is read where it lies (no copy); any other array of real
//! numbers (integers, float32, a Fortran-ordered or strided view) and nested lists of numbers are
//! converted by NumPy once (`np.ascontiguousarray(x, dtype=np.float64)`). Complex numbers,
//! strings, bytes, booleans, dates and Python objects are refused with a message that says what
//! was given (`invalid-argument`), never read silently. Shapes are checked before the core sees
//! the numbers: one row per record (point, ruling, pose), its coordinates along the last axis.
//!
//! **Out**: every array the core returns becomes a NumPy array that owns the core's `Vec`
//! (`PyArray::from_vec`: no copy), shaped by a view (one row per record, as the JavaScript API's
//! flat arrays hold them in order); points are float64 like everything else.

use crate::error::fail_option;
use glam::{DVec2, DVec3};
use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Numbers passed from Python, as a C-contiguous float64 array (the caller's own, or NumPy's
/// conversion of it), borrowed read-only while the core reads it.
pub struct Numbers<'py> {
    array: PyReadonlyArrayDyn<'py, f64>,
}

impl Numbers<'_> {
    /// The numbers in C order.
    pub fn slice(&self) -> &[f64] {
        // C-contiguous by construction (`numbers` converts anything else)
        self.array.as_slice().unwrap_or(&[])
    }

    /// The array's shape.
    pub fn shape(&self) -> &[usize] {
        self.array.shape()
    }
}

/// `(4, 2)`, `(5,)`: a shape as Python writes it.
pub fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!("({})", shape.iter().map(usize::to_string).collect::<Vec<_>>().join(", ")),
    }
}

/// What a NumPy dtype that is not a real number holds, for the message refusing it.
fn refused_kind(kind: char, dtype: &str) -> Option<String> {
    Some(match kind {
        'f' | 'i' | 'u' => return None,
        'c' => format!("complex numbers ({dtype}); pass the real part (x.real) or the modulus (abs(x))"),
        'U' | 'S' => format!("strings ({dtype}); convert them first, e.g. np.asarray(x, dtype=float)"),
        'O' => {
            "Python objects (dtype object): numbers mixed with None, text or other objects, or rows of unequal length"
                .to_string()
        }
        'b' => format!("booleans ({dtype})"),
        'M' | 'm' => format!("dates or times ({dtype})"),
        _ => format!("values of dtype {dtype}"),
    })
}

/// Reads argument `name` of `func` as float64 numbers (see the module documentation).
pub fn numbers<'py>(func: &str, name: &str, obj: &Bound<'py, PyAny>) -> PyResult<Numbers<'py>> {
    if let Ok(a) = obj.cast::<PyArrayDyn<f64>>() {
        if a.is_c_contiguous() {
            return readonly(func, name, a);
        }
    }
    let py = obj.py();
    let np = py.import("numpy")?;
    let given = np.call_method1("asarray", (obj,)).map_err(|e| {
        fail_option(func, name, format!("{name} must be an array of real numbers, but NumPy cannot read it: {e}"))
    })?;
    let dtype = given.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    let text: String = dtype.str()?.extract()?;
    if let Some(what) = refused_kind(kind.chars().next().unwrap_or('?'), &text) {
        return Err(fail_option(func, name, format!("{name} must be an array of real numbers, got {what}")));
    }
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", np.getattr("float64")?)?;
    let converted = np.call_method("ascontiguousarray", (given,), Some(&kwargs))?;
    let array = converted.cast_into::<PyArrayDyn<f64>>().map_err(PyErr::from)?;
    readonly(func, name, &array)
}

fn readonly<'py>(func: &str, name: &str, a: &Bound<'py, PyArrayDyn<f64>>) -> PyResult<Numbers<'py>> {
    let array = a
        .try_readonly()
        .map_err(|e| fail_option(func, name, format!("{name} cannot be read while it is being written: {e}")))?;
    Ok(Numbers { array })
}

/// An (N, width) array: N, or an error naming the shape wanted (`what`: one row is one …).
pub fn rows(func: &str, name: &str, n: &Numbers<'_>, width: usize, what: &str) -> PyResult<usize> {
    match n.shape() {
        [rows, w] if *w == width => Ok(*rows),
        shape => Err(fail_option(
            func,
            name,
            format!("{name} must have shape (N, {width}), one {what} per row, got {}", shape_text(shape)),
        )),
    }
}

/// Segments as one array: shape (N, 6) (a then b in each row) or (N, 2, 3); N.
pub fn segment_rows(func: &str, name: &str, n: &Numbers<'_>, what: &str) -> PyResult<usize> {
    match n.shape() {
        [rows, 6] | [rows, 2, 3] => Ok(*rows),
        shape => Err(fail_option(
            func,
            name,
            format!(
                "{name} must have shape (N, 6) or (N, 2, 3), one {what} per row (its two points), got {}",
                shape_text(shape)
            ),
        )),
    }
}

/// A grid of points, shape (rows, cols, 3): (rows, cols).
pub fn grid_shape(func: &str, name: &str, n: &Numbers<'_>) -> PyResult<(usize, usize)> {
    match n.shape() {
        [rows, cols, 3] => Ok((*rows, *cols)),
        shape => Err(fail_option(
            func,
            name,
            format!("{name} must have shape (rows, cols, 3), one point per grid node, got {}", shape_text(shape)),
        )),
    }
}

/// A grid of lines as one array, shape (rows, cols, 6) or (rows, cols, 2, 3): (rows, cols).
pub fn grid_lines_shape(func: &str, name: &str, n: &Numbers<'_>) -> PyResult<(usize, usize)> {
    match n.shape() {
        [rows, cols, 6] | [rows, cols, 2, 3] => Ok((*rows, *cols)),
        shape => Err(fail_option(
            func,
            name,
            format!(
                "{name} must have shape (rows, cols, 6) or (rows, cols, 2, 3), one line per grid node, got {}",
                shape_text(shape)
            ),
        )),
    }
}

/// A one-dimensional array: its length.
pub fn vector(func: &str, name: &str, n: &Numbers<'_>) -> PyResult<usize> {
    match n.shape() {
        [len] => Ok(*len),
        shape => {
            Err(fail_option(func, name, format!("{name} must be one-dimensional, got shape {}", shape_text(shape))))
        }
    }
}

/// Two arrays of the same shape: an error naming the second otherwise.
pub fn same_shape(func: &str, names: [&str; 2], a: &Numbers<'_>, b: &Numbers<'_>) -> PyResult<()> {
    if a.shape() == b.shape() {
        return Ok(());
    }
    Err(fail_option(
        func,
        names[1],
        format!(
            "{} and {} must have the same shape, got {} and {}",
            names[0],
            names[1],
            shape_text(a.shape()),
            shape_text(b.shape())
        ),
    ))
}

/// The points `a[i]`, `b[i]` of two arrays of 3 columns interleaved: a_0, b_0, a_1, b_1, … (the
/// order in which the core keeps a ruling's two points).
pub fn interleave(a: &[f64], b: &[f64]) -> Vec<DVec3> {
    a.chunks_exact(3).zip(b.chunks_exact(3)).flat_map(|(p, q)| [DVec3::from_slice(p), DVec3::from_slice(q)]).collect()
}

/// Numbers as a NumPy array of `shape` owning `data` (no copy).
pub fn array<'py>(py: Python<'py>, data: Vec<f64>, shape: &[usize]) -> PyResult<Bound<'py, PyAny>> {
    let flat = PyArray1::from_vec(py, data);
    if shape.len() == 1 {
        return Ok(flat.into_any());
    }
    Ok(flat.reshape(shape.to_vec())?.into_any())
}

/// Points as an (n, 3) array (no copy).
pub fn points(py: Python<'_>, points: Vec<DVec3>) -> PyResult<Bound<'_, PyAny>> {
    let n = points.len();
    array(py, bytemuck::allocation::cast_vec(points), &[n, 3])
}

/// Points in a plane as an (n, 2) array (no copy).
pub fn points2(py: Python<'_>, points: Vec<DVec2>) -> PyResult<Bound<'_, PyAny>> {
    let n = points.len();
    array(py, bytemuck::allocation::cast_vec(points), &[n, 2])
}

/// Booleans as a 1-D array of dtype bool (no copy).
pub fn flags(py: Python<'_>, flags: Vec<bool>) -> Bound<'_, PyAny> {
    PyArray1::from_vec(py, flags).into_any()
}

/// Indices as an array of dtype uint32 of `shape` (no copy).
pub fn indices<'py>(py: Python<'py>, data: Vec<u32>, shape: &[usize]) -> PyResult<Bound<'py, PyAny>> {
    let flat = PyArray1::from_vec(py, data);
    Ok(flat.reshape(shape.to_vec())?.into_any())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_are_written_as_python_writes_them() {
        assert_eq!(shape_text(&[5]), "(5,)");
        assert_eq!(shape_text(&[4, 2]), "(4, 2)");
        assert_eq!(shape_text(&[]), "()");
    }

    #[test]
    fn what_is_not_a_real_number_is_said() {
        assert!(refused_kind('f', "<f8").is_none());
        assert!(refused_kind('i', "<i8").is_none());
        assert!(refused_kind('c', "<c16").unwrap().starts_with("complex numbers"));
        assert!(refused_kind('U', "<U1").unwrap().starts_with("strings"));
        assert!(refused_kind('O', "|O").unwrap().starts_with("Python objects"));
        assert!(refused_kind('b', "|b1").unwrap().starts_with("booleans"));
    }

    #[test]
    fn pairs_interleave_as_the_core_keeps_rulings() {
        let p = interleave(&[0.0, 1.0, 2.0, 3.0, 4.0, 5.0], &[6.0, 7.0, 8.0, 9.0, 10.0, 11.0]);
        assert_eq!(
            p,
            vec![
                DVec3::new(0.0, 1.0, 2.0),
                DVec3::new(6.0, 7.0, 8.0),
                DVec3::new(3.0, 4.0, 5.0),
                DVec3::new(9.0, 10.0, 11.0)
            ]
        );
    }
}
