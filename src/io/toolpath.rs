//! A tool path of Example 6 as data: CSV (tip x, y, z and unit axis i, j, k per row, after a
//! comment header with the conventions) and JSON (`{ units, tool, poses: [{ tip, axis }] }`),
//! numbers in the shortest form that reads back to the same doubles. The G-code post is the
//! machine's own format (`crate::milling::post`).

use crate::milling::tool_line;
use crate::milling::{ToolEnd, ToolPath};
use glam::DVec3;
use std::fmt::Write;

/// CSV: a comment header with the conventions, then tip x, y, z and unit axis i, j, k per row.
pub fn write_csv(path: &ToolPath) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# ruledlab tool path; model units; tool: {}", tool_line(path));
    let _ = writeln!(s, "tip_x,tip_y,tip_z,axis_i,axis_j,axis_k");
    for p in &path.poses {
        let _ = writeln!(s, "{:?},{:?},{:?},{:?},{:?},{:?}", p.tip.x, p.tip.y, p.tip.z, p.axis.x, p.axis.y, p.axis.z);
    }
    s
}

/// JSON: { units, tool, poses: [{ tip: [x, y, z], axis: [i, j, k] }] } (shortest round-trip
/// number format, so reading it back gives the same doubles).
pub fn write_json(path: &ToolPath) -> String {
    let v = |p: DVec3| format!("[{:?}, {:?}, {:?}]", p.x, p.y, p.z);
    let end = match path.tool.end {
        ToolEnd::Ball => "ball",
        ToolEnd::Flat => "flat",
    };
    let poses: Vec<String> =
        path.poses.iter().map(|p| format!("    {{ \"tip\": {}, \"axis\": {} }}", v(p.tip), v(p.axis))).collect();
    format!(
        "{{\n  \"format\": \"ruledlab tool path\",\n  \"units\": \"model units; axis is a unit vector from the tip into the spindle\",\n  \"tool\": {{ \"end\": \"{end}\", \"radius\": {:?}, \"length\": {:?} }},\n  \"poses\": [\n{}\n  ]\n}}\n",
        path.tool.radius,
        path.tool.length,
        poses.join(",\n")
    )
}
