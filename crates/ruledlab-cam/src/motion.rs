//! How long each block of a G-code program takes (Example 6's paths on a real machine): the
//! feed at the tool tip, slowed wherever a machine axis would move faster than its speed
//! limit, change its speed faster than its acceleration limit, or the controller's feed word
//! would leave its range.
//!
//! A block moves the five axes (X, Y, Z in mm, the rotary axes in degrees) by Δ_k. At the feed
//! F at the tip over the tip's distance d it takes T₀ = d / F minutes; an axis with speed limit
//! v_k needs at least |Δ_k| / v_k, and a controller whose feed word must stay below F_max (a
//! Heidenhain TNC: 99 999.999) needs at least the block's measure in that word over F_max. The
//! block takes the largest of these. Between two blocks an axis changes its speed from
//! Δ_k/T_i to Δ_k'/T_{i+1} over about (T_i + T_{i+1})/2; where that needs more than its
//! acceleration limit, both blocks are slowed by the square root of the excess (speeds scale
//! with 1/s, accelerations with 1/s²), in up to [`ACCELERATION_PASSES`] passes; what still
//! exceeds it then is reported, not hidden.

use crate::kinematics::Joints;
use crate::machine::Machine;

/// Passes of slowing for the acceleration limits.
pub const ACCELERATION_PASSES: usize = 8;

/// What set a block's time.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Limit {
    /// The feed at the tip.
    #[default]
    Feed,
    /// An axis's speed limit (0–2: X, Y, Z; 3, 4: the rotary axes in the machine's order).
    Speed(usize),
    /// An axis's acceleration limit.
    Acceleration(usize),
    /// The range of the controller's feed word.
    FeedWord,
}

impl Limit {
    /// A small number for programs: 0 the feed, 1 a speed limit, 2 an acceleration limit, 3 the
    /// feed word.
    pub fn code(self) -> u8 {
        match self {
            Limit::Feed => 0,
            Limit::Speed(_) => 1,
            Limit::Acceleration(_) => 2,
            Limit::FeedWord => 3,
        }
    }

    /// The axis that set it (0–4), if one did.
    pub fn axis(self) -> Option<usize> {
        match self {
            Limit::Speed(k) | Limit::Acceleration(k) => Some(k),
            _ => None,
        }
    }
}

/// One block's motion.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BlockMotion {
    /// Its time, minutes.
    pub minutes: f64,
    /// What set it.
    pub limit: Limit,
    /// The axes' moves: X, Y, Z (mm) and the rotary axes (degrees).
    pub delta: [f64; 5],
    /// Whether an acceleration limit is still exceeded at its end after the passes.
    pub over: bool,
}

impl BlockMotion {
    /// The speed of axis k, units per minute.
    pub fn speed(&self, k: usize) -> f64 {
        if self.minutes > 0.0 {
            self.delta[k].abs() / self.minutes
        } else {
            0.0
        }
    }
}

/// The speed limits of the five axes (units per minute), `None` where there is none.
pub fn speed_limits(m: &Machine) -> [Option<f64>; 5] {
    let xyz = m.speed.map_or([None; 3], |s| s.map(Some));
    [xyz[0], xyz[1], xyz[2], m.rotary[0].speed, m.rotary[1].speed]
}

/// The acceleration limits of the five axes (units per second²).
pub fn acceleration_limits(m: &Machine) -> [Option<f64>; 5] {
    let xyz = m.acceleration.map_or([None; 3], |s| s.map(Some));
    [xyz[0], xyz[1], xyz[2], m.rotary[0].acceleration, m.rotary[1].acceleration]
}

/// What a block asks of the controller: its ends' axis values, the tip's distance (or the far
/// end's, for a still tip), and the measure of its feed word where that word is bounded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlockNeed {
    /// Axis values at its start.
    pub from: Joints,
    /// And at its end.
    pub to: Joints,
    /// The distance the feed applies to, mm.
    pub distance: f64,
    /// The quantity the controller's feed word divides by the time (mm or degrees), with that
    /// word's largest value; `None` where the word is not bounded.
    pub word: Option<(f64, f64)>,
}

/// The motion of every block at `feed` (mm/min at the tip) on `m`.
pub fn time_blocks(m: &Machine, blocks: &[BlockNeed], feed: f64) -> Vec<BlockMotion> {
    let speeds = speed_limits(m);
    let mut out: Vec<BlockMotion> = blocks
        .iter()
        .map(|b| {
            let d = b.to.xyz - b.from.xyz;
            let delta = [d.x, d.y, d.z, b.to.rotary[0] - b.from.rotary[0], b.to.rotary[1] - b.from.rotary[1]];
            let mut motion = BlockMotion { minutes: b.distance / feed, limit: Limit::Feed, delta, over: false };
            for (k, v) in speeds.iter().enumerate() {
                if let Some(v) = v {
                    let t = delta[k].abs() / v;
                    if t > motion.minutes {
                        (motion.minutes, motion.limit) = (t, Limit::Speed(k));
                    }
                }
            }
            if let Some((measure, max)) = b.word {
                let t = measure / max;
                if t > motion.minutes {
                    (motion.minutes, motion.limit) = (t, Limit::FeedWord);
                }
            }
            motion
        })
        .collect();
    accelerate(&mut out, &acceleration_limits(m));
    out
}

