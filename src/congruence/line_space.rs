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
