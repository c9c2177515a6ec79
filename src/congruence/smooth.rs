//! Smooth line congruences p(u, v) + t·d(u, v), known by their jets (Section 5): the exact
//! lines a discrete congruence is measured against and sampled from. The catalogue's analytic
//! congruences and congruences typed as formulas implement [`SmoothCongruence`]; the exact
//! focal geometry (`focal_analytic`) takes any implementation.

use crate::base::CongruenceJet;
use crate::congruence::grid::check_grid_shape;
use crate::congruence::LineCongruence;
use crate::error::Result;
use glam::DVec3;

/// A smooth line congruence over a parameter rectangle, known by its jets.
pub trait SmoothCongruence {
    /// Machine name.
    fn name(&self) -> &str;

    /// p, d and their partial derivatives at (u, v), exactly.
    fn jet(&self, u: f64, v: f64) -> CongruenceJet;

    /// [`SmoothCongruence::jet`], refused where it is not finite or d = 0 (formulas say where).
    fn checked_jet(&self, u: f64, v: f64) -> Result<CongruenceJet> {
        Ok(self.jet(u, v))
    }

    /// The parameter rectangle ((u₀, u₁), (v₀, v₁)) and the grid size of its figure.
    fn domain(&self) -> ((f64, f64), (f64, f64), usize, usize);

    /// p(u, v) on d₁ and the line direction d(u, v).
    fn line(&self, u: f64, v: f64) -> (DVec3, DVec3) {
        let j = self.jet(u, v);
        (j.p, j.d)
    }

    /// The (u, v) of line (i, j) of a rows × cols grid over the domain.
    fn parameters(&self, i: usize, j: usize, rows: usize, cols: usize) -> (f64, f64) {
        let ((u0, u1), (v0, v1), _, _) = self.domain();
        (u0 + (u1 - u0) * i as f64 / (rows - 1) as f64, v0 + (v1 - v0) * j as f64 / (cols - 1) as f64)
    }

    /// The rows × cols grid of lines p → p + d at equally spaced (u_i, v_j) of the domain.
    fn grid(&self, rows: usize, cols: usize) -> Result<LineCongruence> {
        self.grid_reaching(rows, cols, 1.0)
    }

    /// As [`SmoothCongruence::grid`], the segments p → p + reach·d.
    fn grid_reaching(&self, rows: usize, cols: usize, reach: f64) -> Result<LineCongruence> {
        check_grid_shape(rows, cols)?;
        let mut p = Vec::with_capacity(rows * cols);
        let mut q = Vec::with_capacity(rows * cols);
        for k in 0..rows * cols {
            let (u, v) = self.parameters(k / cols, k % cols, rows, cols);
            let j = self.checked_jet(u, v)?;
            p.push(j.p);
            q.push(j.p + reach * j.d);
        }
        LineCongruence::from_points(rows, cols, &p, &q)
    }

    /// Errors of a refined grid (from [`SmoothCongruence::grid`]) against the exact lines at
    /// the same parameters, over its new lines: (largest distance |P − p|, largest angle
    /// between P → Q and d, in radians).
    fn errors(&self, refined: &LineCongruence) -> (f64, f64) {
        let (rows, cols) = (refined.rows(), refined.cols());
        let mut worst = (0.0f64, 0.0f64);
        for i in 0..rows {
            for j in 0..cols {
                if i % 2 == 0 && j % 2 == 0 {
                    continue;
                }
                let (u, v) = self.parameters(i, j, rows, cols);
                let (p, d) = self.line(u, v);
                let s = refined.line(i, j);
                worst.0 = worst.0.max((s.a - p).length());
                worst.1 = worst.1.max(s.vector().angle_between(d));
            }
        }
        worst
    }

