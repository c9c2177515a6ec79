//! A flat pattern laid out for cutting, in millimetres (beyond the paper): its pieces turned and
//! placed side by side on one sheet, each with its cut line, score lines and rulings, glue tabs and
//! labels, a check square, and the pages of the sheet printed on A4 or Letter paper.
//!
//! **Pieces on the sheet.** Each piece (see [`super::overlap`]) is scaled by the millimetres per
//! unit of the model, turned so that its longest extent — the principal axis of its outline's
//! points — runs along x, and placed in rows (the tallest first), the rows no wider than the widest
//! piece or about the square root of their total area, whichever is more. The check square of
//! [`CHECK_SQUARE_MM`] takes a place like a piece. Coordinates run from the sheet's lower left
//! corner, y up (an SVG writer turns them over).
//!
//! **What is drawn.** The cut line of each piece is its outline with its tabs, moved out by half the
//! kerf ([`super::outline`]). A ruling that the strip bends through more than the fold angle — the
//! angle between the planes of the faces on either side of it — is a *score* line, where the paper
//! is creased, as is each tab's base; the other rulings inside a piece are drawn thin, as a guide to
//! bending. The strip is glued where the pattern was split: a tab on the last ruling of a piece, its
//! letter on the tab and on the first ruling of the next piece; and, where the strip closes (its
//! last ruling is its first), a tab on the very last ruling with the first. A ruling of no length
//! (where two pieces only touch) has neither tab nor letter: there is nothing to glue.
//!
//! **Pages.** A sheet larger than the paper is printed in tiles: each page's printable area (the
//! paper less a margin on each side) shows a window of the sheet; neighbouring windows overlap by a
//! strip in whose middle registration marks sit, the same marks at the same places of the sheet on
//! both pages, so that laying one page over the next with the marks on each other puts the pattern
//! together.

use super::outline::{offset, outline, Side, Stroke};
use crate::error::{Error, Result};
use crate::msg;
use crate::ruled::RuledSurface;
use crate::tolerance::{
    CHECK_SQUARE_MM, MAX_KERF_MM, MAX_PAGES, MAX_PATTERN_SCALE, MAX_SHEET_MM, MAX_TAB_MM, ZERO_LENGTH_REL,
};
use glam::{DMat2, DVec2, DVec3};
use std::ops::Range;

/// How a pattern is laid out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SheetOptions {
    /// Millimetres per unit of the model.
    pub scale: f64,
    /// Glue tabs where the strip is glued (see the module).
    pub tabs: bool,
    /// A tab's width, millimetres.
    pub tab: f64,
    /// The kerf, millimetres: the cut line is the outline moved out by half of it (0: the outline).
    pub kerf: f64,
    /// Rulings the strip bends through more than this angle (radians) are score lines.
    pub fold_angle: f64,
    /// The free border round the sheet and between pieces, millimetres.
    pub margin: f64,
}

impl Default for SheetOptions {
    fn default() -> Self {
        SheetOptions { scale: 50.0, tabs: true, tab: 8.0, kerf: 0.0, fold_angle: 10f64.to_radians(), margin: 10.0 }
    }
}

/// A text on the sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct SheetLabel {
    /// Where its middle is, millimetres.
    pub at: DVec2,
    /// The direction of its baseline, radians from the x-axis (upright: within ±π/2).
    pub angle: f64,
    /// The height of its letters, millimetres.
    pub size: f64,
    /// What it says: a piece's number, a glue letter, or the check square's length.
    pub text: String,
}

/// One piece on the sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct SheetPiece {
    /// The rulings of the strip it holds: `rulings.start ..= rulings.end`.
    pub rulings: Range<usize>,
    /// Its outline with its tabs, counter-clockwise, millimetres.
    pub outline: Vec<DVec2>,
    /// The cut line: the outline moved out by half the kerf.
    pub cut: Vec<DVec2>,
    /// Score lines: tabs' bases and rulings bent more than the fold angle.
    pub score: Vec<Stroke>,
    /// The other rulings inside the piece.
    pub rulings_drawn: Vec<Stroke>,
    /// The motion from the pattern's coordinates (times the scale) to the sheet: a rotation by this
    /// angle, then this shift.
    pub rotation: f64,
    /// The shift after the rotation, millimetres.
    pub shift: DVec2,
}

