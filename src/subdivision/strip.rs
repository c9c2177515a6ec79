//! Ruled strips refined through their boundary polygons (Section 4): the same curve scheme
//! is applied to a_0 … a_{N−1} and to b_0 … b_{N−1}, and corresponding points are joined.
//! The limit is smooth when both limit curves are.
//!
//! When lines rather than segments are given, the segments are first re-cut (the paper's
//! suggestion): constant length L, centred at the midpoint of the footpoints f_{i,i−1} and
//! f_{i,i+1} (the striction point estimate m_i). End rulings use their one footpoint; where a
//! pair is parallel the other footpoint is used, and with neither, the segment's midpoint.

use crate::error::{Error, Result};
use crate::ruled::RuledSurface;
use crate::subdivision::kernel::{self, Check};
use crate::subdivision::{check_steps, polygon_step, variational, Pair, Scheme};
use crate::tolerance::MAX_COORD;
use glam::DVec3;

/// `steps` steps of `scheme` on the strip (closed: the strip wraps around).
pub fn subdivide_strip(surface: &RuledSurface, scheme: Scheme, closed: bool, steps: usize) -> Result<RuledSurface> {
    scheme.validate()?;
    check_steps(steps)?;
    scheme.output_len_after(surface.len(), closed, steps)?;
    if let Scheme::Variational { n, variant } = scheme {
        let mut s = surface.clone();
        for _ in 0..steps {
            s = variational::refine(&s, n, variant)?;
        }
        return Ok(s);
    }
    if steps == 0 {
        return Ok(surface.clone());
    }
    // the strip as one polygon of endpoint pairs, read in place (the endpoints are laid out as
    // pairs) and handed to the new surface without a copy
    let strip: &[Pair] = bytemuck::cast_slice(surface.points());
    let bezier_degree = surface.len() - 1;
    let mut pairs = Vec::new();
    let mut passed = false;
    for step in 0..steps {
        let p = if step == 0 { strip } else { &pairs[..] };
        // only the last step's rulings become a surface; its kept ones are the input's when it
        // is the only step
        let check = match (step + 1 == steps, steps) {
            (false, _) => Check::Nothing,
            (true, 1) => Check::New,
            (true, _) => Check::All,
        };
        (pairs, passed) = match scheme {
            Scheme::FourPoint { w } => kernel::four_point(p, w, closed, check),
            Scheme::Chaikin => kernel::chaikin(p, closed, check),
            Scheme::BSpline { degree } => kernel::bspline(p, degree, closed, check),
            _ => (polygon_step(p, scheme, closed, bezier_degree), false),
        };
    }
    let points = bytemuck::allocation::cast_vec(pairs);
    // the kernels check the new rulings as they compute them; the full validation runs when
    // they did not, or found something, or too few rulings came out (it then says what, exactly
    // as before)
    if passed && points.len() >= 2 * RuledSurface::MIN_RULINGS {
        Ok(RuledSurface::from_trusted_points(points))
    } else {
        RuledSurface::from_points(points)
    }
}

/// The segments re-cut to length `length` (default: the mean segment length), centred on the
/// striction point estimates.
pub fn recut(surface: &RuledSurface, length: Option<f64>) -> Result<RuledSurface> {
    let n = surface.len();
    let length = match length {
        Some(l) if l.is_finite() && l > 0.0 && l <= MAX_COORD => l,
        Some(l) => return Err(Error::parameter("length", format!("must be a positive finite number, got {l}"))),
        None => surface.segments().map(|s| s.length()).sum::<f64>() / n as f64,
    };
    let inv = surface.invariants();
    let finite = |p: DVec3| p.is_finite().then_some(p);
    let segments = surface
        .segments()
        .enumerate()
        .map(|(i, s)| {
            let back = if i > 0 { finite(inv.footpoints[2 * i - 1]) } else { None };
            let fwd = if i + 1 < n { finite(inv.footpoints[2 * i]) } else { None };
            let centre = match (back, fwd) {
                (Some(p), Some(q)) => 0.5 * (p + q),
                (Some(p), None) | (None, Some(p)) => p,
                (None, None) => 0.5 * (s.a + s.b),
            };
            let e = s.line().dir;
            crate::line::Segment::new(centre - 0.5 * length * e, centre + 0.5 * length * e)
        })
        .collect();
    RuledSurface::new(segments)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::catalogue::AnalyticSurface;
    #[allow(unused_imports)]
    use crate::congruence::SmoothCongruence;
    #[allow(unused_imports)]
    use crate::ruled::SmoothRuled;
    use crate::tolerance::test::EXACT;

    #[test]
    fn both_boundaries_get_the_same_scheme() {
        let q = AnalyticSurface::Quartic;
        let s = q.sample(6, q.ranges()).unwrap();
        let r = subdivide_strip(&s, Scheme::FourPoint { w: 1.0 / 16.0 }, false, 2).unwrap();
        assert_eq!(r.len(), 21);
        for i in 0..6 {
            assert_eq!(r.segment(4 * i), s.segment(i));
        }
        let c = subdivide_strip(&s, Scheme::Chaikin, false, 1).unwrap();
        assert_eq!(c.len(), 10);
        assert_near!(c.segment(0).a, 0.75 * s.segment(0).a + 0.25 * s.segment(1).a, EXACT);
    }

    #[test]
    fn recut_centres_on_the_striction_points() {
        let hyp = AnalyticSurface::ALL[0].clone();
        let s = hyp.sample(20, hyp.ranges()).unwrap();
        let r = recut(&s, Some(0.5)).unwrap();
        let inv = s.invariants();
        for i in 1..19 {
            let seg = r.segment(i);
            assert_near!(seg.length(), 0.5, EXACT);
            assert_near!(0.5 * (seg.a + seg.b), inv.striction[i - 1], EXACT);
            assert_near!(seg.line().dir, s.segment(i).line().dir, EXACT);
        }
        assert!(recut(&s, Some(-1.0)).is_err());
        assert!(recut(&s, Some(f64::NAN)).is_err());
        // the cylinder has no footpoints: segment midpoints are kept
        let cyl = AnalyticSurface::Cylinder.sample(5, AnalyticSurface::Cylinder.ranges()).unwrap();
        let rc = recut(&cyl, None).unwrap();
        assert_near!(rc.segment(2).a + rc.segment(2).b, cyl.segment(2).a + cyl.segment(2).b, EXACT);
    }
}