    /// Errors of the paper's diagonal insertion (Fig. 13, [`crate::congruence::butterfly_diagonal`]:
    /// (rows − 1) × (cols − 1) lines from a rows × cols grid of [`SmoothCongruence::grid`])
    /// against the exact lines at the centres of the grid's cells, (u_{i+½}, v_{j+½}): (largest
    /// distance |P − p|, largest angle between P → Q and d, in radians). These are the lines the
    /// butterfly step on all edges inserts at its odd-odd places, so its errors over those lines.
    fn diagonal_errors(&self, diagonal: &LineCongruence) -> (f64, f64) {
        let (rows, cols) = (2 * diagonal.rows() + 1, 2 * diagonal.cols() + 1);
        let mut worst = (0.0f64, 0.0f64);
        for i in 0..diagonal.rows() {
            for j in 0..diagonal.cols() {
                let (u, v) = self.parameters(2 * i + 1, 2 * j + 1, rows, cols);
                let (p, d) = self.line(u, v);
                let s = diagonal.line(i, j);
                worst.0 = worst.0.max((s.a - p).length());
                worst.1 = worst.1.max(s.vector().angle_between(d));
            }
        }
        worst
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// p(u, v) = (u, v, 0), d(u, v) = (v, −u, 1) over [1, 3] × [−2, 4].
    struct Toy;

    impl SmoothCongruence for Toy {
        fn name(&self) -> &str {
            "toy"
        }
        fn jet(&self, u: f64, v: f64) -> CongruenceJet {
            CongruenceJet {
                p: DVec3::new(u, v, 0.0),
                p_u: DVec3::X,
                p_v: DVec3::Y,
                d: DVec3::new(v, -u, 1.0),
                d_u: DVec3::new(0.0, -1.0, 0.0),
                d_v: DVec3::X,
            }
        }
        fn domain(&self) -> ((f64, f64), (f64, f64), usize, usize) {
            ((1.0, 3.0), (-2.0, 4.0), 5, 5)
        }
    }

    /// The line at (u, v) with its start moved by `shift` across it and its direction turned
    /// by `angle` towards (1, 0, −v)/|…| (perpendicular to d = (v, −u, 1)).
    fn moved(u: f64, v: f64, shift: f64, angle: f64) -> (DVec3, DVec3) {
        let d = DVec3::new(v, -u, 1.0);
        let across = DVec3::new(1.0, 0.0, -v).normalize();
        let p = DVec3::new(u, v, 0.0) + shift * across;
        (p, p + angle.cos() * d + angle.sin() * d.length() * across)
    }

    fn congruence(rows: usize, cols: usize, line: impl Fn(usize, usize) -> (DVec3, DVec3)) -> LineCongruence {
        let (p, q): (Vec<DVec3>, Vec<DVec3>) = (0..rows * cols).map(|k| line(k / cols, k % cols)).unzip();
        LineCongruence::from_points(rows, cols, &p, &q).unwrap()
    }

    #[test]
    fn grid_parameters_span_the_domain_row_by_row() {
        // 5 rows over u ∈ [1, 3] (step 1/2), 4 columns over v ∈ [−2, 4] (step 2)
        assert_eq!(Toy.parameters(0, 0, 5, 4), (1.0, -2.0));
        assert_eq!(Toy.parameters(1, 2, 5, 4), (1.5, 2.0));
        assert_eq!(Toy.parameters(4, 3, 5, 4), (3.0, 4.0));
        let g = Toy.grid_reaching(5, 4, 2.0).unwrap();
        assert_eq!((g.rows(), g.cols()), (5, 4));
        let s = g.line(1, 2);
        assert_eq!((s.a, s.b), (DVec3::new(1.5, 2.0, 0.0), DVec3::new(1.5 + 4.0, 2.0 - 3.0, 2.0)));
        let s = Toy.grid(5, 4).unwrap().line(4, 1);
        assert_eq!((s.a, s.b), (DVec3::new(3.0, 0.0, 0.0), DVec3::new(3.0, -3.0, 1.0)));
    }

    /// Only the new lines of a refined grid count: (0, 0) and (2, 2) are moved far and do not;
    /// the largest shift, 0.25, is at (0, 1) (one odd index), the largest turn, 0.3, at (1, 0).
    #[test]
    fn errors_take_the_worst_new_line() {
        let r = congruence(3, 3, |i, j| {
            let (u, v) = Toy.parameters(i, j, 3, 3);
            let (shift, angle) = match (i, j) {
                (0, 0) | (2, 2) => (10.0, 1.0),
                (0, 1) => (0.25, 0.0),
                (1, 0) => (0.0, 0.3),
                (1, 1) => (0.1, 0.1),
                _ => (0.0, 0.0),
            };
            moved(u, v, shift, angle)
        });
        let (distance, angle) = Toy.errors(&r);
        assert!((distance - 0.25).abs() < 1e-14 && (angle - 0.3).abs() < 1e-12, "{distance} {angle}");
    }

    /// A 2 × 3 diagonal grid stands at the cell centres of a 5 × 7 grid: (u, v) of (2i + 1, 2j + 1).
    #[test]
    fn diagonal_errors_measure_at_the_cell_centres() {
        let d = congruence(2, 3, |i, j| {
            let (u, v) = Toy.parameters(2 * i + 1, 2 * j + 1, 5, 7);
            let (shift, angle) = match (i, j) {
                (1, 2) => (0.5, 0.0),
                (0, 1) => (0.0, 0.2),
                _ => (0.0, 0.0),
            };
            moved(u, v, shift, angle)
        });
        let (distance, angle) = Toy.diagonal_errors(&d);
        assert!((distance - 0.5).abs() < 1e-14 && (angle - 0.2).abs() < 1e-12, "{distance} {angle}");
    }
}
