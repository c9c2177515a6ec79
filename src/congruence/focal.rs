//! Focal geometry of a line congruence — beyond the paper, which treats congruences (Section 5)
//! by subdivision only. Conventions (docs/src/guide/focal.md):
//!
//! - A line of a grid runs p → q; e = (q − p)/|q − p|; a point on it is p + t·e.
//! - For a smooth congruence p(u, v) + t·e(u, v) the **focal parameters** are the roots t of
//!   det(p_u + t·e_u, p_v + t·e_v, e) = 0                                              (F1)
//!   and the **torsal directions** the (du : dv) with
//!   det(p_u du + p_v dv, e, e_u du + e_v dv) = 0.                                      (F2)
//!   Two real roots: hyperbolic; one double root: parabolic; none: elliptic. The **middle
//!   point** is the midpoint of the focal points, t = −b/(2a) in (F3) below (real for every
//!   kind). The **focal planes** are spanned by e and the torsal displacement; the
//!   **normality** is |cos| of their angle (0 for the normals of a surface).
//!
//! Only the *lines* enter: with Plücker coordinates L = (d, m), m = p × q, d = q − p (any scale)
//! and their derivatives L_u, L_v, a point x on the line moves, as the line moves, with
//!   x_k⊥ = ê × (m_k − x × d_k)/|d|     (k = u, v; the part of x_k across the line)      (F4)
//! whatever point p of the line the data names and whatever scale d has. With x = p + t·ê,
//! x_k⊥ = h_k + t·f_k, h_k = ê × (m_k − p × d_k)/|d|, f_k = d_k⊥/|d| (= ê_k), and (F1) reads
//!   a t² + b t + c = 0,  a = det(f_u, f_v, ê),  b = det(h_u, f_v, ê) + det(f_u, h_v, ê),
//!   c = det(h_u, h_v, ê).                                                               (F3)
//! A focal parameter tᵢ has the torsal direction (du : dv) that annihilates
//! (h_u + tᵢ f_u) du + (h_v + tᵢ f_v) dv, which is (F2); the focal plane is spanned by ê and
//! f_u du + f_v dv (by h when tᵢ = ±∞).
//!
//! **Discrete**: the derivatives L_u, L_v of a grid are differences of the lines' Plücker
//! coordinates L_{i,j} = (q − p, p × q) in grid steps — central in the interior, one-sided over
//! three lines at the boundary, both second order; first order along a direction with only two
//! lines. Plücker coordinates do not depend on where p and q sit on the line, so the discrete
//! focal points are *exactly* unchanged by swapping p and q, exactly equivariant under rigid
//! motions, and exact wherever the coordinates are bilinear in (i, j) (the lines meeting two
//! skew lines). The derivative's error changes with the scale of d only in the second order.
//!
//! **Analytic**: the same (F3) with the exact derivatives of a [`CongruenceJet`], scaled to grid
//! steps, so it compares point by point with the discrete values.

use crate::base::CongruenceJet;
use crate::congruence::LineCongruence;
use crate::congruence::SmoothCongruence;
use crate::line::Segment;
use crate::mesh::Mesh;
use crate::tolerance::{FOCAL_PARABOLIC, FOCAL_SHEET_REACH, FOCAL_TORSAL_SIGN, FOCAL_TORSAL_ZERO};
use glam::{DVec2, DVec3};

/// Kind of a line of a congruence by its focal points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum FocalKind {
    /// No real focal point (the quadratic (F3) has no real root).
    Elliptic = 0,
    /// Two real focal points.
    Hyperbolic = 1,
    /// One double focal point (within [`FOCAL_PARABOLIC`]).
    Parabolic = 2,
}

/// The focal geometry of one line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Focal {
    /// Kind.
    pub kind: FocalKind,
    /// t₁ ≤ t₂ on p + t·ê (±∞ for a focal point at infinity; NaN when not real).
    pub parameters: [f64; 2],
    /// The focal points p + tᵢ·ê (NaN when not real or at infinity).
    pub points: [DVec3; 2],
    /// Unit (du, dv) in grid steps of the torsal direction of each focal point, du > 0 (dv > 0
    /// when du = 0 within 1e-9); NaN when not real or when every direction is torsal (as for a
    /// bundle of lines).
    pub torsal: [DVec2; 2],
    /// Midpoint of the focal points, p − b/(2a)·ê (NaN if a = 0).
    pub middle: DVec3,
    /// |cos| of the angle between the focal planes (NaN when not real).
    pub normality: f64,
}

