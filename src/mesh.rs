//! Triangle meshes the core builds for drawing: positions and indices, ready for a GPU
//! buffer (the page draws them as they are and never derives geometry itself).

use crate::base::check_coordinates;
use crate::error::{Error, Result};
use crate::tolerance::MAX_MESH_VERTICES;
use glam::DVec3;

/// An indexed triangle mesh.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Three vertex indices per triangle.
    pub indices: Vec<u32>,
}

/// Triangle indices of a rows × cols grid of vertices (row-major), two triangles per quad:
/// (a, c, d) and (a, d, b) for the quad a = (i, j), b = (i, j + 1), c = (i + 1, j), d = (i + 1, j + 1).
pub fn grid_indices(rows: usize, cols: usize) -> Vec<u32> {
    let mut indices = Vec::with_capacity(6 * rows.saturating_sub(1) * cols.saturating_sub(1));
    for i in 0..rows.saturating_sub(1) {
        for j in 0..cols.saturating_sub(1) {
            let a = (i * cols + j) as u32;
            let (b, c) = (a + 1, a + cols as u32);
            indices.extend([a, c, c + 1, a, c + 1, b]);
        }
    }
    indices
}

/// Triangle indices of a ruled strip whose vertex buffer is its segments (a_i at vertex 2i,
/// b_i at 2i + 1): the quads a_i b_i b_{i+1} a_{i+1} as (a_i, b_i, b_{i+1}) and
/// (a_i, b_{i+1}, a_{i+1}); `closed` adds the quad from the last ruling back to the first.
pub fn strip_indices(rulings: usize, closed: bool) -> Vec<u32> {
    let quads = if closed { rulings } else { rulings.saturating_sub(1) };
    let mut indices = Vec::with_capacity(6 * quads);
    for i in 0..quads {
        let (a0, b0) = (2 * i as u32, 2 * i as u32 + 1);
        let a1 = (2 * (i + 1) % (2 * rulings)) as u32;
        indices.extend([a0, b0, a1 + 1, a0, a1 + 1, a1]);
    }
    indices
}

impl Mesh {
    /// A rows × cols grid of `positions` (row-major), two triangles per quad ([`grid_indices`]).
    pub fn grid(positions: Vec<DVec3>, rows: usize, cols: usize) -> Self {
        Mesh { positions, indices: grid_indices(rows, cols) }
    }

    /// A tube of `radius` about the polyline `points`, `sides` vertices per ring. The rings
    /// are carried along by projecting the previous ring's frame onto each new normal plane
    /// (a rotation-minimising frame), so the tube does not twist.
    pub fn tube(points: &[DVec3], radius: f64, sides: usize) -> Self {
        let n = points.len();
        let sides = sides.max(3);
        let mut positions = Vec::with_capacity(n * sides);
        let mut normal: Option<DVec3> = None;
        for i in 0..n {
            let t = (points[(i + 1).min(n - 1)] - points[i.saturating_sub(1)]).normalize_or(DVec3::X);
            let start = normal.unwrap_or_else(|| t.any_orthonormal_vector());
            let nrm = start.reject_from_normalized(t).normalize_or(t.any_orthonormal_vector());
            let binormal = t.cross(nrm);
            for k in 0..sides {
                let (s, c) = (std::f64::consts::TAU * k as f64 / sides as f64).sin_cos();
                positions.push(points[i] + radius * (c * nrm + s * binormal));
            }
            normal = Some(nrm);
        }
        let mut indices = Vec::with_capacity(6 * n.saturating_sub(1) * sides);
        for i in 0..n.saturating_sub(1) {
            for k in 0..sides {
                let a = (i * sides + k) as u32;
                let b = (i * sides + (k + 1) % sides) as u32;
                let (c, d) = (a + sides as u32, b + sides as u32);
                indices.extend([a, c, d, a, d, b]);
            }
        }
        Mesh { positions, indices }
    }