/// A flat pattern laid out on a sheet (see the module).
#[derive(Debug, Clone, PartialEq)]
pub struct Sheet {
    /// Width and height, millimetres.
    pub size: DVec2,
    /// The pieces.
    pub pieces: Vec<SheetPiece>,
    /// The lower left corner of the check square (its side [`CHECK_SQUARE_MM`]).
    pub check_square: DVec2,
    /// Pieces' numbers, glue letters, the check square's length.
    pub labels: Vec<SheetLabel>,
}

/// The glue letter of join k: A … Z, then AA, AB, ….
fn letter(k: usize) -> String {
    let mut k = k;
    let mut out = Vec::new();
    loop {
        out.push(b'A' + (k % 26) as u8);
        if k < 26 {
            break;
        }
        k = k / 26 - 1;
    }
    out.reverse();
    String::from_utf8(out).expect("ASCII letters")
}

/// The angle through which the strip bends at each ruling: between the planes of the faces on
/// either side (0 at the end rulings). A face's plane is taken through its diagonals, which a skew
/// face also has.
pub fn bends(surface: &RuledSurface) -> Vec<f64> {
    let p = surface.points();
    let n = surface.len();
    let normal =
        |i: usize| -> Option<DVec3> { (p[2 * i + 3] - p[2 * i]).cross(p[2 * i + 2] - p[2 * i + 1]).try_normalize() };
    let normals: Vec<Option<DVec3>> = (0..n.saturating_sub(1)).map(normal).collect();
    (0..n)
        .map(|i| match (i.checked_sub(1).and_then(|k| normals[k]), normals.get(i).copied().flatten()) {
            (Some(m), Some(k)) => m.angle_between(k),
            _ => 0.0,
        })
        .collect()
}

/// Whether the strip closes: its last ruling is its first (the same ends, to rounding of its size).
pub fn closes(surface: &RuledSurface) -> bool {
    let p = surface.points();
    let n = p.len();
    let size = super::coplanar::size_of(p);
    n >= 6 && (p[n - 2] - p[0]).length() <= 1e-9 * size && (p[n - 1] - p[1]).length() <= 1e-9 * size
}

fn check_options(o: &SheetOptions) -> Result<()> {
    let check = |name: &'static str, value: f64, lo: f64, hi: f64| {
        if value.is_finite() && value >= lo && value <= hi {
            Ok(())
        } else {
            Err(Error::parameter(name, msg!("out-of-interval", value = value, min = lo, max = hi)))
        }
    };
    check("scale", o.scale, 1.0 / MAX_PATTERN_SCALE, MAX_PATTERN_SCALE)?;
    check("tab", o.tab, 0.0, MAX_TAB_MM)?;
    check("kerf", o.kerf, 0.0, MAX_KERF_MM)?;
    check("foldAngle", o.fold_angle, 0.0, std::f64::consts::PI)?;
    check("margin", o.margin, 0.0, MAX_TAB_MM)
}

/// The principal direction of a set of points: the angle of the eigenvector of their covariance
/// with the larger eigenvalue.
fn principal_angle(points: &[DVec2]) -> f64 {
    let mean = points.iter().copied().sum::<DVec2>() / points.len().max(1) as f64;
    let (mut xx, mut xy, mut yy) = (0.0, 0.0, 0.0);
    for p in points {
        let d = *p - mean;
        xx += d.x * d.x;
        xy += d.x * d.y;
        yy += d.y * d.y;
    }
    0.5 * (2.0 * xy).atan2(xx - yy)
}

