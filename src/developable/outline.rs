//! The cut line of one piece of a flat pattern: its outline with glue tabs, and the outline moved
//! outwards by half the kerf (beyond the paper: what a plotter, a knife or a laser follows).
//!
//! A piece holds the rulings s … e of the pattern. Its outline runs along the images of the ends a,
//! A_s → … → A_e, across the last ruling to B_e, back along the ends b to B_s, and across the first
//! ruling home; points that coincide (a cone's apex) are merged, and the outline is turned
//! counter-clockwise. A glue tab on a ruling of the outline is a trapezoid outside it: the ruling is
//! its base (a fold line), its sides slope in by the tab's width or less, so that a short ruling
//! gets a low tab.
//!
//! **Kerf.** A cutter removes a band of width k (the kerf) centred on the path it follows. So that
//! the piece keeps its size, the path is the outline offset outwards by k/2: each edge moved along
//! its outward normal, consecutive edges meeting at the mitre point v + (k/2)(n₀ + n₁)/(1 + n₀·n₁),
//! and at a corner sharper than a right angle (where the mitre would stick out more than √2 · k/2)
//! two points v + (k/2)n₀, v + (k/2)n₁ instead (a bevel).

use glam::DVec2;

/// A segment of a flat pattern: a score line or a ruling, and the ruling it is (none for a tab's base).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stroke {
    /// One end.
    pub a: DVec2,
    /// The other.
    pub b: DVec2,
    /// The ruling of the strip it is, if it is one.
    pub ruling: Option<usize>,
}

/// Where a tab goes: on the first or the last ruling of a piece.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The piece's first ruling, B_s → A_s in the outline.
    First,
    /// Its last ruling, A_e → B_e.
    Last,
}

/// An outline with its tabs.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    /// The closed polygon, counter-clockwise (the last point joins the first).
    pub points: Vec<DVec2>,
    /// The tabs' bases (fold lines), with the tab's middle (where its label goes).
    pub tab_bases: Vec<(Stroke, DVec2)>,
}

/// The signed area of a closed polygon (positive counter-clockwise).
pub fn signed_area(points: &[DVec2]) -> f64 {
    let n = points.len();
    (0..n).map(|i| points[i].perp_dot(points[(i + 1) % n])).sum::<f64>() / 2.0
}

/// The perimeter of a closed polygon.
pub fn perimeter(points: &[DVec2]) -> f64 {
    let n = points.len();
    (0..n).map(|i| (points[(i + 1) % n] - points[i]).length()).sum()
}

/// The outline of the piece of rulings `first ..= last` of `points` (A_i, B_i per ruling), with a
/// tab of width `tab` on each side in `tabs` (see the module); `merge`: points closer than this are
/// one.
pub fn outline(points: &[DVec2], first: usize, last: usize, tabs: &[Side], tab: f64, merge: f64) -> Outline {
    // the polygon with, for each point, what the edge leaving it is
    let mut ring: Vec<(DVec2, Option<Side>)> = Vec::with_capacity(2 * (last - first + 1));
    for i in first..=last {
        ring.push((points[2 * i], (i == last).then_some(Side::Last)));
    }
    for i in (first..=last).rev() {
        ring.push((points[2 * i + 1], (i == first).then_some(Side::First)));
    }
    // merge coinciding neighbours, keeping the tag of the edge that leaves the merged point: the
    // edge between them has no length, and a tab on it (a ruling of no length) none to stand on
    let mut merged: Vec<(DVec2, Option<Side>)> = Vec::with_capacity(ring.len());
    for (p, tag) in ring {
        match merged.last_mut() {
            Some((q, t)) if (p - *q).length() <= merge => *t = tag,
            _ => merged.push((p, tag)),
        }
    }
    if merged.len() > 1 && (merged[0].0 - merged[merged.len() - 1].0).length() <= merge {
        merged.pop();
    }
    let pts: Vec<DVec2> = merged.iter().map(|(p, _)| *p).collect();
    let ccw = signed_area(&pts) >= 0.0;
    let mut out = Vec::with_capacity(pts.len() + 4);
    let mut tab_bases = Vec::new();
    let n = merged.len();
    for k in 0..n {
        let (p, tag) = merged[k];
        out.push(p);
        let Some(side) = tag.filter(|s| tabs.contains(s)) else { continue };
        let q = merged[(k + 1) % n].0;
        let along = q - p;
        let length = along.length();
        if length <= merge {
            continue;
        }
        let d = along / length;
        // outwards: right of the edge for a counter-clockwise polygon, left for a clockwise one
        let outward = if ccw { DVec2::new(d.y, -d.x) } else { d.perp() };
        let height = tab.min(0.45 * length);
        let inset = height.min(0.3 * length);
        let (p1, q1) = (p + d * inset + outward * height, q - d * inset + outward * height);
        out.push(p1);
        out.push(q1);
        let ruling = match side {
            Side::First => first,
            Side::Last => last,
        };
        tab_bases.push((Stroke { a: p, b: q, ruling: Some(ruling) }, (p1 + q1 + p + q) / 4.0));
    }
    if !ccw {
        out.reverse();
    }
    Outline { points: out, tab_bases }
}

