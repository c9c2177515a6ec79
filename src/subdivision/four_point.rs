//! The interpolatory four-point scheme of Dyn, Levin and Gregory (Section 4, Fig. 8):
//!
//! p_{i+½} = (½ + w)(p_i + p_{i+1}) − w(p_{i−1} + p_{i+2})        (8)
//!
//! The old points are kept, so N points → 2N − 1 (open) or 2N (closed), old ones at even
//! indices. w = 1/16 reproduces cubic polynomials.
//!
//! **Smoothness.** The paper quotes 0 < w < ⅛, the sufficient condition for a C¹ limit of
//! Dyn, Levin and Gregory (1987); it is not where smoothness ends. Dyn, Gregory and Levin
//! (1991) prove C¹ for 0 < w < (√5 − 1)/8 ≈ 0.155, and it holds further still (two steps of
//! the scheme of divided differences contract below (√5 − 1)/8, more steps further: eight at
//! w = 0.18). For w = 0 the limit is the polygon itself. [`crate::subdivision::turning`]
//! measures the largest turning angle of the refined polygons step by step.
//!
//! **End rule for open polygons.** The first and last edges lack p_{−1} and p_{N}; they are
//! replaced by ghost points extrapolating the cubic through the four end points
//! (p_{−1} = 4p_0 − 6p_1 + 4p_2 − p_3; quadratic for N = 3, linear for N = 2). With
//! w = 1/16 the inserted point is then the cubic interpolant at the edge midpoint,
//! (5p_0 + 15p_1 − 5p_2 + p_3)/16, so cubic data are reproduced up to the ends; the
//! tangent at the ends follows the data instead of being flattened as a repeated end
//! point would do.

use crate::subdivision::Affine;
#[cfg(test)]
use glam::DVec3;

/// The ghost point before `p` (p[0] first), by polynomial extrapolation of up to 4 points.
pub(crate) fn ghost<T: Affine>(p: &[T]) -> T {
    match p.len() {
        0 | 1 => p[0],
        2 => p[0] * 2.0 - p[1],
        3 => p[0] * 3.0 - p[1] * 3.0 + p[2],
        _ => p[0] * 4.0 - p[1] * 6.0 + p[2] * 4.0 - p[3],
    }
}

