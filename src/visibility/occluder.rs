//! A triangle as an occluder: its image's edge functions, evaluated from the same ordered pair
//! of corners in every triangle sharing an edge (no gap between neighbours), its plane oriented
//! towards the eye, its own tolerance τ_T (the global τ, or `HIDDEN_LINE_BEND` times how far its
//! neighbours [`bend`] away from its plane); whether it hides a point, and the interval of a
//! clipped segment it hides — both conditions of the module documentation, exactly.

use super::segment::{meet, nonnegative, Clipped};
use super::view::View;
use crate::tolerance::HIDDEN_LINE_EDGE_ON;
use glam::{DVec2, DVec3};

/// A triangle ready for the tests: its image's edge functions, its plane, its depth range.
#[derive(Debug, Clone, Copy)]
pub(super) struct Occluder {
    /// The three corners' images (in the orientation of the triangle's image: counter-clockwise
    /// in pixel coordinates, y down, once made so).
    corners: [DVec2; 3],
    /// Unit normal and offset of the plane, oriented so that the eye is on the positive side.
    normal: DVec3,
    offset: f64,
    /// Smallest clip w of the corners (a segment nearer than this everywhere is in front).
    pub(super) near_w: f64,
    /// The triangle's own tolerance: the global τ, or how far the triangles across its edges
    /// bend away from its plane, whichever is larger (see [`bend`]).
    tau: f64,
    pub(super) min: DVec2,
    pub(super) max: DVec2,
}

impl Occluder {
    /// e(x) ≥ 0 inside, for edge k (from corner k to corner k + 1), evaluated from the corners
    /// in a fixed order (the lexicographically smaller first) so that a neighbouring triangle
    /// sharing the edge gets the same number with the opposite sign.
    fn edge(&self, k: usize, x: DVec2) -> f64 {
        let (p, q) = (self.corners[k], self.corners[(k + 1) % 3]);
        if (p.x, p.y) <= (q.x, q.y) {
            (q - p).perp_dot(x - p)
        } else {
            -(p - q).perp_dot(x - q)
        }
    }
}

/// A triangle as an occluder; None when a corner is behind the eye or not finite, or its image
/// has no area (seen edge-on, it hides nothing).
pub(super) fn occluder(view: &View, [p0, p1, p2]: [DVec3; 3], tau: f64) -> Option<Occluder> {
    if !(p0.is_finite() && p1.is_finite() && p2.is_finite()) {
        return None;
    }
    let clips = [view.clip(p0), view.clip(p1), view.clip(p2)];
    if clips.iter().any(|c| c.w <= 0.0 || !c.is_finite()) {
        return None;
    }
    let mut corners = clips.map(|c| view.image_of_clip(c).screen);
    let area = (corners[1] - corners[0]).perp_dot(corners[2] - corners[0]);
    let scale = (corners[1] - corners[0]).length_squared().max((corners[2] - corners[0]).length_squared());
    if area.is_nan() || area.abs() <= HIDDEN_LINE_EDGE_ON * scale {
        return None;
    }
    if area < 0.0 {
        corners.swap(1, 2);
    }
    let n = (p1 - p0).cross(p2 - p0).normalize_or_zero();
    if n == DVec3::ZERO {
        return None;
    }
    let d = n.dot(p0);
    let side = view.eye_side(n, d);
    let (normal, offset) = if side >= 0.0 { (n, d) } else { (-n, -d) };
    Some(Occluder {
        corners,
        normal,
        offset,
        near_w: clips.iter().map(|c| c.w).fold(f64::INFINITY, f64::min),
        tau,
        min: corners[0].min(corners[1]).min(corners[2]),
        max: corners[0].max(corners[1]).max(corners[2]),
    })
}

