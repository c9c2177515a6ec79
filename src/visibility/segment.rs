//! A segment clipped to the near plane (z + w ≥ 0) and to w > 0, with the images of its ends,
//! and the intervals of [0, 1] the conditions along it are closed under.

use super::view::{Image, View};
use glam::DVec3;

/// The interval of [0, 1] where a + s(b − a) ≥ 0 (closed), None when empty.
pub(super) fn nonnegative(a: f64, b: f64) -> Option<(f64, f64)> {
    match (a >= 0.0, b >= 0.0) {
        (true, true) => Some((0.0, 1.0)),
        (false, false) => None,
        (true, false) => Some((0.0, a / (a - b))),
        (false, true) => Some((a / (a - b), 1.0)),
    }
}

/// The meet of two intervals, None when either is empty or they are disjoint.
pub(super) fn meet(x: Option<(f64, f64)>, y: Option<(f64, f64)>) -> Option<(f64, f64)> {
    let ((a0, a1), (b0, b1)) = (x?, y?);
    let (lo, hi) = (a0.max(b0), a1.min(b1));
    (lo <= hi).then_some((lo, hi))
}

/// A segment ready for the tests: its world endpoints (clipped to the near plane), their images.
pub(super) struct Clipped {
    pub(super) a: DVec3,
    pub(super) b: DVec3,
    pub(super) ia: Image,
    pub(super) ib: Image,
}

/// The segment p → q clipped to the near plane (z + w ≥ 0) and to w > 0; None when nothing is left.
pub(super) fn clip_segment(view: &View, p: DVec3, q: DVec3) -> Option<Clipped> {
    if !(p.is_finite() && q.is_finite()) {
        return None;
    }
    let (cp, cq) = (view.clip(p), view.clip(q));
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    // near plane, and a small positive w (a guard for degenerate matrices)
    for (fp, fq) in [(cp.z + cp.w, cq.z + cq.w), (cp.w, cq.w)] {
        match nonnegative(fp, fq) {
            None => return None,
            Some((lo, hi)) => {
                t0 = t0.max(lo);
                t1 = t1.min(hi);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    // the ends as they are where nothing is clipped, so that consecutive segments of a polyline
    // meet in exactly the same image point
    let (a, ca) = if t0 == 0.0 { (p, cp) } else { (p.lerp(q, t0), cp.lerp(cq, t0)) };
    let (b, cb) = if t1 == 1.0 { (q, cq) } else { (p.lerp(q, t1), cp.lerp(cq, t1)) };
    if !(ca.w > 0.0 && cb.w > 0.0) {
        return None;
    }
    Some(Clipped { a, b, ia: view.image_of_clip(ca), ib: view.image_of_clip(cb) })
}
#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DMat4, DVec2};

    /// A view from a matrix given by its rows.
    fn view_of_rows(rows: [[f64; 4]; 4]) -> View {
        let m = DMat4::from_cols_array_2d(&rows).transpose();
        View::new(&m.to_cols_array(), 2.0, 2.0).unwrap()
    }

    /// Clipping to the near plane (z + w ≥ 0, closed) and to w > 0 (open: a point at w = 0 has
    /// no image), with matrices that set clip z and w apart; a segment with a point at infinity
    /// is left out.
    #[test]
    fn segments_are_clipped_to_the_near_plane_and_to_positive_w() {
        // clip (y, z, 5, x): z + w ≥ 0 for x ≥ −5; w = x
        let w_is_x =
            view_of_rows([[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 5.0], [1.0, 0.0, 0.0, 0.0]]);
        assert_eq!(w_is_x.project(DVec3::new(2.0, 0.5, 0.25)), Some(DVec2::new(1.25, 0.875)));
        assert_eq!(w_is_x.project(DVec3::new(0.0, 0.5, 0.25)), None);
        assert!(clip_segment(&w_is_x, DVec3::X, DVec3::ZERO).is_none());
        assert!(clip_segment(&w_is_x, DVec3::ZERO, DVec3::X).is_none());
        let whole = clip_segment(&w_is_x, DVec3::X, DVec3::new(3.0, 1.0, 0.0)).unwrap();
        assert_eq!((whole.a, whole.b, whole.ia.w, whole.ib.w), (DVec3::X, DVec3::new(3.0, 1.0, 0.0), 1.0, 3.0));
        // clip (y, z, −1, x): the near plane is x = 1
        let near_at_1 =
            view_of_rows([[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, -1.0], [1.0, 0.0, 0.0, 0.0]]);
        let cut = clip_segment(&near_at_1, DVec3::new(0.5, 0.0, 0.0), DVec3::new(3.0, 2.0, 0.0)).unwrap();
        crate::assert_near!(cut.a, DVec3::new(1.0, 0.4, 0.0), 1e-15);
        assert_eq!(cut.b, DVec3::new(3.0, 2.0, 0.0));
        crate::assert_near!(cut.ia.screen, DVec2::new(1.4, 1.0), 1e-15);
        // touching the near plane in one point: that point is kept
        let touch = clip_segment(&near_at_1, DVec3::X, DVec3::new(0.5, 0.0, 0.0)).unwrap();
        assert_eq!((touch.a, touch.b), (DVec3::X, DVec3::X));
        // clip (y, z, x + 1, x + 2): a point at x = ∞ has z + w = w = ∞ but no image
        let x_grows =
            view_of_rows([[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0, 2.0]]);
        let far = DVec3::new(f64::INFINITY, 0.0, 0.0);
        assert!(clip_segment(&x_grows, far, DVec3::X).is_none());
        assert!(clip_segment(&x_grows, DVec3::X, far).is_none());
        assert!(clip_segment(&x_grows, DVec3::X, DVec3::Y).is_some());
    }
}