/// The closed counter-clockwise polygon `points` offset outwards by `distance` (see the module;
/// `distance` 0 gives the polygon back).
pub fn offset(points: &[DVec2], distance: f64) -> Vec<DVec2> {
    if distance == 0.0 || points.len() < 3 {
        return points.to_vec();
    }
    let n = points.len();
    let normal = |i: usize| {
        let d = (points[(i + 1) % n] - points[i]).normalize_or_zero();
        DVec2::new(d.y, -d.x)
    };
    let mut out = Vec::with_capacity(n + 8);
    for i in 0..n {
        let (n0, n1) = (normal((i + n - 1) % n), normal(i));
        let v = points[i];
        let c = 1.0 + n0.dot(n1);
        // a mitre within √2 of the distance: corners of a right angle or blunter
        if c > 1e-12 && (n0 + n1).length() / c <= std::f64::consts::SQRT_2 + 1e-12 {
            out.push(v + distance * (n0 + n1) / c);
        } else {
            out.push(v + distance * n0);
            out.push(v + distance * n1);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;

    /// A strip of three unit squares: rulings at x = 0, 1, 2, 3 from y = 0 to 1.
    fn squares() -> Vec<DVec2> {
        (0..4).flat_map(|i| [DVec2::new(i as f64, 0.0), DVec2::new(i as f64, 1.0)]).collect()
    }

    #[test]
    fn the_outline_runs_round_the_piece_counter_clockwise() {
        let o = outline(&squares(), 1, 3, &[], 0.0, 1e-9);
        assert_eq!(o.points.len(), 6);
        assert_near!(signed_area(&o.points), 2.0, 1e-15);
        assert_near!(perimeter(&o.points), 6.0, 1e-15);
        // the same strip mirrored (clockwise as built) still comes out counter-clockwise
        let mirrored: Vec<DVec2> = squares().iter().map(|p| DVec2::new(p.x, -p.y)).collect();
        assert_near!(signed_area(&outline(&mirrored, 0, 3, &[], 0.0, 1e-9).points), 3.0, 1e-15);
    }

    #[test]
    fn a_tab_is_a_trapezoid_outside_the_ruling_it_is_glued_on() {
        let o = outline(&squares(), 0, 2, &[Side::Last, Side::First], 0.2, 1e-9);
        assert_eq!(o.tab_bases.len(), 2);
        // each tab adds the trapezoid's area: (1 + 1 − 2·0.2)/2 · 0.2
        assert_near!(signed_area(&o.points), 2.0 + 2.0 * 0.16, 1e-14);
        let (base, middle) = o.tab_bases[0];
        assert_eq!(base.ruling, Some(2));
        assert_near!((base.b - base.a).length(), 1.0, 1e-15);
        assert!(middle.x > 2.0, "the last ruling's tab is outside: {middle:?}");
        assert!(o.tab_bases[1].1.x < 0.0);
        // a short ruling gets a low tab
        let short = outline(&squares(), 0, 1, &[Side::Last], 5.0, 1e-9);
        assert_near!(signed_area(&short.points), 1.0 + (1.0 + 0.4) / 2.0 * 0.45, 1e-14);
    }

    #[test]
    fn a_fan_from_one_point_has_its_apex_once() {
        let fan: Vec<DVec2> = (0..5)
            .flat_map(|i| {
                let u = 0.3 * i as f64;
                [DVec2::ZERO, DVec2::new(u.cos(), u.sin())]
            })
            .collect();
        let o = outline(&fan, 0, 4, &[], 0.0, 1e-9);
        assert_eq!(o.points.len(), 6);
    }

    /// A square offset by d: a square of side 1 + 2d with the same centre; a sharp corner is
    /// bevelled, never further than √2 · d from it.
    #[test]
    fn the_kerf_offset_moves_every_edge_out_by_the_distance() {
        let square = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
        let out = offset(&square, 0.1);
        assert_near!(signed_area(&out), 1.44, 1e-14);
        assert_near!(perimeter(&out), 4.8, 1e-14);
        // a kite with a spike: the blunt corners mitred, the spike's tip and the sharp back bevelled
        let kite = [DVec2::ZERO, DVec2::new(10.0, 0.5), DVec2::new(0.0, 1.0), DVec2::new(-1.0, 0.5)];
        let out = offset(&kite, 0.1);
        assert_eq!(out.len(), 6, "{out:?}");
        for (k, v) in [(0, 0), (1, 1), (2, 1), (3, 2), (4, 3), (5, 3)] {
            assert!((out[k] - kite[v]).length() <= 0.1 * std::f64::consts::SQRT_2 + 1e-12, "{k}");
        }
        assert_eq!(offset(&square, 0.0), square.to_vec());
        assert_eq!(offset(&kite, 0.0), kite.to_vec(), "no offset: not even a bevel");
    }

    /// A regular hexagon offset by d is the regular hexagon of apothem a + d (its corners of 120°
    /// mitred); an equilateral triangle's corners of 60° are bevelled: two points a corner, each
    /// moved by d along an edge's outward normal.
    #[test]
    fn blunt_corners_are_mitred_and_sharp_ones_bevelled_exactly() {
        let corner = |r: f64, k: usize, n: usize| {
            let u = std::f64::consts::TAU * k as f64 / n as f64 + 0.3;
            DVec2::new(1.5 + r * u.cos(), -0.5 + r * u.sin())
        };
        let (d, r) = (0.25, 2.0);
        let hexagon: Vec<DVec2> = (0..6).map(|k| corner(r, k, 6)).collect();
        let out = offset(&hexagon, d);
        // circumradius (a + d)/cos 30° where a = r cos 30°
        let grown = r + d / 30f64.to_radians().cos();
        assert_eq!(out.len(), 6);
        for (k, p) in out.iter().enumerate() {
            assert_near!(*p, corner(grown, k, 6), 1e-15);
        }
        let triangle: Vec<DVec2> = (0..3).map(|k| corner(r, k, 3)).collect();
        let out = offset(&triangle, d);
        assert_eq!(out.len(), 6);
        for k in 0..3 {
            let v = triangle[k];
            let normal = |a: DVec2, b: DVec2| {
                let e = (b - a).normalize();
                DVec2::new(e.y, -e.x)
            };
            let before = normal(triangle[(k + 2) % 3], v);
            let after = normal(v, triangle[(k + 1) % 3]);
            assert_near!(out[2 * k], v + d * before, 1e-15);
            assert_near!(out[2 * k + 1], v + d * after, 1e-15);
        }
    }

    /// Tabs on rulings of length 2 (not 1, where a share of the length and the length's inverse
    /// agree): the trapezoid's corners and its middle exactly.
    #[test]
    fn a_tabs_corners_and_middle_are_where_the_tab_width_puts_them() {
        let tall: Vec<DVec2> = (0..3).flat_map(|i| [DVec2::new(i as f64, 1.0), DVec2::new(i as f64, 3.0)]).collect();
        // a narrow tab: as high as asked, its sides sloping in by as much
        let o = outline(&tall, 0, 2, &[Side::Last], 0.2, 1e-9);
        let expected = [(0.0, 1.0), (1.0, 1.0), (2.0, 1.0), (2.2, 1.2), (2.2, 2.8), (2.0, 3.0), (1.0, 3.0), (0.0, 3.0)];
        assert_eq!(o.points, expected.map(DVec2::from));
        let (base, middle) = o.tab_bases[0];
        assert_eq!((base.a, base.b, base.ruling), (DVec2::new(2.0, 1.0), DVec2::new(2.0, 3.0), Some(2)));
        assert_near!(middle, DVec2::new(2.1, 2.0), 1e-15);
        // a wide tab: 0.45 of the ruling high, its sides in by 0.3 of it; on the first ruling, left
        let o = outline(&tall, 0, 2, &[Side::First], 5.0, 1e-9);
        assert_eq!(o.points.len(), 8);
        assert_near!(o.points[6], DVec2::new(-0.9, 2.4), 1e-15);
        assert_near!(o.points[7], DVec2::new(-0.9, 1.6), 1e-15);
        assert_near!(o.tab_bases[0].1, DVec2::new(-0.45, 2.0), 1e-15);
    }

    /// A fan whose apex is not the origin: the apex (every end a) once. A first or a last ruling of
    /// no length: its two ends one point of the outline, and the tab asked for on it dropped.
    #[test]
    fn coinciding_points_anywhere_are_merged_into_one() {
        let apex = DVec2::new(3.0, 2.0);
        let fan: Vec<DVec2> = (0..4)
            .flat_map(|i| {
                let u = 0.3 * i as f64;
                [apex, apex + DVec2::new(u.cos(), u.sin())]
            })
            .collect();
        let o = outline(&fan, 0, 3, &[], 0.0, 1e-9);
        assert_eq!(o.points.len(), 5, "{:?}", o.points);
        assert_eq!(o.points.iter().filter(|p| **p == apex).count(), 1);
        // a strip whose first ruling has no length: its two ends are one point of the outline
        let mut squares: Vec<DVec2> = squares().iter().map(|p| *p + DVec2::new(5.0, 7.0)).collect();
        squares[1] = squares[0];
        let o = outline(&squares, 0, 3, &[Side::First], 0.2, 1e-9);
        assert_eq!(o.points.len(), 7, "{:?}", o.points);
        assert!(o.tab_bases.is_empty(), "no tab on a ruling of no length");
        // the last ruling of no length (the merge along the outline, not round its end)
        let mut squares: Vec<DVec2> = self::squares().iter().map(|p| *p + DVec2::new(5.0, 7.0)).collect();
        squares[7] = squares[6];
        let o = outline(&squares, 0, 3, &[Side::Last], 0.2, 1e-9);
        assert_eq!(o.points.len(), 7, "{:?}", o.points);
        assert!(o.tab_bases.is_empty(), "no tab on a ruling of no length");
        // a piece shrunk to a point is that point
        let point = [apex; 4];
        assert_eq!(outline(&point, 0, 1, &[Side::First, Side::Last], 0.2, 1e-9).points, [apex]);
    }

    /// A tab on a slanted ruling stands square to it, outside: for a counter-clockwise outline to
    /// the right of the ruling's direction, for a clockwise one (turned afterwards) to its left.
    #[test]
    fn a_tab_on_a_slanted_ruling_stands_square_to_it_outside() {
        // a parallelogram: rulings from (i, 0) to (i + 3, 4), of length 5
        let strip: Vec<DVec2> =
            (0..2).flat_map(|i| [DVec2::new(i as f64, 0.0), DVec2::new(i as f64 + 3.0, 4.0)]).collect();
        let o = outline(&strip, 0, 1, &[Side::Last], 0.5, 1e-9);
        // the last ruling (1, 0) → (4, 4), its unit direction (0.6, 0.8), outward (0.8, −0.6)
        let (d, out) = (DVec2::new(0.6, 0.8), DVec2::new(0.8, -0.6));
        let (p, q) = (DVec2::new(1.0, 0.0), DVec2::new(4.0, 4.0));
        assert_near!(o.points[2], p + 0.5 * d + 0.5 * out, 1e-15);
        assert_near!(o.points[3], q - 0.5 * d + 0.5 * out, 1e-15);
        // mirrored, the outline is built clockwise: the tab still outside, the outline turned
        let mirrored: Vec<DVec2> = strip.iter().map(|p| DVec2::new(-p.x, p.y)).collect();
        let o = outline(&mirrored, 0, 1, &[Side::Last], 0.5, 1e-9);
        let flip = |v: DVec2| DVec2::new(-v.x, v.y);
        assert!(signed_area(&o.points) > 0.0);
        for corner in [flip(p + 0.5 * d + 0.5 * out), flip(q - 0.5 * d + 0.5 * out)] {
            assert!(o.points.iter().any(|x| (*x - corner).length() < 1e-15), "{corner:?} in {:?}", o.points);
        }
    }
}
