//! A discrete ruled surface as a polygon on the Klein quadric M, and the Klein form of its
//! consecutive rulings (Section 2 read on M; docs/src/conventions.md, "The Klein quadric").
//!
//! The rulings R_i of a discrete ruled surface are points L_i = (e_i, a_i × e_i) of M (their
//! normalised Plücker coordinates, the input's orientation kept). For consecutive rulings,
//! with d = a_{i+1} − a_i,
//!
//!   Ω(L_i, L_{i+1}) = e_i·(a_{i+1} × e_{i+1}) + e_{i+1}·(a_i × e_i)
//!                   = det(a_{i+1}, e_{i+1}, e_i) + det(a_i, e_i, e_{i+1})
//!                   = −det(d, e_i, e_{i+1})
//!                   = −h_{i,i+1} sin φ_{i,i+1},                                          (K7)
//!
//! with h and φ of Section 2 as the conventions fix them (h = det(d, e_i, e_{i+1})/|e_i × e_{i+1}|,
//! sin φ = |e_i × e_{i+1}|). So Ω vanishes exactly where consecutive rulings meet or are
//! parallel (a torsal step: the discrete developable's edges, a cone's rulings), and
//! δ_{i,i+1} = h/φ = −Ω/(φ sin φ) is the Klein form over φ sin φ ≈ φ²: on a smooth surface
//! sampled at step H, Ω = −δ φ² + O(φ⁴), a second-order quantity whose sign is −sign δ.

use crate::klein::point::{klein_form, KleinPoint};
use crate::ruled::RuledSurface;
use crate::tolerance::KLEIN_TORSAL;

/// The rulings of a discrete ruled surface as a polygon on M, with Ω of each step.
#[derive(Debug, Clone, PartialEq)]
pub struct KleinPolygon {
    /// L_i = (e_i, a_i × e_i), one per ruling.
    pub points: Vec<KleinPoint>,
    /// Ω(L_i, L_{i+1}) (K7), one per step: n − 1 of them, n when closed (the last Ω(L_{n−1}, L_0)).
    pub omega: Vec<f64>,
    /// Whether step i is torsal: |Ω| ≤ [`KLEIN_TORSAL`] · max(1, |m_i|, |m_{i+1}|).
    pub torsal: Vec<bool>,
    /// The largest Klein residual |Ω(L_i, L_i)|/2 = |e_i·m_i| of the points.
    pub max_residual: f64,
}

impl KleinPolygon {
    /// The polygon of `surface`'s rulings; `closed`: the last ruling and the first are a step too.
    pub fn of(surface: &RuledSurface, closed: bool) -> Self {
        let points: Vec<KleinPoint> = surface.segments().map(|s| KleinPoint::of_segment(&s)).collect();
        let n = points.len();
        let steps = if closed && n > 2 { n } else { n.saturating_sub(1) };
        let (mut omega, mut torsal) = (Vec::with_capacity(steps), Vec::with_capacity(steps));
        for i in 0..steps {
            let (w, t) = step(&points[i], &points[(i + 1) % n]);
            omega.push(w);
            torsal.push(t);
        }
        let max_residual = points.iter().map(|p| p.residual().abs()).fold(0.0, f64::max);
        KleinPolygon { points, omega, torsal, max_residual }
    }

    /// The step of least |Ω| and its Ω: the step nearest to torsal; None without steps.
    pub fn least_omega(&self) -> Option<(usize, f64)> {
        self.omega.iter().copied().enumerate().min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
    }
}