impl Sheet {
    /// Lays out the pattern `points` (A_i, B_i per ruling, in the model's units) of `surface`, cut
    /// into `pieces` (ranges of rulings, as [`super::overlap::pieces`] makes them), on a sheet (see
    /// the module).
    pub fn lay_out(
        surface: &RuledSurface,
        points: &[DVec2],
        pieces: &[Range<usize>],
        options: &SheetOptions,
    ) -> Result<Sheet> {
        check_options(options)?;
        let n = surface.len();
        if points.len() != 2 * n {
            return Err(Error::parameter("points", msg!("pattern-points", need = 2 * n, got = points.len())));
        }
        let o = options;
        let scaled: Vec<DVec2> = points.iter().map(|p| *p * o.scale).collect();
        let merge = ZERO_LENGTH_REL * scaled.iter().fold(1.0f64, |m, p| m.max(p.length()));
        let bends = bends(surface);
        let closed = closes(surface);
        let count = pieces.len();
        // the joins: piece k's last ruling to piece k + 1's first, and the seam of a closed strip
        let joins = count - 1 + usize::from(closed);
        let mut laid = Vec::with_capacity(count);
        let mut labels = Vec::new();
        for (k, r) in pieces.iter().enumerate() {
            let mut tabs = Vec::new();
            if o.tabs && o.tab > 0.0 && k < joins {
                tabs.push(Side::Last);
            }
            let outline = outline(&scaled, r.start, r.end, &tabs, o.tab, merge);
            // turned along its principal axis on the sheet (see below)
            let rotation = -principal_angle(&outline.points);
            let mut score: Vec<Stroke> = outline.tab_bases.iter().map(|(s, _)| *s).collect();
            let mut thin = Vec::new();
            for i in r.start + 1..r.end {
                let stroke = Stroke { a: scaled[2 * i], b: scaled[2 * i + 1], ruling: Some(i) };
                if bends[i] > o.fold_angle {
                    score.push(stroke);
                } else {
                    thin.push(stroke);
                }
            }
            // the piece's own labels, in pattern coordinates: its number in its middle face (reading
            // along x on the sheet), the glue letters on its tab and on its first ruling
            let middle = (r.start + r.end) / 2;
            let face = middle.min(r.end.saturating_sub(1)).max(r.start);
            let centre = (scaled[2 * face] + scaled[2 * face + 1] + scaled[2 * face + 2] + scaled[2 * face + 3]) / 4.0;
            let mut own = vec![(centre, -rotation, 6.0, format!("{}", k + 1))];
            for (base, middle) in &outline.tab_bases {
                own.push((*middle, (base.b - base.a).to_angle(), 4.0, letter(k)));
            }
            let (a, b) = (scaled[2 * r.start], scaled[2 * r.start + 1]);
            // (a join on a ruling of no length has no tab to glue, nor a letter)
            if (k > 0 || closed) && (b - a).length() > merge {
                let join = if k > 0 { k - 1 } else { joins - 1 };
                let inward = (scaled[2 * r.start + 2] + scaled[2 * r.start + 3]) / 2.0 - (a + b) / 2.0;
                let at = (a + b) / 2.0 + inward.normalize_or_zero() * inward.length().min(4.0);
                own.push((at, (b - a).to_angle(), 4.0, letter(join)));
            }
            laid.push((r.clone(), outline.points, score, thin, own, rotation));
        }
        // turn each piece along its principal axis, then place the pieces in rows
        struct Item {
            rotation: f64,
            lo: DVec2,
            size: DVec2,
        }
        let mut items: Vec<Item> = laid
            .iter()
            .map(|&(_, ref outline, .., rotation)| {
                let m = DMat2::from_angle(rotation);
                let turned: Vec<DVec2> = outline.iter().map(|p| m * *p).collect();
                let lo = turned.iter().fold(DVec2::splat(f64::INFINITY), |a, p| a.min(*p));
                let hi = turned.iter().fold(DVec2::splat(f64::NEG_INFINITY), |a, p| a.max(*p));
                Item { rotation, lo, size: hi - lo }
            })
            .collect();
        // the check square and the line of text under it
        items.push(Item { rotation: 0.0, lo: DVec2::ZERO, size: DVec2::new(CHECK_SQUARE_MM, CHECK_SQUARE_MM + 8.0) });
        let gap = o.margin;
        let area: f64 = items.iter().map(|it| (it.size.x + gap) * (it.size.y + gap)).sum();
        let widest = items.iter().fold(0.0f64, |m, it| m.max(it.size.x));
        let row_width = widest.max(1.3 * area.sqrt());
        let mut order: Vec<usize> = (0..items.len()).collect();
        order.sort_by(|&a, &b| items[b].size.y.total_cmp(&items[a].size.y).then(a.cmp(&b)));
        let mut place = vec![DVec2::ZERO; items.len()];
        let (mut x, mut y, mut row_height) = (0.0f64, 0.0f64, 0.0f64);
        for &k in &order {
            let it = &items[k];
            if x > 0.0 && x + it.size.x > row_width {
                y += row_height + gap;
                x = 0.0;
                row_height = 0.0;
            }
            place[k] = DVec2::new(o.margin + x, o.margin + y);
            x += it.size.x + gap;
            row_height = row_height.max(it.size.y);
        }
        let mut size = DVec2::ZERO;
        for (k, it) in items.iter().enumerate() {
            size = size.max(place[k] + it.size + DVec2::splat(o.margin));
        }
        if size.x > MAX_SHEET_MM || size.y > MAX_SHEET_MM {
            return Err(Error::parameter(
                "scale",
                msg!("sheet-too-large", width = size.x, height = size.y, max = MAX_SHEET_MM),
            ));
        }
        let mut out = Vec::with_capacity(count);
        for (k, (rulings, outline_points, score, thin, own, _)) in laid.into_iter().enumerate() {
            let it = &items[k];
            let m = DMat2::from_angle(it.rotation);
            let shift = place[k] - it.lo;
            let map = |p: DVec2| m * p + shift;
            let stroke = |s: Stroke| Stroke { a: map(s.a), b: map(s.b), ruling: s.ruling };
            let outline: Vec<DVec2> = outline_points.iter().map(|p| map(*p)).collect();
            let cut = offset(&outline, o.kerf / 2.0);
            for (at, angle, size, text) in own {
                labels.push(SheetLabel { at: map(at), angle: upright(angle + it.rotation), size, text });
            }
            out.push(SheetPiece {
                rulings,
                outline,
                cut,
                score: score.into_iter().map(stroke).collect(),
                rulings_drawn: thin.into_iter().map(stroke).collect(),
                rotation: it.rotation,
                shift,
            });
        }
        let square = place[items.len() - 1] + DVec2::new(0.0, 8.0);
        labels.push(SheetLabel {
            at: square + DVec2::new(CHECK_SQUARE_MM / 2.0, -4.0),
            angle: 0.0,
            size: 4.0,
            text: format!("{} mm", CHECK_SQUARE_MM as u32),
        });
        Ok(Sheet { size, pieces: out, check_square: square, labels })
    }
}

