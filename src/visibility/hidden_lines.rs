//! The hidden lines of a figure (module documentation): every line's segments clipped to the
//! near plane, the intervals each triangle of the grid hides merged, and the runs of one
//! visibility formed along each polyline, segment or dot.

use super::grid::Scene;
use super::occluder::{hidden_interval, hides_point};
use super::runs::{Chain, Run};
use super::segment::{clip_segment, Clipped};
use super::view::View;
use super::HiddenLineOptions;
use crate::error::{Error, Result};
use crate::tolerance::MAX_HIDDEN_LINE_ITEMS;
use glam::DVec3;

/// How the points of a set of lines are joined.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineKind {
    /// Two points per segment.
    Segments,
    /// Consecutive points joined; a non-finite point breaks the polyline; `closed` joins the
    /// last point to the first.
    Polyline {
        /// Whether the last point is joined to the first.
        closed: bool,
    },
    /// Separate points (dots).
    Points,
}

/// The hidden parts of one clipped segment, as sorted disjoint intervals of s.
fn hidden_parts(scene: &Scene, seg: &Clipped, stamp: &mut [u32], id: u32) -> Vec<(f64, f64)> {
    let far_w = seg.ia.w.max(seg.ib.w);
    let mut parts = Vec::new();
    scene.cells_along(seg.ia.screen, seg.ib.screen, |k| {
        if stamp[k as usize] == id {
            return;
        }
        stamp[k as usize] = id;
        let o = &scene.occluders[k as usize];
        if o.near_w > far_w {
            return; // wholly behind the segment
        }
        if let Some(part) = hidden_interval(o, seg) {
            parts.push(part);
        }
    });
    // by their starts (an insertion sort: a segment crosses few triangles)
    for k in 1..parts.len() {
        let mut j = k;
        while j > 0 && parts[j - 1].0 > parts[j].0 {
            parts.swap(j - 1, j);
            j -= 1;
        }
    }
    let mut merged: Vec<(f64, f64)> = Vec::with_capacity(parts.len());
    for (lo, hi) in parts {
        match merged.last_mut() {
            // intervals that touch (to rounding) are one: no sliver between neighbouring triangles
            Some(last) if lo <= last.1 + 1e-12 => last.1 = last.1.max(hi),
            _ => merged.push((lo, hi)),
        }
    }
    merged
}

/// The visible and hidden runs of every set of lines, as images in pixels: for each entry of
/// `lines` (its kind and world points), the runs of its polylines or segments in order, a dot per
/// point (`Points`). Occluders are the triangles of `meshes` (world points and three indices per
/// triangle; an index naming no point, a corner behind the eye or an image without area leaves
/// the triangle out). Lines and parts of lines behind the near plane are left out.
pub fn hidden_lines(
    view: &View,
    meshes: &[(&[DVec3], &[u32])],
    lines: &[(LineKind, &[DVec3])],
    options: HiddenLineOptions,
) -> Result<Vec<Vec<Run>>> {
    hidden_lines_at_most(view, meshes, lines, options, MAX_HIDDEN_LINE_ITEMS)
}

