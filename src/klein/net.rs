//! A discrete line congruence as a net on the Klein quadric M (Section 5 read on M; the book's
//! chapter "The Klein quadric").
//!
//! The lines L_{i,j} of a rows × cols grid are points of M, and the grid's edges — from each line
//! to the next in its row, L_{i,j+1}, and in its column, L_{i+1,j} — are chords of M. The Klein
//! form of an edge's two lines is, as for the rulings of a surface (K7),
//!
//!   Ω(L, L') = −h sin φ,
//!
//! with h the signed distance and φ the angle of the two lines. It vanishes exactly where
//! neighbouring lines meet or are parallel, which on M says that the edge's chord lies in M
//! altogether: the two lines span a pencil, every point of the chord a line of it (K2). A grid
//! whose every edge is torsal is a discrete congruence in the strict sense of discrete
//! differential geometry (neighbouring lines meet, as the lines of a torsal parametrisation do).
//! Elsewhere the sign of Ω tells how an edge's lines wind about each other; its size is not a
//! distance from that: it grows with h, so with the scale of the lines, and changes sign with the
//! orientation of one of them.

use crate::congruence::LineCongruence;
use crate::klein::point::KleinPoint;
use crate::klein::polygon::{step, KleinPolygon};

/// The lines of a congruence's grid as a net on M, with Ω on each edge.
#[derive(Debug, Clone, PartialEq)]
pub struct KleinNet {
    /// L_{i,j} = (e, a × e) of each line, row-major.
    pub points: Vec<KleinPoint>,
    /// The edges, as indices into `points`: first the rows' (i, j)–(i, j+1), row by row, then
    /// the columns' (i, j)–(i+1, j), column by column.
    pub edges: Vec<[usize; 2]>,
    /// Ω of each edge's two lines (K7).
    pub omega: Vec<f64>,
    /// Whether each edge is torsal (its lines meet or are parallel, to rounding).
    pub torsal: Vec<bool>,
    /// The largest Klein residual |Ω(L, L)|/2 of the points.
    pub max_residual: f64,
}

impl KleinNet {
    /// The net of `grid`'s lines.
    pub fn of(grid: &LineCongruence) -> Self {
        let (rows, cols) = (grid.rows(), grid.cols());
        let mut points = Vec::with_capacity(rows * cols);
        for i in 0..rows {
            for j in 0..cols {
                points.push(KleinPoint::of_segment(&grid.line(i, j)));
            }
        }
        let mut edges = Vec::with_capacity(2 * rows * cols);
        for i in 0..rows {
            for j in 1..cols {
                edges.push([i * cols + j - 1, i * cols + j]);
            }
        }
        for j in 0..cols {
            for i in 1..rows {
                edges.push([(i - 1) * cols + j, i * cols + j]);
            }
        }
        let (mut omega, mut torsal) = (Vec::with_capacity(edges.len()), Vec::with_capacity(edges.len()));
        for &[a, b] in &edges {
            let (w, t) = step(&points[a], &points[b]);
            omega.push(w);
            torsal.push(t);
        }
        let max_residual = points.iter().map(|p| p.residual().abs()).fold(0.0, f64::max);
        KleinNet { points, edges, omega, torsal, max_residual }
    }

    /// A polygon's steps as the edges of a net: step i joins L_i and L_{i+1} (the last, of a
    /// closed polygon, L_{n−1} and L_0).
    pub fn of_polygon(polygon: KleinPolygon) -> Self {
        let n = polygon.points.len();
        let edges = (0..polygon.omega.len()).map(|i| [i, (i + 1) % n]).collect();
        let KleinPolygon { points, omega, torsal, max_residual } = polygon;
        KleinNet { points, edges, omega, torsal, max_residual }
    }

    /// How many edges are torsal.
    pub fn torsal_edges(&self) -> usize {
        self.torsal.iter().filter(|&&t| t).count()
    }

