//! Variational subdivision of line congruences (Section 5.2, Figs. 14–15).
//!
//! **Two-stage scheme** (the structure of the paper's scheme): every column j of lines is a
//! discrete ruled surface; the strip scheme of Section 4 (n = K) inserts the lines T_{i,j}
//! between R_{i,j} and R_{i+1,j}; every row likewise gives S_{i,j} between R_{i,j} and
//! R_{i,j+1} (ERRATA.md 9: T for every row j). The face line R̄_{i,j} then minimises the
//! 8-neighbour umbrella energy (20)–(21), whose neighbours are all known, so it is their
//! average in every layer: P̄ = ⅛ Σ of the four corner and four edge points on d₁, Q̄ likewise.
//! Read literally, the paper's edge lines come from the strip energy (13)–(15) with umbrellas
//! at the new points only, which is the midpoint rule (ERRATA.md): [`EdgeScheme::Literal`],
//! "paper" in the JS API. ruledlab's "two-stage" variant uses the coupled strip energy.
//!
//! **Coupled scheme**: umbrellas (20) at every vertex of the refined grid in every layer
//! k = 0 … K (and, on the boundary, the strip's umbrella along the boundary line), old
//! lines fixed, all new lines unknown. Since every layer point is (1 − t_k)P + t_k Q, the
//! energy is Σ_v [(LP)_v, (LQ)_v] M [(LP)_v, (LQ)_v]ᵀ with the umbrella operator L and
//! M = [[Σ(1−t)², Σt(1−t)], [Σt(1−t), Σt²]] positive definite for K ≥ 1; its minimiser
//! therefore solves L_newᵀ L P = … and L_newᵀ L Q = … separately, independent of K: variational
//! subdivision of the two director grids (the 8-neighbour umbrella is symmetric, so no twist
//! term appears, unlike the strip's two triangulations). Every unknown has fixed old
//! neighbours at distance one, so the system's condition number does not grow with the
//! grid: conjugate gradients, matrix-free and started from the butterfly refinement (16), converge
//! in a bounded number of iterations, O(lines) time (measured in the benchmark).

use crate::congruence::LineCongruence;
use crate::error::{Error, Result};
use crate::subdivision::{variational as strip, Variant};
use glam::DVec3;

/// How the edge lines T, S of the two-stage scheme are made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EdgeScheme {
    /// The paper's strip energy read literally: the midpoint rule.
    Literal,
    /// The coupled strip energy (umbrellas at every vertex).
    Coupled,
}

/// The two-stage scheme of Section 5.2 (K parts per line, K ≥ 3), edge lines by `edges`.
pub fn two_stage(c: &LineCongruence, k: usize, edges: EdgeScheme) -> Result<LineCongruence> {
    let variant = match edges {
        EdgeScheme::Literal => Variant::Literal,
        EdgeScheme::Coupled => Variant::Coupled,
    };
    let (rows, cols) = (c.rows(), c.cols());
    let (rr, cc) = (2 * rows - 1, 2 * cols - 1);
    let mut p = vec![DVec3::ZERO; rr * cc];
    let mut q = vec![DVec3::ZERO; rr * cc];
    let mut put = |i: usize, j: usize, s: crate::line::Segment| {
        p[i * cc + j] = s.a;
        q[i * cc + j] = s.b;
    };
    for j in 0..cols {
        let refined = strip::refine(&c.column(j)?, k, variant)?;
        for (i, s) in refined.segments().enumerate() {
            put(i, 2 * j, s);
        }
    }
    for i in 0..rows {
        let refined = strip::refine(&c.row(i)?, k, variant)?;
        for (j, s) in refined.segments().enumerate().filter(|(j, _)| j % 2 == 1) {
            put(2 * i, j, s);
        }
    }
    for grid in [&mut p, &mut q] {
        for i in (1..rr).step_by(2) {
            for j in (1..cc).step_by(2) {
                let sum: DVec3 = [(-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1)]
                    .iter()
                    .map(|&(di, dj): &(isize, isize)| {
                        grid[(i as isize + di) as usize * cc + (j as isize + dj) as usize]
                    })
                    .sum();
                grid[i * cc + j] = sum / 8.0;
            }
        }
    }
    LineCongruence::from_points(rr, cc, &p, &q)
}