/// Ω(A, B) of two neighbouring lines (K7) and whether their step is torsal: |Ω| ≤
/// [`KLEIN_TORSAL`] · max(1, |m_A|, |m_B|) (the lines meet or are parallel, to rounding of their
/// moments).
pub(crate) fn step(a: &KleinPoint, b: &KleinPoint) -> (f64, bool) {
    let w = klein_form(a, b);
    (w, w.abs() <= KLEIN_TORSAL * a.m.length().max(b.m.length()).max(1.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::AnalyticSurface;
    use crate::developable::construct::{cone, tangent_surface, Span};
    use crate::line::Segment;
    use crate::ruled::smooth::SmoothRuled;
    use glam::DVec3;

    /// Ω = −h sin φ (K7) on the hyperboloid, against Section 2's h and φ.
    #[test]
    fn omega_is_minus_h_sin_phi_on_the_hyperboloid() {
        let s = AnalyticSurface::by_name("hyperboloid").unwrap();
        let surface = s.sample(40, s.ranges()).unwrap();
        let inv = surface.invariants();
        let k = KleinPolygon::of(&surface, false);
        assert_eq!(k.omega.len(), 39);
        for i in 0..39 {
            let want = -inv.distance[i] * inv.angle[i].sin();
            assert!((k.omega[i] - want).abs() < 1e-14, "{i}: {} vs {want}", k.omega[i]);
            assert!(!k.torsal[i]);
        }
        assert!(k.max_residual < 1e-15);
    }

    /// The right helicoid a = (0, 0, pu), d = (cos u, sin u, 0): Ω(u₁, u₂) = −p Δ sin Δ exactly,
    /// Δ = u₂ − u₁ (so h = pΔ, φ = Δ, δ = p).
    #[test]
    fn omega_of_the_helicoid_in_closed_form() {
        let p = 0.5;
        let segs: Vec<Segment> = (0..12)
            .map(|i| {
                let u = 0.37 * i as f64;
                let a = DVec3::new(0.0, 0.0, p * u);
                Segment::new(a, a + DVec3::new(u.cos(), u.sin(), 0.0))
            })
            .collect();
        let k = KleinPolygon::of(&RuledSurface::new(segs).unwrap(), false);
        for w in &k.omega {
            assert!((w + p * 0.37 * 0.37f64.sin()).abs() < 1e-15, "{w}");
        }
        assert_eq!(k.least_omega().map(|(_, w)| w < 0.0), Some(true));
    }

    /// A cone's rulings all meet at the apex, the tangent surface's consecutive rulings at the
    /// polygon's vertices: every step torsal, Ω = 0 to rounding.
    #[test]
    fn omega_vanishes_on_cones_and_tangent_surfaces() {
        let helix: Vec<DVec3> =
            (0..20).map(|i| DVec3::new((0.3 * i as f64).cos(), (0.3 * i as f64).sin(), 0.1 * i as f64)).collect();
        let span = Span { from: 0.2, to: 1.5 };
        for surface in [cone(&helix, DVec3::new(0.3, -0.2, 2.0), span).unwrap(), tangent_surface(&helix, span).unwrap()]
        {
            let k = KleinPolygon::of(&surface, false);
            assert!(k.torsal.iter().all(|&t| t), "{:?}", k.omega);
            assert!(k.omega.iter().all(|w| w.abs() < 1e-14));
        }
        // the catalogue's cone, closed: the last step too
        let c = AnalyticSurface::by_name("cone").unwrap();
        let k = KleinPolygon::of(&c.sample(24, c.ranges()).unwrap(), true);
        assert_eq!(k.omega.len(), 24);
        assert!(k.torsal.iter().all(|&t| t));
    }

    /// A turned-around ruling changes the sign of Ω next to it (h changes sign, sin φ does not).
    #[test]
    fn reversing_a_ruling_flips_omega() {
        let s = AnalyticSurface::by_name("hyperboloid").unwrap();
        let surface = s.sample(6, s.ranges()).unwrap();
        let mut segs: Vec<Segment> = surface.segments().collect();
        segs[2] = Segment::new(segs[2].b, segs[2].a);
        let flipped = KleinPolygon::of(&RuledSurface::new(segs).unwrap(), false);
        let k = KleinPolygon::of(&surface, false);
        for i in 0..5 {
            let sign = if i == 1 || i == 2 { -1.0 } else { 1.0 };
            assert!((flipped.omega[i] - sign * k.omega[i]).abs() < 1e-15);
        }
    }

    /// A cone far from the origin: its moments are about 10⁴, Ω's rounding about 10⁻¹², and
    /// the torsal test scales with |m| (1e-12 alone would call steps of a cone skew).
    #[test]
    fn the_torsal_test_scales_with_the_moments() {
        let apex = DVec3::new(7e3, -4e3, 5e3);
        let ring: Vec<DVec3> =
            (0..16).map(|i| apex + DVec3::new((0.4 * i as f64).cos(), (0.4 * i as f64).sin(), 1.3)).collect();
        let k = KleinPolygon::of(&cone(&ring, apex, Span { from: 0.2, to: 1.5 }).unwrap(), false);
        let ms: Vec<f64> = k.points.iter().map(|p| p.m.length()).collect();
        assert!(ms.iter().all(|&m| m > 3e3), "{ms:?}");
        assert!(k.omega.iter().any(|w| w.abs() > 1e-13), "rounding of moments this long: {:?}", k.omega);
        assert!(k.torsal.iter().all(|&t| t), "{:?}", k.omega);
    }

    /// Two rulings make one step, closed or not (a closed polygon needs three); the step of least
    /// |Ω| is the one the omegas say (the quartic's torsal ruling at u = 0: step 11 of 23).
    #[test]
    fn two_rulings_one_step_and_the_least_step() {
        let s = AnalyticSurface::by_name("hyperboloid").unwrap();
        let two = s.sample(2, s.ranges()).unwrap();
        assert_eq!(KleinPolygon::of(&two, true).omega.len(), 1);
        assert_eq!(KleinPolygon::of(&two, false).omega.len(), 1);
        let q = AnalyticSurface::by_name("quartic").unwrap();
        let k = KleinPolygon::of(&q.sample(24, q.ranges()).unwrap(), false);
        let (i, w) = k.least_omega().unwrap();
        assert_eq!((i, w), (11, k.omega[11]));
        assert!(k.omega.iter().all(|x| x.abs() >= w.abs()));
        assert!(w < 0.0 && w.abs() < 1e-4, "{w}");
    }
}