    /// A cylinder of `radius` from `from` to `to`, with a hemisphere of the same radius at
    /// `from` when `round_end` (a ball-end tool), a disk otherwise.
    pub fn capped_cylinder(from: DVec3, to: DVec3, radius: f64, round_end: bool, sides: usize) -> Self {
        let sides = sides.max(3);
        let axis = (to - from).normalize_or(DVec3::Z);
        let (u, v) = axis.any_orthonormal_pair();
        let ring = |centre: DVec3, r: f64| -> Vec<DVec3> {
            (0..sides)
                .map(|k| {
                    let (s, c) = (std::f64::consts::TAU * k as f64 / sides as f64).sin_cos();
                    centre + r * (c * u + s * v)
                })
                .collect()
        };
        // rings from the bottom up: the hemisphere's latitudes (or the bottom disk's rim), then the top
        let mut rings: Vec<Vec<DVec3>> = Vec::new();
        if round_end {
            let lat = sides / 2;
            for l in 1..=lat {
                let angle = std::f64::consts::FRAC_PI_2 * l as f64 / lat as f64;
                rings.push(ring(from - radius * angle.cos() * axis, radius * angle.sin()));
            }
        } else {
            rings.push(ring(from, radius));
        }
        rings.push(ring(to, radius));
        let bottom = from - if round_end { radius * axis } else { DVec3::ZERO };
        let mut positions = vec![bottom];
        let mut indices = Vec::new();
        for r in &rings {
            positions.extend(r);
        }
        positions.push(to);
        let at = |ring: usize, k: usize| (1 + ring * sides + k % sides) as u32;
        for k in 0..sides {
            indices.extend([0, at(0, k + 1), at(0, k)]);
        }
        for r in 0..rings.len() - 1 {
            for k in 0..sides {
                indices.extend([at(r, k), at(r, k + 1), at(r + 1, k + 1), at(r, k), at(r + 1, k + 1), at(r + 1, k)]);
            }
        }
        let top = (positions.len() - 1) as u32;
        for k in 0..sides {
            indices.extend([top, at(rings.len() - 1, k), at(rings.len() - 1, k + 1)]);
        }
        Mesh { positions, indices }
    }
}

impl Mesh {
    /// A mesh from flat coordinates (3 per vertex) and indices (3 per triangle), checked: at most
    /// [`MAX_MESH_VERTICES`] vertices, coordinates finite and at most `MAX_COORD`, every index a
    /// vertex.
    pub fn from_flat(coords: &[f64], indices: &[u32]) -> Result<Self> {
        Self::from_flat_at_most(coords, indices, MAX_MESH_VERTICES)
    }

    /// [`Mesh::from_flat`] with at most `max_vertices` vertices (a parameter, so that a test
    /// reaches the limit with four vertices instead of eight million).
    fn from_flat_at_most(coords: &[f64], indices: &[u32], max_vertices: usize) -> Result<Self> {
        if coords.len() % 3 != 0 {
            return Err(Error::BadLength { what: "vertex coordinates", len: coords.len(), multiple: 3 });
        }
        if indices.len() % 3 != 0 {
            return Err(Error::BadLength { what: "triangle indices", len: indices.len(), multiple: 3 });
        }
        let n = coords.len() / 3;
        if n > max_vertices {
            return Err(Error::TooMany { what: "vertices", got: n, max: max_vertices });
        }
        check_coordinates(coords, 3)?;
        if let Some((k, &i)) = indices.iter().enumerate().find(|(_, &i)| i as usize >= n) {
            return Err(Error::InvalidParameter {
                name: "indices",
                message: format!("index {i} at position {k} names no vertex (there are {n})").into(),
            });
        }
        Ok(Mesh { positions: coords.chunks_exact(3).map(DVec3::from_slice).collect(), indices: indices.to_vec() })
    }

