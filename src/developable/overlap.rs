//! Where a flat pattern overlaps itself, and the pieces it is cut into so that none does (Section
//! 3's development, made printable: a tangent surface of a helix over more than a turn, or a cone
//! over more than its sector, unrolls onto itself).
//!
//! The pattern's faces are the quadrilaterals A_i B_i B_{i+1} A_{i+1}, each taken as its two
//! triangles A_i B_i B_{i+1} and A_i B_{i+1} A_{i+1}. Two faces overlap when a triangle of one and a
//! triangle of the other have interiors that meet by more than [`OVERLAP_REL`] of the pattern's
//! size: no axis separates them (the separating-axis test, exact for convex polygons). Faces that
//! share a ruling or only touch (at a cone's apex) do not overlap. Candidate pairs come from sorting
//! the faces' bounding boxes along x (sweep and prune), so a pattern that does not overlap costs
//! O(N log N).
//!
//! **Pieces.** A piece is a run of consecutive faces of which no two overlap; the pattern is split
//! at rulings. Walking along the strip, a face that overlaps a face of the piece being built starts
//! the next piece, the ruling between them becoming a cut (and a glue line). Since any part of a
//! piece is a piece, this greedy split makes the fewest pieces.

use crate::tolerance::OVERLAP_REL;
use glam::DVec2;
use std::ops::Range;

/// The two triangles of face i of `points` (A_i, B_i per ruling).
fn triangles(points: &[DVec2], i: usize) -> [[DVec2; 3]; 2] {
    let (a, b, c, d) = (points[2 * i], points[2 * i + 1], points[2 * i + 3], points[2 * i + 2]);
    [[a, b, c], [a, c, d]]
}

/// Whether the interiors of two triangles meet by more than `tol` (no separating axis among their
/// edges' normals with the projections apart or within `tol`).
fn triangles_overlap(s: &[DVec2; 3], t: &[DVec2; 3], tol: f64) -> bool {
    for tri in [s, t] {
        for k in 0..3 {
            let edge = tri[(k + 1) % 3] - tri[k];
            let Some(axis) = edge.perp().try_normalize() else { continue };
            let range = |q: &[DVec2; 3]| {
                q.iter()
                    .map(|p| p.dot(axis))
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)))
            };
            let ((s0, s1), (t0, t1)) = (range(s), range(t));
            if s1 <= t0 + tol || t1 <= s0 + tol {
                return false;
            }
        }
    }
    // a degenerate triangle (no area) has no interior
    let area = |q: &[DVec2; 3]| (q[1] - q[0]).perp_dot(q[2] - q[0]).abs();
    area(s) > tol * tol && area(t) > tol * tol
}

/// The pairs of faces (i, j), i < j, whose interiors overlap (see the module), in ascending order;
/// faces that share a ruling (j = i + 1) are compared too, so a pattern folded onto itself at a
/// ruling shows.
pub fn overlapping_faces(points: &[DVec2]) -> Vec<(usize, usize)> {
    let faces = (points.len() / 2).saturating_sub(1);
    let size = points.iter().fold(0.0f64, |m, p| m.max(p.length())).max(1.0);
    let tol = OVERLAP_REL * size;
    let boxes: Vec<(DVec2, DVec2)> = (0..faces)
        .map(|i| {
            let q = [points[2 * i], points[2 * i + 1], points[2 * i + 2], points[2 * i + 3]];
            (q.iter().fold(q[0], |m, p| m.min(*p)), q.iter().fold(q[0], |m, p| m.max(*p)))
        })
        .collect();
    let mut order: Vec<usize> = (0..faces).collect();
    order.sort_by(|&i, &j| boxes[i].0.x.total_cmp(&boxes[j].0.x));
    let mut out = Vec::new();
    for (k, &i) in order.iter().enumerate() {
        for &j in &order[k + 1..] {
            if boxes[j].0.x >= boxes[i].1.x - tol {
                break;
            }
            let (lo, hi) = (i.min(j), i.max(j));
            if boxes[j].0.y >= boxes[i].1.y - tol || boxes[i].0.y >= boxes[j].1.y - tol {
                continue;
            }
            let (ti, tj) = (triangles(points, lo), triangles(points, hi));
            // a face sharing ruling `hi` with the one before: its triangles next to that ruling touch it
            if ti.iter().any(|s| tj.iter().any(|t| triangles_overlap(s, t, tol))) {
                out.push((lo, hi));
            }
        }
    }
    out.sort_unstable();
    out
}

