//! Focal geometry of congruences and linear complexes (beyond the paper) against exact
//! answers: lines meeting two skew lines, the normals of an ellipsoid, an elliptic linear
//! congruence, Examples 4 and 5 with their measured orders; a helical surface's screw axis, a
//! hyperboloid's regulus, lines drawn from a given complex. Runs natively and in Chromium.

use glam::{DVec2, DVec3};
use ruledlab::assert_near;
use ruledlab::tolerance::test::ORDER;
use ruledlab::{fit_linear_complex, ComplexKind};
use ruledlab::{focal_analytic, focal_grid, SmoothCongruence, SmoothRuled};
use ruledlab::{AnalyticCongruence, CongruenceSpec};
use ruledlab::{AnalyticSurface, Segment};
use ruledlab::{Focal, FocalKind, LineCongruence};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

fn formula(p: [&str; 3], e: [&str; 3], u: (f64, f64), v: (f64, f64)) -> AnalyticCongruence {
    AnalyticCongruence::from_formulas(&CongruenceSpec {
        p: p.map(String::from),
        e: e.map(String::from),
        u,
        v,
        parameters: [0.0; 3],
        grid: (5, 5),
    })
    .unwrap()
}

fn focal_of(c: &LineCongruence) -> Vec<Focal> {
    focal_grid(c.rows(), c.cols(), &c.p(), &c.q())
}

/// The lines from (u, 0, −1) on one line to (0, v, 1) on a skew one: the focal points are the
/// two endpoints, and the Plücker coordinates are bilinear in (u, v), so the discrete focal
/// points are exact on every grid, at the boundary too.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn lines_meeting_two_skew_lines_have_their_focal_points_on_them() {
    let c = formula(["u", "0", "-1"], ["-u", "v", "2"], (-1.0, 1.5), (-0.5, 2.0));
    for (rows, cols) in [(2, 2), (3, 4), (9, 7)] {
        let grid = c.grid(rows, cols).unwrap();
        for (k, f) in focal_of(&grid).iter().enumerate() {
            let s = grid.line(k / cols, k % cols);
            assert_eq!(f.kind, FocalKind::Hyperbolic);
            assert_near!(f.points[0], s.a, 1e-12);
            assert_near!(f.points[1], s.b, 1e-12);
            assert_near!(f.parameters[0], 0.0, 1e-12);
            assert_near!(f.parameters[1], s.length(), 1e-12);
            assert_near!(f.middle, 0.5 * (s.a + s.b), 1e-12);
            // torsal: along u the lines sweep through the fixed point (0, v, 1) (the focal
            // point t₂), along v through (u, 0, −1) (t₁)
            assert_near!(f.torsal[0], DVec2::new(0.0, 1.0), 1e-12);
            assert_near!(f.torsal[1], DVec2::new(1.0, 0.0), 1e-12);
        }
        for (f, g) in focal_of(&grid).iter().zip(focal_analytic(&c, rows, cols)) {
            assert_near!(f.points[0], g.points[0], 1e-12);
            assert_near!(f.points[1], g.points[1], 1e-12);
            assert_near!(f.normality, g.normality, 1e-12);
        }
    }
}