/// One line with the first derivatives of its Plücker coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineJet {
    /// A point of the line (p).
    pub p: DVec3,
    /// Direction d (any nonzero length).
    pub d: DVec3,
    /// ∂d/∂u, ∂d/∂v.
    pub d_uv: [DVec3; 2],
    /// ∂m/∂u, ∂m/∂v for m = p × d (or any point of the line × d).
    pub m_uv: [DVec3; 2],
}

impl LineJet {
    /// From a congruence's exact jet, the derivatives multiplied by the steps (hu, hv).
    pub fn from_jet(j: &CongruenceJet, hu: f64, hv: f64) -> Self {
        let m_u = j.p_u.cross(j.d) + j.p.cross(j.d_u);
        let m_v = j.p_v.cross(j.d) + j.p.cross(j.d_v);
        LineJet { p: j.p, d: j.d, d_uv: [j.d_u * hu, j.d_v * hv], m_uv: [m_u * hu, m_v * hv] }
    }

    /// The focal geometry of the line, (F3) and (F2).
    pub fn focal(&self) -> Focal {
        let len = self.d.length();
        let e = self.d / len;
        let across = |x: DVec3| x - x.dot(e) * e;
        let h = [0, 1].map(|k| e.cross(self.m_uv[k] - self.p.cross(self.d_uv[k])) / len);
        let f = [0, 1].map(|k| across(self.d_uv[k]) / len);
        let det = |x: DVec3, y: DVec3| x.cross(y).dot(e);
        let a = det(f[0], f[1]);
        let b = det(h[0], f[1]) + det(f[0], h[1]);
        let c = det(h[0], h[1]);
        let disc = b * b - 4.0 * a * c;
        let scale = b * b + 4.0 * (a * c).abs();
        let middle = self.p - b / (2.0 * a) * e;
        let middle = if middle.is_finite() { middle } else { DVec3::splat(f64::NAN) };
        let nan2 = DVec2::splat(f64::NAN);
        let nan3 = DVec3::splat(f64::NAN);
        if disc < -FOCAL_PARABOLIC * scale {
            return Focal {
                kind: FocalKind::Elliptic,
                parameters: [f64::NAN; 2],
                points: [nan3; 2],
                torsal: [nan2; 2],
                middle,
                normality: f64::NAN,
            };
        }
        let parabolic = disc <= FOCAL_PARABOLIC * scale;
        // roots without cancellation: q = −(b + sign(b)·√D)/2, t = q/a and c/q
        let root = if parabolic { 0.0 } else { disc.sqrt() };
        let q = -0.5 * (b + b.signum() * root);
        let (mut t1, mut t2) = if parabolic { (-b / (2.0 * a), -b / (2.0 * a)) } else { (q / a, c / q) };
        if a == 0.0 && parabolic {
            // a = b = 0: (F3) is the constant c; no focal point to report (both at infinity
            // when c ≠ 0, every point when c = 0)
            (t1, t2) = (f64::NAN, f64::NAN);
        }
        if t1 > t2 {
            std::mem::swap(&mut t1, &mut t2);
        }
        let point = |t: f64| if t.is_finite() { self.p + t * e } else { nan3 };
        // the torsal direction of tᵢ annihilates x_u⊥ du + x_v⊥ dv = (h + tᵢ f)(du, dv); at
        // t = ±∞ that is f. A displacement is zero when it is small against its two terms.
        let largest = |x: &[DVec3; 2]| x[0].length().max(x[1].length());
        let torsal = |t: f64| {
            if t.is_finite() {
                kernel([h[0] + t * f[0], h[1] + t * f[1]], largest(&h) + t.abs() * largest(&f))
            } else {
                kernel(f, largest(&f))
            }
        };
        let (w1, w2) = (torsal(t1), torsal(t2));
        // focal plane i ∋ ê and f(dirᵢ) (h(dirᵢ) if tᵢ = ±∞); |cos| of the planes' angle
        let plane = |t: f64, w: DVec2| {
            let v = if t.is_finite() { f[0] * w.x + f[1] * w.y } else { h[0] * w.x + h[1] * w.y };
            v.normalize_or_zero()
        };
        let (n1, n2) = (plane(t1, w1), plane(t2, w2));
        let normality = if parabolic {
            1.0
        } else if n1 == DVec3::ZERO || n2 == DVec3::ZERO {
            f64::NAN
        } else {
            n1.dot(n2).abs().min(1.0)
        };
        Focal {
            kind: if parabolic { FocalKind::Parabolic } else { FocalKind::Hyperbolic },
            parameters: [t1, t2],
            points: [point(t1), point(t2)],
            torsal: [w1, w2],
            middle,
            normality,
        }
    }
}

