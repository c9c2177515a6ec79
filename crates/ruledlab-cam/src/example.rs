//! The built-in tool path of Figs. 16–18: a ball-end tool following a profile curve γ on a
//! curved part surface, its axis tilted forward from the surface normal.
//!
//! Part surface z = f(x, y) = 0.3 sin x cos 0.7y; profile γ(s) = (s, 1.5 sin 0.6s, f); surface
//! normal ν(s); tool axis a(s) = (ν + 0.35 T)/|ν + 0.35 T| with T the unit tangent of γ (a lead
//! of about 19°); ball centre C(s) = γ(s) + r ν(s), so the ball touches the surface at γ(s);
//! tip = C − r a. Units: millimetres scaled down (1 unit = 10 mm in the export examples).

use crate::{Pose, Tool, ToolEnd, ToolPath};
use glam::DVec3;
use ruledlab::Mesh;
use ruledlab::Result;

/// The part surface z = f(x, y) = 0.3 sin x cos 0.7y.
pub fn part_height(x: f64, y: f64) -> f64 {
    0.3 * x.sin() * (0.7 * y).cos()
}

/// The part surface over x ∈ [−0.4, 6.4], y ∈ [−2.2, 2.2] as an nx × ny grid mesh.
pub fn part_mesh(nx: usize, ny: usize) -> Mesh {
    let (nx, ny) = (nx.max(2), ny.max(2));
    let positions = (0..nx * ny)
        .map(|k| {
            let (i, j) = (k / ny, k % ny);
            let x = -0.4 + 6.8 * i as f64 / (nx - 1) as f64;
            let y = -2.2 + 4.4 * j as f64 / (ny - 1) as f64;
            DVec3::new(x, y, part_height(x, y))
        })
        .collect();
    Mesh::grid(positions, nx, ny)
}

/// The exact path at parameter s: (profile point γ(s), ball centre, pose).
pub fn example_pose(s: f64, radius: f64) -> (DVec3, DVec3, Pose) {
    let f = part_height;
    let (x, y) = (s, 1.5 * (0.6 * s).sin());
    let gamma = DVec3::new(x, y, f(x, y));
    let (fx, fy) = (0.3 * x.cos() * (0.7 * y).cos(), -0.21 * x.sin() * (0.7 * y).sin());
    let normal = DVec3::new(-fx, -fy, 1.0).normalize();
    let dy = 0.9 * (0.6 * s).cos();
    let tangent = DVec3::new(1.0, dy, fx + fy * dy).normalize();
    let axis = (normal + 0.35 * tangent).normalize();
    let centre = gamma + radius * normal;
    (gamma, centre, Pose { tip: centre - radius * axis, axis })
}

/// Parameter range of the profile.
pub const EXAMPLE_RANGE: (f64, f64) = (0.0, 6.0);

/// The example with `count` given poses (Fig. 16 uses 7), tool radius 0.25, length 1.5.
pub fn example_tool_path(count: usize) -> Result<ToolPath> {
    example_tool_path_for(count, Tool::new(0.25, 1.5, ToolEnd::Ball)?)
}

/// The example for another tool: the ball of the tool's radius touches the profile at every
/// pose (the tip r below its centre along the axis), whatever the tool's end and length.
pub fn example_tool_path_for(count: usize, tool: Tool) -> Result<ToolPath> {
    let count = count.max(2);
    let poses = (0..count)
        .map(|i| {
            example_pose(
                EXAMPLE_RANGE.0 + (EXAMPLE_RANGE.1 - EXAMPLE_RANGE.0) * i as f64 / (count - 1) as f64,
                tool.radius,
            )
            .2
        })
        .collect();
    Ok(ToolPath { poses, tool })
}