/// How far each triangle's neighbours bend away from its plane: the largest distance from the
/// plane of a corner opposite one of its edges in a triangle sharing that edge (by indices).
/// A line drawn on the smooth surface the mesh samples — an exact curve, a polygon between
/// rulings — lies off the triangles by a fraction of this, which is therefore part of the
/// triangle's own tolerance: a twisted quad of a ruled strip bends by its twist, a flat mesh by
/// nothing.
pub(super) fn bend(positions: &[DVec3], indices: &[u32]) -> Vec<f64> {
    let triangles = indices.len() / 3;
    let corner = |t: usize, k: usize| positions.get(indices[3 * t + k] as usize).copied();
    // every edge (i < j) filed under i, with its triangle and the opposite corner: the triangles
    // sharing an edge are in the same bucket (a counting sort, no comparisons)
    // (a triangle naming no point is no one's neighbour)
    let vertices = positions.len();
    let valid = |t: usize| (0..3).all(|k| (indices[3 * t + k] as usize) < vertices);
    let mut starts = vec![0usize; vertices + 1];
    for t in (0..triangles).filter(|&t| valid(t)) {
        for k in 0..3 {
            let (i, j) = (indices[3 * t + k], indices[3 * t + (k + 1) % 3]);
            starts[i.min(j) as usize + 1] += 1;
        }
    }
    for v in 0..vertices {
        starts[v + 1] += starts[v];
    }
    let mut fill = starts.clone();
    let mut edges = vec![(0u32, 0usize, 0u32); starts[vertices]];
    for t in (0..triangles).filter(|&t| valid(t)) {
        for k in 0..3 {
            let (i, j) = (indices[3 * t + k], indices[3 * t + (k + 1) % 3]);
            edges[fill[i.min(j) as usize]] = (i.max(j), t, indices[3 * t + (k + 2) % 3]);
            fill[i.min(j) as usize] += 1;
        }
    }
    let mut out = vec![0.0f64; triangles];
    for v in 0..vertices {
        let bucket = &edges[starts[v]..starts[v + 1]];
        for &(j, t, _) in bucket {
            let (Some(a), Some(b), Some(c)) = (corner(t, 0), corner(t, 1), corner(t, 2)) else { continue };
            let n = (b - a).cross(c - a).normalize_or_zero();
            for &(_, _, opposite) in bucket.iter().filter(|e| e.0 == j && e.1 != t) {
                if let Some(d) = positions.get(opposite as usize).map(|q| n.dot(*q - a).abs()) {
                    if d.is_finite() {
                        out[t] = out[t].max(d);
                    }
                }
            }
        }
    }
    out
}

/// Whether the world point p (image `image`) is hidden by occluder o.
pub(super) fn hides_point(o: &Occluder, p: DVec3, image: DVec2) -> bool {
    (0..3).all(|k| o.edge(k, image) >= 0.0) && o.normal.dot(p) - o.offset < -o.tau
}

/// The hidden interval (in the image parameter s) of a clipped segment behind occluder o.
pub(super) fn hidden_interval(o: &Occluder, seg: &Clipped) -> Option<(f64, f64)> {
    let (a, b) = (seg.ia.screen, seg.ib.screen);
    let mut inside = Some((0.0, 1.0));
    for k in 0..3 {
        inside = meet(inside, nonnegative(o.edge(k, a), o.edge(k, b)));
    }
    let (s0, s1) = inside?;
    // behind by more than τ: −(n·P(t) − d) − τ > 0, linear in t
    let g = |p: DVec3| -(o.normal.dot(p) - o.offset) - o.tau;
    let (ga, gb) = (g(seg.a), g(seg.b));
    let behind_t = match (ga > 0.0, gb > 0.0) {
        (true, true) => (0.0, 1.0),
        (false, false) => return None,
        (true, false) => (0.0, ga / (ga - gb)),
        (false, true) => (ga / (ga - gb), 1.0),
    };
    let (wa, wb) = (seg.ia.w, seg.ib.w);
    let to_s = |t: f64| t * wb / ((1.0 - t) * wa + t * wb);
    meet(Some((s0, s1)), Some((to_s(behind_t.0), to_s(behind_t.1))))
}
#[cfg(test)]
mod tests {
    use super::super::fixtures::{camera, square};
    use super::*;
    use crate::tolerance::test::uniform;
    use glam::DMat4;

