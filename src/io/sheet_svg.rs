//! A flat pattern's sheet as SVG at 1:1 in millimetres (beyond the paper; the pattern is Section
//! 3's development of a developable strip, laid out by `developable::sheet`): what a plotter, a
//! cutting machine or a printer takes.
//!
//! The document is `width`×`height` mm with a viewBox of the same numbers, so one user unit is one
//! millimetre; the sheet's y runs up, SVG's down: a point (x, y) of the sheet is drawn at
//! (x, H − y). Each kind of line has its own group and stroke, so a cutter's software can map
//! them to tools: `cut` (red, solid: the cut line with its tabs, moved out by half the kerf),
//! `score` (blue, dashed: folds and the tabs' bases), `rulings` (grey, thin: the rulings a
//! bent strip passes through), `labels` (piece numbers and glue letters) and the check square
//! `check-square` (black, [`CHECK_SQUARE_MM`] a side; measure it on the print). Every path and
//! line has an id (`cut-k`, `score-k-j`, `ruling-i`) by which a reader finds it.
//!
//! A tiled print ([`page_svg`]) is one SVG per page of the paper: the window of the sheet that page
//! shows, clipped to the printable area, with registration marks (a circle and a cross) at the
//! tiling's marks and the page's place, "row, column", in its bottom margin.

use crate::developable::sheet::{Sheet, Tiling};
use crate::tolerance::CHECK_SQUARE_MM;
use glam::DVec2;
use std::fmt::Write;

/// `x` with `decimals` decimals (at most 9), rounded half away from zero, no "-0": written from an
/// integer, not by the float formatter (whose exact mode would add its tables to the wasm module).
/// For |x| · 10^decimals below 2⁶³ (a sheet is at most 10 m).
pub(crate) fn fixed(x: f64, decimals: u32) -> String {
    let scale = 10i64.pow(decimals);
    let scaled = (x * scale as f64).round();
    if !scaled.is_finite() || scaled.abs() >= 9.2e18 {
        return "0".into();
    }
    let scaled = scaled as i64;
    let (sign, units) = (if scaled < 0 { "-" } else { "" }, scaled.unsigned_abs());
    let (whole, frac) = (units / scale as u64, units % scale as u64);
    if decimals == 0 {
        format!("{sign}{whole}")
    } else {
        format!("{sign}{whole}.{frac:0width$}", width = decimals as usize)
    }
}

/// A number for SVG: at most four decimals (0.1 µm), no trailing zeros, no "-0".
pub(crate) fn num(x: f64) -> String {
    let s = fixed(x, 4);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" || s.is_empty() {
        "0".into()
    } else {
        s.into()
    }
}

