//! A discrete ruled surface: a validated sequence of rulings R_0 … R_{N−1}, N ≥ 2
//! (Section 2). Every constructor checks its input, so the algorithms that take a
//! `RuledSurface` never meet NaN, infinities or zero-length rulings.

use crate::error::{Error, Record, Result};
use crate::line::{Line, Segment};
use crate::ruled::invariants::Invariants;
use crate::tolerance::{MAX_COORD, MAX_RULINGS, ZERO_LENGTH_REL};
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
        for (i, ab) in points.chunks_exact(2).enumerate() {
            let len = (ab[1] - ab[0]).length();
            if len <= ZERO_LENGTH_REL * ab[0].length().max(ab[1].length()) {
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

    /// All discrete invariants of Section 2.
    pub fn invariants(&self) -> Invariants {
        Invariants::from_lines(self.lines())
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

/// Every coordinate finite and at most [`MAX_COORD`] in magnitude (`stride` numbers per
/// record, for the messages).
pub fn check_coordinates(coords: &[f64], stride: usize) -> Result<()> {
    for (index, &value) in coords.iter().enumerate() {
        if !value.is_finite() {
            return Err(Error::NonFinite { index, value, record: Record::of_stride(stride) });
        }
        if value.abs() > MAX_COORD {
            return Err(Error::OutOfRange { index, value, max: MAX_COORD, record: Record::of_stride(stride) });
        }
    }
    Ok(())
}

/// A polygon from flat coordinates, 3 per point: at least 2 and at most [`MAX_RULINGS`]
/// points, every coordinate finite and at most [`MAX_COORD`] in magnitude.
pub fn points_from_flat(coords: &[f64]) -> Result<Vec<DVec3>> {
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
    Ok(coords.chunks_exact(3).map(DVec3::from_slice).collect())
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
}
