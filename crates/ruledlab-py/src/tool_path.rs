//! `ToolPath` for Python (Example 6, Figs. 16–18, through `ruledlab-cam`): a five-axis tool
//! path, its refinement by the strip schemes of Section 4 and its quality, the meshes of the
//! tool and its envelope, its G-code programs (the posts for LinuxCNC, Heidenhain and Sinumerik)
//! and its export as data — the JavaScript class of the same name
//! (`crates/ruledlab-cam-wasm/src/tool_path.rs`) without its WebGL buffers.

use crate::args::{self, describe};
use crate::arrays::{self, interleave};
use crate::convert::{to_json_like, to_python};
use crate::error::{fail, fail_input, fail_option};
use crate::focal::mesh_dict;
use crate::gcode_options::{preset, read_post_options, PostArgs};
use crate::layout::Layout;
use crate::scheme_options::{read, SchemeArgs, Space};
use glam::DVec3;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use ruledlab::tolerance::{MAX_EXAMPLE_POSES, MAX_GRID_SIDE, MAX_MESH_SIDES, MAX_SAMPLES, MAX_STRIDE};
use ruledlab::Error;
use ruledlab_cam::{Pose, Tool, ToolEnd};

/// A five-axis tool path: poses (tool tip, unit tool axis pointing into the spindle) and the
/// tool that follows them (Example 6).
#[pyclass(module = "ruledlab._core", frozen)]
pub struct ToolPath {
    inner: ruledlab_cam::ToolPath,
}

/// The tool of a dict {"radius", "length", "end": "ball" (default) or "flat"}.
fn read_tool(func: &str, tool: &Bound<'_, PyAny>) -> PyResult<Tool> {
    let dict = tool.cast::<PyDict>().map_err(|_| {
        fail_option(func, "tool", format!("tool must be a dict {{radius, length, end}}, got {}", describe(tool)))
    })?;
    for key in dict.keys() {
        let key = key.str()?.to_string();
        if !["radius", "length", "end"].contains(&key.as_str()) {
            return Err(fail_option(
                func,
                &format!("tool.{key}"),
                format!("tool: unknown key \"{key}\"; the keys are radius, length, end"),
            ));
        }
    }
    let required = |name: &str| -> PyResult<f64> {
        match dict.get_item(name)? {
            Some(v) => args::number(func, &format!("tool.{name}"), &v),
            None => Err(fail_option(func, name, format!("tool.{name} (the tool {name}) is required"))),
        }
    };
    let (radius, length) = (required("radius")?, required("length")?);
    let end = match args::choice(func, "tool.end", dict.get_item("end")?.as_ref(), &["ball", "flat"])? {
        None | Some(0) => ToolEnd::Ball,
        _ => ToolEnd::Flat,
    };
    Tool::new(radius, length, end).map_err(|e| fail(func, e))
}

/// Target points, an (M, 3) array (`name` of `func`).
fn targets(func: &str, name: &str, value: &Bound<'_, PyAny>) -> PyResult<Vec<DVec3>> {
    let t = arrays::numbers(func, name, value)?;
    let n = arrays::rows(func, name, &t, 3, "point")?;
    ruledlab::points_from_flat(t.slice())
        .map_err(|e| fail_input(func, e, &Layout::One { name, shape: vec![n, 3], lead: 1 }))
}

fn tool_dict(py: Python<'_>, t: Tool) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("radius", t.radius)?;
    d.set_item("length", t.length)?;
    d.set_item(
        "end",
        match t.end {
            ToolEnd::Ball => "ball",
            ToolEnd::Flat => "flat",
        },
    )?;
    Ok(d)
}

impl ToolPath {
    /// The axis segments tip → tip + L·axis, 6 numbers per pose.
    fn axis_coords(&self) -> Vec<f64> {
        let length = self.inner.tool.length;
        self.inner.poses.iter().flat_map(|p| [p.tip, p.tip + length * p.axis]).flat_map(|q| q.to_array()).collect()
    }
}

#[pymethods]
impl ToolPath {
    // --- making one, and the built-in example