/// `text` with XML's special characters escaped.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The sheet's drawing in SVG user units (millimetres, y down), without the `<svg>` element.
fn body(sheet: &Sheet) -> String {
    let h = sheet.size.y;
    let p = |q: DVec2| format!("{} {}", num(q.x), num(h - q.y));
    let mut out = String::new();
    out.push_str("<g id=\"cut\" fill=\"none\" stroke=\"#e00000\" stroke-width=\"0.2\" stroke-linejoin=\"round\">\n");
    for (k, piece) in sheet.pieces.iter().enumerate() {
        let mut d = String::new();
        for (j, q) in piece.cut.iter().enumerate() {
            let _ = write!(d, "{}{} ", if j == 0 { "M" } else { "L" }, p(*q));
        }
        let _ = writeln!(out, "<path id=\"cut-{k}\" d=\"{d}Z\"/>");
    }
    out.push_str(
        "</g>\n<g id=\"score\" fill=\"none\" stroke=\"#0050e0\" stroke-width=\"0.2\" stroke-dasharray=\"3 1.5\">\n",
    );
    for (k, piece) in sheet.pieces.iter().enumerate() {
        for (j, s) in piece.score.iter().enumerate() {
            let _ = writeln!(
                out,
                "<line id=\"score-{k}-{j}\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>",
                num(s.a.x),
                num(h - s.a.y),
                num(s.b.x),
                num(h - s.b.y)
            );
        }
    }
    out.push_str("</g>\n<g id=\"rulings\" fill=\"none\" stroke=\"#808080\" stroke-width=\"0.1\">\n");
    for piece in &sheet.pieces {
        for s in &piece.rulings_drawn {
            let id = s.ruling.map(|i| format!(" id=\"ruling-{i}\"")).unwrap_or_default();
            let _ = writeln!(
                out,
                "<line{id} x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>",
                num(s.a.x),
                num(h - s.a.y),
                num(s.b.x),
                num(h - s.b.y)
            );
        }
    }
    out.push_str("</g>\n<g id=\"labels\" font-family=\"sans-serif\" fill=\"#000000\" text-anchor=\"middle\">\n");
    for label in &sheet.labels {
        let (x, y) = (num(label.at.x), num(h - label.at.y));
        // SVG turns clockwise for a positive angle (y down): the sheet's counter-clockwise angle negated
        let _ = writeln!(
            out,
            "<text x=\"{x}\" y=\"{y}\" font-size=\"{}\" dominant-baseline=\"central\" transform=\"rotate({} {x} {y})\">{}</text>",
            num(label.size),
            num(-label.angle.to_degrees()),
            escape(&label.text)
        );
    }
    let c = sheet.check_square;
    let _ = writeln!(
        out,
        "</g>\n<rect id=\"check-square\" x=\"{}\" y=\"{}\" width=\"{s}\" height=\"{s}\" fill=\"none\" stroke=\"#000000\" stroke-width=\"0.2\"/>",
        num(c.x),
        num(h - c.y - CHECK_SQUARE_MM),
        s = num(CHECK_SQUARE_MM)
    );
    out
}

/// The sheet as one SVG at 1:1 in millimetres (see the module).
pub fn sheet_svg(sheet: &Sheet) -> String {
    let (w, h) = (num(sheet.size.x), num(sheet.size.y));
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\">\n{}</svg>\n",
        body(sheet)
    )
}

