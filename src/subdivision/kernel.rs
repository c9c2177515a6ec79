//! One step of the curve schemes of Section 4 on a ruled strip, in f64x2 lanes, with the new
//! surface's checks in the same pass: the four-point scheme (8)
//! p_{i+½} = (½ + w)(p_i + p_{i+1}) − w(p_{i−1} + p_{i+2}), Chaikin's corner cutting
//! ¾ p_i + ¼ p_{i+1}, ¼ p_i + ¾ p_{i+1} (Fig. 7), and Lane–Riesenfeld's uniform B-spline
//! subdivision of degree d (double every point, then average neighbours d times).
//!
//! A strip is one polygon of endpoint pairs (a_i, b_i) (Section 4: both boundary polygons with
//! the same scheme), six numbers per ruling. The schemes are affine combinations with the same
//! weights for every coordinate, so the lanes hold coordinates: a ruling is three f64x2
//! vectors (a.x, a.y), (a.z, b.x), (b.y, b.z) and needs no shuffle. The Lane–Riesenfeld step
//! streams: each level of averaging keeps its last value, so one pass computes what d passes
//! over the doubled polygon did.
//!
//! **The same numbers as the generic code** (`four_point`, `chaikin`, `bspline`): every
//! coordinate goes through the same operations in the same order, to the last bit, natively and
//! in wasm. The new surface's checks ([`RuledSurface::from_points`]: every coordinate finite and
//! at most [`MAX_COORD`], no ruling shorter than [`ZERO_LENGTH_REL`] of its endpoints' size) are
//! made on the new rulings while they are in registers, two rulings per f64x2 lane (structure of
//! arrays): the length test exactly as the validation computes it, the coordinate bound through
//! max(|a|², |b|²), which that test computes anyway, with a margin. When anything might fail,
//! the caller runs the full validation, which then reports the error exactly as before.
//!
//! [`RuledSurface::from_points`]: crate::ruled::RuledSurface::from_points

use crate::base::lanes::{F64x2, Mask2, V3x2};
use crate::subdivision::four_point::ghost;
use crate::subdivision::{bspline, four_point, Pair};
use crate::tolerance::{MAX_COORD, ZERO_LENGTH_REL};

/// A ruling as three vectors: (a.x, a.y), (a.z, b.x), (b.y, b.z).
#[derive(Clone, Copy)]
struct R3([F64x2; 3]);

impl R3 {
    #[inline(always)]
    fn load(p: &Pair) -> Self {
        let f: [f64; 6] = bytemuck::cast(*p);
        R3([F64x2::from_array([f[0], f[1]]), F64x2::from_array([f[2], f[3]]), F64x2::from_array([f[4], f[5]])])
    }
    #[inline(always)]
    fn pair(self) -> Pair {
        let [a, b, c] = self.0.map(F64x2::to_array);
        bytemuck::cast([a[0], a[1], b[0], b[1], c[0], c[1]])
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        R3([self.0[0] + o.0[0], self.0[1] + o.0[1], self.0[2] + o.0[2]])
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        R3([self.0[0] - o.0[0], self.0[1] - o.0[1], self.0[2] - o.0[2]])
    }
    /// self·w (the generic code's `p * w`).
    #[inline(always)]
    fn mul(self, w: F64x2) -> Self {
        R3([self.0[0] * w, self.0[1] * w, self.0[2] * w])
    }
}

/// Which new rulings a step checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Check {
    /// None (an intermediate step: only the last step's rulings become a surface).
    Nothing,
    /// Those the step computes; the four-point scheme's kept rulings are taken as valid (they
    /// are the input's, of a valid surface).
    New,
    /// All, the kept ones too (they came from an earlier, unchecked step).
    All,
}

/// What the checks found so far: a ruling that may be too short (or not finite), and the
/// largest squared endpoint norm.
struct Checks {
    short: Mask2,
    size: F64x2,
}

