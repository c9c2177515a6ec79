//! Subdivision in the space of lines, independent of the chosen endpoints (beyond the paper).
//!
//! Every scheme of Section 4 acts on two points per line; slide an endpoint along its line and
//! the refined surface changes although the lines did not. Here an oriented line with unit
//! direction e through p is the dual unit vector L = e + ε m, m = p × e (normalised Plücker
//! coordinates). A linear scheme is applied to the real and the dual parts with the same
//! weights, and each new dual vector a + ε a₀ is projected back onto the dual unit sphere,
//!
//! N(a + ε a₀) = a/|a| + ε (a₀/|a| − a (a·a₀)/|a|³),
//!
//! the line with direction a/|a| and moment orthogonal to it. Rigid motions act on dual vectors
//! by dual orthogonal maps, which commute with the linear step and with N: the scheme commutes
//! with rigid motions, and its result depends on the input lines only. Segments are recovered
//! by cutting the refined lines symmetric to their striction points (Section 4's re-cut).
//!
//! **Orientation.** A line has two dual unit vectors ±L; before refining, each line's sign is
//! chosen so that its direction makes an acute angle with its predecessor's (along rows, then
//! down the first column, for a congruence).

use crate::error::{Error, Result};
use crate::line::{Line, Segment};
use crate::ruled::RuledSurface;
use crate::subdivision::{check_steps, polygon_step, recut, Pair, Scheme};
use glam::DVec3;

/// An oriented line as a dual unit vector e + ε m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DualLine {
    /// Unit direction e.
    pub real: DVec3,
    /// Moment m = p × e.
    pub dual: DVec3,
}

impl DualLine {
    /// The dual vector of `line`.
    pub fn of(line: &Line) -> Self {
        DualLine { real: line.dir, dual: line.point.cross(line.dir) }
    }

    /// N(a + ε a₀); an error when the real part vanishes (a combination of opposite lines).
    pub fn normalized(real: DVec3, dual: DVec3) -> Result<Self> {
        let n = real.length();
        if n.is_nan() || n <= 1e-9 {
            return Err(Error::degenerate("lines", crate::msg!("lines-cancel")));
        }
        Ok(DualLine { real: real / n, dual: dual / n - real * (real.dot(dual) / (n * n * n)) })
    }

    /// Back to a line: direction e, point e × m (the foot of the perpendicular from the origin).
    pub fn line(&self) -> Line {
        Line { point: self.real.cross(self.dual), dir: self.real }
    }
}

/// Dual vectors of the rulings, signs made consistent along the sequence.
pub(crate) fn oriented(lines: impl Iterator<Item = Line>) -> Vec<DualLine> {
    let mut out: Vec<DualLine> = Vec::new();
    for l in lines {
        let mut d = DualLine::of(&l);
        if let Some(prev) = out.last() {
            if prev.real.dot(d.real) < 0.0 {
                d = DualLine { real: -d.real, dual: -d.dual };
            }
        }
        out.push(d);
    }
    out
}

pub(crate) fn split(d: &[DualLine]) -> (Vec<DVec3>, Vec<DVec3>) {
    d.iter().map(|l| (l.real, l.dual)).unzip()
}

pub(crate) fn join(real: Vec<DVec3>, dual: Vec<DVec3>) -> Result<Vec<DualLine>> {
    real.into_iter().zip(dual).map(|(r, d)| DualLine::normalized(r, d)).collect()
}

fn pairs(d: &[DualLine]) -> Vec<Pair> {
    d.iter().map(|l| Pair(l.real, l.dual)).collect()
}

/// `steps` steps of a linear curve scheme (Chaikin, B-spline, four-point) on the lines of
/// `surface`; the refined lines are cut to segments of `length` (default: the mean input
/// length) centred on their striction points.
pub fn subdivide_lines(
    surface: &RuledSurface,
    scheme: Scheme,
    closed: bool,
    steps: usize,
    length: Option<f64>,
) -> Result<RuledSurface> {
    scheme.validate()?;
    check_steps(steps)?;
    if matches!(scheme, Scheme::Bezier | Scheme::Variational { .. }) {
        return Err(Error::parameter("space", "line space supports \"chaikin\", \"bspline\" and \"four-point\""));
    }
    scheme.output_len_after(surface.len(), closed, steps)?;
    let length = length.unwrap_or_else(|| surface.segments().map(|s| s.length()).sum::<f64>() / surface.len() as f64);
    let mut lines = oriented(surface.lines());
    for _ in 0..steps {
        lines = polygon_step(&pairs(&lines), scheme, closed, 0)
            .into_iter()
            .map(|p| DualLine::normalized(p.0, p.1))
            .collect::<Result<_>>()?;
    }
    // unit segments along the refined lines, then the re-cut symmetric to the striction points
    let rough = RuledSurface::new(
        lines
            .iter()
            .map(|d| {
                let l = d.line();
                Segment::new(l.point, l.point + l.dir)
            })
            .collect(),
    )?;
    recut(&rough, Some(length))
}

