//! Conversions of the core's geometry into typed arrays for JavaScript: f32 buffers for WebGL
//! (6 numbers per segment, 3 per point, indexed triangle meshes) and points as f64. The page
//! uploads them as they are. No JS class.

use super::args::to_js;
use glam::DVec3;
use js_sys::{Float32Array, Float64Array, Uint32Array};
use ruledlab::Mesh;
use ruledlab::Segment;
use wasm_bindgen::prelude::*;

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

/// An indexed triangle mesh for WebGL: 3 floats per vertex, 3 indices per triangle.
#[derive(serde::Serialize, tsify_next::Tsify)]
pub struct MeshBuffers {
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    positions: Float32Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Uint32Array")]
    indices: Uint32Array,
}

/// A mesh as `{ positions, indices }`.
pub fn mesh_buffers(func: &str, mesh: &Mesh) -> Result<JsValue, JsValue> {
    to_js(func, &MeshBuffers { positions: points_f32(&mesh.positions), indices: Uint32Array::from(&mesh.indices[..]) })
}

/// Points as f64, 3 per point.
pub fn points_f64(points: &[DVec3]) -> Float64Array {
    Float64Array::from(bytemuck::cast_slice::<_, f64>(points))
}
