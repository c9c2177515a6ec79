//! The butterfly scheme for line congruences (Section 5.1, Figs. 12–13).
//!
//! The points p_{i,j} on the director surface d₁ are triangulated by the diagonals
//! p_{i,j} p_{i+1,j+1} (Fig. 12). On a diagonal edge the new point is
//!
//! p̄_{i,j} = ½(p_{i,j} + p_{i+1,j+1}) + 2w(p_{i+1,j} + p_{i,j+1})
//!           − w(p_{i,j−1} + p_{i−1,j} + p_{i+1,j+2} + p_{i+2,j+1})              (16)
//!
//! and on the other two edge directions of the same triangulation the regular butterfly
//! stencils (the triangles on both sides of the edge give the 2w points, their neighbours
//! across the other edges the −w points):
//!
//! u-edge p_{i,j} p_{i+1,j}: ½(p_{i,j} + p_{i+1,j}) + 2w(p_{i+1,j+1} + p_{i,j−1})
//!                            − w(p_{i,j+1} + p_{i+2,j+1} + p_{i−1,j−1} + p_{i+1,j−1}),
//! v-edge p_{i,j} p_{i,j+1}: ½(p_{i,j} + p_{i,j+1}) + 2w(p_{i+1,j+1} + p_{i−1,j})
//!                            − w(p_{i+1,j} + p_{i+1,j+2} + p_{i−1,j−1} + p_{i−1,j+1}).
//!
//! The same is done for the points q_{i,j} on d₂, so one step maps a rows × cols grid of
//! lines to (2 rows − 1) × (2 cols − 1), old lines at even indices, unchanged. w = 1/16
//! reproduces cubic polynomials.
//!
//! **Boundary rule.** Stencil points outside the grid are ghost points, extrapolated along
//! the grid line by the cubic through the four nearest points (quadratic or linear on
//! shorter lines), as the four-point scheme's end rule; corner ghosts extrapolate ghosts.
//! So cubic data are reproduced up to the boundary.

use crate::subdivision::four_point::ghost;
use crate::subdivision::Affine;
#[cfg(test)]
use glam::DVec3;

/// The grid with a ring of ghost points: (rows + 2) × (cols + 2), p_{i,j} at (i + 1, j + 1).
/// Generic over what is refined: points, or the pairs (p, q) of a congruence's lines, so both
/// director grids are refined in one pass.
struct Extended<T> {
    cols: usize,
    data: Vec<T>,
}

impl<T: Affine> Extended<T> {
    fn new(p: &[T], rows: usize, cols: usize) -> Self {
        let (er, ec) = (rows + 2, cols + 2);
        let mut data = vec![p[0]; er * ec];
        for i in 0..rows {
            data[(i + 1) * ec + 1..(i + 1) * ec + 1 + cols].copy_from_slice(&p[i * cols..(i + 1) * cols]);
        }
        let take = |f: &dyn Fn(usize) -> T, n: usize| (0..n.min(4)).map(f).collect::<Vec<_>>();
        for j in 1..=cols {
            data[j] = ghost(&take(&|k| data[(k + 1) * ec + j], rows));
            data[(rows + 1) * ec + j] = ghost(&take(&|k| data[(rows - k) * ec + j], rows));
        }
        for i in 0..er {
            data[i * ec] = ghost(&take(&|k| data[i * ec + k + 1], cols));
            data[i * ec + cols + 1] = ghost(&take(&|k| data[i * ec + cols - k], cols));
        }
        Extended { cols: ec, data }
    }

    /// p_{i,j} for −1 ≤ i ≤ rows, −1 ≤ j ≤ cols.
    fn at(&self, i: isize, j: isize) -> T {
        self.data[(i + 1) as usize * self.cols + (j + 1) as usize]
    }
}

/// Rule (16) on the diagonal edge (i, j)–(i + 1, j + 1).
fn diagonal<T: Affine>(e: &Extended<T>, i: isize, j: isize, w: f64) -> T {
    (e.at(i, j) + e.at(i + 1, j + 1)) * 0.5 + (e.at(i + 1, j) + e.at(i, j + 1)) * (2.0 * w)
        - (e.at(i, j - 1) + e.at(i - 1, j) + e.at(i + 1, j + 2) + e.at(i + 2, j + 1)) * w
}

fn u_edge<T: Affine>(e: &Extended<T>, i: isize, j: isize, w: f64) -> T {
    (e.at(i, j) + e.at(i + 1, j)) * 0.5 + (e.at(i + 1, j + 1) + e.at(i, j - 1)) * (2.0 * w)
        - (e.at(i, j + 1) + e.at(i + 2, j + 1) + e.at(i - 1, j - 1) + e.at(i + 1, j - 1)) * w
}

