//! Example 6 (Section 4, Figs. 16–18): refining a few 5-axis tool positions into a smooth,
//! dense tool path.
//!
//! A tool pose is a segment from the tool tip along the tool axis; a sequence of poses is a
//! discrete ruled surface (the axis surface), refined by the strip schemes of Section 4
//! (variational by default). The tool is a cylinder of radius r and length L, flat-ended or
//! ball-ended; for a ball end the ball centre is tip + r·axis and the surface it leaves is the
//! envelope of the moving ball, a tube of radius r about the centre curve.

use glam::DVec3;
use ruledlab::Mesh;
use ruledlab::RuledSurface;
use ruledlab::Segment;
use ruledlab::{subdivide_strip, Scheme};
use ruledlab::{Error, Result};

/// The end of the tool.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ToolEnd {
    /// A flat end: the tip is the centre of the bottom disk.
    Flat,
    /// A ball end of the tool's radius: the tip is the lowest point of the ball.
    Ball,
}

/// A cylindrical milling tool.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tool {
    /// Radius r > 0.
    pub radius: f64,
    /// Length L > 0 (from the tip along the axis).
    pub length: f64,
    /// Flat or ball end.
    pub end: ToolEnd,
}

impl Tool {
    /// A validated tool.
    pub fn new(radius: f64, length: f64, end: ToolEnd) -> Result<Self> {
        if !(radius.is_finite() && radius > 0.0) {
            return Err(Error::parameter("radius", format!("the tool radius must be a positive number, got {radius}")));
        }
        if !(length.is_finite() && length > 0.0) {
            return Err(Error::parameter("length", format!("the tool length must be a positive number, got {length}")));
        }
        Ok(Tool { radius, length, end })
    }
}

/// One tool pose: the tip and the unit axis (pointing from the tip into the spindle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// Tool tip.
    pub tip: DVec3,
    /// Unit tool axis.
    pub axis: DVec3,
}

/// A tool path: poses in order and the tool that follows them.
#[derive(Debug, Clone, PartialEq)]
pub struct ToolPath {
    /// The poses.
    pub poses: Vec<Pose>,
    /// The tool.
    pub tool: Tool,
}

impl ToolPath {
    /// From axis segments tip → point on the axis (validated like a ruled surface: at least
    /// two poses, finite, no zero-length axis).
    pub fn from_surface(axes: &RuledSurface, tool: Tool) -> Self {
        let poses = axes.segments().map(|s| Pose { tip: s.a, axis: s.line().dir }).collect();
        ToolPath { poses, tool }
    }

    /// The axis surface: segments from each tip along the axis, of the tool's length.
    pub fn axis_surface(&self) -> Result<RuledSurface> {
        RuledSurface::new(self.poses.iter().map(|p| Segment::new(p.tip, p.tip + self.tool.length * p.axis)).collect())
    }

    /// The path refined by `steps` steps of a strip scheme applied to the axis surface (no step:
    /// the poses as they are, bit for bit).
    pub fn refine(&self, scheme: Scheme, steps: usize) -> Result<ToolPath> {
        let refined = subdivide_strip(&self.axis_surface()?, scheme, false, steps)?;
        if steps == 0 {
            return Ok(self.clone());
        }
        Ok(ToolPath::from_surface(&refined, self.tool))
    }

    /// The tool's barycentre curve (Fig. 16): the centre of the cylinder, tip + (L/2)·axis.
    pub fn barycentres(&self) -> Vec<DVec3> {
        self.poses.iter().map(|p| p.tip + 0.5 * self.tool.length * p.axis).collect()
    }

    /// The envelope of the tool's cutting end (for a ball end, the tube of radius r about the
    /// ball centres, whose lower half is the machined surface) as a mesh.
    pub fn envelope_mesh(&self, sides: usize) -> Mesh {
        Mesh::tube(&self.cutting_centres(), self.tool.radius, sides)
    }

    /// The tool body at pose `i` (Fig. 16): a cylinder of radius r from the tip along the
    /// axis over the tool's length, its end a ball of radius r or a flat disk.
    pub fn tool_mesh(&self, i: usize, sides: usize) -> Option<Mesh> {
        let p = self.poses.get(i)?;
        let (r, ball) = (self.tool.radius, self.tool.end == ToolEnd::Ball);
        let from = if ball { p.tip + r * p.axis } else { p.tip };
        Some(Mesh::capped_cylinder(from, p.tip + self.tool.length * p.axis, r, ball, sides))
    }

    /// The points whose offset by r is the machined surface: ball centres tip + r·axis for a
    /// ball end; for a flat end the tip itself (the centre of the cutting disk).
    pub fn cutting_centres(&self) -> Vec<DVec3> {
        let r = match self.tool.end {
            ToolEnd::Ball => self.tool.radius,
            ToolEnd::Flat => 0.0,
        };
        self.poses.iter().map(|p| p.tip + r * p.axis).collect()
    }
}

