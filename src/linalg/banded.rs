//! Symmetric positive definite banded systems: Cholesky factorisation A = L Lᵀ in
//! O(n p²) time and O(n p) memory for half-bandwidth p, with several right-hand sides
//! (one per coordinate). The variational subdivision schemes (Sections 4 and 5) lead to
//! such systems.

use crate::error::{Error, Result};

/// A symmetric n × n matrix with `A[i][j] = 0` for |i − j| > p, lower band stored by rows.
#[derive(Debug, Clone, PartialEq)]
pub struct SymmetricBanded {
    n: usize,
    p: usize,
    /// Row i holds A[i][i − p ..= i] (entries before column 0 unused).
    band: Vec<f64>,
}

impl SymmetricBanded {
    /// The zero matrix of size `n` with half-bandwidth `p`.
    pub fn zeros(n: usize, p: usize) -> Self {
        SymmetricBanded { n, p, band: vec![0.0; n * (p + 1)] }
    }

    fn at(&self, i: usize, j: usize) -> usize {
        debug_assert!(j <= i && i - j <= self.p, "({i}, {j}) outside the band {}", self.p);
        i * (self.p + 1) + self.p - (i - j)
    }

    /// `A[i][j] += v` (and `A[j][i]`, by symmetry). Panics outside the band (a bug in assembly).
    pub fn add(&mut self, i: usize, j: usize, v: f64) {
        let (i, j) = if i >= j { (i, j) } else { (j, i) };
        assert!(i - j <= self.p, "entry ({i}, {j}) outside half-bandwidth {}", self.p);
        let k = self.at(i, j);
        self.band[k] += v;
    }

    /// `A[i][j]` (0 outside the band).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        let (i, j) = if i >= j { (i, j) } else { (j, i) };
        if i - j > self.p {
            return 0.0;
        }
        self.band[self.at(i, j)]
    }

    /// Factors in place into L (Cholesky). Fails if the matrix is not positive definite.
    pub fn factor(mut self) -> Result<CholeskyBanded> {
        let (n, p) = (self.n, self.p);
        for i in 0..n {
            let j0 = i.saturating_sub(p);
            for j in j0..=i {
                let mut s = self.band[self.at(i, j)];
                for k in i.saturating_sub(p).max(j.saturating_sub(p))..j {
                    s -= self.band[self.at(i, k)] * self.band[self.at(j, k)];
                }
                let ij = self.at(i, j);
                if i == j {
                    if s.is_nan() || s <= 0.0 {
                        return Err(Error::Singular { what: "system", pivot: i, value: s });
                    }
                    self.band[ij] = s.sqrt();
                } else {
                    self.band[ij] = s / self.band[self.at(j, j)];
                }
            }
        }
        Ok(CholeskyBanded { l: self })
    }
}

/// The factor L of [`SymmetricBanded::factor`].
#[derive(Debug, Clone, PartialEq)]
pub struct CholeskyBanded {
    l: SymmetricBanded,
}

impl CholeskyBanded {
    /// Solves A x = b in place for `D` right-hand sides stored as `b[i] = [b_i^1 … b_i^D]`.
    pub fn solve<const D: usize>(&self, b: &mut [[f64; D]]) {
        let l = &self.l;
        let (n, p) = (l.n, l.p);
        assert_eq!(b.len(), n);
        for i in 0..n {
            for k in i.saturating_sub(p)..i {
                let lik = l.band[l.at(i, k)];
                for d in 0..D {
                    b[i][d] -= lik * b[k][d];
                }
            }
            let lii = l.band[l.at(i, i)];
            for v in b[i].iter_mut() {
                *v /= lii;
            }
        }
        for i in (0..n).rev() {
            for k in i + 1..(i + p + 1).min(n) {
                let lki = l.band[l.at(k, i)];
                for d in 0..D {
                    b[i][d] -= lki * b[k][d];
                }
            }
            let lii = l.band[l.at(i, i)];
            for v in b[i].iter_mut() {
                *v /= lii;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    /// A random SPD banded matrix: B Bᵀ for banded B, plus a little diagonal.
    fn random(n: usize, p: usize, seed: u64) -> (SymmetricBanded, DMatrix<f64>) {
        let mut s = seed;
        let mut rnd = || crate::tolerance::test::uniform(&mut s) - 0.5;
        let half = p / 2;
        let b = DMatrix::from_fn(n, n, |i, j| if i >= j && i - j <= half { rnd() } else { 0.0 });
        let a = &b * b.transpose() + DMatrix::identity(n, n) * 0.1;
        let mut m = SymmetricBanded::zeros(n, p);
        for i in 0..n {
            for j in 0..=i {
                if i - j <= p {
                    m.add(i, j, a[(i, j)]);
                } else {
                    assert_eq!(a[(i, j)], 0.0);
                }
            }
        }
        (m, a)
    }

    #[test]
    fn agrees_with_a_dense_solve() {
        for (n, p) in [(1, 0), (5, 1), (17, 3), (40, 4)] {
            let (m, a) = random(n, p, n as u64);
            let rhs: Vec<[f64; 3]> = (0..n).map(|i| [i as f64, 1.0, (i * i) as f64 * 0.1]).collect();
            let mut x = rhs.clone();
            m.factor().unwrap().solve(&mut x);
            let dense = a.clone().cholesky().unwrap();
            for d in 0..3 {
                let b = DVector::from_iterator(n, rhs.iter().map(|r| r[d]));
                let expected = dense.solve(&b);
                for i in 0..n {
                    assert!((x[i][d] - expected[i]).abs() <= 1e-10 * (1.0 + expected[i].abs()));
                }
            }
        }
    }

    #[test]
    fn rejects_an_indefinite_matrix() {
        let mut m = SymmetricBanded::zeros(2, 1);
        m.add(0, 0, 1.0);
        m.add(1, 0, 2.0);
        m.add(1, 1, 1.0);
        assert!(m.factor().unwrap_err().to_string().contains("not positive definite"));
    }
}