    /// The edge of least |Ω| and its Ω: the edge nearest to torsal; None without edges.
    pub fn least_omega(&self) -> Option<(usize, f64)> {
        self.omega.iter().copied().enumerate().min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ruled::smooth::SmoothRuled;
    use glam::DVec3;

    /// A 2 × 3 grid: its edges are the rows' then the columns', each Ω −det(a' − a, e, e') of
    /// its two lines (K7, from the lines' points and unit directions, not from M).
    #[test]
    fn edges_run_along_rows_then_columns() {
        let mut coords = Vec::new();
        for i in 0..2 {
            for j in 0..3 {
                let (x, y) = (j as f64, i as f64);
                coords.extend([x, y, 0.0, x + 0.1 * y, y + 0.2 * x, 1.0]);
            }
        }
        let grid = LineCongruence::from_flat(2, 3, &coords).unwrap();
        let net = KleinNet::of(&grid);
        assert_eq!(net.points.len(), 6);
        assert_eq!(net.edges, vec![[0, 1], [1, 2], [3, 4], [4, 5], [0, 3], [1, 4], [2, 5]]);
        let mut least = (0, f64::INFINITY);
        for (k, &[a, b]) in net.edges.iter().enumerate() {
            let (la, lb) = (grid.line(a / 3, a % 3), grid.line(b / 3, b % 3));
            let (ea, eb) = ((la.b - la.a).normalize(), (lb.b - lb.a).normalize());
            let want = -(lb.a - la.a).dot(ea.cross(eb));
            assert!((net.omega[k] - want).abs() < 1e-15, "{k}: {} vs {want}", net.omega[k]);
            assert!(!net.torsal[k], "{k}");
            if want.abs() < least.1.abs() {
                least = (k, want);
            }
        }
        assert!(net.max_residual < 1e-15);
        let (k, w) = net.least_omega().unwrap();
        assert_eq!(k, least.0);
        assert!((w - least.1).abs() < 1e-15);
    }

    /// A closed polygon's steps become edges i → i + 1, the last back to 0, with their Ω.
    #[test]
    fn a_polygon_is_a_net_of_its_steps() {
        let s = crate::catalogue::AnalyticSurface::by_name("hyperboloid").unwrap();
        let polygon = KleinPolygon::of(&s.sample(5, s.ranges()).unwrap(), true);
        let net = KleinNet::of_polygon(polygon.clone());
        assert_eq!(net.edges, vec![[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]]);
        assert_eq!((net.omega, net.torsal, net.points), (polygon.omega, polygon.torsal, polygon.points));
        let open = KleinNet::of_polygon(KleinPolygon::of(&s.sample(5, s.ranges()).unwrap(), false));
        assert_eq!(open.edges, vec![[0, 1], [1, 2], [2, 3], [3, 4]]);
    }

    /// Lines through one point (a bundle) meet pairwise: every edge is torsal. The lines through
    /// (x, y, 0) along (−y, x, 1) (a linear congruence: a screw's paths' tangents) are skew to
    /// their neighbours: no edge is, and Ω = −h sin φ with h and φ of the two lines.
    #[test]
    fn a_bundle_is_torsal_everywhere_and_skew_lines_nowhere() {
        let apex = DVec3::new(0.3, -0.2, 2.0);
        let mut bundle = Vec::new();
        let mut skew = Vec::new();
        for i in 0..3 {
            for j in 0..4 {
                let p = DVec3::new(j as f64, i as f64, 0.0);
                bundle.extend(p.to_array());
                bundle.extend(apex.to_array());
                // e = (−y, x, 1): neighbouring lines skew (the linear congruence of a screw)
                let e = DVec3::new(-p.y, p.x, 1.0);
                skew.extend(p.to_array());
                skew.extend((p + e).to_array());
            }
        }
        let net = KleinNet::of(&LineCongruence::from_flat(3, 4, &bundle).unwrap());
        assert_eq!(net.torsal_edges(), net.edges.len());
        let net = KleinNet::of(&LineCongruence::from_flat(3, 4, &skew).unwrap());
        assert_eq!(net.torsal_edges(), 0);
        for (k, &[a, b]) in net.edges.iter().enumerate() {
            let (la, lb) = (&net.points[a], &net.points[b]);
            let cross = la.d.cross(lb.d);
            // the lines' common perpendicular: h = (p_b − p_a)·(e_a × e_b)/|e_a × e_b|
            let (pa, pb) = (la.d.cross(la.m), lb.d.cross(lb.m)); // the feet of the origin's perpendiculars
            let h = (pb - pa).dot(cross) / cross.length();
            let want = -h * cross.length();
            assert!((net.omega[k] - want).abs() < 1e-14, "{k}: {} vs {want}", net.omega[k]);
        }
    }
}