/// A focal sheet is the grid of one focal point per line, two triangles per quad (a, a + cols,
/// a + cols + 1; a, a + cols + 1, a + 1); a point farther than FOCAL_SHEET_REACH diagonals of
/// the lines' bounding box from its centre, or not real, sits at the centre and drops its quads.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn a_focal_sheet_is_the_grid_of_focal_points_near_the_lines() {
    let c = formula(["u", "0", "-1"], ["-u", "v", "2"], (-1.0, 1.5), (-0.5, 2.0));
    let (rows, cols) = (3, 4);
    let grid = c.grid(rows, cols).unwrap();
    let mut focal = focal_of(&grid);
    let sheet = ruledlab::focal_sheet(&grid, &focal, 0);
    for (x, f) in sheet.positions.iter().zip(&focal) {
        assert_eq!(*x, f.points[0]);
    }
    let quad = |i: u32, j: u32| {
        let a = i * cols as u32 + j;
        [a, a + cols as u32, a + cols as u32 + 1, a, a + cols as u32 + 1, a + 1]
    };
    let all: Vec<u32> = (0..2).flat_map(|i| (0..3).flat_map(move |j| quad(i, j))).collect();
    assert_eq!(sheet.indices, all);
    // the endpoints span x ∈ [−1, 1.5], y ∈ [−0.5, 2], z ∈ [−1, 1]
    let centre = DVec3::new(0.25, 0.75, 0.0);
    let reach = ruledlab::tolerance::FOCAL_SHEET_REACH * 16.5f64.sqrt();
    focal[0].points[0] = centre + 1.01 * reach * DVec3::X;
    focal[6].points[0] = centre + 0.99 * reach * DVec3::Y;
    focal[11].points[0] = DVec3::NAN;
    let sheet = ruledlab::focal_sheet(&grid, &focal, 0);
    assert_near!(sheet.positions[0], centre, 1e-15);
    assert_eq!(sheet.positions[6], focal[6].points[0]);
    assert_near!(sheet.positions[11], centre, 1e-15);
    // quads (0, 0) and (1, 2) hold the dropped points
    let kept: Vec<u32> = [(0, 1), (0, 2), (1, 0), (1, 1)].into_iter().flat_map(|(i, j)| quad(i, j)).collect();
    assert_eq!(sheet.indices, kept);
}

const A: f64 = 3.0;
const B: f64 = 2.0;
const C: f64 = 1.0;

fn ellipsoid() -> AnalyticCongruence {
    formula(
        ["3*cos(u)*cos(v)", "2*sin(u)*cos(v)", "sin(v)"],
        ["cos(u)*cos(v)/3", "sin(u)*cos(v)/2", "sin(v)"],
        (0.2, 1.3),
        (-0.4, 0.7),
    )
}

/// The principal radii 1/κ of the ellipsoid x²/A² + y²/B² + z²/C² = 1 at x, from
/// K = 1/(A²B²C² h⁴) and |H| = (A² + B² + C² − |x|²)/(2A²B²C² h³), h² = Σ xᵢ²/aᵢ⁴.
fn principal_radii(x: DVec3) -> [f64; 2] {
    let h = (x.x * x.x / A.powi(4) + x.y * x.y / B.powi(4) + x.z * x.z / C.powi(4)).sqrt();
    let abc = A * A * B * B * C * C;
    let k = 1.0 / (abc * h.powi(4));
    let hm = (A * A + B * B + C * C - x.length_squared()) / (2.0 * abc * h.powi(3));
    let root = (hm * hm - k).max(0.0).sqrt();
    [1.0 / (hm + root), 1.0 / (hm - root)]
}

/// The normals of an ellipsoid: focal points at the centres of principal curvature, inside
/// (t = −1/κ along the outer normal), normality 0, and torsal directions along the lines of
/// curvature (Rodrigues: the normal turns along them by κ times the step, dN = −κ dx).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn normals_of_an_ellipsoid_focus_at_the_centres_of_curvature() {
    let c = ellipsoid();
    let (rows, cols) = (9, 9);
    let ((u0, u1), (v0, v1), _, _) = c.domain();
    let (hu, hv) = ((u1 - u0) / (rows - 1) as f64, (v1 - v0) / (cols - 1) as f64);
    for (k, f) in focal_analytic(&c, rows, cols).iter().enumerate() {
        let (u, v) = c.parameters(k / cols, k % cols, rows, cols);
        let jet = c.jet(u, v);
        let radii = principal_radii(jet.p);
        assert_eq!(f.kind, FocalKind::Hyperbolic);
        assert_near!(f.parameters[0], -radii[1], 1e-10);
        assert_near!(f.parameters[1], -radii[0], 1e-10);
        assert!(f.normality < 1e-10, "normality {}", f.normality);
        let n = jet.d.normalize();
        for (t, w) in f.parameters.iter().zip(f.torsal) {
            let dx = (jet.p_u * hu * w.x + jet.p_v * hv * w.y).reject_from(n);
            let dn = (jet.d_u * hu * w.x + jet.d_v * hv * w.y).reject_from(n) / jet.d.length();
            // x + t·n is stationary across the line along a torsal direction: dx + t·dN = 0
            assert_near!(dx + *t * dn, DVec3::ZERO, 1e-10 * dx.length().max(1.0));
        }
    }
}

