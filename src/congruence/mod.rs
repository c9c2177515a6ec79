//! Discrete line congruences and their refinement (Section 5).

pub mod butterfly;
pub mod focal;
pub mod grid;
pub mod line_space;
pub mod smooth;
pub mod variational;

pub use focal::{Focal, FocalKind};
pub use grid::LineCongruence;
pub use smooth::SmoothCongruence;

use crate::error::{Error, Result};
use crate::subdivision::Pair;
use crate::tolerance::MAX_RULINGS;

/// How to refine a congruence.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CongruenceScheme {
    /// Butterfly (16) on all three edge directions.
    Butterfly {
        /// Tension w.
        w: f64,
    },
    /// The two-stage variational scheme of Section 5.2 (K parts per line).
    TwoStage {
        /// K ≥ 3.
        k: usize,
    },
    /// The paper's two-stage scheme read literally: midpoint edge lines, face lines the
    /// average of their 8 neighbours (`congruence/variational.rs`).
    Paper {
        /// K ≥ 3; the result does not depend on it (the literal strip energy is the midpoint
        /// rule for every K, and the face lines are averages).
        k: usize,
    },
    /// The coupled variational scheme.
    Coupled {
        /// K ≥ 3, the layers of the energy (20)–(21); the minimiser does not depend on it.
        k: usize,
    },
}

/// `steps` refinement steps; each maps rows × cols to (2 rows − 1) × (2 cols − 1), old lines
/// kept. Sizes are checked before any work.
pub fn subdivide_congruence(c: &LineCongruence, scheme: CongruenceScheme, steps: usize) -> Result<LineCongruence> {
    match scheme {
        CongruenceScheme::Butterfly { w } if !(w.is_finite() && (-0.25..=0.25).contains(&w)) => {
            return Err(Error::parameter("w", format!("must be a number in [−1/4, 1/4], got {w}")))
        }
        CongruenceScheme::TwoStage { k } | CongruenceScheme::Paper { k } | CongruenceScheme::Coupled { k }
            if !(3..=1000).contains(&k) =>
        {
            return Err(Error::parameter("K", format!("must be an integer from 3 to 1000, got {k}")))
        }
        _ => {}
    }
    let (mut rows, mut cols) = (c.rows(), c.cols());
    for _ in 0..steps {
        (rows, cols) = (2 * rows - 1, 2 * cols - 1);
        if rows.saturating_mul(cols) > MAX_RULINGS {
            return Err(Error::TooMany {
                what: "lines after subdivision",
                got: rows.saturating_mul(cols),
                max: MAX_RULINGS,
            });
        }
    }
    let mut out = c.clone();
    for _ in 0..steps {
        out = match scheme {
            CongruenceScheme::Butterfly { w } => {
                // both director grids at once: the lines' (p, q) pairs, read in place and handed
                // to the new congruence without a copy
                let (r, cc) = (out.rows(), out.cols());
                let pairs: &[Pair] = bytemuck::cast_slice(out.points());
                let refined = butterfly::refine_points(pairs, r, cc, w);
                LineCongruence::from_interleaved(2 * r - 1, 2 * cc - 1, bytemuck::allocation::cast_vec(refined))?
            }
            CongruenceScheme::TwoStage { k } => variational::two_stage(&out, k, variational::EdgeScheme::Coupled)?,
            CongruenceScheme::Paper { k } => variational::two_stage(&out, k, variational::EdgeScheme::Literal)?,
            CongruenceScheme::Coupled { k } => variational::coupled_congruence(&out, k)?.0,
        };
    }
    Ok(out)
}

/// The paper's Fig. 13 insertion: only the lines (16) on the diagonals, a
/// (rows − 1) × (cols − 1) congruence of the inserted lines.
pub fn butterfly_diagonal(c: &LineCongruence, w: f64) -> Result<LineCongruence> {
    if !(w.is_finite() && (-0.25..=0.25).contains(&w)) {
        return Err(Error::parameter("w", format!("must be a number in [−1/4, 1/4], got {w}")));
    }
    let (r, cc) = (c.rows(), c.cols());
    let p = butterfly::diagonal_points(&c.p(), r, cc, w);
    let q = butterfly::diagonal_points(&c.q(), r, cc, w);
    LineCongruence::from_points(r - 1, cc - 1, &p, &q)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 3 × 3 grid of lines from (i, j, 0), their directions varying a little.
    fn grid() -> LineCongruence {
        let coords: Vec<f64> = (0..9)
            .flat_map(|k| {
                let (i, j) = ((k / 3) as f64, (k % 3) as f64);
                [i, j, 0.0, i + 0.1 * i * j, j + 0.05 * i, 1.0]
            })
            .collect();
        LineCongruence::from_flat(3, 3, &coords).unwrap()
    }

    #[test]
    fn parameters_are_refused_by_name_at_their_bounds() {
        let c = grid();
        let option = |scheme: CongruenceScheme| subdivide_congruence(&c, scheme, 1).unwrap_err().details().option;
        for w in [0.2500001, -0.2500001, f64::NAN] {
            assert_eq!(option(CongruenceScheme::Butterfly { w }).as_deref(), Some("w"), "{w}");
            assert_eq!(butterfly_diagonal(&c, w).unwrap_err().details().option.as_deref(), Some("w"));
        }
        for k in [2, 1001] {
            for scheme in
                [CongruenceScheme::TwoStage { k }, CongruenceScheme::Paper { k }, CongruenceScheme::Coupled { k }]
            {
                assert_eq!(option(scheme).as_deref(), Some("K"), "{scheme:?}");
            }
        }
        for w in [0.25, -0.25] {
            assert_eq!(subdivide_congruence(&c, CongruenceScheme::Butterfly { w }, 1).unwrap().rows(), 5);
            let d = butterfly_diagonal(&c, w).unwrap();
            assert_eq!((d.rows(), d.cols()), (2, 2));
        }
        for scheme in [CongruenceScheme::TwoStage { k: 3 }, CongruenceScheme::Coupled { k: 1000 }] {
            let s = subdivide_congruence(&c, scheme, 2).unwrap();
            assert_eq!((s.rows(), s.cols()), (9, 9));
        }
    }

    #[test]
    fn sizes_are_checked_before_any_work() {
        // 3 × 3 → 5 × 5 → … → (2¹¹ + 1)²: the eleventh step would make 2049² = 4 198 401 lines
        let e = subdivide_congruence(&grid(), CongruenceScheme::Butterfly { w: 0.0625 }, 11).unwrap_err();
        assert_eq!(e, Error::TooMany { what: "lines after subdivision", got: 2049 * 2049, max: MAX_RULINGS });
        assert_eq!(subdivide_congruence(&grid(), CongruenceScheme::Butterfly { w: 0.0625 }, 0).unwrap(), grid());
    }
}
