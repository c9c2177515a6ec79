//! The tolerances of the hidden lines: how far off a triangle's plane a line may lie and not be
//! hidden by it, and the shortest run kept between runs of the other kind.

use crate::error::{Error, Result};
use crate::tolerance::{HIDDEN_LINE_MIN_PIECE, HIDDEN_LINE_TOLERANCE, MAX_HIDDEN_LINE_MIN_PIECE};

/// Tolerances of [`hidden_lines`](fn@super::hidden_lines).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HiddenLineOptions {
    /// Lines within this distance of a triangle's plane are not hidden by it, as a fraction of
    /// the diagonal of the triangles' bounding box.
    pub tolerance: f64,
    /// Runs shorter than this (pixels) between runs of the other kind are given to their
    /// neighbours.
    pub min_piece: f64,
}

impl Default for HiddenLineOptions {
    fn default() -> Self {
        HiddenLineOptions { tolerance: HIDDEN_LINE_TOLERANCE, min_piece: HIDDEN_LINE_MIN_PIECE }
    }
}

impl HiddenLineOptions {
    /// Refuses a tolerance outside [0, 1] and a `min_piece` outside [0,
    /// [`MAX_HIDDEN_LINE_MIN_PIECE`]] (or not finite), by name.
    pub(super) fn check(&self) -> Result<()> {
        for (name, x, ok) in [
            ("tolerance", self.tolerance, self.tolerance >= 0.0 && self.tolerance <= 1.0),
            ("minPiece", self.min_piece, self.min_piece >= 0.0 && self.min_piece <= MAX_HIDDEN_LINE_MIN_PIECE),
        ] {
            if !(x.is_finite() && ok) {
                return Err(Error::InvalidParameter {
                    name: if name == "tolerance" { "tolerance" } else { "minPiece" },
                    message: format!(
                        "{name} must be a number in {}, got {x}",
                        if name == "tolerance" {
                            "[0, 1]".to_string()
                        } else {
                            format!("[0, {MAX_HIDDEN_LINE_MIN_PIECE}]")
                        }
                    )
                    .into(),
                });
            }
        }
        Ok(())
    }
}
