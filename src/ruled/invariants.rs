//! Discrete invariants of a sequence of lines (Section 2, Fig. 1, Propositions 1 and 2).
//!
//! For consecutive rulings R_i = (a_i, e_i) and R_{i+1} = (a_{i+1}, e_{i+1}), with
//! d = a_{i+1} − a_i and c = e_i × e_{i+1} (the conventions of docs/src/conventions.md, Section 2):
//!
//! - angle φ_{i,i+1} = atan2(|c|, e_i·e_{i+1}) ∈ [0, π];
//! - signed distance h_{i,i+1} = det(d, e_i, e_{i+1}) / |c| = (d·c)/|c|;
//! - central normal n_{i,i+1} = c/|c|, the direction of the common perpendicular N_{i,i+1};
//!   it converges to the central tangent direction e₃ (4);
//! - footpoints f_{i,i+1} = a_i + t e_i ∈ R_i and f_{i+1,i} = a_{i+1} + s e_{i+1} ∈ R_{i+1},
//!   t = ((d × e_{i+1})·c)/|c|², s = ((d × e_i)·c)/|c|²; they converge to the striction
//!   point at first order (3);
//! - discrete distribution parameter δ_{i,i+1} = h_{i,i+1}/φ_{i,i+1} (1), first order (2);
//! - striction polygon m_i = (f_{i,i−1} + f_{i,i+1})/2 and averaged distribution parameter
//!   (δ_{i−1,i} + δ_{i,i+1})/2 for interior rulings: second order (7), Proposition 2;
//! - Example 1's polygon (f_{i,i+1} + f_{i+1,i})/2, the midpoints of the common
//!   perpendiculars, which approximate s at the parameter midpoint, also at second order.
//!
//! **Parallel pairs.** When |sin φ| < [`PARALLEL_SIN`] (parallel, antiparallel or
//! coincident rulings) the common perpendicular is not unique. Then `parallel` is set, the
//! angle is still returned (≈ 0 or ≈ π), `distance` is the unsigned distance of the two
//! lines, and the distribution parameter, footpoints, normal and every striction quantity
//! that uses them are NaN: never a number that looks valid but is not. Intersecting
//! rulings (h = 0) are not degenerate.

use crate::line::Line;
use crate::ruled::kernel::{self, Rulings};
use crate::tolerance::PARALLEL_SIN;
use bytemuck::Zeroable;
use glam::DVec3;

/// The invariants of one pair of consecutive rulings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairInvariants {
    /// φ_{i,i+1} ∈ [0, π].
    pub angle: f64,
    /// Signed distance h_{i,i+1}; unsigned distance of the lines when parallel.
    pub distance: f64,
    /// n_{i,i+1} = (e_i × e_{i+1})/|e_i × e_{i+1}|; `None` when parallel.
    pub normal: Option<DVec3>,
    /// Footpoints (f_{i,i+1} ∈ R_i, f_{i+1,i} ∈ R_{i+1}); `None` when parallel.
    pub feet: Option<(DVec3, DVec3)>,
}

impl PairInvariants {
    /// The invariants of the lines `r0`, `r1` (unit directions).
    pub fn of(r0: &Line, r1: &Line) -> Self {
        let d = r1.point - r0.point;
        let c = r0.dir.cross(r1.dir);
        let sin = c.length();
        let angle = sin.atan2(r0.dir.dot(r1.dir));
        if sin < PARALLEL_SIN {
            return PairInvariants {
                angle,
                distance: d.reject_from_normalized(r0.dir).length(),
                normal: None,
                feet: None,
            };
        }
        let sin2 = sin * sin;
        let t = d.cross(r1.dir).dot(c) / sin2;
        let s = d.cross(r0.dir).dot(c) / sin2;
        PairInvariants {
            angle,
            distance: d.dot(c) / sin,
            normal: Some(c / sin),
            feet: Some((r0.point + t * r0.dir, r1.point + s * r1.dir)),
        }
    }

    /// Whether the pair counts as parallel (no unique common perpendicular).
    pub fn is_parallel(&self) -> bool {
        self.normal.is_none()
    }

    /// δ_{i,i+1} = h_{i,i+1}/φ_{i,i+1} (1); NaN for a parallel pair.
    pub fn distribution(&self) -> f64 {
        if self.is_parallel() {
            f64::NAN
        } else {
            self.distance / self.angle
        }
    }
}

