//! A discrete ruled surface: a validated sequence of rulings R_0 … R_{N−1}, N ≥ 2
//! (Section 2). Every constructor checks its input, so the algorithms that take a
//! `RuledSurface` never meet NaN, infinities or zero-length rulings.

use crate::base::check_coordinates;
use crate::error::{Error, Result};
use crate::line::{Line, Segment};
use crate::ruled::invariants::Invariants;
use crate::tolerance::{MAX_RULINGS, ZERO_LENGTH_REL};
use glam::DVec3;

/// A discrete ruled surface: N ≥ 2 segments a_i → b_i, each finite and of nonzero length.
///
/// Stored as the 2N endpoints a_0, b_0, a_1, b_1, …, which is exactly the flat layout of
/// the JS API, so [`RuledSurface::flat`] is a view, not a copy.
#[derive(Debug, Clone, PartialEq)]
pub struct RuledSurface {
    points: Vec<DVec3>,
}

/// Numbers per ruling in flat arrays: a.x a.y a.z b.x b.y b.z.
pub const FLAT_STRIDE: usize = 6;

impl RuledSurface {
    /// Fewest rulings a discrete ruled surface may have.
    pub const MIN_RULINGS: usize = 2;

    /// From flat coordinates, 6 numbers per ruling (a_i then b_i).
    pub fn from_flat(coords: &[f64]) -> Result<Self> {
        if coords.len() % FLAT_STRIDE != 0 {
            return Err(Error::BadLength { what: "segment coordinates", len: coords.len(), multiple: FLAT_STRIDE });
        }
        check_count(coords.len() / FLAT_STRIDE)?;
        check_coordinates(coords, FLAT_STRIDE)?;
        let points = coords.chunks_exact(3).map(DVec3::from_slice).collect();
        Self::checked_lengths(points)
    }

    /// From segments; rejects the same inputs as [`RuledSurface::from_flat`].
    pub fn new(segments: Vec<Segment>) -> Result<Self> {
        check_count(segments.len())?;
        for (i, s) in segments.iter().enumerate() {
            let c = [s.a.x, s.a.y, s.a.z, s.b.x, s.b.y, s.b.z];
            check_coordinates(&c, FLAT_STRIDE).map_err(|e| shift_index(e, FLAT_STRIDE * i))?;
        }
        Self::checked_lengths(segments.iter().flat_map(|s| [s.a, s.b]).collect())
    }

    /// From endpoints a_0, b_0, a_1, b_1, … (validated like [`RuledSurface::from_flat`]).
    pub fn from_points(points: Vec<DVec3>) -> Result<Self> {
        if points.len() % 2 != 0 {
            return Err(Error::BadLength { what: "endpoints", len: points.len(), multiple: 2 });
        }
        check_count(points.len() / 2)?;
        check_coordinates(bytemuck::cast_slice(&points), FLAT_STRIDE)?;
        Self::checked_lengths(points)
    }

    fn checked_lengths(points: Vec<DVec3>) -> Result<Self> {
        // |b − a| ≤ rel · max(|a|, |b|), compared squared: no square roots in this pass
        let rel2 = ZERO_LENGTH_REL * ZERO_LENGTH_REL;
        for (i, ab) in points.chunks_exact(2).enumerate() {
            let len2 = (ab[1] - ab[0]).length_squared();
            if len2 <= rel2 * ab[0].length_squared().max(ab[1].length_squared()) {
                return Err(Error::ZeroLength { ruling: i });
            }
        }
        Ok(RuledSurface { points })
    }

    /// A surface from endpoints produced by ruledlab's own algorithms from a validated
    /// surface (rigid motions, subdivision): finite and of nonzero length by construction.
    pub(crate) fn from_trusted_points(points: Vec<DVec3>) -> Self {
        debug_assert!(points.len() >= 4 && points.len() % 2 == 0);
        RuledSurface { points }
    }

    /// Number of rulings N.
    pub fn len(&self) -> usize {
        self.points.len() / 2
    }

