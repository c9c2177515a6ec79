//! A tool path of Example 6 as data: CSV (tip x, y, z and unit axis i, j, k per row, after a
//! comment header with the conventions) and JSON (`{ units, tool, poses: [{ tip, axis }] }`),
//! numbers in the shortest form that reads back to the same doubles. The G-code post is the
//! machine's own format (`crate::milling::post`). Tool poses are read back from both, and from
//! CSV or JSON of tips and axes written elsewhere ([`read_tool_poses`]).

use crate::error::{Error, Result};
use crate::io::json::{self, Value};
use crate::io::{position, NumberParser};
use crate::milling::tool_line;
use crate::milling::{Tool, ToolEnd, ToolPath};
use glam::DVec3;
use std::fmt::Write;

/// CSV: a comment header with the conventions, then tip x, y, z and unit axis i, j, k per row.
pub fn tool_path_csv(path: &ToolPath) -> String {
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
pub fn tool_path_json(path: &ToolPath) -> String {
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

/// Tool poses read from a file: tips, unit axes, and the tool when the file names one.
#[derive(Debug, Clone, PartialEq)]
pub struct ImportedPoses {
    /// Tool tips.
    pub tips: Vec<DVec3>,
    /// Unit tool axes (normalised as read).
    pub axes: Vec<DVec3>,
    /// The tool of ruledlab's own files (CSV header, JSON `tool`).
    pub tool: Option<Tool>,
}

/// Whether a text looks like tool poses rather than segments: JSON with `"poses"` or `"tip"`;
/// CSV from ruledlab's tool-path export (`# ruledlab tool path`) or whose header names a tip or
/// an axis (`tip_x,…,axis_k`).
pub fn looks_like_poses(text: &str) -> bool {
    let t = text.trim_start();
    if t.starts_with(['[', '{']) {
        return t.contains("\"poses\"") || t.contains("\"tip\"");
    }
    for line in t.lines().map(str::trim).filter(|l| !l.is_empty()) {
        if line.starts_with("# ruledlab tool path") {
            return true;
        }
        if line.starts_with('#') {
            continue;
        }
        let l = line.to_ascii_lowercase();
        return l.contains("tip") || l.contains("axis");
    }
    false
}

fn tool_from_header(text: &str) -> Option<Tool> {
    let line = text.lines().find(|l| l.trim_start().starts_with("# ruledlab tool path"))?;
    let after = line.split("tool:").nth(1)?;
    let end = if after.contains("flat end") { ToolEnd::Flat } else { ToolEnd::Ball };
    let value = |key: &str| -> Option<f64> { after.split(key).nth(1)?.split(',').next()?.trim().parse().ok() };
    Tool::new(value("radius")?, value("length")?, end).ok()
}

/// The unit axis of pose k: a unit vector as written (ruledlab's own files) bit for bit, any
/// other nonzero one normalised — scaled by its largest coordinate first where its squared
/// length would overflow (1e300) or underflow (1e-200) — and the zero vector refused.
fn pose_axis(source: &str, k: usize, axis: DVec3, at: (Option<usize>, Option<usize>)) -> Result<DVec3> {
    if (axis.length_squared() - 1.0).abs() < 1e-15 {
        return Ok(axis);
    }
    match axis.try_normalize().or_else(|| (axis / axis.abs().max_element()).try_normalize()) {
        Some(unit) => Ok(unit),
        None => Err(Error::parse(source, at.0, at.1, crate::msg!("import-zero-axis", record = k))),
    }
}

/// Reads tool poses from CSV (tip x, y, z and axis i, j, k per row; the axis need not be a
/// unit vector; an optional header; `#` comments, ruledlab's own naming the tool) or JSON
/// (`{ "poses": [{ "tip": [x, y, z], "axis": [i, j, k] }, …], "tool"?: { "end", "radius",
/// "length" } }` or the array of poses alone). At least two poses; no zero axis.
pub fn read_tool_poses(text: &str, json: bool, number: NumberParser<'_>) -> Result<ImportedPoses> {
    let (tips, axes, tool) = if json { read_json(text, number)? } else { read_csv(text, number)? };
    if tips.len() < 2 {
        let source = if json { "json" } else { "csv" };
        return Err(Error::parse(source, None, None, crate::msg!("import-too-few-poses", found = tips.len())));
    }
    Ok(ImportedPoses { tips, axes, tool })
}

type Read = (Vec<DVec3>, Vec<DVec3>, Option<Tool>);

fn read_csv(text: &str, number: NumberParser<'_>) -> Result<Read> {
    let (coords, lines) = crate::io::csv::rows_with(text, number)?;
    let mut tips = Vec::with_capacity(coords.len() / 6);
    let mut axes = Vec::with_capacity(coords.len() / 6);
    for (k, r) in coords.chunks_exact(6).enumerate() {
        tips.push(DVec3::new(r[0], r[1], r[2]));
        axes.push(pose_axis("csv", k, DVec3::new(r[3], r[4], r[5]), (lines.get(k).copied(), None))?);
    }
    Ok((tips, axes, tool_from_header(text)))
}

fn read_json(text: &str, number: NumberParser<'_>) -> Result<Read> {
    let (root_at, root) = json::value_with(text, number)?;
    let at = |a: usize| {
        let (l, c) = position(text, a);
        (Some(l), Some(c))
    };
    let fail = |a: usize, m: crate::error::Message| {
        let (l, c) = at(a);
        Error::parse("json", l, c, m)
    };
    let field =
        |fields: &[(String, usize, Value)], k: &str| fields.iter().find(|f| f.0 == k).map(|f| (f.1, f.2.clone()));
    let (poses_at, poses, tool) = match root {
        Value::Object(fields) => {
            let Some((p_at, p)) = field(&fields, "poses") else {
                return Err(fail(root_at, crate::msg!("json-poses-missing")));
            };
            let tool = match field(&fields, "tool") {
                Some((_, Value::Object(t))) => {
                    let num = |k: &str| match field(&t, k) {
                        Some((_, Value::Number(x))) => Some(x),
                        _ => None,
                    };
                    let end = match field(&t, "end") {
                        Some((_, Value::String(s))) if s == "flat" => ToolEnd::Flat,
                        _ => ToolEnd::Ball,
                    };
                    num("radius").zip(num("length")).and_then(|(r, l)| Tool::new(r, l, end).ok())
                }
                _ => None,
            };
            (p_at, p, tool)
        }
        other => (root_at, other, None),
    };
    let Value::Array(items) = poses else {
        return Err(fail(poses_at, crate::msg!("json-poses-array")));
    };
    let (mut tips, mut axes) = (Vec::with_capacity(items.len()), Vec::with_capacity(items.len()));
    let vector = |v: Option<(usize, Value)>, a: usize| -> Result<DVec3> {
        match v {
            Some((_, Value::Array(xs))) if xs.len() == 3 => {
                let mut out = [0.0; 3];
                for (k, (xa, x)) in xs.iter().enumerate() {
                    match x {
                        Value::Number(x) => out[k] = *x,
                        _ => return Err(fail(*xa, crate::msg!("json-number"))),
                    }
                }
                Ok(DVec3::from(out))
            }
            _ => Err(fail(a, crate::msg!("json-pose"))),
        }
    };
    for (k, (item_at, item)) in items.iter().enumerate() {
        let Value::Object(fields) = item else {
            return Err(fail(*item_at, crate::msg!("json-pose")));
        };
        tips.push(vector(field(fields, "tip"), *item_at)?);
        axes.push(pose_axis("json", k, vector(field(fields, "axis"), *item_at)?, at(*item_at))?);
    }
    Ok((tips, axes, tool))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::rust_number;
    use crate::milling::example::example_tool_path;

    #[test]
    fn csv_and_json_round_trip_with_the_tool() {
        let path = example_tool_path(5).unwrap();
        for (text, json) in [(tool_path_csv(&path), false), (tool_path_json(&path), true)] {
            assert!(looks_like_poses(&text));
            let back = read_tool_poses(&text, json, &rust_number).unwrap();
            assert_eq!(back.tool, Some(path.tool));
            for (k, p) in path.poses.iter().enumerate() {
                assert_eq!(back.tips[k], p.tip);
                assert_eq!(back.axes[k], p.axis);
            }
        }
        assert!(!looks_like_poses("0,0,0,1,0,0\n0,0,1,0,1,1\n"));
        assert!(!looks_like_poses("{ \"segments\": [] }"));
    }

    #[test]
    fn bad_poses_are_said_where_they_are() {
        let e =
            read_tool_poses("tip_x,tip_y,tip_z,axis_i,axis_j,axis_k\n0,0,0,0,0,1\n1,0,0,0,0,0\n", false, &rust_number);
        assert_eq!(
            e.unwrap_err().to_string(),
            "csv: line 3: pose 1 has a zero axis (i = j = k = 0), so it has no direction"
        );
        let e = read_tool_poses("{\"poses\": [{\"tip\": [0, 0, 0]}]}", true, &rust_number).unwrap_err();
        assert!(e.to_string().starts_with("json: line 1, column 12: expected a pose"), "{e}");
        let e = read_tool_poses("[{\"tip\": [0, 0, 0], \"axis\": [0, 0, 1]}]", true, &rust_number).unwrap_err();
        assert!(e.to_string().contains("at least 2"), "{e}");
    }

    #[test]
    fn a_flat_tool_and_three_numbers_per_vector_are_read_as_written() {
        let text = |tip: &str| {
            format!(
                "{{\"tool\": {{\"end\": \"flat\", \"radius\": 2, \"length\": 30}}, \"poses\": [{{\"tip\": {tip}, \"axis\": [0, 0, 1]}}, {{\"tip\": [1, 0, 0], \"axis\": [0, 0, 1]}}]}}"
            )
        };
        let read = read_tool_poses(&text("[0, 0, 0]"), true, &rust_number).unwrap();
        assert_eq!(read.tool.map(|t| (t.end, t.radius, t.length)), Some((ToolEnd::Flat, 2.0, 30.0)));
        for tip in ["[0, 0]", "[0, 0, 0, 0]"] {
            let e = read_tool_poses(&text(tip), true, &rust_number).unwrap_err();
            assert_eq!(e.details().reason, Some("json-pose"), "{tip}");
        }
    }

    #[test]
    fn an_axis_of_any_nonzero_length_is_a_direction_and_zero_is_none() {
        let at = (Some(1), None);
        let axis = |v: DVec3| pose_axis("csv", 0, v, at);
        // (2, 3, 6)/7 has |a|² = 1 − 2⁻⁵³ as written, and normalising it would move its last bits
        let unit = DVec3::new(2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0);
        assert_ne!(unit.normalize(), unit);
        assert_eq!(axis(unit).unwrap().to_array().map(f64::to_bits), unit.to_array().map(f64::to_bits));
        let diagonal = DVec3::new(1.0, 1.0, 0.0) / 2f64.sqrt();
        for v in [DVec3::new(3.0, 3.0, 0.0), DVec3::new(1e300, 1e300, 0.0), DVec3::new(1e-200, 1e-200, 0.0)] {
            assert!((axis(v).unwrap() - diagonal).length() < 1e-15, "{v}");
        }
        let e = axis(DVec3::ZERO).unwrap_err();
        assert_eq!((e.details().reason, e.details().line), (Some("import-zero-axis"), Some(1)));
    }

    #[test]
    fn poses_are_told_from_segments_by_a_tip_or_an_axis() {
        assert!(looks_like_poses("[{\"tip\": [0, 0, 0], \"axis\": [0, 0, 1]}]"));
        assert!(looks_like_poses("{\"poses\": []}"));
        assert!(looks_like_poses("# a comment\nx,y,z,axis_i,axis_j,axis_k\n"));
        assert!(looks_like_poses("TIP_X TIP_Y TIP_Z I J K\n"));
        assert!(!looks_like_poses("[[0, 0, 0, 1, 0, 0]]"));
        assert!(!looks_like_poses("ax,ay,az,bx,by,bz\n"));
    }
}
