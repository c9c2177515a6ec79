//! A discrete line congruence (Section 5): a rows × cols grid of lines R_{i,j}, each a
//! segment p_{i,j} → q_{i,j} between two director surfaces d₁ ∋ p and d₂ ∋ q, stored row
//! by row. Every row and every column is a discrete ruled surface, so Section 2's
//! invariants apply to them.

use crate::base::check_coordinates;
use crate::error::{Error, Record, Result};
use crate::line::Segment;
use crate::ruled::RuledSurface;
use crate::tolerance::{MAX_RULINGS, ZERO_LENGTH_REL};
use glam::DVec3;

/// A validated grid of lines: rows, cols ≥ 2, finite, no zero-length segment.
#[derive(Debug, Clone, PartialEq)]
pub struct LineCongruence {
    rows: usize,
    cols: usize,
    /// p then q for each line, row-major.
    points: Vec<DVec3>,
}

impl LineCongruence {
    /// From flat coordinates, 6 numbers per line (p then q), row-major.
    pub fn from_flat(rows: usize, cols: usize, coords: &[f64]) -> Result<Self> {
        check_grid_shape(rows, cols)?;
        let expected = 6 * rows * cols;
        if coords.len() != expected {
            return Err(Error::parameter(
                "coords",
                format!("a {rows} × {cols} grid needs {expected} numbers (6 per line), got {}", coords.len()),
            ));
        }
        check_coordinates(coords, 6).map_err(|e| name_line(e, cols))?;
        Self::checked(rows, cols, coords.chunks_exact(3).map(DVec3::from_slice).collect())
    }

    /// From endpoints p_{i,j}, q_{i,j} (row-major), validated.
    pub fn from_points(rows: usize, cols: usize, p: &[DVec3], q: &[DVec3]) -> Result<Self> {
        check_grid_shape(rows, cols)?;
        let points: Vec<DVec3> = p.iter().zip(q).flat_map(|(&a, &b)| [a, b]).collect();
        if points.len() != 2 * rows * cols {
            return Err(Error::parameter("points", "need one p and one q per line"));
        }
        check_coordinates(bytemuck::cast_slice(&points), 6)?;
        Self::checked(rows, cols, points)
    }

    /// From endpoints p_{i,j}, q_{i,j} interleaved (p then q per line, row-major), validated;
    /// the vector becomes the congruence's storage without a copy.
    pub fn from_interleaved(rows: usize, cols: usize, points: Vec<DVec3>) -> Result<Self> {
        check_grid_shape(rows, cols)?;
        if points.len() != 2 * rows * cols {
            return Err(Error::parameter("points", "need one p and one q per line"));
        }
        check_coordinates(bytemuck::cast_slice(&points), 6)?;
        Self::checked(rows, cols, points)
    }

