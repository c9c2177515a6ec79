//! Tool paths for JavaScript (Example 6, Figs. 16–18): `ToolPath`.

use super::args::{self, fail, fail_option, finite_option, numbers, to_js};
use super::live::Live;
use super::timing::Measure;
use crate::error::Error;
use crate::milling::{self, example, machine, post, quality};
use crate::ruled::surface::points_from_flat;
use crate::ruled::RuledSurface;
use crate::tolerance::{MAX_EXAMPLE_POSES, MAX_SAMPLES};
use glam::DVec3;
use js_sys::{Float32Array, Float64Array};
use serde::{Deserialize, Serialize};
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// A 5-axis tool path: poses (tip, unit axis) and the tool following them.
#[wasm_bindgen]
pub struct ToolPath {
    inner: milling::ToolPath,
    _live: Live,
}

impl ToolPath {
    /// The axis segments tip → tip + L·axis, 6 numbers per pose.
    fn axis_coords(&self) -> Vec<f64> {
        let length = self.inner.tool.length;
        self.inner.poses.iter().flat_map(|p| [p.tip, p.tip + length * p.axis]).flat_map(|q| q.to_array()).collect()
    }

    /// The core path.
    pub fn core(&self) -> &milling::ToolPath {
        &self.inner
    }
}

/// A milling tool: a cylinder of `radius` and `length` (model units), flat or ball end.
#[derive(Deserialize, Tsify)]
struct ToolOptions {
    #[tsify(type = "number")]
    radius: Option<f64>,
    #[tsify(type = "number")]
    length: Option<f64>,
    /// The cutting end (default "ball").
    #[serde(default)]
    #[tsify(optional)]
    end: Option<ToolEndName>,
}

/// A path's tool as `ToolPath.tool` gives it (and `ToolPath.fromSegments` takes it back).
#[derive(Serialize, Tsify)]
struct ToolSpec {
    /// Radius, model units.
    radius: f64,
    /// Length along the axis, model units (a pose's axis segment is this long).
    length: f64,
    /// The cutting end.
    end: ToolEndName,
}

/// The end of a milling tool.
#[derive(Deserialize, Serialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"ball\" or \"flat\"")]
enum ToolEndName {
    /// A ball end: the tool cuts along a sphere of its radius.
    Ball,
    /// A flat end: the tool cuts along the disk of its end.
    Flat,
}

/// Options of `ToolPath.export("gcode", …)` and `ToolPath.post`: the controller, the machine,
/// the feeds and the safe moves (README, "For CAM"). Every option is optional.
#[derive(Deserialize, Default, Tsify)]
#[serde(default, rename_all = "camelCase")]
struct GcodeOptions {
    /// The controller's language: "linuxcnc" (default; rs274ngc), "heidenhain" (TNC Klartext)
    /// or "sinumerik" (Siemens 840D).
    #[tsify(optional)]
    dialect: Option<DialectName>,
    /// "machine" (default): X Y Z are machine coordinates computed with the machine's pivots and
    /// offsets (work offset 0); "tcp": tool-centre point, the controller does the kinematics
    /// (FUNCTION TCPM, TRAORI, a TCP kinematics on LinuxCNC), X Y Z the tip in part coordinates.
    #[tsify(optional)]
    mode: Option<ModeName>,
    /// A preset's name (default "table-table-ac") or a machine description (`Machine`).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(
        type = "\"table-table-ac\" | \"table-table-bc\" | \"head-table-bc\" | \"head-head-ac\" | Machine",
        optional
    )]
    machine: JsValue,
    /// Feed at the tool tip, mm/min (default 1000); blocks that turn a rotary axis get inverse
    /// time (G93) so that the tip keeps it.
    #[tsify(optional)]
    feed: Option<f64>,
    /// Feed of the approach and retract along the tool axis, mm/min (default feed / 4).
    #[tsify(optional)]
    approach_feed: Option<f64>,
    /// Millimetres per model unit (default 1).
    #[tsify(optional)]
    scale: Option<f64>,
    /// Tool number, 1–99999 (default 1): T…, its length offset (G43 H…, D1, TOOL CALL).
    #[tsify(optional)]
    tool: Option<f64>,
    /// Spindle speed, 1/min (default 10000).
    #[tsify(optional)]
    spindle: Option<f64>,
    /// "flood" (default, M8), "mist" (M7) or "off".
    #[tsify(optional)]
    coolant: Option<CoolantName>,
    /// Work offset 1–6: G54–G59 (Sinumerik G54–G57, G505, G506; Heidenhain datum 1–6; default 1).
    #[tsify(optional)]
    work_offset: Option<f64>,
    /// Part height (mm above the part's zero) of the points on the first and last tool axes where
    /// the safe moves turn (default 25 mm above the highest tip plus the clearance).
    #[tsify(optional)]
    safe_height: Option<f64>,
    /// Distance along the tool axis covered at the approach feed, mm (default 5).
    #[tsify(optional)]
    clearance: Option<f64>,
    /// Largest deviation of the controller's linear interpolation from the path, mm (default
    /// 0.01): blocks beyond it are halved.
    #[tsify(optional)]
    tolerance: Option<f64>,
    /// Program name (Heidenhain, Sinumerik): letters, digits, _ (default "RULEDLAB").
    #[tsify(optional)]
    name: Option<String>,
}

