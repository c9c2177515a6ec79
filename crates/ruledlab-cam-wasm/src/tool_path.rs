//! `ToolPath` for JavaScript (Example 6, Figs. 16–18): a 5-axis tool path, its refinement and
//! quality, the meshes and buffers the page draws of it, its G-code programs and its export as
//! data.

use super::gcode_options::{preset, read_post_options};
use ruledlab::Error;
use ruledlab_js::args::{self, fail, fail_option, finite_option, integer, numbers, to_js};
use ruledlab_js::buffers::{self, mesh_buffers, points_f64, Lines};
use ruledlab_js::line_buffers;
use ruledlab_js::live::Live;
use ruledlab_js::subdivide_options::{read, Space};
use ruledlab_js::timing::Measure;
use std::borrow::Cow;

use glam::DVec3;
use js_sys::{Float32Array, Float64Array, Uint8Array};
use ruledlab::points_from_flat;
use ruledlab::tolerance::{MAX_EXAMPLE_POSES, MAX_GRID_SIDE, MAX_MESH_SIDES, MAX_SAMPLES};
use ruledlab::RuledSurface;
use ruledlab::Segment;
use serde::{Deserialize, Serialize};
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

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
    /// The program's units: lengths here are in them.
    #[tsify(type = "\"mm\" | \"inch\"")]
    units: &'static str,
    /// The machine's axes: "X", "Y", "Z", then its two rotary axes' letters.
    letters: Vec<&'static str>,
    /// Per pose of the program: the axes' values as the block arriving there ends, 5 numbers (X, Y,
    /// Z machine positions, then the rotary axes in degrees).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    axes: Float64Array,
    /// Per block: its time, minutes.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    block_minutes: Float64Array,
    /// Per block: the feed at the tool tip it keeps, units/min (below the job's where the axes
    /// slowed it).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    block_feed: Float64Array,
    /// Per block: the rotary axes' speeds, degrees/min, 2 numbers.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    block_rotary_speed: Float64Array,
    /// Per block: what set its time: 0 the feed, 1 an axis's speed limit, 2 an acceleration
    /// limit, 3 the controller's feed word.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Uint8Array")]
    block_limit: Uint8Array,
    /// Blocks still needing more acceleration than an axis has.
    over_acceleration: usize,
    /// The poses of the program where a limited rotary axis unwinds (out, turned, back).
    unwinds: Vec<usize>,
    /// Per pose of the program: how far the pole cone turned its tool axis, degrees.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    adjusted: Float64Array,
    /// What the machinist should know: duplicate poses, flipped axes, blocks slowed, the pole
    /// cone, the holder or shank in the stock.
    warnings: Vec<PostWarning>,
    /// The stock the rapids were checked against: [[xmin, ymin, zmin], [xmax, ymax, zmax]], part
    /// frame, program units.
    stock: [[f64; 3]; 2],
    /// Where the options give a target: its deviation from the sweep of the program as posted
    /// (the tool moved through the blocks as the controller interpolates them), program units.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    deviation: Option<PostDeviation>,
}

/// The deviation of the target from the sweep of the program as posted, program units.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
struct PostDeviation {
    /// The deepest gouge (≤ 0: the least signed distance, 0 where none cuts in).
    gouge: f64,
    /// The most material left (≥ 0).
    leave: f64,
    /// The root mean square of the target points' deviations.
    rms: f64,
    /// Where the largest |deviation| is: the target point (3 numbers, program units, part frame).
    at: [f64; 3],
    /// That deviation.
    largest: f64,
    /// The target point's index.
    worst: usize,
    /// Where along the program's poses the nearest tool is (k + s between poses k and k + 1).
    pose: f64,
    /// Per target point: its signed distance from the sweep (> 0 left, < 0 cut into).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    points: Float64Array,
}

/// A warning of the post, naming the pose (of the input where `input` told its numbering).
#[derive(Serialize, Tsify)]
struct PostWarning {
    /// The pose.
    pose: usize,
    /// Its line in the input file.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    line: Option<usize>,
    /// The stable key of what it is (the page words it in the reader's language).
    reason: &'static str,
    /// The values its text names.
    #[tsify(type = "Record<string, string | number>")]
    args: ruledlab::Args,
    /// In English.
    message: String,
}