    /// p then q for each line, row-major (a view).
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    fn checked(rows: usize, cols: usize, points: Vec<DVec3>) -> Result<Self> {
        // |q − p| ≤ rel · max(|p|, |q|), compared squared: no square roots in this pass
        let rel2 = ZERO_LENGTH_REL * ZERO_LENGTH_REL;
        for (k, pq) in points.chunks_exact(2).enumerate() {
            if (pq[1] - pq[0]).length_squared() <= rel2 * pq[0].length_squared().max(pq[1].length_squared()) {
                return Err(Error::degenerate(
                    "coords",
                    crate::msg!("line-zero-length", row = k / cols, col = k % cols),
                ));
            }
        }
        Ok(LineCongruence { rows, cols, points })
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Line (i, j) as a segment p → q.
    pub fn line(&self, i: usize, j: usize) -> Segment {
        let k = 2 * (i * self.cols + j);
        Segment::new(self.points[k], self.points[k + 1])
    }

    /// The lines (i, j) with i or j not a multiple of `stride`: after k interpolatory steps
    /// (stride 2^k), the inserted lines, row-major.
    pub fn inserted(&self, stride: usize) -> Vec<Segment> {
        let stride = stride.max(1);
        (0..self.rows * self.cols)
            .filter(|k| (k / self.cols) % stride != 0 || (k % self.cols) % stride != 0)
            .map(|k| self.line(k / self.cols, k % self.cols))
            .collect()
    }

    /// The endpoints on d₁ (row-major).
    pub fn p(&self) -> Vec<DVec3> {
        self.points.iter().step_by(2).copied().collect()
    }

    /// The endpoints on d₂ (row-major).
    pub fn q(&self) -> Vec<DVec3> {
        self.points.iter().skip(1).step_by(2).copied().collect()
    }

    /// Flat coordinates, 6 per line (a view).
    pub fn flat(&self) -> &[f64] {
        bytemuck::cast_slice(&self.points)
    }

    /// Row i (lines (i, 0) … (i, cols − 1)) as a discrete ruled surface.
    pub fn row(&self, i: usize) -> Result<RuledSurface> {
        if i >= self.rows {
            return Err(Error::parameter("i", format!("row {i} does not exist (rows: {})", self.rows)));
        }
        RuledSurface::new((0..self.cols).map(|j| self.line(i, j)).collect())
    }

    /// Column j (lines (0, j) … (rows − 1, j)) as a discrete ruled surface.
    pub fn column(&self, j: usize) -> Result<RuledSurface> {
        if j >= self.cols {
            return Err(Error::parameter("j", format!("column {j} does not exist (cols: {})", self.cols)));
        }
        RuledSurface::new((0..self.rows).map(|i| self.line(i, j)).collect())
    }
}

/// A coordinate error restated in the congruence's terms: "line (i, j), q.x".
fn name_line(e: Error, cols: usize) -> Error {
    let record = Record::GridLine { cols };
    match e {
        Error::NonFinite { index, value, .. } => Error::NonFinite { index, value, record },
        Error::OutOfRange { index, value, max, .. } => Error::OutOfRange { index, value, max, record },
        other => other,
    }
}

/// Whether a grid shape is one a congruence may have: rows, cols ≥ 2 and rows · cols ≤
/// [`MAX_RULINGS`] (checked without overflow).
pub fn check_grid_shape(rows: usize, cols: usize) -> Result<()> {
    if rows < 2 || cols < 2 {
        return Err(Error::parameter(
            "rows, cols",
            format!("a congruence needs at least 2 × 2 lines, got {rows} × {cols}"),
        ));
    }
    match rows.checked_mul(cols) {
        Some(n) if n <= MAX_RULINGS => Ok(()),
        _ => Err(Error::TooMany { what: "lines (rows × cols)", got: rows.saturating_mul(cols), max: MAX_RULINGS }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(rows: usize, cols: usize) -> Vec<f64> {
        (0..rows * cols)
            .flat_map(|k| {
                let (i, j) = ((k / cols) as f64, (k % cols) as f64);
                [i, j, 0.0, i, j, 1.0]
            })
            .collect()
    }

    #[test]
    fn rows_and_columns_are_ruled_surfaces() {
        let c = LineCongruence::from_flat(3, 4, &grid(3, 4)).unwrap();
        assert_eq!(c.row(1).unwrap().len(), 4);
        assert_eq!(c.column(2).unwrap().segment(2), Segment::new(DVec3::new(2.0, 2.0, 0.0), DVec3::new(2.0, 2.0, 1.0)));
        assert!(c.row(3).is_err() && c.column(4).is_err());
    }

    #[test]
    fn rejects_bad_grids() {
        assert!(LineCongruence::from_flat(1, 4, &grid(1, 4)).is_err());
        assert!(LineCongruence::from_flat(3, 4, &grid(3, 3)).unwrap_err().to_string().contains("needs 72 numbers"));
        assert!(matches!(check_grid_shape(1 << 12, 1 << 12), Err(Error::TooMany { .. })));
        assert!(check_grid_shape(usize::MAX, 3).is_err());
        let mut g = grid(2, 2);
        g[5] = 0.0;
        assert!(LineCongruence::from_flat(2, 2, &g).unwrap_err().to_string().contains("line (0, 0) has zero length"));
        g[5] = f64::NAN;
        assert!(LineCongruence::from_flat(2, 2, &g).unwrap_err().to_string().contains("NaN"));
    }

    #[test]
    fn inserted_lines_are_those_off_the_coarse_grid_and_flat_is_the_input() {
        // the 3 × 5 grid of lines (i, j, 0) → (i, j, 1): with stride 2 the coarse lines are
        // (0, 0), (0, 2), (0, 4), (2, 0), (2, 2), (2, 4); the other nine were inserted
        let g = grid(3, 5);
        let c = LineCongruence::from_flat(3, 5, &g).unwrap();
        assert_eq!(c.flat(), &g[..]);
        let at = |s: &Segment| (s.a.x as usize, s.a.y as usize);
        let inserted: Vec<(usize, usize)> = c.inserted(2).iter().map(at).collect();
        assert_eq!(inserted, [(0, 1), (0, 3), (1, 0), (1, 1), (1, 2), (1, 3), (1, 4), (2, 1), (2, 3)]);
        assert!(c.inserted(1).is_empty() && c.inserted(0).is_empty());
        assert_eq!(c.inserted(4).len(), 15 - 2);
        // and with an even number of columns (3 × 4)
        let even = LineCongruence::from_flat(3, 4, &grid(3, 4)).unwrap();
        let inserted: Vec<(usize, usize)> = even.inserted(2).iter().map(at).collect();
        assert_eq!(inserted, [(0, 1), (0, 3), (1, 0), (1, 1), (1, 2), (1, 3), (2, 1), (2, 3)]);
    }

    #[test]
    fn a_line_is_of_zero_length_relative_to_its_endpoints_and_named_by_its_place() {
        // line (1, 2) of a 2 × 3 grid: endpoints near 1000 apart by 1e-10 (relative 1e-13) is
        // of zero length; near 1 apart by 1e-11 (relative 1e-11) it has a direction
        let mut g = grid(2, 3);
        g[30..36].copy_from_slice(&[1000.0, 0.0, 0.0, 1000.0, 1e-10, 0.0]);
        let e = LineCongruence::from_flat(2, 3, &g).unwrap_err();
        assert!(e.to_string().contains("line (1, 2) has zero length"), "{e}");
        g[30..36].copy_from_slice(&[1.0, 0.0, 0.0, 1.0, 1e-11, 0.0]);
        assert!(LineCongruence::from_flat(2, 3, &g).is_ok());
    }
}
