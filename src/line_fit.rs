//! The line that best fits points, and how far the points stray from it — beyond the paper: how
//! nearly straight a striction curve is (an exercise asks for a surface whose striction curve is
//! a straight line), or a polygon's points.
//!
//! **Fit.** With the centroid c = (1/n) Σ p_k and the scatter matrix S = Σ (p_k − c)(p_k − c)ᵀ,
//! the least-squares line passes through c along the eigenvector d of S's largest eigenvalue
//! (nalgebra's `SymmetricEigen`); it minimises Σ dist(p_k, line)². The **deviation** reported is
//! the largest distance of a point from that line,
//!   max_k |(p_k − c) − ((p_k − c)·d) d|,                                              (F1)
//! zero exactly when the points are collinear, and invariant under rigid motions. The **extent**
//! is the length of the points' shadow on the line,
//!   max_k (p_k − c)·d − min_k (p_k − c)·d,                                         (F2)
//! so that deviation / extent says how straight the points are whatever their scale.

use crate::error::{Error, Result};
use glam::DVec3;
use nalgebra::{Matrix3, SymmetricEigen};

/// The least-squares line of points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineFit {
    /// The centroid of the points, on the line.
    pub point: DVec3,
    /// Unit direction of the line (its sign is the eigensolver's).
    pub direction: DVec3,
    /// The largest distance of a point from the line (F1).
    pub deviation: f64,
    /// The length of the points' shadow on the line (F2).
    pub extent: f64,
}

/// The least-squares line of `points` (at least two, all finite, not all equal).
pub fn fit_line(points: &[DVec3]) -> Result<LineFit> {
    if points.len() < 2 {
        return Err(Error::parameter("points", format!("a line needs at least 2 points, got {}", points.len())));
    }
    if let Some(k) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::parameter("points", format!("point {k} is not finite")));
    }
    let c = points.iter().copied().sum::<DVec3>() / points.len() as f64;
    let mut s = Matrix3::zeros();
    for p in points {
        let q = *p - c;
        let v = nalgebra::Vector3::new(q.x, q.y, q.z);
        s += v * v.transpose();
    }
    if s.iter().all(|&x| x == 0.0) {
        return Err(Error::parameter("points", "all points are equal: they lie on every line through them"));
    }
    let eigen = SymmetricEigen::new(s);
    let k = eigen.eigenvalues.imax();
    let e = eigen.eigenvectors.column(k);
    let direction = DVec3::new(e[0], e[1], e[2]).normalize();
    let (mut deviation, mut low, mut high) = (0.0_f64, f64::INFINITY, f64::NEG_INFINITY);
    for p in points {
        let q = *p - c;
        let along = q.dot(direction);
        deviation = deviation.max((q - along * direction).length());
        low = low.min(along);
        high = high.max(along);
    }
    Ok(LineFit { point: c, direction, deviation, extent: high - low })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use glam::DQuat;

    /// Two points are the fewest: the line through them; one is refused.
    #[test]
    fn two_points_are_enough_and_one_is_not() {
        let fit = fit_line(&[DVec3::new(1.0, 1.0, 0.0), DVec3::new(3.0, 1.0, 0.0)]).unwrap();
        assert_near!(fit.direction.dot(DVec3::X).abs(), 1.0, 1e-15);
        assert_eq!(fit.deviation, 0.0);
        assert_eq!(fit_line(&[DVec3::ONE]).unwrap_err().code(), "invalid-argument");
        assert!(fit_line(&[]).is_err());
    }

    #[test]
    fn points_on_a_line_deviate_by_rounding_only() {
        let d = DVec3::new(1.0, -2.0, 0.5).normalize();
        let a = DVec3::new(3.0, 1.0, -4.0);
        let points: Vec<DVec3> = (0..50).map(|k| a + (k as f64 * 0.37 - 5.0) * d).collect();
        let fit = fit_line(&points).unwrap();
        assert!(fit.deviation < 1e-13, "deviation {}", fit.deviation);
        assert_near!(fit.direction.dot(d).abs(), 1.0, 1e-14);
        // the shadow runs from the first point to the last: 49 steps of 0.37 (F2)
        assert_near!(fit.extent, 49.0 * 0.37, 1e-12);
        // the centroid is the mean of the parameters' points
        let mean = points.iter().copied().sum::<DVec3>() / 50.0;
        assert!((fit.point - mean).length() < 1e-14);
    }

    #[test]
    fn a_rectangle_fits_its_long_axis_and_strays_by_half_its_width() {
        // corners (±2, ±1, 0): the scatter is 16 along x, 4 along y: the line is the x-axis
        let points = [
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(-2.0, 1.0, 0.0),
            DVec3::new(2.0, -1.0, 0.0),
            DVec3::new(-2.0, -1.0, 0.0),
        ];
        let fit = fit_line(&points).unwrap();
        assert_near!(fit.direction.x.abs(), 1.0, 1e-15);
        assert_near!(fit.deviation, 1.0, 1e-15);
        assert_near!(fit.extent, 4.0, 1e-15);
        assert!(fit.point.length() < 1e-15);
    }

    #[test]
    fn a_parabola_strays_by_what_its_arc_bulges() {
        // y = x² on x = −1, 0, 1: centroid (0, 2/3), the line y = 2/3 (scatter 2 along x, 2/3 along y)
        let points = [DVec3::new(-1.0, 1.0, 0.0), DVec3::new(0.0, 0.0, 0.0), DVec3::new(1.0, 1.0, 0.0)];
        let fit = fit_line(&points).unwrap();
        assert_near!(fit.direction.x.abs(), 1.0, 1e-15);
        assert_near!(fit.deviation, 2.0 / 3.0, 1e-15);
    }

    #[test]
    fn the_deviation_is_invariant_under_rigid_motions() {
        let points: Vec<DVec3> =
            (0..20).map(|k| DVec3::new(k as f64, (k as f64 * 0.7).sin(), 0.1 * k as f64)).collect();
        let fit = fit_line(&points).unwrap();
        let q = DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.9);
        let moved: Vec<DVec3> = points.iter().map(|p| q * *p + DVec3::new(-3.0, 4.0, 7.0)).collect();
        let other = fit_line(&moved).unwrap();
        assert_near!(other.deviation, fit.deviation, 1e-12);
        assert_near!(other.extent, fit.extent, 1e-12);
        assert_near!(other.direction.dot(q * fit.direction).abs(), 1.0, 1e-12);
    }

    #[test]
    fn deviation_over_extent_does_not_depend_on_scale() {
        let points: Vec<DVec3> = (0..30).map(|k| DVec3::new(k as f64, (k as f64 * 0.3).cos(), 0.0)).collect();
        let fit = fit_line(&points).unwrap();
        for scale in [1e-9, 1e-3, 1e4] {
            let scaled: Vec<DVec3> = points.iter().map(|p| *p * scale).collect();
            let other = fit_line(&scaled).unwrap();
            assert_near!(other.deviation / other.extent, fit.deviation / fit.extent, 1e-12);
        }
    }

    #[test]
    fn too_few_equal_or_broken_points_are_refused() {
        assert!(fit_line(&[DVec3::ZERO]).is_err());
        assert!(fit_line(&[DVec3::ONE, DVec3::ONE, DVec3::ONE]).is_err());
        assert!(fit_line(&[DVec3::ZERO, DVec3::new(f64::NAN, 0.0, 0.0)]).is_err());
    }
}