/// [`hidden_lines`] with at most `max_items` triangles and line points (a parameter so that a
/// test can reach the limit).
fn hidden_lines_at_most(
    view: &View,
    meshes: &[(&[DVec3], &[u32])],
    lines: &[(LineKind, &[DVec3])],
    options: HiddenLineOptions,
    max_items: usize,
) -> Result<Vec<Vec<Run>>> {
    options.check()?;
    let triangles: usize = meshes.iter().map(|(_, idx)| idx.len() / 3).sum();
    let points: usize = lines.iter().map(|(_, p)| p.len()).sum();
    for (what, got) in [("triangles", triangles), ("line points", points)] {
        if got > max_items {
            return Err(Error::TooMany { what, got, max: max_items });
        }
    }
    // τ from the triangles' bounding box
    let (lo, hi) = meshes
        .iter()
        .flat_map(|(p, idx)| idx.iter().filter_map(|&i| p.get(i as usize)))
        .filter(|p| p.is_finite())
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let tau = if lo.x <= hi.x { options.tolerance * (hi - lo).length() } else { 0.0 };
    let scene = Scene::new(view, meshes, tau);
    let mut stamp = vec![u32::MAX; scene.occluders.len()];
    let mut next_id = 0u32;
    let mut id = || {
        next_id = next_id.wrapping_add(1);
        if next_id == u32::MAX {
            next_id = 0;
        }
        next_id
    };
    let mut out = Vec::with_capacity(lines.len());
    for &(kind, points) in lines {
        let mut runs = Vec::new();
        match kind {
            LineKind::Points => {
                for &p in points {
                    let Some(image) = view.project(p) else { continue };
                    let mut hidden = false;
                    scene.cells_along(image, image, |k| {
                        hidden = hidden || hides_point(&scene.occluders[k as usize], p, image);
                    });
                    runs.push(Run { points: vec![image], visible: !hidden });
                }
            }
            LineKind::Segments => {
                for pair in points.chunks_exact(2) {
                    if let Some(seg) = clip_segment(view, pair[0], pair[1]) {
                        let parts = hidden_parts(&scene, &seg, &mut stamp, id());
                        let mut chain = Chain::new();
                        chain.push_segment(seg.ia.screen, seg.ib.screen, &parts);
                        runs.extend(chain.runs(options.min_piece));
                    }
                }
            }
            LineKind::Polyline { closed } => {
                // pieces of consecutive finite points; `closed` joins the last to the first when
                // no point is missing
                let all_finite = points.iter().all(|p| p.is_finite());
                let mut edges: Vec<(DVec3, DVec3)> = points.windows(2).map(|w| (w[0], w[1])).collect::<Vec<_>>();
                if closed && all_finite && points.len() > 2 {
                    edges.push((points[points.len() - 1], points[0]));
                }
                let mut chain = Chain::new();
                for (p, q) in edges {
                    let seg = clip_segment(view, p, q);
                    let joins = seg.as_ref().is_some_and(|s| chain.points.last() == Some(&s.ia.screen));
                    if !joins && !chain.visible.is_empty() {
                        runs.extend(std::mem::replace(&mut chain, Chain::new()).runs(options.min_piece));
                    }
                    if let Some(seg) = seg {
                        let parts = hidden_parts(&scene, &seg, &mut stamp, id());
                        chain.push_segment(seg.ia.screen, seg.ib.screen, &parts);
                    }
                }
                if !chain.visible.is_empty() {
                    runs.extend(chain.runs(options.min_piece));
                }
            }
        }
        out.push(runs);
    }
    Ok(out)
}
#[cfg(test)]
mod tests {
    use super::super::fixtures::{camera, exact, refused, seen, square};
    use super::*;
    use crate::tolerance::HIDDEN_LINE_TOLERANCE;
    use glam::{DMat4, DVec2};

