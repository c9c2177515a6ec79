//! The G-code post of tool paths, for a table-table A–C five-axis machine (their CSV and JSON
//! are written in `io/toolpath.rs`).
//!
//! **Machine model.** The tool stands still along the machine +Z axis; the table carries the
//! workpiece and rotates it first by C about its own Z axis, then by A about the machine X
//! axis: a workpiece vector v appears in the machine as R v with R = R_x(A) R_z(C), both
//! rotation axes through the workpiece origin (put the part's zero on the table's centre of
//! rotation). Linear axes X Y Z are the tool-tip position R·tip in machine coordinates (no
//! TCPM needed).
//!
//! **Inverse kinematics.** For the unit tool axis (i, j, k) in workpiece coordinates,
//! R (i, j, k) = (0, 0, 1) gives C = atan2(i, j) and A = atan2(√(i² + j²), k) ∈ [0°, 180°].
//! **Wrap**: C is unwrapped, each value chosen within ±180° of the previous one, so the table
//! never spins round between two poses. **Pole**: where the axis is vertical (√(i² + j²) <
//! 1e-9) C is undefined and is held at its previous value.

use crate::error::{Error, Result};
use crate::milling::{Pose, ToolEnd, ToolPath};
use glam::{DMat3, DVec3};
use std::fmt::Write;

/// Options of the G-code export.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GcodeOptions {
    /// Feed rate in mm/min.
    pub feed: f64,
    /// Millimetres per model unit.
    pub scale: f64,
    /// Clearance above the highest machine Z of the path for the safe moves, in mm.
    pub clearance: f64,
}

impl Default for GcodeOptions {
    fn default() -> Self {
        GcodeOptions { feed: 1000.0, scale: 1.0, clearance: 5.0 }
    }
}

/// The rotation R = R_x(A) R_z(C) (angles in radians).
pub fn table_rotation(a: f64, c: f64) -> DMat3 {
    DMat3::from_rotation_x(a) * DMat3::from_rotation_z(c)
}

/// (A, C) in degrees for the unit axis, C unwrapped towards `previous_c`.
pub fn inverse_kinematics(axis: DVec3, previous_c: f64) -> (f64, f64) {
    let rho = axis.x.hypot(axis.y);
    let a = rho.atan2(axis.z).to_degrees();
    if rho < 1e-9 {
        return (a, previous_c);
    }
    let raw = axis.x.atan2(axis.y).to_degrees();
    let c = raw + 360.0 * ((previous_c - raw) / 360.0).round();
    (a, c)
}

/// The machine coordinates (X, Y, Z, A, C) of every pose, scaled to mm.
pub fn machine_coordinates(path: &ToolPath, scale: f64) -> Vec<[f64; 5]> {
    let mut c = 0.0;
    path.poses
        .iter()
        .map(|p| {
            let (a, cc) = inverse_kinematics(p.axis, c);
            c = cc;
            let m = table_rotation(a.to_radians(), cc.to_radians()) * (scale * p.tip);
            [m.x, m.y, m.z, a, cc]
        })
        .collect()
}

pub(crate) fn tool_line(path: &ToolPath) -> String {
    let end = match path.tool.end {
        ToolEnd::Ball => "ball end",
        ToolEnd::Flat => "flat end",
    };
    format!("{end}, radius {}, length {}", path.tool.radius, path.tool.length)
}

