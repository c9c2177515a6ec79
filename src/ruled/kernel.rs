//! Section 2's invariants (Fig. 1, (1)–(7), Propositions 1 and 2) in f64x2 lanes: two pairs of
//! consecutive rulings at a time, structure of arrays inside the kernel.
//!
//! Each step loads the endpoints of two rulings R_{k+1}, R_{k+2} (twelve numbers, six vector
//! loads), turns them into coordinates by lanes (x = (x_{k+1}, x_{k+2}), …: six shuffles),
//! normalises both directions at once, and takes R_k, R_{k+1} from the step before (one shuffle
//! per coordinate: the window moves by two). The formulas are those of
//! [`PairInvariants::of`](super::PairInvariants::of) and docs/src/conventions.md, with d = a_{k+1} − a_k and
//! c = e_k × e_{k+1}:
//!
//! - φ = atan2(|c|, e_k·e_{k+1}) ∈ [0, π], by [`atan2_fast`] (no library call; should a lane
//!   ever fall outside its domain, the range is computed again with [`atan2_upper`]);
//! - h = (d·c)/|c| and δ = h/φ (1); n = c/|c|;
//! - f_{k,k+1} = a_k + t e_k, f_{k+1,k} = a_{k+1} + s e_{k+1} with t = ((d × e_{k+1})·c)/|c|²,
//!   s = ((d × e_k)·c)/|c|² (3);
//! - m_k = (f_{k,k−1} + f_{k,k+1})/2 and (δ_{k−1,k} + δ_{k,k+1})/2 (7), from the previous step's
//!   second lane; Example 1's (f_{k,k+1} + f_{k+1,k})/2;
//! - a parallel pair (|c| < [`PARALLEL_SIN`]): h is the distance of the lines
//!   |d − (d·e_k) e_k|, and δ, n, the footpoints and what uses them are NaN.
//!
//! **The same numbers as the scalar path.** Every operation is the scalar code's, in its order
//! (glam's dot and cross products, `normalize` as v·(1/|v|)), with no fused multiply-add, so
//! h, n, the footpoints, the striction polygon, Example 1's polygon and the parallel flags are
//! bit for bit those of [`Invariants::of`](super::Invariants::of); φ is within 1 ulp of
//! `f64::atan2`, so δ = h/φ and (δ_{k−1,k} + δ_{k,k+1})/2 are within a few ulp
//! (`tests/kernels.rs` states and checks the bounds). Natively and in wasm the kernel computes
//! the same bits.
//!
//! The kernel fills slices for a range of pairs, so a caller may compute a long surface block by
//! block (the wasm bindings fill JavaScript's arrays that way without a copy of the whole
//! result in wasm memory); the first step of a block recomputes the pair before it.

use crate::base::angle::{atan2_fast, atan2_upper};
use crate::base::lanes::{F64x2, Mask2, V3x2};
use crate::tolerance::PARALLEL_SIN;

/// The rulings R_0 … R_{N−1} as 6 numbers each (a then b); closed, R_N is R_0 again.
#[derive(Clone, Copy, Debug)]
pub struct Rulings<'a> {
    flat: &'a [f64],
    closed: bool,
}

impl<'a> Rulings<'a> {
    /// The rulings of flat coordinates (6 per ruling, at least 2 rulings, each of nonzero length).
    pub fn new(flat: &'a [f64], closed: bool) -> Self {
        debug_assert!(flat.len() % 6 == 0 && flat.len() >= 12);
        Rulings { flat, closed }
    }

    /// N.
    pub fn len(&self) -> usize {
        self.flat.len() / 6
    }

    /// Pairs (R_k, R_{k+1}): N − 1, or N when closed.
    pub fn pairs(&self) -> usize {
        if self.closed {
            self.len()
        } else {
            self.len() - 1
        }
    }

    /// Ruling r (R_N is R_0; beyond it, the last ruling again: a lane nobody stores).
    fn ruling(&self, r: usize) -> [f64; 6] {
        let n = self.len();
        let r = if r == n && self.closed { 0 } else { r.min(n - 1) };
        self.flat[6 * r..6 * r + 6].try_into().expect("six numbers")
    }
}