    /// Always false: a surface has at least two rulings.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Ruling i as a segment. Panics if i ≥ N.
    pub fn segment(&self, i: usize) -> Segment {
        Segment::new(self.points[2 * i], self.points[2 * i + 1])
    }

    /// The rulings as segments.
    pub fn segments(&self) -> impl ExactSizeIterator<Item = Segment> + '_ {
        self.points.chunks_exact(2).map(|ab| Segment::new(ab[0], ab[1]))
    }

    /// The rulings as oriented lines (a_i, e_i).
    pub fn lines(&self) -> impl ExactSizeIterator<Item = Line> + '_ {
        self.segments().map(|s| s.line())
    }

    /// The endpoints a_0, b_0, a_1, b_1, ….
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// The segments as flat f64 coordinates, 6 per ruling (a view, no copy).
    pub fn flat(&self) -> &[f64] {
        bytemuck::cast_slice(&self.points)
    }

    /// The segments as flat f32 coordinates for GPU buffers.
    pub fn flat_f32(&self) -> Vec<f32> {
        self.flat().iter().map(|&x| x as f32).collect()
    }

    /// All discrete invariants of Section 2, by the f64x2 kernel
    /// ([`Invariants::compute_from_points`]: [`Invariants::of`] of the lines to the last bit, φ
    /// and what divides by it to within a few ulp).
    pub fn invariants(&self) -> Invariants {
        let mut inv = Invariants::default();
        inv.compute_from_points(&self.points, false);
        inv
    }

    /// The invariants of the surface read as closed: R_{N−1} is followed by R_0 again
    /// ([`Invariants::from_lines_closed`]; computed as [`RuledSurface::invariants`]).
    pub fn invariants_closed(&self) -> Invariants {
        let mut inv = Invariants::default();
        inv.compute_from_points(&self.points, true);
        inv
    }

    /// The invariants (closed or open) written into `out`, reusing its memory: the zero-copy
    /// path of the wasm API keeps `out` in wasm memory and hands out views of its arrays.
    pub fn invariants_into(&self, out: &mut Invariants, closed: bool) {
        out.compute_from_points(&self.points, closed);
    }

    /// The unit directions e_i = (b_i − a_i)/|b_i − a_i|.
    pub fn directions(&self) -> Vec<DVec3> {
        self.lines().map(|l| l.dir).collect()
    }

    /// Mean length |b_i − a_i| of the segments.
    pub fn mean_length(&self) -> f64 {
        self.segments().map(|s| s.length()).sum::<f64>() / self.len() as f64
    }

    /// The same lines with other segments: a_i moved to a_i + s_i e_i and b_i to b_i + t_i e_i,
    /// where `amounts` holds s_i, t_i per ruling (the rulings as lines do not change).
    pub fn slide(&self, amounts: &[f64]) -> Result<Self> {
        if amounts.len() != 2 * self.len() {
            return Err(Error::parameter(
                "amounts",
                format!(
                    "need 2 numbers per ruling ({} for {} rulings), got {}",
                    2 * self.len(),
                    self.len(),
                    amounts.len()
                ),
            ));
        }
        check_coordinates(amounts, 2)
            .map_err(|_| Error::parameter("amounts", "every amount must be a finite number"))?;
        let points = self
            .segments()
            .zip(amounts.chunks_exact(2))
            .flat_map(|(s, st)| {
                let e = s.line().dir;
                [s.a + st[0] * e, s.b + st[1] * e]
            })
            .collect();
        Self::from_points(points)
    }

    /// Largest angle (radians, in [0, π/2]) between corresponding rulings of `self` and
    /// `other` as unoriented lines; `other` must have as many rulings.
    pub fn max_angle_to(&self, other: &RuledSurface) -> Result<f64> {
        if other.len() != self.len() {
            return Err(Error::parameter("other", format!("needs {} rulings, got {}", self.len(), other.len())));
        }
        Ok(self
            .lines()
            .zip(other.lines())
            .map(|(a, b)| a.dir.cross(b.dir).length().atan2(a.dir.dot(b.dir).abs()))
            .fold(0.0, f64::max))
    }

    /// The largest relative change of an edge length of the two boundary polygons (a_i) and
    /// (b_i) between `self` and `other`: 0 (to rounding) for an isometric deformation.
    pub fn max_edge_change(&self, other: &RuledSurface) -> Result<f64> {
        if other.len() != self.len() {
            return Err(Error::parameter("other", format!("needs {} rulings, got {}", self.len(), other.len())));
        }
        let (p, q) = (&self.points, &other.points);
        let mut worst = 0.0f64;
        for i in 0..p.len().saturating_sub(2) {
            let before = (p[i + 2] - p[i]).length();
            if before > 0.0 {
                worst = worst.max(((q[i + 2] - q[i]).length() - before).abs() / before);
            }
        }
        Ok(worst)
    }

    /// The rulings whose index is not a multiple of `stride`: after `k` steps of an
    /// interpolatory scheme (stride 2^k), the inserted ones.
    pub fn inserted(&self, stride: usize) -> Vec<Segment> {
        let stride = stride.max(1);
        self.segments().enumerate().filter(|(i, _)| i % stride != 0).map(|(_, s)| s).collect()
    }

    /// The surface with `f` applied to every endpoint (re-validated: `f` could collapse
    /// a ruling).
    pub fn map_points(&self, f: impl Fn(DVec3) -> DVec3) -> Result<Self> {
        let points: Vec<DVec3> = self.points.iter().map(|&p| f(p)).collect();
        check_coordinates(bytemuck::cast_slice(&points), FLAT_STRIDE)?;
        Self::checked_lengths(points)
    }
}