/// The deviation of target points from the surface the tool machines: `ToolPath.envelopeDeviation`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
struct EnvelopeResult {
    /// Per target point: its signed distance from the tool's swept solid (> 0 material left, < 0
    /// cut into), model units.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    points: Float64Array,
    /// Per target point: where along the path the nearest tool is (k + s between poses k and k + 1).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    at: Float64Array,
    /// Per pose: the deviation of largest size among the target points nearest it (NaN: none).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    per_pose: Float64Array,
    /// The target point of the largest |deviation|, its index.
    worst: usize,
    /// Its deviation.
    worst_deviation: f64,
    /// The point itself, 3 numbers.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    worst_point: Float64Array,
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

fn read_tool(func: &'static str, tool: JsValue) -> Result<ruledlab_cam::Tool, JsValue> {
    if tool.is_undefined() || tool.is_null() {
        return Err(fail(func, "tool is required: { radius, length, end? }"));
    }
    let o: ToolOptions = args::required(func, "tool", tool, &[])?;
    let radius = finite_option(func, "radius", o.radius)?
        .ok_or_else(|| fail_option(func, "radius", "tool.radius (the tool radius) is required"))?;
    let length = finite_option(func, "length", o.length)?
        .ok_or_else(|| fail_option(func, "length", "tool.length (the tool length) is required"))?;
    let end = match o.end.unwrap_or(ToolEndName::Ball) {
        ToolEndName::Ball => ruledlab_cam::ToolEnd::Ball,
        ToolEndName::Flat => ruledlab_cam::ToolEnd::Flat,
    };
    ruledlab_cam::Tool::new(radius, length, end).map_err(|e| fail(func, e))
}

/// A 5-axis tool path: poses (tip, unit axis) and the tool following them.
#[wasm_bindgen]
pub struct ToolPath {
    inner: ruledlab_cam::ToolPath,
    _live: Live,
}

impl ToolPath {
    /// The axis segments tip → tip + L·axis, 6 numbers per pose.
    fn axis_coords(&self) -> Vec<f64> {
        let length = self.inner.tool.length;
        self.inner.poses.iter().flat_map(|p| [p.tip, p.tip + length * p.axis]).flat_map(|q| q.to_array()).collect()
    }

    /// The core path.
    pub fn core(&self) -> &ruledlab_cam::ToolPath {
        &self.inner
    }
}

#[wasm_bindgen]
impl ToolPath {
    // --- making one, and the built-in example

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
        Ok(ToolPath { inner: ruledlab_cam::ToolPath::from_surface(&axes, tool), _live: Live::new() })
    }