    /// Vertex normals: at every vertex the sum of the unit normals of the triangles around it,
    /// each weighted by the triangle's angle at the vertex (Thürmer and Wüthrich's angle-weighted
    /// normal, which does not depend on how a quad is split into triangles), normalised and
    /// oriented by the triangles' winding. A vertex no triangle uses (or whose triangles are all
    /// degenerate) gets the zero vector. Shading by these instead of by facets keeps models with
    /// more rulings than pixels free of moiré.
    pub fn vertex_normals(&self) -> Vec<DVec3> {
        let p = &self.positions;
        let mut normals = vec![DVec3::ZERO; p.len()];
        for t in self.indices.chunks_exact(3) {
            let [i, j, k] = [t[0] as usize, t[1] as usize, t[2] as usize];
            let n = (p[j] - p[i]).cross(p[k] - p[i]).normalize_or_zero();
            if n == DVec3::ZERO {
                continue;
            }
            for (v, a, b) in [(i, j, k), (j, k, i), (k, i, j)] {
                normals[v] += (p[a] - p[v]).angle_between(p[b] - p[v]) * n;
            }
        }
        normals.iter().map(|n| n.normalize_or_zero()).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vertex_normals_of_a_cylinder_strip_are_radial_and_of_a_plane_constant() {
        // a closed strip of 64 rulings on the cylinder x² + y² = 1: the normal at every vertex
        // is the radial direction (to the accuracy of the polygon, cos(π/64)-close)
        let n = 64;
        let positions: Vec<DVec3> = (0..n)
            .flat_map(|i| {
                let (s, c) = (std::f64::consts::TAU * i as f64 / n as f64).sin_cos();
                [DVec3::new(c, s, -1.0), DVec3::new(c, s, 1.0)]
            })
            .collect();
        let indices: Vec<u32> = (0..n as u32)
            .flat_map(|i| {
                let (a0, b0, a1) = (2 * i, 2 * i + 1, (2 * i + 2) % (2 * n as u32));
                [a0, b0, a1 + 1, a0, a1 + 1, a1]
            })
            .collect();
        let normals = Mesh { positions: positions.clone(), indices }.vertex_normals();
        for (p, nrm) in positions.iter().zip(&normals) {
            let radial = DVec3::new(p.x, p.y, 0.0);
            assert!((nrm.length() - 1.0).abs() < 1e-12);
            assert!(nrm.dot(radial).abs() > 1.0 - 1e-12, "normal {nrm} at {p}");
        }
        // the winding decides the side: all point the same way (all outward or all inward)
        let sign = normals[0].dot(DVec3::new(positions[0].x, positions[0].y, 0.0)).signum();
        assert!(normals.iter().zip(&positions).all(|(m, p)| m.dot(DVec3::new(p.x, p.y, 0.0)).signum() == sign));
        // a flat grid: every normal is the plane's, exactly; an unused vertex gets zero
        let mut grid = Mesh::grid((0..12).map(|k| DVec3::new((k % 4) as f64, (k / 4) as f64, 2.0)).collect(), 3, 4);
        grid.positions.push(DVec3::ONE);
        let flat = grid.vertex_normals();
        assert!(flat[..12].iter().all(|m| m.abs() == DVec3::Z));
        assert_eq!(flat[12], DVec3::ZERO);
        // a degenerate triangle (two equal corners) adds nothing, not NaN
        let m = Mesh { positions: vec![DVec3::ZERO, DVec3::ZERO, DVec3::X, DVec3::Y], indices: vec![0, 1, 2, 0, 2, 3] };
        assert!(m.vertex_normals().iter().all(|n| n.is_finite()));
    }

    #[test]
    fn from_flat_checks_lengths_coordinates_and_indices() {
        let square = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0];
        let m = Mesh::from_flat(&square, &[0, 1, 2, 0, 2, 3]).unwrap();
        assert_eq!(m.vertex_normals(), vec![DVec3::Z; 4]);
        assert_eq!(Mesh::from_flat(&square[..11], &[0, 1, 2]).unwrap_err().code(), "invalid-argument");
        assert_eq!(Mesh::from_flat(&square, &[0, 1]).unwrap_err().code(), "invalid-argument");
        let e = Mesh::from_flat(&square, &[0, 1, 4]).unwrap_err();
        assert_eq!(e.code(), "invalid-argument");
        assert!(e.to_string().contains("index 4 at position 2"), "{e}");
        let mut nan = square;
        nan[4] = f64::NAN;
        assert_eq!(Mesh::from_flat(&nan, &[0, 1, 2]).unwrap_err().code(), "not-finite");
    }