/// An angle turned by π where needed so that text along it reads upright (within (−π/2, π/2]).
fn upright(angle: f64) -> f64 {
    let a = (angle + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI;
    if a > std::f64::consts::FRAC_PI_2 {
        a - std::f64::consts::PI
    } else if a <= -std::f64::consts::FRAC_PI_2 {
        a + std::f64::consts::PI
    } else {
        a
    }
}

/// A paper size, millimetres (portrait).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Paper {
    /// Width.
    pub width: f64,
    /// Height.
    pub height: f64,
}

impl Paper {
    /// ISO A4, 210 × 297 mm.
    pub const A4: Paper = Paper { width: 210.0, height: 297.0 };
    /// US Letter, 8.5 × 11 in.
    pub const LETTER: Paper = Paper { width: 215.9, height: 279.4 };
}

/// One page of a tiled print: the window of the sheet its printable area shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tile {
    /// Its column, from the left.
    pub column: usize,
    /// Its row, from the top.
    pub row: usize,
    /// The window's lower left corner on the sheet, millimetres.
    pub origin: DVec2,
}

/// A sheet printed on pages (see the module).
#[derive(Debug, Clone, PartialEq)]
pub struct Tiling {
    /// The paper.
    pub paper: Paper,
    /// The margin left blank on each side of a page, millimetres.
    pub margin: f64,
    /// How far neighbouring windows overlap, millimetres.
    pub overlap: f64,
    /// The window's width and height: the paper less the margins.
    pub window: DVec2,
    /// Columns and rows.
    pub columns: usize,
    /// Rows.
    pub rows: usize,
    /// The pages, row by row from the top, each row from the left.
    pub tiles: Vec<Tile>,
    /// The registration marks, on the sheet: in the middle of every overlap, at the crossings of
    /// the overlaps' middle lines (and on the sheet's outer strips, where a page has no neighbour).
    pub marks: Vec<DVec2>,
}

