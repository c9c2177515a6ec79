//! Triangle meshes the core builds for drawing: positions and indices, ready for a GPU
//! buffer (the page draws them as they are and never derives geometry itself).

use glam::DVec3;

/// An indexed triangle mesh.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Three vertex indices per triangle.
    pub indices: Vec<u32>,
}

impl Mesh {
    /// A rows × cols grid of `positions` (row-major), two triangles per quad.
    pub fn grid(positions: Vec<DVec3>, rows: usize, cols: usize) -> Self {
        let mut indices = Vec::with_capacity(6 * rows.saturating_sub(1) * cols.saturating_sub(1));
        for i in 0..rows.saturating_sub(1) {
            for j in 0..cols.saturating_sub(1) {
                let a = (i * cols + j) as u32;
                let (b, c) = (a + 1, a + cols as u32);
                indices.extend([a, c, c + 1, a, c + 1, b]);
            }
        }
        Mesh { positions, indices }
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
