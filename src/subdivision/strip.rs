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
            s = variational::refine_variational(&s, n, variant)?;
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

    /// Rulings from (0, i, 0) along x with the given lengths. (The four-point rule with w = 1/16
    /// gives 9/16·(1 + 1) − 1/16·(9 + 9) = 0 on an edge between two rulings of length 1 that
    /// have rulings of length 9 beyond them.)
    fn strip_of_lengths(lengths: [f64; 6]) -> RuledSurface {
        RuledSurface::from_points(
            lengths
                .iter()
                .enumerate()
                .flat_map(|(i, &l)| {
                    let a = DVec3::new(0.0, i as f64, 0.0);
                    [a, a + DVec3::new(l, 0.0, 0.0)]
                })
                .collect(),
        )
        .unwrap()
    }

    /// Every new ruling is checked, wherever the kernel computes it: the leftover interior edge
    /// (open), the edge back to R_0 (closed), and a vanishing ruling of the first of two steps,
    /// kept by the second.
    #[test]
    fn a_vanishing_new_ruling_is_refused_wherever_it_falls() {
        let four = Scheme::FourPoint { w: 1.0 / 16.0 };
        // open: edge 3 (between the rulings of length 1 at 3 and 4, with 9 at 2 and 5) is the
        // kernel's leftover edge for six rulings; it becomes ruling 7
        let open = strip_of_lengths([1.0, 1.0, 9.0, 1.0, 1.0, 9.0]);
        assert_eq!(subdivide_strip(&open, four, false, 1), Err(Error::ZeroLength { ruling: 7 }));
        // closed: the edge R_5 → R_0, with R_4 and R_1 of length 9 beyond: ruling 11, and after a
        // second step (which keeps it) ruling 22
        let closed = strip_of_lengths([1.0, 9.0, 3.0, 3.0, 9.0, 1.0]);
        assert_eq!(subdivide_strip(&closed, four, true, 1), Err(Error::ZeroLength { ruling: 11 }));
        assert_eq!(subdivide_strip(&closed, four, true, 2), Err(Error::ZeroLength { ruling: 22 }));
        // open, the last edge (n − 2): its outer neighbour is the ghost 4p₅ − 6p₄ + 4p₃ − p₂, so
        // the new ruling is (15 d₄ + 5 d₅ − 5 d₃ + d₂)/16 = 0 for lengths 5, 5, 1, 1: ruling 9,
        // and after a second step (which keeps it next to the end) ruling 18
        let end = strip_of_lengths([2.0, 1.0, 5.0, 5.0, 1.0, 1.0]);
        assert_eq!(subdivide_strip(&end, four, false, 1), Err(Error::ZeroLength { ruling: 9 }));
        assert_eq!(subdivide_strip(&end, four, false, 2), Err(Error::ZeroLength { ruling: 18 }));
    }

    /// Without a length the re-cut takes the mean length of the segments.
    #[test]
    fn recut_to_the_mean_length() {
        let s = strip_of_lengths([1.0, 2.0, 3.0, 4.0, 5.0, 9.0]);
        assert!(recut(&s, None).unwrap().segments().all(|seg| (seg.length() - 4.0).abs() < 1e-15));
    }

    /// One de Casteljau step of a quadratic strip: both boundaries' halves, exactly.
    #[test]
    fn a_bezier_strip_of_degree_two() {
        let a = [DVec3::ZERO, DVec3::new(1.0, 2.0, 0.0), DVec3::new(2.0, 0.0, 0.0)];
        let s = RuledSurface::from_points(a.iter().flat_map(|&p| [p, p + DVec3::Z]).collect()).unwrap();
        let r = subdivide_strip(&s, Scheme::Bezier, false, 1).unwrap();
        let want = [(0.0, 0.0), (0.5, 1.0), (1.0, 1.0), (1.5, 1.0), (2.0, 0.0)].map(|(x, y)| DVec3::new(x, y, 0.0));
        assert_eq!(r.segments().map(|s| s.a).collect::<Vec<_>>(), want);
        assert_eq!(r.segments().map(|s| s.b).collect::<Vec<_>>(), want.map(|p| p + DVec3::Z));
    }

    #[test]
    fn a_recut_length_must_be_positive() {
        let s = strip_of_lengths([1.0; 6]);
        for l in [0.0, -1.0, f64::NAN, 2.0 * MAX_COORD] {
            assert!(matches!(recut(&s, Some(l)), Err(Error::InvalidParameter { name: "length", .. })), "{l}");
        }
        assert!(recut(&s, Some(MAX_COORD)).is_ok());
    }
}