/// The torsal strokes on the ellipsoid run along its lines of curvature, so the two strokes at a
/// point are orthogonal — up to the grid's second-order error, which falls by 4 per halving.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn torsal_strokes_on_the_ellipsoid_are_orthogonal() {
    let worst = |n: usize| {
        let grid = ellipsoid().grid(n, n).unwrap();
        let strokes = ruledlab::torsal_strokes(n, n, &grid.p(), &focal_of(&grid), 0.35);
        assert_eq!(strokes.len(), 2 * n * n, "two real torsal directions per line");
        strokes.chunks(2).map(|w| w[0].vector().normalize().dot(w[1].vector().normalize()).abs()).fold(0.0, f64::max)
    };
    let (coarse, fine) = (worst(9), worst(17));
    assert!(fine < 0.02, "|cos| between the strokes: {fine}");
    assert!(coarse / fine > 3.5, "not second order: {coarse} → {fine}");
}

/// Max over lines common to every level of |discrete − exact| for one quantity, on grids of
/// 2^k·(n − 1) + 1 lines per side; returns the errors per level.
fn errors(
    c: &AnalyticCongruence,
    base: (usize, usize),
    levels: usize,
    keep: impl Fn(usize, usize, usize, usize) -> bool,
    value: impl Fn(&Focal) -> Vec<f64>,
) -> Vec<f64> {
    (0..levels)
        .map(|l| {
            let (rows, cols) = ((base.0 - 1) * (1 << l) + 1, (base.1 - 1) * (1 << l) + 1);
            let exact = focal_analytic(c, rows, cols);
            let discrete = focal_of(&c.grid(rows, cols).unwrap());
            let step = 1 << l;
            let mut worst = 0.0f64;
            for i in (0..rows).step_by(step) {
                for j in (0..cols).step_by(step) {
                    if !keep(i / step, j / step, base.0, base.1) {
                        continue;
                    }
                    let k = i * cols + j;
                    for (a, b) in value(&discrete[k]).iter().zip(value(&exact[k])) {
                        worst = worst.max((a - b).abs());
                    }
                }
            }
            worst
        })
        .collect()
}

fn order(errs: &[f64]) -> f64 {
    let n = errs.len();
    (errs[n - 2] / errs[n - 1]).log2()
}

fn interior(i: usize, j: usize, rows: usize, cols: usize) -> bool {
    i > 0 && j > 0 && i + 1 < rows && j + 1 < cols
}

fn boundary(i: usize, j: usize, rows: usize, cols: usize) -> bool {
    !interior(i, j, rows, cols)
}

fn focal_parameters(f: &Focal) -> Vec<f64> {
    f.parameters.to_vec()
}

fn torsal_and_middle(f: &Focal) -> Vec<f64> {
    // directions up to sign are fixed by du > 0; the middle point and the normality too
    vec![f.torsal[0].x, f.torsal[0].y, f.torsal[1].x, f.torsal[1].y, f.middle.x, f.middle.y, f.middle.z, f.normality]
}

