//! Tool poses optimised against the part: flank milling's envelope fit, after P. Bo, M. Bartoň,
//! D. Plakhotnik and H. Pottmann, *Towards efficient 5-axis flank CNC machining of free-form
//! surfaces via fitting envelopes of surfaces of revolution*, Computer-Aided Design 71 (2016),
//! and P. Bo, M. Bartoň, H. Pottmann, *Automatic fitting of conical envelopes to
//! free-form surfaces for flank CNC machining*, Computer-Aided Design 91 (2017): the tool's
//! axis moves on a ruled surface (here the discrete one of the poses, Section 4 of Odehnal &
//! Pottmann), and the squared distances of the part's points from the envelope of the moving tool
//! are minimised with a fairness energy, by Gauss–Newton steps with fixed foot points. The start
//! is the ruling-aligned pose [`ruling_aligned`] (the tool's axis along the ruling, offset by the
//! radius along the normal), which C. Menzel, S. Bedi and S. Mann's triple-tangent positioning
//! (*Triple tangent flank milling of ruled surfaces*, CAD 36, 2004) improves one pose at a time,
//! tangent to two guiding curves and a ruling; here all poses move together, and the gap between poses counts.
//!
//! **Unknowns.** Pose k is held by two points, its tip Pₖ and its axis end Qₖ = Pₖ + L·aₖ (L the
//! tool's length): 6 numbers a pose, as in the strips of the variational schemes.
//!
//! **Energy.** With D(q; x) the deviation of target point q from the tool swept through the path
//! of the poses x — the signed distance of q from the swept solid, the tip on the chords and the
//! axis on the great-circle arcs between poses ([`envelope_deviation`], the measure of C. Li,
//! S. Mann, S. Bedi, CAD 2005) —
//!
//! E(x) = Σᵢ D(qᵢ; x)² + λ·(M/N)·Σₖ (|Δ²(P − P⁰)ₖ|² + |Δ²(Q − Q⁰)ₖ|²),  Δ²Vₖ = Vₖ₋₁ − 2Vₖ + Vₖ₊₁   (1)
//!
//! M target points, N poses, P⁰, Q⁰ the given poses, λ the fairness weight
//! ([`OptimiseOptions::fairness`]); the second sum is the fairness term of the variational
//! schemes' energy (15) on the strip's two boundary polylines (`ruledlab`'s
//! `subdivision/variational.rs`), taken of how far the poses move, so that they move smoothly and
//! a curved path is not pulled straight (the term of the poses themselves did that on the coarse
//! paths of Example 6: it raised the largest deviation), scaled to weigh alike for any density of
//! the target.
//!
//! **Linearisation.** The nearest tool to qᵢ is found at block k, parameter s (the pose
//! Pₖ + s(Pₖ₊₁ − Pₖ), its axis turned a share s) and height t·L along its axis; with g = ∇_q D
//! (the unit direction from the tool's surface to q), moving the tool's point there by δ changes
//! D by −g·δ, and that point moves by (1 − t)δP(s) + t δQ(s), δP(s) = (1 − s)δPₖ + s δPₖ₊₁
//! (δQ alike), so
//!
//! ∂D/∂Pₖ = −(1 − s)(1 − t) g, ∂D/∂Pₖ₊₁ = −s(1 − t) g, ∂D/∂Qₖ = −(1 − s) t g, ∂D/∂Qₖ₊₁ = −s t g.  (2)
//!
//! The foot (k, s, t) is where D is least, so (2) is D's gradient (the envelope theorem); the
//! feet are found again at every round.
//!
//! **Steps.** Levenberg–Marquardt: (JᵀJ + λ(M/N)·F + μ·diag(JᵀJ + τ)) δ = −(Jᵀr + λ(M/N)·F(x − x⁰)), F
//! the fairness term's matrix ((1) = rᵀr + λ(M/N)·(x − x⁰)ᵀF(x − x⁰)), banded with half-bandwidth 17 (poses
//! k − 2 … k + 2), solved by the banded Cholesky factorisation; each Qₖ is then put back at the
//! tool's length from Pₖ along its direction. A step that does not lower (1) is refused and μ
//! raised fourfold; one that does is taken and μ lowered threefold. The rounds stop when a taken
//! step lowers (1) by less than [`OPTIMISE_STOP`] of it, or to below [`OPTIMISE_FLOOR`] of where
//! it began (a fit exact to rounding), or when μ has grown beyond [`OPTIMISE_MAX_DAMPING`] (no
//! step lowers it), or after [`OptimiseOptions::rounds`]; μ starts at [`OPTIMISE_DAMPING`] and stays above
//! [`OPTIMISE_LEAST_DAMPING`]; τ is [`OPTIMISE_TAU`] of the mean of diag(JᵀJ + λ(M/N)·F).
//!
//! What the optimisation lowers is the deviation of the path's own sweep; what a machinist signs
//! off is the program's (`post()`'s `deviation`), which the post keeps within its chordal
//! tolerance of the path's: the book's suite measures both.

