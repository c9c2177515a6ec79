//! A flat pattern's sheet as DXF R12 (AC1009), millimetres, for laser cutters and CAD (beyond the
//! paper; the pattern is Section 3's development of a developable strip, laid out by
//! `developable::sheet`).
//!
//! R12 is the version every cutter's software reads. The file has a header (the version and the
//! drawing's extents), a layer table and the entities, in the sheet's coordinates (x right, y up,
//! millimetres; R12 has no unit variable, so the unit is stated here and in the layer names'
//! documentation):
//!
//! - `CUT` (red): each piece's cut line (the outline with its tabs, moved out by half the kerf) as
//!   one closed POLYLINE of VERTEX entities;
//! - `SCORE` (blue): folds and tabs' bases, LINE entities, to be scored or engraved, not cut;
//! - `RULING` (grey): the other rulings, LINE entities (a guide, usually switched off);
//! - `TEXT` (white/black): piece numbers and glue letters, TEXT entities;
//! - `CHECK` (green): the check square, a closed POLYLINE [`CHECK_SQUARE_MM`] a side.

use crate::developable::sheet::Sheet;
use crate::tolerance::CHECK_SQUARE_MM;
use glam::DVec2;
use std::fmt::Write;

/// The layers: name and ACI colour.
const LAYERS: [(&str, u8); 5] = [("CUT", 1), ("SCORE", 5), ("RULING", 8), ("TEXT", 7), ("CHECK", 3)];

/// One group code and its value.
fn pair(out: &mut String, code: u16, value: impl std::fmt::Display) {
    let _ = write!(out, "{code:>3}\n{value}\n");
}

/// A coordinate: six decimals (a nanometre).
fn c(x: f64) -> String {
    let s = crate::io::sheet_svg::fixed(x, 6);
    if s.trim_start_matches('-').chars().all(|ch| ch == '0' || ch == '.') {
        "0.0".into()
    } else {
        s
    }
}

fn polyline(out: &mut String, layer: &str, points: &[DVec2]) {
    pair(out, 0, "POLYLINE");
    pair(out, 8, layer);
    pair(out, 66, 1);
    pair(out, 10, "0.0");
    pair(out, 20, "0.0");
    pair(out, 30, "0.0");
    pair(out, 70, 1);
    for p in points {
        pair(out, 0, "VERTEX");
        pair(out, 8, layer);
        pair(out, 10, c(p.x));
        pair(out, 20, c(p.y));
        pair(out, 30, "0.0");
    }
    pair(out, 0, "SEQEND");
    pair(out, 8, layer);
}

fn line(out: &mut String, layer: &str, a: DVec2, b: DVec2) {
    pair(out, 0, "LINE");
    pair(out, 8, layer);
    pair(out, 10, c(a.x));
    pair(out, 20, c(a.y));
    pair(out, 30, "0.0");
    pair(out, 11, c(b.x));
    pair(out, 21, c(b.y));
    pair(out, 31, "0.0");
}

/// The sheet as DXF R12 (see the module).
pub fn sheet_dxf(sheet: &Sheet) -> String {
    let mut out = String::new();
    pair(&mut out, 0, "SECTION");
    pair(&mut out, 2, "HEADER");
    pair(&mut out, 9, "$ACADVER");
    pair(&mut out, 1, "AC1009");
    pair(&mut out, 9, "$EXTMIN");
    pair(&mut out, 10, "0.0");
    pair(&mut out, 20, "0.0");
    pair(&mut out, 9, "$EXTMAX");
    pair(&mut out, 10, c(sheet.size.x));
    pair(&mut out, 20, c(sheet.size.y));
    pair(&mut out, 0, "ENDSEC");
    pair(&mut out, 0, "SECTION");
    pair(&mut out, 2, "TABLES");
    pair(&mut out, 0, "TABLE");
    pair(&mut out, 2, "LTYPE");
    pair(&mut out, 70, 1);
    pair(&mut out, 0, "LTYPE");
    pair(&mut out, 2, "CONTINUOUS");
    pair(&mut out, 70, 0);
    pair(&mut out, 3, "Solid line");
    pair(&mut out, 72, 65);
    pair(&mut out, 73, 0);
    pair(&mut out, 40, "0.0");
    pair(&mut out, 0, "ENDTAB");
    pair(&mut out, 0, "TABLE");
    pair(&mut out, 2, "LAYER");
    pair(&mut out, 70, LAYERS.len());
    for (name, colour) in LAYERS {
        pair(&mut out, 0, "LAYER");
        pair(&mut out, 2, name);
        pair(&mut out, 70, 0);
        pair(&mut out, 62, colour);
        pair(&mut out, 6, "CONTINUOUS");
    }
    pair(&mut out, 0, "ENDTAB");
    pair(&mut out, 0, "ENDSEC");
    pair(&mut out, 0, "SECTION");
    pair(&mut out, 2, "ENTITIES");
    for piece in &sheet.pieces {
        polyline(&mut out, "CUT", &piece.cut);
        for s in &piece.score {
            line(&mut out, "SCORE", s.a, s.b);
        }
        for s in &piece.rulings_drawn {
            line(&mut out, "RULING", s.a, s.b);
        }
    }
    for label in &sheet.labels {
        // TEXT is placed by its start; centred (72 = 1, 73 = 2) it is placed by the second point
        let text: String = label.text.chars().filter(|ch| !ch.is_control()).collect();
        pair(&mut out, 0, "TEXT");
        pair(&mut out, 8, "TEXT");
        pair(&mut out, 10, c(label.at.x));
        pair(&mut out, 20, c(label.at.y));
        pair(&mut out, 30, "0.0");
        pair(&mut out, 40, c(label.size));
        pair(&mut out, 1, text);
        pair(&mut out, 50, c(label.angle.to_degrees()));
        pair(&mut out, 72, 1);
        pair(&mut out, 11, c(label.at.x));
        pair(&mut out, 21, c(label.at.y));
        pair(&mut out, 31, "0.0");
        pair(&mut out, 73, 2);
    }
    let q = sheet.check_square;
    let s = CHECK_SQUARE_MM;
    polyline(&mut out, "CHECK", &[q, q + DVec2::new(s, 0.0), q + DVec2::new(s, s), q + DVec2::new(0.0, s)]);
    pair(&mut out, 0, "ENDSEC");
    pair(&mut out, 0, "EOF");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coordinates_have_six_decimals_and_no_negative_zero() {
        assert_eq!(c(1.0), "1.000000");
        assert_eq!(c(-0.0000001), "0.0");
        assert_eq!(c(-2.5), "-2.500000");
        let mut s = String::new();
        pair(&mut s, 0, "LINE");
        assert_eq!(s, "  0\nLINE\n");
    }
}