/// The controller's language.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"linuxcnc\", \"heidenhain\" or \"sinumerik\"")]
enum DialectName {
    /// LinuxCNC (rs274ngc).
    Linuxcnc,
    /// Heidenhain TNC plain text.
    Heidenhain,
    /// Siemens Sinumerik 840D.
    Sinumerik,
}

/// Who does the kinematics.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"tcp\" or \"machine\"")]
enum ModeName {
    /// The controller (tool-centre point).
    Tcp,
    /// ruledlab (machine coordinates).
    Machine,
}

/// The coolant of the cut.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"flood\", \"mist\" or \"off\"")]
enum CoolantName {
    /// M8.
    Flood,
    /// M7.
    Mist,
    /// None.
    Off,
}

/// The deviations of one kind, mm.
#[derive(Serialize, Tsify)]
struct Deviation {
    /// Of the tool tip from the chord between two poses.
    tip: f64,
    /// Of the tool axis from the great-circle arc, times the tool length.
    axis: f64,
}

/// A G-code program with what the post did: `ToolPath.post`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
struct PostResult {
    /// The program.
    text: String,
    /// Poses of the cut: the path's and the inserted ones.
    poses: usize,
    /// Poses the linearisation inserted.
    inserted: usize,
    /// The tolerance, mm.
    tolerance: f64,
    /// The largest deviations before inserting poses.
    before: Deviation,
    /// The largest deviations of the program.
    after: Deviation,
    /// Per block of the program: the tip's deviation, mm.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    block_tip: Float64Array,
    /// Per block: the axis's deviation times the tool length, mm.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    block_axis: Float64Array,
    /// Per pose of the program: where it lies on the path (k + s between poses k and k + 1).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    origin: Float64Array,
}

/// Tool poses read by `importToolPoses`.
#[derive(Serialize, Tsify)]
struct ImportedPoses {
    /// Tips, 3 numbers per pose.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    tips: Float64Array,
    /// Unit axes, 3 numbers per pose.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    axes: Float64Array,
    /// Tip and unit axis, 6 numbers per pose (what `ToolPath.fromPoses` reads).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    poses: Float64Array,
    /// The tool, where the file names one (ruledlab's own files).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    tool: Option<ToolOut>,
}

/// A tool as a file names it.
#[derive(Serialize, Tsify)]
struct ToolOut {
    radius: f64,
    length: f64,
    /// "ball" or "flat".
    #[tsify(type = "\"ball\" | \"flat\"")]
    end: &'static str,
}

