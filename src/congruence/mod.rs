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
pub fn subdivide(c: &LineCongruence, scheme: CongruenceScheme, steps: usize) -> Result<LineCongruence> {
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
            CongruenceScheme::Coupled { k } => variational::coupled(&out, k)?.0,
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
