//! A tool path of Example 6 as data: CSV (tip x, y, z and unit axis i, j, k per row, after a
//! comment header with the conventions) and JSON (`{ units, tool, poses: [{ tip, axis }] }`),
//! numbers in the shortest form that reads back to the same doubles. The G-code post is the
//! machine's own format (`crate::post`). Tool poses are read back from both, and from
//! CSV or JSON of tips and axes written elsewhere ([`read_tool_poses`]).

use crate::kinematics::tool_axis;
use crate::machine::Machine;
use crate::tool_path::tool_line;
use crate::units::units_word;
use crate::{Tool, ToolEnd, ToolPath};
use glam::DVec3;
use ruledlab::tolerance::MAX_RULINGS;
use ruledlab::{pose_columns, position, NumberParser, PoseColumns};
use ruledlab::{read_json_value, JsonValue as Value};
use ruledlab::{read_table, Table};
use ruledlab::{Error, Result};
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
    /// The 1-based line of each pose in the file.
    pub lines: Vec<usize>,
    /// "mm" or "inch" where the file says so (`# units: …`, JSON `"units"`).
    pub units: Option<String>,
    /// The machine whose rotary angles the file gives, where it gives angles.
    pub machine: Option<String>,
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

/// Reads tool poses from CSV (see the module documentation; the axis need not be a unit
/// vector; `#` comments, ruledlab's own naming the tool) or JSON (`{ "poses": [{ "tip": [x, y,
/// z], "axis": [i, j, k] }, …], "tool"?: { "end", "radius", "length" }, "units"? }` or the array
/// of poses alone). At least two poses; no zero axis.
pub fn read_tool_poses(text: &str, json: bool, number: NumberParser<'_>) -> Result<ImportedPoses> {
    read_tool_poses_for(text, json, number, None)
}

/// [`read_tool_poses`] with the machine whose rotary angles a CSV's `a`, `b`, `c` columns are
/// (where the file names none in a comment `# machine: <preset>`).
pub fn read_tool_poses_for(
    text: &str,
    json: bool,
    number: NumberParser<'_>,
    machine: Option<&Machine>,
) -> Result<ImportedPoses> {
    let read = if json { read_json(text, number)? } else { read_csv(text, number, machine)? };
    if read.tips.len() < 2 {
        let source = if json { "json" } else { "csv" };
        return Err(Error::parse(source, None, None, crate::msg!("import-too-few-poses", found = read.tips.len())));
    }
    Ok(read)
}