/// Iterations and final relative residual of the last coupled solve (for the benchmark).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveReport {
    /// Conjugate-gradient iterations (largest of the two director grids).
    pub iterations: usize,
}

/// The coupled scheme (see the module docs); its minimiser does not depend on K (K ≥ 1).
pub fn coupled(c: &LineCongruence, _k: usize) -> Result<(LineCongruence, SolveReport)> {
    // the start only decides the iterations, not the result: the butterfly refinement (16)
    // lies closer to the minimiser than the two-stage scheme and costs a fifth of it
    let start = super::subdivide(c, super::CongruenceScheme::Butterfly { w: 1.0 / 16.0 }, 1)?;
    let (rr, cc) = (start.rows(), start.cols());
    let (mut p, mut q) = (start.p(), start.q());
    let ip = solve_grid(&mut p, rr, cc)?;
    let iq = solve_grid(&mut q, rr, cc)?;
    Ok((LineCongruence::from_points(rr, cc, &p, &q)?, SolveReport { iterations: ip.max(iq) }))
}

/// The umbrella operator L of the refined grid: the 8-neighbour umbrella (20) at interior
/// vertices, the 1D umbrella along the boundary line at boundary vertices (not corners).
struct Umbrella {
    rows: usize,
    cols: usize,
}

impl Umbrella {
    /// out = x − (mean of the 8 neighbours) (20) at the nodes at least `margin` ≥ 1 nodes from
    /// the boundary, three rows of slices at a time; the other nodes are left alone.
    fn ring(&self, x: &[DVec3], out: &mut [DVec3], margin: usize) {
        let (r, c) = (self.rows, self.cols);
        for i in margin..r - margin {
            let (prev, cur, next) = (&x[(i - 1) * c..i * c], &x[i * c..(i + 1) * c], &x[(i + 1) * c..(i + 2) * c]);
            let out = &mut out[i * c..(i + 1) * c];
            for j in margin..c - margin {
                let ring =
                    prev[j - 1] + prev[j] + prev[j + 1] + cur[j - 1] + cur[j + 1] + next[j - 1] + next[j] + next[j + 1];
                out[j] = cur[j] - ring * 0.125;
            }
        }
    }

    /// u = L x: the interior by `ring`, then the boundary lines.
    fn apply(&self, x: &[DVec3], u: &mut [DVec3]) {
        let (r, c) = (self.rows, self.cols);
        self.ring(x, u, 1);
        for i in 1..r - 1 {
            let (prev, cur, next) = (&x[(i - 1) * c..i * c], &x[i * c..(i + 1) * c], &x[(i + 1) * c..(i + 2) * c]);
            let out = &mut u[i * c..(i + 1) * c];
            out[0] = cur[0] - 0.5 * (prev[0] + next[0]);
            out[c - 1] = cur[c - 1] - 0.5 * (prev[c - 1] + next[c - 1]);
        }
        for i in [0, r - 1] {
            let row = &x[i * c..(i + 1) * c];
            let out = &mut u[i * c..(i + 1) * c];
            for j in 1..c - 1 {
                out[j] = row[j] - 0.5 * (row[j - 1] + row[j + 1]);
            }
            out[0] = DVec3::ZERO;
            out[c - 1] = DVec3::ZERO;
        }
    }

    /// y = Lᵀ u. Away from the boundary (two nodes in) the stencil is symmetric, so Lᵀ is
    /// gathered like L; the band along the boundary is scattered from its sources.
    fn apply_transpose(&self, u: &[DVec3], y: &mut [DVec3]) {
        let (r, c) = (self.rows, self.cols);
        if r < 5 || c < 5 {
            return self.scatter_transpose(u, y, |_, _| true, 0);
        }
        self.ring(u, y, 2);
        let band = |i: usize, j: usize| i < 2 || i >= r - 2 || j < 2 || j >= c - 2;
        self.scatter_transpose(u, y, band, 2);
    }