use crate::sweep::{envelope_deviation, slerp, tool_distance, EnvelopeDeviation};
use crate::tolerance::{
    MAX_OPTIMISE_ROUNDS, OPTIMISE_DAMPING, OPTIMISE_FAIRNESS, OPTIMISE_FLOOR, OPTIMISE_GRADIENT_STEP,
    OPTIMISE_LEAST_DAMPING, OPTIMISE_MAX_DAMPING, OPTIMISE_ROUNDS, OPTIMISE_STOP, OPTIMISE_TAU,
};
use crate::{Pose, ToolPath};
use glam::DVec3;
use ruledlab::{Error, Result, RuledSurface, SymmetricBanded};

/// Options of [`optimise_poses`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OptimiseOptions {
    /// The fairness weight λ of (1) (default [`OPTIMISE_FAIRNESS`]), ≥ 0.
    pub fairness: f64,
    /// Most rounds of Levenberg–Marquardt steps (default [`OPTIMISE_ROUNDS`], at most
    /// [`MAX_OPTIMISE_ROUNDS`]).
    pub rounds: usize,
}

impl Default for OptimiseOptions {
    fn default() -> Self {
        OptimiseOptions { fairness: OPTIMISE_FAIRNESS, rounds: OPTIMISE_ROUNDS }
    }
}

/// The optimised poses and what they changed.
#[derive(Debug, Clone, PartialEq)]
pub struct Optimised {
    /// The optimised path (the same tool, as many poses).
    pub path: ToolPath,
    /// The deviation of the target from the given path's own sweep.
    pub before: EnvelopeDeviation,
    /// The deviation of the target from the optimised path's own sweep.
    pub after: EnvelopeDeviation,
    /// The energy (1) of the given and of the optimised poses.
    pub energy: (f64, f64),
    /// Rounds taken: the steps tried, the refused ones among them.
    pub rounds: usize,
}

/// The ruling-aligned poses of a flank cut of `rulings` (each from its foot a to its end b):
/// the tool's axis along the ruling, its tip the foot moved by the tool's radius along the unit
/// normal n = ±(m′ × (b − a))/|…| at the ruling's midpoint m (m′ the difference of the neighbours'
/// midpoints, one-sided at the ends), `+` where `side` > 0. On a developable surface the tool's
/// side touches the part along the ruling; on any other it cuts into it or leaves material.
pub fn ruling_aligned(rulings: &RuledSurface, tool: crate::Tool, side: f64) -> ToolPath {
    let segments: Vec<_> = rulings.segments().collect();
    let mid: Vec<DVec3> = segments.iter().map(|s| 0.5 * (s.a + s.b)).collect();
    let n = segments.len();
    let sign = if side < 0.0 { -1.0 } else { 1.0 };
    let poses = (0..n)
        .map(|k| {
            let (lo, hi) = (k.saturating_sub(1), (k + 1).min(n - 1));
            let along = mid[hi] - mid[lo];
            let d = segments[k].b - segments[k].a;
            let normal = sign * along.cross(d).normalize();
            Pose { tip: segments[k].a + tool.radius * normal, axis: d.normalize() }
        })
        .collect();
    ToolPath { poses, tool }
}

