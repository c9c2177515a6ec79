//! Variational subdivision of line congruences (Section 5.2, Figs. 14–15).
//!
//! **Two-stage scheme** (the structure of the paper's scheme): every column j of lines is a
//! discrete ruled surface; the strip scheme of Section 4 (n = K) inserts the lines T_{i,j}
//! between R_{i,j} and R_{i+1,j}; every row likewise gives S_{i,j} between R_{i,j} and
//! R_{i,j+1} (T for every row j: docs/src/conventions.md, Section 5.2). The face line R̄_{i,j} then minimises the
//! 8-neighbour umbrella energy (20)–(21), whose neighbours are all known, so it is their
//! average in every layer: P̄ = ⅛ Σ of the four corner and four edge points on d₁, Q̄ likewise.
//! Read literally, the paper's edge lines come from the strip energy (13)–(15) with umbrellas
//! at the new points only, which is the midpoint rule (docs/src/conventions.md, Section 5.2): [`EdgeScheme::Literal`],
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
//! grid: conjugate gradients, matrix-free and started from the butterfly refinement (16),
//! converge in a bounded number of iterations, O(lines) time (measured in the benchmark). The
//! three coordinates are separate systems with the same operator; one the start already gets
//! right (an affine coordinate, which (16) reproduces) is not solved at all.