/// Second order in the interior and at the boundary, for the focal parameters, the torsal
/// directions, the middle points and the normality — on the ellipsoid's normals and on the
/// paper's Examples 4 (both congruences of Fig. 13) and 5 (Fig. 15), on lines that are
/// hyperbolic and keep their focal points within reach (|t| < 20).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn discrete_focal_geometry_converges_with_second_order() {
    let cases = [
        (ellipsoid(), (5, 5)),
        (AnalyticCongruence::Sphere, (5, 5)),
        (AnalyticCongruence::HyperbolicParaboloid, (5, 5)),
        (AnalyticCongruence::Example5, (8, 7)),
    ];
    for (c, base) in cases {
        let exact = focal_analytic(&c, base.0, base.1);
        let good = |i: usize, j: usize, _: usize, cols: usize| {
            let f = &exact[i * cols + j];
            f.kind == FocalKind::Hyperbolic && f.parameters.iter().all(|t| t.abs() < 20.0)
        };
        assert!(exact.iter().filter(|f| f.kind == FocalKind::Hyperbolic).count() > 0, "{}", c.name());
        for (region, name) in [(interior as fn(usize, usize, usize, usize) -> bool, "interior"), (boundary, "boundary")]
        {
            let keep = |i: usize, j: usize, r: usize, cc: usize| region(i, j, r, cc) && good(i, j, r, cc);
            for (what, value) in [
                ("parameters", focal_parameters as fn(&Focal) -> Vec<f64>),
                ("torsal, middle, normality", torsal_and_middle),
            ] {
                let e = errors(&c, base, 5, keep, value);
                let p = order(&e);
                println!(
                    "order {} {name} {what}: {p:.2} (errors {:.1e} → {:.1e})",
                    c.name(),
                    e[e.len() - 2],
                    e[e.len() - 1]
                );
                assert!(p > 2.0 - 2.0 * ORDER, "{} {name} {what}: order {p:.2}, errors {e:?}", c.name());
            }
        }
    }
}

/// Lines x = (u, v, 0) + t·(−kv, ku, 1): no real focal point anywhere (kind 0, NaN), a real
/// middle point, in the discrete and the exact version.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn an_elliptic_congruence_has_no_real_focal_points() {
    let c = formula(["u", "v", "0"], ["-0.7*v", "0.7*u", "1"], (-1.0, 1.0), (-1.0, 1.0));
    let discrete = focal_of(&c.grid(6, 7).unwrap());
    for f in discrete.iter().chain(&focal_analytic(&c, 6, 7)) {
        assert_eq!(f.kind, FocalKind::Elliptic);
        assert!(f.parameters.iter().chain(&[f.normality]).all(|x| x.is_nan()));
        assert!(f.points.iter().all(|x| x.is_nan()) && f.torsal.iter().all(|x| x.is_nan()));
        assert!(f.middle.is_finite());
    }
}

/// Lines x = (u, 0, 0) + t·(v, 1, u): through each point of the x-axis a pencil of lines, so
/// every line has one double focal point, at t = 0 on the axis; det(p_u + t·d_u, p_v + t·d_v, d)
/// = t². Its Plücker coordinates are quadratic in (u, v), so grid differences are exact: the
/// discrete congruence is parabolic too, with the pencil's direction (0, 1) as torsal direction.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn a_parabolic_congruence_has_one_double_focal_point() {
    let c = formula(["u", "0", "0"], ["v", "1", "u"], (-1.0, 1.0), (-1.0, 1.0));
    let grid = c.grid(5, 6).unwrap();
    for (k, (f, g)) in focal_of(&grid).iter().zip(focal_analytic(&c, 5, 6)).enumerate() {
        for f in [f, &g] {
            assert_eq!(f.kind, FocalKind::Parabolic, "line {k}");
            assert_near!(f.parameters[0], 0.0, 1e-12);
            assert_near!(f.parameters[1], 0.0, 1e-12);
            assert_near!(f.points[0], grid.line(k / 6, k % 6).a, 1e-12);
            assert_near!(f.torsal[0], DVec2::new(0.0, 1.0), 1e-12);
            assert_eq!(f.normality, 1.0);
        }
    }
}

