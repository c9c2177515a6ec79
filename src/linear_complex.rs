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
pub fn fit_linear_complex(segments: &[Segment], tolerance: Option<f64>) -> LinearComplex {
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
    // the mean of r rᵀ (the 1/n changes no eigenvector: a mutant that drops it is equivalent)
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
        let fit = fit_linear_complex(&lines, None);
        assert_eq!(fit.nullity, 3);
        assert_eq!(fit.kind, ComplexKind::Special);
    }

    #[test]
    fn lines_meeting_the_z_axis_at_right_angles_are_a_congruence() {
        let lines: Vec<Segment> = (0..10)
            .map(|k| (k as f64 * 0.4, k as f64 * 0.3 - 1.0))
            .map(|(a, z)| seg([0.0, 0.0, z], [a.cos(), a.sin(), z]))
            .collect();
        let fit = fit_linear_complex(&lines, None);
        assert_eq!((fit.nullity, fit.kind), (2, ComplexKind::Congruence));
        assert!(fit.residual < 1e-12);
    }

    /// Lines near the helical complex of axis z and pitch p (c = e_z, c̄ = p e_z: the lines
    /// with m_z + p d_z = 0), each moved off it by a known amount: the line through
    /// (r cos t, r sin t, z) with direction ∝ (p t̂ − r e_z + s r̂) (t̂, r̂ the circle's tangent and
    /// radius) lies in it; moved by ε along r̂ it has m_z + p d_z = ε (t̂ · d).
    fn near_helical(p: f64, eps: &[f64]) -> Vec<Segment> {
        eps.iter()
            .enumerate()
            .map(|(k, &e)| {
                let (x, d, radial) = helical_line(p, k);
                let x = x + e * radial;
                Segment::new(x - 0.8 * d, x + 1.3 * d)
            })
            .collect()
    }

    /// The k-th line of [`near_helical`] before it is moved: a point, its unit direction, r̂.
    fn helical_line(p: f64, k: usize) -> (DVec3, DVec3, DVec3) {
        let k = k as f64;
        let (t, r, z, s) = (k * 0.9, 1.0 + 0.15 * k, 0.3 * k - 1.0, (0.7 * k).sin());
        let (radial, tangent) = (DVec3::new(t.cos(), t.sin(), 0.0), DVec3::new(-t.sin(), t.cos(), 0.0));
        let d = (p * tangent - r * DVec3::Z + s * radial).normalize();
        (r * radial + DVec3::new(0.0, 0.0, z), d, radial)
    }

    /// The residual is the documented value: the root mean square of c·m + c̄·d over the lines,
    /// with m taken at a point of each line other than the one the fit used.
    fn residual_by_hand(fit: &LinearComplex, lines: &[Segment]) -> f64 {
        let c = DVec3::from_slice(&fit.plucker[..3]);
        let cbar = DVec3::from_slice(&fit.plucker[3..]);
        let sum: f64 = lines
            .iter()
            .map(|s| {
                let d = (s.b - s.a).normalize();
                (c.dot(s.b.cross(d)) + cbar.dot(d)).powi(2)
            })
            .sum();
        (sum / lines.len() as f64).sqrt()
    }

    #[test]
    fn lines_of_a_helical_complex_give_its_axis_and_pitch_exactly() {
        let p = 0.6;
        let lines = near_helical(p, &[0.0; 14]);
        let fit = fit_linear_complex(&lines, None);
        assert_eq!((fit.nullity, fit.kind, fit.kind.name()), (1, ComplexKind::Complex, "complex"));
        let sign = fit.plucker[2].signum();
        let plucker: Vec<f64> = fit.plucker.iter().map(|x| x * sign).collect();
        for (got, want) in plucker.iter().zip([0.0, 0.0, 1.0, 0.0, 0.0, p]) {
            crate::assert_near!(*got, want, 1e-12);
        }
        crate::assert_near!(fit.pitch, p, 1e-12);
        crate::assert_near!(fit.axis_direction.cross(DVec3::Z).length(), 0.0, 1e-12);
        crate::assert_near!(fit.axis_point, DVec3::ZERO, 1e-12);
        assert!(fit.residual < 1e-13 && fit.spectrum[0] < 1e-13);
        assert!(fit.spectrum[1] > 1e-2, "a second complex would make it a congruence: {:?}", fit.spectrum);
    }

    #[test]
    fn the_residual_of_lines_moved_off_a_complex_is_what_they_were_moved_by() {
        // one line moved by ε among many exact ones: the fit keeps the helical complex to O(ε²)
        // and the residual is ε |t̂ · d| / √n to first order
        let (p, n, eps) = (0.6, 20, 1e-6);
        let mut moved = vec![0.0; n];
        moved[7] = eps;
        let lines = near_helical(p, &moved);
        let fit = fit_linear_complex(&lines, None);
        let (_, d, radial) = helical_line(p, 7);
        let tangent = DVec3::Z.cross(radial);
        let first_order = eps * tangent.dot(d).abs() / (n as f64).sqrt();
        // the helical complex itself has that residual; the fit leans towards the moved line,
        // which only lowers it, to √(1 − h) of it where h is the line's leverage in the least
        // squares (5 free parameters over 20 lines: h ≈ ¼ on average; 0.887 measured here)
        assert!(fit.residual <= first_order * (1.0 + 1e-6), "{} > {}", fit.residual, first_order);
        assert!(fit.residual >= 0.8 * first_order, "{} ≪ {}", fit.residual, first_order);
        crate::assert_near!(fit.residual, residual_by_hand(&fit, &lines), 1e-9 * eps);
        crate::assert_near!(fit.pitch, p, 1e-4);
    }

    #[test]
    fn the_residual_of_scattered_lines_is_the_rms_of_the_complex_equation() {
        let eps: Vec<f64> = (0..16).map(|k| 0.05 * ((1.7 * k as f64).sin())).collect();
        let lines = near_helical(0.4, &eps);
        let fit = fit_linear_complex(&lines, None);
        assert!(fit.residual > 1e-3);
        crate::assert_near!(fit.residual, residual_by_hand(&fit, &lines), 1e-12);
    }

    #[test]
    fn a_similarity_carries_the_fit_along() {
        // rotate, scale by λ and translate: the complex moves with the lines, the pitch and
        // the residual scale by λ, and the spectrum (measured in the fit's own frame) stays
        let eps: Vec<f64> = (0..16).map(|k| 0.05 * ((1.7 * k as f64).sin())).collect();
        let lines = near_helical(0.4, &eps);
        let (lambda, shift) = (3.5, DVec3::new(10.0, -4.0, 7.0));
        let turn = glam::DQuat::from_axis_angle(DVec3::new(1.0, -2.0, 0.5).normalize(), 2.1);
        let moved: Vec<Segment> =
            lines.iter().map(|s| Segment::new(lambda * (turn * s.a) + shift, lambda * (turn * s.b) + shift)).collect();
        let (before, after) = (fit_linear_complex(&lines, None), fit_linear_complex(&moved, None));
        crate::assert_near!(after.residual, lambda * before.residual, 1e-10);
        crate::assert_near!(after.pitch, lambda * before.pitch, 1e-10);
        for (a, b) in after.spectrum.iter().zip(before.spectrum) {
            crate::assert_near!(*a, b, 1e-10);
        }
        crate::assert_near!(after.axis_direction.cross(turn * before.axis_direction).length(), 0.0, 1e-10);
        let axis_point = lambda * (turn * before.axis_point) + shift;
        crate::assert_near!((axis_point - after.axis_point).cross(after.axis_direction).length(), 0.0, 1e-9);
        let mid = |f: &LinearComplex| 0.5 * (f.axis_segment[0] + f.axis_segment[1]);
        crate::assert_near!(mid(&after), lambda * (turn * mid(&before)) + shift, 1e-9);
        crate::assert_near!(
            (after.axis_segment[1] - after.axis_segment[0]).length(),
            lambda * (before.axis_segment[1] - before.axis_segment[0]).length(),
            1e-9
        );
    }

    #[test]
    fn lines_through_their_common_midpoint_keep_a_finite_frame() {
        // every midpoint at T: the spread is 0 and the frame takes the mean length instead
        let lines: Vec<Segment> = (0..9)
            .map(|k| {
                let t = k as f64 * 0.7;
                let d = DVec3::new(t.cos() * (1.3 * t).sin(), t.sin(), (2.1 * t).cos()).normalize();
                Segment::new(DVec3::new(1.0, 2.0, 3.0) - d, DVec3::new(1.0, 2.0, 3.0) + d)
            })
            .collect();
        let fit = fit_linear_complex(&lines, None);
        assert!(fit.plucker.iter().all(|x| x.is_finite()), "{:?}", fit.plucker);
        assert!(fit.axis_segment.iter().all(|p| p.is_finite()) || fit.pitch.is_infinite());
        assert_eq!((fit.nullity, fit.kind), (3, ComplexKind::Special));
        // the mean length 2 is the frame's unit: the bundle's three complexes have residual 0,
        // the three others the rms of the unit directions' components, 1/√3 on average
        assert!(fit.spectrum[..3].iter().all(|&r| r < 1e-13), "{:?}", fit.spectrum);
        let rest: f64 = fit.spectrum[3..].iter().map(|r| r * r).sum();
        crate::assert_near!(rest, 1.0, 1e-12);
    }

    #[test]
    fn the_spectrum_of_parallel_lines_is_measured_in_the_frame_of_their_spread() {
        // lines along z through (±1, ±1, 0) and (±2, 0, 0), (0, ±2, 0), 5 long: T = 0,
        // ℓ² = ⟨x² + y²⟩ = 3, rows (y/ℓ, −x/ℓ, 0, 0, 0, 1), so M = diag(½, ½, 0, 0, 0, 1)
        // (⟨x²⟩ = ⟨y²⟩ = 3/2, ⟨xy⟩ = 0): three complexes hold the lines (m_z, d_x, d_y: the
        // bundle of lines through z's point at infinity), the others have residual √½, √½, 1
        let feet =
            [[1.0, 1.0], [1.0, -1.0], [-1.0, 1.0], [-1.0, -1.0], [2.0, 0.0], [-2.0, 0.0], [0.0, 2.0], [0.0, -2.0]];
        let lines: Vec<Segment> = feet.iter().map(|&[x, y]| seg([x, y, -2.5], [x, y, 2.5])).collect();
        let fit = fit_linear_complex(&lines, None);
        let half = 0.5_f64.sqrt();
        for (got, want) in fit.spectrum.iter().zip([0.0, 0.0, 0.0, half, half, 1.0]) {
            crate::assert_near!(*got, want, 1e-14);
        }
        assert_eq!((fit.nullity, fit.kind), (3, ComplexKind::Special));
    }

    #[test]
    fn one_family_of_rulings_of_a_hyperboloid_is_a_regulus() {
        // x² + y² − z² = 1: the lines through (cos t, sin t, 0) along (−sin t, cos t, 1)
        let lines: Vec<Segment> = (0..10)
            .map(|k| {
                let t = k as f64 * 0.6;
                let (x, d) = (DVec3::new(t.cos(), t.sin(), 0.0), DVec3::new(-t.sin(), t.cos(), 1.0));
                Segment::new(x - d, x + 0.5 * d)
            })
            .collect();
        let fit = fit_linear_complex(&lines, None);
        assert_eq!((fit.nullity, fit.kind, fit.kind.name()), (3, ComplexKind::Regulus, "regulus"));
        assert!(fit.spectrum[3] > 1e-2, "{:?}", fit.spectrum);
    }

    #[test]
    fn lines_in_general_position_lie_in_no_complex() {
        let lines: Vec<Segment> = (0..12)
            .map(|k| {
                let t = k as f64;
                let x = DVec3::new((1.1 * t).sin(), (2.3 * t).cos(), (0.7 * t).sin()) * 2.0;
                let d = DVec3::new((1.9 * t).cos(), (0.4 * t + 1.0).sin(), (3.1 * t).cos() + 0.2);
                Segment::new(x, x + d)
            })
            .collect();
        let fit = fit_linear_complex(&lines, None);
        assert_eq!((fit.nullity, fit.kind, fit.kind.name()), (0, ComplexKind::General, "general"));
        assert!(fit.spectrum[0] > 1e-3 && fit.residual > 1e-3, "{:?}", fit.spectrum);
    }

    #[test]
    fn kinds_have_machine_names() {
        let names = [
            ComplexKind::General,
            ComplexKind::Complex,
            ComplexKind::Congruence,
            ComplexKind::Regulus,
            ComplexKind::Special,
        ]
        .map(ComplexKind::name);
        assert_eq!(names, ["general", "complex", "congruence", "regulus", "special"]);
    }
}