/// Where [`pairs`] writes the invariants of pairs start … end − 1 (lengths: `end − start`
/// values per pair quantity, times 6 or 3 for points and vectors), and the striction
/// quantities of the rulings max(start, 1) … end − 1.
#[derive(Debug)]
pub struct Out<'a> {
    /// φ.
    pub angle: &'a mut [f64],
    /// h.
    pub distance: &'a mut [f64],
    /// δ (1).
    pub distribution: &'a mut [f64],
    /// f_{k,k+1} then f_{k+1,k}, 6 numbers per pair.
    pub footpoints: &'a mut [f64],
    /// n, 3 numbers per pair.
    pub normal: &'a mut [f64],
    /// Whether the pair is parallel.
    pub parallel: &'a mut [bool],
    /// m_k (7), 3 numbers per ruling.
    pub striction: &'a mut [f64],
    /// (δ_{k−1,k} + δ_{k,k+1})/2 (7).
    pub mean: &'a mut [f64],
    /// (f_{k,k+1} + f_{k+1,k})/2, 3 numbers per pair.
    pub midpoints: &'a mut [f64],
}

/// Ruling k in lane 1 (position and unit direction) and pair k − 1's f_{k,k−1} and δ in lane 1:
/// what the next step needs of the one before.
#[derive(Clone, Copy)]
struct Window {
    a: V3x2,
    e: V3x2,
    f1: V3x2,
    delta: F64x2,
}

/// Everything a step computes for pairs k, k + 1 (lanes 0, 1).
struct Step {
    angle: F64x2,
    distance: F64x2,
    delta: F64x2,
    f0: V3x2,
    f1: V3x2,
    normal: V3x2,
    parallel: Mask2,
    midpoint: V3x2,
    /// m of rulings k, k + 1.
    striction: V3x2,
    /// (δ_{k−1,k} + δ_{k,k+1})/2 of rulings k, k + 1.
    mean: F64x2,
}

/// Two rulings from six vectors of two numbers (R: (a.x, a.y), (a.z, b.x), (b.y, b.z); R′
/// likewise): their points a and unit directions e = (b − a)·(1/|b − a|), by lanes.
#[inline(always)]
fn rulings_x2(v: [F64x2; 6]) -> (V3x2, V3x2) {
    let a = V3x2 {
        x: F64x2::first_lanes(v[0], v[3]),
        y: F64x2::second_lanes(v[0], v[3]),
        z: F64x2::first_lanes(v[1], v[4]),
    };
    let b = V3x2 {
        x: F64x2::second_lanes(v[1], v[4]),
        y: F64x2::first_lanes(v[2], v[5]),
        z: F64x2::second_lanes(v[2], v[5]),
    };
    let d = b.sub(a);
    let recip = F64x2::splat(1.0) / d.dot(d).sqrt();
    (a, V3x2 { x: d.x * recip, y: d.y * recip, z: d.z * recip })
}

/// Twelve consecutive numbers as six vectors.
#[inline(always)]
fn load12(s: &[f64; 12]) -> [F64x2; 6] {
    core::array::from_fn(|i| F64x2::from_array([s[2 * i], s[2 * i + 1]]))
}

/// Rulings r and r′ of the sequence (with its wrap) in lanes 0 and 1, through a copy.
#[inline(always)]
fn load_pair(seq: &Rulings<'_>, r: usize, r2: usize) -> (V3x2, V3x2) {
    let mut s = [0.0; 12];
    s[..6].copy_from_slice(&seq.ruling(r));
    s[6..].copy_from_slice(&seq.ruling(r2));
    rulings_x2(load12(&s))
}

