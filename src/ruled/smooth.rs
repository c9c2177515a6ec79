//! Smooth ruled surfaces x(u, v) = a(u) + v·d(u), known by their jets, with their exact
//! invariants (Section 2) — what the discrete models are measured against. The catalogue's
//! analytic surfaces and surfaces typed as formulas implement [`SmoothRuled`]; the studies of
//! convergence (Propositions 1–2) and accuracy take any implementation, so the algorithms do
//! not depend on the catalogue.
//!
//! For any parametrisation, with e = d/|d| and e′ = (d′ − (d′·e)e)/|d| (docs/src/conventions.md, Section 2):
//!
//! - striction point s(u) = a − ((a′·e′)/(e′·e′)) e,
//! - distribution parameter δ(u) = det(a′, e, e′)/(e′·e′),
//! - central tangent direction e₃ = e × e′/|e × e′| (4).
//!
//! A cylindrical ruling (e′ = 0) has no striction point and δ = 0 (it is torsal).

use crate::base::{sample_parameters, Jet, Ranges};
use crate::error::{Error, Result};
use crate::line::{Line, Segment};
use crate::ruled::RuledSurface;
use crate::tolerance::{DISTANCE_REFINE_STEPS, DISTANCE_SCAN, MAX_SAMPLES};
use glam::DVec3;

/// A smooth ruled surface, known by its jets.
pub trait SmoothRuled {
    /// Machine name ("hyperboloid", "formula", …).
    fn name(&self) -> &str;

    /// a(u), a′(u), d(u), d′(u) (NaN where a formula is undefined).
    fn jet(&self, u: f64) -> Jet;

    /// [`SmoothRuled::jet`], refused where it is not finite or d(u) = 0 (a surface typed as
    /// formulas says where); a closed-form surface has nothing to refuse.
    fn checked_jet(&self, u: f64) -> Result<Jet> {
        Ok(self.jet(u))
    }

    /// The surface point x(u, v) = a(u) + v d(u).
    fn point(&self, u: f64, v: f64) -> DVec3 {
        let j = self.jet(u);
        j.a + v * j.d
    }

    /// The ruling R(u) as an oriented line (direction e = d/|d|).
    fn line(&self, u: f64) -> Line {
        let j = self.jet(u);
        Line { point: j.a, dir: j.d.normalize() }
    }

    /// Exact striction point s(u) = a − ((a′·e′)/(e′·e′)) e; `None` on a cylindrical ruling.
    fn striction(&self, u: f64) -> Option<DVec3> {
        let j = self.jet(u);
        let (e, de) = j.frame();
        let de2 = de.length_squared();
        (de2 > 0.0).then(|| j.a - (j.da.dot(de) / de2) * e)
    }

    /// Exact distribution parameter δ(u) = det(a′, e, e′)/(e′·e′); 0 on a cylindrical ruling.
    fn distribution(&self, u: f64) -> f64 {
        let j = self.jet(u);
        let (e, de) = j.frame();
        let de2 = de.length_squared();
        if de2 > 0.0 {
            j.da.dot(e.cross(de)) / de2
        } else {
            0.0
        }
    }

    /// Exact central tangent direction e₃ = e × e′/|e × e′| (4); `None` on a cylindrical ruling.
    fn central_tangent(&self, u: f64) -> Option<DVec3> {
        let (e, de) = self.jet(u).frame();
        e.cross(de).try_normalize()
    }

    /// Distance of `p` from the surface (rulings extended to whole lines), searching the
    /// rulings with u in `[u0, u1]`: a scan of [`DISTANCE_SCAN`] rulings, then golden-section
    /// refinement of the point-to-line distance around the best one.
    fn distance_to(&self, p: DVec3, u0: f64, u1: f64) -> f64 {
        let f = |u: f64| self.line(u).distance_to(p);
        let samples = DISTANCE_SCAN;
        let h = (u1 - u0) / samples as f64;
        let best = (0..=samples).map(|i| u0 + i as f64 * h).fold((u0, f64::INFINITY), |(bu, bf), u| {
            let fu = f(u);
            if fu < bf {
                (u, fu)
            } else {
                (bu, bf)
            }
        });
        let (mut lo, mut hi) = (best.0 - h, best.0 + h);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let (mut c, mut d) = (hi - g * (hi - lo), lo + g * (hi - lo));
        let (mut fc, mut fd) = (f(c), f(d));
        for _ in 0..DISTANCE_REFINE_STEPS {
            if fc < fd {
                hi = d;
                d = c;
                fd = fc;
                c = hi - g * (hi - lo);
                fc = f(c);
            } else {
                lo = c;
                c = d;
                fc = fd;
                d = lo + g * (hi - lo);
                fd = f(d);
            }
        }
        best.1.min(fc).min(fd)
    }

    /// `count` rulings at the [`sample_parameters`] of `r`, each the segment from a + v₀d to a + v₁d.
    fn sample(&self, count: usize, r: Ranges) -> Result<RuledSurface> {
        if count > MAX_SAMPLES {
            return Err(Error::TooMany { what: "samples", got: count, max: MAX_SAMPLES });
        }
        for (name, x) in [("uMin", r.u.0), ("uMax", r.u.1), ("vMin", r.v.0), ("vMax", r.v.1)] {
            if !x.is_finite() {
                return Err(Error::parameter(name, format!("must be a finite number, got {x}")));
            }
        }
        if r.v.0 == r.v.1 {
            return Err(Error::parameter("vMax", "must differ from vMin (segments of zero length)"));
        }
        let segments = sample_parameters(count, r)
            .into_iter()
            .map(|u| {
                let j = self.checked_jet(u)?;
                Ok(Segment::new(j.a + r.v.0 * j.d, j.a + r.v.1 * j.d))
            })
            .collect::<Result<Vec<Segment>>>()?;
        RuledSurface::new(segments)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::AnalyticSurface;

    #[test]
    fn the_central_tangent_of_a_helicoid_is_its_axis_and_a_cylinder_has_none() {
        // rulings (cos u, sin u, 0) turning about the z-axis: e × e′ is ±z at every u
        let h = AnalyticSurface::by_name("helicoid").unwrap();
        for u in [-1.0, 0.0, 0.4, 2.5] {
            let t = SmoothRuled::central_tangent(&h, u).unwrap();
            assert!((t.z.abs() - 1.0).abs() < 1e-15 && t.x.abs() < 1e-15 && t.y.abs() < 1e-15, "{t}");
        }
        assert_eq!(SmoothRuled::central_tangent(&AnalyticSurface::by_name("cylinder").unwrap(), 0.3), None);
    }
}