    /// An occluder is left out when a corner is behind the eye, or its image is edge-on: with
    /// A = |(b − a) × (c − a)| (twice its area) and L its longer side from a, kept when
    /// A > [`HIDDEN_LINE_EDGE_ON`] L² (10⁻¹²): a triangle far from the origin with A = 10⁻¹¹ L² is
    /// kept, whichever side is longer; one with A = 10⁻¹³ L² is not.
    #[test]
    fn occluders_leave_out_what_hides_nothing() {
        // clip (x, y, z, 1): the image of (x, y, z) is (x + 1, 1 − y)
        let flat = View::new(&DMat4::IDENTITY.to_cols_array(), 2.0, 2.0).unwrap();
        assert_eq!(HIDDEN_LINE_EDGE_ON, 1e-12);
        let triangle = |c0: DVec2, d1: DVec2, d2: DVec2| [c0.extend(0.0), (c0 + d1).extend(0.0), (c0 + d2).extend(0.0)];
        let far = DVec2::splat(1000.0);
        let (long, short) = (DVec2::new(1.0, 0.0), DVec2::new(0.5, 1e-11));
        assert!(occluder(&flat, triangle(far, long, short), 0.0).is_some());
        assert!(occluder(&flat, triangle(far, short, long), 0.0).is_some());
        let (long, short) = (DVec2::new(100.0, 0.0), DVec2::new(0.5, 1e-11));
        assert!(occluder(&flat, triangle(far, long, short), 0.0).is_none());
        assert!(occluder(&flat, triangle(far, short, long), 0.0).is_none());
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let (p, _) = square();
        assert!(occluder(&view, [p[0], p[1], p[2]], 0.0).is_some());
        assert!(occluder(&view, [p[0], p[1], DVec3::new(0.0, 0.0, 20.0)], 0.0).is_none());
        // seen edge-on
        assert!(occluder(&view, [DVec3::X, DVec3::new(1.0, 0.0, 1.0), DVec3::new(2.0, 0.0, 0.0)], 0.0).is_none());
    }

    /// How far the triangles across each edge bend away from a triangle's plane, against the
    /// same found pair by pair; a triangle naming a point that does not exist is no one's
    /// neighbour and bends nothing.
    #[test]
    fn bend_is_the_largest_distance_of_a_neighbours_far_corner() {
        let n = 5;
        let mut seed = 7u64;
        let mut p: Vec<DVec3> =
            (0..n * n).map(|k| DVec3::new((k % n) as f64, (k / n) as f64, uniform(&mut seed) - 0.5)).collect();
        p.push(DVec3::NAN);
        let mut idx = crate::grid_indices(n, n);
        // a triangle with a NaN corner (across the edge 0–1 of the grid) and one naming no point
        idx.extend([0, 1, (n * n) as u32, (n * n + 1) as u32, (n * n + 1) as u32, 0]);
        let triangles = idx.len() / 3;
        let mut pairwise = vec![0.0f64; triangles];
        let corners = |t: usize| [idx[3 * t], idx[3 * t + 1], idx[3 * t + 2]];
        for (a, out) in pairwise.iter_mut().enumerate() {
            let ca = corners(a);
            let Some(pa) = ca.iter().map(|&i| p.get(i as usize).copied()).collect::<Option<Vec<_>>>() else { continue };
            let normal = (pa[1] - pa[0]).cross(pa[2] - pa[0]).normalize_or_zero();
            for b in (0..triangles).filter(|&b| b != a) {
                let cb = corners(b);
                if cb.iter().any(|&i| i as usize >= p.len()) {
                    continue;
                }
                for k in 0..3 {
                    let (i, j) = (ca[k], ca[(k + 1) % 3]);
                    if cb.contains(&i) && cb.contains(&j) {
                        let far = cb.iter().find(|&&c| c != i && c != j).unwrap();
                        let d = normal.dot(p[*far as usize] - pa[0]).abs();
                        if d.is_finite() {
                            *out = out.max(d);
                        }
                    }
                }
            }
        }
        let b = bend(&p, &idx);
        assert_eq!(b.len(), triangles);
        for t in 0..triangles {
            crate::assert_near!(b[t], pairwise[t], 1e-14);
        }
        // the same triangles with their corners named from the second on (the smallest index
        // is no longer always first)
        let turned: Vec<u32> = idx.chunks_exact(3).flat_map(|t| [t[1], t[2], t[0]]).collect();
        for (x, y) in bend(&p, &turned).into_iter().zip(&b) {
            crate::assert_near!(x, *y, 1e-14);
        }
        assert!(b[..triangles - 2].iter().all(|&x| x > 0.0), "{b:?}");
        assert_eq!(&b[triangles - 2..], [0.0, 0.0]);
        // flat: nothing bends
        let (square, idx) = square();
        assert_eq!(bend(&square, &idx), [0.0, 0.0]);
    }
}