/// G-code for the machine model above.
pub fn gcode(path: &ToolPath, o: GcodeOptions) -> Result<String> {
    for (name, v) in [("feed", o.feed), ("scale", o.scale), ("clearance", o.clearance)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(Error::parameter(
                if name == "feed" {
                    "feed"
                } else if name == "scale" {
                    "scale"
                } else {
                    "clearance"
                },
                format!("must be a positive number, got {v}"),
            ));
        }
    }
    let m = machine_coordinates(path, o.scale);
    let safe = m.iter().map(|p| p[2]).fold(f64::NEG_INFINITY, f64::max) + o.clearance;
    let mut g = String::new();
    let _ = writeln!(g, "(ruledlab tool path, {} poses)", m.len());
    let _ = writeln!(
        g,
        "(machine: table-table 5-axis; C rotates the table about its Z axis, then A tilts it about machine X;"
    );
    let _ = writeln!(
        g,
        "( workpiece vector v appears as R_x(A) R_z(C) v; both rotation axes through the workpiece origin)"
    );
    let _ =
        writeln!(g, "(tool along machine +Z; X Y Z are the tool tip; A = atan2(sqrt(i^2+j^2), k) in [0, 180] deg,)");
    let _ = writeln!(
        g,
        "( C = atan2(i, j) unwrapped within 180 deg of the previous pose, held where the axis is vertical)"
    );
    let _ = writeln!(
        g,
        "(units: mm, {} mm per model unit; feed {} mm/min; tool: {} model units)",
        o.scale,
        o.feed,
        tool_line(path)
    );
    let _ = writeln!(g, "G21 G90 G94");
    let first = m[0];
    let _ = writeln!(g, "G0 Z{safe:.6}");
    let _ = writeln!(g, "G0 X{:.6} Y{:.6} A{:.6} C{:.6}", first[0], first[1], first[3], first[4]);
    for p in &m {
        let _ = writeln!(g, "G1 X{:.6} Y{:.6} Z{:.6} A{:.6} C{:.6} F{}", p[0], p[1], p[2], p[3], p[4], o.feed);
    }
    let _ = writeln!(g, "G0 Z{safe:.6}");
    let _ = writeln!(g, "M30");
    Ok(g)
}

/// Reads back the G1 moves of [`gcode`] output and inverts the kinematics: the poses in
/// workpiece coordinates (model units).
pub fn parse_gcode(text: &str, scale: f64) -> Result<Vec<Pose>> {
    let mut poses = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let code = line.split('(').next().unwrap_or("").trim();
        if !code.starts_with("G1 ") {
            continue;
        }
        let word = |letter: char| -> Result<f64> {
            code.split_whitespace().find_map(|w| w.strip_prefix(letter)).and_then(|v| v.parse::<f64>().ok()).ok_or_else(
                || Error::parse("gcode", Some(number + 1), None, format!("no {letter} value in \"{code}\"")),
            )
        };
        let (x, y, z, a, c) = (word('X')?, word('Y')?, word('Z')?, word('A')?, word('C')?);
        let r = table_rotation(a.to_radians(), c.to_radians());
        let back = r.transpose();
        poses.push(Pose { tip: back * DVec3::new(x, y, z) / scale, axis: back * DVec3::Z });
    }
    Ok(poses)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::milling::{Tool, ToolEnd};

    #[test]
    fn kinematics_maps_the_axis_onto_machine_z() {
        for axis in [DVec3::new(0.3, -0.5, 0.8), DVec3::new(-1.0, 0.2, -0.1), DVec3::new(0.0, 1.0, 0.0)] {
            let axis = axis.normalize();
            let (a, c) = inverse_kinematics(axis, 0.0);
            let m = table_rotation(a.to_radians(), c.to_radians()) * axis;
            assert!((m - DVec3::Z).length() < 1e-14, "{axis} → {m}");
            assert!((0.0..=180.0).contains(&a));
        }
        // the pole keeps C
        assert_eq!(inverse_kinematics(DVec3::Z, 37.0), (0.0, 37.0));
    }

    #[test]
    fn unwraps_c_around_the_circle() {
        let tool = Tool::new(0.1, 1.0, ToolEnd::Flat).unwrap();
        let poses = (0..=80)
            .map(|k| {
                let t = k as f64 / 80.0 * 4.0 * std::f64::consts::PI; // two full turns
                Pose { tip: DVec3::new(t, 0.0, 0.0), axis: DVec3::new(0.5 * t.cos(), 0.5 * t.sin(), 0.8).normalize() }
            })
            .collect();
        let m = machine_coordinates(&ToolPath { poses, tool }, 1.0);
        for w in m.windows(2) {
            assert!((w[1][4] - w[0][4]).abs() < 10.0, "C jumps from {} to {}", w[0][4], w[1][4]);
        }
        assert!((m.last().unwrap()[4] - m[0][4]).abs() > 700.0, "two turns of C");
    }
}