    #[test]
    fn strip_and_grid_indices() {
        assert_eq!(strip_indices(3, false), [0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4]);
        assert_eq!(strip_indices(2, true), [0, 1, 3, 0, 3, 2, 2, 3, 1, 2, 1, 0]);
        assert_eq!(&strip_indices(3, true)[12..], [4, 5, 1, 4, 1, 0]);
        assert!(strip_indices(1, false).is_empty());
        assert_eq!(grid_indices(2, 3), [0, 3, 4, 0, 4, 1, 1, 4, 5, 1, 5, 2]);
        assert!(grid_indices(1, 5).is_empty());
    }

    #[test]
    fn grid_tube_and_cylinder_are_closed_up_correctly() {
        let g = Mesh::grid(vec![DVec3::ZERO; 12], 3, 4);
        assert_eq!(g.indices.len(), 6 * 2 * 3);
        assert!(g.indices.iter().all(|&i| i < 12));
        // a tube about a straight line: every vertex at the radius from the axis
        let line: Vec<DVec3> = (0..5).map(|i| DVec3::new(i as f64, 0.0, 0.0)).collect();
        let t = Mesh::tube(&line, 0.25, 8);
        assert_eq!(t.positions.len(), 40);
        assert!(t.positions.iter().all(|p| ((p.y * p.y + p.z * p.z).sqrt() - 0.25).abs() < 1e-12));
        assert!(t.indices.iter().all(|&i| (i as usize) < t.positions.len()));
        // a ball-end cylinder: its lowest point is the ball's bottom, every index valid
        let c = Mesh::capped_cylinder(DVec3::ZERO, DVec3::new(0.0, 0.0, 2.0), 0.5, true, 12);
        let lowest = c.positions.iter().map(|p| p.z).fold(f64::INFINITY, f64::min);
        assert!((lowest + 0.5).abs() < 1e-12);
        assert!(c.indices.iter().all(|&i| (i as usize) < c.positions.len()));
        assert!(c.positions.iter().all(|p| (p.x * p.x + p.y * p.y).sqrt() <= 0.5 + 1e-12));
    }

    /// The side every triangle of `m` faces (by its winding): 1 when all face away from
    /// `inside(centroid)`, −1 when all face towards it, 0 when they differ.
    fn facing(m: &Mesh, inside: impl Fn(DVec3) -> DVec3) -> i32 {
        let signs: Vec<f64> = m
            .indices
            .chunks_exact(3)
            .map(|t| {
                let [a, b, c] = [0, 1, 2].map(|k| m.positions[t[k] as usize]);
                let centroid = (a + b + c) / 3.0;
                (b - a).cross(c - a).dot(centroid - inside(centroid)).signum()
            })
            .collect();
        if signs.iter().all(|&s| s == signs[0]) {
            signs[0] as i32
        } else {
            0
        }
    }