    /// The ruling-aligned poses of a flank cut of a part's rulings (6 numbers each, foot then
    /// end): the tool's axis along each ruling, its tip the foot moved by the tool's radius along
    /// the surface's unit normal at the ruling's midpoint, on the side `side` (+1 or −1) says; the
    /// start `optimisePoses` improves. Throws for zero-length rulings, non-finite numbers, fewer
    /// than 2 rulings, a bad tool or a side other than ±1.
    #[wasm_bindgen(js_name = rulingAligned)]
    pub fn ruling_aligned(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] rulings: JsValue,
        #[wasm_bindgen(unchecked_param_type = "ToolOptions")] tool: JsValue,
        #[wasm_bindgen(unchecked_param_type = "1 | -1")] side: JsValue,
    ) -> Result<ToolPath, JsValue> {
        const F: &str = "ToolPath.rulingAligned";
        let _measure = Measure::start(F);
        let coords = numbers(F, "rulings", &rulings)?;
        let tool = read_tool(F, tool)?;
        let side = args::number(F, "side", &side)?;
        if side != 1.0 && side != -1.0 {
            return Err(fail(F, format!("side must be 1 or -1 (the side of the part the tool stands on), got {side}")));
        }
        let rulings = RuledSurface::from_flat(&coords).map_err(|e| fail(F, e))?;
        Ok(ToolPath { inner: ruledlab_cam::ruling_aligned(&rulings, tool, side), _live: Live::new() })
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
            out.push(ruledlab_cam::Pose { tip: t, axis });
        }
        Ok(ToolPath { inner: ruledlab_cam::ToolPath { poses: out, tool }, _live: Live::new() })
    }

    /// The built-in path of Figs. 16–18 with `count` given poses (default 7), for its tool (a ball
    /// end of radius 0.25 and length 1.5) or for `tool`: its ball touches the profile at every pose.
    pub fn example(
        #[wasm_bindgen(unchecked_optional_param_type = "number")] count: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "ToolOptions")] tool: JsValue,
    ) -> Result<ToolPath, JsValue> {
        const F: &str = "ToolPath.example";
        let count = args::optional_integer(F, "count", &count, 2, MAX_EXAMPLE_POSES, 7)?;
        let made = if tool.is_undefined() || tool.is_null() {
            ruledlab_cam::example_tool_path(count)
        } else {
            ruledlab_cam::example_tool_path_for(count, read_tool(F, tool)?)
        };
        made.map(|inner| ToolPath { inner, _live: Live::new() }).map_err(|e| fail(F, e))
    }

    /// The example's target profile γ, `count` points (3 numbers each).
    #[wasm_bindgen(js_name = exampleProfile)]
    pub fn example_profile(
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
    ) -> Result<Float64Array, JsValue> {
        let count = args::integer("ToolPath.exampleProfile", "count", &count, 2, MAX_SAMPLES)?;
        Ok(points_f64(&ruledlab_cam::example_profile(count)))
    }

    /// The part surface of the built-in example, z = 0.3 sin x cos 0.7y, as an nx × ny grid mesh.
    #[wasm_bindgen(js_name = examplePart, unchecked_return_type = "MeshBuffers")]
    pub fn example_part(
        #[wasm_bindgen(unchecked_param_type = "number")] nx: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] ny: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "ToolPath.examplePart";
        let (nx, ny) = (integer(F, "nx", &nx, 2, MAX_GRID_SIDE)?, integer(F, "ny", &ny, 2, MAX_GRID_SIDE)?);
        mesh_buffers(F, &ruledlab_cam::part_mesh(nx, ny))
    }

    // --- its poses and tool

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
            ruledlab_cam::ToolEnd::Ball => ToolEndName::Ball,
            ruledlab_cam::ToolEnd::Flat => ToolEndName::Flat,
        };
        to_js("ToolPath.tool", &ToolSpec { radius: t.radius, length: t.length, end })
    }

    /// Tool tips, 3 numbers per pose.
    pub fn tips(&self) -> Float64Array {
        let t: Vec<DVec3> = self.inner.poses.iter().map(|p| p.tip).collect();
        points_f64(&t)
    }

    /// Unit axes, 3 numbers per pose.
    pub fn axes(&self) -> Float64Array {
        let a: Vec<DVec3> = self.inner.poses.iter().map(|p| p.axis).collect();
        points_f64(&a)
    }

    /// Axis segments tip → tip + L·axis, 6 numbers per pose.
    pub fn segments(&self) -> Float64Array {
        Float64Array::from(&self.axis_coords()[..])
    }

    /// The barycentre curve (Fig. 16): tip + (L/2)·axis per pose.
    pub fn barycentres(&self) -> Float64Array {
        points_f64(&self.inner.barycentres())
    }

    /// Ball centres (ball end) or disk centres (flat end): the machined surface is the
    /// envelope of the tool about these.
    #[wasm_bindgen(js_name = cuttingCentres)]
    pub fn cutting_centres(&self) -> Float64Array {
        points_f64(&self.inner.cutting_centres())
    }

    // --- refinement and quality (Example 6, Figs. 17 and 18)

    /// The refined path: `steps` steps of a strip scheme on the axis surface (options as for
    /// `RuledSurface.subdivide`; scheme defaults to "variational").
    pub fn refine(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "Partial<SubdivideOptions>")] options: JsValue,
    ) -> Result<ToolPath, JsValue> {
        const F: &str = "ToolPath.refine";
        let _measure = Measure::start(F);
        let (scheme, closed, steps, space) = read(F, options, Some("variational"))?;
        if !matches!(space, Space::Points) {
            return Err(fail(F, "options.space: a tool path is refined through its tips and axes (space \"points\")"));
        }
        if closed {
            return Err(fail(F, "a tool path is open: options.closed must be false"));
        }
        self.inner.refine(scheme, steps).map(|inner| ToolPath { inner, _live: Live::new() }).map_err(|e| fail(F, e))
    }

    /// Orientation smoothness: axis angle per step and its second difference.
    #[wasm_bindgen(unchecked_return_type = "PathQuality")]
    pub fn quality(&self) -> Result<JsValue, JsValue> {
        let _measure = Measure::start("ToolPath.quality");
        let q = ruledlab_cam::Quality::of(&self.inner);
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
        Ok(Float64Array::from(&ruledlab_cam::deviation(&self.inner, &t)[..]))
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
        Ok(Float64Array::from(&ruledlab_cam::deviation_per_pose(&self.inner, &t)[..]))
    }

    /// The deviation of a target curve (3 numbers per point, the edge or contact curve the tool
    /// should machine) from the surface the tool machines: each point's signed distance from the
    /// solid the tool sweeps along the path (ball or flat end, its length; > 0 material left, < 0
    /// cut into), where along the path that is, per pose, and the worst point.
    #[wasm_bindgen(js_name = envelopeDeviation, unchecked_return_type = "EnvelopeResult")]
    pub fn envelope_deviation(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] targets: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "ToolPath.envelopeDeviation";
        let _measure = Measure::start(F);
        let t = points_from_flat(&numbers(F, "targets", &targets)?).map_err(|e| fail(F, e))?;
        if t.is_empty() {
            return Err(fail(F, Error::TooFew { what: "target points", got: 0, min: 1 }));
        }
        let d = ruledlab_cam::envelope_deviation(&self.inner, &t);
        to_js(
            F,
            &EnvelopeResult {
                per_pose: Float64Array::from(&d.per_pose(self.inner.poses.len())[..]),
                worst_deviation: d.points[d.worst],
                worst_point: points_f64(&[t[d.worst]]),
                worst: d.worst,
                points: Float64Array::from(&d.points[..]),
                at: Float64Array::from(&d.at[..]),
            },
        )
    }

    // --- buffers for WebGL (and `segmentsF32()`, `insertedF32(stride)`: `line_buffers!` below)

    /// The axes (tip → tip + L·axis) of every `every`-th pose and the last, as f32 segments: a
    /// level of detail of a path too long to draw whole.
    #[wasm_bindgen(js_name = everyF32)]
    pub fn every_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] every: JsValue,
    ) -> Result<Float32Array, JsValue> {
        let length = self.inner.tool.length;
        buffers::every_f32("ToolPath", "every", &every, self.inner.poses.len(), |i| {
            let p = &self.inner.poses[i];
            Segment::new(p.tip, p.tip + length * p.axis)
        })
    }

    /// The envelope of the tool's cutting end along the path (a tube of the tool radius about
    /// the ball centres; its lower half is the machined surface), `sides` vertices per ring.
    #[wasm_bindgen(js_name = envelopeMesh, unchecked_return_type = "MeshBuffers")]
    pub fn envelope_mesh(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] sides: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "ToolPath.envelopeMesh";
        let sides = integer(F, "sides", &sides, 3, MAX_MESH_SIDES)?;
        mesh_buffers(F, &self.core().envelope_mesh(sides))
    }

    /// The tool body at pose `index` (Fig. 16): a cylinder with its ball or flat end.
    #[wasm_bindgen(js_name = toolMesh, unchecked_return_type = "MeshBuffers")]
    pub fn tool_mesh(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] index: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] sides: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "ToolPath.toolMesh";
        let index = integer(F, "index", &index, 0, self.length().saturating_sub(1))?;
        let sides = integer(F, "sides", &sides, 3, MAX_MESH_SIDES)?;
        match self.core().tool_mesh(index, sides) {
            Some(m) => mesh_buffers(F, &m),
            None => Ok(JsValue::UNDEFINED),
        }
    }

    // --- G-code and data (docs/src/cam/gcode.md)

    /// The path as text: "json" or "csv" (poses, full precision), or "gcode": a program for a
    /// five-axis controller (see `GcodeOptions`; what it assumes is said in the program's header
    /// and in docs/src/cam/gcode.md).
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
            "json" => Ok(ruledlab_cam::tool_path_json(&self.inner)),
            "csv" => Ok(ruledlab_cam::tool_path_csv(&self.inner)),
            "gcode" => {
                let o = read_post_options(F, options)?;
                ruledlab_cam::gcode(&self.inner, &o).map(|p| p.text).map_err(|e| fail(F, e))
            }
            _ => Err(fail(F, format!("format must be \"json\", \"csv\" or \"gcode\", got \"{format}\""))),
        }
    }

    /// The G-code program (as `export("gcode", options)`) with what the post did: the poses it
    /// inserted and the deviation of every block from the path (the linearisation check), the
    /// machine's axes along the path and each block's time, the unwinds, the pole cone, the
    /// warnings. `onProgress(fraction)` is called as the post goes on (a long job's progress).
    #[wasm_bindgen(unchecked_return_type = "PostResult")]
    pub fn post(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "GcodeOptions")] options: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "(fraction: number) => void")] on_progress: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "ToolPath.post";
        let _measure = Measure::start(F);
        let o = read_post_options(F, options)?;
        let mut progress = args::progress_reporter(F, on_progress)?;
        let p = ruledlab_cam::gcode_reporting(&self.inner, &o, &mut progress).map_err(|e| fail(F, e))?;
        let u = o.units.mm();
        let l = &p.linearisation;
        let tip: Vec<f64> = l.blocks.iter().map(|b| b.tip / u).collect();
        let axis: Vec<f64> = l.blocks.iter().map(|b| b.axis / u).collect();
        let axes = p.axis_values(u);
        let minutes: Vec<f64> = p.motion.iter().map(|b| b.minutes).collect();
        let feed = p.block_feeds(u);
        let speeds = p.rotary_speeds();
        let limits: Vec<u8> = p.motion.iter().map(|b| b.limit.code()).collect();
        let adjusted: Vec<f64> = p.adjusted.iter().map(|a| a.to_degrees()).collect();
        let warnings = p
            .warnings
            .iter()
            .map(|w| PostWarning {
                pose: w.pose,
                line: w.line,
                reason: w.message.reason,
                args: ruledlab::Args(w.message.args.clone()),
                message: w.text(),
            })
            .collect();
        let m = &o.machine;
        let deviation = p.deviation.as_ref().map(|d| {
            let q = o.target.as_ref().map_or(DVec3::ZERO, |t| t[d.worst] * o.scale);
            let points: Vec<f64> = d.points.iter().map(|x| x / u).collect();
            PostDeviation {
                gouge: d.gouge / u,
                leave: d.leave / u,
                rms: d.rms / u,
                at: q.to_array(),
                largest: d.largest() / u,
                worst: d.worst,
                pose: d.at[d.worst],
                points: Float64Array::from(&points[..]),
            }
        });
        to_js(
            F,
            &PostResult {
                text: p.text,
                poses: p.poses.len(),
                inserted: l.inserted,
                tolerance: l.tolerance / u,
                before: Deviation { tip: l.before.tip / u, axis: l.before.axis / u },
                after: Deviation { tip: l.after.tip / u, axis: l.after.axis / u },
                block_tip: Float64Array::from(&tip[..]),
                block_axis: Float64Array::from(&axis[..]),
                origin: Float64Array::from(&p.origin[..]),
                units: o.units.word(),
                letters: vec!["X", "Y", "Z", m.rotary[0].name.letter(), m.rotary[1].name.letter()],
                axes: Float64Array::from(&axes[..]),
                block_minutes: Float64Array::from(&minutes[..]),
                block_feed: Float64Array::from(&feed[..]),
                block_rotary_speed: Float64Array::from(&speeds[..]),
                block_limit: Uint8Array::from(&limits[..]),
                over_acceleration: p.motion.iter().filter(|b| b.over).count(),
                unwinds: (0..p.unwound.len()).filter(|&i| p.unwound[i].is_some()).collect(),
                adjusted: Float64Array::from(&adjusted[..]),
                warnings,
                stock: p.stock.map(|c| c.map(|x| x / u)),
                deviation,
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
}

line_buffers!(ToolPath);

impl Lines for ToolPath {
    const CLASS: &'static str = "ToolPath";
    fn coordinates(&self) -> Cow<'_, [f64]> {
        Cow::Owned(self.axis_coords())
    }
    fn inserted(&self, stride: usize) -> ruledlab::Result<Vec<Segment>> {
        Ok(self.core().axis_surface()?.inserted(stride))
    }
}