fn preset(func: &str, name: &str) -> Result<machine::Machine, JsValue> {
    machine::Machine::preset(name).ok_or_else(|| {
        let known: Vec<String> = machine::PRESETS.iter().map(|p| format!("\"{p}\"")).collect();
        fail_option(func, "machine", format!("machine: unknown preset \"{name}\", expected {}", known.join(", ")))
    })
}

fn read_post_options(func: &'static str, options: JsValue) -> Result<post::PostOptions, JsValue> {
    let o: GcodeOptions = args::options(func, options)?;
    let d = post::PostOptions::default();
    let machine = if o.machine.is_undefined() || o.machine.is_null() {
        d.machine.clone()
    } else if let Some(name) = o.machine.as_string() {
        preset(func, &name)?
    } else {
        // arrays where arrays belong (serde-wasm-bindgen would say "Reflect.get called on non-object")
        let array = |v: &JsValue, key: &str, path: &str| -> Result<(), JsValue> {
            let inner = js_sys::Reflect::get(v, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED);
            if inner.is_undefined() || js_sys::Array::is_array(&inner) {
                Ok(())
            } else {
                Err(fail_option(func, path, format!("{path} must be an array, got {}", args::describe(&inner))))
            }
        };
        if o.machine.is_object() {
            for key in ["rotary", "travel", "partZero"] {
                array(&o.machine, key, &format!("machine.{key}"))?;
            }
            let rotary = js_sys::Reflect::get(&o.machine, &JsValue::from_str("rotary")).unwrap_or(JsValue::UNDEFINED);
            if js_sys::Array::is_array(&rotary) {
                for (k, axis) in js_sys::Array::from(&rotary).iter().enumerate() {
                    if axis.is_object() {
                        array(&axis, "pivot", &format!("machine.rotary[{k}].pivot"))?;
                    }
                }
            }
        }
        args::required(func, "machine", o.machine.clone(), &[])?
    };
    let integer = |name: &'static str, v: Option<f64>, default: u32| -> Result<u32, JsValue> {
        match finite_option(func, name, v)? {
            None => Ok(default),
            Some(x) if x.fract() == 0.0 && (0.0..=1e9).contains(&x) => Ok(x as u32),
            Some(x) => Err(fail_option(func, name, format!("{name}: must be an integer, got {x}"))),
        }
    };
    Ok(post::PostOptions {
        dialect: match o.dialect {
            None | Some(DialectName::Linuxcnc) => post::Dialect::LinuxCnc,
            Some(DialectName::Heidenhain) => post::Dialect::Heidenhain,
            Some(DialectName::Sinumerik) => post::Dialect::Sinumerik,
        },
        mode: match o.mode {
            None | Some(ModeName::Machine) => post::Mode::Machine,
            Some(ModeName::Tcp) => post::Mode::Tcp,
        },
        machine,
        feed: finite_option(func, "feed", o.feed)?.unwrap_or(d.feed),
        approach_feed: finite_option(func, "approachFeed", o.approach_feed)?,
        scale: finite_option(func, "scale", o.scale)?.unwrap_or(d.scale),
        tool: integer("tool", o.tool, d.tool)?,
        spindle: finite_option(func, "spindle", o.spindle)?.unwrap_or(d.spindle),
        coolant: match o.coolant {
            None | Some(CoolantName::Flood) => post::Coolant::Flood,
            Some(CoolantName::Mist) => post::Coolant::Mist,
            Some(CoolantName::Off) => post::Coolant::Off,
        },
        work_offset: integer("workOffset", o.work_offset, d.work_offset)?,
        safe_height: finite_option(func, "safeHeight", o.safe_height)?,
        clearance: finite_option(func, "clearance", o.clearance)?.unwrap_or(d.clearance),
        tolerance: finite_option(func, "tolerance", o.tolerance)?.unwrap_or(d.tolerance),
        name: o.name.unwrap_or(d.name),
    })
}