/// Checks the ruling count against [`RuledSurface::MIN_RULINGS`] and [`MAX_RULINGS`].
pub fn check_count(n: usize) -> Result<()> {
    if n < RuledSurface::MIN_RULINGS {
        return Err(Error::TooFew { what: "rulings", got: n, min: RuledSurface::MIN_RULINGS });
    }
    if n > MAX_RULINGS {
        return Err(Error::TooMany { what: "rulings", got: n, max: MAX_RULINGS });
    }
    Ok(())
}

/// A polygon from flat coordinates, 3 per point: at least 2 and at most [`MAX_RULINGS`]
/// points, every coordinate finite and at most [`crate::tolerance::MAX_COORD`] in magnitude.
pub fn points_from_flat(coords: &[f64]) -> Result<Vec<DVec3>> {
    checked_points(coords).map(<[DVec3]>::to_vec)
}

/// The points of flat coordinates, checked as [`points_from_flat`] checks them, as a view of
/// the same memory (no copy: glam lays a `DVec3` out as three consecutive `f64`).
pub fn checked_points(coords: &[f64]) -> Result<&[DVec3]> {
    if coords.len() % 3 != 0 {
        return Err(Error::BadLength { what: "point coordinates", len: coords.len(), multiple: 3 });
    }
    let n = coords.len() / 3;
    if n < 2 {
        return Err(Error::TooFew { what: "points", got: n, min: 2 });
    }
    if n > MAX_RULINGS {
        return Err(Error::TooMany { what: "points", got: n, max: MAX_RULINGS });
    }
    check_coordinates(coords, 3)?;
    // (a slice of f64 is aligned for DVec3, whose alignment is f64's, and 3n long)
    Ok(bytemuck::cast_slice(coords))
}