use crate::congruence::LineCongruence;
use crate::error::{Error, Result};
use crate::subdivision::{variational as strip, Variant};
use crate::tolerance::{SOLVE_MAX_ITERATIONS, SOLVE_TOLERANCE};
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
        let refined = strip::refine_variational(&c.column(j)?, k, variant)?;
        for (i, s) in refined.segments().enumerate() {
            put(i, 2 * j, s);
        }
    }
    for i in 0..rows {
        let refined = strip::refine_variational(&c.row(i)?, k, variant)?;
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
pub fn coupled_congruence(c: &LineCongruence, _k: usize) -> Result<(LineCongruence, SolveReport)> {
    // the start only decides the iterations, not the result: the butterfly refinement (16)
    // lies closer to the minimiser than the two-stage scheme and costs a fifth of it
    let start = super::subdivide_congruence(c, super::CongruenceScheme::Butterfly { w: 1.0 / 16.0 }, 1)?;
    let (rr, cc) = (start.rows(), start.cols());
    let (mut p, mut q) = (start.p(), start.q());
    let mut iterations = 0;
    for grid in [&mut p, &mut q] {
        iterations = iterations.max(solve_coordinates(grid, rr, cc)?);
    }
    Ok((LineCongruence::from_points(rr, cc, &p, &q)?, SolveReport { iterations }))
}

/// Solves the coupled system of one director grid, coordinate by coordinate: the three
/// coordinates are separate systems with the same operator, each stopping when it has
/// converged — one the start already gets right (an affine one, which the butterfly rule
/// reproduces) costs one residual and no iteration. One coordinate at a time, the operator
/// and the updates run over plain `f64` arrays, which the compiler turns into SIMD (f64x2).
/// The solve runs on the grid scaled by a power of two to a largest coordinate in [1, 2):
/// that scaling is exact, so the result is the same bit for bit, and the solve's squares and
/// its convergence floor do not underflow however small the data (at 10⁻¹⁵⁹ they did). Only
/// the new nodes are written back: the old ones stay bit for bit, even a coordinate that the
/// scaling would have made subnormal. Returns the most iterations taken.
fn solve_coordinates(grid: &mut [DVec3], rows: usize, cols: usize) -> Result<usize> {
    let op = Umbrella { rows, cols };
    let n = grid.len();
    let largest = grid.iter().fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    let unit = power_of_two_below(largest);
    let floor = convergence_floor(largest / unit, n);
    let mut x = vec![0.0; n];
    let mut most = 0;
    for axis in 0..3 {
        x.iter_mut().zip(grid.iter()).for_each(|(s, p)| *s = p[axis] / unit);
        most = most.max(conjugate_gradients(&op, &mut x, floor)?);
        for (k, (p, s)) in grid.iter_mut().zip(&x).enumerate() {
            if (k / cols) % 2 == 1 || (k % cols) % 2 == 1 {
                p[axis] = *s * unit;
            }
        }
    }
    Ok(most)
}

/// The largest power of two 2ᵉ ≤ x, read from x's exponent bits (exact), for finite x > 0;
/// 1 for x = 0.
fn power_of_two_below(x: f64) -> f64 {
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    if x >= f64::MIN_POSITIVE {
        f64::from_bits(x.to_bits() & EXPONENT)
    } else if x > 0.0 {
        // subnormal: 2⁵² x is normal, and dividing its power of two by 2⁵² is exact
        let up = 2f64.powi(52);
        f64::from_bits((x * up).to_bits() & EXPONENT) / up
    } else {
        1.0
    }
}

/// Converged: ‖r‖ ≤ SOLVE_TOLERANCE · (largest coordinate) · √n, against the size of the data
/// (n points); returned squared, ‖r‖² ≤ floor.
fn convergence_floor(largest: f64, n: usize) -> f64 {
    (SOLVE_TOLERANCE * largest).powi(2) * n as f64
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
    fn ring(&self, x: &[f64], out: &mut [f64], margin: usize) {
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
    fn apply(&self, x: &[f64], u: &mut [f64]) {
        let (r, c) = (self.rows, self.cols);
        self.ring(x, u, 1);
        for i in 1..r - 1 {
            let (prev, cur, next) = (&x[(i - 1) * c..i * c], &x[i * c..(i + 1) * c], &x[(i + 1) * c..(i + 2) * c]);
            let out = &mut u[i * c..(i + 1) * c];
            out[0] = cur[0] - (prev[0] + next[0]) * 0.5;
            out[c - 1] = cur[c - 1] - (prev[c - 1] + next[c - 1]) * 0.5;
        }
        for i in [0, r - 1] {
            let row = &x[i * c..(i + 1) * c];
            let out = &mut u[i * c..(i + 1) * c];
            for j in 1..c - 1 {
                out[j] = row[j] - (row[j - 1] + row[j + 1]) * 0.5;
            }
            out[0] = 0.0;
            out[c - 1] = 0.0;
        }
    }

    /// y = Lᵀ u. Away from the boundary (two nodes in) the stencil is symmetric, so Lᵀ is
    /// gathered like L; the band along the boundary is scattered from its sources.
    fn apply_transpose(&self, u: &[f64], y: &mut [f64]) {
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
    fn scatter_transpose(&self, u: &[f64], y: &mut [f64], target: impl Fn(usize, usize) -> bool, depth: usize) {
        let (r, c) = (self.rows, self.cols);
        // the nodes within `reach` of the boundary, row by row (every node when reach is 0),
        // each once
        let ring = |reach: usize| {
            (0..r).flat_map(move |i| {
                // a whole row, or its first and last `reach` columns, none twice (5 columns
                // with reach 3 took column 2 twice)
                let whole = reach == 0 || i < reach || i + reach >= r;
                let (left, right) = if whole { (c, c) } else { (reach, (c - reach).max(reach)) };
                (0..left).chain(right..c).map(move |j| (i, j))
            })
        };
        for (i, j) in ring(depth) {
            if target(i, j) {
                y[i * c + j] = 0.0;
            }
        }
        let mut add = |i: usize, j: usize, v: f64| {
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
                        add(a, b, w * -0.125);
                    }
                }
                (true, false) => {
                    add(i, j, w);
                    add(i, j - 1, w * -0.5);
                    add(i, j + 1, w * -0.5);
                }
                (false, true) => {
                    add(i, j, w);
                    add(i - 1, j, w * -0.5);
                    add(i + 1, j, w * -0.5);
                }
                (true, true) => {}
            }
        }
    }

    /// out = L_newᵀ L v, zero at the old nodes (even row and column), which are fixed.
    fn normal(&self, v: &[f64], u: &mut [f64], out: &mut [f64]) {
        self.apply(v, u);
        self.apply_transpose(u, out);
        for i in (0..self.rows).step_by(2) {
            for j in (0..self.cols).step_by(2) {
                out[i * self.cols + j] = 0.0;
            }
        }
    }
}

