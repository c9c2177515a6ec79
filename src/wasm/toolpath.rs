//! Tool paths for JavaScript (Example 6, Figs. 16–18): `ToolPath`.

use super::args::{fail, numbers, ObjectBuilder, Options};
use super::live::Live;
use crate::error::Error;
use crate::milling::{self, example, export, quality};
use crate::ruled::surface::points_from_flat;
use crate::ruled::RuledSurface;
use glam::DVec3;
use js_sys::{Float32Array, Float64Array};
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** A milling tool: a cylinder of `radius` and `length` (model units), flat or ball end (default "ball"). */
export interface ToolOptions { radius: number; length: number; end?: "ball" | "flat" }

/** Options of `ToolPath.export`: G-code only. */
export interface ExportOptions {
  /** Feed rate, mm/min (default 1000). */
  feed?: number;
  /** Millimetres per model unit (default 1). */
  scale?: number;
  /** Clearance above the highest point of the path for the safe moves, mm (default 5). */
  clearance?: number;
}

/** Orientation smoothness of a tool path. */
export interface PathQuality {
  /** Angle between consecutive axes (radians). */
  angleStep: Float64Array;
  /** |a_{k−1} − 2a_k + a_{k+1}| per interior pose. */
  secondDifference: Float64Array;
  maxAngleStep: number;
  maxSecondDifference: number;
}
"#;

/// A 5-axis tool path: poses (tip, unit axis) and the tool following them.
#[wasm_bindgen]
pub struct ToolPath {
    inner: milling::ToolPath,
    _live: Live,
}

impl ToolPath {
    /// The core path.
    pub fn core(&self) -> &milling::ToolPath {
        &self.inner
    }
}

fn read_tool(func: &'static str, tool: JsValue) -> Result<milling::Tool, JsValue> {
    if tool.is_undefined() || tool.is_null() {
        return Err(fail(func, "tool is required: { radius, length, end? }"));
    }
    let o = Options::new(func, tool, &["radius", "length", "end"])?;
    let radius = o.number("radius")?.ok_or_else(|| fail(func, "options.radius (the tool radius) is required"))?;
    let length = o.number("length")?.ok_or_else(|| fail(func, "options.length (the tool length) is required"))?;
    let end = match o.string("end")?.as_deref() {
        None | Some("ball") => milling::ToolEnd::Ball,
        Some("flat") => milling::ToolEnd::Flat,
        Some(other) => return Err(fail(func, format!("options.end must be \"ball\" or \"flat\", got \"{other}\""))),
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
    pub fn example(count: Option<f64>) -> Result<ToolPath, JsValue> {
        let count = super::args::integer("ToolPath.example", "count", count.unwrap_or(7.0), 2, 1000)?;
        example::example(count)
            .map(|inner| ToolPath { inner, _live: Live::new() })
            .map_err(|e| fail("ToolPath.example", e))
    }

    /// The example's target profile γ, `count` points (3 numbers each).
    #[wasm_bindgen(js_name = exampleProfile)]
    pub fn example_profile(count: f64) -> Result<Float64Array, JsValue> {
        let count = super::args::integer("ToolPath.exampleProfile", "count", count, 2, 1_000_000)?;
        Ok(flat(&example::profile(count)))
    }

    /// Number of poses.
    #[wasm_bindgen(getter)]
    pub fn length(&self) -> usize {
        self.inner.poses.len()
    }

    /// The refined path: `steps` steps of a strip scheme on the axis surface (options as for
    /// `RuledSurface.subdivide`; scheme defaults to "variational").
    pub fn refine(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Partial<SubdivideOptions> | undefined")] options: JsValue,
    ) -> Result<ToolPath, JsValue> {
        const F: &str = "ToolPath.refine";
        let (scheme, closed, steps, space) = super::subdivide::read(F, options, Some("variational"))?;
        if !matches!(space, super::subdivide::Space::Points) {
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
        let v: Vec<f64> = self
            .inner
            .poses
            .iter()
            .flat_map(|p| {
                let b = p.tip + self.inner.tool.length * p.axis;
                [p.tip.x, p.tip.y, p.tip.z, b.x, b.y, b.z]
            })
            .collect();
        Float64Array::from(&v[..])
    }

    /// Axis segments tip → tip + L·axis (6 numbers per pose) as 32-bit floats for WebGL.
    #[wasm_bindgen(js_name = segmentsF32)]
    pub fn segments_f32(&self) -> Float32Array {
        let v: Vec<f32> = self
            .inner
            .poses
            .iter()
            .flat_map(|p| {
                let b = p.tip + self.inner.tool.length * p.axis;
                [p.tip.x, p.tip.y, p.tip.z, b.x, b.y, b.z]
            })
            .map(|x| x as f32)
            .collect();
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
    pub fn quality(&self) -> JsValue {
        let q = quality::Quality::of(&self.inner);
        ObjectBuilder::new()
            .f64s("angleStep", &q.angle_step)
            .f64s("secondDifference", &q.second_difference)
            .set("maxAngleStep", q.max_angle_step())
            .set("maxSecondDifference", q.max_second_difference())
            .build()
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
    /// A–C machine (see `ExportOptions`; conventions in the file's header).
    pub fn export(
        &self,
        #[wasm_bindgen(unchecked_param_type = "\"json\" | \"csv\" | \"gcode\"")] format: JsValue,
        #[wasm_bindgen(unchecked_param_type = "ExportOptions | undefined")] options: JsValue,
    ) -> Result<String, JsValue> {
        const F: &str = "ToolPath.export";
        let format = format.as_string().unwrap_or_default();
        let o = Options::new(F, options, &["feed", "scale", "clearance"])?;
        if format != "gcode" && ["feed", "scale", "clearance"].iter().any(|k| o.has(k)) {
            return Err(fail(F, "feed, scale and clearance apply to the \"gcode\" format only"));
        }
        match format.as_str() {
            "json" => Ok(export::json(&self.inner)),
            "csv" => Ok(export::csv(&self.inner)),
            "gcode" => {
                let d = export::GcodeOptions::default();
                let g = export::GcodeOptions {
                    feed: o.number("feed")?.unwrap_or(d.feed),
                    scale: o.number("scale")?.unwrap_or(d.scale),
                    clearance: o.number("clearance")?.unwrap_or(d.clearance),
                };
                export::gcode(&self.inner, g).map_err(|e| fail(F, e))
            }
            _ => Err(fail(F, format!("format must be \"json\", \"csv\" or \"gcode\", got \"{format}\""))),
        }
    }
}