/// The normals of a cylinder of radius 2: one focal point on the axis (t = −2), the other at
/// infinity (a = 0 in (F3): t = ±∞, point NaN); the focal planes are orthogonal. The sheet at
/// infinity has no triangle to draw, the one on the axis all of them.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn normals_of_a_cylinder_have_a_focal_point_at_infinity() {
    let c = formula(["2*cos(u)", "2*sin(u)", "v"], ["cos(u)", "sin(u)", "0"], (0.0, 2.0), (-1.0, 1.0));
    let grid = c.grid(17, 5).unwrap();
    let discrete = focal_of(&grid);
    let exact = focal_analytic(&c, 17, 5);
    // the discrete axis point is second-order accurate (h = 1/8 here), the exact one to rounding
    let cases = discrete.iter().map(|f| (f, 2e-2)).chain(exact.iter().map(|f| (f, 1e-12)));
    for (f, tolerance) in cases {
        assert_eq!(f.kind, FocalKind::Hyperbolic);
        let (finite, infinite) = if f.parameters[0].is_finite() { (0, 1) } else { (1, 0) };
        assert!(f.parameters[infinite].is_infinite(), "{:?}", f.parameters);
        assert!(f.points[infinite].is_nan());
        assert_near!(f.parameters[finite], -2.0, tolerance);
        assert!(f.normality < 1e-12, "normality {}", f.normality);
    }
    let sheets = [0, 1].map(|s| ruledlab::focal_sheet(&grid, &discrete, s).indices.len());
    assert_eq!(sheets.iter().filter(|&&n| n == 0).count(), 1, "{sheets:?}");
    assert_eq!(sheets.iter().max(), Some(&(6 * 16 * 4)));
}

/// Swapping p and q of every line keeps the focal points exactly (up to rounding).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn reversed_lines_keep_their_focal_points() {
    let c = AnalyticCongruence::Example5.grid(8, 7).unwrap();
    let reversed = LineCongruence::from_points(8, 7, &c.q(), &c.p()).unwrap();
    for (f, g) in focal_of(&c).iter().zip(focal_of(&reversed)) {
        assert_eq!(f.kind, g.kind);
        if f.kind == FocalKind::Hyperbolic {
            // t runs the other way from the other end: the points are the same, in swapped order
            let (a, b) = if (f.points[0] - g.points[0]).length() < (f.points[0] - g.points[1]).length() {
                (g.points[0], g.points[1])
            } else {
                (g.points[1], g.points[0])
            };
            assert_near!(f.points[0], a, 1e-9);
            assert_near!(f.points[1], b, 1e-9);
            assert_near!(f.normality, g.normality, 1e-9);
        }
        assert_near!(f.middle, g.middle, 1e-9);
    }
}

fn rulings(s: &AnalyticSurface, n: usize) -> Vec<Segment> {
    s.sample(n, s.ranges()).unwrap().segments().collect()
}

/// The rulings of a helical surface lie in one linear complex whose axis is the screw axis
/// (here z); those of the right helicoid meet the axis at right angles (a linear congruence);
/// a hyperboloid's are a regulus.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn linear_complexes_of_helical_surfaces_and_a_hyperboloid() {
    let helical = AnalyticSurface::HelicalRuled { radius: 1.5, pitch: 0.4, slope: 0.6 };
    let f = fit_linear_complex(&rulings(&helical, 40), None);
    assert_eq!((f.nullity, f.kind), (1, ComplexKind::Complex));
    assert_near!(f.axis_direction.cross(DVec3::Z), DVec3::ZERO, 1e-10);
    assert_near!(f.axis_point, DVec3::ZERO, 1e-10);
    assert!(f.residual < 1e-12);
    // the piece of axis to draw lies on the z-axis, centred at the rulings' mean height
    let mean_z = rulings(&helical, 40).iter().map(|s| 0.5 * (s.a.z + s.b.z)).sum::<f64>() / 40.0;
    for end in f.axis_segment {
        assert_near!(DVec3::new(end.x, end.y, 0.0), DVec3::ZERO, 1e-10);
    }
    assert_near!(0.5 * (f.axis_segment[0].z + f.axis_segment[1].z), mean_z, 1e-10);
    let helicoid = AnalyticSurface::Helicoid { pitch: 0.5 };
    let f = fit_linear_complex(&rulings(&helicoid, 40), None);
    assert_eq!((f.nullity, f.kind), (2, ComplexKind::Congruence));
    let hyperboloid = AnalyticSurface::Hyperboloid { a: 1.0, b: 2.0, c: 3.0 };
    let f = fit_linear_complex(&rulings(&hyperboloid, 40), None);
    assert_eq!((f.nullity, f.kind), (3, ComplexKind::Regulus));
    // Example 3's quartic: a = (1, u²/2, u), d = (u², u, −1), m = a × d has m_x = −3u²/2, so
    // m_x + (3/2) d_x = 0: a complex with the x-axis as axis and pitch 3/2
    let f = fit_linear_complex(&rulings(&AnalyticSurface::Quartic, 40), None);
    assert_eq!((f.nullity, f.kind), (1, ComplexKind::Complex));
    assert_near!(f.axis_direction.cross(DVec3::X), DVec3::ZERO, 1e-10);
    assert_near!(f.pitch, 1.5, 1e-10);
    assert_near!(f.axis_point, DVec3::ZERO, 1e-10);
    // seven lines in general position
    let general: Vec<Segment> = (0..7)
        .map(|k| {
            let t = k as f64;
            Segment::new(DVec3::new(t.sin(), (2.0 * t).cos(), t * 0.3), DVec3::new((3.0 * t).cos(), t.cos() + 2.0, -t))
        })
        .collect();
    assert_eq!(fit_linear_complex(&general, None).kind, ComplexKind::General);
}

