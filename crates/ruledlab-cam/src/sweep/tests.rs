//! The sweep's tests: closed forms where the axis is held, and ≥ 10⁴ samples a block (brute
//! force) where it turns, in every way a controller interpolates.

use super::*;
use crate::Tool;
use std::f64::consts::PI;

/// The least over every block of the distance at `SAMPLES` + 1 evenly spaced s: the brute-force
/// reference.
const SAMPLES: usize = 10_000;

fn brute_force(m: &Machine, gauge: f64, tool: &Tool, blocks: &[SweptBlock], q: DVec3) -> f64 {
    let mut best = f64::INFINITY;
    for b in blocks {
        for k in 0..=SAMPLES {
            let p = pose_at(m, gauge, b, k as f64 / SAMPLES as f64);
            best = best.min(tool_distance(q, &p, tool.radius, tool.length, tool.end));
        }
    }
    best
}

/// A ball end of radius r = 2 and length 20 around a circle: N = 24 poses, the ball's centre
/// on the circle of radius R = 30 at height h = 2 (the tip at 0), the axis vertical. The
/// machine cuts the chords, so the centre runs on the 24-gon. A target point q at angle φ
/// on the circle of radius R_t = 28 at height z_t = −1 lies nearest the chord whose middle
/// is at the angle m of φ's block: in that block's plane, at distance R cos(π/N) −
/// R_t cos(φ − m) across the chord and z_t − h below it, so its deviation is
/// √((R cos(π/N) − R_t cos(φ − m))² + (h − z_t)²) − r exactly. A flat end of the same size
/// with its tip at height h: its bottom disk sweeps the same chords, so the point is
/// √(max(0, R cos(π/N) − R_t cos(φ − m) − r)² + (h − z_t)²) from it.
#[test]
fn a_tool_around_a_circle_deviates_by_the_distance_in_closed_form() {
    let (n, big_r, r, h, rt, zt) = (24usize, 30.0, 2.0, 2.0, 28.0, -1.0);
    let poses = |tip_z: f64| -> Vec<Pose> {
        (0..=n)
            .map(|k| {
                let f = 2.0 * PI * k as f64 / n as f64;
                Pose { tip: DVec3::new(big_r * f.cos(), big_r * f.sin(), tip_z), axis: DVec3::Z }
            })
            .collect()
    };
    let ball = ToolPath { poses: poses(h - r), tool: Tool::new(r, 20.0, ToolEnd::Ball).unwrap() };
    let flat = ToolPath { poses: poses(h), tool: Tool::new(r, 20.0, ToolEnd::Flat).unwrap() };
    let phis: Vec<f64> = (0..50).map(|k| 0.123 + 2.0 * PI * k as f64 / 50.0).collect();
    let targets: Vec<DVec3> = phis.iter().map(|f| DVec3::new(rt * f.cos(), rt * f.sin(), zt)).collect();
    let block = 2.0 * PI / n as f64;
    let across = |f: f64| {
        let m = (f / block).floor() * block + block / 2.0;
        big_r * (PI / n as f64).cos() - rt * (f - m).cos()
    };
    let b = envelope_deviation(&ball, &targets);
    let fl = envelope_deviation(&flat, &targets);
    for (k, &f) in phis.iter().enumerate() {
        let want = across(f).hypot(h - zt) - r;
        assert!((b.points[k] - want).abs() < 1e-9, "ball at φ = {f}: {} vs {want}", b.points[k]);
        let want = (across(f) - r).max(0.0).hypot(h - zt);
        assert!((fl.points[k] - want).abs() < 1e-9, "flat at φ = {f}: {} vs {want}", fl.points[k]);
        // the nearest tool is in φ's block
        assert!((b.at[k] - f / block).abs() < 1.0, "{} vs {}", b.at[k], f / block);
    }
    // the worst point is where the chord is farthest from the target: φ at a block's end
    let worst = b.points[b.worst];
    assert!(b.points.iter().all(|d| d.abs() <= worst.abs()));
    // per pose: each pose's nearest target points, their largest deviation
    let per = b.per_pose(n + 1);
    assert_eq!(per.len(), n + 1);
    assert!(per.iter().filter(|d| d.is_finite()).count() >= n - 1);
    // a target inside the tool is cut into: negative
    let gouge = envelope_deviation(&ball, &[DVec3::new(big_r, 0.0, h)]);
    assert!((gouge.points[0] + r).abs() < 1e-12, "{}", gouge.points[0]);
}