fn read_csv(text: &str, number: NumberParser<'_>, machine: Option<&Machine>) -> Result<ImportedPoses> {
    let table: Table = read_table(text, number, "csv", MAX_RULINGS)?;
    if table.rows.is_empty() {
        return Err(Error::parse("csv", None, None, crate::msg!("csv-no-data")));
    }
    // a header must name a pose's columns: six numbers read by position under a header that
    // means something else (a3,b3,c3,x,y,z; i,j,kk,x,y,z) would swap tip and axis silently
    let cols = match table.header.as_deref() {
        None => PoseColumns::Positional,
        Some(h) => pose_columns(h).ok_or_else(|| {
            Error::parse(
                "csv",
                Some(table.rows[0].line.saturating_sub(1).max(1)),
                None,
                crate::msg!("pose-header-unknown", columns = h.join(",")),
            )
        })?,
    };
    let named = table.said("machine");
    let preset = named.as_deref().and_then(Machine::preset);
    let mut out = ImportedPoses {
        tips: Vec::with_capacity(table.rows.len()),
        axes: Vec::with_capacity(table.rows.len()),
        tool: tool_from_header(text),
        lines: Vec::with_capacity(table.rows.len()),
        units: units_word(table.said("units"), "csv")?,
        machine: None,
    };
    let m = match &cols {
        PoseColumns::Angles(_, letters) => {
            let names: String = letters.iter().map(|(l, _)| l.to_ascii_uppercase()).collect();
            let Some(m) = preset.as_ref().or(machine) else {
                return Err(Error::parse(
                    "csv",
                    table.header.as_ref().map(|_| 1),
                    None,
                    crate::msg!("pose-angles-machine", columns = names),
                ));
            };
            out.machine = Some(m.name.clone());
            Some(m)
        }
        _ => None,
    };
    for (k, row) in table.rows.iter().enumerate() {
        let v = &row.values;
        let wrong = |found: usize, need: usize| {
            let col = row.columns.get(need.min(found)).copied().or(row.columns.last().map(|c| c + 1));
            Error::parse("csv", Some(row.line), col, crate::msg!("csv-pose-numbers", found = found))
        };
        let (tip, axis) = match &cols {
            PoseColumns::Positional => {
                if v.len() != 6 {
                    return Err(wrong(v.len(), 6));
                }
                (DVec3::new(v[0], v[1], v[2]), DVec3::new(v[3], v[4], v[5]))
            }
            PoseColumns::Vector(c) => {
                if c.iter().any(|&i| i >= v.len()) {
                    return Err(wrong(v.len(), 6));
                }
                (DVec3::new(v[c[0]], v[c[1]], v[c[2]]), DVec3::new(v[c[3]], v[c[4]], v[c[5]]))
            }
            PoseColumns::Angles(xyz, letters) => {
                let m = m.expect("a machine for angles");
                let need = xyz.iter().chain(letters.iter().map(|(_, c)| c)).copied().max().unwrap_or(0);
                if need >= v.len() {
                    let names: String = letters.iter().map(|(l, _)| l.to_ascii_uppercase()).collect();
                    let col = row.columns.last().map(|c| c + 1);
                    return Err(Error::parse(
                        "csv",
                        Some(row.line),
                        col,
                        crate::msg!("csv-pose-angles", columns = format!("X Y Z {names}"), found = v.len()),
                    ));
                }
                let mut rotary = [0.0; 2];
                for (l, c) in letters {
                    let letter = l.to_ascii_uppercase().to_string();
                    match (0..2).find(|&a| m.rotary[a].name.letter() == letter) {
                        Some(a) => rotary[a] = v[*c],
                        None if v[*c] == 0.0 => {}
                        None => {
                            return Err(Error::parse(
                                "csv",
                                Some(row.line),
                                row.columns.get(*c).copied(),
                                crate::msg!("pose-angles-letter", machine = m.name.as_str(), letter = letter),
                            ));
                        }
                    }
                }
                (DVec3::new(v[xyz[0]], v[xyz[1]], v[xyz[2]]), tool_axis(m, rotary))
            }
        };
        out.tips.push(tip);
        out.axes.push(pose_axis("csv", k, axis, (Some(row.line), None))?);
        out.lines.push(row.line);
    }
    Ok(out)
}

