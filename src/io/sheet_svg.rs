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
    }
}