/// Orientation smoothness of a tool path.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
struct PathQuality {
    /// Angle between consecutive axes (radians).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    angle_step: Float64Array,
    /// |a_{k−1} − 2a_k + a_{k+1}| per interior pose.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    second_difference: Float64Array,
    max_angle_step: f64,
    max_second_difference: f64,
}

fn read_tool(func: &'static str, tool: JsValue) -> Result<milling::Tool, JsValue> {
    if tool.is_undefined() || tool.is_null() {
        return Err(fail(func, "tool is required: { radius, length, end? }"));
    }
    let o: ToolOptions = args::required(func, "tool", tool, &[])?;
    let radius = finite_option(func, "radius", o.radius)?
        .ok_or_else(|| fail_option(func, "radius", "tool.radius (the tool radius) is required"))?;
    let length = finite_option(func, "length", o.length)?
        .ok_or_else(|| fail_option(func, "length", "tool.length (the tool length) is required"))?;
    let end = match o.end.unwrap_or(ToolEndName::Ball) {
        ToolEndName::Ball => milling::ToolEnd::Ball,
        ToolEndName::Flat => milling::ToolEnd::Flat,
    };
    milling::Tool::new(radius, length, end).map_err(|e| fail(func, e))
}

fn flat(points: &[DVec3]) -> Float64Array {
    Float64Array::from(bytemuck::cast_slice::<_, f64>(points))
}

