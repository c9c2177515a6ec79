//! Reading the CAM data files given as text: `import_tool_poses` (tool poses, from the files CAM
//! systems and ruledlab write) and `import_target` (a target curve), as the JavaScript
//! functions of the CAM module (`crates/ruledlab-cam-wasm/src/import.rs`).

use crate::args;
use crate::arrays;
use crate::error::fail;
use crate::gcode_options::preset;
use crate::import::text_and_format;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use ruledlab_cam::{read_target, read_tool_poses_for, ToolEnd};

/// Tool poses read from CSV (tip x, y, z and axis i, j, k per row; a header naming the columns
/// as CAM systems do; or x, y, z, a, b, c: rotary angles in degrees of the machine the file names
/// in ``# machine: …`` or ``machine``, a preset's name) or JSON (``{"poses": [{"tip", "axis"}],
/// "tool", "units"}``), ruledlab's own tool-path files included: ``tips`` (N, 3), ``axes`` (N, 3)
/// unit, ``lines`` (N,) the 1-based line of each pose, and where the file says them ``tool``,
/// ``units``, ``machine``.
#[pyfunction]
#[pyo3(signature = (text, format=None, *, machine=None))]
pub fn import_tool_poses<'py>(
    py: Python<'py>,
    text: &Bound<'py, PyAny>,
    format: Option<&Bound<'py, PyAny>>,
    machine: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    const F: &str = "import_tool_poses";
    let (text, json) = text_and_format(F, text, format)?;
    let machine = match args::optional_text(F, "machine", machine)? {
        None => None,
        Some(name) => Some(preset(F, &name)?),
    };
    let p = py
        .detach(|| read_tool_poses_for(&text, json, &ruledlab::rust_number, machine.as_ref()))
        .map_err(|e| fail(F, e))?;
    let d = PyDict::new(py);
    if let Some(t) = p.tool {
        let tool = PyDict::new(py);
        tool.set_item("radius", t.radius)?;
        tool.set_item("length", t.length)?;
        tool.set_item(
            "end",
            match t.end {
                ToolEnd::Ball => "ball",
                ToolEnd::Flat => "flat",
            },
        )?;
        d.set_item("tool", tool)?;
    }
    if let Some(units) = &p.units {
        d.set_item("units", units)?;
    }
    if let Some(machine) = &p.machine {
        d.set_item("machine", machine)?;
    }
    let n = p.lines.len();
    d.set_item("lines", numpy::PyArray1::from_vec(py, p.lines.iter().map(|&l| l as u64).collect::<Vec<u64>>()))?;
    debug_assert_eq!(n, p.tips.len());
    d.set_item("tips", arrays::points(py, p.tips)?)?;
    d.set_item("axes", arrays::points(py, p.axes)?)?;
    Ok(d)
}

/// A target curve — the edge or contact curve the tool should machine — read from CSV (x, y, z
/// per row, an optional header, ``# units: inch``) or JSON (``[[x, y, z], …]`` or ``{"points",
/// "units"}``): ``points`` (M, 3) and, where the file says so, ``units``.
#[pyfunction]
#[pyo3(signature = (text, format=None))]
pub fn import_target<'py>(
    py: Python<'py>,
    text: &Bound<'py, PyAny>,
    format: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    const F: &str = "import_target";
    let (text, json) = text_and_format(F, text, format)?;
    let t = py.detach(|| read_target(&text, json, &ruledlab::rust_number)).map_err(|e| fail(F, e))?;
    let d = PyDict::new(py);
    d.set_item("points", arrays::points(py, t.points)?)?;
    if let Some(units) = &t.units {
        d.set_item("units", units)?;
    }
    Ok(d)
}