fn shift_index(e: Error, offset: usize) -> Error {
    match e {
        Error::NonFinite { index, value, record } => Error::NonFinite { index: index + offset, value, record },
        Error::OutOfRange { index, value, max, record } => {
            Error::OutOfRange { index: index + offset, value, max, record }
        }
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat(n: usize) -> Vec<f64> {
        (0..n).flat_map(|i| [i as f64, 0.0, 0.0, i as f64, 1.0, i as f64]).collect()
    }

    #[test]
    fn round_trips_flat_coordinates() {
        let c = flat(4);
        let s = RuledSurface::from_flat(&c).unwrap();
        assert_eq!(s.len(), 4);
        assert_eq!(s.flat(), &c[..]);
        assert_eq!(s.segment(2).b, DVec3::new(2.0, 1.0, 2.0));
        assert_eq!(RuledSurface::new(s.segments().collect()).unwrap(), s);
    }

    #[test]
    fn rejects_bad_input_with_the_reason() {
        assert!(matches!(RuledSurface::from_flat(&[0.0; 13]), Err(Error::BadLength { len: 13, multiple: 6, .. })));
        assert!(matches!(RuledSurface::from_flat(&flat(1)), Err(Error::TooFew { got: 1, min: 2, .. })));
        let mut c = flat(3);
        c[10] = f64::NAN;
        assert!(matches!(RuledSurface::from_flat(&c), Err(Error::NonFinite { index: 10, .. })));
        c[10] = f64::NEG_INFINITY;
        assert!(matches!(RuledSurface::from_flat(&c), Err(Error::NonFinite { index: 10, .. })));
        c[10] = 1e300;
        assert!(matches!(RuledSurface::from_flat(&c), Err(Error::OutOfRange { index: 10, .. })));
        let mut c = flat(3);
        c[9..12].copy_from_slice(&[1.0, 2.0, 3.0]);
        c[6..9].copy_from_slice(&[1.0, 2.0, 3.0]);
        assert_eq!(RuledSurface::from_flat(&c), Err(Error::ZeroLength { ruling: 1 }));
        // Far from the origin a length of 1e-13 relative is rounding noise.
        let mut c = flat(2);
        c[0..6].copy_from_slice(&[1e5, 0.0, 0.0, 1e5 + 1e-9, 0.0, 0.0]);
        assert_eq!(RuledSurface::from_flat(&c), Err(Error::ZeroLength { ruling: 0 }));
        // Tiny but well-resolved models are fine.
        let c: Vec<f64> = flat(3).iter().map(|x| x * 1e-100).collect();
        assert!(RuledSurface::from_flat(&c).is_ok());
    }

    #[test]
    fn map_points_revalidates() {
        let s = RuledSurface::from_flat(&flat(3)).unwrap();
        assert!(matches!(s.map_points(|_| DVec3::ZERO), Err(Error::ZeroLength { ruling: 0 })));
        assert!(matches!(s.map_points(|p| p * 1e300), Err(Error::OutOfRange { .. })));
    }

    /// Rulings from (0, i, 0) along x, of lengths 1, 2, 3, …
    fn ladder(n: usize) -> RuledSurface {
        RuledSurface::new(
            (0..n)
                .map(|i| {
                    let y = i as f64;
                    Segment::new(DVec3::new(0.0, y, 0.0), DVec3::new(y + 1.0, y, 0.0))
                })
                .collect(),
        )
        .unwrap()
    }

    #[test]
    fn from_points_counts_rulings_as_pairs_of_points() {
        let p = |x: f64| DVec3::new(x, 0.0, 1.0);
        assert!(matches!(
            RuledSurface::from_points(vec![p(0.0), p(1.0), p(2.0)]),
            Err(Error::BadLength { what: "endpoints", len: 3, multiple: 2 })
        ));
        assert!(matches!(RuledSurface::from_points(vec![p(0.0), p(1.0)]), Err(Error::TooFew { got: 1, min: 2, .. })));
        let s = RuledSurface::from_points(vec![p(0.0), p(1.0), p(2.0), p(4.0)]).unwrap();
        assert_eq!((s.len(), s.segment(1).b), (2, p(4.0)));
        assert!(!s.is_empty());
        assert!(matches!(
            RuledSurface::from_points(vec![p(0.0), p(f64::NAN), p(2.0), p(4.0)]),
            Err(Error::NonFinite { index: 3, .. })
        ));
    }

    #[test]
    fn a_short_ruling_is_kept_until_its_length_is_rounding() {
        // |b − a| = 1e-9 beside |a| = 1: short, but a thousand times above ZERO_LENGTH_REL
        let a = DVec3::new(1.0, 0.0, 0.0);
        let short = vec![a, a + DVec3::new(0.0, 1e-9, 0.0), a, a + DVec3::Z];
        assert!(RuledSurface::from_points(short).is_ok());
        let rounding = vec![a, a + DVec3::new(0.0, 1e-12, 0.0), a, a + DVec3::Z];
        assert_eq!(RuledSurface::from_points(rounding), Err(Error::ZeroLength { ruling: 0 }));
    }

    #[test]
    fn f32_coordinates_directions_and_mean_length() {
        let s = ladder(3);
        assert_eq!(
            s.flat_f32(),
            [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 2.0, 1.0, 0.0, 0.0, 2.0, 0.0, 3.0, 2.0, 0.0]
        );
        assert_eq!(s.directions(), [DVec3::X; 3]);
        // lengths 1, 2, 3
        assert_eq!(s.mean_length(), 2.0);
        assert_eq!(ladder(2).mean_length(), 1.5);
    }

    #[test]
    fn slide_moves_each_end_along_its_ruling() {
        let s = ladder(2);
        let slid = s.slide(&[0.5, -0.25, -1.0, 2.0]).unwrap();
        assert_eq!(slid.segment(0), Segment::new(DVec3::new(0.5, 0.0, 0.0), DVec3::new(0.75, 0.0, 0.0)));
        assert_eq!(slid.segment(1), Segment::new(DVec3::new(-1.0, 1.0, 0.0), DVec3::new(4.0, 1.0, 0.0)));
        // a slide that makes a ruling's ends meet is refused like any zero-length ruling
        assert_eq!(s.slide(&[0.0, -1.0, 0.0, 0.0]), Err(Error::ZeroLength { ruling: 0 }));
        let wrong = s.slide(&[0.0; 3]).unwrap_err();
        assert_eq!(wrong.code(), "invalid-argument");
        assert!(wrong.to_string().contains("need 2 numbers per ruling (4 for 2 rulings), got 3"), "{wrong}");
        assert!(s.slide(&[0.0; 5]).is_err());
        // 2 numbers per ruling, not 2 more than the rulings
        assert!(ladder(3).slide(&[0.0; 5]).is_err());
        assert_eq!(ladder(3).slide(&[0.0; 6]).unwrap(), ladder(3));
        let nan = s.slide(&[0.0, f64::NAN, 0.0, 0.0]).unwrap_err();
        assert!(nan.to_string().contains("every amount must be a finite number"), "{nan}");
    }

    #[test]
    fn angle_between_corresponding_rulings_as_unoriented_lines() {
        let s = ladder(3);
        // ruling 1 turned by 30° about z, ruling 2 reversed (the same line)
        let turned = RuledSurface::new(vec![
            s.segment(0),
            Segment::new(DVec3::new(0.0, 1.0, 0.0), DVec3::new(3f64.sqrt() / 2.0, 1.5, 0.0)),
            Segment::new(s.segment(2).b, s.segment(2).a),
        ])
        .unwrap();
        assert!((s.max_angle_to(&turned).unwrap() - std::f64::consts::FRAC_PI_6).abs() < 1e-15);
        assert_eq!(s.max_angle_to(&s).unwrap(), 0.0);
        let e = s.max_angle_to(&ladder(2)).unwrap_err();
        assert!(e.to_string().contains("needs 3 rulings, got 2"), "{e}");
        assert!(s.max_angle_to(&ladder(4)).is_err());
    }

    #[test]
    fn edge_change_of_the_boundary_polygons() {
        // a_i = (0, i, 0), b_i = (i + 1, i, 0): edges a_i a_{i+1} of length 1, b_i b_{i+1} of √2
        let s = ladder(3);
        assert_eq!(s.max_edge_change(&s).unwrap(), 0.0);
        // b_2 moved to (3, 2, 1): the edge b_1 b_2 grows from √2 to √3
        let mut p = s.points().to_vec();
        p[5].z = 1.0;
        let moved = RuledSurface::from_points(p).unwrap();
        let want = (3f64.sqrt() - 2f64.sqrt()) / 2f64.sqrt();
        assert!((s.max_edge_change(&moved).unwrap() - want).abs() < 1e-15);
        // a_1 moved to (0, 0.5, 0): a_0 a_1 shrinks to ½ and a_1 a_2 grows to 1.5
        let mut p = s.points().to_vec();
        p[2].y = 0.5;
        let moved = RuledSurface::from_points(p).unwrap();
        assert_eq!(s.max_edge_change(&moved).unwrap(), 0.5);
        assert_eq!(moved.max_edge_change(&s).unwrap(), 1.0);
        // an edge of length 0 has no relative change: skipped
        let doubled = RuledSurface::from_points(vec![DVec3::ZERO, DVec3::X, DVec3::ZERO, DVec3::Y]).unwrap();
        let other = RuledSurface::from_points(vec![DVec3::ZERO, DVec3::X, DVec3::Z, DVec3::Y * 3.0]).unwrap();
        // (a_0 a_1 of length 0 becomes 1; b_0 b_1 grows from √2 to √10)
        assert!((doubled.max_edge_change(&other).unwrap() - (5f64.sqrt() - 1.0)).abs() < 1e-15);
        assert!(s.max_edge_change(&ladder(2)).unwrap_err().to_string().contains("needs 3 rulings, got 2"));
    }

    #[test]
    fn inserted_rulings_are_those_off_the_stride() {
        let s = ladder(7);
        let ys = |stride| s.inserted(stride).iter().map(|r| r.a.y).collect::<Vec<_>>();
        assert_eq!(ys(2), [1.0, 3.0, 5.0]);
        assert_eq!(ys(4), [1.0, 2.0, 3.0, 5.0, 6.0]);
        assert_eq!(ys(1), Vec::<f64>::new());
        assert_eq!(ys(0), Vec::<f64>::new());
    }

    #[test]
    fn counts_are_checked_at_both_ends() {
        assert!(matches!(check_count(1), Err(Error::TooFew { got: 1, min: 2, .. })));
        assert!(check_count(2).is_ok());
        assert!(check_count(MAX_RULINGS).is_ok());
        assert!(matches!(check_count(MAX_RULINGS + 1), Err(Error::TooMany { max: MAX_RULINGS, .. })));
    }

    #[test]
    fn a_polygon_from_flat_coordinates() {
        assert_eq!(
            points_from_flat(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).unwrap(),
            [DVec3::new(1.0, 2.0, 3.0), DVec3::new(4.0, 5.0, 6.0)]
        );
        assert!(matches!(points_from_flat(&[0.0; 7]), Err(Error::BadLength { len: 7, multiple: 3, .. })));
        assert!(matches!(points_from_flat(&[0.0; 3]), Err(Error::TooFew { got: 1, min: 2, .. })));
        assert!(matches!(points_from_flat(&[]), Err(Error::TooFew { got: 0, .. })));
        assert!(matches!(
            points_from_flat(&[0.0, 0.0, 0.0, 0.0, f64::NAN, 0.0]),
            Err(Error::NonFinite { index: 4, .. })
        ));
        assert_eq!(points_from_flat(&vec![0.0; 3 * MAX_RULINGS]).unwrap().len(), MAX_RULINGS);
        assert!(matches!(
            points_from_flat(&vec![0.0; 3 * MAX_RULINGS + 3]),
            Err(Error::TooMany { got, max: MAX_RULINGS, .. }) if got == MAX_RULINGS + 1
        ));
    }

    #[test]
    fn a_bad_segment_is_named_by_its_index_in_the_flat_layout() {
        let mut segments: Vec<Segment> = ladder(3).segments().collect();
        segments[2].b.y = f64::NAN;
        // segment 2's b.y is number 6·2 + 4 of the flat coordinates
        assert!(matches!(RuledSurface::new(segments.clone()), Err(Error::NonFinite { index: 16, .. })));
        segments[2].b.y = 1e300;
        assert!(matches!(RuledSurface::new(segments), Err(Error::OutOfRange { index: 16, .. })));
    }
}
