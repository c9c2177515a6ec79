//! Conversions of the core's geometry into typed arrays for JavaScript: f32 buffers for WebGL
//! (6 numbers per segment, 3 per point, indexed triangle meshes) and points as f64. The page
//! uploads them as they are. No JS class.
//!
//! The buffer methods every class of lines has (`segmentsF32()`, `insertedF32(stride)`) are
//! written once here: a class says what its lines are ([`Lines`]) and `line_buffers!(Class)`
//! binds both methods to it (wasm-bindgen binds methods class by class, so one macro, not one
//! method per class). What only some classes have (`everyF32(k)`, the ends of some lines) is a
//! function here that each of them calls with its name and its lines.

use super::args::{fail, integer, to_js};
use glam::DVec3;
use js_sys::{Float32Array, Float64Array, Uint32Array};
use ruledlab::tolerance::MAX_STRIDE;
use ruledlab::Mesh;
use ruledlab::Segment;
use std::borrow::Cow;
use wasm_bindgen::prelude::*;

/// Numbers as f32 (`segmentsF32()`: a class's coordinates, 6 per line).
pub fn f32s(values: impl IntoIterator<Item = f64>) -> Float32Array {
    let out: Vec<f32> = values.into_iter().map(|x| x as f32).collect();
    Float32Array::from(&out[..])
}

/// A class of lines, as the buffer methods `line_buffers!` binds see it: a surface's rulings, a
/// congruence's lines, a tool path's axes.
pub trait Lines {
    /// The class's name in JavaScript (its errors say `<CLASS>.insertedF32`).
    const CLASS: &'static str;
    /// Every line's two ends, x y z x y z, in the class's order (borrowed where the class
    /// keeps them so).
    fn coordinates(&self) -> Cow<'_, [f64]>;
    /// The lines whose index is not a multiple of `stride` (of a grid: (i, j) with i or j not
    /// a multiple of it).
    fn inserted(&self, stride: usize) -> ruledlab::Result<Vec<Segment>>;
}

/// `<class>.insertedF32(stride)`: the lines [`Lines::inserted`] gives for a stride from 1 to
/// [`MAX_STRIDE`] (those whose index is not a multiple of it: after k steps of an interpolatory
/// scheme, stride 2^k, the inserted ones), as f32 segments.
pub fn inserted_f32<L: Lines>(lines: &L, stride: &JsValue) -> Result<Float32Array, JsValue> {
    let func = format!("{}.insertedF32", L::CLASS);
    let stride = integer(&func, "stride", stride, 1, MAX_STRIDE)?;
    lines.inserted(stride).map(|lines| segments_f32(&lines)).map_err(|e| fail(&func, e))
}

/// Binds `segmentsF32()` and `insertedF32(stride)` to a class of lines (a type in scope that
/// implements [`Lines`](crate::buffers::Lines) and is a wasm-bindgen class), in a second
/// bound impl block of the crate and file that declare the class.
#[macro_export]
macro_rules! line_buffers {
    ($class:ident) => {
        #[wasm_bindgen::prelude::wasm_bindgen]
        impl $class {
            /// The lines (a surface's rulings, a congruence's lines row by row, a tool path's axes
            /// tip → tip + L·axis) as 32-bit floats for a WebGL buffer, 6 per line.
            #[wasm_bindgen(js_name = segmentsF32)]
            pub fn segments_f32(&self) -> js_sys::Float32Array {
                $crate::buffers::f32s($crate::buffers::Lines::coordinates(self).iter().copied())
            }

            /// The lines whose index is not a multiple of `stride` (of a congruence: (i, j) with i
            /// or j not a multiple of it; after k steps of an interpolatory scheme, stride 2^k:
            /// the inserted lines), as f32 segments.
            #[wasm_bindgen(js_name = insertedF32)]
            pub fn inserted_f32(
                &self,
                #[wasm_bindgen(unchecked_param_type = "number")] stride: wasm_bindgen::JsValue,
            ) -> Result<js_sys::Float32Array, wasm_bindgen::JsValue> {
                $crate::buffers::inserted_f32(self, &stride)
            }
        }
    };
}

/// `<class>.everyF32(k)`: every k-th of `count` lines (indices 0, k, 2k, …) and the last, k from
/// 1 to [`MAX_STRIDE`] (its argument's name `name`), as f32 segments: a level of detail for
/// drawing more lines than a view can show.
pub fn every_f32(
    class: &str,
    name: &str,
    k: &JsValue,
    count: usize,
    line: impl Fn(usize) -> Segment,
) -> Result<Float32Array, JsValue> {
    let k = integer(&format!("{class}.everyF32"), name, k, 1, MAX_STRIDE)?;
    let lines: Vec<Segment> = (0..count).filter(|i| i % k == 0 || i + 1 == count).map(line).collect();
    Ok(segments_f32(&lines))
}

/// The first ends a (`which` = 1) or the second ends b (2) of `lines`, as f32 points.
pub fn ends_f32(lines: &[Segment], which: usize) -> Float32Array {
    let points: Vec<DVec3> = lines.iter().map(|s| if which == 1 { s.a } else { s.b }).collect();
    points_f32(&points)
}

/// Segments as f32, 6 per segment.
pub fn segments_f32(segments: &[Segment]) -> Float32Array {
    let out: Vec<f32> = segments.iter().flat_map(|s| [s.a, s.b]).flat_map(|p| p.to_array()).map(|x| x as f32).collect();
    Float32Array::from(&out[..])
}

/// Points as f32, 3 per point.
pub fn points_f32(points: &[DVec3]) -> Float32Array {
    let out: Vec<f32> = points.iter().flat_map(|p| p.to_array()).map(|x| x as f32).collect();
    Float32Array::from(&out[..])
}

/// An indexed triangle mesh for WebGL: 3 floats per vertex, 3 indices per triangle (a focal
/// sheet adds its normals and box to these fields, `#[serde(flatten)]`).
#[derive(serde::Serialize, tsify_next::Tsify)]
pub struct MeshBuffers {
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    positions: Float32Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Uint32Array")]
    indices: Uint32Array,
}

impl MeshBuffers {
    /// The buffers of `mesh`: positions as f32, indices as u32.
    pub fn of(mesh: &Mesh) -> MeshBuffers {
        MeshBuffers { positions: points_f32(&mesh.positions), indices: Uint32Array::from(&mesh.indices[..]) }
    }
}

/// A mesh as `{ positions, indices }`.
pub fn mesh_buffers(func: &str, mesh: &Mesh) -> Result<JsValue, JsValue> {
    to_js(func, &MeshBuffers::of(mesh))
}

/// Points as f64, 3 per point.
pub fn points_f64(points: &[DVec3]) -> Float64Array {
    Float64Array::from(bytemuck::cast_slice::<_, f64>(points))
}