/// The invariants of a whole discrete ruled surface R_0 … R_{N−1}, as flat arrays
/// (N − 1 pairs, N − 2 interior rulings). Points and vectors are `DVec3`s, which glam lays
/// out as three consecutive `f64`, so [`Invariants::flat`] views them without copying.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Invariants {
    /// φ_{i,i+1}, N − 1 values.
    pub angle: Vec<f64>,
    /// h_{i,i+1}, N − 1 values.
    pub distance: Vec<f64>,
    /// δ_{i,i+1} (1), N − 1 values.
    pub distribution: Vec<f64>,
    /// f_{i,i+1} then f_{i+1,i} for each pair: 2(N − 1) points.
    pub footpoints: Vec<DVec3>,
    /// n_{i,i+1}, N − 1 unit vectors.
    pub central_normal: Vec<DVec3>,
    /// Whether pair (i, i+1) is parallel, N − 1 flags.
    pub parallel: Vec<bool>,
    /// m_i = (f_{i,i−1} + f_{i,i+1})/2 for i = 1 … N − 2 (7).
    pub striction: Vec<DVec3>,
    /// (δ_{i−1,i} + δ_{i,i+1})/2 for i = 1 … N − 2 (7).
    pub distribution_mean: Vec<f64>,
    /// (f_{i,i+1} + f_{i+1,i})/2, N − 1 points: Example 1's polygon.
    pub perpendicular_midpoints: Vec<DVec3>,
}

const NAN3: DVec3 = DVec3::splat(f64::NAN);

/// One block of [`Invariants::by_blocks`].
#[derive(Debug)]
pub struct InvariantsBlock<'a> {
    /// Where the block's pairs begin in the whole surface's pair arrays (`angle`, `distance`,
    /// `distribution`, `central_normal`, `parallel`, `perpendicular_midpoints`; twice this in
    /// `footpoints`).
    pub pairs_from: usize,
    /// Where the block's striction quantities begin in the whole surface's `striction` and
    /// `distribution_mean`.
    pub interior_from: usize,
    /// The block's invariants (arrays of the block's size).
    pub inv: &'a Invariants,
}

impl Invariants {
    /// Computes every invariant in one pass over the lines (O(N), one allocation per array).
    pub fn of(lines: &[Line]) -> Self {
        Self::from_lines(lines.iter().copied())
    }

    /// As [`Invariants::of`], streaming: no intermediate array of lines is allocated, which
    /// matters at 10⁶ rulings, where first-touch of fresh memory dominates the run time.
    pub fn from_lines(lines: impl ExactSizeIterator<Item = Line>) -> Self {
        let mut inv = Invariants {
            angle: Vec::new(),
            distance: Vec::new(),
            distribution: Vec::new(),
            footpoints: Vec::new(),
            central_normal: Vec::new(),
            parallel: Vec::new(),
            striction: Vec::new(),
            distribution_mean: Vec::new(),
            perpendicular_midpoints: Vec::new(),
        };
        inv.compute_from(lines);
        inv
    }

    /// As [`Invariants::from_lines`], into these arrays: their memory is reused (nothing is
    /// allocated once they are large enough), which is what a zero-copy caller needs — the
    /// results stay where they were, at the same addresses, call after call.
    pub fn compute_from(&mut self, mut lines: impl ExactSizeIterator<Item = Line>) {
        let pairs = lines.len().saturating_sub(1);
        let interior = lines.len().saturating_sub(2);
        let inv = self;
        macro_rules! reset {
            ($($v:ident: $n:expr),*) => {$( inv.$v.clear(); inv.$v.reserve($n); )*};
        }
        reset!(angle: pairs, distance: pairs, distribution: pairs, footpoints: 2 * pairs, central_normal: pairs,
            parallel: pairs, striction: interior, distribution_mean: interior, perpendicular_midpoints: pairs);
        let Some(mut prev) = lines.next() else { return };
        for (i, line) in lines.enumerate() {
            let p = PairInvariants::of(&prev, &line);
            prev = line;
            let (f0, f1) = p.feet.unwrap_or((NAN3, NAN3));
            let delta = p.distribution();
            if i > 0 {
                // f_{i,i−1} is the foot on R_i of the previous pair, stored last.
                let f_prev = inv.footpoints[2 * i - 1];
                inv.striction.push(0.5 * (f_prev + f0));
                inv.distribution_mean.push(0.5 * (inv.distribution[i - 1] + delta));
            }
            inv.angle.push(p.angle);
            inv.distance.push(p.distance);
            inv.distribution.push(delta);
            inv.footpoints.push(f0);
            inv.footpoints.push(f1);
            inv.central_normal.push(p.normal.unwrap_or(NAN3));
            inv.parallel.push(p.is_parallel());
            inv.perpendicular_midpoints.push(0.5 * (f0 + f1));
        }
    }