#[cfg(test)]
mod tests {
    use super::*;
    #[allow(unused_imports)]
    use crate::congruence::SmoothCongruence;
    #[allow(unused_imports)]
    use crate::ruled::SmoothRuled;

    #[test]
    fn dual_round_trip_and_normalisation() {
        let l = Line { point: DVec3::new(1.0, 2.0, 3.0), dir: DVec3::new(0.0, 0.6, 0.8) };
        let d = DualLine::of(&l);
        let back = d.line();
        assert!((back.dir - l.dir).length() < 1e-15);
        assert!(back.distance_to(l.point) < 1e-14);
        // N(2L + ε·(something along e)) is L
        let n = DualLine::normalized(2.0 * d.real, 2.0 * d.dual + 0.7 * d.real).unwrap();
        assert!((n.real - d.real).length() < 1e-15 && (n.dual - d.dual).length() < 1e-15);
        assert!(DualLine::normalized(DVec3::ZERO, DVec3::X).is_err());
    }

    /// The midpoint of two lines in line space through the same point passes through it and
    /// bisects the angle.
    #[test]
    fn average_of_two_concurrent_lines_bisects_them() {
        let o = DVec3::new(1.0, -1.0, 2.0);
        let a = DualLine::of(&Line { point: o, dir: DVec3::X });
        let b = DualLine::of(&Line { point: o, dir: DVec3::Y });
        let m = DualLine::normalized(0.5 * (a.real + b.real), 0.5 * (a.dual + b.dual)).unwrap().line();
        assert!(m.distance_to(o) < 1e-15);
        assert!((m.dir - DVec3::new(1.0, 1.0, 0.0).normalize()).length() < 1e-15);
    }

    /// Rulings through (0, i, 0) turning about y, of lengths 1, 2, 3, 4, all pointing to +x:
    /// refined in line space, they are cut to the mean length 2.5 and keep pointing to +x.
    #[test]
    fn refined_lines_get_the_mean_length_and_keep_their_orientation() {
        let segments = (0..4)
            .map(|i| {
                let (a, t) = (DVec3::new(0.0, i as f64, 0.0), 0.3 * i as f64);
                Segment::new(a, a + (i + 1) as f64 * DVec3::new(t.cos(), 0.0, t.sin()))
            })
            .collect();
        let s = RuledSurface::new(segments).unwrap();
        for scheme in [Scheme::Chaikin, Scheme::FourPoint { w: 0.0625 }] {
            let r = subdivide_lines(&s, scheme, false, 2, None).unwrap();
            for seg in r.segments() {
                assert!((seg.length() - 2.5).abs() < 1e-12, "{scheme:?}: {}", seg.length());
                assert!(seg.line().dir.x > 0.5, "{scheme:?}: {}", seg.line().dir);
            }
            let r = subdivide_lines(&s, scheme, false, 1, Some(0.5)).unwrap();
            assert!(r.segments().all(|seg| (seg.length() - 0.5).abs() < 1e-13));
        }
    }

    /// A line perpendicular to its predecessor keeps the orientation it was given (neither sign
    /// makes an acute angle): lines along x, y, x give Chaikin's ¾ x + ¼ y first, not ¾ x − ¼ y.
    #[test]
    fn a_perpendicular_line_keeps_its_orientation() {
        let segments = [DVec3::X, DVec3::Y, DVec3::X]
            .iter()
            .enumerate()
            .map(|(i, &e)| Segment::new(DVec3::new(0.0, 0.0, i as f64), DVec3::new(0.0, 0.0, i as f64) + e))
            .collect();
        let s = RuledSurface::new(segments).unwrap();
        let r = subdivide_lines(&s, Scheme::Chaikin, false, 1, None).unwrap();
        let want = DVec3::new(3.0, 1.0, 0.0).normalize();
        assert!((r.segment(0).line().dir - want).length() < 1e-15, "{}", r.segment(0).line().dir);
    }
}
