//! What the page draws, built by the core as f32 buffers (6 numbers per segment, 3 per point,
//! 3 per vertex with u32 triangle indices): inserted rulings and lines, the triangulations of a
//! refined strip, director surfaces, the reference frame of the conoidal model, meshes of the
//! milling example. The page uploads them as they are.

use super::args::{self, fail, integer, to_js};
use super::congruence::LineCongruence;
use super::milling::ToolPath;
use super::surface::RuledSurface;
use crate::line::Segment;
use crate::mesh::Mesh;
use crate::milling::example;
use crate::ruled::development::{Development, Frame};
use crate::subdivision::triangulation::{self, Triangulation};
use crate::tolerance::{MAX_GRID_SIDE, MAX_MESH_SIDES, MAX_PARTS, MAX_STRIDE};
use glam::DVec3;
use js_sys::{Float32Array, Float64Array, Uint32Array};
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
struct MeshBuffers {
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

/// Triangle indices of a ruled strip drawn from its segments (a_i at vertex 2i, b_i at 2i + 1):
/// two triangles per quad a_i b_i b_{i+1} a_{i+1}; `closed` adds the quad back to R_0.
#[wasm_bindgen(js_name = stripIndices)]
pub fn strip_indices(
    #[wasm_bindgen(unchecked_param_type = "number")] rulings: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "boolean")] closed: JsValue,
) -> Result<Uint32Array, JsValue> {
    const FUNC: &str = "stripIndices";
    let rulings = args::integer(FUNC, "rulings", &rulings, 0, crate::tolerance::MAX_RULINGS)?;
    let closed = args::optional_bool(FUNC, "closed", &closed, false)?;
    Ok(Uint32Array::from(&crate::mesh::strip_indices(rulings, closed)[..]))
}

/// Triangle indices of a rows × cols grid of vertices (row-major), two triangles per quad.
#[wasm_bindgen(js_name = gridIndices)]
pub fn grid_indices(
    #[wasm_bindgen(unchecked_param_type = "number")] rows: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] cols: JsValue,
) -> Result<Uint32Array, JsValue> {
    const FUNC: &str = "gridIndices";
    let rows = args::integer(FUNC, "rows", &rows, 0, crate::tolerance::MAX_RULINGS)?;
    let cols = args::integer(FUNC, "cols", &cols, 0, crate::tolerance::MAX_RULINGS)?;
    if rows.saturating_mul(cols) > crate::tolerance::MAX_RULINGS {
        return Err(fail(
            FUNC,
            crate::Error::TooMany {
                what: "lines (rows × cols)",
                got: rows.saturating_mul(cols),
                max: crate::tolerance::MAX_RULINGS,
            },
        ));
    }
    Ok(Uint32Array::from(&crate::mesh::grid_indices(rows, cols)[..]))
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

#[wasm_bindgen]
impl RuledSurface {
    /// The rulings whose index is not a multiple of `stride` (after k interpolatory steps,
    /// stride 2^k: the inserted ones), as f32 segments.
    #[wasm_bindgen(js_name = insertedF32)]
    pub fn inserted_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] stride: JsValue,
    ) -> Result<Float32Array, JsValue> {
        let stride = integer("RuledSurface.insertedF32", "stride", &stride, 1, MAX_STRIDE)?;
        Ok(segments_f32(&self.core().inserted(stride)))
    }