/// The tolerance decides the nullity: rulings of a helical surface moved by up to 1e-7 lie in
/// no complex at the default 1e-9, in one at 1e-5.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn the_tolerance_decides_what_holds_the_lines() {
    let helical = AnalyticSurface::HelicalRuled { radius: 1.5, pitch: 0.4, slope: 0.6 };
    let noisy: Vec<Segment> = rulings(&helical, 40)
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let wobble = 1e-7 * DVec3::new((k as f64 * 1.3).sin(), (k as f64 * 2.1).cos(), (k as f64 * 0.7).sin());
            Segment::new(s.a + wobble, s.b - wobble)
        })
        .collect();
    assert_eq!(fit_linear_complex(&noisy, None).kind, ComplexKind::General);
    let loose = fit_linear_complex(&noisy, Some(1e-5));
    assert_eq!((loose.nullity, loose.kind), (1, ComplexKind::Complex));
    assert_near!(loose.axis_direction.cross(DVec3::Z), DVec3::ZERO, 1e-5);
}

/// Lines drawn from a given complex give it back to 1e-10.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn lines_of_a_given_complex_give_it_back() {
    let (axis, point, pitch) = (DVec3::new(1.0, 2.0, -0.5).normalize(), DVec3::new(0.3, -1.0, 2.0), 0.7);
    // c = axis, c̄ = pitch·c + point × c  (axis point (c × c̄) is then the foot of `point`)
    let cbar = pitch * axis + point.cross(axis);
    let mut seed = 7u64;
    let mut rand = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let lines: Vec<Segment> = (0..50)
        .map(|_| {
            let x = DVec3::new(rand(), rand(), rand()) * 4.0;
            // lines through x in the complex are orthogonal to c̄ + c × x (the null plane)
            let normal = cbar + axis.cross(x);
            let d = DVec3::new(rand(), rand(), rand()).reject_from(normal).normalize();
            Segment::new(x, x + (1.0 + rand().abs()) * d)
        })
        .collect();
    let f = fit_linear_complex(&lines, None);
    assert_eq!((f.nullity, f.kind), (1, ComplexKind::Complex));
    let sign = f.axis_direction.dot(axis).signum();
    let got = DVec3::from_slice(&f.plucker[..3]) * sign;
    let got_bar = DVec3::from_slice(&f.plucker[3..]) * sign;
    assert_near!(got, axis, 1e-10);
    assert_near!(got_bar, cbar, 1e-10);
    assert_near!(f.pitch, pitch, 1e-10);
    assert_near!(f.axis_point, point.reject_from(axis), 1e-10);
}