/// A helix: the ball's centre on the helix (R cos t, R sin t, c t) with a vertical axis, the
/// target the helix's axis line point (0, 0, z): its distance from every centre is at least
/// R; with dense poses the deviation tends to R − r (to the chords' sag, R(1 − cos(π/N))).
#[test]
fn a_ball_along_a_helix_is_r_minus_its_radius_from_the_axis() {
    let (n, big_r, c, r) = (720usize, 10.0, 1.0, 1.5);
    let poses: Vec<Pose> = (0..=n)
        .map(|k| {
            let t = 4.0 * PI * k as f64 / n as f64;
            Pose { tip: DVec3::new(big_r * t.cos(), big_r * t.sin(), c * t - r), axis: DVec3::Z }
        })
        .collect();
    let path = ToolPath { poses, tool: Tool::new(r, 10.0, ToolEnd::Ball).unwrap() };
    let d = envelope_deviation(&path, &[DVec3::new(0.0, 0.0, 2.0 * PI * c)]);
    let sag = big_r * (1.0 - (PI / (n as f64 / 2.0)).cos());
    assert!(d.points[0] <= big_r - r + 1e-12 && d.points[0] >= big_r - r - sag - 1e-12, "{}", d.points[0]);
}

/// A path whose axis turns by up to 45° a block, both ends, every way of interpolating (machine
/// axes, angles, vectors) on a table–table machine: the search agrees with 10⁴ samples a block
/// within 1 µm (lengths in mm) and never finds less than they do by more than rounding.
#[test]
fn the_search_agrees_with_ten_thousand_samples_a_block() {
    let m = Machine::preset("table-table-ac").unwrap();
    let gauge = 40.0;
    let mut seed = 11;
    let mut u = || ruledlab::tolerance::test::uniform(&mut seed) * 2.0 - 1.0;
    // rotary values and tips of five poses; the poses are the kinematics' of them
    let joints: Vec<Joints> = (0..5)
        .map(|k| {
            let x = 6.0 * k as f64;
            Joints { xyz: DVec3::new(x, 2.0 * u(), 1.0 * u()), rotary: [20.0 * u(), 40.0 * k as f64 + 10.0 * u()] }
        })
        .collect();
    let poses: Vec<Pose> = joints.iter().map(|j| crate::forward_kinematics(&m, j, gauge)).collect();
    let lo = poses.iter().fold(DVec3::splat(f64::INFINITY), |a, p| a.min(p.tip));
    let hi = poses.iter().fold(DVec3::splat(f64::NEG_INFINITY), |a, p| a.max(p.tip + 10.0 * p.axis));
    for end in [ToolEnd::Ball, ToolEnd::Flat] {
        let tool = Tool::new(3.0, 12.0, end).unwrap();
        for how in [Move::Joints, Move::Angles, Move::Vector, Move::Straight] {
            let blocks: Vec<SweptBlock> = (1..poses.len())
                .map(|k| SweptBlock {
                    from: poses[k - 1],
                    to: poses[k],
                    joints: (joints[k - 1], joints[k]),
                    how,
                    start: (k - 1) as f64,
                    span: 1.0,
                })
                .collect();
            // the blocks start and end at their poses
            for b in &blocks {
                for (s, want) in [(0.0, b.from), (1.0, b.to)] {
                    let p = pose_at(&m, gauge, b, s);
                    assert!((p.tip - want.tip).length() < 1e-9, "{how:?}");
                    if how != Move::Straight || s == 0.0 {
                        assert!((p.axis - want.axis).length() < 1e-9, "{how:?}");
                    }
                }
            }
            let targets: Vec<DVec3> = (0..12)
                .map(|_| {
                    let t = DVec3::new(0.5 * (u() + 1.0), 0.5 * (u() + 1.0), 0.5 * (u() + 1.0));
                    lo + t * (hi - lo)
                })
                .collect();
            let fast = sweep_deviation(&m, gauge, &tool, &blocks, &targets, &mut |_| {});
            for (q, got) in targets.iter().zip(&fast.points) {
                let want = brute_force(&m, gauge, &tool, &blocks, *q);
                assert!(got - want <= 1e-3 && want - got <= 1e-3, "{end:?} {how:?} at {q}: {got} against {want}");
                assert!(*got <= want + 1e-12, "{end:?} {how:?} at {q}: {got} above the samples' {want}");
            }
        }
    }
}