/// The unit (du, dv), sign fixed by du > 0 (dv > 0 when du ≈ 0), with x_u du + x_v dv = 0 for x_u ∥ x_v;
/// NaN when both vanish against `scale` (every direction is torsal).
fn kernel(x: [DVec3; 2], scale: f64) -> DVec2 {
    let w = if x[0].length_squared() >= x[1].length_squared() { x[0] } else { x[1] };
    if w.length() <= FOCAL_TORSAL_ZERO * scale {
        return DVec2::splat(f64::NAN);
    }
    let dir = DVec2::new(x[1].dot(w), -x[0].dot(w)).normalize();
    if dir.x < -FOCAL_TORSAL_SIGN || (dir.x.abs() <= FOCAL_TORSAL_SIGN && dir.y < 0.0) {
        -dir
    } else {
        dir
    }
}

/// Index differences along one grid direction: central inside, one-sided over three
/// samples at the ends (both second order), the plain difference for two samples.
fn difference<T>(at: impl Fn(usize) -> T, k: usize, n: usize) -> T
where
    T: std::ops::Sub<Output = T> + std::ops::Mul<f64, Output = T>,
{
    if n == 2 {
        at(1) - at(0)
    } else if k == 0 {
        (at(1) - at(0)) * 2.0 - (at(2) - at(0)) * 0.5
    } else if k == n - 1 {
        (at(n - 1) - at(n - 2)) * 2.0 - (at(n - 1) - at(n - 3)) * 0.5
    } else {
        (at(k + 1) - at(k - 1)) * 0.5
    }
}

/// The focal geometry of every line of a grid (row-major), from the Plücker coordinates of its
/// lines differenced as the module documentation says.
pub fn focal_grid(rows: usize, cols: usize, p: &[DVec3], q: &[DVec3]) -> Vec<Focal> {
    let plucker: Vec<Plucker> = p.iter().zip(q).map(|(&p, &q)| Plucker { d: q - p, m: p.cross(q) }).collect();
    let mut out = Vec::with_capacity(rows * cols);
    for i in 0..rows {
        for j in 0..cols {
            let du = difference(|r| plucker[r * cols + j], i, rows);
            let dv = difference(|c| plucker[i * cols + c], j, cols);
            let k = i * cols + j;
            let jet = LineJet { p: p[k], d: plucker[k].d, d_uv: [du.d, dv.d], m_uv: [du.m, dv.m] };
            out.push(jet.focal());
        }
    }
    out
}

/// The exact focal geometry of an analytic congruence at the lines of its rows × cols grid,
/// derivatives in grid steps (comparable with [`focal_grid`] of the same grid).
pub fn focal_analytic(c: &(impl SmoothCongruence + ?Sized), rows: usize, cols: usize) -> Vec<Focal> {
    let ((u0, u1), (v0, v1), _, _) = c.domain();
    let (hu, hv) = ((u1 - u0) / (rows - 1) as f64, (v1 - v0) / (cols - 1) as f64);
    let mut out = Vec::with_capacity(rows * cols);
    for i in 0..rows {
        for j in 0..cols {
            let (u, v) = c.parameters(i, j, rows, cols);
            out.push(LineJet::from_jet(&c.jet(u, v), hu, hv).focal());
        }
    }
    out
}

/// Focal sheet `sheet` (0: the points of t₁, 1: of t₂) of a congruence as a triangle mesh: the
/// grid's quads whose four focal points are real and within [`FOCAL_SHEET_REACH`] diagonals of
/// the lines' bounding box from its centre (a focal surface runs off to infinity where a = 0 in
/// (F3); a view shows what lies near the lines). Vertices of no kept quad sit at the centre.
pub fn focal_sheet(c: &LineCongruence, focal: &[Focal], sheet: usize) -> Mesh {
    let ends = c.p().into_iter().chain(c.q());
    let (lo, hi) = ends.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
    let (centre, reach) = (0.5 * (lo + hi), FOCAL_SHEET_REACH * (hi - lo).length());
    let ok = |x: DVec3| x.is_finite() && (x - centre).length() <= reach;
    let positions: Vec<DVec3> =
        focal.iter().map(|f| if ok(f.points[sheet]) { f.points[sheet] } else { centre }).collect();
    let (rows, cols) = (c.rows(), c.cols());
    let mut indices = Vec::new();
    for i in 0..rows - 1 {
        for j in 0..cols - 1 {
            let a = i * cols + j;
            let quad = [a, a + 1, a + cols, a + cols + 1];
            if quad.iter().all(|&k| ok(focal[k].points[sheet])) {
                let [a, b, c, d] = quad.map(|k| k as u32);
                indices.extend([a, c, d, a, d, b]);
            }
        }
    }
    Mesh { positions, indices }
}

