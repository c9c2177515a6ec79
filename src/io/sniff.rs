//! What kind of data a text holds, before it is read: segments (the geometry's own), tool
//! poses or a target curve (read by ruledlab-cam). The page asks this of any text it is given
//! and loads the CAM module only for what is CAM's; the test is on the text alone — JSON keys,
//! a CSV header's column names, how many numbers a line has.

/// Which columns of a table give a tool pose (read by ruledlab-cam's pose reader).
#[derive(Debug, Clone, PartialEq)]
pub enum PoseColumns {
    /// Six numbers a line: tip x, y, z, axis i, j, k.
    Positional,
    /// The columns of tip x, y, z and axis i, j, k.
    Vector([usize; 6]),
    /// The columns of tip x, y, z and of the rotary angles (letter, column), degrees.
    Angles([usize; 3], Vec<(char, usize)>),
}

/// The columns a header names, if it names a pose's: tip x, y, z (or tip_x, …) with axis i, j, k
/// (or axis_i, …), or with rotary angles a, b, c for a machine.
pub fn pose_columns(header: &[String]) -> Option<PoseColumns> {
    let find = |names: &[&str]| header.iter().position(|h| names.contains(&h.as_str()));
    let xyz =
        [find(&["x", "tip_x", "tipx", "px"]), find(&["y", "tip_y", "tipy", "py"]), find(&["z", "tip_z", "tipz", "pz"])];
    let ijk = [
        find(&["i", "axis_i", "axisi", "nx"]),
        find(&["j", "axis_j", "axisj", "ny"]),
        find(&["k", "axis_k", "axisk", "nz"]),
    ];
    let [Some(x), Some(y), Some(z)] = xyz else { return None };
    if let [Some(i), Some(j), Some(k)] = ijk {
        return Some(PoseColumns::Vector([x, y, z, i, j, k]));
    }
    let angles: Vec<(char, usize)> = ['a', 'b', 'c']
        .into_iter()
        .filter_map(|l| header.iter().position(|h| h.len() == 1 && h.starts_with(l)).map(|c| (l, c)))
        .collect();
    (!angles.is_empty() && ijk.iter().all(Option::is_none)).then_some(PoseColumns::Angles([x, y, z], angles))
}

/// Whether a text looks like tool poses rather than segments: JSON with `"poses"` or `"tip"`;
/// CSV from ruledlab's tool-path export (`# ruledlab tool path`) or whose header names a tip or
/// an axis (`tip_x,…,axis_k`).
pub fn looks_like_poses(text: &str) -> bool {
    let t = text.trim_start_matches('\u{feff}').trim_start();
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
        let names: Vec<String> =
            l.split([',', ';', '\t', ' ']).map(|f| f.trim().to_string()).filter(|f| !f.is_empty()).collect();
        return l.contains("tip") || l.contains("axis") || pose_columns(&names).is_some();
    }
    false
}

/// What a text holds, as the importers name it: "poses" (tool poses), "target" (a target curve)
/// or "segments" (anything else: the geometry's own reader says what is wrong with it).
pub fn detect_import(text: &str) -> &'static str {
    if looks_like_poses(text) {
        "poses"
    } else if looks_like_target(text) {
        "target"
    } else {
        "segments"
    }
}

/// Whether a text looks like a target curve rather than segments or poses: JSON with
/// `"points"`, or CSV whose first record has 3 numbers.
pub fn looks_like_target(text: &str) -> bool {
    let t = text.trim_start_matches('\u{feff}').trim_start();
    if t.starts_with(['[', '{']) {
        return t.contains("\"points\"");
    }
    let record = t.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#')).find(|l| {
        let fields: Vec<&str> = l.split([',', ';', '\t', ' ']).filter(|f| !f.is_empty()).collect();
        fields.iter().all(|f| super::classify(&f.replace(',', ".")) == super::Token::Number)
    });
    record.is_some_and(|l| {
        let sep: &[char] = if l.contains(';') { &[';', '\t', ' '] } else { &[',', '\t', ' '] };
        l.split(sep).filter(|f| !f.is_empty()).count() == 3
    })
}

