//! Hidden lines on the hyperboloid of Example 1 (Fig. 2), against a ray cast: every ruling of
//! the discrete strip, and the exact striction curve lying on the smooth surface, are split by
//! `hidden_lines` where the front sheet hides them; at 1000 points along each, a ray from the
//! eye tested against every triangle (no grid, no intervals) must agree. Runs natively and, with
//! the same body, in headless Chromium under wasm-bindgen-test.

use glam::{DVec2, DVec3};
use ruledlab::tolerance::{HIDDEN_LINE_BEND, HIDDEN_LINE_TOLERANCE};
use ruledlab::{hidden_lines, strip_indices, AnalyticSurface, HiddenLineOptions, LineKind, Run, SmoothRuled, View};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

/// Fig. 2's strip: 36 rulings of the hyperboloid, closed, as the page draws it (a_i, b_i at
/// vertices 2i, 2i + 1), the eye where the page's striction scene looks from.
struct Figure {
    points: Vec<DVec3>,
    indices: Vec<u32>,
    eye: DVec3,
    view: View,
    /// Each triangle's tolerance: τ, or half of how far the triangles sharing an edge with it
    /// bend away from its plane (found here by brute force), whichever is larger.
    tau: Vec<f64>,
}

fn figure() -> Figure {
    let h = AnalyticSurface::by_name("hyperboloid").unwrap();
    let surface = h.sample(36, h.ranges()).unwrap();
    let points: Vec<DVec3> = surface.segments().flat_map(|s| [s.a, s.b]).collect();
    let indices = strip_indices(36, true);
    let (yaw, pitch, distance) = (-0.9f64, 0.45f64, 16.0);
    let eye = distance * DVec3::new(pitch.cos() * yaw.cos(), pitch.cos() * yaw.sin(), pitch.sin());
    let view = View::looking(eye, DVec3::ZERO, 35f64.to_radians(), 640.0, 420.0).unwrap();
    let (lo, hi) = points.iter().fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(l, h), &p| (l.min(p), h.max(p)));
    let tau = HIDDEN_LINE_TOLERANCE * (hi - lo).length();
    let triangles: Vec<[u32; 3]> = indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
    let tau = triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| points[i as usize]);
            let n = (b - a).cross(c - a).normalize();
            let mut bend: f64 = 0.0;
            for u in &triangles {
                let shared = u.iter().filter(|i| t.contains(i)).count();
                if shared == 2 {
                    let opposite = u.iter().find(|i| !t.contains(i)).unwrap();
                    bend = bend.max(n.dot(points[*opposite as usize] - a).abs());
                }
            }
            (HIDDEN_LINE_BEND * bend).max(tau)
        })
        .collect();
    Figure { points, indices, eye, view, tau }
}

/// Hidden by the ray cast: the segment from the eye to p crosses a triangle (Möller–Trumbore)
/// from which p lies more than τ behind the triangle's plane.
fn ray_cast_hidden(f: &Figure, p: DVec3) -> bool {
    let d = p - f.eye;
    f.indices.chunks_exact(3).zip(&f.tau).any(|(t, &tau)| {
        let [a, b, c] = [t[0], t[1], t[2]].map(|i| f.points[i as usize]);
        let (e1, e2) = (b - a, c - a);
        let q = d.cross(e2);
        let det = e1.dot(q);
        if det.abs() < 1e-14 {
            return false;
        }
        let s = f.eye - a;
        let u = s.dot(q) / det;
        let r = s.cross(e1);
        let v = d.dot(r) / det;
        let lambda = e2.dot(r) / det;
        let n = e1.cross(e2).normalize();
        u >= 0.0 && v >= 0.0 && u + v <= 1.0 && lambda > 0.0 && lambda < 1.0 && n.dot(p - a).abs() > tau
    })
}