/// The pieces of the pattern (see the module): runs of faces, as ranges of ruling indices — piece
/// `r` holds the rulings `r.start ..= r.end`, and consecutive pieces share a ruling. One piece when
/// nothing overlaps.
pub fn pieces(points: &[DVec2], overlaps: &[(usize, usize)]) -> Vec<Range<usize>> {
    let rulings = points.len() / 2;
    let faces = rulings.saturating_sub(1);
    // for each face, the latest earlier face it overlaps
    let mut latest: Vec<Option<usize>> = vec![None; faces];
    for &(i, j) in overlaps {
        latest[j] = Some(latest[j].map_or(i, |k| k.max(i)));
    }
    let mut out = Vec::new();
    let mut start = 0;
    for f in 0..faces {
        if latest[f].is_some_and(|g| g >= start) {
            out.push(start..f);
            start = f;
        }
    }
    out.push(start..faces);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tolerance::test::uniform;
    use std::f64::consts::{PI, TAU};

    /// The area common to two triangles, by clipping one with the other's edges
    /// (Sutherland–Hodgman): the reference the separating axes are checked against.
    fn common_area(s: &[DVec2; 3], t: &[DVec2; 3]) -> f64 {
        let orient = |q: &[DVec2; 3]| if (q[1] - q[0]).perp_dot(q[2] - q[0]) >= 0.0 { 1.0 } else { -1.0 };
        let o = orient(t);
        let mut poly: Vec<DVec2> = s.to_vec();
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let side = |p: DVec2| o * (b - a).perp_dot(p - a);
            let mut out = Vec::new();
            for i in 0..poly.len() {
                let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
                let (sp, sq) = (side(p), side(q));
                if sp >= 0.0 {
                    out.push(p);
                }
                if (sp >= 0.0) != (sq >= 0.0) {
                    out.push(p + (q - p) * (sp / (sp - sq)));
                }
            }
            poly = out;
            if poly.is_empty() {
                return 0.0;
            }
        }
        let n = poly.len();
        (0..n).map(|i| poly[i].perp_dot(poly[(i + 1) % n])).sum::<f64>().abs() / 2.0
    }

    /// Random zigzag strips, folded onto themselves many times: the pairs of faces found are the
    /// pairs whose triangles share an area (pairs that share only a sliver, where the separating
    /// axes and the area may disagree by the tolerance, are left out), and the pieces hold no pair.
    #[test]
    fn the_overlaps_found_are_the_faces_that_share_an_area() {
        let mut seed = 17;
        let mut found = 0;
        for _ in 0..40 {
            let n = 14;
            let offset = DVec2::new(100.0 * uniform(&mut seed), -50.0 * uniform(&mut seed));
            let p: Vec<DVec2> =
                (0..2 * n).map(|_| offset + DVec2::new(10.0 * uniform(&mut seed), 4.0 * uniform(&mut seed))).collect();
            let got = overlapping_faces(&p);
            for i in 0..n - 1 {
                for j in i + 1..n - 1 {
                    // the faces' triangles as the module defines them: A_i B_i B_{i+1}, A_i B_{i+1} A_{i+1}
                    let face =
                        |i: usize| [[p[2 * i], p[2 * i + 1], p[2 * i + 3]], [p[2 * i], p[2 * i + 3], p[2 * i + 2]]];
                    let (ti, tj) = (face(i), face(j));
                    let area = ti.iter().flat_map(|s| tj.iter().map(move |t| common_area(s, t))).fold(0.0, f64::max);
                    // (a convex common part of area 1e-5 in a strip about 11 across is at least
                    // 1e-6 thick, well beyond the tolerance of 1e-9 of the size)
                    if area > 1e-5 {
                        assert!(got.contains(&(i, j)), "faces {i}, {j} share {area}");
                        found += 1;
                    } else if area == 0.0 {
                        assert!(!got.contains(&(i, j)), "faces {i}, {j} share nothing");
                    }
                }
            }
            assert!(got.windows(2).all(|w| w[0] < w[1]), "ascending, once each");
            let pieces = pieces(&p, &got);
            assert_eq!((pieces[0].start, pieces.last().unwrap().end), (0, n - 1));
            for w in pieces.windows(2) {
                assert_eq!(w[0].end, w[1].start, "consecutive pieces share a ruling");
            }
            for r in &pieces {
                assert!(got.iter().all(|&(i, j)| !(r.start <= i && j < r.end)), "{r:?} holds an overlap");
            }
        }
        assert!(found > 200, "{found} overlapping pairs: the strips fold");
    }

    /// Two triangles side by side, moved into each other by less and by more than the tolerance.
    #[test]
    fn triangles_overlap_when_they_reach_into_each_other_by_more_than_the_tolerance() {
        let tol = 1e-6;
        let s = [DVec2::new(0.0, 0.0), DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0)];
        // its mirror image across x + y = 1, shifted along the normal (1, 1)/√2 by d
        let t = |d: f64| {
            let shift = DVec2::splat(d / 2f64.sqrt());
            [DVec2::new(1.0, 0.0) + shift, DVec2::new(1.0, 1.0) + shift, DVec2::new(0.0, 1.0) + shift]
        };
        for (d, overlap) in [(0.0, false), (-0.5 * tol, false), (-2.0 * tol, true), (-0.3, true), (0.1, false)] {
            assert_eq!(triangles_overlap(&s, &t(d), tol), overlap, "moved by {d}");
            assert_eq!(triangles_overlap(&t(d), &s, tol), overlap, "moved by {d}, the other way round");
        }
        // a triangle without area has no interior, even inside another
        let flat = [DVec2::new(0.1, 0.1), DVec2::new(0.2, 0.2), DVec2::new(0.3, 0.3)];
        assert!(!triangles_overlap(&s, &flat, tol) && !triangles_overlap(&flat, &s, tol));
        // one inside the other
        let small = [DVec2::new(0.1, 0.1), DVec2::new(0.3, 0.1), DVec2::new(0.1, 0.3)];
        assert!(triangles_overlap(&s, &small, tol) && triangles_overlap(&small, &s, tol));
        // a thin triangle whose area is below tol² is none
        let sliver = [DVec2::new(0.1, 0.1), DVec2::new(0.5, 0.1), DVec2::new(0.1, 0.1 + 1e-12)];
        assert!(!triangles_overlap(&s, &sliver, tol));
        // a small one inside: it has an interior while its legs' product (twice its area) is above
        // tol², none at tol² (numbers exact in binary)
        let tol = 2f64.powi(-20);
        let small = |leg: f64| [DVec2::new(0.25, 0.25), DVec2::new(0.25 + leg, 0.25), DVec2::new(0.25, 0.25 + leg)];
        assert!(triangles_overlap(&s, &small(2.0 * tol), tol) && triangles_overlap(&small(2.0 * tol), &s, tol));
        assert!(!triangles_overlap(&s, &small(tol), tol) && !triangles_overlap(&small(tol), &s, tol));
    }

    /// The tolerance is a share of the pattern's size: a face folded back onto its neighbour by
    /// less than it does not overlap, by more it does, whatever the size.
    #[test]
    fn what_counts_as_overlapping_grows_with_the_pattern() {
        for size in [1.0, 10.0, 1000.0] {
            // rulings at x = 0 and 1, then back at 1 − δ: the last face folded onto the first by δ
            let folded = |delta: f64| {
                [0.0, 1.0, 1.0 - delta]
                    .into_iter()
                    .flat_map(|x| [DVec2::new(x, 0.0), DVec2::new(x, 1.0)])
                    .map(|p| size * p)
                    .collect::<Vec<_>>()
            };
            // the tolerance: 1e-9 of the largest |p|, √2 · size
            let tol = OVERLAP_REL * 2f64.sqrt() * size;
            assert!(overlapping_faces(&folded(0.5 * tol / size)).is_empty(), "size {size}");
            assert_eq!(overlapping_faces(&folded(2.0 * tol / size)), [(0, 1)], "size {size}");
        }
    }

    /// A flat annulus strip turning `turns` times about the origin: rulings from radius 1 to 2.
    fn annulus(n: usize, turns: f64) -> Vec<DVec2> {
        (0..n)
            .flat_map(|i| {
                let u = turns * TAU * i as f64 / (n - 1) as f64;
                let d = DVec2::new(u.cos(), u.sin());
                [d, 2.0 * d]
            })
            .collect()
    }

    #[test]
    fn a_strip_that_turns_less_than_once_does_not_overlap() {
        let p = annulus(40, 0.9);
        assert!(overlapping_faces(&p).is_empty());
        assert_eq!(pieces(&p, &[]), std::slice::from_ref(&(0..39)));
    }

    /// Two and a half turns: every face overlaps the faces one turn before; the pieces are the
    /// turns, each just under a full turn (the face that closes a turn touches its first face only
    /// along a ruling, when the turn is a whole number of faces).
    #[test]
    fn a_strip_over_two_and_a_half_turns_is_split_into_three_pieces() {
        let n = 101; // 100 faces, 40 per turn
        let p = annulus(n, 2.5);
        let overlaps = overlapping_faces(&p);
        assert!(overlaps.contains(&(0, 40)) && overlaps.contains(&(30, 70)) && !overlaps.contains(&(0, 39)));
        // faces one or two turns apart, give or take a face
        assert!(overlaps.iter().all(|&(i, j)| [39, 40, 41, 79, 80, 81].contains(&(j - i))), "{overlaps:?}");
        assert!(overlaps.contains(&(5, 85)));
        let pieces = pieces(&p, &overlaps);
        assert_eq!(pieces, [0..40, 40..80, 80..100]);
        // no two faces of a piece overlap
        for r in &pieces {
            assert!(overlaps.iter().all(|&(i, j)| !(r.contains(&i) && r.contains(&j) && j < r.end)));
        }
    }

    /// The same pattern turned and moved: the same overlaps (every face of the first one and a
    /// half turns overlaps the face one turn on, wherever it lies: left of the origin too).
    #[test]
    fn the_overlaps_do_not_depend_on_where_the_pattern_lies() {
        let p = annulus(101, 2.5);
        let expected = overlapping_faces(&p);
        assert!((0..60).all(|i| expected.contains(&(i, i + 40))), "{expected:?}");
        for (angle, shift) in [(PI, DVec2::ZERO), (1.0, DVec2::new(-30.0, -40.0)), (-0.3, DVec2::new(25.0, -7.0))] {
            let turn = DVec2::from_angle(angle);
            let q: Vec<DVec2> = p.iter().map(|&x| turn.rotate(x) + shift).collect();
            assert_eq!(overlapping_faces(&q), expected, "turned by {angle}, moved by {shift}");
        }
    }

    #[test]
    fn faces_that_only_touch_do_not_overlap() {
        // a fan about the origin (a cone unrolled from its apex): every face touches every other there
        let p: Vec<DVec2> = (0..12)
            .flat_map(|i| {
                let u = 0.5 * i as f64;
                [DVec2::ZERO, DVec2::new(u.cos(), u.sin())]
            })
            .collect();
        // 11 faces of 0.5 rad: 5.5 rad, less than a turn
        assert!(overlapping_faces(&p).is_empty());
        // a square and its neighbour sharing an edge
        let q = [DVec2::ZERO, DVec2::Y, DVec2::X, DVec2::new(1.0, 1.0), DVec2::new(2.0, 0.0), DVec2::new(2.0, 1.0)];
        assert!(overlapping_faces(&q).is_empty());
        // folded back onto itself at the middle ruling: the two faces overlap
        let folded =
            [DVec2::ZERO, DVec2::Y, DVec2::X, DVec2::new(1.0, 1.0), DVec2::new(0.2, 0.0), DVec2::new(0.2, 1.0)];
        assert_eq!(overlapping_faces(&folded), [(0, 1)]);
    }
}