/// Pairs k, k + 1 from the window before them and rulings k + 1, k + 2 (`a`, `e`). `CAREFUL`:
/// the angle with `f64::atan2`'s answer outside the fast path's domain; else the lanes outside it
/// are marked in `missed` (and the caller computes again, carefully).
#[inline(always)]
fn step<const CAREFUL: bool>(prev: &Window, a: V3x2, e: V3x2, missed: &mut Mask2) -> (Step, Window) {
    let a0 = V3x2::shift(prev.a, a);
    let e0 = V3x2::shift(prev.e, e);
    let d = a.sub(a0);
    let c = e0.cross(e);
    let sin = c.dot(c).sqrt();
    let angle = if CAREFUL {
        atan2_upper(sin, e0.dot(e))
    } else {
        let (angle, inside) = atan2_fast(sin, e0.dot(e));
        *missed = missed.or(inside.not());
        angle
    };
    let parallel = sin.lt(F64x2::splat(PARALLEL_SIN));
    let sin2 = sin * sin;
    let t = d.cross(e).dot(c) / sin2;
    let s = d.cross(e0).dot(c) / sin2;
    let mut distance = d.dot(c) / sin;
    let mut normal = c.map(|v| v / sin);
    let mut f0 = a0.add(e0.scale(t));
    let mut f1 = a.add(e.scale(s));
    let mut delta = distance / angle;
    if parallel.any() {
        // |d − (d·e_k) e_k|, glam's reject_from_normalized; everything else NaN
        let along = d.dot(e0);
        let r = V3x2 { x: d.x - e0.x * along, y: d.y - e0.y * along, z: d.z - e0.z * along };
        distance = F64x2::select(parallel, r.dot(r).sqrt(), distance);
        let nan = F64x2::splat(f64::NAN);
        let nan3 = V3x2::splat(nan);
        normal = V3x2::select(parallel, nan3, normal);
        f0 = V3x2::select(parallel, nan3, f0);
        f1 = V3x2::select(parallel, nan3, f1);
        delta = F64x2::select(parallel, nan, delta);
    }
    let half = F64x2::splat(0.5);
    let out = Step {
        angle,
        distance,
        delta,
        f0,
        f1,
        normal,
        parallel,
        midpoint: f0.add(f1).scale(half),
        striction: V3x2::shift(prev.f1, f1).add(f0).scale(half),
        mean: half * (F64x2::shift(prev.delta, delta) + delta),
    };
    (out, Window { a, e, f1, delta })
}

/// Where a whole step goes: pairs k, k + 1 and the striction quantities of rulings k, k + 1.
struct Dst<'a> {
    angle: &'a mut [f64],
    distance: &'a mut [f64],
    distribution: &'a mut [f64],
    footpoints: &'a mut [f64],
    normal: &'a mut [f64],
    midpoints: &'a mut [f64],
    parallel: &'a mut [bool],
    striction: &'a mut [f64],
    mean: &'a mut [f64],
}

/// Two numbers into a chunk of two.
#[inline(always)]
fn put(dst: &mut [f64], v: F64x2) {
    let d: &mut [f64; 2] = dst.try_into().expect("a chunk of two");
    *d = v.to_array();
}

/// Three vectors into a chunk of six.
#[inline(always)]
fn put3(dst: &mut [f64], v: [F64x2; 3]) {
    let d: &mut [f64; 6] = dst.try_into().expect("a chunk of six");
    for (q, v) in v.into_iter().enumerate() {
        [d[2 * q], d[2 * q + 1]] = v.to_array();
    }
}

/// Stores a whole step.
#[inline(always)]
fn store(d: Dst<'_>, s: &Step) {
    put(d.angle, s.angle);
    put(d.distance, s.distance);
    put(d.distribution, s.delta);
    let (f0, f1) = (s.f0, s.f1);
    let (first, second) = d.footpoints.split_at_mut(6);
    put3(first, [F64x2::first_lanes(f0.x, f0.y), F64x2::first_lanes(f0.z, f1.x), F64x2::first_lanes(f1.y, f1.z)]);
    put3(second, [F64x2::second_lanes(f0.x, f0.y), F64x2::second_lanes(f0.z, f1.x), F64x2::second_lanes(f1.y, f1.z)]);
    put3(d.normal, s.normal.to_interleaved());
    put3(d.midpoints, s.midpoint.to_interleaved());
    let p: &mut [bool; 2] = d.parallel.try_into().expect("a chunk of two");
    *p = s.parallel.to_array();
    put3(d.striction, s.striction.to_interleaved());
    put(d.mean, s.mean);
}

