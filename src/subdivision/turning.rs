//! How smooth the polygons of a curve scheme become, measured (Section 4, Figs. 7–8; beyond
//! the paper).
//!
//! The *turning angle* of a polygon at a vertex is the angle between the edge that arrives
//! and the edge that leaves, in [0, π]: 0 where the polygon runs straight on, π where it
//! turns back. This module measures the *largest* turning angle of a polygon (at every vertex
//! of a closed polygon, at the interior vertices of an open one) and of each of its
//! refinements by a curve scheme.
//!
//! Where the limit is a regular C¹ curve (a continuous derivative that does not vanish), the
//! refined polygons turn less and less: their largest turning angle falls towards 0 from step
//! to step. Where it stops falling, the limit has a corner, or a cusp where its derivative
//! vanishes (a C¹ parametrisation may have one), or the polygons approach a smooth limit only
//! slowly. For the four-point scheme (8) this shows where the polygons stop straightening out
//! as the tension w grows: the paper's 0 < w < ⅛ (Dyn, Levin and Gregory 1987) is a sufficient
//! condition for C¹, not the place where kinks appear. A measurement over finitely many steps
//! is evidence, not a proof.
//!
//! Edges of zero length (|p_{i+1} − p_i| ≤ [`ZERO_LENGTH_REL`] · max(|p_i|, |p_{i+1}|)) have
//! no direction and are skipped: the angle is taken between the neighbouring edges.

use crate::error::{Error, Result};
use crate::subdivision::{check_steps, polygon_step, Scheme};
use crate::tolerance::ZERO_LENGTH_REL;
use glam::DVec3;

/// The largest turning angle of a polygon, in radians (0 … π): the largest angle between an
/// edge and the next (with the closing edge p_{N−1} p_0 when `closed`). 0 when the polygon
/// has fewer than two edges of nonzero length.
pub fn largest_turning_angle(points: &[DVec3], closed: bool) -> f64 {
    let n = points.len();
    let count = if closed && n > 2 { n } else { n.saturating_sub(1) };
    let edges: Vec<DVec3> = (0..count)
        .map(|i| (points[i], points[(i + 1) % n]))
        .filter(|(p, q)| (*q - *p).length() > ZERO_LENGTH_REL * p.length().max(q.length()))
        .map(|(p, q)| q - p)
        .collect();
    let pairs = match (closed, edges.len()) {
        (_, 0 | 1) => 0,
        (true, m) => m,
        (false, m) => m - 1,
    };
    // atan2(|a × b|, a · b) keeps its accuracy for small angles, where acos of the cosine loses it
    (0..pairs)
        .map(|i| {
            let (a, b) = (edges[i], edges[(i + 1) % edges.len()]);
            a.cross(b).length().atan2(a.dot(b))
        })
        .fold(0.0, f64::max)
}