#[cfg(test)]
mod detect_tests {
    use super::{detect_import, looks_like_poses, looks_like_target, pose_columns, PoseColumns};

    fn header(text: &str) -> Vec<String> {
        text.split(',').map(str::to_string).collect()
    }

    #[test]
    fn a_header_names_a_poses_columns() {
        // a tip and an axis, in any order and naming
        assert_eq!(pose_columns(&header("i,j,k,x,y,z")), Some(PoseColumns::Vector([3, 4, 5, 0, 1, 2])));
        assert_eq!(pose_columns(&header("tip_x,tip_y,tip_z,nx,ny,nz")), Some(PoseColumns::Vector([0, 1, 2, 3, 4, 5])));
        // a tip and rotary angles (one-letter columns only), no axis
        assert_eq!(pose_columns(&header("x,y,z,b,c")), Some(PoseColumns::Angles([0, 1, 2], vec![('b', 3), ('c', 4)])));
        assert_eq!(pose_columns(&header("x,y,z,ab")), None);
        // an axis begun but not whole is not angles either; a tip without both is nothing
        assert_eq!(pose_columns(&header("x,y,z,i,a")), None);
        assert_eq!(pose_columns(&header("x,y,z")), None);
        assert_eq!(pose_columns(&header("x,y,i,j,k")), None);
    }

    #[test]
    fn poses_are_told_by_their_json_keys_their_comment_or_their_header() {
        assert!(looks_like_poses("{\"poses\": []}") && looks_like_poses("[{\"tip\": [0, 0, 0]}]"));
        assert!(!looks_like_poses("{\"points\": []}"));
        assert!(looks_like_poses("# ruledlab tool path\n0,0,0,0,0,1\n"));
        // other comments are passed over; the first line that is not decides
        assert!(looks_like_poses("# a job\n\nTIP_X;TIP_Y;TIP_Z;AXIS_I;AXIS_J;AXIS_K\n"));
        assert!(looks_like_poses("x y z b c\n1 2 3 10 20\n"));
        assert!(!looks_like_poses("# rulings\n0,0,0,1,0,0\n# tip\n"));
        // a header naming a tip alone, or an axis alone, is enough
        assert!(looks_like_poses("tip,note\n") && looks_like_poses("axis,note\n"));
        assert!(!looks_like_poses(""));
    }

    #[test]
    fn a_target_is_json_points_or_records_of_three_numbers() {
        assert!(looks_like_target("\u{feff}  {\"points\": [[0, 0, 0]]}"));
        assert!(!looks_like_target("[[0, 0, 0, 1, 0, 0]]"));
        // the first record of numbers decides: three of them (commas or semicolons with decimal commas)
        assert!(looks_like_target("# target\n1,2,3\n"));
        assert!(looks_like_target("# target\n\n1,2,3\n"), "an empty line is passed over");
        assert!(looks_like_target("1,5;2,5;3\n"));
        assert!(!looks_like_target("x,y,z\n"));
        assert!(!looks_like_target("1,2,3,4\n"));
        assert!(!looks_like_target("1,2\n"));
        assert!(!looks_like_target("# only a comment\n"));
    }

    #[test]
    fn a_text_is_poses_a_target_or_segments() {
        assert_eq!(detect_import("tip_x,tip_y,tip_z,axis_i,axis_j,axis_k\n0,0,0,0,0,1\n"), "poses");
        assert_eq!(detect_import("{\"points\": [[0, 0, 0], [1, 0, 0]]}"), "target");
        assert_eq!(detect_import("0,0,0\n1,0,0\n"), "target");
        assert_eq!(detect_import("0,0,0,1,0,0\n"), "segments");
        assert_eq!(detect_import(""), "segments");
    }
}
