//! The butterfly scheme (16) in the space of lines (beyond the paper): the congruence's lines
//! as dual unit vectors e + ε m (`crate::subdivision::line_space`), the stencils applied to the
//! real and the dual parts with the same weights, each new dual vector projected back onto the
//! dual unit sphere, N(a + ε a₀) = a/|a| + ε (a₀/|a| − a (a·a₀)/|a|³). The result depends on the
//! lines only, not on the points chosen on them, and commutes with rigid motions.
//!
//! **Orientation.** A line has two dual unit vectors ±L; before refining, each line's sign is
//! chosen so that its direction makes an acute angle with its predecessor's (along rows, then
//! down the first column).

use crate::congruence::{butterfly, LineCongruence};
use crate::error::{Error, Result};
use crate::ruled::PairInvariants;
use crate::subdivision::line_space::{join, split, DualLine};
use glam::DVec3;

/// Butterfly (16) on the lines of a congruence; each refined line is cut to `length` (default:
/// the mean input length) centred on the mean of its footpoints with its grid neighbours.
pub fn butterfly_lines(c: &LineCongruence, w: f64, steps: usize, length: Option<f64>) -> Result<LineCongruence> {
    let (mut rows, mut cols) = (c.rows(), c.cols());
    for _ in 0..steps {
        (rows, cols) = (2 * rows - 1, 2 * cols - 1);
        if rows.saturating_mul(cols) > crate::tolerance::MAX_RULINGS {
            return Err(Error::TooMany {
                what: "lines after subdivision",
                got: rows.saturating_mul(cols),
                max: crate::tolerance::MAX_RULINGS,
            });
        }
    }
    if !(w.is_finite() && (-0.25..=0.25).contains(&w)) {
        return Err(Error::parameter("w", format!("must be a number in [−1/4, 1/4], got {w}")));
    }
    let length = length.unwrap_or_else(|| {
        let n = c.rows() * c.cols();
        (0..n).map(|k| c.line(k / c.cols(), k % c.cols()).length()).sum::<f64>() / n as f64
    });
    // orientation: along each row, and each row's first line after the previous row's
    let (mut r, mut cc) = (c.rows(), c.cols());
    let mut lines: Vec<DualLine> = Vec::with_capacity(r * cc);
    for i in 0..r {
        for j in 0..cc {
            let mut d = DualLine::of(&c.line(i, j).line());
            let prev = if j > 0 {
                Some(lines[i * cc + j - 1])
            } else if i > 0 {
                Some(lines[(i - 1) * cc])
            } else {
                None
            };
            if prev.is_some_and(|p| p.real.dot(d.real) < 0.0) {
                d = DualLine { real: -d.real, dual: -d.dual };
            }
            lines.push(d);
        }
    }
    for _ in 0..steps {
        let (real, dual) = split(&lines);
        lines = join(butterfly::refine_points(&real, r, cc, w), butterfly::refine_points(&dual, r, cc, w))?;
        (r, cc) = (2 * r - 1, 2 * cc - 1);
    }
    let line_at = |i: usize, j: usize| lines[i * cc + j].line();
    let mut p = Vec::with_capacity(r * cc);
    let mut q = Vec::with_capacity(r * cc);
    for i in 0..r {
        for j in 0..cc {
            let l = line_at(i, j);
            let neighbours = [(i.wrapping_sub(1), j), (i + 1, j), (i, j.wrapping_sub(1)), (i, j + 1)];
            let feet: Vec<DVec3> = neighbours
                .iter()
                .filter(|&&(a, b)| a < r && b < cc)
                .filter_map(|&(a, b)| PairInvariants::of(&l, &line_at(a, b)).feet.map(|f| f.0))
                .collect();
            let centre = if feet.is_empty() { l.point } else { feet.iter().sum::<DVec3>() / feet.len() as f64 };
            p.push(centre - 0.5 * length * l.dir);
            q.push(centre + 0.5 * length * l.dir);
        }
    }
    LineCongruence::from_points(r, cc, &p, &q)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tolerance::MAX_RULINGS;

    fn congruence(rows: usize, cols: usize, ends: impl Fn(usize, usize) -> (DVec3, DVec3)) -> LineCongruence {
        let (p, q): (Vec<DVec3>, Vec<DVec3>) = (0..rows * cols).map(|k| ends(k / cols, k % cols)).unzip();
        LineCongruence::from_points(rows, cols, &p, &q).unwrap()
    }

    fn assert_lines(c: &LineCongruence, expected: impl Fn(usize, usize) -> (DVec3, DVec3)) {
        for i in 0..c.rows() {
            for j in 0..c.cols() {
                let (g, (p, q)) = (c.line(i, j), expected(i, j));
                assert!((g.a - p).length() < 1e-12 && (g.b - q).length() < 1e-12, "({i}, {j}): {g:?} vs {p} → {q}");
            }
        }
    }

    /// Parallel lines x = (i, 2j, ·): the dual parts (2j, −i, 0) are linear in the grid, which
    /// the butterfly reproduces, so two steps put the lines at (i/2, j, ·) exactly. Three lines
    /// come reversed (one along a row, one down the first column, one inside): the orientation
    /// step turns them back. Parallel neighbours have no feet, so each line is centred on its
    /// own point nearest the origin, (x, y, 0), and cut to the mean input length: column j runs
    /// from z = −1 to 2 + j, lengths 3, 4, 5, 6, mean 4.5.
    #[test]
    fn parallel_lines_refine_to_the_half_grid_reversed_ones_included() {
        let c = congruence(3, 4, |i, j| {
            let (p, q) =
                (DVec3::new(i as f64, 2.0 * j as f64, -1.0), DVec3::new(i as f64, 2.0 * j as f64, 2.0 + j as f64));
            if [(0, 2), (2, 0), (1, 1)].contains(&(i, j)) {
                (q, p)
            } else {
                (p, q)
            }
        });
        let r = butterfly_lines(&c, 1.0 / 16.0, 2, None).unwrap();
        assert_eq!((r.rows(), r.cols()), (9, 13));
        assert_lines(&r, |i, j| {
            let (x, y) = (i as f64 / 4.0, j as f64 / 2.0);
            (DVec3::new(x, y, -2.25), DVec3::new(x, y, 2.25))
        });
    }

    /// No step shows the orientation: each line's sign makes an acute angle with its left
    /// neighbour's, a row's first line with the first line above. Directions in the xy-plane (in
    /// degrees, lines at different heights): row 0 at 0, 60, 120 keeps them; row 1's first at 150
    /// is turned to 330 by the line above it, and 255, 200 then follow their left neighbours
    /// (each is obtuse to the line above-left, 0 and 60, which a wrong reference would use);
    /// row 2's first at 255 is acute to 330 above it and obtuse to row 0's 0.
    #[test]
    fn each_line_is_oriented_by_its_left_neighbour_or_the_first_line_above() {
        let given = [[0.0, 60.0, 120.0], [150.0, 255.0, 200.0], [255.0, 300.0, 340.0]];
        let expected = [[0.0, 60.0, 120.0], [330.0, 255.0, 200.0], [255.0, 300.0, 340.0]];
        let dir = |deg: f64| DVec3::new(deg.to_radians().cos(), deg.to_radians().sin(), 0.0);
        let c = congruence(3, 3, |i, j| {
            let m = DVec3::new(i as f64, j as f64, (3 * i + j) as f64);
            (m - dir(given[i][j]), m + dir(given[i][j]))
        });
        let r = butterfly_lines(&c, 0.0, 0, None).unwrap();
        for i in 0..3 {
            for j in 0..3 {
                let g = r.line(i, j);
                let d = (g.b - g.a).normalize();
                assert!((d - dir(expected[i][j])).length() < 1e-12, "({i}, {j}): {d}, expected {}°", expected[i][j]);
            }
        }
    }

    /// No step: each line is centred on the mean of its feet with its grid neighbours, worked
    /// out by hand. L₀₀ is the x-axis, L₀₁ and L₁₀ run along y through (5, 0, 1) and
    /// (−3, 0, −1), L₁₁ along x through (0, 4, 2); input lengths 2, 4, 3, 7 (mean 4).
    #[test]
    fn each_line_is_centred_on_the_mean_of_its_feet_with_its_neighbours() {
        let x = DVec3::X;
        let y = DVec3::Y;
        let ends = [
            (DVec3::new(-1.0, 0.0, 0.0), DVec3::new(1.0, 0.0, 0.0)),
            (DVec3::new(5.0, -2.0, 1.0), DVec3::new(5.0, 2.0, 1.0)),
            (DVec3::new(-3.0, -1.0, -1.0), DVec3::new(-3.0, 2.0, -1.0)),
            (DVec3::new(-3.0, 4.0, 2.0), DVec3::new(4.0, 4.0, 2.0)),
        ];
        let c = congruence(2, 2, |i, j| ends[2 * i + j]);
        // feet on L₀₀: (5, 0, 0) and (−3, 0, 0); on L₀₁: (5, 0, 1), (5, 4, 1); on L₁₀: (−3, 0, −1),
        // (−3, 4, −1); on L₁₁: (5, 4, 2), (−3, 4, 2)
        let centres = [
            (DVec3::new(1.0, 0.0, 0.0), x),
            (DVec3::new(5.0, 2.0, 1.0), y),
            (DVec3::new(-3.0, 2.0, -1.0), y),
            (DVec3::new(1.0, 4.0, 2.0), x),
        ];
        for (length, half) in [(None, 2.0), (Some(1.0), 0.5)] {
            let r = butterfly_lines(&c, 0.0, 0, length).unwrap();
            assert_eq!((r.rows(), r.cols()), (2, 2));
            assert_lines(&r, |i, j| {
                let (m, d) = centres[2 * i + j];
                (m - half * d, m + half * d)
            });
        }
    }

    /// The size is checked before any work: a 2 × 2 grid has 1025² lines after ten steps (under
    /// the limit of 2²², so the next check, of w, speaks) and 2049² after eleven (over it); a 3 × 3
    /// grid is over it after ten.
    #[test]
    fn the_line_limit_is_checked_first_and_exactly() {
        let c = congruence(2, 2, |i, j| (DVec3::new(i as f64, j as f64, 0.0), DVec3::new(i as f64, j as f64, 1.0)));
        assert!(matches!(
            butterfly_lines(&c, 0.0, 11, None),
            Err(Error::TooMany { got, max: MAX_RULINGS, .. }) if got == 2049 * 2049
        ));
        assert!(matches!(butterfly_lines(&c, 0.5, 10, None), Err(Error::InvalidParameter { name: "w", .. })));
        assert!(matches!(butterfly_lines(&c, 0.5, 11, None), Err(Error::TooMany { .. })), "the size before w");
        let c = congruence(3, 3, |i, j| (DVec3::new(i as f64, j as f64, 0.0), DVec3::new(i as f64, j as f64, 1.0)));
        assert!(matches!(
            butterfly_lines(&c, 0.0, 10, None),
            Err(Error::TooMany { got, .. }) if got == 2049 * 2049
        ));
        // 3 × 2: 2049 × 1025 after ten steps, under the limit; 4097 × 2049 after eleven
        let c = congruence(3, 2, |i, j| (DVec3::new(i as f64, j as f64, 0.0), DVec3::new(i as f64, j as f64, 1.0)));
        assert!(matches!(
            butterfly_lines(&c, 0.0, 11, None),
            Err(Error::TooMany { got, .. }) if got == 4097 * 2049
        ));
    }

    /// w is a finite number in [−1/4, 1/4], both ends included.
    #[test]
    fn w_is_checked_at_both_ends() {
        let c = congruence(2, 2, |i, j| (DVec3::new(i as f64, j as f64, 0.0), DVec3::new(i as f64, j as f64, 1.0)));
        for w in [-0.25, 0.25] {
            assert_eq!(butterfly_lines(&c, w, 1, None).unwrap().rows(), 3);
        }
        for w in [-0.25 - 1e-15, 0.25 + 1e-15, f64::NAN, f64::INFINITY] {
            assert!(matches!(butterfly_lines(&c, w, 1, None), Err(Error::InvalidParameter { name: "w", .. })), "{w}");
        }
    }
}
