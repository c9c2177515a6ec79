//! How far the line-space subdivision's points leave the Klein quadric M before they are
//! projected back (Section 4 in line space, `subdivision/line_space.rs`; docs/src/conventions.md,
//! "The Klein quadric").
//!
//! A linear scheme combines the rulings' 6-vectors L_j = (e_j, m_j) with weights w_j summing
//! to 1: the combination a + ε a₀ = Σ w_j L_j is a point of P⁵ on the chord (or the plane, the
//! 3-space …) that the L_j span, off M unless they lie in a pencil. Its Klein residual
//! ρ = a·a₀/|a|² (K3) — for two lines with weights ½, ½: ρ = Ω(L₁, L₂)/(2|a|²) = −h sin φ/(2|a|²) —
//! is the distance from M the line-space scheme removes with N (normalising a + ε a₀ to a line:
//! the direction a/|a|, the moment's part along it taken away). After N, ρ is 0 to rounding.

use crate::error::Result;
use crate::klein::point::KleinPoint;
use crate::ruled::RuledSurface;
use crate::subdivision::line_space::{oriented, DualLine};
use crate::subdivision::{check_steps, polygon_step, Pair, Scheme};

/// The line-space subdivision's departure from M, step by step.
#[derive(Debug, Clone, PartialEq)]
pub struct Departure {
    /// For each step, the largest |ρ| of the combined points before N (K3).
    pub before: Vec<f64>,
    /// For each step, the largest |ρ| of the lines after N: 0 to rounding.
    pub after: Vec<f64>,
    /// The last step's combined points, before N (the input's lines when `steps` is 0).
    pub combined: Vec<KleinPoint>,
    /// The last step's lines, after N (oriented as the line-space scheme orients them).
    pub lines: Vec<KleinPoint>,
}

/// `steps` steps of `scheme` (Chaikin, B-spline, four-point) on `surface`'s rulings in line
/// space, as `subdivide_lines` takes them, with each step's points before and after N.
pub fn line_space_departure(surface: &RuledSurface, scheme: Scheme, closed: bool, steps: usize) -> Result<Departure> {
    scheme.validate()?;
    check_steps(steps)?;
    if matches!(scheme, Scheme::Bezier | Scheme::Variational { .. }) {
        return Err(crate::error::Error::parameter(
            "space",
            "line space supports \"chaikin\", \"bspline\" and \"four-point\"",
        ));
    }
    scheme.output_len_after(surface.len(), closed, steps)?;
    let klein = |d: &DualLine| KleinPoint::new(d.real, d.dual);
    let mut lines = oriented(surface.lines());
    let mut combined: Vec<KleinPoint> = lines.iter().map(klein).collect();
    let largest = |p: &[KleinPoint]| p.iter().map(|k| k.residual().abs()).fold(0.0, f64::max);
    let (mut before, mut after) = (Vec::with_capacity(steps), Vec::with_capacity(steps));
    for _ in 0..steps {
        let pairs: Vec<Pair> = lines.iter().map(|l| Pair(l.real, l.dual)).collect();
        let raw = polygon_step(&pairs, scheme, closed, 0);
        combined = raw.iter().map(|p| KleinPoint::new(p.0, p.1)).collect();
        before.push(largest(&combined));
        lines = raw.iter().map(|p| DualLine::normalized(p.0, p.1)).collect::<Result<_>>()?;
        after.push(largest(&lines.iter().map(klein).collect::<Vec<_>>()));
    }
    Ok(Departure { before, after, combined, lines: lines.iter().map(klein).collect() })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::AnalyticSurface;
    use crate::klein::point::klein_form;
    use crate::ruled::smooth::SmoothRuled;
    use crate::subdivision::line_space::subdivide_lines;

    /// Chaikin's first new line is ¾ L₀ + ¼ L₁: its residual is (3/16) Ω(L₀, L₁)/|a|² (K3).
    #[test]
    fn chaikins_points_leave_m_by_the_klein_form() {
        let s = AnalyticSurface::by_name("helicoid").unwrap();
        let surface = s.sample(24, s.ranges()).unwrap();
        let d = line_space_departure(&surface, Scheme::Chaikin, false, 1).unwrap();
        let l: Vec<KleinPoint> = surface.segments().map(|g| KleinPoint::of_segment(&g)).collect();
        let a = 0.75 * l[0].d + 0.25 * l[1].d;
        let want = 2.0 * 0.75 * 0.25 * klein_form(&l[0], &l[1]) / 2.0 / a.length_squared();
        assert!((d.combined[0].residual() - want).abs() < 1e-15, "{} {want}", d.combined[0].residual());
        assert!(d.before[0] > 1e-3 && d.after[0] < 1e-15);
    }

    /// The lines after N are the lines `subdivide_lines` refines to.
    #[test]
    fn the_lines_after_n_are_the_line_space_schemes() {
        let s = AnalyticSurface::by_name("hyperboloid").unwrap();
        let surface = s.sample(9, s.ranges()).unwrap();
        let scheme = Scheme::FourPoint { w: 0.0625 };
        let d = line_space_departure(&surface, scheme, true, 2).unwrap();
        let refined = subdivide_lines(&surface, scheme, true, 2, None).unwrap();
        assert_eq!(d.lines.len(), refined.len());
        for (k, seg) in d.lines.iter().zip(refined.segments()) {
            let l = KleinPoint::of_segment(&seg);
            assert!((k.d - l.d).length() < 1e-12 && (k.m - l.m).length() < 1e-12);
        }
        assert_eq!((d.before.len(), d.after.len()), (2, 2));
        assert!(line_space_departure(&surface, Scheme::Bezier, false, 1).is_err());
    }
}
