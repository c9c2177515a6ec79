//! How good a tool path is: smoothness of the orientation and the distance of the cutting
//! centres from the target. The deviation of the target from the surface the tool machines —
//! the envelope of the swept tool — is `sweep.rs`'s.

use crate::ToolPath;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Pose, Tool, ToolEnd};
    use std::f64::consts::FRAC_PI_2;

    fn path(poses: &[(DVec3, DVec3)], end: ToolEnd) -> ToolPath {
        ToolPath {
            poses: poses.iter().map(|&(tip, axis)| Pose { tip, axis }).collect(),
            tool: Tool::new(0.5, 2.0, end).unwrap(),
        }
    }

    /// Axes Z, X, Z: two right-angle steps, and |Z − 2X + Z| = 2√2.
    #[test]
    fn smoothness_of_the_orientation() {
        let p = path(&[(DVec3::ZERO, DVec3::Z), (DVec3::X, DVec3::X), (2.0 * DVec3::X, DVec3::Z)], ToolEnd::Ball);
        let q = Quality::of(&p);
        assert_eq!(q.angle_step, [FRAC_PI_2, FRAC_PI_2]);
        assert_eq!(q.second_difference, [2.0 * 2f64.sqrt()]);
        assert_eq!((q.max_angle_step(), q.max_second_difference()), (FRAC_PI_2, 2.0 * 2f64.sqrt()));
        let straight = Quality::of(&path(&[(DVec3::ZERO, DVec3::Z), (DVec3::X, DVec3::Z)], ToolEnd::Ball));
        assert_eq!((straight.max_angle_step(), straight.max_second_difference()), (0.0, 0.0));
    }

    /// A ball of radius ½ whose centre runs from (0, 0, ½) to (2, 0, ½): targets below the
    /// centre line by ¾ leave ¼ of material, above it by ¼ are gouged by ¼; beyond the ends the
    /// distance is to the end.
    #[test]
    fn deviation_from_the_targets() {
        let p = path(&[(DVec3::ZERO, DVec3::Z), (2.0 * DVec3::X, DVec3::Z)], ToolEnd::Ball);
        let targets = [
            DVec3::new(1.0, 0.0, -0.25),
            DVec3::new(1.0, 0.0, 0.25),
            DVec3::new(3.0, 0.0, 0.5),
            DVec3::new(-1.0, 0.0, 0.5),
        ];
        assert_eq!(deviation(&p, &targets), [0.25, -0.25, 0.5, 0.5]);
        // per pose: the centres (0, 0, ½) and (2, 0, ½) against the target line z = 0: they touch it
        assert_eq!(deviation_per_pose(&p, &[DVec3::ZERO, 4.0 * DVec3::X]), [0.0, 0.0]);
        let raised =
            path(&[(DVec3::new(1.0, 0.0, 0.25), DVec3::Z), (DVec3::new(5.0, 0.0, 0.0), DVec3::Z)], ToolEnd::Ball);
        assert_eq!(deviation_per_pose(&raised, &[DVec3::ZERO, 4.0 * DVec3::X]), [0.25, 1f64.hypot(0.5) - 0.5]);
        // a flat end cuts with the tip itself
        let flat = path(&[(DVec3::ZERO, DVec3::Z), (2.0 * DVec3::X, DVec3::Z)], ToolEnd::Flat);
        assert_eq!(deviation(&flat, &[DVec3::new(1.0, 0.0, -0.75)]), [0.25]);
        // a path that does not start at x = 0: the foot on the centre line is at x = 2
        let shifted = path(&[(DVec3::X, DVec3::Z), (3.0 * DVec3::X, DVec3::Z)], ToolEnd::Ball);
        assert_eq!(deviation(&shifted, &[DVec3::new(2.0, 0.0, -0.25)]), [0.25]);
        // a target segment of no length is its point
        assert_eq!(deviation_per_pose(&p, &[DVec3::new(0.0, 0.0, 2.0), DVec3::new(0.0, 0.0, 2.0)])[0], 1.0);
    }
}
