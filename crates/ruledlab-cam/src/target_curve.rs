//! A target curve: the edge or contact curve the tool should machine, as points in order — CSV
//! (x, y, z a line, an optional header, `#` comments, `# units: inch` for inches) or JSON (an
//! array of [x, y, z], or `{ "points": […], "units"? }`). The deviation of the machined surface
//! is measured against it (`milling/quality.rs`).

use crate::units::units_word;
use glam::DVec3;
use ruledlab::read_table;
use ruledlab::tolerance::MAX_RULINGS;
use ruledlab::{position, NumberParser};
use ruledlab::{read_json_value, JsonValue as Value};
use ruledlab::{Error, Result};

/// A target curve read: its points and the units its file says, if it says them.
#[derive(Debug, Clone, PartialEq)]
pub struct TargetCurve {
    /// The points, in order.
    pub points: Vec<DVec3>,
    /// "mm" or "inch" where the file says so.
    pub units: Option<String>,
}

/// Reads a target curve (see the module documentation): at least two points.
pub fn read_target(text: &str, json: bool, number: NumberParser<'_>) -> Result<TargetCurve> {
    let source = if json { "json" } else { "csv" };
    let target = if json { from_json(text, number)? } else { from_csv(text, number)? };
    if target.points.len() < 2 {
        return Err(Error::parse(source, None, None, crate::msg!("target-too-few", found = target.points.len())));
    }
    Ok(target)
}

fn from_csv(text: &str, number: NumberParser<'_>) -> Result<TargetCurve> {
    let t = read_table(text, number, "csv", MAX_RULINGS)?;
    let mut points = Vec::with_capacity(t.rows.len());
    for row in &t.rows {
        if row.values.len() != 3 {
            let col = row.columns.get(3).copied().or(row.columns.last().map(|c| c + 1));
            return Err(Error::parse(
                "csv",
                Some(row.line),
                col,
                crate::msg!("target-three-numbers", found = row.values.len()),
            ));
        }
        points.push(DVec3::new(row.values[0], row.values[1], row.values[2]));
    }
    Ok(TargetCurve { points, units: units_word(t.said("units"), "csv")? })
}

fn from_json(text: &str, number: NumberParser<'_>) -> Result<TargetCurve> {
    let (root_at, root) = read_json_value(text, number)?;
    let fail = |a: usize, m: ruledlab::Message| {
        let (l, c) = position(text, a);
        Error::parse("json", Some(l), Some(c), m)
    };
    let (at, items, units) = match root {
        Value::Array(items) => (root_at, items, None),
        Value::Object(fields) => {
            let units = fields.iter().find(|f| f.0 == "units").and_then(|f| match &f.2 {
                Value::String(s) => Some(s.clone()),
                _ => None,
            });
            match fields.into_iter().find(|f| f.0 == "points") {
                Some((_, a, Value::Array(items))) => (a, items, units),
                _ => return Err(fail(root_at, crate::msg!("target-json"))),
            }
        }
        _ => return Err(fail(root_at, crate::msg!("target-json"))),
    };
    let _ = at;
    let mut points = Vec::with_capacity(items.len());
    for (item_at, item) in &items {
        match item {
            Value::Array(xs) if xs.len() == 3 => {
                let mut p = [0.0; 3];
                for (k, (xa, x)) in xs.iter().enumerate() {
                    match x {
                        Value::Number(x) => p[k] = *x,
                        _ => return Err(fail(*xa, crate::msg!("json-number"))),
                    }
                }
                points.push(DVec3::from(p));
            }
            _ => return Err(fail(*item_at, crate::msg!("target-json-point"))),
        }
    }
    Ok(TargetCurve { points, units: units_word(units, "json")? })
}

#[cfg(test)]
mod tests {
    use super::*;
    use ruledlab::looks_like_target;
    use ruledlab::rust_number;

    #[test]
    fn a_target_is_told_by_its_three_numbers() {
        assert!(looks_like_target("x,y,z\n0,0,0\n1,2,3\n"));
        assert!(looks_like_target("0;0;0\n1,5;2;3\n"));
        assert!(looks_like_target("{\"points\": []}"));
        assert!(!looks_like_target("0,0,0,1,0,0\n"));
        assert!(!looks_like_target("[[0, 0, 0, 1, 0, 0]]"));
    }

    #[test]
    fn targets_from_csv_and_json() {
        // a line with semicolons writes decimal commas: 1;5,2;3 is 1, 5.2, 3
        let csv = read_target("0,0,0\n1;5,2;3\n", false, &rust_number).unwrap();
        assert_eq!(csv.points[1], DVec3::new(1.0, 5.2, 3.0));
        let csv = read_target("# units: inch\nx,y,z\n0,0,0\n1,2,3\n", false, &rust_number).unwrap();
        assert_eq!((csv.points.len(), csv.units.as_deref()), (2, Some("inch")));
        let json = read_target("{\"units\": \"mm\", \"points\": [[0, 0, 0], [1, 2, 3]]}", true, &rust_number).unwrap();
        assert_eq!(json.points[1], DVec3::new(1.0, 2.0, 3.0));
        assert_eq!(read_target("[[0,0,0],[1,1,1],[2,2,2]]", true, &rust_number).unwrap().points.len(), 3);
        let e = read_target("0,0\n1,1\n", false, &rust_number).unwrap_err();
        assert_eq!((e.details().reason, e.details().line), (Some("target-three-numbers"), Some(1)));
        // the column said: where the fourth number starts, or just after the last one when
        // there are fewer than three ("10,20" has its second number at column 4: column 5)
        let e = read_target("0,0,0\n10,20\n", false, &rust_number).unwrap_err();
        assert_eq!((e.details().line, e.details().column), (Some(2), Some(5)));
        let e = read_target("0,0,0\n1,2,3,44\n", false, &rust_number).unwrap_err();
        assert_eq!((e.details().line, e.details().column), (Some(2), Some(7)));
        let e = read_target("[[0,0,0]]", true, &rust_number).unwrap_err();
        assert_eq!(e.details().reason, Some("target-too-few"));
        // units other than mm and inch are refused, not read as mm
        for text in ["# units: imperial\n0,0,0\n1,1,1\n", "# units: furlong\n0,0,0\n1,1,1\n"] {
            let e = read_target(text, false, &rust_number).unwrap_err();
            assert_eq!(e.details().reason, Some("units-unknown"), "{text}");
        }
        let e = read_target("{\"units\": \"furlong\", \"points\": [[0, 0, 0], [1, 2, 3]]}", true, &rust_number)
            .unwrap_err();
        assert_eq!(e.details().reason, Some("units-unknown"));
        let e = read_target("[[0,0,0], [1, 2]]", true, &rust_number).unwrap_err();
        assert_eq!(e.details().reason, Some("target-json-point"));
    }
}