/// The visibility `runs` give the image point x of a line whose image runs through `path`
/// (None within `margin` pixels of a change of visibility: there the two answers may differ
/// by rounding).
fn visibility_at(runs: &[Run], x: DVec2, margin: f64) -> Option<bool> {
    let mut best: Option<(f64, bool)> = None;
    let mut boundary = f64::INFINITY;
    for (k, run) in runs.iter().enumerate() {
        for w in run.points.windows(2) {
            let (a, b) = (w[0], w[1]);
            let t = ((x - a).dot(b - a) / (b - a).length_squared().max(1e-300)).clamp(0.0, 1.0);
            let dist = x.distance(a + (b - a) * t);
            if best.is_none_or(|(d, _)| dist < d) {
                best = Some((dist, run.visible));
            }
        }
        if k > 0 && runs[k - 1].visible != run.visible {
            boundary = boundary.min(x.distance(run.points[0]));
        }
    }
    let (dist, visible) = best?;
    assert!(dist < 1e-6, "{x} is on no run (nearest {dist} px away)");
    (boundary > margin).then_some(visible)
}

/// Compares `hidden_lines` with the ray cast at 1000 points of the polyline `line`; returns how
/// many of the points are hidden, and the runs.
fn compare(f: &Figure, line: &[DVec3], what: &str) -> (usize, Vec<Run>) {
    let exact = HiddenLineOptions { min_piece: 0.0, ..Default::default() };
    let runs =
        hidden_lines(&f.view, &[(&f.points, &f.indices)], &[(LineKind::Polyline { closed: false }, line)], exact)
            .unwrap()
            .remove(0);
    let length: Vec<f64> = line.windows(2).map(|w| w[0].distance(w[1])).collect();
    let total: f64 = length.iter().sum();
    let mut hidden = 0;
    for k in 0..1000 {
        // the point at arc length k/999 of the polyline
        let mut s = total * k as f64 / 999.0;
        let mut i = 0;
        while i + 1 < length.len() && s > length[i] {
            s -= length[i];
            i += 1;
        }
        let p = line[i].lerp(line[i + 1], (s / length[i]).min(1.0));
        let reference = ray_cast_hidden(f, p);
        hidden += reference as usize;
        if let Some(visible) = visibility_at(&runs, f.view.project(p).unwrap(), 1e-6) {
            assert_eq!(
                visible, !reference,
                "{what}: point {k} ({p}) visible {visible}, hidden by the ray cast {reference}"
            );
        }
    }
    (hidden, runs)
}

#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn rulings_of_the_hyperboloid_split_where_the_front_sheet_hides_them() {
    let f = figure();
    let mut split = 0;
    for i in 0..36 {
        let ruling = [f.points[2 * i], f.points[2 * i + 1]];
        let (hidden, _) = compare(&f, &ruling, &format!("ruling {i}"));
        split += (hidden > 0 && hidden < 1000) as usize;
    }
    // the back sheet's rulings are partly hidden by the front sheet, partly seen through the ends
    assert!(split >= 6, "only {split} rulings are split");
}

#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn the_exact_striction_curve_on_the_surface_is_seen_where_it_faces_the_eye() {
    let f = figure();
    let h = AnalyticSurface::by_name("hyperboloid").unwrap();
    let curve: Vec<DVec3> = (0..=400).map(|k| h.striction(std::f64::consts::TAU * k as f64 / 400.0).unwrap()).collect();
    let (hidden, runs) = compare(&f, &curve, "striction curve");
    // about half of the curve is behind the surface, or seen through the open ends
    assert!((300..700).contains(&hidden), "{hidden} of 1000 points hidden");
    // where the surface faces the eye, the curve lying on it is seen: not hidden by the strip,
    // from whose triangles the smooth curve is up to 0.078 away (HIDDEN_LINE_BEND)
    let mut facing = 0;
    for (k, p) in curve.iter().enumerate() {
        let j = h.jet(std::f64::consts::TAU * k as f64 / 400.0);
        let v = (*p - j.a).dot(j.d) / j.d.length_squared();
        let mut normal = j.d.cross(j.da + v * j.dd).normalize();
        if normal.dot(DVec3::new(p.x, p.y, 0.0)) < 0.0 {
            normal = -normal; // outwards
        }
        // clearly facing the eye (one facing away may be seen too, through an open end)
        if normal.dot((f.eye - *p).normalize()) > 0.3 {
            facing += 1;
            let seen = visibility_at(&runs, f.view.project(*p).unwrap(), 0.0);
            assert_eq!(seen, Some(true), "point {k} of the striction curve faces the eye but is hidden");
        }
    }
    assert!(facing > 100, "{facing}");
}