    /// A path from the tool tips ``tips`` and points further along each tool axis ``ends``
    /// (two (N, 3) arrays; the axis runs tip → end) with ``tool`` ``{"radius", "length",
    /// "end"}`` ("ball", the default, or "flat").
    #[staticmethod]
    fn from_segments(
        py: Python<'_>,
        tips: &Bound<'_, PyAny>,
        ends: &Bound<'_, PyAny>,
        tool: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        const F: &str = "ToolPath.from_segments";
        let tool = read_tool(F, tool)?;
        let (t, e) = (arrays::numbers(F, "tips", tips)?, arrays::numbers(F, "ends", ends)?);
        let n = arrays::rows(F, "tips", &t, 3, "pose")?;
        arrays::rows(F, "ends", &e, 3, "pose")?;
        arrays::same_shape(F, ["tips", "ends"], &t, &e)?;
        let (st, se) = (t.slice(), e.slice());
        let axes = py.detach(|| ruledlab::RuledSurface::from_points(interleave(st, se))).map_err(|e| match e {
            Error::ZeroLength { ruling } => {
                fail_option(F, "ends", format!("tool axis {ruling} has zero length (tip and axis point coincide)"))
            }
            other => fail_input(F, other, &Layout::Pair { names: ["tips", "ends"], lead: vec![n] }),
        })?;
        Ok(ToolPath { inner: ruledlab_cam::ToolPath::from_surface(&axes, tool) })
    }

    /// A path from the tool tips and tool axes (two (N, 3) arrays; an axis points into the
    /// spindle and need not be a unit vector: a unit one is kept bit for bit) and ``tool``.
    #[staticmethod]
    fn from_poses(tips: &Bound<'_, PyAny>, axes: &Bound<'_, PyAny>, tool: &Bound<'_, PyAny>) -> PyResult<Self> {
        const F: &str = "ToolPath.from_poses";
        let tool = read_tool(F, tool)?;
        let (t, a) = (arrays::numbers(F, "tips", tips)?, arrays::numbers(F, "axes", axes)?);
        let n = arrays::rows(F, "tips", &t, 3, "pose")?;
        arrays::rows(F, "axes", &a, 3, "pose")?;
        arrays::same_shape(F, ["tips", "axes"], &t, &a)?;
        if n < 2 {
            return Err(fail(F, Error::TooFew { what: "poses", got: n, min: 2 }));
        }
        let points = interleave(t.slice(), a.slice());
        ruledlab::check_coordinates(bytemuck::cast_slice(&points), 6)
            .map_err(|e| fail_input(F, e, &Layout::Pair { names: ["tips", "axes"], lead: vec![n] }))?;
        let mut poses = Vec::with_capacity(n);
        for (k, pair) in points.chunks_exact(2).enumerate() {
            let (tip, a) = (pair[0], pair[1]);
            let len = a.length();
            if !(len > 0.0 && (a / len).is_finite()) {
                return Err(fail_option(F, "axes", format!("tool axis {k} has zero length")));
            }
            let axis = if (a.length_squared() - 1.0).abs() < 1e-15 { a } else { a / len };
            poses.push(Pose { tip, axis });
        }
        Ok(ToolPath { inner: ruledlab_cam::ToolPath { poses, tool } })
    }

    /// The built-in path of Figs. 16–18 with ``count`` given poses (default 7), for its tool (a
    /// ball end of radius 0.25 and length 1.5) or for ``tool``: its ball touches the profile at
    /// every pose.
    #[staticmethod]
    #[pyo3(signature = (count=None, tool=None))]
    fn example(count: Option<&Bound<'_, PyAny>>, tool: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        const F: &str = "ToolPath.example";
        let count = args::optional_integer(F, "count", count, 2, MAX_EXAMPLE_POSES, 7)?;
        let made = match tool.filter(|t| !t.is_none()) {
            None => ruledlab_cam::example_tool_path(count),
            Some(t) => ruledlab_cam::example_tool_path_for(count, read_tool(F, t)?),
        };
        made.map(|inner| ToolPath { inner }).map_err(|e| fail(F, e))
    }