/// Page `index` of a tiled print of the sheet (see the module): an SVG of the paper's size, in
/// millimetres. `index` must be below `tiling.tiles.len()`.
pub fn page_svg(sheet: &Sheet, tiling: &Tiling, index: usize) -> String {
    let tile = tiling.tiles[index];
    let (pw, ph) = (num(tiling.paper.width), num(tiling.paper.height));
    let m = tiling.margin;
    let win = tiling.window;
    // the window's top left corner in the sheet's SVG coordinates (y down)
    let top = sheet.size.y - tile.origin.y - win.y;
    let (dx, dy) = (m - tile.origin.x, m - top);
    let mut out = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{pw}mm\" height=\"{ph}mm\" viewBox=\"0 0 {pw} {ph}\">\n"
    );
    let _ = writeln!(
        out,
        "<clipPath id=\"window\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>",
        num(m),
        num(m),
        num(win.x),
        num(win.y)
    );
    let _ = writeln!(out, "<g clip-path=\"url(#window)\">\n<g transform=\"translate({} {})\">", num(dx), num(dy));
    out.push_str(&body(sheet));
    out.push_str("<g id=\"registration\" fill=\"none\" stroke=\"#000000\" stroke-width=\"0.15\">\n");
    for mark in &tiling.marks {
        let (x, y) = (mark.x, sheet.size.y - mark.y);
        let _ = writeln!(
            out,
            "<circle cx=\"{}\" cy=\"{}\" r=\"3\"/><path d=\"M{} {}h10M{} {}v10\"/>",
            num(x),
            num(y),
            num(x - 5.0),
            num(y),
            num(x),
            num(y - 5.0)
        );
    }
    out.push_str("</g>\n</g>\n</g>\n");
    let _ = writeln!(
        out,
        "<text x=\"{}\" y=\"{}\" font-family=\"sans-serif\" font-size=\"3.5\" text-anchor=\"middle\">{} / {} · {}, {}</text>",
        num(tiling.paper.width / 2.0),
        num(tiling.paper.height - m / 2.0),
        index + 1,
        tiling.tiles.len(),
        tile.row + 1,
        tile.column + 1
    );
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_never_negative_zero() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(-0.00001), "0");
        assert_eq!(num(12.345678), "12.3457");
        assert_eq!(num(-2.5), "-2.5");
        assert_eq!(num(0.00005), "0.0001");
        assert_eq!(num(-1234.56789), "-1234.5679");
        assert_eq!(fixed(2.0, 0), "2");
        assert_eq!(fixed(-0.000001, 6), "-0.000001");
        assert_eq!(escape("a<b&\"c\">"), "a&lt;b&amp;&quot;c&quot;&gt;");
        // zero has no sign; what is not finite, or beyond 2⁶³ units, is written as 0
        assert_eq!(fixed(0.0, 2), "0.00");
        assert_eq!(fixed(-0.0, 0), "0");
        assert_eq!(fixed(-3.0, 0), "-3");
        assert_eq!(fixed(f64::NAN, 3), "0");
        assert_eq!(fixed(-f64::INFINITY, 3), "0");
        assert_eq!(fixed(1e300, 1), "0");
        assert_eq!(fixed(9.1e14, 4), "910000000000000.0000");
        assert_eq!((num(f64::NAN), num(1e300), num(0.0)), ("0".into(), "0".into(), "0".into()));
    }

    use crate::developable::outline::Stroke;
    use crate::developable::sheet::{tile, two_pieces, Paper, SheetLabel};

    /// The writers' sheet of two pieces, its label with a character XML escapes.
    fn sheet() -> Sheet {
        two_pieces(SheetLabel { at: DVec2::new(40.0, 50.5), angle: 0.5, size: 4.25, text: "B<2".into() })
    }

    /// The numbers of attribute `name` of the elements whose tag starts `tag` (with its id's
    /// prefix, if any), in order.
    fn attribute(svg: &str, tag: &str, name: &str) -> Vec<f64> {
        svg.split('<')
            .filter(|e| e.starts_with(tag))
            .map(|e| {
                let from = e.find(&format!(" {name}=\"")).unwrap_or_else(|| panic!("{name} in {e}")) + name.len() + 3;
                e[from..from + e[from..].find('"').unwrap()].parse().unwrap()
            })
            .collect()
    }

    #[test]
    fn the_drawing_read_back_is_the_sheet_with_y_turned_down() {
        let sheet = sheet();
        let svg = sheet_svg(&sheet);
        let h = sheet.size.y;
        assert!(svg.contains("width=\"310.5mm\" height=\"397.25mm\" viewBox=\"0 0 310.5 397.25\""));
        // the cut lines: M x y L x y … Z, each point (x, H − y)
        for (k, piece) in sheet.pieces.iter().enumerate() {
            let tag = format!("path id=\"cut-{k}\" d=\"");
            let e = svg.split('<').find(|e| e.starts_with(&tag)).unwrap();
            let d = &e[tag.len()..e.find(" Z").unwrap_or_else(|| e.find('Z').unwrap())];
            let numbers: Vec<f64> =
                d.split([' ', 'M', 'L']).filter(|t| !t.is_empty()).map(|t| t.parse().unwrap()).collect();
            let expected: Vec<f64> = piece.cut.iter().flat_map(|q| [q.x, h - q.y]).collect();
            assert_eq!(numbers, expected, "cut-{k}");
        }
        // score lines and rulings, in order, the ruling with its index as id
        let strokes: Vec<&Stroke> = sheet.pieces.iter().flat_map(|p| &p.score).collect();
        let rulings: Vec<&Stroke> = sheet.pieces.iter().flat_map(|p| &p.rulings_drawn).collect();
        for (tag, want) in [("line id=\"score-", &strokes), ("line", &rulings)] {
            let only = |name| -> Vec<f64> {
                let all = attribute(&svg, tag, name);
                // "line" alone matches the score lines too: the rulings are the last ones
                all[all.len() - want.len()..].to_vec()
            };
            assert_eq!(only("x1"), want.iter().map(|s| s.a.x).collect::<Vec<_>>());
            assert_eq!(only("y1"), want.iter().map(|s| h - s.a.y).collect::<Vec<_>>());
            assert_eq!(only("x2"), want.iter().map(|s| s.b.x).collect::<Vec<_>>());
            assert_eq!(only("y2"), want.iter().map(|s| h - s.b.y).collect::<Vec<_>>());
        }
        assert!(svg.contains("<line id=\"score-1-0\""));
        assert_eq!(svg.matches("<line id=\"ruling-7\"").count(), 2);
        // the check square: its lower left corner at (x, H − y), drawn from its upper left one
        let q = sheet.check_square;
        assert_eq!(attribute(&svg, "rect id=\"check-square", "x"), [q.x]);
        assert_eq!(attribute(&svg, "rect id=\"check-square", "y"), [h - q.y - CHECK_SQUARE_MM]);
        assert_eq!(attribute(&svg, "rect id=\"check-square", "width"), [CHECK_SQUARE_MM]);
        // the label: at (x, H − y), turned clockwise by the angle in degrees, its text escaped
        assert_eq!(attribute(&svg, "text", "x"), [40.0]);
        assert_eq!(attribute(&svg, "text", "y"), [h - 50.5]);
        assert_eq!(attribute(&svg, "text", "font-size"), [4.25]);
        let degrees = num(-0.5f64.to_degrees());
        assert!(svg.contains(&format!("transform=\"rotate({degrees} 40 {})\">B&lt;2</text>", num(h - 50.5))));
    }

    #[test]
    fn each_page_shows_its_window_in_the_printable_area_with_the_marks_where_they_are_on_the_sheet() {
        let sheet = sheet();
        let tiling = tile(sheet.size, Paper::A4, 10.0, 12.0).unwrap();
        assert!(tiling.tiles.len() >= 4);
        let h = sheet.size.y;
        for (index, t) in tiling.tiles.iter().enumerate() {
            let page = page_svg(&sheet, &tiling, index);
            assert!(page.contains("width=\"210mm\" height=\"297mm\" viewBox=\"0 0 210 297\""));
            assert_eq!(attribute(&page, "rect x", "width"), [tiling.window.x]);
            assert_eq!(attribute(&page, "rect x", "height"), [tiling.window.y]);
            assert_eq!(attribute(&page, "rect x", "x"), [10.0]);
            assert_eq!(attribute(&page, "rect x", "y"), [10.0]);
            // the window's upper left corner on the sheet, (origin.x, origin.y + window.y), drawn
            // at (x, H − y), lands on the printable area's upper left corner (margin, margin)
            let e = page.split("translate(").nth(1).unwrap();
            let shift: Vec<f64> = e[..e.find(')').unwrap()].split(' ').map(|t| t.parse().unwrap()).collect();
            let corner = DVec2::new(t.origin.x, h - (t.origin.y + tiling.window.y));
            assert!(
                (corner.x + shift[0] - 10.0).abs() < 1e-4 && (corner.y + shift[1] - 10.0).abs() < 1e-4,
                "{shift:?}"
            );
            // every mark: a circle at (x, H − y) and a cross of 10 mm centred on it
            // (to the 4 decimals written)
            let near = |got: Vec<f64>, want: Vec<f64>| {
                assert_eq!(got.len(), want.len());
                assert!(got.iter().zip(&want).all(|(a, b)| (a - b).abs() <= 5e-5), "{got:?} vs {want:?}");
            };
            near(attribute(&page, "circle", "cx"), tiling.marks.iter().map(|m| m.x).collect());
            near(attribute(&page, "circle", "cy"), tiling.marks.iter().map(|m| h - m.y).collect());
            for m in &tiling.marks {
                let (x, y) = (m.x, h - m.y);
                let cross = format!("d=\"M{} {}h10M{} {}v10\"", num(x - 5.0), num(y), num(x), num(y - 5.0));
                assert!(page.contains(&cross), "{cross}");
            }
            // the page's place, centred in its bottom margin
            let place = format!("{} / {} · {}, {}</text>", index + 1, tiling.tiles.len(), t.row + 1, t.column + 1);
            assert!(
                page.contains(&format!(
                    "x=\"105\" y=\"292\" font-family=\"sans-serif\" font-size=\"3.5\" text-anchor=\"middle\">{place}"
                )),
                "{place}"
            );
        }
    }
}