    /// Every k-th ruling (indices 0, k, 2k, …, and the last), as f32 segments: a level of
    /// detail for drawing surfaces with more rulings than a view can show.
    #[wasm_bindgen(js_name = everyF32)]
    pub fn every_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] k: JsValue,
    ) -> Result<Float32Array, JsValue> {
        let k = integer("RuledSurface.everyF32", "k", &k, 1, MAX_STRIDE)?;
        let n = self.length();
        let rulings: Vec<Segment> =
            (0..n).filter(|i| i % k == 0 || *i == n - 1).map(|i| self.core().segment(i)).collect();
        Ok(segments_f32(&rulings))
    }

    /// The endpoints a_i (`which` = 1) or b_i (2) of the rulings whose index is not a multiple
    /// of `stride` (stride 1: of every ruling), as f32 points.
    #[wasm_bindgen(js_name = endsF32)]
    pub fn ends_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] which: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] stride: JsValue,
    ) -> Result<Float32Array, JsValue> {
        const F: &str = "RuledSurface.endsF32";
        let which = integer(F, "which", &which, 1, 2)?;
        let stride = integer(F, "stride", &stride, 1, MAX_STRIDE)?;
        let rulings: Vec<Segment> =
            if stride == 1 { self.core().segments().collect() } else { self.core().inserted(stride) };
        let points: Vec<DVec3> = rulings.iter().map(|s| if which == 1 { s.a } else { s.b }).collect();
        Ok(points_f32(&points))
    }

    /// z_{i,k} = ((n − k)/n) a_i + (k/n) b_i (9): the point k/n of the way along ruling i.
    #[wasm_bindgen(js_name = divisionPoint)]
    pub fn division_point(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] i: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] k: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] n: JsValue,
    ) -> Result<Float64Array, JsValue> {
        const F: &str = "RuledSurface.divisionPoint";
        let i = integer(F, "i", &i, 0, self.length() - 1)?;
        let n = integer(F, "n", &n, 1, MAX_STRIDE)?;
        let k = integer(F, "k", &k, 0, n)?;
        Ok(Float64Array::from(&triangulation::division_point(self.core(), i, k, n).to_array()[..]))
    }

    /// The edges of the first (`which` = 1, neighbours (11)) or second (2, (12)) triangulation
    /// of Fig. 9 with every segment divided into `n` parts, as f32 segments.
    #[wasm_bindgen(js_name = triangulationF32)]
    pub fn triangulation_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] n: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] which: JsValue,
    ) -> Result<Float32Array, JsValue> {
        const F: &str = "RuledSurface.triangulationF32";
        let n = integer(F, "n", &n, 1, MAX_PARTS)?;
        let which = match integer(F, "which", &which, 1, 2)? {
            1 => Triangulation::First,
            _ => Triangulation::Second,
        };
        if (self.length() - 1).saturating_mul(2 * n + 1) > crate::tolerance::MAX_RULINGS {
            return Err(fail(
                F,
                crate::Error::TooMany {
                    what: "edges",
                    got: (self.length() - 1) * (2 * n + 1),
                    max: crate::tolerance::MAX_RULINGS,
                },
            ));
        }
        let edges: Vec<Segment> =
            triangulation::edges(self.core(), n, which).into_iter().map(|[a, b]| Segment::new(a, b)).collect();
        Ok(segments_f32(&edges))
    }

    /// The reference frame of the conoidal model and development (origin a_0, x = e_0,
    /// z = n_{0,1}): the 4 × 4 matrix taking world to frame coordinates, column-major (as
    /// `gl.uniformMatrix4fv` takes it).
    #[wasm_bindgen(js_name = referenceFrame)]
    pub fn reference_frame(&self) -> Float64Array {
        Float64Array::from(&Frame::of(self.core()).world_to_frame().to_cols_array()[..])
    }

    /// The development (Fig. 6) in space: its rulings as segments of the reference plane,
    /// 6 numbers per ruling in world coordinates (`referenceFrame()` maps them to z = 0).
    #[wasm_bindgen(js_name = developmentInSpace)]
    pub fn development_in_space(&self) -> Float64Array {
        let dev = Development::of(self.core());
        let frame = Frame::of(self.core());
        let out: Vec<f64> = dev.points.iter().flat_map(|&p| frame.plane_point(p).to_array()).collect();
        Float64Array::from(&out[..])
    }

    /// The image of the striction polygon m_i in the development: N − 2 points (one per
    /// interior ruling), x, y in the reference plane. It is inscribed in the polygon the
    /// developed rulings envelop (`developmentEnvelope`): each point the midpoint of the edge on
    /// its ruling.
    #[wasm_bindgen(js_name = developmentStriction)]
    pub fn development_striction(&self) -> Float64Array {
        let image = Development::of(self.core()).striction_image();
        Float64Array::from(bytemuck::cast_slice::<_, f64>(&image))
    }

    /// [`RuledSurface::development_striction`] in space (3 numbers per point, world coordinates).
    #[wasm_bindgen(js_name = developmentStrictionInSpace)]
    pub fn development_striction_in_space(&self) -> Float64Array {
        let frame = Frame::of(self.core());
        let out: Vec<f64> = Development::of(self.core())
            .striction_image()
            .into_iter()
            .flat_map(|p| frame.plane_point(p).to_array())
            .collect();
        Float64Array::from(&out[..])
    }

    /// The polygon the developed rulings envelop: the N − 1 points where consecutive developed
    /// rulings meet, each the image of both footpoints of a pair (and of Fig. 3's
    /// perpendicular midpoint), x, y in the reference plane.
    #[wasm_bindgen(js_name = developmentEnvelope)]
    pub fn development_envelope(&self) -> Float64Array {
        let corners = Development::of(self.core()).envelope_polygon();
        Float64Array::from(bytemuck::cast_slice::<_, f64>(&corners))
    }

    /// [`RuledSurface::development_envelope`] in space (3 numbers per point, world coordinates).
    #[wasm_bindgen(js_name = developmentEnvelopeInSpace)]
    pub fn development_envelope_in_space(&self) -> Float64Array {
        let frame = Frame::of(self.core());
        let out: Vec<f64> = Development::of(self.core())
            .envelope_polygon()
            .into_iter()
            .flat_map(|p| frame.plane_point(p).to_array())
            .collect();
        Float64Array::from(&out[..])
    }
}