    /// y = Lᵀ u at the nodes where `target(i, j)` holds (the others are left alone), by
    /// scattering each node's row of L. `depth`: the targets are the nodes within `depth`
    /// of the boundary (0: every node), so only sources within depth + 1 are visited.
    fn scatter_transpose(&self, u: &[DVec3], y: &mut [DVec3], target: impl Fn(usize, usize) -> bool, depth: usize) {
        let (r, c) = (self.rows, self.cols);
        // the nodes within `reach` of the boundary, row by row (every node when reach is 0)
        let ring = |reach: usize| {
            (0..r).flat_map(move |i| {
                let full = reach == 0 || i < reach || i + reach >= r;
                let cols: Vec<usize> = if full { (0..c).collect() } else { (0..reach).chain(c - reach..c).collect() };
                cols.into_iter().map(move |j| (i, j))
            })
        };
        for (i, j) in ring(depth) {
            if target(i, j) {
                y[i * c + j] = DVec3::ZERO;
            }
        }
        let mut add = |i: usize, j: usize, v: DVec3| {
            if target(i, j) {
                y[i * c + j] += v;
            }
        };
        for (i, j) in ring(if depth == 0 { 0 } else { depth + 1 }) {
            let w = u[i * c + j];
            let (edge_i, edge_j) = (i == 0 || i == r - 1, j == 0 || j == c - 1);
            match (edge_i, edge_j) {
                (false, false) => {
                    add(i, j, w);
                    for (a, b) in [
                        (i - 1, j - 1),
                        (i - 1, j),
                        (i - 1, j + 1),
                        (i, j - 1),
                        (i, j + 1),
                        (i + 1, j - 1),
                        (i + 1, j),
                        (i + 1, j + 1),
                    ] {
                        add(a, b, -0.125 * w);
                    }
                }
                (true, false) => {
                    add(i, j, w);
                    add(i, j - 1, -0.5 * w);
                    add(i, j + 1, -0.5 * w);
                }
                (false, true) => {
                    add(i, j, w);
                    add(i - 1, j, -0.5 * w);
                    add(i + 1, j, -0.5 * w);
                }
                (true, true) => {}
            }
        }
    }
}

