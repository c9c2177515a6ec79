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
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::developable::construct::{cone, Span};
    use crate::developable::outline::perimeter;
    use crate::developable::overlap::{overlapping_faces, pieces};
    use crate::developable::unfold::Unfolding;
    use std::f64::consts::TAU;

    /// A right circular cone all round (radius 1, height 2, 24 rulings, the last one the first).
    fn full_cone() -> RuledSurface {
        let c: Vec<DVec3> = (0..=24)
            .map(|i| {
                let u = TAU * i as f64 / 24.0;
                DVec3::new(u.cos(), u.sin(), 0.0)
            })
            .collect();
        cone(&c, DVec3::new(0.0, 0.0, 2.0), Span { from: 0.3, to: 1.0 }).unwrap()
    }

    #[test]
    fn a_closed_cone_is_one_piece_with_a_tab_on_its_seam() {
        let s = full_cone();
        assert!(closes(&s));
        let flat = Unfolding::of(&s).unwrap();
        let overlaps = overlapping_faces(&flat.points);
        let parts = pieces(&flat.points, &overlaps);
        assert_eq!(parts, std::slice::from_ref(&(0..24)));
        // every interior ruling bends by the dihedral angle β of the regular pyramid:
        // cos β = (H² cos(2π/N) + r²)/(H² + r²), r = R cos(π/N) the base polygon's inradius
        let (h, r) = (2.0f64, (std::f64::consts::PI / 24.0).cos());
        let beta = ((h * h * (TAU / 24.0).cos() + r * r) / (h * h + r * r)).acos();
        for b in &bends(&s)[1..24] {
            assert_near!(*b, beta, 1e-12);
        }
        let o = SheetOptions { scale: 40.0, fold_angle: 1.01 * beta, ..SheetOptions::default() };
        let sheet = Sheet::lay_out(&s, &flat.points, &parts, &o).unwrap();
        assert_eq!(sheet.pieces.len(), 1);
        let piece = &sheet.pieces[0];
        // the seam's tab: its base is the last ruling, scored; "A" on the tab and on the first ruling
        let bases: Vec<&Stroke> = piece.score.iter().filter(|s| s.ruling == Some(24)).collect();
        assert_eq!(bases.len(), 1);
        assert_near!((bases[0].b - bases[0].a).length(), 40.0 * s.segment(24).length(), 1e-9);
        assert_eq!(sheet.labels.iter().filter(|l| l.text == "A").count(), 2);
        // bent by less than the fold angle: drawn thin
        assert_eq!(piece.rulings_drawn.len(), 23);
        for stroke in &piece.rulings_drawn {
            let i = stroke.ruling.unwrap();
            assert_near!((stroke.b - stroke.a).length(), 40.0 * s.segment(i).length(), 1e-9);
        }
        // everything on the sheet, the check square too
        let inside = |p: DVec2| p.x >= 0.0 && p.y >= 0.0 && p.x <= sheet.size.x && p.y <= sheet.size.y;
        assert!(piece.cut.iter().all(|p| inside(*p)));
        assert!(inside(sheet.check_square) && inside(sheet.check_square + DVec2::splat(CHECK_SQUARE_MM)));
    }

    /// The layout is a rigid motion of the scaled pattern: every ruling keeps its length and the
    /// outline its perimeter; with a kerf the cut line runs outside the outline by half of it.
    #[test]
    fn the_layout_keeps_lengths_and_the_kerf_moves_the_cut_out() {
        let s = full_cone();
        let flat = Unfolding::of(&s).unwrap();
        let o = SheetOptions { scale: 25.0, tabs: false, kerf: 0.4, fold_angle: 0.05, ..SheetOptions::default() };
        let sheet = Sheet::lay_out(&s, &flat.points, std::slice::from_ref(&(0..24)), &o).unwrap();
        let piece = &sheet.pieces[0];
        assert_eq!(piece.score.len(), 23, "every interior ruling bends more than 0.05 rad");
        for (stroke, i) in piece.score.iter().zip(1..24) {
            assert_eq!(stroke.ruling, Some(i));
            assert_near!((stroke.b - stroke.a).length(), 25.0 * s.segment(i).length(), 1e-9);
        }
        // every corner of the pattern, moved by the piece's motion, is a corner of its outline
        let m = DMat2::from_angle(piece.rotation);
        for p in &flat.points {
            let on_sheet = m * (*p * 25.0) + piece.shift;
            assert!(piece.outline.iter().any(|q| (*q - on_sheet).length() < 1e-9), "{on_sheet:?}");
        }
        let outline = perimeter(&piece.outline);
        let cut = perimeter(&piece.cut);
        // a convex-ish outline: the offset adds about 2π · 0.2 and the bevels, never less
        assert!(cut > outline && cut < outline + TAU * 0.2 * 1.5, "{outline} {cut}");
    }

    #[test]
    fn pages_overlap_and_share_their_registration_marks() {
        let t = tile(DVec2::new(500.0, 400.0), Paper::A4, 10.0, 10.0).unwrap();
        assert_eq!(t.window, DVec2::new(190.0, 277.0));
        assert_eq!((t.columns, t.rows), (3, 2));
        assert_eq!(t.tiles.len(), 6);
        // the windows cover the sheet
        let last = t.tiles.iter().fold(DVec2::ZERO, |m, tile| m.max(tile.origin + t.window));
        assert!(last.x >= 500.0 && last.y >= 400.0);
        // each mark inside two neighbouring windows is on both
        let shows = |tile: &Tile, m: DVec2| {
            m.x >= tile.origin.x
                && m.y >= tile.origin.y
                && m.x <= tile.origin.x + t.window.x
                && m.y <= tile.origin.y + t.window.y
        };
        let (left, right) = (&t.tiles[0], &t.tiles[1]);
        let shared: Vec<&DVec2> = t.marks.iter().filter(|m| shows(left, **m) && shows(right, **m)).collect();
        assert_eq!(shared.len(), 2, "{shared:?}");
        for tile in &t.tiles {
            assert!(t.marks.iter().filter(|m| shows(tile, **m)).count() >= 4);
        }
        assert!(tile(DVec2::new(100.0, 100.0), Paper { width: 20.0, height: 20.0 }, 10.0, 10.0).is_err());
        let huge = tile(DVec2::new(20000.0, 20000.0), Paper::A4, 10.0, 10.0).unwrap_err();
        assert_eq!(huge.code(), "too-large");
    }

    /// Two pieces joined at a ruling: a tab and the letter "A" twice; where the flat points give
    /// that ruling no length (the pieces only touch), neither.
    #[test]
    fn a_join_on_a_ruling_of_no_length_has_no_tab_and_no_letter() {
        let s = RuledSurface::from_points(
            (0..5).flat_map(|i| [DVec3::new(i as f64, 0.0, 0.0), DVec3::new(i as f64, 1.0, 0.0)]).collect(),
        )
        .unwrap();
        let flat: Vec<DVec2> = s.points().iter().map(|p| p.truncate()).collect();
        let parts = [0..2, 2..4];
        let o = SheetOptions { scale: 30.0, ..SheetOptions::default() };
        let glued = Sheet::lay_out(&s, &flat, &parts, &o).unwrap();
        assert_eq!(glued.labels.iter().filter(|l| l.text == "A").count(), 2);
        assert_eq!(glued.pieces[0].score.iter().filter(|s| s.ruling == Some(2)).count(), 1, "the tab's base");
        let mut touching = flat.clone();
        touching[5] = touching[4];
        let touching = Sheet::lay_out(&s, &touching, &parts, &o).unwrap();
        assert_eq!(touching.labels.iter().filter(|l| l.text == "A").count(), 0);
        assert!(touching.pieces[0].score.iter().all(|s| s.ruling != Some(2)));
        assert_eq!(touching.pieces[0].cut.len(), glued.pieces[0].cut.len() - 3, "no tab, the ruling a point");
    }

    #[test]
    fn glue_letters_count_on_and_text_stays_upright() {
        assert_eq!([0, 1, 25, 26, 27, 701, 702].map(letter), ["A", "B", "Z", "AA", "AB", "ZZ", "AAA"]);
        // a quarter turn is upright as it is, its opposite turned to it
        assert_eq!(upright(std::f64::consts::FRAC_PI_2), std::f64::consts::FRAC_PI_2);
        assert_eq!(upright(-std::f64::consts::FRAC_PI_2), std::f64::consts::FRAC_PI_2);
        for a in [-3.0, -1.6, -1.0, 0.0, 1.0, 1.6, 3.0, 7.0] {
            let u = upright(a);
            assert!(u > -std::f64::consts::FRAC_PI_2 - 1e-12 && u <= std::f64::consts::FRAC_PI_2 + 1e-12);
            assert_near!((u - a).sin(), 0.0, 1e-12);
        }
    }

    #[test]
    fn options_out_of_their_ranges_are_refused_by_name() {
        let s = full_cone();
        let flat = Unfolding::of(&s).unwrap();
        for (o, name) in [
            (SheetOptions { scale: 0.0, ..SheetOptions::default() }, "scale"),
            (SheetOptions { kerf: 6.0, ..SheetOptions::default() }, "kerf"),
            (SheetOptions { tab: f64::NAN, ..SheetOptions::default() }, "tab"),
            (SheetOptions { scale: 1e4, ..SheetOptions::default() }, "scale"),
        ] {
            match Sheet::lay_out(&s, &flat.points, std::slice::from_ref(&(0..24)), &o) {
                Err(Error::InvalidParameter { name: got, .. }) => assert_eq!(got, name),
                other => panic!("{name}: {other:?}"),
            }
        }
    }

    /// A face's plane is taken through its diagonals: a strip of two faces, the first skew (a₁
    /// lifted by 1 off the plane of the others), the second flat, bends at its middle ruling by
    /// the angle between (1, −1, −2) and (−1, −1, −2), the diagonals' normals: acos(2/3).
    #[test]
    fn a_skew_face_bends_by_the_plane_of_its_diagonals() {
        let a = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
        let s = RuledSurface::from_points(vec![
            a(0.0, 0.0, 0.0),
            a(0.0, 1.0, 0.0),
            a(1.0, 0.0, 1.0),
            a(1.0, 1.0, 0.0),
            a(2.0, 0.0, 0.0),
            a(2.0, 1.0, 0.0),
        ])
        .unwrap();
        let b = bends(&s);
        assert_eq!((b.len(), b[0], b[2]), (3, 0.0, 0.0));
        assert_near!(b[1], (2.0f64 / 3.0).acos(), 1e-15);
    }

    /// A strip closes when its last ruling is its first to 1e-9 of its size: the full cone, and
    /// the same cone 1000 times larger with its last ruling 1e-7 off, do; a cone whose last
    /// ruling shares only its end a with the first, one whose last end a is 1e-6 of its size off
    /// the first, and a cone's open half do not.
    #[test]
    fn a_strip_closes_where_its_last_ruling_is_its_first() {
        let s = full_cone();
        let n = s.points().len();
        let moved = |f: &dyn Fn(usize, DVec3) -> DVec3| {
            RuledSurface::from_points(s.points().iter().enumerate().map(|(k, &p)| f(k, p)).collect()).unwrap()
        };
        assert!(closes(&s));
        let size = super::super::coplanar::size_of(s.points());
        let big = moved(&|k, p| 1000.0 * p + if k >= n - 2 { DVec3::new(1e-7, 0.0, 0.0) } else { DVec3::ZERO });
        assert!(closes(&big));
        let b_apart = moved(&|k, p| if k == n - 1 { p + DVec3::new(0.0, 0.0, 0.1) } else { p });
        assert!(!closes(&b_apart));
        let gap = moved(&|k, p| if k == n - 2 { p + DVec3::new(1e-6 * size, 0.0, 0.0) } else { p });
        assert!(!closes(&gap));
        let half = RuledSurface::from_points(s.points()[..26].to_vec()).unwrap();
        assert!(!closes(&half));
    }

    /// The principal direction of points along a line at 30° far from the origin, spread a little
    /// across it (symmetrically): 30°.
    #[test]
    fn the_principal_direction_is_that_of_the_longest_extent() {
        let dir = DVec2::from_angle(std::f64::consts::FRAC_PI_6);
        let points: Vec<DVec2> = (0..11)
            .flat_map(|i| [-0.1, 0.1].map(|w| DVec2::new(100.0, 50.0) + (i as f64 - 5.0) * dir + w * dir.perp()))
            .collect();
        assert_near!(principal_angle(&points), std::f64::consts::FRAC_PI_6, 1e-14);
        // turned by 90°: 120°, said as −60° (the angle is of a line, within (−90°, 90°])
        let turned: Vec<DVec2> = points.iter().map(|p| p.perp()).collect();
        assert_near!(principal_angle(&turned), -std::f64::consts::FRAC_PI_3, 1e-14);
    }

    /// The scale runs from 1/MAX_PATTERN_SCALE to MAX_PATTERN_SCALE millimetres per unit: half a
    /// millimetre per unit is a scale too.
    #[test]
    fn a_scale_below_one_millimetre_per_unit_is_accepted() {
        let o = |scale: f64| check_options(&SheetOptions { scale, ..SheetOptions::default() }).is_ok();
        assert!(o(0.5) && o(1.0 / MAX_PATTERN_SCALE) && o(MAX_PATTERN_SCALE));
        assert!(!o(0.99 / MAX_PATTERN_SCALE) && !o(1.01 * MAX_PATTERN_SCALE));
    }

    /// The piece's number stands at the centre of its middle face (face 12 of the cone's 24), as
    /// the piece is turned and placed; a ruling bent by exactly the fold angle is not scored.
    #[test]
    fn the_number_is_in_the_middle_face_and_a_bend_at_the_fold_angle_is_no_score() {
        let s = full_cone();
        let flat = Unfolding::of(&s).unwrap();
        let most = bends(&s)[1..24].iter().fold(0.0f64, |m, b| m.max(*b));
        let o = SheetOptions { scale: 40.0, fold_angle: most, ..SheetOptions::default() };
        let sheet = Sheet::lay_out(&s, &flat.points, std::slice::from_ref(&(0..24)), &o).unwrap();
        let piece = &sheet.pieces[0];
        assert_eq!((piece.rulings_drawn.len(), piece.score.len()), (23, 1), "only the seam tab's base is scored");
        let p = |k: usize| 40.0 * flat.points[k];
        let centre = (p(24) + p(25) + p(26) + p(27)) / 4.0;
        let number = sheet.labels.iter().find(|l| l.text == "1").unwrap();
        assert_near!(number.at, DMat2::from_angle(piece.rotation) * centre + piece.shift, 1e-9);
    }

    /// Tabs only where a piece is glued to the next: not on the last piece of an open strip, none
    /// of width 0; a join on a ruling shorter than the rounding of the pattern's size (3e-13 of
    /// a unit, 9e-12 mm at 30 mm a unit) has neither tab nor letter.
    #[test]
    fn tabs_are_where_pieces_are_glued() {
        let s = RuledSurface::from_points(
            (0..5).flat_map(|i| [DVec3::new(i as f64, 0.0, 0.0), DVec3::new(i as f64, 1.0, 0.0)]).collect(),
        )
        .unwrap();
        let flat: Vec<DVec2> = s.points().iter().map(|p| p.truncate()).collect();
        let parts = [0..2, 2..4];
        let o = SheetOptions { scale: 30.0, ..SheetOptions::default() };
        let sheet = Sheet::lay_out(&s, &flat, &parts, &o).unwrap();
        assert_eq!(sheet.pieces.iter().map(|p| p.score.len()).collect::<Vec<_>>(), [1, 0], "the flat strip's one tab");
        let no_width = Sheet::lay_out(&s, &flat, &parts, &SheetOptions { tab: 0.0, ..o }).unwrap();
        assert_eq!(no_width.pieces.iter().map(|p| p.score.len()).collect::<Vec<_>>(), [0, 0]);
        assert_eq!(
            no_width.labels.iter().filter(|l| l.text == "A").count(),
            1,
            "the letter on the next piece's ruling"
        );
        let mut short = flat.clone();
        short[5] = short[4] + DVec2::new(0.0, 3e-13);
        let short = Sheet::lay_out(&s, &short, &parts, &o).unwrap();
        assert_eq!(short.labels.iter().filter(|l| l.text == "A").count(), 0);
        assert_eq!(short.pieces[0].score.len(), 0);
    }

    /// Four pieces 40 × 60 mm (a flat strip of 20 × 30 faces, one a piece, at 2 mm a unit) and the
    /// check square (100 × 108 with its text), 10 mm apart: the rows may be 1.3 √(total area) =
    /// 1.3 √26 980 ≈ 213.5 wide. Tallest first: the square at (10, 10), piece 1 turned to lie
    /// along x (60 × 40) beside it at (120, 10); piece 2 would end at 240, so a new row 10 above
    /// the square: (10, 128), (80, 128), (150, 128). The sheet is 220 × 178. Piece 2's number
    /// stands at its face's centre and the letter of the join with piece 1 on its first ruling,
    /// 4 mm inwards from its middle, both reading along x; the pattern turned in its plane gives
    /// the same places.
    #[test]
    fn pieces_are_turned_along_x_and_placed_in_rows_tallest_first() {
        let s = RuledSurface::from_points(
            (0..5)
                .flat_map(|i| [DVec3::new(20.0 * i as f64, 0.0, 0.0), DVec3::new(20.0 * i as f64, 30.0, 0.0)])
                .collect(),
        )
        .unwrap();
        let flat: Vec<DVec2> = s.points().iter().map(|p| p.truncate()).collect();
        let o = SheetOptions { scale: 2.0, tabs: false, ..SheetOptions::default() };
        let sheet = Sheet::lay_out(&s, &flat, &[0..1, 1..2, 2..3, 3..4], &o).unwrap();
        assert_near!(sheet.size, DVec2::new(220.0, 178.0), 1e-9);
        assert_near!(sheet.check_square, DVec2::new(10.0, 18.0), 1e-9);
        let length = sheet.labels.iter().find(|l| l.text == "100 mm").unwrap();
        assert_near!(length.at, DVec2::new(60.0, 14.0), 1e-9); // under the square's middle
        let places = [(120.0, 10.0), (10.0, 128.0), (80.0, 128.0), (150.0, 128.0)];
        for (piece, place) in sheet.pieces.iter().zip(places) {
            assert_near!(piece.rotation, -std::f64::consts::FRAC_PI_2, 1e-15);
            let lo = piece.outline.iter().fold(DVec2::splat(f64::INFINITY), |m, p| m.min(*p));
            let hi = piece.outline.iter().fold(DVec2::splat(f64::NEG_INFINITY), |m, p| m.max(*p));
            assert_near!(lo, DVec2::from(place), 1e-9);
            assert_near!(hi - lo, DVec2::new(60.0, 40.0), 1e-9);
        }
        // piece 1's a₁ (40, 0) turned by −90° lies at its box's lower left
        let a1 = DMat2::from_angle(sheet.pieces[0].rotation) * DVec2::new(40.0, 0.0) + sheet.pieces[0].shift;
        assert_near!(a1, DVec2::new(120.0, 10.0), 1e-9);
        let label = |text: &str| sheet.labels.iter().find(|l| l.text == text).unwrap();
        assert_near!(label("2").at, DVec2::new(40.0, 148.0), 1e-9);
        assert_near!(label("A").at, DVec2::new(40.0, 164.0), 1e-9);
        assert_near!(label("A").angle, 0.0, 1e-15);
        assert_eq!(["A", "B", "C"].map(|t| sheet.labels.iter().filter(|l| l.text == t).count()), [1, 1, 1]);
        // the numbers read along x, as the pieces run
        for k in 1..=4 {
            assert_near!(label(&k.to_string()).angle, 0.0, 1e-12);
        }
        // the same pattern turned by 30° in its plane and moved: the pieces in the same places
        // (each turned along x, perhaps the other way round), the numbers still reading along x
        let turn = DMat2::from_angle(std::f64::consts::FRAC_PI_6);
        let turned: Vec<DVec2> = flat.iter().map(|p| turn * *p + DVec2::new(-7.0, 3.0)).collect();
        let again = Sheet::lay_out(&s, &turned, &[0..1, 1..2, 2..3, 3..4], &o).unwrap();
        assert_near!(again.size, sheet.size, 1e-9);
        let bounds = |p: &SheetPiece| {
            let lo = p.outline.iter().fold(DVec2::splat(f64::INFINITY), |m, q| m.min(*q));
            (lo, p.outline.iter().fold(DVec2::splat(f64::NEG_INFINITY), |m, q| m.max(*q)))
        };
        for (a, b) in again.pieces.iter().zip(&sheet.pieces) {
            let ((lo, hi), (lo2, hi2)) = (bounds(a), bounds(b));
            assert_near!(lo, lo2, 1e-9);
            assert_near!(hi, hi2, 1e-9);
        }
        for k in 1..=4 {
            let number = again.labels.iter().find(|l| l.text == k.to_string()).unwrap();
            assert_near!(number.angle, 0.0, 1e-12);
        }
        // and with tabs, the letters on the tabs and the rulings read along the rulings: along x
        let o_tabs = SheetOptions { tabs: true, ..o };
        let again = Sheet::lay_out(&s, &turned, &[0..1, 1..2, 2..3, 3..4], &o_tabs).unwrap();
        let letters: Vec<&SheetLabel> =
            again.labels.iter().filter(|l| ["A", "B", "C"].contains(&l.text.as_str())).collect();
        assert_eq!(letters.len(), 6);
        for l in letters {
            assert_near!(l.angle.sin(), 0.0, 1e-12);
        }
        // with tabs: each letter on its tab too, reading along the tab's base (the ruling) as well
        let tabbed = Sheet::lay_out(&s, &flat, &[0..1, 1..2, 2..3, 3..4], &SheetOptions { tabs: true, ..o }).unwrap();
        let letters: Vec<&SheetLabel> =
            tabbed.labels.iter().filter(|l| ["A", "B", "C"].contains(&l.text.as_str())).collect();
        assert_eq!(letters.len(), 6);
        for l in letters {
            assert_near!(l.angle, 0.0, 1e-12);
        }
    }

    /// A sheet too large in one direction only is refused by the scale: a flat strip 100 units long
    /// and 1 wide at 120 mm a unit is 12 020 mm wide (over MAX_SHEET_MM), 258 mm high; at 80 mm a
    /// unit it fits, and at exactly MAX_SHEET_MM too.
    #[test]
    fn a_sheet_too_long_is_refused_by_its_scale() {
        let s = RuledSurface::from_points(
            (0..=10)
                .flat_map(|i| [DVec3::new(10.0 * i as f64, 0.0, 0.0), DVec3::new(10.0 * i as f64, 1.0, 0.0)])
                .collect(),
        )
        .unwrap();
        let flat: Vec<DVec2> = s.points().iter().map(|p| p.truncate()).collect();
        let at = |scale: f64| {
            Sheet::lay_out(
                &s,
                &flat,
                std::slice::from_ref(&(0..10)),
                &SheetOptions { scale, tabs: false, ..SheetOptions::default() },
            )
        };
        match at(120.0) {
            Err(Error::InvalidParameter { name, .. }) => assert_eq!(name, "scale"),
            other => panic!("{other:?}"),
        }
        assert_near!(at(80.0).unwrap().size, DVec2::new(8020.0, 218.0), 1e-6);
        // 80 units at 124.75 mm a unit and the margins: exactly MAX_SHEET_MM wide, still a sheet
        let short = RuledSurface::from_points(s.points()[..18].to_vec()).unwrap();
        let o = SheetOptions { scale: 124.75, tabs: false, ..SheetOptions::default() };
        let sheet = Sheet::lay_out(&short, &flat[..18], std::slice::from_ref(&(0..8)), &o).unwrap();
        assert_eq!(sheet.size, DVec2::new(MAX_SHEET_MM, 262.75));
        // too tall only: strips of one-unit faces with rulings 80 long, one face a piece, each
        // turned to lie along x (9 600 × 120 mm at 120 mm a unit), one to a row: 70 of them fit
        // (narrower than the sheet), 81 are too tall
        let standing = |n: usize| {
            let s = RuledSurface::from_points(
                (0..=n).flat_map(|i| [DVec3::new(i as f64, 0.0, 0.0), DVec3::new(i as f64, 80.0, 0.0)]).collect(),
            )
            .unwrap();
            let flat: Vec<DVec2> = s.points().iter().map(|p| p.truncate()).collect();
            let pieces: Vec<Range<usize>> = (0..n).map(|i| i..i + 1).collect();
            Sheet::lay_out(&s, &flat, &pieces, &SheetOptions { scale: 120.0, tabs: false, ..SheetOptions::default() })
        };
        let fits = standing(70).unwrap();
        assert!(fits.size.x < MAX_SHEET_MM && fits.size.y < MAX_SHEET_MM, "{}", fits.size);
        match standing(81) {
            Err(Error::InvalidParameter { name, .. }) => assert_eq!(name, "scale"),
            other => panic!("{other:?}"),
        }
    }

    /// A piece that just fits the rest of its row stays in it: pieces 200, 95 and 95 mm long and
    /// 10 high (a flat strip cut at 200, 295 and 390) with the check square; the rows are 200 wide
    /// (the widest piece; 1.3 √21 380 ≈ 190 is less): the square, then the 200 piece in a row of
    /// its own, then 95 at x = 10 and the other 95 ending exactly at the row's end, at x = 115.
    #[test]
    fn a_piece_that_just_fits_stays_in_its_row() {
        let xs = [0.0, 200.0, 295.0, 390.0];
        let s = RuledSurface::from_points(
            xs.iter().flat_map(|&x| [DVec3::new(x, 0.0, 0.0), DVec3::new(x, 10.0, 0.0)]).collect(),
        )
        .unwrap();
        let flat: Vec<DVec2> = s.points().iter().map(|p| p.truncate()).collect();
        let o = SheetOptions { scale: 1.0, tabs: false, ..SheetOptions::default() };
        let sheet = Sheet::lay_out(&s, &flat, &[0..1, 1..2, 2..3], &o).unwrap();
        let lo = |p: &SheetPiece| p.outline.iter().fold(DVec2::splat(f64::INFINITY), |m, q| m.min(*q));
        let places: Vec<DVec2> = sheet.pieces.iter().map(lo).collect();
        assert_near!(places[0], DVec2::new(10.0, 128.0), 1e-9);
        assert_near!(places[1], DVec2::new(10.0, 148.0), 1e-9);
        assert_near!(places[2], DVec2::new(115.0, 148.0), 1e-9);
        assert_near!(sheet.size, DVec2::new(220.0, 168.0), 1e-9);
    }

    /// A4 with 10 mm margins and overlaps: windows 190 × 277, steps 180 × 267. A 500 × 400 sheet
    /// takes 3 × 2 pages, row 0 at the top (y from 267), the marks in the middles of the
    /// overlaps, 5 mm in; a paper whose window is no larger than the overlap either way is
    /// refused, and 50 × 50 pages (2 500, the most) are a tiling.
    #[test]
    fn pages_are_counted_and_placed_from_the_top() {
        let t = tile(DVec2::new(500.0, 400.0), Paper::A4, 10.0, 10.0).unwrap();
        let origins: Vec<(usize, usize, DVec2)> = t.tiles.iter().map(|p| (p.row, p.column, p.origin)).collect();
        assert_eq!(
            origins,
            [
                (0, 0, DVec2::new(0.0, 267.0)),
                (0, 1, DVec2::new(180.0, 267.0)),
                (0, 2, DVec2::new(360.0, 267.0)),
                (1, 0, DVec2::ZERO),
                (1, 1, DVec2::new(180.0, 0.0)),
                (1, 2, DVec2::new(360.0, 0.0)),
            ]
        );
        assert_eq!(t.marks.len(), 12);
        assert_eq!(
            (t.marks[0], t.marks[5], t.marks[11]),
            (DVec2::splat(5.0), DVec2::new(185.0, 272.0), DVec2::new(545.0, 539.0))
        );
        for paper in [Paper { width: 210.0, height: 30.0 }, Paper { width: 30.0, height: 297.0 }] {
            assert!(tile(DVec2::new(100.0, 100.0), paper, 10.0, 10.0).is_err(), "{paper:?}");
        }
        let most = tile(DVec2::new(190.0 + 49.0 * 180.0, 277.0 + 49.0 * 267.0), Paper::A4, 10.0, 10.0).unwrap();
        assert_eq!((most.columns, most.rows, most.tiles.len()), (50, 50, MAX_PAGES));
    }
}