fn read_json(text: &str, number: NumberParser<'_>) -> Result<ImportedPoses> {
    let (root_at, root) = read_json_value(text, number)?;
    let at = |a: usize| {
        let (l, c) = position(text, a);
        (Some(l), Some(c))
    };
    let fail = |a: usize, m: ruledlab::Message| {
        let (l, c) = at(a);
        Error::parse("json", l, c, m)
    };
    let field =
        |fields: &[(String, usize, Value)], k: &str| fields.iter().find(|f| f.0 == k).map(|f| (f.1, f.2.clone()));
    let mut units = None;
    let (poses_at, poses, tool) = match root {
        Value::Object(fields) => {
            if let Some((_, Value::String(u))) = field(&fields, "units") {
                units = units_word(Some(u), "json")?;
            }
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
    let mut lines = Vec::with_capacity(items.len());
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
        lines.push(position(text, *item_at).0);
    }
    Ok(ImportedPoses { tips, axes, tool, lines, units, machine: None })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::example::example_tool_path;
    use ruledlab::looks_like_poses;
    use ruledlab::rust_number;

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
            "csv: line 3: pose 1 has a zero tool axis (i = j = k = 0), so it has no direction"
        );
        // a pose's numbers are counted in a pose's words, where they are
        let e = read_tool_poses("0,0,0,0,0,1\n1,0,0,0,1\n", false, &rust_number).unwrap_err();
        assert_eq!(
            e.to_string(),
            "csv: line 2, column 10: expected 6 numbers for a pose (tip x, y, z and tool axis i, j, k), found 5"
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

    /// The CAM header `x,y,z,i,j,k` (any order, any case), the units in a comment, a BOM and
    /// semicolons with decimal commas; each pose's line.
    #[test]
    fn named_columns_units_and_lines() {
        let text = "\u{feff}# units: inch\nI;J;K;X;Y;Z\n0;0;1;1,5;0;0\n\n0;0,6;0,8;2;0;0\n";
        assert!(looks_like_poses(text));
        let p = read_tool_poses(text, false, &rust_number).unwrap();
        assert_eq!(p.tips, [DVec3::new(1.5, 0.0, 0.0), DVec3::new(2.0, 0.0, 0.0)]);
        assert_eq!(p.axes[1], DVec3::new(0.0, 0.6, 0.8));
        assert_eq!((p.lines, p.units.as_deref(), p.machine), (vec![3, 5], Some("inch"), None));
        assert!(looks_like_poses("x,y,z,i,j,k\n"));
        assert!(!looks_like_poses("x,y,z,u,v,w\n"));
    }

    /// A header that names no pose's columns is refused (naming it), never read by position.
    #[test]
    fn a_header_that_names_no_pose_is_refused() {
        for text in ["a3,b3,c3,x,y,z\n0,0,1,5,6,7\n0,0,1,8,6,7\n", "i,j,kk,x,y,z\n0,0,1,5,6,7\n0,0,1,8,6,7\n"] {
            let e = read_tool_poses(text, false, &rust_number).unwrap_err();
            assert_eq!((e.details().reason, e.details().line), (Some("pose-header-unknown"), Some(1)), "{text}");
            assert!(e.to_string().contains(text.lines().next().unwrap()), "{e}");
        }
        let e = read_tool_poses("# units: mm\nu,v,w,x,y,z\n0,0,1,5,6,7\n", false, &rust_number).unwrap_err();
        assert_eq!(e.details().line, Some(2));
        // the same numbers without a header, or under x,y,z,i,j,k in any order, are poses
        assert!(read_tool_poses("0,0,1,5,6,7\n0,0,1,8,6,7\n", false, &rust_number).is_ok());
        let p = read_tool_poses("i,j,k,x,y,z\n0,0,1,5,6,7\n0,0,1,8,6,7\n", false, &rust_number).unwrap();
        assert_eq!((p.tips[0], p.axes[0]), (DVec3::new(5.0, 6.0, 7.0), DVec3::Z));
    }

    /// `x y z a b c` in degrees: the tool axis the named machine's rotary axes give (table-table-ac:
    /// A tilts about X, C turns about Z; A = 90°, C = 0 turns the table's +Y to +Z, so the tool
    /// axis, +Z of the machine, is −Y… seen from the part: R_Tᵀ Z with R_T = R_X(90°) is (0, 1, 0)
    /// rotated back, tool_axis's answer); without a machine the file is refused, naming its
    /// columns; a B on an A/C machine is refused where it is not 0.
    #[test]
    fn rotary_angles_for_a_named_machine() {
        let m = Machine::preset("table-table-ac").unwrap();
        let text = "# machine: table-table-ac\nx y z a b c\n0 0 0 0 0 0\n1 0 0 90 0 0\n2 0 0 30 0 45\n";
        assert!(looks_like_poses(text));
        let p = read_tool_poses(text, false, &rust_number).unwrap();
        assert_eq!(p.machine.as_deref(), Some("table-table-ac"));
        assert_eq!(p.axes[0], DVec3::Z);
        assert!((p.axes[1] - tool_axis(&m, [90.0, 0.0])).length() < 1e-15);
        assert!((p.axes[2] - tool_axis(&m, [30.0, 45.0])).length() < 1e-15);
        let bare = "x,y,z,a,c\n0,0,0,0,0\n1,0,0,10,0\n";
        let e = read_tool_poses(bare, false, &rust_number).unwrap_err();
        assert_eq!(e.details().reason, Some("pose-angles-machine"));
        let h = Machine::preset("head-head-ac").unwrap();
        let p = read_tool_poses_for(bare, false, &rust_number, Some(&h)).unwrap();
        assert!((p.axes[1] - tool_axis(&h, [0.0, 10.0])).length() < 1e-15, "A is head-head-ac's second axis");
        let e =
            read_tool_poses_for("x y z a b c\n0 0 0 0 5 0\n1 0 0 0 0 0\n", false, &rust_number, Some(&m)).unwrap_err();
        assert_eq!(
            (e.details().reason, e.details().line, e.details().column),
            (Some("pose-angles-letter"), Some(2), Some(9))
        );
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