/// "ball end, radius r, length L" (model units), for file headers.
pub(crate) fn tool_line(path: &ToolPath) -> String {
    let end = match path.tool.end {
        ToolEnd::Ball => "ball end",
        ToolEnd::Flat => "flat end",
    };
    format!("{end}, radius {}, length {}", path.tool.radius, path.tool.length)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Three poses of a ball-end tool of radius ½ and length 2: axes along z, along x, and
    /// (1, 2, 2)/3.
    fn path(end: ToolEnd) -> ToolPath {
        let poses = [
            (DVec3::new(0.0, 0.0, 0.0), DVec3::Z),
            (DVec3::new(1.0, 0.0, 0.0), DVec3::X),
            (DVec3::new(2.0, 1.0, 0.0), DVec3::new(1.0, 2.0, 2.0) / 3.0),
        ]
        .map(|(tip, axis)| Pose { tip, axis });
        ToolPath { poses: poses.to_vec(), tool: Tool::new(0.5, 2.0, end).unwrap() }
    }

    #[test]
    fn points_along_the_axis() {
        let p = path(ToolEnd::Ball);
        let tips = [DVec3::ZERO, DVec3::X, DVec3::new(2.0, 1.0, 0.0)];
        let ends = [
            DVec3::new(0.0, 0.0, 2.0),
            DVec3::new(3.0, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0) + DVec3::new(2.0, 4.0, 4.0) / 3.0,
        ];
        let axes = p.axis_surface().unwrap();
        assert_eq!(
            axes.segments().map(|s| (s.a, s.b)).collect::<Vec<_>>(),
            tips.into_iter().zip(ends).collect::<Vec<_>>()
        );
        // the barycentres halfway (L/2 = 1), the ball centres at r = ½
        let half = [
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0) + DVec3::new(1.0, 2.0, 2.0) / 3.0,
        ];
        assert_eq!(p.barycentres(), half);
        let centres = [
            DVec3::new(0.0, 0.0, 0.5),
            DVec3::new(1.5, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0) + DVec3::new(1.0, 2.0, 2.0) / 6.0,
        ];
        assert_eq!(p.cutting_centres(), centres);
        assert_eq!(path(ToolEnd::Flat).cutting_centres(), tips);
    }

    #[test]
    fn refining_by_no_step_keeps_the_poses_bit_for_bit() {
        let p = path(ToolEnd::Ball);
        assert_eq!(p.refine(Scheme::Chaikin, 0).unwrap(), p);
        // one step of Chaikin's corner cutting: 2·3 − 2 poses, a quarter along the first edge
        let r = p.refine(Scheme::Chaikin, 1).unwrap();
        assert_eq!(r.poses.len(), 4);
        assert_eq!(r.poses[0].tip, DVec3::new(0.25, 0.0, 0.0));
        assert_eq!(r.tool, p.tool);
    }

    /// The envelope is a tube of radius r about the cutting centres: every ring vertex is r from
    /// its centre.
    #[test]
    fn the_envelope_is_a_tube_about_the_cutting_centres() {
        for end in [ToolEnd::Ball, ToolEnd::Flat] {
            let p = path(end);
            let m = p.envelope_mesh(12);
            let centres = p.cutting_centres();
            assert_eq!(m.positions.len(), 3 * 12);
            for (k, v) in m.positions.iter().enumerate() {
                assert!(((*v - centres[k / 12]).length() - 0.5).abs() < 1e-15, "{end:?}, vertex {k}");
            }
        }
    }

    /// The tool body from its lowest point, the tip, to the top of the cylinder at tip + L·axis;
    /// a ball end has sides/2 latitude rings, a flat end one rim.
    #[test]
    fn the_tool_body_from_the_tip_to_its_length() {
        for (end, rings) in [(ToolEnd::Ball, 4), (ToolEnd::Flat, 1)] {
            let p = path(end);
            for (i, pose) in p.poses.iter().enumerate() {
                let m = p.tool_mesh(i, 8).unwrap();
                assert_eq!(m.positions.len(), 1 + (rings + 1) * 8 + 1, "{end:?}");
                assert!((m.positions[0] - pose.tip).length() < 1e-15, "{end:?}, pose {i}");
                assert!((m.positions[m.positions.len() - 1] - (pose.tip + 2.0 * pose.axis)).length() < 1e-15);
                // the widest ring is r from the axis
                let radius =
                    m.positions.iter().map(|v| (*v - pose.tip).reject_from(pose.axis).length()).fold(0.0, f64::max);
                assert!((radius - 0.5).abs() < 1e-15, "{end:?}, pose {i}: {radius}");
            }
            assert!(p.tool_mesh(3, 8).is_none());
        }
    }
}
