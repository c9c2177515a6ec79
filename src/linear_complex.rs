//! Linear line complexes fitted to lines — beyond the paper (Pottmann & Wallner, *Computational
//! Line Geometry*, §3.1 and §6.2), for the rulings of a surface (Section 2) or the lines of a
//! congruence (Section 5).
//!
//! A line with unit direction d through x has Plücker coordinates (d, m), m = x × d. A linear
//! complex C = (c, c̄) holds the lines with
//!   c·m + c̄·d = 0;                                                                     (C1)
//! its pitch is (c·c̄)/(c·c), its axis has direction c and passes through (c × c̄)/(c·c);
//! c = 0 is the complex of the lines orthogonal to c̄.
//!
//! **Fit.** In the frame centred at the centroid T of the segments' midpoints, lengths divided
//! by their root-mean-square distance ℓ from T, the rows r = (m′, d), m′ = ((x − T)/ℓ) × d,
//! give the 6 × 6 symmetric matrix M = (1/n) Σ r rᵀ. Its eigenvector of the smallest
//! eigenvalue minimises the mean square of (C1) over unit C′ (nalgebra's `SymmetricEigen`),
//! and the frame makes the fit invariant under rigid motions and scaling. Back in the world
//!   c = c′/ℓ,  c̄ = c̄′ − (c′ × T)/ℓ,                                                       (C2)
//! normalised to |c| = 1 (to |c̄| = 1 when c′ ≈ 0). The **nullity** counts the eigenvalues whose
//! root is within the tolerance: 1 a linear complex, 2 a linear congruence, 3 a regulus — or,
//! when the Klein form Ω(C₁, C₂) = c₁·c̄₂ + c̄₁·c₂ vanishes on those three complexes, the
//! lines of a bundle or of a plane ("special", as are nullities above 3).

use crate::line::Segment;
use crate::tolerance::{COMPLEX_REGULUS_DET, COMPLEX_TOLERANCE};
use glam::DVec3;
use nalgebra::{Matrix3, Matrix6, SymmetricEigen, Vector6};

/// What the lines are, by how many independent linear complexes hold them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ComplexKind {
    /// No linear complex holds them (nullity 0).
    General,
    /// Exactly one (nullity 1): e.g. the rulings of a helical surface.
    Complex,
    /// Two (nullity 2): the lines of a linear congruence, e.g. those meeting two lines.
    Congruence,
    /// Three, with a non-degenerate Klein form: one regulus of a quadric.
    Regulus,
    /// Three with a degenerate Klein form (lines of a bundle or a field), or more than three
    /// (a pencil, a single line, too few lines).
    Special,
}

impl ComplexKind {
    /// Machine name ("general", "complex", "congruence", "regulus", "special").
    pub fn name(self) -> &'static str {
        match self {
            Self::General => "general",
            Self::Complex => "complex",
            Self::Congruence => "congruence",
            Self::Regulus => "regulus",
            Self::Special => "special",
        }
    }
}

/// The best-fitting linear complex of a set of lines.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearComplex {
    /// (c, c̄), |c| = 1 (|c̄| = 1 when c = 0).
    pub plucker: [f64; 6],
    /// (c·c̄)/(c·c); ±∞ when c = 0.
    pub pitch: f64,
    /// (c × c̄)/(c·c), the axis point nearest the origin; NaN when c = 0.
    pub axis_point: DVec3,
    /// c (c̄ when c = 0), unit.
    pub axis_direction: DVec3,
    /// A piece of the axis to draw: centred at the foot of the segments' centroid T, four times
    /// their spread ℓ long; NaN when c = 0.
    pub axis_segment: [DVec3; 2],
    /// Root mean square of c·m + c̄·d over the lines (unit d), in the world's lengths when
    /// c ≠ 0, dimensionless when c = 0.
    pub residual: f64,
    /// The root-mean-square residual, in the fit's frame, of each eigenvector of M (six
    /// orthogonal complexes), ascending by eigenvalue.
    pub spectrum: [f64; 6],
    /// How many independent complexes hold the lines within the tolerance.
    pub nullity: usize,
    /// What that makes the lines.
    pub kind: ComplexKind,
}

