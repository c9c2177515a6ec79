//! Section 5 against exact congruences. Runs natively and in Chromium.

use ruledlab::assert_near;
use ruledlab::AnalyticCongruence;
use ruledlab::{
    butterfly_diagonal, subdivide_congruence as subdivide, CongruenceScheme, LineCongruence, SmoothCongruence,
};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

const BUTTERFLY: CongruenceScheme = CongruenceScheme::Butterfly { w: 1.0 / 16.0 };

fn keeps_old_lines(c: &LineCongruence, r: &LineCongruence) {
    assert_eq!((r.rows(), r.cols()), (2 * c.rows() - 1, 2 * c.cols() - 1));
    for i in 0..c.rows() {
        for j in 0..c.cols() {
            assert_eq!(r.line(2 * i, 2 * j), c.line(i, j));
        }
    }
}

/// The paper's scheme read literally (docs/src/conventions.md, Section 5.2): edge lines by the literal strip energy are
/// the midpoint rule, and the face line, the average of its 8 neighbours, is then the bilinear
/// average of the 4 corners, exactly.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn the_papers_scheme_read_literally_is_bilinear_averaging() {
    let c = AnalyticCongruence::Example5.grid(5, 4).unwrap();
    let r = subdivide(&c, CongruenceScheme::Paper { k: 6 }, 1).unwrap();
    keeps_old_lines(&c, &r);
    for i in 0..r.rows() {
        for j in 0..r.cols() {
            let corners: Vec<(usize, usize)> =
                [(i / 2, j / 2), (i.div_ceil(2), j / 2), (i / 2, j.div_ceil(2)), (i.div_ceil(2), j.div_ceil(2))]
                    .to_vec();
            let mean = |end: fn(&ruledlab::Segment) -> glam::DVec3| {
                corners.iter().map(|&(a, b)| end(&c.line(a, b))).sum::<glam::DVec3>() / 4.0
            };
            assert_near!(r.line(i, j).a, mean(|s| s.a), 1e-13);
            assert_near!(r.line(i, j).b, mean(|s| s.b), 1e-13);
        }
    }
}

/// Example 5 (Fig. 15): 8 × 7 lines on [−1.1, 1.1]², K = 6, refined to 15 × 13 by every
/// scheme with the old lines kept bit for bit; against the exact congruence, the coupled
/// scheme beats the two-stage one, which beats bilinear averaging; butterfly is best.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn example_5() {
    let ex = AnalyticCongruence::Example5;
    let c = ex.grid(8, 7).unwrap();
    let two = subdivide(&c, CongruenceScheme::TwoStage { k: 6 }, 1).unwrap();
    let coupled = subdivide(&c, CongruenceScheme::Coupled { k: 6 }, 1).unwrap();
    let butterfly = subdivide(&c, BUTTERFLY, 1).unwrap();
    for r in [&two, &coupled, &butterfly] {
        keeps_old_lines(&c, r);
    }
    let (e2, ec, eb) = (ex.errors(&two), ex.errors(&coupled), ex.errors(&butterfly));
    assert!(ec.0 < e2.0 && ec.1 < e2.1, "coupled {ec:?} vs two-stage {e2:?}");
    assert!(eb.0 < ec.0 && eb.1 < ec.1, "butterfly {eb:?} vs coupled {ec:?}");
    assert!(e2.0 < 0.05 && e2.1 < 0.02);
}

/// On the hyperbolic paraboloid the director surface is bilinear: butterfly and the coupled
/// scheme place every new point on it exactly.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn bilinear_director_surface_is_reproduced() {
    let h = AnalyticCongruence::HyperbolicParaboloid;
    let c = h.grid(6, 6).unwrap();
    for scheme in [BUTTERFLY, CongruenceScheme::Coupled { k: 6 }] {
        let (d, _) = h.errors(&subdivide(&c, scheme, 1).unwrap());
        assert!(d < 1e-11, "{scheme:?}: {d:e}");
    }
}

/// Fig. 13: the paper's diagonal-only insertion gives (rows − 1) × (cols − 1) lines, the
/// odd-odd lines of the full butterfly step.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn diagonal_insertion_of_fig_13() {
    let s = AnalyticCongruence::Sphere.grid(6, 6).unwrap();
    let d = butterfly_diagonal(&s, 1.0 / 16.0).unwrap();
    let full = subdivide(&s, BUTTERFLY, 1).unwrap();
    assert_eq!((d.rows(), d.cols()), (5, 5));
    for i in 0..5 {
        for j in 0..5 {
            assert_eq!(d.line(i, j), full.line(2 * i + 1, 2 * j + 1));
        }
    }
}