/// The sums: gouge the least (or 0), leave the largest (or 0), the RMS, the worst point.
#[test]
fn gouge_leave_and_rms() {
    let d = summed(vec![0.5, -2.0, 1.0], vec![0.0; 3]);
    assert_eq!((d.gouge, d.leave, d.worst, d.largest()), (-2.0, 1.0, 1, -2.0));
    assert!((d.rms - (5.25f64 / 3.0).sqrt()).abs() < 1e-15);
    let d = summed(vec![0.5, 0.25], vec![0.0; 2]);
    assert_eq!((d.gouge, d.leave), (0.0, 0.5));
}

/// The signed distance from the tool in closed form: a ball as short as its radius is the ball
/// alone (|q − c| − r); inside a flat end's cylinder the distance is minus the depth to its
/// nearest side or end.
#[test]
fn the_distance_from_a_tool_is_signed() {
    let p = Pose { tip: DVec3::new(1.0, 2.0, 3.0), axis: DVec3::Z };
    let ball = |q: DVec3| tool_distance(p.tip + q, &p, 5.0, 5.0, ToolEnd::Ball);
    assert_eq!(ball(DVec3::new(0.0, 0.0, 5.0)), -5.0);
    assert_eq!(ball(DVec3::new(0.0, 7.0, 5.0)), 2.0);
    assert_eq!(ball(DVec3::new(0.0, 0.0, 13.0)), 3.0);
    let flat = |q: DVec3| tool_distance(p.tip + q, &p, 5.0, 20.0, ToolEnd::Flat);
    assert_eq!(flat(DVec3::new(2.0, 0.0, 10.0)), -3.0);
    assert_eq!(flat(DVec3::new(0.0, 0.0, 1.0)), -1.0);
    assert_eq!(flat(DVec3::new(8.0, 0.0, -4.0)), 5.0);
}

/// Per pose, the deviation of largest size among the points nearest it (the first of two of one
/// size), NaN where none is.
#[test]
fn per_pose_keeps_the_largest_deviation_near_each_pose() {
    let d = summed(vec![0.1, -0.3, 0.2, 0.2, -0.2], vec![0.0, 0.2, 0.4, 1.0, 1.1]);
    let per = d.per_pose(3);
    assert_eq!((per[0], per[1]), (-0.3, 0.2));
    assert!(per[2].is_nan());
}

/// Progress is said every fiftieth of the targets and at the end: 0, 0.02, …, 0.98, 1 for 100
/// targets; for 30 (fewer than 50), at every target.
#[test]
fn progress_is_said_fifty_times_and_at_the_end() {
    let tool = Tool::new(2.0, 20.0, ToolEnd::Ball).unwrap();
    let poses = vec![Pose { tip: DVec3::ZERO, axis: DVec3::Z }, Pose { tip: DVec3::X, axis: DVec3::Z }];
    let path = ToolPath { poses, tool };
    let m = Machine::preset("table-table-ac").unwrap();
    for (n, want) in [
        (100usize, (0..50).map(|k| k as f64 / 50.0).collect::<Vec<_>>()),
        (30, (0..30).map(|k| k as f64 / 30.0).collect()),
    ] {
        let targets: Vec<DVec3> = (0..n).map(|k| DVec3::new(k as f64, 5.0, 0.0)).collect();
        let mut said = Vec::new();
        sweep_deviation(&m, 20.0, &path.tool, &path_blocks(&path), &targets, &mut |f| said.push(f));
        assert_eq!(said.last(), Some(&1.0));
        said.pop();
        assert_eq!(said, want, "{n} targets");
    }
}

