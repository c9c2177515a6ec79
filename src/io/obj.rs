//! A ruled strip as Wavefront OBJ: the endpoints a_i, b_i as vertices (a_i is vertex 2i + 1,
//! OBJ counts from 1), each ruling a line element, and, for a surface, each pair of
//! consecutive rulings a quad face a_i b_i b_{i+1} a_{i+1}.

use std::fmt::Write;

/// OBJ of segments (6 numbers each), named `name`; `faces`: the quads between consecutive
/// rulings (a surface; not for the lines of a congruence).
pub fn write_obj(coords: &[f64], faces: bool, name: &str) -> String {
    // a name is one token in OBJ: whitespace and control characters would end it
    let name: String = name.chars().map(|c| if c.is_whitespace() || c.is_control() { '_' } else { c }).collect();
    let n = coords.len() / 6;
    let mut out = String::with_capacity(64 * n + 64);
    let _ = writeln!(out, "# {name}: {n} rulings from ruledlab");
    let _ = writeln!(out, "o {name}");
    for p in coords.chunks_exact(3) {
        let _ = writeln!(out, "v {:?} {:?} {:?}", p[0], p[1], p[2]);
    }
    for i in 0..n {
        let _ = writeln!(out, "l {} {}", 2 * i + 1, 2 * i + 2);
    }
    if faces {
        for i in 0..n.saturating_sub(1) {
            let _ = writeln!(out, "f {} {} {} {}", 2 * i + 1, 2 * i + 2, 2 * i + 4, 2 * i + 3);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vertices_lines_and_quads() {
        let obj = write_obj(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.5, 1.0, 1.0], true, "my strip");
        assert_eq!(obj, "# my_strip: 2 rulings from ruledlab\no my_strip\nv 0.0 0.0 0.0\nv 1.0 0.0 0.0\nv 0.0 0.0 1.0\nv 0.5 1.0 1.0\nl 1 2\nl 3 4\nf 1 2 4 3\n");
        assert!(!write_obj(&[0.0; 12], false, "x").contains("\nf "));
    }
}