    /// The invariants of a *closed* discrete ruled surface, whose last ruling R_{N−1} is followed
    /// by R_0 again (a sampled closed surface: the hyperboloid, a cone, Plücker's conoid): N
    /// pairs (the last one is (R_{N−1}, R_0)) and N interior rulings, so `striction[i]` and
    /// `distribution_mean[i]` belong to ruling i itself, and the striction polygon closes.
    pub fn from_lines_closed(lines: &[Line]) -> Self {
        let mut inv = Self::from_lines(std::iter::empty());
        inv.compute_from_closed(lines);
        inv
    }

    /// As [`Invariants::from_lines_closed`], into these arrays (see [`Invariants::compute_from`]).
    pub fn compute_from_closed(&mut self, lines: &[Line]) {
        let n = lines.len();
        self.compute_from(lines.iter().chain(lines.first()).copied().collect::<Vec<_>>().into_iter());
        let inv = self;
        if n < 2 {
            return;
        }
        // m_0 = (f_{0,N−1} + f_{0,1})/2: f_{0,N−1} is the foot on R_0 of the last pair.
        let f_last = inv.footpoints[2 * n - 1];
        inv.striction.insert(0, 0.5 * (f_last + inv.footpoints[0]));
        inv.distribution_mean.insert(0, 0.5 * (inv.distribution[n - 1] + inv.distribution[0]));
    }

    /// The invariants of the rulings a_i → b_i given by their endpoints a_0, b_0, a_1, b_1, …
    /// (N ≥ 2 segments of nonzero length, as a [`RuledSurface`](super::RuledSurface) holds them),
    /// open or closed, by the f64x2 kernel (`ruled/kernel.rs`), into these arrays: their memory
    /// is reused when they have the size already (as [`Invariants::compute_from`]). The numbers
    /// are those of [`Invariants::from_lines`] of the segments' lines bit for bit, except φ
    /// (within 1 ulp of `f64::atan2`) and δ, (δ_{i−1,i} + δ_{i,i+1})/2, which divide by it.
    pub fn compute_from_points(&mut self, points: &[DVec3], closed: bool) {
        let seq = Rulings::new(bytemuck::cast_slice(points), closed);
        let pairs = seq.pairs();
        // closed: R_0's striction quantities come first, from the last pair
        self.compute_range(&seq, 0, pairs, closed as usize);
        if closed {
            let inv = self;
            let (m, mean) = kernel::closing(
                inv.footpoints[0].into(),
                inv.footpoints[2 * pairs - 1].into(),
                inv.distribution[0],
                inv.distribution[pairs - 1],
            );
            inv.striction[0] = m.into();
            inv.distribution_mean[0] = mean;
        }
    }

