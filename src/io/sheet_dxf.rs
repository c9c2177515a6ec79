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
    use crate::developable::outline::Stroke;
    use crate::developable::sheet::{two_pieces, SheetLabel};

    /// The writers' sheet of two pieces, its label with a control character (not written).
    fn sheet() -> Sheet {
        two_pieces(SheetLabel { at: DVec2::new(40.0, 50.5), angle: -0.5, size: 4.25, text: "A\u{7}1".into() })
    }

    /// The file's entities as (type, its group codes and values in order), read as a reader does:
    /// a code on one line, its value on the next.
    fn entities(dxf: &str) -> Vec<(String, Vec<(u16, String)>)> {
        let lines: Vec<&str> = dxf.lines().collect();
        assert_eq!(lines.len() % 2, 0);
        let mut out: Vec<(String, Vec<(u16, String)>)> = Vec::new();
        for pair in lines.chunks(2) {
            let code: u16 = pair[0].trim().parse().unwrap();
            if code == 0 {
                out.push((pair[1].to_string(), vec![]));
            } else {
                out.last_mut().unwrap().1.push((code, pair[1].to_string()));
            }
        }
        out
    }

    /// The number of group `code` in `groups` (the first, or the n-th with `nth`).
    fn number(groups: &[(u16, String)], code: u16, nth: usize) -> f64 {
        groups.iter().filter(|(c, _)| *c == code).nth(nth).unwrap().1.parse().unwrap()
    }

    fn text(groups: &[(u16, String)], code: u16) -> &str {
        &groups.iter().find(|(c, _)| *c == code).unwrap().1
    }

    #[test]
    fn the_file_read_back_gives_the_sheets_geometry() {
        let sheet = sheet();
        let all = entities(&sheet_dxf(&sheet));
        let close = |a: f64, b: f64| assert!((a - b).abs() <= 1e-6, "{a} vs {b}");
        // the header: R12 and the sheet's extents
        let header = &all[0].1;
        assert_eq!(text(header, 2), "HEADER");
        assert_eq!(text(header, 1), "AC1009");
        close(number(header, 10, 1), 310.5);
        close(number(header, 20, 1), 397.25);
        assert_eq!((number(header, 10, 0), number(header, 20, 0)), (0.0, 0.0));
        // the layers, with their colours
        let layers: Vec<(String, f64)> =
            all.iter().filter(|(t, _)| t == "LAYER").map(|(_, g)| (text(g, 2).to_string(), number(g, 62, 0))).collect();
        assert_eq!(
            layers,
            [("CUT", 1.0), ("SCORE", 5.0), ("RULING", 8.0), ("TEXT", 7.0), ("CHECK", 3.0)]
                .map(|(n, c)| (n.to_string(), c))
        );
        let table = all.iter().find(|(t, g)| t == "TABLE" && text(g, 2) == "LAYER").unwrap();
        assert_eq!(number(&table.1, 70, 0), 5.0);
        // polylines: their layer and their vertices, in order, closed
        let mut polylines: Vec<(String, Vec<DVec2>)> = Vec::new();
        let mut lines: Vec<(String, DVec2, DVec2)> = Vec::new();
        for (kind, g) in &all {
            match kind.as_str() {
                "POLYLINE" => {
                    assert_eq!((number(g, 66, 0), number(g, 70, 0)), (1.0, 1.0), "vertices follow; closed");
                    polylines.push((text(g, 8).to_string(), vec![]));
                }
                "VERTEX" => {
                    let last = polylines.last_mut().unwrap();
                    assert_eq!(text(g, 8), last.0);
                    last.1.push(DVec2::new(number(g, 10, 0), number(g, 20, 0)));
                }
                "LINE" => lines.push((
                    text(g, 8).to_string(),
                    DVec2::new(number(g, 10, 0), number(g, 20, 0)),
                    DVec2::new(number(g, 11, 0), number(g, 21, 0)),
                )),
                _ => {}
            }
        }
        let s = CHECK_SQUARE_MM;
        let q = sheet.check_square;
        let square = vec![q, q + DVec2::new(s, 0.0), q + DVec2::new(s, s), q + DVec2::new(0.0, s)];
        let expected: Vec<(String, Vec<DVec2>)> = sheet
            .pieces
            .iter()
            .map(|p| ("CUT".to_string(), p.cut.clone()))
            .chain([("CHECK".to_string(), square)])
            .collect();
        assert_eq!(polylines.len(), expected.len());
        for ((layer, got), (want_layer, want)) in polylines.iter().zip(&expected) {
            assert_eq!(layer, want_layer);
            assert_eq!(got.len(), want.len());
            for (a, b) in got.iter().zip(want) {
                close(a.x, b.x);
                close(a.y, b.y);
            }
        }
        let expected: Vec<(&str, &Stroke)> = sheet
            .pieces
            .iter()
            .flat_map(|p| p.score.iter().map(|s| ("SCORE", s)).chain(p.rulings_drawn.iter().map(|s| ("RULING", s))))
            .collect();
        assert_eq!(lines.len(), expected.len());
        for ((layer, a, b), (want_layer, s)) in lines.iter().zip(&expected) {
            assert_eq!(layer, want_layer);
            for (got, want) in [(a, s.a), (b, s.b)] {
                close(got.x, want.x);
                close(got.y, want.y);
            }
        }
        // the text: centred on its point, its height, its angle in degrees, no control characters
        let label = &all.iter().find(|(t, _)| t == "TEXT").unwrap().1;
        assert_eq!(text(label, 8), "TEXT");
        assert_eq!(text(label, 1), "A1");
        close(number(label, 10, 0), 40.0);
        close(number(label, 20, 0), 50.5);
        close(number(label, 11, 0), 40.0);
        close(number(label, 21, 0), 50.5);
        close(number(label, 40, 0), 4.25);
        close(number(label, 50, 0), -0.5f64.to_degrees());
        assert_eq!((number(label, 72, 0), number(label, 73, 0)), (1.0, 2.0));
        assert_eq!(all.last().unwrap().0, "EOF");
    }

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