/// The pages of a `sheet` (its size) on `paper`, with `margin` blank on each page and windows
/// overlapping by `overlap` (see the module).
pub fn tile(sheet: DVec2, paper: Paper, margin: f64, overlap: f64) -> Result<Tiling> {
    let window = DVec2::new(paper.width, paper.height) - DVec2::splat(2.0 * margin);
    if !(margin >= 0.0 && overlap >= 0.0 && window.x > overlap && window.y > overlap && sheet.is_finite()) {
        return Err(Error::parameter("paper", msg!("paper-too-small", width = paper.width, height = paper.height)));
    }
    let step = window - DVec2::splat(overlap);
    let count = |length: f64, window: f64, step: f64| -> usize {
        if length <= window {
            1
        } else {
            ((length - window) / step).ceil() as usize + 1
        }
    };
    let (columns, rows) = (count(sheet.x, window.x, step.x), count(sheet.y, window.y, step.y));
    if columns.saturating_mul(rows) > MAX_PAGES {
        return Err(Error::TooMany { what: "pages", got: columns.saturating_mul(rows), max: MAX_PAGES });
    }
    let mut tiles = Vec::with_capacity(columns * rows);
    for row in 0..rows {
        for column in 0..columns {
            // row 0 at the top of the sheet
            let origin = DVec2::new(column as f64 * step.x, (rows - 1 - row) as f64 * step.y);
            tiles.push(Tile { column, row, origin });
        }
    }
    let xs: Vec<f64> = (0..=columns).map(|j| j as f64 * step.x + overlap / 2.0).collect();
    let ys: Vec<f64> = (0..=rows).map(|j| j as f64 * step.y + overlap / 2.0).collect();
    let marks = ys.iter().flat_map(|&y| xs.iter().map(move |&x| DVec2::new(x, y))).collect();
    Ok(Tiling { paper, margin, overlap, window, columns, rows, tiles, marks })
}

/// A sheet of two pieces, larger than A4, with numbers that tell its coordinates apart and carry
/// few decimals (exact in binary): what the writers' tests read back. One label, `label`.
#[cfg(test)]
pub(crate) fn two_pieces(label: SheetLabel) -> Sheet {
    let stroke = |a: (f64, f64), b: (f64, f64), ruling| Stroke { a: DVec2::from(a), b: DVec2::from(b), ruling };
    let piece = |k: f64| SheetPiece {
        rulings: 0..2,
        outline: vec![],
        cut: vec![DVec2::new(10.5 + k, 20.25), DVec2::new(60.125 + k, 21.0), DVec2::new(35.0 + k, 70.75)],
        score: vec![stroke((11.0 + k, 22.0), (33.5 + k, 44.25), None)],
        rulings_drawn: vec![stroke((12.0 + k, 23.0), (34.5, 45.25 + k), Some(7)), stroke((1.0, 2.0), (3.0, 4.0), None)],
        rotation: 0.0,
        shift: DVec2::ZERO,
    };
    Sheet {
        size: DVec2::new(310.5, 397.25),
        pieces: vec![piece(0.0), piece(100.0)],
        check_square: DVec2::new(7.5, 180.25),
        labels: vec![label],
    }
}

#[cfg(test)]
mod tests;