/// The largest turning angle of `points` and of each of its refinements by `scheme`:
/// `steps + 1` values, the first for the polygon itself, the k-th after k steps. Sizes are
/// checked before any work, as in [`crate::subdivision::subdivide_polygon`].
pub fn turning_angles(points: &[DVec3], scheme: Scheme, closed: bool, steps: usize) -> Result<Vec<f64>> {
    scheme.validate()?;
    check_steps(steps)?;
    if matches!(scheme, Scheme::Variational { .. }) {
        return Err(Error::parameter("scheme", "\"variational\" refines ruled strips, not polygons"));
    }
    scheme.output_len_after(points.len(), closed, steps)?;
    let bezier_degree = points.len().saturating_sub(1);
    let mut p = points.to_vec();
    let mut out = Vec::with_capacity(steps + 1);
    out.push(largest_turning_angle(&p, closed));
    for _ in 0..steps {
        p = polygon_step(&p, scheme, closed, bezier_degree);
        out.push(largest_turning_angle(&p, closed));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::subdivision::Variant;
    use crate::tolerance::test::EXACT;
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_3, PI};

    fn regular(n: usize) -> Vec<DVec3> {
        (0..n)
            .map(|k| DVec3::new((2.0 * PI * k as f64 / n as f64).cos(), (2.0 * PI * k as f64 / n as f64).sin(), 0.0))
            .collect()
    }

    #[test]
    fn angles_of_simple_polygons() {
        let zigzag = [DVec3::ZERO, DVec3::new(1.0, 1.0, 0.0), DVec3::new(2.0, 0.0, 0.0)];
        assert_near!(largest_turning_angle(&zigzag, false), FRAC_PI_2, EXACT);
        // closed, the triangle turns by 3π/4 at its two base corners
        assert_near!(largest_turning_angle(&zigzag, true), 0.75 * PI, EXACT);
        let line: Vec<DVec3> = (0..5).map(|i| DVec3::new(i as f64, 2.0 * i as f64, -(i as f64))).collect();
        assert_eq!(largest_turning_angle(&line, false), 0.0);
        // going back along the same line is a turn by π
        let back = [DVec3::ZERO, DVec3::X, DVec3::ZERO];
        assert_near!(largest_turning_angle(&back, false), PI, EXACT);
        // a repeated point is skipped: the angle is the one between its neighbouring edges
        let repeated = [DVec3::ZERO, DVec3::X, DVec3::X, DVec3::new(1.0, 1.0, 0.0)];
        assert_near!(largest_turning_angle(&repeated, false), FRAC_PI_2, EXACT);
        // fewer than two edges do not turn
        assert_eq!(largest_turning_angle(&[DVec3::ZERO, DVec3::X], false), 0.0);
        assert_eq!(largest_turning_angle(&[DVec3::X], true), 0.0);
        assert_eq!(largest_turning_angle(&[], false), 0.0);
        // a regular hexagon turns by π/3 at every vertex
        assert_near!(largest_turning_angle(&regular(6), true), FRAC_PI_3, EXACT);
    }

    /// Chaikin on a regular N-gon: each new vertex joins a middle half of an old edge to a cut
    /// edge along the bisector of the old corner, so after one step every vertex turns by
    /// exactly half of 2π/N; later steps keep falling (the limit is a C¹ quadratic B-spline).
    #[test]
    fn chaikin_halves_the_turning_angle_of_a_regular_polygon() {
        let angles = turning_angles(&regular(6), Scheme::Chaikin, true, 5).unwrap();
        assert_eq!(angles.len(), 6);
        assert_near!(angles[0], FRAC_PI_3, EXACT);
        assert_near!(angles[1], FRAC_PI_3 / 2.0, EXACT);
        for w in angles.windows(2) {
            assert!(w[1] < w[0], "{angles:?}");
        }
    }

    /// The four-point scheme on the square (±1, 0), (0, ±1): the new points lie on the
    /// diagonals at radius ρ = (1 + 4w)/√2, and the largest turn, at the old vertices, is
    /// acos((2c − 1)/((1 − c)² + c²)) with c = ρ/√2 = (1 + 4w)/2: acos(8/17) for w = 1/16.
    /// With w = 0 (the midpoint rule) the corners stay: π/2 at every step.
    #[test]
    fn four_point_on_the_square() {
        let square = regular(4);
        let angles = turning_angles(&square, Scheme::FourPoint { w: 1.0 / 16.0 }, true, 1).unwrap();
        assert_near!(angles[0], FRAC_PI_2, EXACT);
        assert_near!(angles[1], (8.0f64 / 17.0).acos(), EXACT);
        let w = 0.1;
        let c = (1.0 + 4.0 * w) / 2.0;
        let angles = turning_angles(&square, Scheme::FourPoint { w }, true, 1).unwrap();
        assert_near!(angles[1], ((2.0 * c - 1.0) / ((1.0 - c).powi(2) + c * c)).acos(), EXACT);
        for a in turning_angles(&square, Scheme::FourPoint { w: 0.0 }, true, 6).unwrap() {
            assert_near!(a, FRAC_PI_2, EXACT);
        }
    }

    #[test]
    fn refuses_what_subdivide_polygon_refuses() {
        let p = regular(5);
        assert!(turning_angles(&p, Scheme::Variational { n: 6, variant: Variant::Coupled }, false, 1).is_err());
        assert!(turning_angles(&p, Scheme::FourPoint { w: 0.3 }, false, 1).is_err());
        assert!(turning_angles(&p, Scheme::Chaikin, false, 25).is_err());
        assert!(matches!(
            turning_angles(&p, Scheme::FourPoint { w: 0.1 }, true, 22).unwrap_err(),
            Error::TooMany { .. }
        ));
        assert!(turning_angles(&p[..2], Scheme::Chaikin, true, 1).is_err());
        assert_eq!(turning_angles(&p, Scheme::Chaikin, false, 0).unwrap().len(), 1);
    }

    #[test]
    fn open_polygons_do_not_wrap_and_two_points_do_not_close() {
        let v = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        // edges +x, +y, −x: two right angles; the first and last edges (π apart) are not a pair
        let hook = [v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)];
        assert_near!(largest_turning_angle(&hook, false), FRAC_PI_2, EXACT);
        assert_near!(largest_turning_angle(&hook, true), FRAC_PI_2, EXACT);
        // two points closed would run there and back: read as the open segment, no angle
        assert_eq!(largest_turning_angle(&hook[..2], true), 0.0);
        assert_eq!(largest_turning_angle(&hook[..1], true), 0.0);
    }

    #[test]
    fn edges_of_zero_length_are_skipped_at_any_scale() {
        let v = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        // a repeated vertex at the origin: the angle is the one between −x and +y
        let corner = [v(1.0, 0.0), v(0.0, 0.0), v(0.0, 0.0), v(0.0, 1.0)];
        assert_near!(largest_turning_angle(&corner, false), FRAC_PI_2, EXACT);
        // a right angle 1e-10 across is resolved, not rounding
        let tiny: Vec<DVec3> = corner.iter().map(|p| *p * 1e-10).collect();
        assert_near!(largest_turning_angle(&tiny, false), FRAC_PI_2, EXACT);
    }
}