/// The change of speed of axis k at the junction of blocks a and b, units per second².
fn acceleration(a: &BlockMotion, b: &BlockMotion, k: usize) -> f64 {
    let (ta, tb) = (a.minutes * 60.0, b.minutes * 60.0);
    if ta <= 0.0 || tb <= 0.0 {
        return 0.0;
    }
    (b.delta[k] / tb - a.delta[k] / ta).abs() / (0.5 * (ta + tb))
}

/// Slows blocks whose junctions need more than an axis's acceleration (module documentation).
fn accelerate(blocks: &mut [BlockMotion], limits: &[Option<f64>; 5]) {
    for _ in 0..ACCELERATION_PASSES {
        let mut changed = false;
        for i in 1..blocks.len() {
            for (k, limit) in limits.iter().enumerate() {
                let Some(limit) = limit else { continue };
                let need = acceleration(&blocks[i - 1], &blocks[i], k);
                if need > limit * (1.0 + 1e-9) {
                    let s = (need / limit).sqrt() * (1.0 + 1e-12);
                    for b in [i - 1, i] {
                        blocks[b].minutes *= s;
                        blocks[b].limit = Limit::Acceleration(k);
                    }
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
    for i in 1..blocks.len() {
        let over = limits
            .iter()
            .enumerate()
            .any(|(k, l)| l.is_some_and(|l| acceleration(&blocks[i - 1], &blocks[i], k) > l * (1.0 + 1e-6)));
        blocks[i].over = over;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;
    use ruledlab::assert_near;

    fn joints(x: f64, c: f64) -> Joints {
        Joints { xyz: DVec3::new(x, 0.0, 0.0), rotary: [0.0, c] }
    }

    fn need(from: Joints, to: Joints, distance: f64) -> BlockNeed {
        BlockNeed { from, to, distance, word: None }
    }

    /// table-table-ac: C at most 10 800°/min. A block of 1 mm at 1000 mm/min takes 0.001 min;
    /// turning C by 90° it needs 90/10800 = 0.00833 min; X alone at 30 000 mm/min: 0.6 mm at
    /// 1000 is 0.0006 min, 600 mm would be 0.02 min at least.
    #[test]
    fn a_block_takes_the_longest_of_its_axes_times() {
        let mut m = Machine::preset("table-table-ac").unwrap();
        m.acceleration = None;
        m.rotary = m.rotary.map(|r| crate::machine::RotaryAxis { acceleration: None, ..r });
        let b = time_blocks(
            &m,
            &[
                need(joints(0.0, 0.0), joints(1.0, 0.0), 1.0),
                need(joints(1.0, 0.0), joints(2.0, 90.0), 1.0),
                need(joints(2.0, 90.0), joints(602.0, 90.0), 600.0),
            ],
            1000.0,
        );
        assert_eq!((b[0].minutes, b[0].limit), (0.001, Limit::Feed));
        assert_eq!((b[1].minutes, b[1].limit), (90.0 / 10800.0, Limit::Speed(4)));
        assert_eq!((b[2].minutes, b[2].limit), (0.6, Limit::Feed));
        assert!((b[1].speed(4) - 10800.0).abs() < 1e-9);
        // a feed word of at most 99 999.999 for 500 mm: 0.005 min at least
        let w = time_blocks(
            &m,
            &[BlockNeed { word: Some((500.0, 99_999.999)), ..need(joints(0.0, 0.0), joints(0.1, 0.0), 0.1) }],
            1000.0,
        );
        assert_eq!((w[0].minutes, w[0].limit), (500.0 / 99_999.999, Limit::FeedWord));
        // no limits: the feed alone
        let mut free = m.clone();
        free.speed = None;
        free.rotary = free.rotary.map(|r| crate::machine::RotaryAxis { speed: None, ..r });
        assert_eq!(time_blocks(&free, &[need(joints(0.0, 0.0), joints(0.0, 90.0), 1.0)], 1000.0)[0].limit, Limit::Feed);
    }

    /// C reverses at full speed between two blocks: 6 000°/min = 100°/s each way over 0.1 s
    /// blocks needs 200/0.1 = 2000°/s²; with 500°/s² both blocks are slowed by √4 = 2 (then
    /// 50°/s each way over 0.2 s: 500°/s², at the limit).
    #[test]
    fn a_reversal_beyond_the_acceleration_is_slowed() {
        let m = c_limited(500.0);
        // 10 mm at 6000 mm/min: 0.1 s; C +10°, then −10°
        let b = time_blocks(
            &m,
            &[need(joints(0.0, 0.0), joints(10.0, 10.0), 10.0), need(joints(10.0, 10.0), joints(20.0, 0.0), 10.0)],
            6000.0,
        );
        for x in &b {
            assert!((x.minutes * 60.0 - 0.2).abs() < 1e-9, "{x:?}");
            assert_eq!(x.limit, Limit::Acceleration(4));
            assert!(!x.over);
        }
        assert!((acceleration(&b[0], &b[1], 4) - 500.0).abs() < 1e-6);
    }

    #[test]
    fn each_limit_has_its_code_and_axis() {
        let cases = [
            (Limit::Feed, 0, None),
            (Limit::Speed(3), 1, Some(3)),
            (Limit::Acceleration(4), 2, Some(4)),
            (Limit::FeedWord, 3, None),
        ];
        for (limit, code, axis) in cases {
            assert_eq!((limit.code(), limit.axis()), (code, axis), "{limit:?}");
        }
        // a block of no time has no speed and no acceleration at its junctions
        let still = BlockMotion { delta: [1.0, 0.0, 0.0, 0.0, 10.0], ..BlockMotion::default() };
        assert_eq!(still.speed(0), 0.0);
        let moving = BlockMotion { minutes: 0.01, delta: [0.0, 0.0, 0.0, 0.0, -10.0], ..BlockMotion::default() };
        assert_eq!((acceleration(&still, &moving, 4), acceleration(&moving, &still, 4)), (0.0, 0.0));
    }

    /// The feed word's time equal to the feed's (100 in a word of at most 100 000: 0.001 min,
    /// as 1 mm at 1000 mm/min): the feed set it, the word did not.
    #[test]
    fn a_tie_with_the_feed_is_the_feeds() {
        let mut m = Machine::preset("table-table-ac").unwrap();
        m.acceleration = None;
        m.rotary = m.rotary.map(|r| crate::machine::RotaryAxis { acceleration: None, ..r });
        let b = BlockNeed { word: Some((100.0, 100_000.0)), ..need(joints(0.0, 0.0), joints(1.0, 0.0), 1.0) };
        assert_eq!(
            time_blocks(&m, &[b], 1000.0)[0],
            BlockMotion { minutes: 0.001, delta: [1.0, 0.0, 0.0, 0.0, 0.0], ..BlockMotion::default() }
        );
    }

    /// table-table-ac with no limit but C's acceleration.
    fn c_limited(acceleration: f64) -> Machine {
        let mut m = Machine::preset("table-table-ac").unwrap();
        m.speed = None;
        m.acceleration = None;
        m.rotary[0].speed = None;
        m.rotary[0].acceleration = None;
        m.rotary[1].speed = None;
        m.rotary[1].acceleration = Some(acceleration);
        m
    }

    /// A junction that needs its axis's acceleration exactly is not slowed; one that needs half a
    /// unit more is, by the square root of the excess and a hair (1e-12) more, so that it then
    /// needs at most the limit.
    #[test]
    fn a_junction_is_slowed_only_beyond_the_limit_and_then_within_it() {
        let blocks =
            [need(joints(0.0, 0.0), joints(10.0, 10.0), 10.0), need(joints(10.0, 10.0), joints(20.0, 0.0), 10.0)];
        let free = time_blocks(&c_limited(1e9), &blocks, 6000.0);
        let need = acceleration(&free[0], &free[1], 4);
        assert_near!(need, 2000.0, 1e-9);
        assert_eq!(time_blocks(&c_limited(need), &blocks, 6000.0), free);
        let slowed = time_blocks(&c_limited(need - 0.5), &blocks, 6000.0);
        let s = (need / (need - 0.5)).sqrt() * (1.0 + 1e-12);
        for (x, f) in slowed.iter().zip(&free) {
            assert_eq!((x.minutes, x.limit), (f.minutes * s, Limit::Acceleration(4)));
        }
        assert!(acceleration(&slowed[0], &slowed[1], 4) <= need - 0.5);
    }

    /// Slowing a junction changes the one before it: passes until none needs more (three
    /// blocks C +8°, +2°, +8° over 20, 6 and 20 mm at 100°/s²: within 1e-6 of the limit, none
    /// over); where eight passes do not settle it (20, 6 and 15 mm) the block after the junction
    /// still over is marked, and only that one.
    #[test]
    fn the_passes_settle_the_junctions_or_say_where_they_do_not() {
        let m = c_limited(100.0);
        let chain = |d: [f64; 3]| {
            let c = [0.0, 8.0, 10.0, 18.0];
            (0..3).map(|i| need(joints(i as f64, c[i]), joints(i as f64 + 1.0, c[i + 1]), d[i])).collect::<Vec<_>>()
        };
        let settled = time_blocks(&m, &chain([20.0, 6.0, 20.0]), 6000.0);
        assert!(settled.iter().all(|b| !b.over));
        for i in 1..3 {
            assert!(acceleration(&settled[i - 1], &settled[i], 4) <= 100.0 * (1.0 + 1e-6));
        }
        let unsettled = time_blocks(&m, &chain([20.0, 6.0, 15.0]), 6000.0);
        assert_eq!(unsettled.iter().map(|b| b.over).collect::<Vec<_>>(), [false, true, false]);
        let worst = acceleration(&unsettled[0], &unsettled[1], 4);
        assert!(worst > 100.0 * (1.0 + 1e-6) && worst < 100.01, "{worst}");
    }
}