/// Fits a linear complex to segments (a → b each); `tolerance` bounds a residual in the fit's
/// frame for the nullity ([`COMPLEX_TOLERANCE`] by default). Segments must have nonzero length
/// (the validated surfaces and congruences guarantee it).
pub fn fit(segments: &[Segment], tolerance: Option<f64>) -> LinearComplex {
    let tolerance = tolerance.unwrap_or(COMPLEX_TOLERANCE);
    let n = segments.len().max(1) as f64;
    let mid = |s: &Segment| 0.5 * (s.a + s.b);
    let centre = segments.iter().map(mid).sum::<DVec3>() / n;
    let spread = (segments.iter().map(|s| (mid(s) - centre).length_squared()).sum::<f64>() / n).sqrt();
    let scale = if spread > 0.0 { spread } else { segments.iter().map(|s| s.length()).sum::<f64>() / n };
    let rows: Vec<Vector6<f64>> = segments
        .iter()
        .map(|s| {
            let d = (s.b - s.a).normalize();
            let moment = ((mid(s) - centre) / scale).cross(d);
            Vector6::new(moment.x, moment.y, moment.z, d.x, d.y, d.z)
        })
        .collect();
    let m = rows.iter().fold(Matrix6::<f64>::zeros(), |m, r| m + r * r.transpose()) / n;
    let eigen = SymmetricEigen::new(m);
    let mut order: Vec<usize> = (0..6).collect();
    order.sort_by(|&i, &j| eigen.eigenvalues[i].total_cmp(&eigen.eigenvalues[j]));
    // each eigen-complex's residual from the rows themselves: √λ would lose half the digits
    let spectrum: [f64; 6] = std::array::from_fn(|k| {
        let v = eigen.eigenvectors.column(order[k]);
        (rows.iter().map(|r| r.dot(&v).powi(2)).sum::<f64>() / n).sqrt()
    });
    let nullity = spectrum.iter().filter(|&&r| r <= tolerance).count();
    let basis = |k: usize| eigen.eigenvectors.column(order[k]).into_owned();
    let kind = match nullity {
        0 => ComplexKind::General,
        1 => ComplexKind::Complex,
        2 => ComplexKind::Congruence,
        3 => {
            let klein = Matrix3::from_fn(|i, j| {
                let (a, b) = (basis(i), basis(j));
                a.fixed_rows::<3>(0).dot(&b.fixed_rows::<3>(3)) + a.fixed_rows::<3>(3).dot(&b.fixed_rows::<3>(0))
            });
            if klein.determinant().abs() > COMPLEX_REGULUS_DET {
                ComplexKind::Regulus
            } else {
                ComplexKind::Special
            }
        }
        _ => ComplexKind::Special,
    };
    let best = basis(0);
    let c_frame = DVec3::new(best[0], best[1], best[2]);
    let cbar_frame = DVec3::new(best[3], best[4], best[5]);
    // (C2)
    let c = c_frame / scale;
    let cbar = cbar_frame - c_frame.cross(centre) / scale;
    let (c, cbar) = if c_frame.length() > tolerance {
        (c / c.length(), cbar / c.length())
    } else {
        (DVec3::ZERO, cbar / cbar.length())
    };
    let residual = (segments
        .iter()
        .map(|s| {
            let d = (s.b - s.a).normalize();
            let r = c.dot(s.a.cross(d)) + cbar.dot(d);
            r * r
        })
        .sum::<f64>()
        / n)
        .sqrt();
    let (pitch, axis_point, axis_direction) =
        if c == DVec3::ZERO { (f64::INFINITY, DVec3::splat(f64::NAN), cbar) } else { (c.dot(cbar), c.cross(cbar), c) };
    let foot = axis_point + (centre - axis_point).dot(axis_direction) * axis_direction;
    let axis_segment = [foot - 2.0 * scale * axis_direction, foot + 2.0 * scale * axis_direction];
    LinearComplex {
        plucker: [c.x, c.y, c.z, cbar.x, cbar.y, cbar.z],
        pitch,
        axis_point,
        axis_direction,
        axis_segment,
        residual,
        spectrum,
        nullity,
        kind,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seg(a: [f64; 3], b: [f64; 3]) -> Segment {
        Segment::new(DVec3::from(a), DVec3::from(b))
    }

    #[test]
    fn lines_through_a_point_are_special() {
        let lines: Vec<Segment> = (0..12)
            .map(|k| {
                let t = k as f64 * 0.7;
                let d = DVec3::new(t.cos() * (1.3 * t).sin(), t.sin(), (2.1 * t).cos());
                Segment::new(DVec3::new(1.0, 2.0, 3.0) - d, DVec3::new(1.0, 2.0, 3.0) + 2.0 * d)
            })
            .collect();
        let fit = fit(&lines, None);
        assert_eq!(fit.nullity, 3);
        assert_eq!(fit.kind, ComplexKind::Special);
    }

    #[test]
    fn lines_meeting_the_z_axis_at_right_angles_are_a_congruence() {
        let lines: Vec<Segment> = (0..10)
            .map(|k| (k as f64 * 0.4, k as f64 * 0.3 - 1.0))
            .map(|(a, z)| seg([0.0, 0.0, z], [a.cos(), a.sin(), z]))
            .collect();
        let fit = fit(&lines, None);
        assert_eq!((fit.nullity, fit.kind), (2, ComplexKind::Congruence));
        assert!(fit.residual < 1e-12);
    }
}