/// The accuracy of Fig. 13's diagonal insertion, measured at the cell centres: the errors of
/// the full butterfly step over its odd-odd lines (the same lines), and never more than the
/// full step's errors over all its new lines; no distance where the scheme reproduces the
/// points (bilinear in (u, v)).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn errors_of_the_diagonal_insertion() {
    for c in [AnalyticCongruence::Sphere, AnalyticCongruence::HyperbolicParaboloid, AnalyticCongruence::Example5] {
        let ((u0, u1), (v0, v1), r, cc) = c.domain();
        let grid = c.grid(r, cc).unwrap();
        let diagonal = c.diagonal_errors(&butterfly_diagonal(&grid, 1.0 / 16.0).unwrap());
        let full = subdivide(&grid, BUTTERFLY, 1).unwrap();
        let mut odd = (0.0f64, 0.0f64);
        for i in (1..full.rows()).step_by(2) {
            for j in (1..full.cols()).step_by(2) {
                let u = u0 + (u1 - u0) * i as f64 / (full.rows() - 1) as f64;
                let v = v0 + (v1 - v0) * j as f64 / (full.cols() - 1) as f64;
                let (p, d) = c.line(u, v);
                let s = full.line(i, j);
                odd = (odd.0.max((s.a - p).length()), odd.1.max(s.vector().angle_between(d)));
            }
        }
        assert_near!(diagonal.0, odd.0, 1e-15);
        assert_near!(diagonal.1, odd.1, 1e-15);
        let all = c.errors(&full);
        assert!(diagonal.0 <= all.0 && diagonal.1 <= all.1, "{c:?}: {diagonal:?} vs {all:?}");
    }
    // exact where the scheme reproduces the data: the hyperbolic paraboloid's points (u, v, uv)
    // are bilinear, so the inserted points lie on it
    let h = AnalyticCongruence::HyperbolicParaboloid;
    let ((_, _), (_, _), r, cc) = h.domain();
    let (distance, angle) = h.diagonal_errors(&butterfly_diagonal(&h.grid(r, cc).unwrap(), 1.0 / 16.0).unwrap());
    assert!(distance < 1e-15 && angle > 1e-4, "{distance} {angle}");
}

/// Repeated butterfly steps on the sphere converge to the exact lines at third order or
/// better in the distance of the new points (cubic precision).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn butterfly_error_falls_with_the_grid() {
    let s = AnalyticCongruence::Sphere;
    let coarse = s.errors(&subdivide(&s.grid(6, 6).unwrap(), BUTTERFLY, 1).unwrap());
    let fine = s.errors(&subdivide(&s.grid(11, 11).unwrap(), BUTTERFLY, 1).unwrap());
    assert!((coarse.0 / fine.0).log2() > 2.5, "{coarse:?} → {fine:?}");
}

/// Rows and columns are ruled surfaces; sizes and parameters are checked.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn rows_columns_and_limits() {
    let c = AnalyticCongruence::Example5.grid(8, 7).unwrap();
    assert_eq!(c.row(3).unwrap().invariants().angle.len(), 6);
    assert_eq!(c.column(6).unwrap().len(), 8);
    assert!(subdivide(&c, BUTTERFLY, 10).is_err());
    assert!(subdivide(&c, CongruenceScheme::Butterfly { w: f64::NAN }, 1).is_err());
    assert!(subdivide(&c, CongruenceScheme::TwoStage { k: 2 }, 1).is_err());
}

/// The coupled solve takes a bounded number of conjugate-gradient iterations however large
/// the grid (every unknown has fixed old neighbours): time linear in the number of lines.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn coupled_solve_iterations_do_not_grow_with_the_grid() {
    let counts: Vec<usize> = [9, 17, 33]
        .iter()
        .map(|&n| {
            ruledlab::coupled_congruence(&AnalyticCongruence::Example5.grid(n, n).unwrap(), 6).unwrap().1.iterations
        })
        .collect();
    assert!(counts.iter().all(|&k| k > 0 && k <= 40), "{counts:?}");
    assert!(counts[2] <= counts[0] + 2, "iterations grow: {counts:?}");
}