/// Minimises |L x|² over the new nodes of `x` in place (old nodes fixed) by conjugate
/// gradients on L_newᵀ L, started from `x`, until ‖r‖² ≤ `floor` or 10⁻²⁶ of its first
/// value. Returns the iteration count (0 when the start has converged already).
fn conjugate_gradients(op: &Umbrella, x: &mut [f64], floor: f64) -> Result<usize> {
    let n = x.len();
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let (mut u, mut ap, mut r) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    // the residual r = −L_newᵀ L x of the start
    op.normal(x, &mut u, &mut r);
    r.iter_mut().for_each(|v| *v = -*v);
    let mut rr = dot(&r, &r);
    let target = (rr * (SOLVE_TOLERANCE * SOLVE_TOLERANCE)).max(floor);
    let mut p = r.to_vec();
    for iteration in 0..SOLVE_MAX_ITERATIONS {
        if rr <= target {
            return Ok(iteration);
        }
        op.normal(&p, &mut u, &mut ap);
        let pap = dot(&p, &ap);
        let alpha = if pap > 0.0 { rr / pap } else { 0.0 };
        // one pass: the update and the new residual norm
        let mut rr_new = 0.0;
        for ((xk, rk), (pk, apk)) in x.iter_mut().zip(r.iter_mut()).zip(p.iter().zip(&ap)) {
            *xk += alpha * pk;
            *rk -= alpha * apk;
            rr_new += *rk * *rk;
        }
        let beta = if rr > 0.0 { rr_new / rr } else { 0.0 };
        for (pk, rk) in p.iter_mut().zip(r.iter()) {
            *pk = rk + beta * *pk;
        }
        rr = rr_new;
    }
    Err(Error::NotConverged { what: "system", iterations: SOLVE_MAX_ITERATIONS })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fast operator and its transpose against their definition: (Lᵀu)·x = u·(Lx) for
    /// random x, u, and L computed node by node from (20), on small and large grids.
    #[test]
    fn umbrella_and_its_transpose_are_adjoint_and_match_the_definition() {
        let mut seed = 7u64;
        let mut rnd = move || crate::tolerance::test::uniform(&mut seed) - 0.5;
        // every size from 3 × 3 to 12 × 12 (5 columns and 7 rows or more once scattered a
        // node of the band's middle column twice)
        for (r, c) in (3..=12).flat_map(|r| (3..=12).map(move |c| (r, c))) {
            let op = Umbrella { rows: r, cols: c };
            let n = r * c;
            let x: Vec<f64> = (0..n).map(|_| rnd()).collect();
            let v: Vec<f64> = (0..n).map(|_| rnd()).collect();
            let (mut lx, mut ltv) = (vec![0.0; n], vec![9.0; n]);
            op.apply(&x, &mut lx);
            op.apply_transpose(&v, &mut ltv);
            // L x from (20) node by node
            for i in 0..r {
                for j in 0..c {
                    let at = |a: isize, b: isize| x[(i as isize + a) as usize * c + (j as isize + b) as usize];
                    let want = match (i == 0 || i == r - 1, j == 0 || j == c - 1) {
                        (false, false) => {
                            let ring: f64 = [(-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1)]
                                .iter()
                                .map(|&(a, b)| at(a, b))
                                .sum();
                            at(0, 0) - ring / 8.0
                        }
                        (true, false) => at(0, 0) - 0.5 * (at(0, -1) + at(0, 1)),
                        (false, true) => at(0, 0) - 0.5 * (at(-1, 0) + at(1, 0)),
                        (true, true) => 0.0,
                    };
                    assert!((lx[i * c + j] - want).abs() < 1e-14, "{r}×{c} L at ({i}, {j})");
                }
            }
            // the gathered interior and scattered band equal Lᵀ scattered everywhere
            let mut reference = vec![0.0; n];
            op.scatter_transpose(&v, &mut reference, |_, _| true, 0);
            for k in 0..n {
                assert!((ltv[k] - reference[k]).abs() < 1e-14, "{r}×{c} Lᵀ at node {k}");
            }
            let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(p, q)| p * q).sum::<f64>();
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
        // 4 × 3 lines refine to 7 × 5 (the umbrella's transpose once took a node twice there)
        for (rows, cols) in [(3, 4), (4, 3)] {
            minimises_the_layered_energy(&congruence(rows, cols, wavy));
        }
    }

    /// Moving either end of any new line of the coupled result by 10⁻⁴ along an axis raises the
    /// layered energy (20)–(21), summed over k = 0 … 6.
    fn minimises_the_layered_energy(c: &LineCongruence) {
        let (r, report) = coupled_congruence(c, 6).unwrap();
        assert!(report.iterations > 0);
        let energy = |g: &LineCongruence| {
            let (rr, cc) = (g.rows(), g.cols());
            let op = Umbrella { rows: rr, cols: cc };
            let mut total = 0.0;
            for k in 0..=6 {
                let t = k as f64 / 6.0;
                let layer: Vec<DVec3> = g.p().iter().zip(g.q()).map(|(p, q)| (1.0 - t) * *p + t * q).collect();
                for axis in 0..3 {
                    let coordinate: Vec<f64> = layer.iter().map(|v| v[axis]).collect();
                    let mut u = vec![0.0; layer.len()];
                    op.apply(&coordinate, &mut u);
                    total += u.iter().map(|v| v * v).sum::<f64>();
                }
            }
            total
        };
        let e0 = energy(&r);
        let (p, q) = (r.p(), r.q());
        let cols = r.cols();
        for k in (0..p.len()).filter(|k| (k / cols) % 2 == 1 || (k % cols) % 2 == 1) {
            for (end, axis, sign) in
                (0..2).flat_map(|end| (0..3).flat_map(move |axis| [(end, axis, -1.0), (end, axis, 1.0)]))
            {
                let (mut p, mut q) = (p.clone(), q.clone());
                [&mut p, &mut q][end][k][axis] += sign * 1e-4;
                let moved = LineCongruence::from_points(r.rows(), r.cols(), &p, &q).unwrap();
                assert!(energy(&moved) > e0, "{}×{}: node {k}, end {end}, axis {axis}", c.rows(), c.cols());
            }
        }
    }

    /// The start decides only the iterations: started from the butterfly refinement (as
    /// `coupled_congruence` is) or from the two-stage scheme, the solve ends at the same lines.
    #[test]
    fn the_coupled_result_does_not_depend_on_the_start() {
        let c = congruence(9, 11, wavy);
        let (fast, _) = coupled_congruence(&c, 6).unwrap();
        let start = two_stage(&c, 6, EdgeScheme::Coupled).unwrap();
        let (rr, cc) = (start.rows(), start.cols());
        let (mut p, mut q) = (start.p(), start.q());
        solve_coordinates(&mut p, rr, cc).unwrap();
        solve_coordinates(&mut q, rr, cc).unwrap();
        let moved = fast.p().iter().zip(&start.p()).map(|(a, b)| (*a - *b).length()).fold(0.0, f64::max);
        assert!(moved > 1e-4, "the two starts differ ({moved})");
        for (k, (a, b)) in fast.p().iter().zip(&p).chain(fast.q().iter().zip(&q)).enumerate() {
            assert!((*a - *b).length() < 1e-11, "node {k}: {a} vs {b}");
        }
    }

    /// A coordinate the butterfly start reproduces (here x and y, affine in the grid) takes no
    /// iteration and is kept bit for bit; the curved one (z) is solved.
    #[test]
    fn a_coordinate_the_start_gets_right_is_not_solved() {
        let c = congruence(9, 11, wavy);
        let start = crate::congruence::subdivide_congruence(
            &c,
            crate::congruence::CongruenceScheme::Butterfly { w: 1.0 / 16.0 },
            1,
        )
        .unwrap();
        let (rows, cols) = (start.rows(), start.cols());
        let op = Umbrella { rows, cols };
        let grid = start.p();
        let n = grid.len();
        let floor = convergence_floor(10.0, n);
        let iterations: Vec<usize> = (0..3)
            .map(|axis| {
                let mut x: Vec<f64> = grid.iter().map(|p| p[axis]).collect();
                conjugate_gradients(&op, &mut x, floor).unwrap()
            })
            .collect();
        assert_eq!(&iterations[..2], &[0, 0], "x and y need no iteration");
        assert!(iterations[2] > 3, "z is solved ({} iterations)", iterations[2]);
        let mut each = grid.clone();
        solve_coordinates(&mut each, rows, cols).unwrap();
        for k in 0..n {
            assert_eq!((each[k].x, each[k].y), (grid[k].x, grid[k].y), "node {k}: affine coordinates kept");
        }
        assert!(each.iter().zip(&grid).any(|(a, b)| (a.z - b.z).abs() > 1e-6), "z was solved");
    }

    /// Affine data stay affine; old lines are kept bit for bit.
    #[test]
    fn coupled_keeps_affine_data() {
        let c = congruence(4, 4, |u, v| (DVec3::new(u, v, 0.2 * u - 0.1 * v), DVec3::new(u, v, 2.0)));
        let (r, _) = coupled_congruence(&c, 6).unwrap();
        for i in 0..7 {
            for j in 0..7 {
                let (u, v) = (i as f64 / 2.0, j as f64 / 2.0);
                assert!((r.line(i, j).a - DVec3::new(u, v, 0.2 * u - 0.1 * v)).length() < 1e-10);
            }
        }
        assert_eq!(r.line(2, 4), c.line(1, 2));
    }

    /// The convergence floor, by hand: (10⁻¹³ · 8)² · 4 for four points whose largest
    /// coordinate is 8; and the power of two the solve scales by.
    #[test]
    fn the_convergence_floor_and_the_scale_of_the_solve() {
        assert_eq!(SOLVE_TOLERANCE, 1e-13);
        let floor = convergence_floor(8.0, 4);
        assert!((floor / 2.56e-24 - 1.0).abs() < 1e-14, "{floor:e}");
        let just_below = |x: f64| f64::from_bits(x.to_bits() - 1);
        for (x, below) in [
            (1.0, 1.0),
            (1.5, 1.0),
            (0.75, 0.5),
            (1e-159, 2f64.powi(-529)),
            (3e120, 2f64.powi(400)),
            (just_below(2f64.powi(400)), 2f64.powi(399)),
            (f64::MAX, 2f64.powi(1023)),
            (f64::MIN_POSITIVE, f64::MIN_POSITIVE),
            (just_below(f64::MIN_POSITIVE), f64::from_bits(1 << 51)),
            (3e-320, f64::from_bits(1 << 12)),
            (5e-324, 5e-324),
        ] {
            assert_eq!(power_of_two_below(x), below, "{x:e}");
        }
        assert_eq!(power_of_two_below(0.0), 1.0);
    }

    /// The coupled scheme commutes with scaling by powers of two, bit for bit, also where the
    /// squares of its solve would underflow unscaled (2⁻⁵²⁸ ≈ 10⁻¹⁵⁹); old lines are kept bit
    /// for bit, even a coordinate of 5·10⁻³²⁴ beside ones of 4.
    #[test]
    fn coupled_commutes_with_scaling_by_powers_of_two() {
        let c = congruence(4, 5, wavy);
        let (r, _) = coupled_congruence(&c, 3).unwrap();
        let times = |points: Vec<DVec3>, s: f64| points.into_iter().map(|x| x * s).collect::<Vec<_>>();
        for s in [2f64.powi(-528), 2f64.powi(-60), 2f64.powi(400)] {
            let scaled = LineCongruence::from_points(4, 5, &times(c.p(), s), &times(c.q(), s)).unwrap();
            let (rs, _) = coupled_congruence(&scaled, 3).unwrap();
            assert_eq!(rs.p(), times(r.p(), s), "{s:e}");
            assert_eq!(rs.q(), times(r.q(), s), "{s:e}");
        }
        let (mut p, q) = (c.p(), c.q());
        p[6].x = 5e-324;
        let tiny = LineCongruence::from_points(4, 5, &p, &q).unwrap();
        let (refined, _) = coupled_congruence(&tiny, 3).unwrap();
        assert_eq!(refined.line(2, 2), tiny.line(1, 1));
        assert_eq!(refined.line(2, 2).a.x, 5e-324);
    }
}