/// One step of the four-point scheme with tension `w`.
pub fn four_point<T: Affine>(points: &[T], w: f64, closed: bool) -> Vec<T> {
    let n = points.len();
    let rule = |a: T, b: T, c: T, d: T| (b + c) * (0.5 + w) - (a + d) * w;
    let (before, after) = if closed {
        (points[n - 1], points[0])
    } else {
        let tail: Vec<T> = points.iter().rev().take(4).copied().collect();
        (ghost(points), ghost(&tail))
    };
    // p_{k}, with the ghost or wrapped points at k = −1 and k = n, n + 1
    let at = |k: isize| -> T {
        if k < 0 {
            before
        } else if (k as usize) < n {
            points[k as usize]
        } else if closed {
            points[k as usize - n]
        } else {
            after
        }
    };
    let edges = if closed { n } else { n - 1 };
    let mut out = Vec::with_capacity(2 * n);
    for i in 0..edges {
        out.push(points[i]);
        let inner = i >= 1 && i + 2 < n;
        out.push(if inner {
            rule(points[i - 1], points[i], points[i + 1], points[i + 2])
        } else {
            let k = i as isize;
            rule(at(k - 1), at(k), at(k + 1), at(k + 2))
        });
    }
    if !closed {
        out.push(points[n - 1]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ghost point continues the polynomial through the points: of degree 0, 1, 2, 3.
    #[test]
    fn ghosts_extrapolate_the_polynomial_through_the_points() {
        // x(k) = 1 + 2k + 3k² − k³ at k = 0, 1, 2, 3; the ghost is x(−1) for the cubic
        let x = |k: f64| DVec3::new(1.0 + 2.0 * k + 3.0 * k * k - k * k * k, k, 0.0);
        let p: Vec<DVec3> = (0..4).map(|k| x(k as f64)).collect();
        assert_eq!(ghost(&p), x(-1.0));
        assert_eq!(ghost(&p[..1]), p[0]);
        // the line through x(0) = (1, 0, 0) and x(1) = (5, 1, 0) at −1; the parabola k² at −1
        assert_eq!(ghost(&p[..2]), DVec3::new(-3.0, -1.0, 0.0));
        assert_eq!(ghost(&[DVec3::ZERO, DVec3::ONE, 4.0 * DVec3::ONE]), DVec3::ONE);
    }

    fn cubic(t: f64) -> DVec3 {
        DVec3::new(t, 0.5 * t * t - t, 0.1 * t * t * t - 0.3 * t * t + 2.0)
    }

    #[test]
    fn rule_eight_on_random_data() {
        let p: Vec<DVec3> =
            (0..7).map(|i| DVec3::new((i as f64).sin(), (i * i) as f64 * 0.1, (3.0 * i as f64).cos())).collect();
        let w = 1.0 / 13.0;
        let q = four_point(&p, w, false);
        assert_eq!(q.len(), 13);
        for i in 1..5 {
            assert_eq!(q[2 * i], p[i]);
            let expected = (0.5 + w) * (p[i] + p[i + 1]) - w * (p[i - 1] + p[i + 2]);
            assert!((q[2 * i + 1] - expected).length() < 1e-15);
        }
        let c = four_point(&p, w, true);
        assert_eq!(c.len(), 14);
        assert!((c[13] - ((0.5 + w) * (p[6] + p[0]) - w * (p[5] + p[1]))).length() < 1e-15);
    }

    /// w = 1/16 reproduces cubics everywhere, the ends included (cubic ghost points).
    #[test]
    fn reproduces_cubics_with_w_one_sixteenth() {
        let p: Vec<DVec3> = (0..6).map(|i| cubic(i as f64)).collect();
        let q = four_point(&p, 1.0 / 16.0, false);
        for (j, x) in q.iter().enumerate() {
            assert!((*x - cubic(j as f64 / 2.0)).length() < 1e-13, "point {j}");
        }
        // and the end formula is the cubic interpolant at the first midpoint
        let expected = (5.0 * p[0] + 15.0 * p[1] - 5.0 * p[2] + p[3]) / 16.0;
        assert!((q[1] - expected).length() < 1e-14);
    }
    /// The smoothness bounds quoted in the module documentation, by the test of Dyn, Gregory
    /// and Levin: the limit is C¹ when the scheme of divided differences, with symbol
    /// 2a(z)/(1 + z), converges, that is when its own difference scheme, c(z) = 2a(z)/(1 + z)²,
    /// contracts in some number L of steps: max over the residues r mod 2^L of the sums of
    /// |coefficients| of c(z)c(z²)…c(z^{2^{L−1}}) with index ≡ r is below 1.
    #[test]
    fn divided_differences_contract_beyond_one_eighth() {
        fn multiply(a: &[f64], b: &[f64]) -> Vec<f64> {
            let mut r = vec![0.0; a.len() + b.len() - 1];
            for (i, x) in a.iter().enumerate() {
                for (j, y) in b.iter().enumerate() {
                    r[i + j] += x * y;
                }
            }
            r
        }
        /// a(z)/(1 + z), exactly when a(−1) = 0.
        fn divide(a: &[f64]) -> Vec<f64> {
            let mut q = vec![0.0; a.len() - 1];
            let mut rest = a.to_vec();
            for i in (1..a.len()).rev() {
                q[i - 1] = rest[i];
                rest[i - 1] -= rest[i];
            }
            assert!(rest[0].abs() < 1e-15);
            q
        }
        let norm = |w: f64, steps: u32| -> f64 {
            // the mask of (8), z⁻³ … z³
            let a = [-w, 0.0, 0.5 + w, 1.0, 0.5 + w, 0.0, -w];
            let c: Vec<f64> = divide(&divide(&a)).iter().map(|x| 2.0 * x).collect();
            let mut product = vec![1.0];
            for l in 0..steps {
                let mut spread = vec![0.0; (c.len() - 1) * (1 << l) + 1];
                for (i, x) in c.iter().enumerate() {
                    spread[i << l] = *x;
                }
                product = multiply(&product, &spread);
            }
            let m = 1usize << steps;
            (0..m).map(|r| product.iter().skip(r).step_by(m).map(|x| x.abs()).sum::<f64>()).fold(0.0, f64::max)
        };
        let bound = (5f64.sqrt() - 1.0) / 8.0;
        assert!(norm(1.0 / 8.0, 2) < 1.0);
        assert!(norm(bound - 1e-4, 2) < 1.0 && norm(bound + 1e-4, 2) > 1.0);
        assert!(norm(0.18, 7) > 1.0 && norm(0.18, 8) < 0.98);
    }
}