/// Below this squared endpoint norm every coordinate is within [`MAX_COORD`], rounding
/// included (a margin of 10⁻¹², far above the rounding of |a|²).
const SIZE_LIMIT: f64 = (MAX_COORD * (1.0 - 1e-12)) * (MAX_COORD * (1.0 - 1e-12));

impl Checks {
    fn new() -> Self {
        Checks { short: F64x2::splat(0.0).lt(F64x2::splat(0.0)), size: F64x2::splat(0.0) }
    }

    /// Two rulings, as the validation tests them: |b − a|² ≤ rel²·max(|a|², |b|²) is too short.
    /// A NaN or an infinity anywhere makes that test fail too (NaN compares false, ∞ ≤ ∞).
    #[inline(always)]
    fn two(&mut self, r: R3, s: R3) {
        let (u, v) = (r.0, s.0);
        let a = V3x2 {
            x: F64x2::first_lanes(u[0], v[0]),
            y: F64x2::second_lanes(u[0], v[0]),
            z: F64x2::first_lanes(u[1], v[1]),
        };
        let b = V3x2 {
            x: F64x2::second_lanes(u[1], v[1]),
            y: F64x2::first_lanes(u[2], v[2]),
            z: F64x2::second_lanes(u[2], v[2]),
        };
        let d = b.sub(a);
        let len2 = d.dot(d);
        let size = a.dot(a).max(b.dot(b));
        let long = (F64x2::splat(ZERO_LENGTH_REL * ZERO_LENGTH_REL) * size).lt(len2);
        self.short = self.short.or(long.not());
        self.size = self.size.max(size);
    }

    /// Whether every checked ruling certainly passes the validation.
    fn passed(&self) -> bool {
        !self.short.any() && self.size.to_array().iter().all(|&s| s <= SIZE_LIMIT)
    }
}

/// One step of the four-point scheme (8) with tension `w` on the strip `p`, and whether the
/// checked rulings certainly pass the validation. As [`four_point::four_point`] to the last bit.
pub fn four_point(p: &[Pair], w: f64, closed: bool, check: Check) -> (Vec<Pair>, bool) {
    let n = p.len();
    if n < 5 {
        return checked(four_point::four_point(p, w, closed), check);
    }
    let rule = |a: Pair, b: Pair, c: Pair, d: Pair| (b + c) * (0.5 + w) - (a + d) * w;
    let (cw, ww) = (F64x2::splat(0.5 + w), F64x2::splat(w));
    let vrule = |a: R3, b: R3, c: R3, d: R3| b.add(c).mul(cw).sub(a.add(d).mul(ww));
    let mut checks = Checks::new();
    let kept = check == Check::All;
    let mut out: Vec<Pair> = Vec::with_capacity(2 * n);
    // the ends: edges 0 and n − 2 (and n − 1 closed) with their ghost or wrapped neighbours
    let (before, after) =
        if closed { (p[n - 1], p[0]) } else { (ghost(p), ghost(&[p[n - 1], p[n - 2], p[n - 3], p[n - 4]])) };
    let first = rule(before, p[0], p[1], p[2]);
    out.extend_from_slice(&[p[0], first]);
    if check != Check::Nothing {
        checks.two(R3::load(&first), R3::load(if kept { &p[0] } else { &first }));
    }
    // the interior edges i = 1 … n − 3, two at a time from p_{i−1} … p_{i+3}, through an
    // iterator of known length: the loop has no capacity check and no call (a call in the loop
    // makes V8 keep the vectors on the stack), and no bounds check that could panic
    let twos = (n - 3) / 2;
    let at = |k: usize| p.get(k).copied().unwrap_or(p[0]);
    out.extend((0..twos).flat_map(|j| {
        let i = 1 + 2 * j;
        let q: [Pair; 5] = core::array::from_fn(|k| at(i - 1 + k));
        let [a, b, c, d, e] = q.map(|r| R3::load(&r));
        let (q0, q1) = (vrule(a, b, c, d), vrule(b, c, d, e));
        match check {
            Check::Nothing => {}
            Check::New => checks.two(q0, q1),
            Check::All => {
                checks.two(q0, q1);
                checks.two(b, c);
            }
        }
        [q[1], q0.pair(), q[2], q1.pair()]
    }));
    let i = 1 + 2 * twos;
    if i + 2 < n {
        // one interior edge left
        let [a, b, c, d] = [p[i - 1], p[i], p[i + 1], p[i + 2]].map(|r| R3::load(&r));
        let q = vrule(a, b, c, d);
        out.extend_from_slice(&[p[i], q.pair()]);
        if check != Check::Nothing {
            checks.two(q, if kept { b } else { q });
        }
    }
    // edge n − 2, and closed the edge n − 1 back to p_0
    let last = rule(p[n - 3], p[n - 2], p[n - 1], after);
    out.extend_from_slice(&[p[n - 2], last, p[n - 1]]);
    let mut tail = [last, if kept { p[n - 2] } else { last }, if kept { p[n - 1] } else { last }, last];
    if closed {
        let wrap = rule(p[n - 2], p[n - 1], p[0], p[1]);
        out.push(wrap);
        tail[3] = wrap;
    }
    if check != Check::Nothing {
        checks.two(R3::load(&tail[0]), R3::load(&tail[1]));
        checks.two(R3::load(&tail[2]), R3::load(&tail[3]));
    }
    (out, check == Check::Nothing || checks.passed())
}