#[wasm_bindgen]
impl ToolPath {
    /// A path from 6 numbers per pose: the tool tip, then any point further along the axis
    /// (the axis direction is tip → point). Throws for zero-length axes, non-finite numbers,
    /// fewer than 2 poses or a bad tool (radius or length ≤ 0).
    #[wasm_bindgen(js_name = fromSegments)]
    pub fn from_segments(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] coords: JsValue,
        #[wasm_bindgen(unchecked_param_type = "ToolOptions")] tool: JsValue,
    ) -> Result<ToolPath, JsValue> {
        const F: &str = "ToolPath.fromSegments";
        let coords = numbers(F, "coords", &coords)?;
        let tool = read_tool(F, tool)?;
        let axes = RuledSurface::from_flat(&coords).map_err(|e| match e {
            Error::ZeroLength { ruling } => {
                fail(F, format!("tool axis {ruling} has zero length (tip and axis point coincide)"))
            }
            other => fail(F, other),
        })?;
        Ok(ToolPath { inner: milling::ToolPath::from_surface(&axes, tool), _live: Live::new() })
    }

    /// The built-in path of Figs. 16–18 with `count` given poses (default 7).
    pub fn example(
        #[wasm_bindgen(unchecked_optional_param_type = "number")] count: JsValue,
    ) -> Result<ToolPath, JsValue> {
        let count = args::optional_integer("ToolPath.example", "count", &count, 2, MAX_EXAMPLE_POSES, 7)?;
        example::example(count)
            .map(|inner| ToolPath { inner, _live: Live::new() })
            .map_err(|e| fail("ToolPath.example", e))
    }

    /// The example's target profile γ, `count` points (3 numbers each).
    #[wasm_bindgen(js_name = exampleProfile)]
    pub fn example_profile(
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
    ) -> Result<Float64Array, JsValue> {
        let count = super::args::integer("ToolPath.exampleProfile", "count", &count, 2, MAX_SAMPLES)?;
        Ok(flat(&example::profile(count)))
    }

    /// Number of poses.
    #[wasm_bindgen(getter)]
    pub fn length(&self) -> usize {
        self.inner.poses.len()
    }

    /// The tool: `{ radius, length, end }`, as `ToolPath.fromSegments` takes it (the same tool
    /// along other poses).
    #[wasm_bindgen(getter, unchecked_return_type = "ToolSpec")]
    pub fn tool(&self) -> Result<JsValue, JsValue> {
        let t = self.inner.tool;
        let end = match t.end {
            milling::ToolEnd::Ball => ToolEndName::Ball,
            milling::ToolEnd::Flat => ToolEndName::Flat,
        };
        to_js("ToolPath.tool", &ToolSpec { radius: t.radius, length: t.length, end })
    }

    /// The refined path: `steps` steps of a strip scheme on the axis surface (options as for
    /// `RuledSurface.subdivide`; scheme defaults to "variational").
    pub fn refine(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "Partial<SubdivideOptions>")] options: JsValue,
    ) -> Result<ToolPath, JsValue> {
        const F: &str = "ToolPath.refine";
        let _measure = Measure::start(F);
        let (scheme, closed, steps, space) = super::subdivision::read(F, options, Some("variational"))?;
        if !matches!(space, super::subdivision::Space::Points) {
            return Err(fail(F, "options.space: a tool path is refined through its tips and axes (space \"points\")"));
        }
        if closed {
            return Err(fail(F, "a tool path is open: options.closed must be false"));
        }
        self.inner.refine(scheme, steps).map(|inner| ToolPath { inner, _live: Live::new() }).map_err(|e| fail(F, e))
    }

    /// Tool tips, 3 numbers per pose.
    pub fn tips(&self) -> Float64Array {
        let t: Vec<DVec3> = self.inner.poses.iter().map(|p| p.tip).collect();
        flat(&t)
    }

    /// Unit axes, 3 numbers per pose.
    pub fn axes(&self) -> Float64Array {
        let a: Vec<DVec3> = self.inner.poses.iter().map(|p| p.axis).collect();
        flat(&a)
    }

    /// Axis segments tip → tip + L·axis, 6 numbers per pose.
    pub fn segments(&self) -> Float64Array {
        Float64Array::from(&self.axis_coords()[..])
    }

    /// Axis segments tip → tip + L·axis (6 numbers per pose) as 32-bit floats for WebGL.
    #[wasm_bindgen(js_name = segmentsF32)]
    pub fn segments_f32(&self) -> Float32Array {
        let v: Vec<f32> = self.axis_coords().into_iter().map(|x| x as f32).collect();
        Float32Array::from(&v[..])
    }

    /// The barycentre curve (Fig. 16): tip + (L/2)·axis per pose.
    pub fn barycentres(&self) -> Float64Array {
        flat(&self.inner.barycentres())
    }

    /// Ball centres (ball end) or disk centres (flat end): the machined surface is the
    /// envelope of the tool about these.
    #[wasm_bindgen(js_name = cuttingCentres)]
    pub fn cutting_centres(&self) -> Float64Array {
        flat(&self.inner.cutting_centres())
    }

    /// Orientation smoothness: axis angle per step and its second difference.
    #[wasm_bindgen(unchecked_return_type = "PathQuality")]
    pub fn quality(&self) -> Result<JsValue, JsValue> {
        let _measure = Measure::start("ToolPath.quality");
        let q = quality::Quality::of(&self.inner);
        to_js(
            "ToolPath.quality",
            &PathQuality {
                angle_step: Float64Array::from(&q.angle_step[..]),
                second_difference: Float64Array::from(&q.second_difference[..]),
                max_angle_step: q.max_angle_step(),
                max_second_difference: q.max_second_difference(),
            },
        )
    }

    /// Signed deviation of each target point (3 numbers each) from the surface the tool leaves
    /// (> 0: material left, < 0: gouge).
    pub fn deviation(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] targets: JsValue,
    ) -> Result<Float64Array, JsValue> {
        const F: &str = "ToolPath.deviation";
        let _measure = Measure::start(F);
        let t = points_from_flat(&numbers(F, "targets", &targets)?).map_err(|e| fail(F, e))?;
        Ok(Float64Array::from(&quality::deviation(&self.inner, &t)[..]))
    }

    /// The path as text: "json" or "csv" (poses, full precision), or "gcode": a program for a
    /// five-axis controller (see `GcodeOptions`; what it assumes in the file's header and the
    /// README's "For CAM").
    pub fn export(
        &self,
        #[wasm_bindgen(unchecked_param_type = "\"json\" | \"csv\" | \"gcode\"")] format: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "GcodeOptions")] options: JsValue,
    ) -> Result<String, JsValue> {
        const F: &str = "ToolPath.export";
        let format = format.as_string().unwrap_or_default();
        match format.as_str() {
            "json" | "csv" if !(options.is_undefined() || options.is_null()) => {
                Err(fail(F, "the options (feed, scale, machine, …) apply to the \"gcode\" format only"))
            }
            "json" => Ok(crate::io::toolpath::write_json(&self.inner)),
            "csv" => Ok(crate::io::toolpath::write_csv(&self.inner)),
            "gcode" => {
                let o = read_post_options(F, options)?;
                post::program(&self.inner, &o).map(|p| p.text).map_err(|e| fail(F, e))
            }
            _ => Err(fail(F, format!("format must be \"json\", \"csv\" or \"gcode\", got \"{format}\""))),
        }
    }

    /// The G-code program (as `export("gcode", options)`) with what the post did: the poses it
    /// inserted and the deviation of every block from the path (the linearisation check).
    #[wasm_bindgen(unchecked_return_type = "PostResult")]
    pub fn post(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "GcodeOptions")] options: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "ToolPath.post";
        let _measure = Measure::start(F);
        let o = read_post_options(F, options)?;
        let p = post::program(&self.inner, &o).map_err(|e| fail(F, e))?;
        let l = &p.linearisation;
        let tip: Vec<f64> = l.blocks.iter().map(|b| b.tip).collect();
        let axis: Vec<f64> = l.blocks.iter().map(|b| b.axis).collect();
        to_js(
            F,
            &PostResult {
                text: p.text,
                poses: p.poses.len(),
                inserted: l.inserted,
                tolerance: l.tolerance,
                before: Deviation { tip: l.before.tip, axis: l.before.axis },
                after: Deviation { tip: l.after.tip, axis: l.after.axis },
                block_tip: Float64Array::from(&tip[..]),
                block_axis: Float64Array::from(&axis[..]),
                origin: Float64Array::from(&p.origin[..]),
            },
        )
    }

    /// A preset machine's description (`Machine`, the JSON a custom machine is written in):
    /// "table-table-ac", "table-table-bc", "head-table-bc" or "head-head-ac".
    #[wasm_bindgen(unchecked_return_type = "Machine")]
    pub fn machine(
        #[wasm_bindgen(
            unchecked_param_type = "\"table-table-ac\" | \"table-table-bc\" | \"head-table-bc\" | \"head-head-ac\""
        )]
        name: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "ToolPath.machine";
        let name = name.as_string().ok_or_else(|| fail(F, "name must be a string: a preset's name"))?;
        to_js(F, &preset(F, &name)?)
    }

    /// A path from 6 numbers per pose: the tip x, y, z and the axis i, j, k (pointing into the
    /// spindle; it need not be a unit vector, a unit one is kept bit for bit), and a tool. Throws
    /// for zero axes, non-finite numbers or fewer than 2 poses.
    #[wasm_bindgen(js_name = fromPoses)]
    pub fn from_poses(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] poses: JsValue,
        #[wasm_bindgen(unchecked_param_type = "ToolOptions")] tool: JsValue,
    ) -> Result<ToolPath, JsValue> {
        const F: &str = "ToolPath.fromPoses";
        let _measure = Measure::start(F);
        let rows = numbers(F, "poses", &poses)?;
        let tool = read_tool(F, tool)?;
        if rows.len() % 6 != 0 {
            return Err(fail(F, Error::BadLength { what: "poses", len: rows.len(), multiple: 6 }));
        }
        let points = points_from_flat(&rows).map_err(|e| fail(F, e))?;
        if points.len() < 4 {
            return Err(fail(F, Error::TooFew { what: "poses", got: points.len() / 2, min: 2 }));
        }
        let mut out = Vec::with_capacity(points.len() / 2);
        for (k, pair) in points.chunks_exact(2).enumerate() {
            let (t, a) = (pair[0], pair[1]);
            let n = a.length();
            if !(n > 0.0 && (a / n).is_finite()) {
                return Err(fail(F, format!("tool axis {k} has zero length")));
            }
            let axis = if (a.length_squared() - 1.0).abs() < 1e-15 { a } else { a / n };
            out.push(milling::Pose { tip: t, axis });
        }
        Ok(ToolPath { inner: milling::ToolPath { poses: out, tool }, _live: Live::new() })
    }

    /// Per pose: the distance of its cutting centre from the target polyline (3 numbers per
    /// point) minus the tool radius (> 0 material left, < 0 a gouge): the deviation along the path.
    #[wasm_bindgen(js_name = deviationPerPose)]
    pub fn deviation_per_pose(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] targets: JsValue,
    ) -> Result<Float64Array, JsValue> {
        const F: &str = "ToolPath.deviationPerPose";
        let t = points_from_flat(&numbers(F, "targets", &targets)?).map_err(|e| fail(F, e))?;
        if t.len() < 2 {
            return Err(fail(F, Error::TooFew { what: "target points", got: t.len(), min: 2 }));
        }
        Ok(Float64Array::from(&quality::deviation_per_pose(&self.inner, &t)[..]))
    }
}