/// Short strokes on the director surface along the torsal directions: for each real torsal
/// direction (du, dv) of line (i, j), the segment p ± scale·(du·p_i + dv·p_j), with the grid
/// differences of p as in [`focal_grid`].
pub fn torsal_strokes(rows: usize, cols: usize, p: &[DVec3], focal: &[Focal], scale: f64) -> Vec<Segment> {
    let mut out = Vec::new();
    for i in 0..rows {
        for j in 0..cols {
            let k = i * cols + j;
            let p_i = difference(|r| p[r * cols + j], i, rows);
            let p_j = difference(|c| p[i * cols + c], j, cols);
            for w in focal[k].torsal.iter().filter(|w| w.is_finite()) {
                let step = scale * (w.x * p_i + w.y * p_j);
                out.push(Segment::new(p[k] - step, p[k] + step));
            }
        }
    }
    out
}

/// Plücker coordinates (d, m) as a vector space element.
#[derive(Debug, Clone, Copy)]
struct Plucker {
    d: DVec3,
    m: DVec3,
}

impl std::ops::Sub for Plucker {
    type Output = Plucker;
    fn sub(self, o: Plucker) -> Plucker {
        Plucker { d: self.d - o.d, m: self.m - o.m }
    }
}

impl std::ops::Mul<f64> for Plucker {
    type Output = Plucker;
    fn mul(self, s: f64) -> Plucker {
        Plucker { d: self.d * s, m: self.m * s }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[allow(unused_imports)]
    use crate::congruence::SmoothCongruence;
    #[allow(unused_imports)]
    use crate::ruled::SmoothRuled;

    /// Lines x = (u, v, 0) + t·(−kv, ku, 1): an elliptic linear congruence.
    #[test]
    fn elliptic_has_no_real_focal_point() {
        let k = 0.7;
        let (rows, cols) = (5, 6);
        let mut p = Vec::new();
        let mut q = Vec::new();
        for i in 0..rows {
            for j in 0..cols {
                let (u, v) = (i as f64 * 0.3 - 0.6, j as f64 * 0.25 - 0.5);
                p.push(DVec3::new(u, v, 0.0));
                q.push(DVec3::new(u - k * v, v + k * u, 1.0));
            }
        }
        for f in focal_grid(rows, cols, &p, &q) {
            assert_eq!(f.kind, FocalKind::Elliptic);
            assert!(f.parameters.iter().all(|t| t.is_nan()));
            assert!(f.points.iter().all(|x| x.is_nan()));
            assert!(f.normality.is_nan());
            assert!(f.middle.is_finite());
        }
    }

    #[test]
    fn differences_are_second_order_at_the_ends_too() {
        // d/dk of (k h)² at k = 0, 2, 4 of five samples: 2 k h², exact for quadratics; the
        // samples are a slice, so a difference reaching past either end panics
        let h = 0.1;
        let samples: Vec<DVec3> = (0..5).map(|r| DVec3::splat((r as f64 * h).powi(2))).collect();
        for k in [0, 2, 4] {
            let got = difference(|r| samples[r], k, 5);
            assert!((got.x - 2.0 * k as f64 * h * h).abs() < 1e-15, "{k}: {got}");
        }
        // two samples: the plain difference at both
        for k in [0, 1] {
            assert_eq!(difference(|r| [1.0, 3.5][r], k, 2), 2.5);
        }
    }

    /// The line x = t·(0, 0, 1) whose jet has, in (F3), f_k = (f_k, 0) and h_k = (h_k, 0):
    /// d = ê, d_k = f_k and m_k = (h_k.y, −h_k.x, 0), so that ê × m_k = h_k (p = 0).
    fn jet(f: [[f64; 2]; 2], h: [[f64; 2]; 2]) -> LineJet {
        let d_uv = f.map(|[x, y]| DVec3::new(x, y, 0.0));
        let m_uv = h.map(|[x, y]| DVec3::new(y, -x, 0.0));
        LineJet { p: DVec3::ZERO, d: DVec3::Z, d_uv, m_uv }
    }

    /// a = 4, b = −16 and c = 16 − y in (F3): for y = 0 the double root t = 2. With c chosen
    /// so that the discriminant b² − 4ac is s·FOCAL_PARABOLIC·(b² + 4|ac|), the line is
    /// parabolic for |s| < 1 (focal point t = −b/(2a) = 2 exactly), elliptic below, hyperbolic above.
    #[test]
    fn the_parabolic_tolerance_is_relative_to_b2_plus_4ac() {
        let line = |s: f64| {
            let c = 16.0 * (1.0 - s * FOCAL_PARABOLIC) / (1.0 + s * FOCAL_PARABOLIC);
            jet([[2.0, 0.0], [0.0, 2.0]], [[-4.0, 16.0 - c], [1.0, -4.0]]).focal()
        };
        assert_eq!(line(-1.1).kind, FocalKind::Elliptic);
        assert_eq!(line(1.1).kind, FocalKind::Hyperbolic);
        for s in [-0.9, 0.0, 0.9] {
            let f = line(s);
            assert_eq!(f.kind, FocalKind::Parabolic, "{s}");
            assert_eq!(f.parameters, [2.0, 2.0], "{s}");
            assert_eq!(f.points, [DVec3::new(0.0, 0.0, 2.0); 2], "{s}");
            assert_eq!(f.middle, DVec3::new(0.0, 0.0, 2.0), "{s}");
            // at t = 2, x_u⊥ = (0, 16 − c, 0) ≈ 0 and x_v⊥ = (1, 0, 0): du = 1, dv = 0
            assert_eq!(f.torsal, [DVec2::X; 2], "{s}");
            assert_eq!(f.normality, 1.0, "{s}");
        }
    }

    /// A bundle through (0, 0, 2) disturbed by δ: f_k = 3·(unit k), h₀ = (−6, 0), h₁ = (δ, −6), so
    /// a = 9, b = −36, c = 36 (double root t = 2) and at t = 2 the displacements are 0 and
    /// (δ, 0). Every direction is torsal while δ ≤ FOCAL_TORSAL_ZERO·(|h|max + |t|·|f|max) =
    /// 12·FOCAL_TORSAL_ZERO; above, only du (torsal (1, 0)).
    #[test]
    fn every_direction_is_torsal_within_the_tolerance_of_the_derivatives() {
        let torsal = |delta: f64| jet([[3.0, 0.0], [0.0, 3.0]], [[-6.0, 0.0], [delta, -6.0]]).focal().torsal;
        assert!(torsal(11.5 * FOCAL_TORSAL_ZERO).iter().all(|w| w.is_nan()));
        assert!(torsal(12.5 * FOCAL_TORSAL_ZERO).iter().all(|w| (*w - DVec2::X).length() < 1e-15));
        assert!(torsal(0.0).iter().all(|w| w.is_nan()));
    }

    /// f₀ = f₁ = (1, 0) (a = 0), h₀ = (2, 1), h₁ = (0, 2): b = 1, c = 4, so t = −4 and a focal
    /// point at infinity. At t = −4 the displacements (−2, 1) and (−4, 2) vanish along
    /// (du, dv) = (2, −1)/√5, whose focal plane holds f = (1, 0, 0); at infinity f vanishes along
    /// (1, −1)/√2 and the plane holds h₀ − h₁ = (2, −1, 0): normality 2/√5.
    #[test]
    fn a_focal_point_at_infinity_has_its_plane_through_h() {
        let f = jet([[1.0, 0.0], [1.0, 0.0]], [[2.0, 1.0], [0.0, 2.0]]).focal();
        assert_eq!(f.kind, FocalKind::Hyperbolic);
        assert_eq!(f.parameters, [f64::NEG_INFINITY, -4.0]);
        assert!(f.points[0].is_nan());
        assert_eq!(f.points[1], DVec3::new(0.0, 0.0, -4.0));
        assert!(f.middle.is_nan(), "a = 0: no middle point");
        let [w1, w2] = f.torsal;
        assert!((w1 - DVec2::new(1.0, -1.0) / 2f64.sqrt()).length() < 1e-15, "{w1}");
        assert!((w2 - DVec2::new(2.0, -1.0) / 5f64.sqrt()).length() < 1e-15, "{w2}");
        assert!((f.normality - 2.0 / 5f64.sqrt()).abs() < 1e-15, "{}", f.normality);
    }

    /// The kernel's sign: du > 0, or dv > 0 when du = 0.
    #[test]
    fn torsal_directions_point_to_growing_u() {
        // x_u = (4, 0, 0), x_v = (−3, 0, 0): 4 du − 3 dv = 0 along ±(0.6, 0.8)
        let w = kernel([DVec3::new(4.0, 0.0, 0.0), DVec3::new(-3.0, 0.0, 0.0)], 1.0);
        assert!((w - DVec2::new(0.6, 0.8)).length() < 1e-15, "{w}");
        // x_v = 0: the direction (0, ±1)
        assert_eq!(kernel([DVec3::X, DVec3::ZERO], 1.0), DVec2::Y);
    }
}
