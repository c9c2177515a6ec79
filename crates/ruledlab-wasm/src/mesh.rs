//! Meshes for WebGL from their sizes or vertices: `stripIndices` and `gridIndices` (the
//! triangles of a ruled strip and of a grid) and `meshNormalsF32` (vertex normals).

use js_sys::{Float32Array, Uint32Array};
use ruledlab::tolerance::MAX_RULINGS;
use ruledlab::Mesh;
use ruledlab_js::args::{self, fail};
use ruledlab_js::buffers::points_f32;
use wasm_bindgen::prelude::*;

/// Triangle indices of a ruled strip drawn from its segments (a_i at vertex 2i, b_i at 2i + 1):
/// two triangles per quad a_i b_i b_{i+1} a_{i+1}; `closed` adds the quad back to R_0.
#[wasm_bindgen(js_name = stripIndices)]
pub fn strip_indices(
    #[wasm_bindgen(unchecked_param_type = "number")] rulings: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "boolean")] closed: JsValue,
) -> Result<Uint32Array, JsValue> {
    const FUNC: &str = "stripIndices";
    let rulings = args::integer(FUNC, "rulings", &rulings, 0, MAX_RULINGS)?;
    let closed = args::optional_bool(FUNC, "closed", &closed, false)?;
    Ok(Uint32Array::from(&ruledlab::strip_indices(rulings, closed)[..]))
}

/// Triangle indices of a rows × cols grid of vertices (row-major), two triangles per quad.
#[wasm_bindgen(js_name = gridIndices)]
pub fn grid_indices(
    #[wasm_bindgen(unchecked_param_type = "number")] rows: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] cols: JsValue,
) -> Result<Uint32Array, JsValue> {
    const FUNC: &str = "gridIndices";
    let rows = args::integer(FUNC, "rows", &rows, 0, MAX_RULINGS)?;
    let cols = args::integer(FUNC, "cols", &cols, 0, MAX_RULINGS)?;
    if rows.saturating_mul(cols) > MAX_RULINGS {
        return Err(fail(
            FUNC,
            ruledlab::Error::TooMany { what: "lines (rows × cols)", got: rows.saturating_mul(cols), max: MAX_RULINGS },
        ));
    }
    Ok(Uint32Array::from(&ruledlab::grid_indices(rows, cols)[..]))
}

/// Vertex normals of an indexed triangle mesh (3 floats per vertex, 3 indices per triangle), as
/// f32: the area-weighted average of the facet normals around each vertex, oriented by the
/// winding ([`Mesh::vertex_normals`]). For shading models whose facets are smaller than a pixel.
#[wasm_bindgen(js_name = meshNormalsF32)]
pub fn mesh_normals_f32(
    #[wasm_bindgen(unchecked_param_type = "Float32Array | Float64Array | number[]")] positions: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Uint32Array | number[]")] indices: JsValue,
) -> Result<Float32Array, JsValue> {
    const FUNC: &str = "meshNormalsF32";
    let coords = args::numbers(FUNC, "positions", &positions)?;
    let indices = args::indices(FUNC, "indices", &indices)?;
    let mesh = Mesh::from_flat(&coords, &indices).map_err(|e| fail(FUNC, e))?;
    Ok(points_f32(&mesh.vertex_normals()))
}