fn v_edge<T: Affine>(e: &Extended<T>, i: isize, j: isize, w: f64) -> T {
    (e.at(i, j) + e.at(i, j + 1)) * 0.5 + (e.at(i + 1, j + 1) + e.at(i - 1, j)) * (2.0 * w)
        - (e.at(i + 1, j) + e.at(i + 1, j + 2) + e.at(i - 1, j - 1) + e.at(i - 1, j + 1)) * w
}

/// One butterfly step on a rows × cols point grid: (2 rows − 1) × (2 cols − 1) points.
pub fn refine_points<T: Affine>(p: &[T], rows: usize, cols: usize, w: f64) -> Vec<T> {
    let e = Extended::new(p, rows, cols);
    let (rr, cc) = (2 * rows - 1, 2 * cols - 1);
    let mut out = vec![p[0]; rr * cc];
    for i in 0..rows {
        for j in 0..cols {
            let (ii, jj) = (i as isize, j as isize);
            out[2 * i * cc + 2 * j] = p[i * cols + j];
            if i + 1 < rows {
                out[(2 * i + 1) * cc + 2 * j] = u_edge(&e, ii, jj, w);
            }
            if j + 1 < cols {
                out[2 * i * cc + 2 * j + 1] = v_edge(&e, ii, jj, w);
            }
            if i + 1 < rows && j + 1 < cols {
                out[(2 * i + 1) * cc + 2 * j + 1] = diagonal(&e, ii, jj, w);
            }
        }
    }
    out
}

/// The paper's insertion of Fig. 13: only the diagonal points (16), (rows − 1) × (cols − 1).
pub fn diagonal_points<T: Affine>(p: &[T], rows: usize, cols: usize, w: f64) -> Vec<T> {
    let e = Extended::new(p, rows, cols);
    (0..rows - 1)
        .flat_map(|i| (0..cols - 1).map(move |j| (i, j)))
        .map(|(i, j)| diagonal(&e, i as isize, j as isize, w))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cubic(u: f64, v: f64) -> DVec3 {
        DVec3::new(u + 0.1 * u * v * v, v - 0.2 * u * u * u, 0.3 * u * u * v + 0.05 * v * v * v - u * v + 1.0)
    }

    fn grid(rows: usize, cols: usize, f: impl Fn(f64, f64) -> DVec3) -> Vec<DVec3> {
        (0..rows * cols).map(|k| f((k / cols) as f64, (k % cols) as f64)).collect()
    }

    /// w = 1/16 reproduces bivariate cubics, boundary included (cubic ghost points).
    #[test]
    fn reproduces_cubics() {
        let (rows, cols) = (6, 5);
        let out = refine_points(&grid(rows, cols, cubic), rows, cols, 1.0 / 16.0);
        let cc = 2 * cols - 1;
        for (k, x) in out.iter().enumerate() {
            let (u, v) = ((k / cc) as f64 / 2.0, (k % cc) as f64 / 2.0);
            assert!((*x - cubic(u, v)).length() < 1e-12, "({u}, {v}): {x} vs {}", cubic(u, v));
        }
    }

    /// Rule (16) verbatim on random data in the interior.
    #[test]
    fn rule_sixteen_in_the_interior() {
        let p = grid(6, 6, |u, v| DVec3::new((u * 1.7 + v).sin(), (v * 2.3 - u).cos(), (u * v).sin()));
        let w = 0.07;
        let out = refine_points(&p, 6, 6, w);
        let at = |i: usize, j: usize| p[i * 6 + j];
        for (i, j) in [(1, 1), (2, 3), (3, 2)] {
            let expected = 0.5 * (at(i, j) + at(i + 1, j + 1)) + 2.0 * w * (at(i + 1, j) + at(i, j + 1))
                - w * (at(i, j - 1) + at(i - 1, j) + at(i + 1, j + 2) + at(i + 2, j + 1));
            assert!((out[(2 * i + 1) * 11 + 2 * j + 1] - expected).length() < 1e-15);
            assert!((diagonal_points(&p, 6, 6, w)[i * 5 + j] - expected).length() < 1e-15);
        }
    }

    /// On an affine grid every rule gives the edge midpoint, for any w.
    #[test]
    fn affine_grids_stay_affine() {
        let p = grid(4, 5, |u, v| DVec3::new(2.0 * u + v, v - u, 0.5 * u));
        let out = refine_points(&p, 4, 5, 0.1);
        for (k, x) in out.iter().enumerate() {
            let (u, v) = ((k / 9) as f64 / 2.0, (k % 9) as f64 / 2.0);
            assert!((*x - DVec3::new(2.0 * u + v, v - u, 0.5 * u)).length() < 1e-13);
        }
    }
}