/// One step of Chaikin's algorithm on the strip, checked (all rulings are new). As
/// [`chaikin`](crate::subdivision::chaikin::chaikin) to the last bit.
pub fn chaikin(p: &[Pair], closed: bool, check: Check) -> (Vec<Pair>, bool) {
    let n = p.len();
    let edges = if closed { n } else { n - 1 };
    let (three, one) = (F64x2::splat(0.75), F64x2::splat(0.25));
    let mut out = Vec::with_capacity(2 * edges);
    let mut checks = Checks::new();
    let mut q = R3::load(&p[0]);
    for i in 0..edges {
        let r = R3::load(&p[if i + 1 < n { i + 1 } else { 0 }]);
        // p·¾ + q·¼ and p·¼ + q·¾, as the generic code writes them
        let (u, v) = (q.mul(three).add(r.mul(one)), q.mul(one).add(r.mul(three)));
        out.extend_from_slice(&[u.pair(), v.pair()]);
        if check != Check::Nothing {
            checks.two(u, v);
        }
        q = r;
    }
    (out, check == Check::Nothing || checks.passed())
}

/// One step of degree-`degree` uniform B-spline subdivision on the strip, checked (all rulings
/// are new). As [`bspline::bspline`] to the last bit.
pub fn bspline(p: &[Pair], degree: usize, closed: bool, check: Check) -> (Vec<Pair>, bool) {
    match degree {
        1 => lane_riesenfeld::<1>(p, closed, check),
        2 => lane_riesenfeld::<2>(p, closed, check),
        3 => lane_riesenfeld::<3>(p, closed, check),
        4 => lane_riesenfeld::<4>(p, closed, check),
        5 => lane_riesenfeld::<5>(p, closed, check),
        6 => lane_riesenfeld::<6>(p, closed, check),
        7 => lane_riesenfeld::<7>(p, closed, check),
        _ => checked(bspline::bspline(p, degree, closed), check),
    }
}