    /// The example's target profile γ, ``count`` points, (count, 3).
    #[staticmethod]
    fn example_profile<'py>(py: Python<'py>, count: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let count = args::integer("ToolPath.example_profile", "count", count, 2, MAX_SAMPLES)?;
        arrays::points(py, ruledlab_cam::example_profile(count))
    }

    /// The part surface of the built-in example, z = 0.3 sin x cos 0.7y, as an nx × ny grid mesh
    /// (``positions``, ``indices``).
    #[staticmethod]
    fn example_part<'py>(
        py: Python<'py>,
        nx: &Bound<'py, PyAny>,
        ny: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        const F: &str = "ToolPath.example_part";
        let (nx, ny) = (args::integer(F, "nx", nx, 2, MAX_GRID_SIDE)?, args::integer(F, "ny", ny, 2, MAX_GRID_SIDE)?);
        mesh_dict(py, ruledlab_cam::part_mesh(nx, ny))
    }

    /// A preset machine's description, as a dict in the JSON a custom machine is written in
    /// (keys as the book writes them): "table-table-ac", "table-table-bc", "head-table-bc" or
    /// "head-head-ac".
    #[staticmethod]
    fn machine<'py>(py: Python<'py>, name: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        const F: &str = "ToolPath.machine";
        let name = args::text(F, "name", name)?;
        to_json_like(py, &preset(F, &name)?)
    }

    // --- its poses and tool

    /// Number of poses.
    fn __len__(&self) -> usize {
        self.inner.poses.len()
    }

    fn __repr__(&self) -> String {
        format!("<ruledlab.ToolPath of {} poses>", self.inner.poses.len())
    }

    /// The tool: ``{"radius", "length", "end"}``, as ``from_segments`` takes it.
    #[getter]
    fn tool<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        tool_dict(py, self.inner.tool)
    }

    /// The tool tips, (N, 3).
    fn tips<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        arrays::points(py, self.inner.poses.iter().map(|p| p.tip).collect())
    }

    /// The unit tool axes, (N, 3).
    fn axes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        arrays::points(py, self.inner.poses.iter().map(|p| p.axis).collect())
    }

    /// The axis segments tip → tip + L·axis, (N, 6).
    fn segments<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        arrays::array(py, self.axis_coords(), &[self.inner.poses.len(), 6])
    }

    /// The barycentre curve (Fig. 16): tip + (L/2)·axis per pose, (N, 3).
    fn barycentres<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        arrays::points(py, self.inner.barycentres())
    }

    /// Ball centres (ball end) or disk centres (flat end), (N, 3): the machined surface is the
    /// envelope of the tool about these.
    fn cutting_centres<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        arrays::points(py, self.inner.cutting_centres())
    }

    // --- refinement and quality (Example 6, Figs. 17 and 18)

    /// The refined path: ``steps`` steps of a strip scheme of Section 4 on the axis surface
    /// (``scheme`` default "variational" (13)/(14); the options of ``RuledSurface.subdivide``, a
    /// path being open and refined through its tips and axes). Releases the GIL.
    #[pyo3(signature = (*, scheme=None, steps=None, w=None, n=None, variant=None, degree=None))]
    #[allow(clippy::too_many_arguments)]
    fn refine(
        &self,
        py: Python<'_>,
        scheme: Option<&Bound<'_, PyAny>>,
        steps: Option<&Bound<'_, PyAny>>,
        w: Option<&Bound<'_, PyAny>>,
        n: Option<&Bound<'_, PyAny>>,
        variant: Option<&Bound<'_, PyAny>>,
        degree: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        const F: &str = "ToolPath.refine";
        let a = SchemeArgs { scheme, steps, w, n, variant, degree, closed: None, space: None, length: None };
        let (scheme, _, steps, space) = read(F, &a, Some("variational"))?;
        debug_assert!(matches!(space, Space::Points));
        py.detach(|| self.inner.refine(scheme, steps)).map(|inner| ToolPath { inner }).map_err(|e| fail(F, e))
    }

    /// The orientation smoothness: ``angle_step`` (N − 1,) the angle between consecutive axes
    /// (radians), ``second_difference`` (N − 2,) ‖a_{k−1} − 2a_k + a_{k+1}‖, and their maxima
    /// ``max_angle_step``, ``max_second_difference``.
    fn quality<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let q = ruledlab_cam::Quality::of(&self.inner);
        let d = PyDict::new(py);
        d.set_item("max_angle_step", q.max_angle_step())?;
        d.set_item("max_second_difference", q.max_second_difference())?;
        let (a, s) = (q.angle_step.len(), q.second_difference.len());
        d.set_item("angle_step", arrays::array(py, q.angle_step, &[a])?)?;
        d.set_item("second_difference", arrays::array(py, q.second_difference, &[s])?)?;
        Ok(d)
    }

    /// The signed deviation of each target point ((M, 3)) from the surface the tool leaves
    /// (> 0: material left, < 0: a gouge), (M,).
    fn deviation<'py>(&self, py: Python<'py>, targets: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let t = self::targets("ToolPath.deviation", "targets", targets)?;
        let out = py.detach(|| ruledlab_cam::deviation(&self.inner, &t));
        let n = out.len();
        arrays::array(py, out, &[n])
    }

    /// Per pose: the distance of its cutting centre from the target polyline ((M, 3), M ≥ 2)
    /// minus the tool radius (> 0 material left, < 0 a gouge), (N,).
    fn deviation_per_pose<'py>(&self, py: Python<'py>, targets: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        const F: &str = "ToolPath.deviation_per_pose";
        let t = self::targets(F, "targets", targets)?;
        let out = py.detach(|| ruledlab_cam::deviation_per_pose(&self.inner, &t));
        let n = out.len();
        arrays::array(py, out, &[n])
    }

    /// The deviation of a target curve ((M, 3)) from the surface the tool machines: ``points``
    /// (M,) each point's signed distance from the solid the tool sweeps (> 0 material left, < 0
    /// cut into), ``at`` (M,) where along the path the nearest tool is (k + s between poses k and
    /// k + 1), ``per_pose`` (N,), and the worst point ``worst`` (its index),
    /// ``worst_deviation``, ``worst_point`` (3,). Releases the GIL.
    fn envelope_deviation<'py>(&self, py: Python<'py>, targets: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
        let t = self::targets("ToolPath.envelope_deviation", "targets", targets)?;
        let dev = py.detach(|| ruledlab_cam::envelope_deviation(&self.inner, &t));
        let d = PyDict::new(py);
        let n = self.inner.poses.len();
        d.set_item("per_pose", arrays::array(py, dev.per_pose(n), &[n])?)?;
        d.set_item("worst", dev.worst)?;
        d.set_item("worst_deviation", dev.points[dev.worst])?;
        d.set_item("worst_point", arrays::array(py, t[dev.worst].to_array().to_vec(), &[3])?)?;
        let m = dev.points.len();
        d.set_item("points", arrays::array(py, dev.points, &[m])?)?;
        d.set_item("at", arrays::array(py, dev.at, &[m])?)?;
        Ok(d)
    }

    /// The envelope of the tool's cutting end along the path (a tube of the tool radius about
    /// the cutting centres; its lower half is the machined surface), ``sides`` vertices per
    /// ring: ``positions``, ``indices``.
    fn envelope_mesh<'py>(&self, py: Python<'py>, sides: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
        let sides = args::integer("ToolPath.envelope_mesh", "sides", sides, 3, MAX_MESH_SIDES)?;
        mesh_dict(py, py.detach(|| self.inner.envelope_mesh(sides)))
    }

    /// The tool body at pose ``index`` (Fig. 16): a cylinder with its ball or flat end
    /// (``positions``, ``indices``).
    fn tool_mesh<'py>(
        &self,
        py: Python<'py>,
        index: &Bound<'py, PyAny>,
        sides: &Bound<'py, PyAny>,
    ) -> PyResult<Option<Bound<'py, PyDict>>> {
        const F: &str = "ToolPath.tool_mesh";
        let index = args::integer(F, "index", index, 0, self.inner.poses.len().saturating_sub(1))?;
        let sides = args::integer(F, "sides", sides, 3, MAX_MESH_SIDES)?;
        self.inner.tool_mesh(index, sides).map(|m| mesh_dict(py, m)).transpose()
    }

    /// The axes (tip → tip + L·axis) of the poses whose index is not a multiple of ``stride``
    /// (after k steps, 2^k: the inserted poses), (M, 6).
    fn inserted<'py>(&self, py: Python<'py>, stride: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        const F: &str = "ToolPath.inserted";
        let stride = args::integer(F, "stride", stride, 1, MAX_STRIDE)?;
        let axes = self.inner.axis_surface().map_err(|e| fail(F, e))?;
        let flat: Vec<f64> = axes.inserted(stride).iter().flat_map(|s| [s.a, s.b]).flat_map(|p| p.to_array()).collect();
        let n = flat.len() / 6;
        arrays::array(py, flat, &[n, 6])
    }

    // --- G-code and data (the book's "G-code and its dialects")

    /// The path as text: "json" or "csv" (the poses, full precision), or "gcode": a program for
    /// a five-axis controller, with the keyword options of ``post`` (what it assumes is said in
    /// the program's header).
    #[pyo3(signature = (format, **options))]
    fn export(
        &self,
        py: Python<'_>,
        format: &Bound<'_, PyAny>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<String> {
        const F: &str = "ToolPath.export";
        let a = PostArgs::read(F, options)?;
        let formats = ["json", "csv", "gcode"];
        let format = args::choice(F, "format", Some(format), &formats)?.map(|k| formats[k]);
        match format {
            Some("json" | "csv") if a.any() => {
                Err(fail(F, "the options (feed, scale, machine, …) apply to the \"gcode\" format only"))
            }
            Some("json") => Ok(ruledlab_cam::tool_path_json(&self.inner)),
            Some("csv") => Ok(ruledlab_cam::tool_path_csv(&self.inner)),
            _ => {
                let o = read_post_options(F, &a)?;
                py.detach(|| ruledlab_cam::gcode(&self.inner, &o)).map(|p| p.text).map_err(|e| fail(F, e))
            }
        }
    }

    /// The G-code program with what the post did: ``text``; ``poses`` and ``inserted`` (the
    /// poses the linearisation added), ``tolerance``, the largest deviations ``before`` and
    /// ``after`` (``{"tip", "axis"}``), per block ``block_tip``, ``block_axis``,
    /// ``block_minutes``, ``block_feed``, ``block_rotary_speed`` (B, 2), ``block_limit`` (0 feed,
    /// 1 speed limit, 2 acceleration limit, 3 the controller's feed word), per pose ``origin``,
    /// ``axes`` (P, 5: X, Y, Z, then the rotary axes in degrees), ``adjusted``; ``units``,
    /// ``letters``, ``over_acceleration``, ``unwinds``, ``warnings``, ``stock``; with a ``target``
    /// ((M, 3) points of the part, model units) its ``deviation`` from the sweep of the program as
    /// posted, program units: ``gouge`` (≤ 0), ``leave`` (≥ 0), ``rms``, ``at`` (3,), ``largest``,
    /// ``worst`` (its point's index), ``pose`` (k + s between poses k and k + 1), ``points`` (M,).
    /// Options as for ``export("gcode", …)``; ``on_progress(fraction)`` is called as the post goes on. Releases
    /// the GIL while the post computes.
    #[pyo3(signature = (*, on_progress=None, **options))]
    fn post<'py>(
        &self,
        py: Python<'py>,
        on_progress: Option<&Bound<'py, PyAny>>,
        options: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        const F: &str = "ToolPath.post";
        let a = PostArgs::read(F, options)?;
        let o = read_post_options(F, &a)?;
        let report: Option<Py<PyAny>> = match on_progress.filter(|f| !f.is_none()) {
            None => None,
            Some(f) if f.is_callable() => Some(f.clone().unbind()),
            Some(f) => {
                return Err(fail_option(F, "on_progress", format!("on_progress must be callable, got {}", describe(f))))
            }
        };
        // the first exception of the callback, raised once the post is done (it cannot stop it)
        let mut raised: Option<PyErr> = None;
        let posted = py.detach(|| {
            let mut progress = |fraction: f64| {
                if let (Some(f), None) = (&report, &raised) {
                    Python::attach(|py| {
                        if let Err(e) = f.call1(py, (fraction,)) {
                            raised = Some(e);
                        }
                    });
                }
            };
            ruledlab_cam::gcode_reporting(&self.inner, &o, &mut progress)
        });
        if let Some(e) = raised {
            return Err(e);
        }
        let p = posted.map_err(|e| fail(F, e))?;
        let u = o.units.mm();
        let l = &p.linearisation;
        let blocks = l.blocks.len();
        let motions = p.motion.len();
        let pose_count = p.joints.len();
        let d = PyDict::new(py);
        d.set_item("text", &p.text)?;
        d.set_item("poses", p.poses.len())?;
        d.set_item("inserted", l.inserted)?;
        d.set_item("tolerance", l.tolerance / u)?;
        let deviation = |tip: f64, axis: f64| -> PyResult<Bound<'py, PyDict>> {
            let d = PyDict::new(py);
            d.set_item("tip", tip / u)?;
            d.set_item("axis", axis / u)?;
            Ok(d)
        };
        d.set_item("before", deviation(l.before.tip, l.before.axis)?)?;
        d.set_item("after", deviation(l.after.tip, l.after.axis)?)?;
        d.set_item("block_tip", arrays::array(py, l.blocks.iter().map(|b| b.tip / u).collect(), &[blocks])?)?;
        d.set_item("block_axis", arrays::array(py, l.blocks.iter().map(|b| b.axis / u).collect(), &[blocks])?)?;
        let origin = p.origin.len();
        d.set_item("origin", arrays::array(py, p.origin.clone(), &[origin])?)?;
        d.set_item("units", o.units.word())?;
        let m = &o.machine;
        d.set_item("letters", vec!["X", "Y", "Z", m.rotary[0].name.letter(), m.rotary[1].name.letter()])?;
        d.set_item("axes", arrays::array(py, p.axis_values(u), &[pose_count, 5])?)?;
        d.set_item("block_minutes", arrays::array(py, p.motion.iter().map(|b| b.minutes).collect(), &[motions])?)?;
        d.set_item("block_feed", arrays::array(py, p.block_feeds(u), &[motions])?)?;
        d.set_item("block_rotary_speed", arrays::array(py, p.rotary_speeds(), &[motions, 2])?)?;
        let limits: Vec<u8> = p.motion.iter().map(|b| b.limit.code()).collect();
        d.set_item("block_limit", numpy::PyArray1::from_vec(py, limits))?;
        d.set_item("over_acceleration", p.motion.iter().filter(|b| b.over).count())?;
        d.set_item("unwinds", (0..p.unwound.len()).filter(|&i| p.unwound[i].is_some()).collect::<Vec<_>>())?;
        let adjusted: Vec<f64> = p.adjusted.iter().map(|a| a.to_degrees()).collect();
        let n_adjusted = adjusted.len();
        d.set_item("adjusted", arrays::array(py, adjusted, &[n_adjusted])?)?;
        let warnings = PyList::empty(py);
        for w in &p.warnings {
            let item = PyDict::new(py);
            item.set_item("pose", w.pose)?;
            if let Some(line) = w.line {
                item.set_item("line", line)?;
            }
            item.set_item("reason", w.message.reason)?;
            item.set_item("args", to_python(py, &ruledlab::Args(w.message.args.clone()))?)?;
            item.set_item("message", w.text())?;
            warnings.append(item)?;
        }
        d.set_item("warnings", warnings)?;
        d.set_item("stock", p.stock.map(|c| c.map(|x| x / u)).map(|c| c.to_vec()).to_vec())?;
        if let (Some(v), Some(target)) = (&p.deviation, &o.target) {
            let e = PyDict::new(py);
            e.set_item("gouge", v.gouge / u)?;
            e.set_item("leave", v.leave / u)?;
            e.set_item("rms", v.rms / u)?;
            e.set_item("at", arrays::array(py, (target[v.worst] * o.scale).to_array().to_vec(), &[3])?)?;
            e.set_item("largest", v.largest() / u)?;
            e.set_item("worst", v.worst)?;
            e.set_item("pose", v.at[v.worst])?;
            let n = v.points.len();
            e.set_item("points", arrays::array(py, v.points.iter().map(|x| x / u).collect(), &[n])?)?;
            d.set_item("deviation", e)?;
        }
        Ok(d)
    }
}