/// Minimises |L x|² over the new nodes of `x` in place (old nodes fixed), by conjugate
/// gradients on L_newᵀ L, three coordinates at once. Returns the iteration count.
fn solve_grid(x: &mut [DVec3], rows: usize, cols: usize) -> Result<usize> {
    const TOL: f64 = 1e-13;
    const MAX_ITERATIONS: usize = 2000;
    let op = Umbrella { rows, cols };
    let n = x.len();
    let (mut u, mut ap) = (vec![DVec3::ZERO; n], vec![DVec3::ZERO; n]);
    let normal = |v: &[DVec3], u: &mut Vec<DVec3>, out: &mut Vec<DVec3>| {
        op.apply(v, u);
        op.apply_transpose(u, out);
        // the old lines (even, even) are fixed: no division per node to find them
        for i in (0..rows).step_by(2) {
            for j in (0..cols).step_by(2) {
                out[i * cols + j] = DVec3::ZERO;
            }
        }
    };
    let dot = |a: &[DVec3], b: &[DVec3]| a.iter().zip(b).fold(DVec3::ZERO, |s, (x, y)| s + *x * *y);
    // residual r = −L_newᵀ L x
    let mut r = vec![DVec3::ZERO; n];
    normal(x, &mut u, &mut r);
    r.iter_mut().for_each(|v| *v = -*v);
    let scale = x.iter().fold(0.0f64, |m, p| m.max(p.abs().max_element())).max(f64::MIN_POSITIVE);
    let floor = DVec3::splat((TOL * scale).powi(2) * n as f64);
    let mut rr = dot(&r, &r);
    let target = (rr * TOL * TOL).max(floor);
    let mut p = r.clone();
    for iteration in 0..MAX_ITERATIONS {
        if rr.cmple(target).all() {
            return Ok(iteration);
        }
        normal(&p, &mut u, &mut ap);
        let pap = dot(&p, &ap);
        let alpha = DVec3::select(pap.cmpgt(DVec3::ZERO), rr / pap, DVec3::ZERO);
        // one pass: the update and the new residual norm
        let mut rr_new = DVec3::ZERO;
        for ((xk, rk), (pk, apk)) in x.iter_mut().zip(r.iter_mut()).zip(p.iter().zip(&ap)) {
            *xk += alpha * *pk;
            *rk -= alpha * *apk;
            rr_new += *rk * *rk;
        }
        let beta = DVec3::select(rr.cmpgt(DVec3::ZERO), rr_new / rr, DVec3::ZERO);
        for (pk, rk) in p.iter_mut().zip(&r) {
            *pk = *rk + beta * *pk;
        }
        rr = rr_new;
    }
    Err(Error::NotConverged { what: "system", iterations: MAX_ITERATIONS })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fast operator and its transpose against their definition: (Lᵀu)·x = u·(Lx) for
    /// random x, u, and L computed node by node from (20), on small and large grids.
    #[test]
    fn umbrella_and_its_transpose_are_adjoint_and_match_the_definition() {
        let mut seed = 7u64;
        let mut rnd = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) - 0.5
        };
        for (r, c) in [(3, 3), (3, 7), (4, 5), (5, 5), (6, 9), (11, 8)] {
            let op = Umbrella { rows: r, cols: c };
            let n = r * c;
            let x: Vec<DVec3> = (0..n).map(|_| DVec3::new(rnd(), rnd(), rnd())).collect();
            let v: Vec<DVec3> = (0..n).map(|_| DVec3::new(rnd(), rnd(), rnd())).collect();
            let (mut lx, mut ltv) = (vec![DVec3::ZERO; n], vec![DVec3::splat(9.0); n]);
            op.apply(&x, &mut lx);
            op.apply_transpose(&v, &mut ltv);
            // L x from (20) node by node
            for i in 0..r {
                for j in 0..c {
                    let at = |a: isize, b: isize| x[(i as isize + a) as usize * c + (j as isize + b) as usize];
                    let want = match (i == 0 || i == r - 1, j == 0 || j == c - 1) {
                        (false, false) => {
                            let ring: DVec3 = [(-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1)]
                                .iter()
                                .map(|&(a, b)| at(a, b))
                                .sum();
                            at(0, 0) - ring / 8.0
                        }
                        (true, false) => at(0, 0) - 0.5 * (at(0, -1) + at(0, 1)),
                        (false, true) => at(0, 0) - 0.5 * (at(-1, 0) + at(1, 0)),
                        (true, true) => DVec3::ZERO,
                    };
                    assert!((lx[i * c + j] - want).length() < 1e-14, "{r}×{c} L at ({i}, {j})");
                }
            }
            // the gathered interior and scattered band equal Lᵀ scattered everywhere
            let mut reference = vec![DVec3::ZERO; n];
            op.scatter_transpose(&v, &mut reference, |_, _| true, 0);
            for k in 0..n {
                assert!((ltv[k] - reference[k]).length() < 1e-14, "{r}×{c} Lᵀ at node {k}");
            }
            let dot = |a: &[DVec3], b: &[DVec3]| a.iter().zip(b).map(|(p, q)| p.dot(*q)).sum::<f64>();
            let (left, right) = (dot(&ltv, &x), dot(&v, &lx));
            assert!((left - right).abs() < 1e-12 * (1.0 + right.abs()), "{r}×{c}: {left} vs {right}");
        }
    }

    fn congruence(rows: usize, cols: usize, f: impl Fn(f64, f64) -> (DVec3, DVec3)) -> LineCongruence {
        let (p, q): (Vec<DVec3>, Vec<DVec3>) =
            (0..rows * cols).map(|k| f((k / cols) as f64, (k % cols) as f64)).unzip();
        LineCongruence::from_points(rows, cols, &p, &q).unwrap()
    }

    fn wavy(u: f64, v: f64) -> (DVec3, DVec3) {
        let p = DVec3::new(u, v, 0.5 * (0.4 * u + 0.3 * v).sin());
        (p, p + DVec3::new(0.1 * u, 0.1 * v, 1.0))
    }

    /// The face line is the average of its eight neighbours, old lines are kept.
    #[test]
    fn two_stage_faces_average_their_neighbours() {
        let c = congruence(4, 5, wavy);
        let r = two_stage(&c, 6, EdgeScheme::Coupled).unwrap();
        assert_eq!((r.rows(), r.cols()), (7, 9));
        for i in 0..4 {
            for j in 0..5 {
                assert_eq!(r.line(2 * i, 2 * j), c.line(i, j));
            }
        }
        let avg = [(0, 0), (0, 1), (0, 2), (1, 0), (1, 2), (2, 0), (2, 1), (2, 2)]
            .iter()
            .map(|&(i, j)| r.line(2 + i, 4 + j).a)
            .sum::<DVec3>()
            / 8.0;
        assert!((r.line(3, 5).a - avg).length() < 1e-14);
    }

    /// The coupled solution minimises the layered energy (20)–(21) summed over k = 0 … K,
    /// written out literally: perturbing any new endpoint raises it.
    #[test]
    fn coupled_minimises_the_layered_energy() {
        let c = congruence(3, 4, wavy);
        let (r, report) = coupled(&c, 6).unwrap();
        assert!(report.iterations > 0);
        let energy = |g: &LineCongruence| {
            let (rr, cc) = (g.rows(), g.cols());
            let op = Umbrella { rows: rr, cols: cc };
            let mut total = 0.0;
            for k in 0..=6 {
                let t = k as f64 / 6.0;
                let layer: Vec<DVec3> = g.p().iter().zip(g.q()).map(|(p, q)| (1.0 - t) * *p + t * q).collect();
                let mut u = vec![DVec3::ZERO; layer.len()];
                op.apply(&layer, &mut u);
                total += u.iter().map(|v| v.length_squared()).sum::<f64>();
            }
            total
        };
        let e0 = energy(&r);
        let (mut p, q) = (r.p(), r.q());
        for k in [1, 5, 7, 10] {
            for axis in 0..3 {
                for sign in [-1.0, 1.0] {
                    let mut e = DVec3::ZERO;
                    e[axis] = sign * 1e-4;
                    p[k] += e;
                    let moved = LineCongruence::from_points(r.rows(), r.cols(), &p, &q).unwrap();
                    assert!(energy(&moved) > e0, "node {k} axis {axis}");
                    p[k] -= e;
                }
            }
        }
    }

    /// The start decides only the iterations: started from the butterfly refinement (as
    /// `coupled` is) or from the two-stage scheme, the solve ends at the same lines.
    #[test]
    fn the_coupled_result_does_not_depend_on_the_start() {
        let c = congruence(9, 11, wavy);
        let (fast, _) = coupled(&c, 6).unwrap();
        let start = two_stage(&c, 6, EdgeScheme::Coupled).unwrap();
        let (rr, cc) = (start.rows(), start.cols());
        let (mut p, mut q) = (start.p(), start.q());
        solve_grid(&mut p, rr, cc).unwrap();
        solve_grid(&mut q, rr, cc).unwrap();
        let moved = fast.p().iter().zip(&start.p()).map(|(a, b)| (*a - *b).length()).fold(0.0, f64::max);
        assert!(moved > 1e-4, "the two starts differ ({moved})");
        for (k, (a, b)) in fast.p().iter().zip(&p).chain(fast.q().iter().zip(&q)).enumerate() {
            assert!((*a - *b).length() < 1e-11, "node {k}: {a} vs {b}");
        }
    }

    /// Affine data stay affine; old lines are kept bit for bit.
    #[test]
    fn coupled_keeps_affine_data() {
        let c = congruence(4, 4, |u, v| (DVec3::new(u, v, 0.2 * u - 0.1 * v), DVec3::new(u, v, 2.0)));
        let (r, _) = coupled(&c, 6).unwrap();
        for i in 0..7 {
            for j in 0..7 {
                let (u, v) = (i as f64 / 2.0, j as f64 / 2.0);
                assert!((r.line(i, j).a - DVec3::new(u, v, 0.2 * u - 0.1 * v)).length() < 1e-10);
            }
        }
        assert_eq!(r.line(2, 4), c.line(1, 2));
    }
}