/// A straight block or a turn of the axis about a still tip, sampled with a ball r = 2 on a
/// cutter L = 5 (step 0.02·min(r, L) = 0.04). Straight, 10 along x with the axis held, from
/// o = (−4.5, 0.5, −2): 16 coarse moves of 0.625 make 10, so n = 10 / 0.04 = 250 samples,
/// each 0.04 on; the tool's ends fill the box o + [0, 10] × {0} × [0, 5] whose centre is
/// o + (5, 0, 2.5) = (0.5, 0.5, 0.5), farthest from it √(5² + 2.5²) (at both ends), so the
/// sphere's reach is that plus r plus the largest move. The turn from z
/// to x: the tip stands, the far end moves on the quarter circle of radius L, the coarse sum of
/// its 16 chords 32 L sin(π/64); each of the n samples' moves is the chord 2 L sin(π/(4n)).
#[test]
fn a_block_is_sampled_so_the_ends_move_at_most_the_step() {
    let m = Machine::preset("table-table-ac").unwrap();
    let tool = Tool::new(2.0, 5.0, ToolEnd::Ball).unwrap();
    let still = Joints { xyz: DVec3::ZERO, rotary: [0.0; 2] };
    let block =
        |from: Pose, to: Pose, how: Move| SweptBlock { from, to, joints: (still, still), how, start: 0.0, span: 1.0 };
    let up = |tip: DVec3| Pose { tip, axis: DVec3::Z };
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1.0);

    let o = DVec3::new(-4.5, 0.5, -2.0);
    let s = sample(&m, 5.0, &tool, &block(up(o), up(o + 10.0 * DVec3::X), Move::Straight));
    assert_eq!(s.poses.len(), 251);
    for (k, p) in s.poses.iter().enumerate() {
        assert!((p.tip - o - DVec3::new(0.04 * k as f64, 0.0, 0.0)).length() < 1e-12, "sample {k}: {}", p.tip);
    }
    assert!(s.moves.len() == 250 && s.moves.iter().all(|&d| close(d, 0.04)), "{:?}", &s.moves[..3]);
    assert!((s.centre - DVec3::splat(0.5)).length() < 1e-12, "{}", s.centre);
    assert!(close(s.reach, 31.25f64.sqrt() + 2.0 + 0.04), "{}", s.reach);

    let turn = block(up(DVec3::ZERO), Pose { tip: DVec3::ZERO, axis: DVec3::X }, Move::Vector);
    let s = sample(&m, 5.0, &tool, &turn);
    let n = (32.0 * 5.0 * (PI / 64.0).sin() / 0.04).ceil() as usize;
    assert_eq!(s.poses.len(), n + 1);
    let chord = 10.0 * (PI / (4.0 * n as f64)).sin();
    assert!(s.moves.iter().all(|&d| close(d, chord)), "{} against {chord}", s.moves[0]);
    assert!((s.centre - DVec3::new(2.5, 0.0, 2.5)).length() < 1e-12, "{}", s.centre);
    assert!(close(s.reach, 12.5f64.sqrt() + 2.0 + chord), "{}", s.reach);

    // 0.64 on is the coarse samples themselves; no motion, one sample step; a long block at most
    for (length, want) in [(0.64, 16), (0.0, 1), (1000.0, MAX_SWEEP_SAMPLES)] {
        let s = sample(&m, 5.0, &tool, &block(up(DVec3::ZERO), up(length * DVec3::Y), Move::Straight));
        assert_eq!(s.poses.len(), want + 1, "{length} on");
        let last = s.poses[want].tip;
        assert!((s.poses[1].tip - last / want as f64).length() < 1e-12, "{length} on: {}", s.poses[1].tip);
    }
}

/// Two blocks pass a target point on either side: in one a sample falls on the nearest pose
/// (1.00003 from it), in the other the nearest pose lies halfway between two samples, which are
/// √(0.02² + 3²) − 2 ≈ 1.0000667 from it though the pose between comes to 1. The second block's
/// samples look farther, yet it comes nearer: the search must refine it too (the slack), and
/// finds 1 in it.
#[test]
fn a_block_whose_samples_look_farther_is_refined_when_it_can_come_nearer() {
    let m = Machine::preset("table-table-ac").unwrap();
    let tool = Tool::new(2.0, 5.0, ToolEnd::Ball).unwrap();
    let still = Joints { xyz: DVec3::ZERO, rotary: [0.0; 2] };
    let along = |y: f64, x0: f64, start: f64| SweptBlock {
        from: Pose { tip: DVec3::new(x0 - 5.0, y, 0.0), axis: DVec3::Z },
        to: Pose { tip: DVec3::new(x0 + 5.0, y, 0.0), axis: DVec3::Z },
        joints: (still, still),
        how: Move::Straight,
        start,
        span: 1.0,
    };
    let q = DVec3::new(0.0, 0.0, 3.0);
    let on_sample = along(-3.00003, 0.0, 0.0);
    let between = along(3.0, 0.02, 1.0);
    for blocks in [[on_sample, between], [between, on_sample]] {
        let d = sweep_deviation(&m, 5.0, &tool, &blocks, &[q], &mut |_| {});
        assert!((d.points[0] - 1.0).abs() < 1e-9, "{}", d.points[0]);
        // where: the block passing at 3 (it starts at 1), 0.498 along it (its tip at x = 0)
        assert!((d.at[0] - 1.498).abs() < 1e-6, "{}", d.at[0]);
    }
}