/// The target profile sampled at `count` points.
pub fn example_profile(count: usize) -> Vec<DVec3> {
    (0..count)
        .map(|i| {
            example_pose(
                EXAMPLE_RANGE.0 + (EXAMPLE_RANGE.1 - EXAMPLE_RANGE.0) * i as f64 / (count.max(2) - 1) as f64,
                0.25,
            )
            .0
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ball_touches_the_profile() {
        for s in [0.3, 2.0, 4.7] {
            let (g, c, pose) = example_pose(s, 0.25);
            assert!(((c - g).length() - 0.25).abs() < 1e-15);
            assert!((pose.axis.length() - 1.0).abs() < 1e-15);
            assert!(((pose.tip + 0.25 * pose.axis) - c).length() < 1e-15);
        }
    }

    #[test]
    fn the_part_surface_at_known_points() {
        use std::f64::consts::{FRAC_PI_2, FRAC_PI_6};
        // 0.3 · sin x · cos 0.7y: sin π/6 = ½, cos 0 = 1, cos(0.7 · π/1.4) = cos π/2 = 0
        assert_eq!(part_height(FRAC_PI_6, 0.0), 0.3 * 0.5);
        assert_eq!(part_height(-FRAC_PI_2, 0.0), -0.3);
        assert!(part_height(FRAC_PI_2, FRAC_PI_2 / 0.7).abs() < 1e-16);
        assert!((part_height(FRAC_PI_2, 1.0) - 0.3 * 0.7f64.cos()).abs() < 1e-16);
    }

    /// The grid runs over x ∈ [−0.4, 6.4], y ∈ [−2.2, 2.2], y fastest, on the part surface.
    #[test]
    fn the_part_mesh_covers_the_part() {
        let m = part_mesh(5, 3);
        assert_eq!(m.positions.len(), 15);
        assert_eq!(m.indices.len(), 6 * 4 * 2);
        let xy = |k: usize| (m.positions[k].x, m.positions[k].y);
        assert_eq!(xy(0), (-0.4, -2.2));
        assert_eq!(xy(1), (-0.4, 0.0));
        assert!((xy(3).0 - 1.3).abs() < 1e-15 && xy(3).1 == -2.2);
        let last = xy(14);
        assert!((last.0 - 6.4).abs() < 1e-15 && (last.1 - 2.2).abs() < 1e-15, "{last:?}");
        assert!(m.positions.iter().all(|p| p.z == part_height(p.x, p.y)));
        // fewer than 2 × 2 points is 2 × 2
        assert_eq!(part_mesh(1, 0).positions.len(), 4);
    }

    /// The pose against what it is defined by, with derivatives by central differences (to
    /// 10⁻⁸): γ on the surface over (s, 1.5 sin 0.6s), ν normal to the surface and upwards, the
    /// axis in the plane of ν and γ′ at the lead angle atan 0.35 from ν, towards γ′.
    #[test]
    fn the_pose_is_what_the_example_defines() {
        let h = 1e-6;
        for s in [0.0, 0.7, 2.5, 4.1, 6.0] {
            let (g, c, pose) = example_pose(s, 0.25);
            assert_eq!(g, DVec3::new(s, 1.5 * (0.6 * s).sin(), part_height(s, 1.5 * (0.6 * s).sin())));
            let (x, y) = (g.x, g.y);
            let fx = (part_height(x + h, y) - part_height(x - h, y)) / (2.0 * h);
            let fy = (part_height(x, y + h) - part_height(x, y - h)) / (2.0 * h);
            let normal = (c - g) / 0.25;
            assert!(normal.dot(DVec3::new(1.0, 0.0, fx)).abs() < 1e-8, "s = {s}");
            assert!(normal.dot(DVec3::new(0.0, 1.0, fy)).abs() < 1e-8, "s = {s}");
            assert!(normal.z > 0.0 && (normal.length() - 1.0).abs() < 1e-15);
            let tangent = (example_pose(s + h, 0.25).0 - example_pose(s - h, 0.25).0).normalize();
            let lead = pose.axis.dot(normal).clamp(-1.0, 1.0).acos();
            assert!((lead - 0.35f64.atan()).abs() < 1e-8, "s = {s}: lead {lead}");
            // in the plane of ν and γ′, leaning towards γ′
            assert!(pose.axis.dot(normal.cross(tangent)).abs() < 1e-8 && pose.axis.dot(tangent) > 0.3);
        }
    }

    /// Another tool's example: its ball touches the same profile; the radius 0.25 gives the
    /// paper's example bit for bit.
    #[test]
    fn the_example_for_another_tool_touches_the_same_profile() {
        let tool = Tool::new(0.4, 2.0, ToolEnd::Flat).unwrap();
        let p = example_tool_path_for(5, tool).unwrap();
        assert_eq!(p.tool, tool);
        for (k, pose) in p.poses.iter().enumerate() {
            let (g, c, _) = example_pose(1.5 * k as f64, 0.4);
            assert!(((pose.tip + 0.4 * pose.axis) - c).length() < 1e-15 && ((c - g).length() - 0.4).abs() < 1e-15);
        }
        assert_eq!(
            example_tool_path_for(7, Tool::new(0.25, 1.5, ToolEnd::Ball).unwrap()).unwrap(),
            example_tool_path(7).unwrap()
        );
    }

    #[test]
    fn the_example_samples_the_profile_evenly() {
        let path = example_tool_path(7).unwrap();
        assert_eq!((path.tool.radius, path.tool.length, path.tool.end), (0.25, 1.5, ToolEnd::Ball));
        assert_eq!(path.poses.len(), 7);
        for (k, pose) in path.poses.iter().enumerate() {
            assert_eq!(*pose, example_pose(k as f64, 0.25).2, "pose {k}");
        }
        assert_eq!(example_tool_path(1).unwrap().poses, [example_pose(0.0, 0.25).2, example_pose(6.0, 0.25).2]);
        let p = example_profile(4);
        assert_eq!(p, [0.0, 2.0, 4.0, 6.0].map(|s| example_pose(s, 0.25).0));
    }
}
