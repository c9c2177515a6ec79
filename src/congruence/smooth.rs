//! Smooth line congruences p(u, v) + t·d(u, v), known by their jets (Section 5): the exact
//! lines a discrete congruence is measured against and sampled from. The catalogue's analytic
//! congruences and congruences typed as formulas implement [`SmoothCongruence`]; the exact
//! focal geometry (`focal_analytic`) takes any implementation.

use crate::base::CongruenceJet;
use crate::congruence::grid::check_shape;
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
        check_shape(rows, cols)?;
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