/// The fairness term of (1) as its matrix F (xᵀF x = Σ |Δ²P|² + |Δ²Q|²), added with weight `w`
/// into `h` and w·F x into `g`.
fn add_fairness(h: &mut SymmetricBanded, g: &mut [f64], x: &[DVec3], w: f64) {
    let n = x.len() / 2;
    for k in 1..n.saturating_sub(1) {
        let poses = [k - 1, k, k + 1];
        let c = [1.0, -2.0, 1.0];
        for end in 0..2 {
            let second = c.iter().zip(poses).fold(DVec3::ZERO, |s, (c, p)| s + *c * x[2 * p + end]);
            for (ca, pa) in c.iter().zip(poses) {
                for comp in 0..3 {
                    let i = 6 * pa + 3 * end + comp;
                    g[i] += w * ca * second[comp];
                    for (cb, pb) in c.iter().zip(poses) {
                        let j = 6 * pb + 3 * end + comp;
                        if j <= i {
                            h.add(i, j, w * ca * cb);
                        }
                    }
                }
            }
        }
    }
}

/// Σ |Δ²P|² + |Δ²Q|² of the unknowns (P₀, Q₀, P₁, Q₁, …).
fn fairness(x: &[DVec3]) -> f64 {
    let n = x.len() / 2;
    (1..n.saturating_sub(1))
        .map(|k| {
            (0..2).map(|e| (x[2 * k - 2 + e] - 2.0 * x[2 * k + e] + x[2 * k + 2 + e]).length_squared()).sum::<f64>()
        })
        .sum()
}

/// The path of the unknowns: tip Pₖ, axis (Qₖ − Pₖ)/|Qₖ − Pₖ|.
fn path_of(x: &[DVec3], like: &ToolPath) -> ToolPath {
    let poses = x.chunks_exact(2).map(|pq| Pose { tip: pq[0], axis: (pq[1] - pq[0]).normalize() }).collect();
    ToolPath { poses, tool: like.tool }
}

/// The gradient of the signed distance from the tool at `p` with respect to the point `q`, by
/// central differences (it is the unit direction from the tool's surface to q, whichever part
/// of the tool is nearest).
fn distance_gradient(q: DVec3, p: &Pose, path: &ToolPath) -> DVec3 {
    let t = path.tool;
    let h = OPTIMISE_GRADIENT_STEP * t.radius;
    let d = |v: DVec3| tool_distance(q + v, p, t.radius, t.length, t.end);
    DVec3::new(
        d(DVec3::X * h) - d(DVec3::X * -h),
        d(DVec3::Y * h) - d(DVec3::Y * -h),
        d(DVec3::Z * h) - d(DVec3::Z * -h),
    ) / (2.0 * h)
}

