//! The two triangulations of a refined strip (Section 4, Fig. 9): every segment divided into
//! n equal parts, z_{j,k} = ((n − k)/n) a_j + (k/n) b_j (9)–(10), and consecutive rulings
//! joined by the level segments z_{j,k} z_{j+1,k} and one diagonal per quad: z_{j,k} z_{j+1,k+1}
//! in the first triangulation, whose neighbours are (11), and z_{j,k+1} z_{j+1,k} in the
//! second, (12). The umbrella vectors (13)–(14) are taken over these edges.

use crate::ruled::RuledSurface;
use glam::DVec3;

/// Which triangulation of Fig. 9.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Triangulation {
    /// Diagonals z_{j,k} z_{j+1,k+1}: the neighbours (11) of the umbrella vector (13).
    First,
    /// Diagonals z_{j,k+1} z_{j+1,k}: the neighbours (12) of (14).
    Second,
}

/// z_{j,k} (9): the point k/n of the way from a_j to b_j.
pub fn division_point(strip: &RuledSurface, j: usize, k: usize, n: usize) -> DVec3 {
    let s = strip.segment(j);
    ((n - k) as f64 / n as f64) * s.a + (k as f64 / n as f64) * s.b
}

/// The edges between consecutive rulings of `strip` (the rulings themselves not included):
/// (n + 1) level segments and n diagonals per pair of rulings.
pub fn triangulation_edges(strip: &RuledSurface, n: usize, which: Triangulation) -> Vec<[DVec3; 2]> {
    let n = n.max(1);
    let mut out = Vec::with_capacity((strip.len() - 1) * (2 * n + 1));
    for j in 0..strip.len() - 1 {
        for k in 0..=n {
            out.push([division_point(strip, j, k, n), division_point(strip, j + 1, k, n)]);
            if k < n {
                out.push(match which {
                    Triangulation::First => [division_point(strip, j, k, n), division_point(strip, j + 1, k + 1, n)],
                    Triangulation::Second => [division_point(strip, j, k + 1, n), division_point(strip, j + 1, k, n)],
                });
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::tolerance::test::EXACT;

    /// On the unit square strip a = (j, 0, 0), b = (j, 1, 0) the first triangulation's
    /// diagonals rise to the right ("/"), the second's fall ("\"); the neighbours of a point
    /// of the middle ruling are exactly (11) and (12).
    #[test]
    fn the_two_triangulations_of_fig_9() {
        let strip =
            RuledSurface::from_flat(&[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 0., 2., 0., 0., 2., 1., 0.]).unwrap();
        let n = 4;
        let first = triangulation_edges(&strip, n, Triangulation::First);
        let second = triangulation_edges(&strip, n, Triangulation::Second);
        assert_eq!(first.len(), 2 * (2 * n + 1));
        let z = |j: usize, k: usize| DVec3::new(j as f64, k as f64 / n as f64, 0.0);
        let neighbours = |edges: &[[DVec3; 2]], p: DVec3| -> Vec<DVec3> {
            edges
                .iter()
                .filter_map(|[a, b]| {
                    if *a == p {
                        Some(*b)
                    } else if *b == p {
                        Some(*a)
                    } else {
                        None
                    }
                })
                .collect()
        };
        // Z_{i,k} = z(1, 2): across the rulings, (11) gives z_{i,k}, z_{i,k−1}, z_{i+1,k+1}, z_{i+1,k}
        let mut got = neighbours(&first, z(1, 2));
        got.sort_by(|a, b| a.to_array().partial_cmp(&b.to_array()).unwrap());
        assert_eq!(got, vec![z(0, 1), z(0, 2), z(2, 2), z(2, 3)]);
        let mut got = neighbours(&second, z(1, 2));
        got.sort_by(|a, b| a.to_array().partial_cmp(&b.to_array()).unwrap());
        assert_eq!(got, vec![z(0, 2), z(0, 3), z(2, 1), z(2, 2)]);
        assert_near!(division_point(&strip, 2, 3, 4), z(2, 3), EXACT);
    }
}