    #[test]
    fn a_line_behind_a_square_is_hidden_exactly_over_its_shadow() {
        // seen from (0, 0, 10), the square's shadow on the plane z = −1 is [−1.1, 1.1]²
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let (p, idx) = square();
        let line = [DVec3::new(-5.0, 0.3, -1.0), DVec3::new(5.0, 0.3, -1.0)];
        let runs = hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &line)], exact()).unwrap();
        let runs = &runs[0];
        assert_eq!(seen(runs), [true, false, true]);
        let shadow = |x: f64| view.project(DVec3::new(x, 0.3, -1.0)).unwrap();
        crate::assert_near!(runs[1].points[0], shadow(-1.1), 1e-9);
        crate::assert_near!(runs[1].points[1], shadow(1.1), 1e-9);
        crate::assert_near!(runs[0].points[0], shadow(-5.0), 1e-9);
        crate::assert_near!(runs[2].points[1], shadow(5.0), 1e-9);
        // in front of the square, or beside its shadow: seen whole
        let front = [DVec3::new(-5.0, 0.3, 1.0), DVec3::new(5.0, 0.3, 1.0)];
        let beside = [DVec3::new(-5.0, 1.2, -1.0), DVec3::new(5.0, 1.2, -1.0)];
        let runs =
            hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &front), (LineKind::Segments, &beside)], exact())
                .unwrap();
        assert!(runs.iter().all(|r| r.len() == 1 && r[0].visible));
        // a line piercing the square: hidden from the crossing on, exactly
        let through = [DVec3::new(0.5, 0.0, 1.0), DVec3::new(0.5, 0.0, -1.0)];
        let slanted = [DVec3::new(-0.5, 0.0, 1.0), DVec3::new(0.5, 0.0, -1.0)];
        let runs = hidden_lines(
            &view,
            &[(&p, &idx)],
            &[(LineKind::Segments, &through), (LineKind::Segments, &slanted)],
            exact(),
        )
        .unwrap();
        assert_eq!(seen(&runs[0]), [true, false]);
        assert_eq!(seen(&runs[1]), [true, false]);
        let tau = HIDDEN_LINE_TOLERANCE * 8f64.sqrt();
        // hidden from where it is τ below the plane: z = −τ, x = τ/2 on the slanted line
        let crossing = view.project(DVec3::new(tau / 2.0, 0.0, -tau)).unwrap();
        crate::assert_near!(runs[1][1].points[0], crossing, 1e-9);
        // the same lines the other way: hidden up to there
        let (up, rising) = ([through[1], through[0]], [slanted[1], slanted[0]]);
        let runs =
            hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &up), (LineKind::Segments, &rising)], exact())
                .unwrap();
        assert_eq!(seen(&runs[0]), [false, true]);
        assert_eq!(seen(&runs[1]), [false, true]);
        crate::assert_near!(runs[1][0].points[1], crossing, 1e-9);
        crate::assert_near!(runs[1][0].points[0], view.project(rising[0]).unwrap(), 1e-9);
    }

    /// The scene of the last test moved off the origin (the square's plane no longer through
    /// it), the camera with it: the same runs, to rounding.
    #[test]
    fn a_moved_scene_hides_the_same() {
        let (p, idx) = square();
        let line = [DVec3::new(-5.0, 0.3, -1.0), DVec3::new(5.0, 0.3, -1.0)];
        let runs = |shift: DVec3| {
            let view = camera(DVec3::new(0.0, 0.0, 10.0) + shift, shift);
            let p: Vec<DVec3> = p.iter().map(|&q| q + shift).collect();
            let line = line.map(|q| q + shift);
            hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &line)], exact()).unwrap().remove(0)
        };
        let here = runs(DVec3::ZERO);
        for shift in [DVec3::new(3.0, -2.0, 7.0), DVec3::new(0.0, 0.0, -40.0)] {
            let there = runs(shift);
            assert_eq!(seen(&there), seen(&here), "{shift}");
            for (a, b) in there.iter().zip(&here) {
                for (x, y) in a.points.iter().zip(&b.points) {
                    crate::assert_near!(*x, *y, 1e-9);
                }
            }
        }
    }

    #[test]
    fn the_same_in_an_orthographic_view() {
        // x/3, y/2 onto [−1, 1]², looking down −z from z = 10 (near 0.1, far 100)
        let m = DMat4::from_cols_array(&[
            1.0 / 3.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.5,
            0.0,
            0.0,
            0.0,
            0.0,
            -2.0 / 99.9,
            0.0,
            0.0,
            0.0,
            (20.0 - 100.1) / 99.9,
            1.0,
        ]);
        let view = View::new(&m.to_cols_array(), 600.0, 400.0).unwrap();
        let (p, idx) = square();
        let line = [DVec3::new(-2.0, 0.0, -1.0), DVec3::new(2.0, 0.0, -1.0)];
        let runs = hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &line)], exact()).unwrap();
        assert_eq!(runs[0].len(), 3);
        crate::assert_near!(runs[0][1].points[0], DVec2::new(200.0, 200.0), 1e-9);
        crate::assert_near!(runs[0][1].points[1], DVec2::new(400.0, 200.0), 1e-9);
    }

    #[test]
    fn lines_on_a_surface_stay_visible_and_a_grid_leaves_no_sliver() {
        let view = camera(DVec3::new(3.0, -4.0, 6.0), DVec3::ZERO);
        // a 10 × 10 grid of squares on [−1, 1]², slightly bent (z = 0.05 x²)
        let n = 11;
        let p: Vec<DVec3> = (0..n * n)
            .map(|k| {
                let (x, y) = (-1.0 + 0.2 * (k % n) as f64, -1.0 + 0.2 * (k / n) as f64);
                DVec3::new(x, y, 0.05 * x * x)
            })
            .collect();
        let idx = crate::grid_indices(n, n);
        // its edges, a diagonal through its vertices, a curve on the smooth surface between them
        let edge: Vec<DVec3> = (0..n).map(|i| p[5 * n + i]).collect();
        let diagonal: Vec<DVec3> = (0..n).map(|i| p[i * n + i]).collect();
        let curve: Vec<DVec3> = (0..=200)
            .map(|k| {
                let x = -1.0 + 0.01 * k as f64;
                DVec3::new(x, 0.37, 0.05 * x * x)
            })
            .collect();
        let lines = [
            (LineKind::Polyline { closed: false }, &edge[..]),
            (LineKind::Polyline { closed: false }, &diagonal[..]),
            (LineKind::Polyline { closed: false }, &curve[..]),
        ];
        let runs = hidden_lines(&view, &[(&p, &idx)], &lines, exact()).unwrap();
        for r in &runs {
            assert_eq!(r.len(), 1);
            assert!(r[0].visible);
        }
        // the same lines pushed below the grid by 0.05 (> τ = 0.014): hidden whole, in one run each
        // (the diagonal passes exactly through vertices of the grid's image: no gap between triangles)
        // (their inner parts: an end below the grid's border peeks out beside it in perspective)
        let below = |v: &[DVec3]| {
            let k = v.len() / 10;
            v[k..v.len() - k].iter().map(|q| *q - DVec3::new(0.0, 0.0, 0.05)).collect::<Vec<_>>()
        };
        let (e, d, c) = (below(&edge), below(&diagonal), below(&curve));
        let lines = [
            (LineKind::Polyline { closed: false }, &e[..]),
            (LineKind::Polyline { closed: false }, &d[..]),
            (LineKind::Polyline { closed: false }, &c[..]),
        ];
        let runs = hidden_lines(&view, &[(&p, &idx)], &lines, exact()).unwrap();
        for r in &runs {
            assert!(r.iter().all(|run| !run.visible), "{r:?}");
        }
        assert_eq!(runs[1].len(), 1, "one run along the diagonal: {:?}", runs[1]);
    }

    #[test]
    fn dots_slivers_and_the_near_plane() {
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let (p, idx) = square();
        let dots = [DVec3::new(0.0, 0.0, -1.0), DVec3::new(3.0, 0.0, -1.0), DVec3::new(0.0, 0.0, 1.0)];
        let runs = hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Points, &dots)], exact()).unwrap();
        assert_eq!(
            runs[0].iter().map(|r| (r.points.len(), r.visible)).collect::<Vec<_>>(),
            [(1, false), (1, true), (1, true)]
        );
        // a line whose hidden part is a fraction of a pixel: the sliver goes to its neighbours
        let tiny = [
            DVec3::new(1.0995, -3.0, -1.0),
            DVec3::new(1.0995, -1.1, -1.0),
            DVec3::new(1.2, -1.0, -1.0),
            DVec3::new(2.0, -1.0, -1.0),
        ];
        let sliver =
            hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Polyline { closed: false }, &tiny)], exact()).unwrap();
        assert!(sliver[0].len() > 1, "the exact answer has a hidden sliver");
        let clean = hidden_lines(
            &view,
            &[(&p, &idx)],
            &[(LineKind::Polyline { closed: false }, &tiny)],
            HiddenLineOptions::default(),
        )
        .unwrap();
        assert_eq!(clean[0].len(), 1);
        assert!(clean[0][0].visible);
        let drawn = &clean[0][0].points;
        assert_eq!(
            (drawn[0], drawn[drawn.len() - 1]),
            (view.project(tiny[0]).unwrap(), view.project(tiny[3]).unwrap())
        );
        // behind the eye: cut at the near plane (0.1 in front of the eye), the rest drawn
        let long = [DVec3::new(0.5, 0.5, 20.0), DVec3::new(0.5, 0.5, 5.0)];
        let runs = hidden_lines(&view, &[], &[(LineKind::Segments, &long)], exact()).unwrap();
        assert_eq!(runs[0].len(), 1);
        // a NaN point breaks a polyline in two; bad options and views are refused
        let broken = [DVec3::ZERO, DVec3::X, DVec3::NAN, DVec3::Y, DVec3::ONE];
        let runs = hidden_lines(&view, &[], &[(LineKind::Polyline { closed: true }, &broken)], exact()).unwrap();
        assert_eq!(runs[0].len(), 2);
        // 20 000 triangles each filling the view: binned coarsely, answered quickly
        let huge: Vec<DVec3> = (0..20_000)
            .flat_map(|k| {
                let z = -0.5 - k as f64 * 1e-4;
                [DVec3::new(-50.0, -50.0, z), DVec3::new(50.0, -50.0, z), DVec3::new(0.0, 50.0, z)]
            })
            .collect();
        let idx: Vec<u32> = (0..60_000).collect();
        let runs = hidden_lines(&view, &[(&huge, &idx)], &[(LineKind::Points, &dots)], exact()).unwrap();
        assert_eq!(seen(&runs[0]), [false, false, true]);
        // a triangle naming no point hides nothing (and breaks nothing)
        let wild = [0, 1, u32::MAX, 0, 2, 3];
        let runs = hidden_lines(&view, &[(&p, &wild)], &[(LineKind::Points, &dots)], exact()).unwrap();
        assert_eq!(seen(&runs[0]), [false, true, true]);
        let bad = HiddenLineOptions { tolerance: f64::NAN, ..Default::default() };
        assert_eq!(hidden_lines(&view, &[], &[], bad).unwrap_err().code(), "invalid-argument");
        assert!(View::new(&[0.0; 16], 10.0, 10.0).is_err());
        assert!(View::new(&[1.0; 15], 10.0, 10.0).is_err());
        assert!(View::new(&DMat4::IDENTITY.to_cols_array(), 0.0, 10.0).is_err());
    }

    /// Options at their bounds, refused beyond by name; at most `max_items` triangles (counted
    /// in threes of indices) and line points.
    #[test]
    fn options_and_sizes_are_refused_by_name_at_their_bounds() {
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let with =
            |tolerance: f64, min_piece: f64| hidden_lines(&view, &[], &[], HiddenLineOptions { tolerance, min_piece });
        assert!(with(1.0, 1000.0).is_ok());
        assert!(with(0.0, 0.0).is_ok());
        for (tolerance, min_piece, which) in [
            (1.000_000_1, 1.0, "tolerance"),
            (-1e-9, 1.0, "tolerance"),
            (f64::INFINITY, 1.0, "tolerance"),
            (0.5, 1000.5, "minPiece"),
            (0.5, -1.0, "minPiece"),
            (0.5, f64::NAN, "minPiece"),
        ] {
            assert_eq!(refused(with(tolerance, min_piece)), which, "{tolerance} {min_piece}");
        }
        let e = with(0.5, 1000.5).unwrap_err().to_string();
        assert!(e.contains("minPiece must be a number in [0, 1000], got 1000.5"), "{e}");
        let (p, _) = square();
        let at_most_10 = |idx: &[u32], points: &[DVec3]| {
            hidden_lines_at_most(&view, &[(&p, idx)], &[(LineKind::Points, points)], exact(), 10)
        };
        let ten: Vec<u32> = [0, 1, 2].repeat(10);
        assert!(at_most_10(&ten, &[DVec3::ZERO; 10]).is_ok());
        let and_one_index: Vec<u32> = [&ten[..], &[3]].concat();
        assert!(at_most_10(&and_one_index, &[]).is_ok());
        let eleven: Vec<u32> = [0, 1, 2].repeat(11);
        let too_many = |r: Result<Vec<Vec<Run>>>| match r {
            Err(Error::TooMany { what, got, max }) => (what, got, max),
            other => panic!("expected too many, got {other:?}"),
        };
        assert_eq!(too_many(at_most_10(&eleven, &[])), ("triangles", 11, 10));
        assert_eq!(too_many(at_most_10(&ten, &[DVec3::ZERO; 11])), ("line points", 11, 10));
    }

    /// A closed polyline joins its last point to its first (three points or more); two points
    /// are one segment either way.
    #[test]
    fn closed_polylines_come_back_to_their_first_point() {
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let triangle = [DVec3::new(-1.0, -1.0, 0.0), DVec3::new(1.0, -1.0, 0.0), DVec3::new(0.0, 1.0, 0.0)];
        let images: Vec<DVec2> = triangle.iter().map(|&q| view.project(q).unwrap()).collect();
        let draw = |closed: bool, points: &[DVec3]| {
            hidden_lines(&view, &[], &[(LineKind::Polyline { closed }, points)], exact()).unwrap().remove(0)
        };
        assert_eq!(draw(true, &triangle), [Run { points: [&images[..], &images[..1]].concat(), visible: true }]);
        assert_eq!(draw(false, &triangle), [Run { points: images.clone(), visible: true }]);
        assert_eq!(draw(true, &triangle[..2]), [Run { points: images[..2].to_vec(), visible: true }]);
    }

    /// A point or a line ending on a surface is not hidden by it, tolerance zero or not; a square
    /// between the eye and the origin hides what is behind it, not what is in front (the eye's
    /// side of its plane from the homogeneous eye).
    #[test]
    fn what_lies_on_a_surface_is_seen_and_the_eye_decides_the_side() {
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let (p, idx) = square();
        let on = [DVec3::new(0.3, 0.2, 0.0)];
        let up = [DVec3::new(0.3, 0.2, 0.0), DVec3::new(0.3, 0.2, 1.0)];
        let down = [up[1], up[0]];
        for tolerance in [0.0, HIDDEN_LINE_TOLERANCE] {
            let options = HiddenLineOptions { tolerance, min_piece: 0.0 };
            let lines = [(LineKind::Points, &on[..]), (LineKind::Segments, &up[..]), (LineKind::Segments, &down[..])];
            let runs = hidden_lines(&view, &[(&p, &idx)], &lines, options).unwrap();
            for r in &runs {
                assert_eq!(seen(r), [true], "τ = {tolerance}: {r:?}");
            }
        }
        // from 100 above the origin (the eye's homogeneous w ≈ −1/2), a square at z = 60
        let view = camera(DVec3::new(0.0, 0.0, 100.0), DVec3::ZERO);
        let lifted: Vec<DVec3> = p.iter().map(|q| *q + DVec3::new(0.0, 0.0, 60.0)).collect();
        let dots = [DVec3::new(0.0, 0.0, 59.0), DVec3::new(0.0, 0.0, 61.0)];
        let runs = hidden_lines(&view, &[(&lifted, &idx)], &[(LineKind::Points, &dots)], exact()).unwrap();
        assert_eq!(seen(&runs[0]), [false, true]);
    }

    /// Eight squares in a row above a line drawn from right to left: the grid finds their
    /// triangles column by column, left to right, so the hidden intervals (in the line's
    /// parameter, which grows leftwards) come in falling order and must be sorted before they
    /// are merged; each shadow is hidden exactly, the gaps between them seen.
    #[test]
    fn hidden_parts_found_out_of_order_are_sorted() {
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let mut p = Vec::new();
        let mut idx = Vec::new();
        for k in 0..8 {
            let x = -3.75 + k as f64;
            let base = p.len() as u32;
            p.extend([
                DVec3::new(x - 0.25, -0.25, 0.0),
                DVec3::new(x + 0.25, -0.25, 0.0),
                DVec3::new(x + 0.25, 0.25, 0.0),
                DVec3::new(x - 0.25, 0.25, 0.0),
            ]);
            idx.extend([base, base + 1, base + 2, base, base + 2, base + 3]);
        }
        let scene = Scene::new(&view, &[(&p, &idx)], 0.0);
        assert!(scene.cols >= 3, "the squares lie in several columns of the grid");
        let line = [DVec3::new(5.0, 0.1, -1.0), DVec3::new(-5.0, 0.1, -1.0)];
        let runs = hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &line)], exact()).unwrap().remove(0);
        assert_eq!(runs.len(), 17);
        // seen from z = 10, a square's shadow on z = −1 is 1.1 times as wide
        let shadow = |x: f64| view.project(DVec3::new(1.1 * x, 0.1, -1.0)).unwrap();
        for (k, run) in runs.iter().enumerate() {
            assert_eq!(run.visible, k % 2 == 0, "run {k}");
            if !run.visible {
                let x = 3.25 - (k / 2) as f64;
                crate::assert_near!(run.points[0], shadow(x + 0.25), 1e-9);
                crate::assert_near!(run.points[1], shadow(x - 0.25), 1e-9);
            }
        }
    }
}