/// Optimises the poses of `path` against `targets` (points of the part, the path's units) by
/// minimising (1) (module documentation), telling `progress` the share of rounds done.
///
/// Errors: no target point, a coordinate not finite, fewer than two poses, a fairness weight not
/// finite or negative, rounds beyond [`MAX_OPTIMISE_ROUNDS`], or the system singular.
pub fn optimise_poses(
    path: &ToolPath,
    targets: &[DVec3],
    options: &OptimiseOptions,
    progress: &mut dyn FnMut(f64),
) -> Result<Optimised> {
    let n = path.poses.len();
    if n < 2 {
        return Err(Error::TooFew { what: "poses", got: n, min: 2 });
    }
    if targets.is_empty() {
        return Err(Error::TooFew { what: "target points", got: 0, min: 1 });
    }
    if let Some(i) = targets.iter().position(|q| !q.is_finite()) {
        return Err(Error::parameter("targets", format!("target point {i} is not finite")));
    }
    if let Some(i) = path.poses.iter().position(|p| !(p.tip.is_finite() && p.axis.is_finite())) {
        return Err(Error::parameter("poses", format!("pose {i} is not finite")));
    }
    if !(options.fairness.is_finite() && options.fairness >= 0.0) {
        return Err(Error::parameter(
            "fairness",
            format!("the fairness weight must be a number ≥ 0, got {}", options.fairness),
        ));
    }
    if options.rounds > MAX_OPTIMISE_ROUNDS {
        return Err(Error::parameter(
            "rounds",
            format!("at most {MAX_OPTIMISE_ROUNDS} rounds, got {}", options.rounds),
        ));
    }
    let length = path.tool.length;
    let mut x: Vec<DVec3> = path.poses.iter().flat_map(|p| [p.tip, p.tip + length * p.axis]).collect();
    let start = x.clone();
    // how far the unknowns moved from the given poses: the fairness term's argument
    let offset = |x: &[DVec3]| -> Vec<DVec3> { x.iter().zip(&start).map(|(a, b)| *a - *b).collect() };
    let weight = options.fairness * targets.len() as f64 / n as f64;
    let energy = |d: &EnvelopeDeviation, x: &[DVec3]| -> f64 {
        d.points.iter().map(|v| v * v).sum::<f64>() + weight * fairness(&offset(x))
    };
    let before = envelope_deviation(path, targets);
    let mut current = before.clone();
    let mut e = energy(&current, &x);
    let first = e;
    if e == 0.0 {
        progress(1.0);
        return Ok(Optimised { path: path.clone(), before, after: current, energy: (e, e), rounds: 0 });
    }
    let mut mu = OPTIMISE_DAMPING;
    let mut rounds = 0;
    let dim = 6 * n;
    let mut moved = false;
    'rounds: while rounds < options.rounds {
        progress(rounds as f64 / options.rounds as f64);
        let now = path_of(&x, path);
        let blocks = n - 1;
        let mut h = SymmetricBanded::zeros(dim, 17);
        let mut g = vec![0.0; dim];
        for (i, &q) in targets.iter().enumerate() {
            let k = (current.at[i].floor().max(0.0) as usize).min(blocks - 1);
            let s = (current.at[i] - k as f64).clamp(0.0, 1.0);
            let (a, b) = (now.poses[k], now.poses[k + 1]);
            let pose = Pose { tip: a.tip.lerp(b.tip, s), axis: slerp(a.axis, b.axis, s) };
            let grad = distance_gradient(q, &pose, &now);
            let t = ((q - pose.tip).dot(pose.axis) / length).clamp(0.0, 1.0);
            // (2): the weights of Pₖ, Qₖ, Pₖ₊₁, Qₖ₊₁ times −g
            let weights = [
                (2 * k, (1.0 - s) * (1.0 - t)),
                (2 * k + 1, (1.0 - s) * t),
                (2 * k + 2, s * (1.0 - t)),
                (2 * k + 3, s * t),
            ];
            let r = current.points[i];
            for &(ua, wa) in &weights {
                for ca in 0..3 {
                    let ia = 3 * ua + ca;
                    let ja = -wa * grad[ca];
                    g[ia] += ja * r;
                    for &(ub, wb) in &weights {
                        for cb in 0..3 {
                            let ib = 3 * ub + cb;
                            if ib <= ia {
                                h.add(ia, ib, ja * -wb * grad[cb]);
                            }
                        }
                    }
                }
            }
        }
        add_fairness(&mut h, &mut g, &offset(&x), weight);
        // Marquardt's damping, and τ for the unknowns no target point reaches
        let diagonal: Vec<f64> = (0..dim).map(|i| h.get(i, i)).collect();
        let tau = OPTIMISE_TAU * diagonal.iter().sum::<f64>() / dim as f64 + f64::MIN_POSITIVE;
        // each step tried is a round
        while rounds < options.rounds {
            rounds += 1;
            let mut damped = h.clone();
            for (i, d) in diagonal.iter().enumerate() {
                damped.add(i, i, mu * (d + tau));
            }
            let mut step: Vec<[f64; 1]> = g.iter().map(|v| [-v]).collect();
            damped.factor()?.solve(&mut step);
            let mut trial: Vec<DVec3> = x
                .iter()
                .enumerate()
                .map(|(u, p)| *p + DVec3::new(step[3 * u][0], step[3 * u + 1][0], step[3 * u + 2][0]))
                .collect();
            for pq in trial.chunks_exact_mut(2) {
                pq[1] = pq[0] + length * (pq[1] - pq[0]).normalize();
            }
            let candidate = envelope_deviation(&path_of(&trial, path), targets);
            let e_trial = energy(&candidate, &trial);
            if e_trial.is_finite() && e_trial < e {
                let gain = (e - e_trial) / e;
                (x, current, e, moved) = (trial, candidate, e_trial, true);
                mu = (mu / 3.0).max(OPTIMISE_LEAST_DAMPING);
                if gain < OPTIMISE_STOP || e < OPTIMISE_FLOOR * first {
                    break 'rounds;
                }
                continue 'rounds;
            }
            mu *= 4.0;
            if mu > OPTIMISE_MAX_DAMPING {
                break 'rounds;
            }
            progress(rounds as f64 / options.rounds as f64);
        }
    }
    progress(1.0);
    let path = if moved { path_of(&x, path) } else { path.clone() };
    Ok(Optimised { path, before, after: current, energy: (first, e), rounds })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tolerance::OPTIMISE_FAIRNESS;
    use crate::{Tool, ToolEnd};
    use ruledlab::Segment;

    /// The plane y = 0 as 11 vertical rulings 10 long over x ∈ [0, 10], and its points a tenth
    /// to nine tenths up, between the rulings.
    fn plane() -> (RuledSurface, Vec<DVec3>) {
        let rulings = RuledSurface::new(
            (0..=10).map(|k| Segment::new(DVec3::new(k as f64, 0.0, 0.0), DVec3::new(k as f64, 0.0, 10.0))).collect(),
        )
        .unwrap();
        let targets =
            (0..40).flat_map(|i| (1..=9).map(move |j| DVec3::new(0.125 + 0.25 * i as f64, 0.0, j as f64))).collect();
        (rulings, targets)
    }

    /// On a plane (developable) the ruling-aligned tool stands r off it along the normal, its
    /// side on the plane: nothing to optimise, and the poses come back as they were.
    #[test]
    fn on_a_plane_the_ruling_aligned_poses_touch_and_stay() {
        let (rulings, targets) = plane();
        for end in [ToolEnd::Flat, ToolEnd::Ball] {
            let tool = Tool::new(0.5, 12.0, end).unwrap();
            let path = ruling_aligned(&rulings, tool, -1.0);
            for (k, p) in path.poses.iter().enumerate() {
                assert!((p.tip - DVec3::new(k as f64, 0.5, 0.0)).length() < 1e-15, "{end:?} {k}: {}", p.tip);
                assert_eq!(p.axis, DVec3::Z);
            }
            let flipped = ruling_aligned(&rulings, tool, 1.0);
            assert!((flipped.poses[3].tip - DVec3::new(3.0, -0.5, 0.0)).length() < 1e-15);
            let o = optimise_poses(&path, &targets, &OptimiseOptions::default(), &mut |_| {}).unwrap();
            assert!(o.before.points.iter().all(|d| d.abs() < 1e-12), "{end:?}: {:?}", o.before.gouge);
            assert!(o.energy.1 <= o.energy.0 && o.after.rms <= 1e-12, "{end:?}");
            for (a, b) in o.path.poses.iter().zip(&path.poses) {
                assert!((a.tip - b.tip).length() < 1e-9 && (a.axis - b.axis).length() < 1e-9, "{end:?}");
            }
        }
    }

    /// Poses moved off the plane — pushed 0.2 away, tilted 5° about x and 3° about y, each a
    /// little differently — are brought back onto it: the deviation falls from about 1 to below
    /// 1 µm of the 10-long flank with little fairness, below 5 µm with the default (which holds the
    /// uneven push back against its unevenness; 2.9 µm measured), the energy by 10⁴ or more. The
    /// tool's length is kept.
    #[test]
    fn poses_moved_off_a_plane_are_brought_back() {
        let (rulings, targets) = plane();
        for (end, fairness, within) in [
            (ToolEnd::Flat, 1e-4, 1e-3),
            (ToolEnd::Ball, 1e-4, 1e-3),
            (ToolEnd::Flat, OPTIMISE_FAIRNESS, 5e-3),
            (ToolEnd::Ball, OPTIMISE_FAIRNESS, 5e-3),
        ] {
            let tool = Tool::new(0.5, 12.0, end).unwrap();
            let mut path = ruling_aligned(&rulings, tool, -1.0);
            for (k, p) in path.poses.iter_mut().enumerate() {
                let wobble = (k as f64).sin();
                p.tip.y += 0.2 + 0.05 * wobble;
                p.axis = (DVec3::Z + DVec3::new((3f64 + wobble).to_radians().tan(), 5f64.to_radians().tan(), 0.0))
                    .normalize();
            }
            let mut shares = Vec::new();
            let options = OptimiseOptions { rounds: 60, fairness };
            let o = optimise_poses(&path, &targets, &options, &mut |f| shares.push(f)).unwrap();
            let largest = |d: &EnvelopeDeviation| d.gouge.abs().max(d.leave);
            assert!(largest(&o.before) > 0.5, "{end:?}: {}", largest(&o.before));
            assert!(largest(&o.after) < within, "{end:?} {fairness}: {} after {} rounds", largest(&o.after), o.rounds);
            assert!(o.energy.1 < 1e-4 * o.energy.0, "{end:?}: {:?}", o.energy);
            assert_eq!(o.path.poses.len(), path.poses.len());
            assert_eq!(o.path.tool, tool);
            assert!(o.path.poses.iter().all(|p| (p.axis.length() - 1.0).abs() < 1e-12));
            // what the optimisation says of its poses is their sweep's deviation
            assert_eq!(o.after, envelope_deviation(&o.path, &targets));
            // progress: from 0, never back, to 1
            assert_eq!(shares.first(), Some(&0.0));
            assert_eq!(shares.last(), Some(&1.0));
            assert!(shares.windows(2).all(|w| w[0] <= w[1]), "{shares:?}");
        }
    }

    /// The fairness term's matrix and gradient are those of Σ |Δ²P|² + |Δ²Q|² (its gradient is
    /// twice F x, its value xᵀF x), checked on arbitrary points.
    #[test]
    fn the_fairness_term_is_its_quadratic_form() {
        let x: Vec<DVec3> =
            (0..10).map(|i| DVec3::new((i as f64).sin(), (i * i) as f64 * 0.1, (i as f64).cos())).collect();
        let mut h = SymmetricBanded::zeros(30, 17);
        let mut g = vec![0.0; 30];
        add_fairness(&mut h, &mut g, &x, 1.0);
        let flat: Vec<f64> = x.iter().flat_map(|p| p.to_array()).collect();
        let fx: Vec<f64> = (0..30).map(|i| (0..30).map(|j| h.get(i, j) * flat[j]).sum()).collect();
        let quadratic: f64 = flat.iter().zip(&fx).map(|(a, b)| a * b).sum();
        assert!((quadratic - fairness(&x)).abs() < 1e-12 * fairness(&x), "{quadratic} {}", fairness(&x));
        for i in 0..30 {
            assert!((g[i] - fx[i]).abs() < 1e-12, "{i}: {} {}", g[i], fx[i]);
            // against central differences of the energy: ∂/∂xᵢ (xᵀF x) = 2(F x)ᵢ
            let h = 1e-6;
            let mut up = x.clone();
            let mut down = x.clone();
            up[i / 3][i % 3] += h;
            down[i / 3][i % 3] -= h;
            let numeric = (fairness(&up) - fairness(&down)) / (2.0 * h);
            assert!((numeric - 2.0 * fx[i]).abs() < 1e-6, "{i}: {numeric} {}", 2.0 * fx[i]);
        }
    }

    #[test]
    fn bad_input_is_refused() {
        let (rulings, targets) = plane();
        let path = ruling_aligned(&rulings, Tool::new(0.5, 12.0, ToolEnd::Flat).unwrap(), -1.0);
        let run = |p: &ToolPath, t: &[DVec3], o: OptimiseOptions| optimise_poses(p, t, &o, &mut |_| {});
        let d = OptimiseOptions::default();
        assert_eq!(run(&path, &[], d).unwrap_err().code(), "too-small");
        let mut bad = targets.clone();
        bad[7].x = f64::NAN;
        assert!(run(&path, &bad, d).unwrap_err().to_string().contains("target point 7"));
        let short = ToolPath { poses: path.poses[..1].to_vec(), tool: path.tool };
        assert_eq!(run(&short, &targets, d).unwrap_err().code(), "too-small");
        for fairness in [-1.0, f64::NAN, f64::INFINITY] {
            let e = run(&path, &targets, OptimiseOptions { fairness, ..d }).unwrap_err();
            assert!(e.to_string().contains("fairness"), "{e}");
        }
        let e = run(&path, &targets, OptimiseOptions { rounds: MAX_OPTIMISE_ROUNDS + 1, ..d }).unwrap_err();
        assert!(e.to_string().contains("rounds"), "{e}");
        // no round: the poses as given
        let o = run(&path, &targets, OptimiseOptions { rounds: 0, ..d }).unwrap();
        assert_eq!((o.path, o.rounds), (path, 0));
    }
}
