//! How good a tool path is: smoothness of the orientation and deviation from the target.

use crate::milling::ToolPath;
use glam::DVec3;

/// Orientation smoothness of a path.
#[derive(Debug, Clone, PartialEq)]
pub struct Quality {
    /// Angle between consecutive axes (radians), one per step.
    pub angle_step: Vec<f64>,
    /// Second difference of the axis, |a_{k−1} − 2a_k + a_{k+1}| (radians², as a measure of
    /// how unevenly the orientation turns), one per interior pose.
    pub second_difference: Vec<f64>,
}

impl Quality {
    /// Measures `path`.
    pub fn of(path: &ToolPath) -> Self {
        let a: Vec<DVec3> = path.poses.iter().map(|p| p.axis).collect();
        Quality {
            angle_step: a.windows(2).map(|w| w[0].angle_between(w[1])).collect(),
            second_difference: a.windows(3).map(|w| (w[0] - 2.0 * w[1] + w[2]).length()).collect(),
        }
    }

    /// Largest angle step.
    pub fn max_angle_step(&self) -> f64 {
        self.angle_step.iter().copied().fold(0.0, f64::max)
    }

    /// Largest second difference.
    pub fn max_second_difference(&self) -> f64 {
        self.second_difference.iter().copied().fold(0.0, f64::max)
    }
}

/// Signed deviation of each target point from the surface the tool leaves: its distance to
/// the cutting-centre polyline minus r for a ball end (> 0: material left, < 0: gouge).
/// For a flat end the distance to the polyline of disk centres minus r approximates the
/// same for a tool swept sideways.
pub fn deviation(path: &ToolPath, targets: &[DVec3]) -> Vec<f64> {
    let c = path.cutting_centres();
    targets
        .iter()
        .map(|&q| {
            let d = c.windows(2).map(|w| distance_to_segment(q, w[0], w[1])).fold(f64::INFINITY, f64::min);
            d - path.tool.radius
        })
        .collect()
}

/// Per pose of the path: the distance of its cutting centre from the target polyline minus r
/// (for a ball end, how far the ball stands off the target curve at that pose: > 0 material
/// left, < 0 a gouge; 0 where the ball touches it) — the deviation along the path.
pub fn deviation_per_pose(path: &ToolPath, targets: &[DVec3]) -> Vec<f64> {
    path.cutting_centres()
        .iter()
        .map(|&c| {
            let d = targets.windows(2).map(|w| distance_to_segment(c, w[0], w[1])).fold(f64::INFINITY, f64::min);
            d - path.tool.radius
        })
        .collect()
}

fn distance_to_segment(q: DVec3, a: DVec3, b: DVec3) -> f64 {
    let ab = b - a;
    let t = if ab.length_squared() > 0.0 { ((q - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
    (q - (a + t * ab)).length()
}
