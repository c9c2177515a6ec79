//! Tool paths for JavaScript (Example 6, Figs. 16–18): `ToolPath`.

use super::args::{self, fail, fail_option, finite_option, numbers, to_js};
use super::live::Live;
use crate::error::Error;
use crate::milling::{self, example, export, quality};
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

/// Options of `ToolPath.export`: G-code only.
#[derive(Deserialize, Default, Tsify)]
#[serde(default)]
struct GcodeOptions {
    /// Feed rate, mm/min (default 1000).
    feed: Option<f64>,
    /// Millimetres per model unit (default 1).
    scale: Option<f64>,
    /// Clearance above the highest point of the path for the safe moves, mm (default 5).
    clearance: Option<f64>,
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
        let t = points_from_flat(&numbers(F, "targets", &targets)?).map_err(|e| fail(F, e))?;
        Ok(Float64Array::from(&quality::deviation(&self.inner, &t)[..]))
    }

    /// The path as text: "json" or "csv" (poses, full precision), or "gcode" for a table-table
    /// A–C machine (see `GcodeOptions`; conventions in the file's header).
    pub fn export(
        &self,
        #[wasm_bindgen(unchecked_param_type = "\"json\" | \"csv\" | \"gcode\"")] format: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "GcodeOptions")] options: JsValue,
    ) -> Result<String, JsValue> {
        const F: &str = "ToolPath.export";
        let format = format.as_string().unwrap_or_default();
        let o: GcodeOptions = args::options(F, options)?;
        if format != "gcode" && (o.feed.is_some() || o.scale.is_some() || o.clearance.is_some()) {
            return Err(fail(F, "feed, scale and clearance apply to the \"gcode\" format only"));
        }
        match format.as_str() {
            "json" => Ok(crate::io::toolpath::write_json(&self.inner)),
            "csv" => Ok(crate::io::toolpath::write_csv(&self.inner)),
            "gcode" => {
                let d = export::GcodeOptions::default();
                let g = export::GcodeOptions {
                    feed: finite_option(F, "feed", o.feed)?.unwrap_or(d.feed),
                    scale: finite_option(F, "scale", o.scale)?.unwrap_or(d.scale),
                    clearance: finite_option(F, "clearance", o.clearance)?.unwrap_or(d.clearance),
                };
                export::gcode(&self.inner, g).map_err(|e| fail(F, e))
            }
            _ => Err(fail(F, format!("format must be \"json\", \"csv\" or \"gcode\", got \"{format}\""))),
        }
    }
}
