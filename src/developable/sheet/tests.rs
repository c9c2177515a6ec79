//! The sheet's tests: layouts worked out by hand (rows, places, labels), the cone all round,
//! tilings, and the options' bounds.

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

/// A flat strip in the plane z = 0: rulings from (x, 0) to (x, `length`) at the given x, and its
/// flat points (the strip is its own pattern).
fn flat_strip(xs: impl IntoIterator<Item = f64>, length: f64) -> (RuledSurface, Vec<DVec2>) {
    let s = RuledSurface::from_points(
        xs.into_iter().flat_map(|x| [DVec3::new(x, 0.0, 0.0), DVec3::new(x, length, 0.0)]).collect(),
    )
    .unwrap();
    let flat = s.points().iter().map(|p| p.truncate()).collect();
    (s, flat)
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

/// Two pieces joined at a ruling: a tab (on the first piece only: the last piece of an open strip
/// has none) and the letter "A" twice; a tab of width 0 is none, its letter on the next piece
/// stays; where the flat points give that ruling no length (the pieces only touch), or less than
/// the rounding of the pattern's size (3e-13 of a unit, 9e-12 mm at 30 mm a unit), neither.
#[test]
fn tabs_and_letters_are_where_pieces_are_glued() {
    let (s, flat) = flat_strip((0..5).map(|i| i as f64), 1.0);
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
    assert_eq!(glued.pieces.iter().map(|p| p.score.len()).collect::<Vec<_>>(), [1, 0], "the flat strip's one tab");
    let no_width = Sheet::lay_out(&s, &flat, &parts, &SheetOptions { tab: 0.0, ..o }).unwrap();
    assert_eq!(no_width.pieces.iter().map(|p| p.score.len()).collect::<Vec<_>>(), [0, 0]);
    assert_eq!(no_width.labels.iter().filter(|l| l.text == "A").count(), 1, "the letter on the next piece's ruling");
    let mut short = flat.clone();
    short[5] = short[4] + DVec2::new(0.0, 3e-13);
    let short = Sheet::lay_out(&s, &short, &parts, &o).unwrap();
    assert_eq!(short.labels.iter().filter(|l| l.text == "A").count(), 0);
    assert_eq!(short.pieces[0].score.len(), 0);
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
    let (s, flat) = flat_strip((0..5).map(|i| 20.0 * i as f64), 30.0);
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
    let (s, flat) = flat_strip((0..=10).map(|i| 10.0 * i as f64), 1.0);
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
        let (s, flat) = flat_strip((0..=n).map(|i| i as f64), 80.0);
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
    let (s, flat) = flat_strip(xs, 10.0);
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