    /// As [`Invariants::compute_from_points`], a block of at most `block` pairs at a time
    /// (`block` ≥ 2), computed into `scratch` (whose arrays are reused, as by
    /// [`Invariants::compute_from`]): `f` gets each block's invariants in arrays of the block's
    /// size, which a caller copies where they belong (the wasm bindings straight into
    /// JavaScript's arrays, so that the whole result never sits in wasm memory). A block computed
    /// alone gives the same numbers as the whole surface at once.
    pub fn by_blocks(
        points: &[DVec3],
        closed: bool,
        block: usize,
        scratch: &mut Invariants,
        mut f: impl FnMut(&InvariantsBlock<'_>),
    ) {
        let seq = Rulings::new(bytemuck::cast_slice(points), closed);
        let pairs = seq.pairs();
        let block = block.max(2);
        let (mut first, mut last) = ((DVec3::ZERO, 0.0), (DVec3::ZERO, 0.0));
        let mut start = 0;
        while start < pairs {
            let end = (start + block).min(pairs);
            scratch.compute_range(&seq, start, end, 0);
            if start == 0 {
                first = (scratch.footpoints[0], scratch.distribution[0]);
            }
            if end == pairs {
                last = (scratch.footpoints[2 * (end - start) - 1], scratch.distribution[end - start - 1]);
            }
            f(&InvariantsBlock { pairs_from: start, interior_from: start.max(1) - 1 + closed as usize, inv: scratch });
            start = end;
        }
        if closed {
            let (m, mean) = kernel::closing(first.0.into(), last.0.into(), first.1, last.1);
            scratch.compute_range(&seq, pairs, pairs, 0);
            scratch.striction.push(m.into());
            scratch.distribution_mean.push(mean);
            f(&InvariantsBlock { pairs_from: pairs, interior_from: 0, inv: scratch });
        }
    }

    /// The kernel on pairs start … end − 1 into these arrays, sized for them: the striction
    /// quantities of rulings max(start, 1) … end − 1 after `skip` entries left for the caller.
    fn compute_range(&mut self, seq: &Rulings<'_>, start: usize, end: usize, skip: usize) {
        let (pairs, interior) = (end - start, end.saturating_sub(start.max(1)) + skip);
        let inv = self;
        sized(&mut inv.angle, pairs);
        sized(&mut inv.distance, pairs);
        sized(&mut inv.distribution, pairs);
        sized(&mut inv.footpoints, 2 * pairs);
        sized(&mut inv.central_normal, pairs);
        sized(&mut inv.parallel, pairs);
        sized(&mut inv.striction, interior);
        sized(&mut inv.distribution_mean, interior);
        sized(&mut inv.perpendicular_midpoints, pairs);
        kernel::pairs(
            seq,
            start,
            end,
            &mut kernel::Out {
                angle: &mut inv.angle,
                distance: &mut inv.distance,
                distribution: &mut inv.distribution,
                footpoints: bytemuck::cast_slice_mut(&mut inv.footpoints),
                normal: bytemuck::cast_slice_mut(&mut inv.central_normal),
                parallel: &mut inv.parallel,
                striction: bytemuck::cast_slice_mut(&mut inv.striction[skip..]),
                mean: &mut inv.distribution_mean[skip..],
                midpoints: bytemuck::cast_slice_mut(&mut inv.perpendicular_midpoints),
            },
        );
    }

    /// A `DVec3` slice as its flat `f64` coordinates, without copying.
    pub fn flat(points: &[DVec3]) -> &[f64] {
        bytemuck::cast_slice(points)
    }
}

/// `v` with `n` elements, whose numbers the caller overwrites: shortened, or lengthened in its
/// own memory when it is large enough (only the new elements are written), else fresh zeroed
/// memory (which the system hands out without writing it).
fn sized<T: Zeroable + Clone>(v: &mut Vec<T>, n: usize) {
    if v.len() >= n {
        v.truncate(n);
    } else if v.capacity() >= n {
        v.resize(n, T::zeroed());
    } else {
        *v = bytemuck::zeroed_vec(n);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::tolerance::test::EXACT;
    use std::f64::consts::FRAC_PI_2;

    fn line(p: [f64; 3], d: [f64; 3]) -> Line {
        Line { point: DVec3::from(p), dir: DVec3::from(d).normalize() }
    }

    /// Closed: the rulings of a regulus of a hyperboloid of revolution, equally spaced around
    /// it, all have their striction point on the gorge circle; the closed invariants give one
    /// per ruling, and the same numbers as the open invariants of the wrapped sequence.
    #[test]
    fn closed_surfaces_get_a_striction_point_per_ruling() {
        let n = 12;
        let lines: Vec<Line> = (0..n)
            .map(|i| {
                let u = std::f64::consts::TAU * i as f64 / n as f64;
                let (s, c) = u.sin_cos();
                line([c, s, 0.0], [-s, c, 1.0])
            })
            .collect();
        let closed = Invariants::from_lines_closed(&lines);
        assert_eq!((closed.angle.len(), closed.striction.len(), closed.distribution_mean.len()), (n, n, n));
        let wrapped: Vec<Line> = [lines[n - 1]].into_iter().chain(lines.iter().copied()).chain([lines[0]]).collect();
        let open = Invariants::from_lines(wrapped.into_iter());
        for i in 0..n {
            assert_near!(closed.striction[i], open.striction[i], EXACT);
            assert_near!(closed.distribution_mean[i], open.distribution_mean[i], EXACT);
            // the gorge circle z = 0, radius 1, at the ruling's own point (by symmetry)
            assert_near!(closed.striction[i], lines[i].point, 1e-12);
        }
    }

    /// The in-place path gives the same numbers as a fresh computation, and once its arrays
    /// are large enough it keeps them where they are (the zero-copy views rely on that).
    #[test]
    fn computing_into_reuses_the_arrays() {
        let lines = |n: usize, twist: f64| -> Vec<Line> {
            (0..n)
                .map(|i| line([i as f64 * 0.1, 0.0, 0.0], [0.0, (twist * i as f64).cos(), (twist * i as f64).sin()]))
                .collect()
        };
        let mut inv = Invariants::from_lines(lines(50, 0.2).into_iter());
        let (angle, feet) = (inv.angle.as_ptr(), inv.footpoints.as_ptr());
        for (n, twist) in [(50, 0.3), (20, 0.1), (50, 0.25)] {
            inv.compute_from(lines(n, twist).into_iter());
            assert_eq!(inv, Invariants::from_lines(lines(n, twist).into_iter()));
            assert_eq!((inv.angle.as_ptr(), inv.footpoints.as_ptr()), (angle, feet));
        }
        inv.compute_from_closed(&lines(12, 0.4));
        assert_eq!(inv, Invariants::from_lines_closed(&lines(12, 0.4)));
    }

    /// The kernel's path keeps its arrays where they are too, once they are large enough (the
    /// zero-copy `InvariantsBuffer` relies on it), and a smaller surface in between does not move
    /// them.
    #[test]
    fn computing_from_points_reuses_the_arrays() {
        let points = |n: usize, twist: f64| -> Vec<DVec3> {
            (0..n)
                .flat_map(|i| {
                    let (s, c) = (twist * i as f64).sin_cos();
                    [DVec3::new(i as f64 * 0.1, 0.0, 0.0), DVec3::new(i as f64 * 0.1, c, s)]
                })
                .collect()
        };
        let mut inv = Invariants::default();
        inv.compute_from_points(&points(50, 0.2), true);
        let (angle, feet, striction) = (inv.angle.as_ptr(), inv.footpoints.as_ptr(), inv.striction.as_ptr());
        for (n, twist, closed) in [(50, 0.3, false), (20, 0.1, true), (50, 0.25, true), (49, 0.2, false)] {
            inv.compute_from_points(&points(n, twist), closed);
            let mut fresh = Invariants::default();
            fresh.compute_from_points(&points(n, twist), closed);
            assert_eq!(format!("{inv:?}"), format!("{fresh:?}"));
            assert_eq!((inv.angle.as_ptr(), inv.footpoints.as_ptr(), inv.striction.as_ptr()), (angle, feet, striction));
        }
    }

    #[test]
    fn perpendicular_skew_lines() {
        // R0 = x-axis, R1 = the line through (0, 0, 2) along y: h = 2, φ = π/2.
        let r0 = line([5.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        let r1 = line([0.0, -3.0, 2.0], [0.0, 1.0, 0.0]);
        let p = PairInvariants::of(&r0, &r1);
        assert_near!(p.angle, FRAC_PI_2, EXACT);
        assert_near!(p.distance, 2.0, EXACT);
        assert_near!(p.distribution(), 2.0 / FRAC_PI_2, EXACT);
        assert_eq!(p.normal, Some(DVec3::Z));
        let (f0, f1) = p.feet.unwrap();
        assert_near!(f0, DVec3::ZERO, EXACT);
        assert_near!(f1, DVec3::new(0.0, 0.0, 2.0), EXACT);
    }

    #[test]
    fn sign_of_h_follows_the_orientation_convention() {
        // h = det(d, e0, e1)/|e0 × e1| changes sign with e1 and with the order of the lines.
        let r0 = line([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        let r1 = line([0.0, 0.0, 2.0], [0.0, 1.0, 0.0]);
        let r1_flipped = line([0.0, 0.0, 2.0], [0.0, -1.0, 0.0]);
        assert_near!(PairInvariants::of(&r0, &r1).distance, 2.0, EXACT);
        assert_near!(PairInvariants::of(&r0, &r1_flipped).distance, -2.0, EXACT);
        assert_near!(PairInvariants::of(&r1, &r0).distance, 2.0, EXACT);
    }

    #[test]
    fn intersecting_lines_have_zero_distance_and_meet_at_the_feet() {
        let r0 = line([1.0, 1.0, 1.0], [1.0, 2.0, 0.5]);
        let r1 = line([1.0, 1.0, 1.0], [-1.0, 0.3, 2.0]);
        let p = PairInvariants::of(&r0, &r1);
        assert_near!(p.distance, 0.0, EXACT);
        assert_eq!(p.distribution(), 0.0);
        let (f0, f1) = p.feet.unwrap();
        assert_near!(f0, DVec3::ONE, EXACT);
        assert_near!(f1, DVec3::ONE, EXACT);
    }

    #[test]
    fn parallel_antiparallel_and_coincident_pairs_are_flagged() {
        let r0 = line([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
        let cases = [
            (line([3.0, 4.0, 7.0], [0.0, 0.0, 1.0]), 0.0, 5.0),
            (line([3.0, 4.0, 7.0], [0.0, 0.0, -1.0]), std::f64::consts::PI, 5.0),
            (line([0.0, 0.0, 9.0], [0.0, 0.0, 1.0]), 0.0, 0.0),
            // sin φ = 1e-12: below the threshold
            (line([1.0, 0.0, 0.0], [1e-12, 0.0, 1.0]), 1e-12, 1.0),
        ];
        for (r1, angle, dist) in cases {
            let p = PairInvariants::of(&r0, &r1);
            assert!(p.is_parallel());
            assert_near!(p.angle, angle, EXACT);
            assert_near!(p.distance, dist, EXACT);
            assert!(p.distribution().is_nan());
            assert!(p.feet.is_none() && p.normal.is_none());
        }
    }

    #[test]
    fn nearly_parallel_skew_lines_just_above_the_threshold_are_accurate() {
        // Lines x = 0 and x = 1 along z, the second tilted by angle 1e-6 about the x-axis
        // through (1, 0, 0): the common perpendicular is the x-axis segment [0, 1].
        let eps = 1e-6_f64;
        let r0 = line([0.0, 0.0, 5.0], [0.0, 0.0, 1.0]);
        let r1 = line([1.0, eps.sin() * 5.0, eps.cos() * 5.0], [0.0, eps.sin(), eps.cos()]);
        let p = PairInvariants::of(&r0, &r1);
        assert!(!p.is_parallel());
        let (f0, f1) = p.feet.unwrap();
        assert_near!(f0, DVec3::ZERO, 1e-8);
        assert_near!(f1, DVec3::X, 1e-8);
        assert_near!(p.distance.abs(), 1.0, 1e-9);
    }

    #[test]
    fn striction_polygon_averages_the_two_feet_on_each_ruling() {
        let lines = [
            line([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
            line([0.0, 0.0, 1.0], [1.0, 1.0, 0.0]),
            line([0.0, 0.0, 2.0], [0.0, 1.0, 0.0]),
        ];
        let inv = Invariants::of(&lines);
        assert_eq!(inv.angle.len(), 2);
        assert_eq!(inv.footpoints.len(), 4);
        assert_eq!(inv.striction.len(), 1);
        // Every pair meets the z-axis orthogonally: all feet lie on it.
        assert_near!(inv.footpoints[1], DVec3::new(0.0, 0.0, 1.0), EXACT);
        assert_near!(inv.footpoints[2], DVec3::new(0.0, 0.0, 1.0), EXACT);
        assert_near!(inv.striction[0], DVec3::new(0.0, 0.0, 1.0), EXACT);
        assert_near!(inv.distribution_mean[0], 1.0 / std::f64::consts::FRAC_PI_4, EXACT);
        assert_near!(inv.perpendicular_midpoints[0], DVec3::new(0.0, 0.0, 0.5), EXACT);
        assert_eq!(Invariants::flat(&inv.striction), &[0.0, 0.0, 1.0][..]);
    }

    #[test]
    fn a_parallel_pair_poisons_only_its_neighbours() {
        let lines = [
            line([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
            line([0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
            line([0.0, 1.0, 1.0], [0.0, 1.0, 0.0]),
            line([0.0, 1.0, 2.0], [1.0, 0.0, 0.0]),
            line([0.0, 1.0, 3.0], [0.0, 1.0, 0.0]),
        ];
        let inv = Invariants::of(&lines);
        assert_eq!(inv.parallel, [false, true, false, false]);
        assert!(inv.striction[0].is_nan() && inv.striction[1].is_nan());
        assert!(inv.striction[2].is_finite());
        assert!(inv.distribution_mean[1].is_nan() && inv.distribution_mean[2].is_finite());
    }
}