    #[test]
    fn a_tube_is_regular_polygons_in_the_normal_planes_wound_alike() {
        // a straight line off the origin along d = (1, 2, 2)/3: every ring lies in the plane
        // normal to d through its point, on the circle of the radius, as a regular polygon
        let d = DVec3::new(1.0, 2.0, 2.0) / 3.0;
        let line: Vec<DVec3> = (0..4).map(|i| DVec3::new(5.0, -1.0, 2.0) + 1.5 * i as f64 * d).collect();
        let (r, sides) = (0.25, 6);
        let t = Mesh::tube(&line, r, sides);
        assert_eq!(t.positions.len(), 4 * sides);
        let side = 2.0 * r * (std::f64::consts::PI / sides as f64).sin();
        for (i, ring) in t.positions.chunks_exact(sides).enumerate() {
            for (k, p) in ring.iter().enumerate() {
                assert!((*p - line[i]).dot(d).abs() < 1e-14, "ring {i} vertex {k} off the normal plane");
                assert!(((*p - line[i]).length() - r).abs() < 1e-14);
                assert!(((*p - ring[(k + 1) % sides]).length() - side).abs() < 1e-14);
            }
        }
        // two rings of three: the quads (a, c, d), (a, d, b) between vertex k and k + 1
        let two = Mesh::tube(&line[..2], r, 3);
        assert_eq!(two.indices, [0, 3, 4, 0, 4, 1, 1, 4, 5, 1, 5, 2, 2, 5, 3, 2, 3, 0]);
        let three = Mesh::tube(&line[..3], r, 3);
        assert_eq!(&three.indices[18..], [3, 6, 7, 3, 7, 4, 4, 7, 8, 4, 8, 5, 5, 8, 6, 5, 6, 3]);
        // every face wound the same way: towards the axis (the capped cylinder's face away
        // from it; the page colours the two sides alike, see issue 34's note)
        let axis = |p: DVec3| line[0] + (p - line[0]).dot(d) * d;
        assert_eq!(facing(&t, axis), -1);
    }

    #[test]
    fn a_capped_cylinder_is_rings_on_its_surface_with_every_face_outward() {
        let (from, to, r) = (DVec3::new(1.0, 2.0, 3.0), DVec3::new(1.0, 2.0, 5.0), 0.5);
        let axis = |p: DVec3| DVec3::new(1.0, 2.0, p.z.clamp(3.0, 5.0));
        // a flat end: the bottom centre, a ring at each end, the top centre; fans and quads
        let flat = Mesh::capped_cylinder(from, to, r, false, 3);
        assert_eq!(flat.positions.len(), 8);
        assert_eq!((flat.positions[0], flat.positions[7]), (from, to));
        assert!(flat.positions[1..4].iter().all(|p| p.z == 3.0 && ((*p - from).length() - r).abs() < 1e-15));
        assert!(flat.positions[4..7].iter().all(|p| p.z == 5.0 && ((*p - to).length() - r).abs() < 1e-15));
        #[rustfmt::skip]
        let want = [0, 2, 1, 0, 3, 2, 0, 1, 3,
                    1, 2, 5, 1, 5, 4, 2, 3, 6, 2, 6, 5, 3, 1, 4, 3, 4, 6,
                    7, 4, 5, 7, 5, 6, 7, 6, 4];
        assert_eq!(flat.indices, want);
        // a ball end of 12 sides: 6 latitudes at 15°, 30°, …, 90° from the bottom, each a ring on
        // the sphere about `from`, below it by r·cos of its latitude
        let ball = Mesh::capped_cylinder(from, to, r, true, 12);
        assert_eq!(ball.positions.len(), 1 + 7 * 12 + 1);
        assert_eq!(ball.positions[0], from - r * DVec3::Z);
        for l in 1..=6 {
            let angle = (15 * l) as f64 * std::f64::consts::PI / 180.0;
            for p in &ball.positions[1 + (l - 1) * 12..1 + l * 12] {
                assert!(((*p - from).length() - r).abs() < 1e-15);
                assert!((p.z - (3.0 - r * angle.cos())).abs() < 1e-15, "latitude {l}: {p}");
            }
        }
        for m in [&flat, &ball] {
            assert_eq!(facing(m, axis), 1);
        }
    }

    #[test]
    fn vertices_beyond_the_limit_are_refused() {
        let square = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0];
        assert_eq!(Mesh::from_flat_at_most(&square, &[0, 1, 2], 4).unwrap().positions.len(), 4);
        let e = Mesh::from_flat_at_most(&square, &[0, 1, 2], 3).unwrap_err();
        assert_eq!(e, Error::TooMany { what: "vertices", got: 4, max: 3 });
    }
}