/// Stores one lane of a step: the pair at `i` and, if given, the striction quantities at `j`.
fn store_lane(out: &mut Out<'_>, lane: usize, i: Option<usize>, j: Option<usize>, s: &Step) {
    let get = |v: F64x2| v.to_array()[lane];
    let get3 = |v: V3x2| [get(v.x), get(v.y), get(v.z)];
    if let Some(i) = i {
        out.angle[i] = get(s.angle);
        out.distance[i] = get(s.distance);
        out.distribution[i] = get(s.delta);
        out.footpoints[6 * i..6 * i + 3].copy_from_slice(&get3(s.f0));
        out.footpoints[6 * i + 3..6 * i + 6].copy_from_slice(&get3(s.f1));
        out.normal[3 * i..3 * i + 3].copy_from_slice(&get3(s.normal));
        out.midpoints[3 * i..3 * i + 3].copy_from_slice(&get3(s.midpoint));
        out.parallel[i] = s.parallel.to_array()[lane];
    }
    if let Some(j) = j {
        out.striction[3 * j..3 * j + 3].copy_from_slice(&get3(s.striction));
        out.mean[j] = get(s.mean);
    }
}

/// The invariants of pairs start … end − 1 of `seq` into `out` (see [`Out`] for the lengths).
pub fn pairs(seq: &Rulings<'_>, start: usize, end: usize, out: &mut Out<'_>) {
    debug_assert!(start <= end && end <= seq.pairs());
    if start == end {
        return;
    }
    // an angle outside the fast path's domain (never for unit directions): all again, carefully
    if !run::<false>(seq, start, end, out) {
        run::<true>(seq, start, end, out);
    }
}

/// [`pairs`] with the angle's fast path alone (`CAREFUL` false; returns whether every lane was
/// inside its domain) or with `f64::atan2` outside it.
fn run<const CAREFUL: bool>(seq: &Rulings<'_>, start: usize, end: usize, out: &mut Out<'_>) -> bool {
    let mut missed = F64x2::splat(0.0).lt(F64x2::splat(0.0));
    let first = start.max(1);
    let n = seq.len();
    let mut k = start;
    // the window before pair k
    let mut win = if k == 0 {
        // pairs 0 and 1 through the copying loader (R_2 may be the wrap, or absent), ruling 0's
        // striction not stored
        let (a0, e0) = load_pair(seq, 0, 0);
        let nan = F64x2::splat(f64::NAN);
        let before = Window { a: a0, e: e0, f1: V3x2::splat(nan), delta: nan };
        let (a, e) = load_pair(seq, 1, 2);
        let (s, w) = step::<CAREFUL>(&before, a, e, &mut missed);
        store_lane(out, 0, Some(0), None, &s);
        if end >= 2 {
            store_lane(out, 1, Some(1), Some(0), &s);
        }
        k = 2;
        w
    } else {
        // pair k − 1 in lane 1 (lane 0 is a repeat nobody reads)
        let (a, e) = load_pair(seq, k - 1, k);
        step::<CAREFUL>(&Window { a, e, f1: a, delta: a.x }, a, e, &mut missed).1
    };
    // whole steps straight from the coordinates: rulings k + 1, k + 2 are R_{k+1}, R_{k+2}; the
    // output in chunks of exactly one step, so that no store needs a bounds check
    let steps = (end.min(n - 1).saturating_sub(k)) / 2;
    if steps > 0 {
        let (i, j) = (k - start, k - first);
        let input = seq.flat[6 * (k + 1)..6 * (k + 1 + 2 * steps)].chunks_exact(12);
        fn chunks<T>(v: &mut [T], at: usize, size: usize, steps: usize) -> core::slice::ChunksExactMut<'_, T> {
            v[at..at + size * steps].chunks_exact_mut(size)
        }
        let outputs = chunks(out.angle, i, 2, steps)
            .zip(chunks(out.distance, i, 2, steps))
            .zip(chunks(out.distribution, i, 2, steps))
            .zip(chunks(out.footpoints, 6 * i, 12, steps))
            .zip(chunks(out.normal, 3 * i, 6, steps))
            .zip(chunks(out.midpoints, 3 * i, 6, steps))
            .zip(chunks(out.parallel, i, 2, steps))
            .zip(chunks(out.striction, 3 * j, 6, steps))
            .zip(chunks(out.mean, j, 2, steps));
        for (
            s,
            ((((((((angle, distance), distribution), footpoints), normal), midpoints), parallel), striction), mean),
        ) in input.zip(outputs)
        {
            let (a, e) = rulings_x2(load12(s.try_into().expect("twelve numbers")));
            let (s, w) = step::<CAREFUL>(&win, a, e, &mut missed);
            store(Dst { angle, distance, distribution, footpoints, normal, midpoints, parallel, striction, mean }, &s);
            win = w;
        }
        k += 2 * steps;
    }
    // the last one or two pairs (the wrap of a closed surface among them)
    while k < end {
        let (a, e) = load_pair(seq, k + 1, k + 2);
        let (s, w) = step::<CAREFUL>(&win, a, e, &mut missed);
        store_lane(out, 0, Some(k - start), Some(k - first), &s);
        if k + 1 < end {
            store_lane(out, 1, Some(k + 1 - start), Some(k + 1 - first), &s);
        }
        win = w;
        k += 2;
    }
    !missed.any()
}