/// Lane–Riesenfeld of degree D in one pass. The doubled polygon x_0 x_1 … (x_{2i} = x_{2i+1} =
/// p_i) is fed one point at a time; level l keeps L_l[j], its newest value, and a new point x
/// makes L_1 = (L_0 + x)·½, L_2 = (L_1 + L_1′)·½, …: the averages of the d passes, each with the
/// same two operands as there. Closed, the feed starts D/2 points before the end and wraps, so
/// that the points come out already turned as the generic code turns them.
fn lane_riesenfeld<const D: usize>(p: &[Pair], closed: bool, check: Check) -> (Vec<Pair>, bool) {
    let n = p.len();
    let m = 2 * n;
    let (start, feeds, outputs) = if closed { (m - D / 2, m + D, m) } else { (0, m, m - D) };
    let x = |k: usize| R3::load(&p[((start + k) % m) / 2]);
    let half = F64x2::splat(0.5);
    let mut out = Vec::with_capacity(outputs);
    let mut checks = Checks::new();
    // level[l] = the newest L_l; the first D points fill the levels
    let mut level = [x(0); D];
    for k in 1..D {
        let mut new = x(k);
        for l in 0..k {
            let avg = level[l].add(new).mul(half);
            level[l] = new;
            new = avg;
        }
        level[k] = new;
    }
    let mut pending: Option<R3> = None;
    for k in D..feeds {
        let mut new = x(k);
        for slot in level.iter_mut() {
            let avg = slot.add(new).mul(half);
            *slot = new;
            new = avg;
        }
        out.push(new.pair());
        if check != Check::Nothing {
            match pending.take() {
                Some(prev) => checks.two(prev, new),
                None => pending = Some(new),
            }
        }
    }
    if let Some(last) = pending {
        checks.two(last, last);
    }
    debug_assert_eq!(out.len(), outputs);
    (out, check == Check::Nothing || checks.passed())
}

/// A step computed by the generic code, checked ruling by ruling (small polygons).
fn checked(out: Vec<Pair>, check: Check) -> (Vec<Pair>, bool) {
    if check == Check::Nothing {
        return (out, true);
    }
    let mut checks = Checks::new();
    for r in &out {
        checks.two(R3::load(r), R3::load(r));
    }
    let passed = checks.passed();
    (out, passed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ruled::RuledSurface;
    use glam::DVec3;

    /// The kernels on six parallel rulings a_i = (x, 0, i), b_i = a_i + (0, ℓ·(i + 1), 0), one
    /// step each (the four-point scheme's kernel takes five rulings or more): whether each one's
    /// checks pass, and whether the validation accepts the same rulings.
    fn checks(x: f64, length: f64) -> [(bool, bool); 3] {
        let strip: Vec<Pair> = (0..6)
            .map(|i| {
                let a = DVec3::new(x, 0.0, i as f64);
                Pair(a, a + DVec3::new(0.0, length * (i + 1) as f64, 0.0))
            })
            .collect();
        [
            chaikin(&strip, false, Check::New),
            four_point(&strip, 0.0625, false, Check::New),
            bspline(&strip, 3, false, Check::New),
        ]
        .map(|(out, passed)| {
            let valid = RuledSurface::from_points(out.iter().flat_map(|p| [p.0, p.1]).collect()).is_ok();
            (passed, valid)
        })
    }

    /// The length test is the validation's: rulings 10⁻⁹ long beside |a| = 1 are short but
    /// certainly valid (the limit is 10⁻¹² of |a|), and pass without the full validation.
    #[test]
    fn short_rulings_the_validation_accepts_pass_the_checks() {
        assert_eq!(checks(1.0, 1e-9), [(true, true); 3]);
        assert_eq!(checks(1.0, 1.0), [(true, true); 3]);
        // 10⁻¹³ of |a|: too short for the validation, so the checks must not pass
        assert_eq!(checks(1.0, 1e-13), [(false, false); 3]);
    }

    /// The size test: |a|² below MAX_COORD²·(1 − 10⁻¹²)² passes; within that margin of
    /// MAX_COORD (where rounding of |a|² could hide a coordinate above it) the full validation
    /// decides, and it accepts these rulings.
    #[test]
    fn coordinates_near_the_limit_are_left_to_the_validation() {
        // a ruling 10⁻¹⁰ of |a| long: long enough at every size here
        let length = |x: f64| x * 1e-10;
        let far = MAX_COORD * (1.0 - 1e-11);
        assert_eq!(checks(far, length(far)), [(true, true); 3]);
        let near = MAX_COORD * (1.0 - 7.5e-13);
        assert_eq!(checks(near, length(near)), [(false, true); 3]);
        assert_eq!(checks(MAX_COORD, length(MAX_COORD)), [(false, true); 3]);
    }
}