#[wasm_bindgen]
impl LineCongruence {
    /// The lines (i, j) with i or j not a multiple of `stride` (after k steps, 2^k: the
    /// inserted lines), as f32 segments.
    #[wasm_bindgen(js_name = insertedF32)]
    pub fn inserted_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] stride: JsValue,
    ) -> Result<Float32Array, JsValue> {
        let stride = integer("LineCongruence.insertedF32", "stride", &stride, 1, MAX_STRIDE)?;
        Ok(segments_f32(&self.core().inserted(stride)))
    }

    /// The points of the director surface d₁ (`which` = 1, the p) or d₂ (2, the q), f32,
    /// 3 per line, row-major: draw them as a rows × cols grid.
    #[wasm_bindgen(js_name = directorF32)]
    pub fn director_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] which: JsValue,
    ) -> Result<Float32Array, JsValue> {
        let which = integer("LineCongruence.directorF32", "which", &which, 1, 2)?;
        Ok(points_f32(&if which == 1 { self.core().p() } else { self.core().q() }))
    }

    /// The points of d₁ (`which` = 1) or d₂ of the lines that `insertedF32(stride)` returns.
    #[wasm_bindgen(js_name = insertedDirectorF32)]
    pub fn inserted_director_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] stride: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] which: JsValue,
    ) -> Result<Float32Array, JsValue> {
        const F: &str = "LineCongruence.insertedDirectorF32";
        let stride = integer(F, "stride", &stride, 1, MAX_STRIDE)?;
        let which = integer(F, "which", &which, 1, 2)?;
        let points: Vec<DVec3> =
            self.core().inserted(stride).iter().map(|s| if which == 1 { s.a } else { s.b }).collect();
        Ok(points_f32(&points))
    }
}

#[wasm_bindgen]
impl ToolPath {
    /// The part surface of the built-in example, z = 0.3 sin x cos 0.7y, as an nx × ny grid mesh.
    #[wasm_bindgen(js_name = examplePart, unchecked_return_type = "MeshBuffers")]
    pub fn example_part(
        #[wasm_bindgen(unchecked_param_type = "number")] nx: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] ny: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "ToolPath.examplePart";
        let (nx, ny) = (integer(F, "nx", &nx, 2, MAX_GRID_SIDE)?, integer(F, "ny", &ny, 2, MAX_GRID_SIDE)?);
        mesh_buffers(F, &example::part_mesh(nx, ny))
    }

    /// The axes (tip → tip + L·axis) of the poses whose index is not a multiple of `stride`
    /// (after k steps, 2^k: the inserted poses), as f32 segments.
    #[wasm_bindgen(js_name = insertedF32)]
    pub fn inserted_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] stride: JsValue,
    ) -> Result<Float32Array, JsValue> {
        const F: &str = "ToolPath.insertedF32";
        let stride = integer(F, "stride", &stride, 1, MAX_STRIDE)?;
        let axes = self.core().axis_surface().map_err(|e| fail(F, e))?;
        Ok(segments_f32(&axes.inserted(stride)))
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
}