/// Reads tool poses from CSV (tip x, y, z, axis i, j, k per row) or JSON (`{ poses: [{ tip,
/// axis }], tool? }`), ruledlab's own tool-path files included (with their tool). `format`
/// defaults to JSON when the text starts with `[` or `{`, else CSV.
#[wasm_bindgen(js_name = importToolPoses, unchecked_return_type = "ImportedPoses")]
pub fn import_tool_poses(
    #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "\"csv\" | \"json\"")] format: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "importToolPoses";
    let _measure = Measure::start(F);
    let Some(text) = text.as_string() else {
        return Err(fail(F, format!("text must be a string, got {}", args::describe(&text))));
    };
    let json = match format.as_string().as_deref() {
        None if format.is_undefined() || format.is_null() => text.trim_start().starts_with(['[', '{']),
        Some("json") => true,
        Some("csv") => false,
        _ => return Err(fail(F, format!("format must be \"csv\" or \"json\", got {}", args::describe(&format)))),
    };
    let number = |t: &str| js_sys::parse_float(t);
    let p = crate::io::toolpath::read_poses(&text, json, &number).map_err(|e| fail(F, e))?;
    let tool = p.tool.map(|t| ToolOut {
        radius: t.radius,
        length: t.length,
        end: match t.end {
            milling::ToolEnd::Ball => "ball",
            milling::ToolEnd::Flat => "flat",
        },
    });
    let poses: Vec<DVec3> = p.tips.iter().zip(&p.axes).flat_map(|(&t, &a)| [t, a]).collect();
    to_js(F, &ImportedPoses { tips: flat(&p.tips), axes: flat(&p.axes), poses: flat(&poses), tool })
}

/// What an imported text holds: "poses" (tool poses: JSON with poses or tips, CSV from
/// ruledlab's tool-path export or with a tip/axis header) or "segments".
#[wasm_bindgen(js_name = detectImport, unchecked_return_type = "\"poses\" | \"segments\"")]
pub fn detect_import(#[wasm_bindgen(unchecked_param_type = "string")] text: JsValue) -> Result<String, JsValue> {
    let Some(text) = text.as_string() else {
        return Err(fail("detectImport", format!("text must be a string, got {}", args::describe(&text))));
    };
    Ok(if crate::io::toolpath::looks_like_poses(&text) { "poses" } else { "segments" }.to_string())
}