/// Closed surfaces: R_0's striction point (f_{0,N−1} + f_{0,1})/2 and its mean distribution
/// parameter (δ_{N−1,0} + δ_{0,1})/2, from the first and last pairs' numbers.
pub fn closing(first_foot: [f64; 3], last_foot: [f64; 3], first_delta: f64, last_delta: f64) -> ([f64; 3], f64) {
    (core::array::from_fn(|q| 0.5 * (last_foot[q] + first_foot[q])), 0.5 * (last_delta + first_delta))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The careful run (never needed for unit directions, so no surface reaches it) computes the
    /// same numbers as the fast one wherever the fast one is inside its domain.
    #[test]
    fn the_careful_run_agrees_with_the_fast_one() {
        let flat: Vec<f64> = (0..6 * 11).map(|i| ((i * 7919) % 113) as f64 / 17.0 - 3.0).collect();
        for closed in [false, true] {
            let seq = Rulings::new(&flat, closed);
            let (p, m) = (seq.pairs(), seq.pairs() - 1);
            let mut runs = [(); 2].map(|_| (vec![0.0; 19 * p], vec![false; p]));
            let mut inside = [false; 2];
            for (r, (v, par)) in runs.iter_mut().enumerate() {
                let (angle, rest) = v.split_at_mut(p);
                let (distance, rest) = rest.split_at_mut(p);
                let (distribution, rest) = rest.split_at_mut(p);
                let (footpoints, rest) = rest.split_at_mut(6 * p);
                let (normal, rest) = rest.split_at_mut(3 * p);
                let (midpoints, rest) = rest.split_at_mut(3 * p);
                let (striction, rest) = rest.split_at_mut(3 * m);
                let mean = &mut rest[..m];
                let mut out = Out {
                    angle,
                    distance,
                    distribution,
                    footpoints,
                    normal,
                    parallel: par,
                    striction,
                    mean,
                    midpoints,
                };
                inside[r] = if r == 0 { run::<false>(&seq, 0, p, &mut out) } else { run::<true>(&seq, 0, p, &mut out) };
            }
            assert!(inside[0] && inside[1]);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&runs[0].0), bits(&runs[1].0));
            assert_eq!(runs[0].1, runs[1].1);
        }
    }
}
