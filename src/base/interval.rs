//! Parameter intervals: the ranges a smooth surface is sampled over, the parameters of a
//! sampling, and the check of an interval typed by a user.

use crate::error::{Error, Message, Result};
use crate::tolerance::MAX_COORD;

/// Sampling ranges of a surface, for figures and examples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ranges {
    /// Parameter interval of the rulings.
    pub u: (f64, f64),
    /// Interval of v: the segments run from a + v₀d to a + v₁d.
    pub v: (f64, f64),
    /// Whether u wraps around (the surface is closed in u).
    pub closed: bool,
}

/// `count` equally spaced values in [u₀, u₁] (u₁ excluded when `closed`, so a closed surface
/// is not sampled twice at the seam): the parameters u_i of a sampling.
pub fn sample_parameters(count: usize, r: Ranges) -> Vec<f64> {
    let intervals = if r.closed { count } else { count.saturating_sub(1).max(1) };
    let step = (r.u.1 - r.u.0) / intervals as f64;
    (0..count).map(|i| r.u.0 + i as f64 * step).collect()
}

/// Checks a parameter interval called `name`: finite ends of at most [`MAX_COORD`] in
/// magnitude, `lo < hi` (or `lo ≠ hi` when `distinct` suffices).
pub fn check_interval(name: &'static str, (lo, hi): (f64, f64), distinct: bool) -> Result<()> {
    if !(lo.is_finite() && hi.is_finite()) || lo.abs() > MAX_COORD || hi.abs() > MAX_COORD {
        return Err(Error::parameter(name, crate::msg!("interval-not-finite", lo = lo, hi = hi)));
    }
    if (distinct && lo == hi) || (!distinct && lo >= hi) {
        let reason = if distinct { "interval-equal" } else { "interval-order" };
        return Err(Error::parameter(name, Message::new(reason).with("lo", lo).with("hi", hi)));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_closed_sampling_leaves_out_the_seam() {
        let r = Ranges { u: (0.0, 4.0), v: (-1.0, 1.0), closed: false };
        assert_eq!(sample_parameters(5, r), [0.0, 1.0, 2.0, 3.0, 4.0]);
        assert_eq!(sample_parameters(4, Ranges { closed: true, ..r }), [0.0, 1.0, 2.0, 3.0]);
    }

    #[test]
    fn intervals_are_checked() {
        assert!(check_interval("u", (0.0, 1.0), false).is_ok());
        assert!(check_interval("u", (1.0, 1.0), false).is_err());
        assert!(check_interval("v", (1.0, -1.0), true).is_ok());
        assert!(check_interval("v", (1.0, 1.0), true).is_err());
        assert_eq!(
            check_interval("u", (0.0, f64::INFINITY), false).unwrap_err().details().reason,
            Some("interval-not-finite")
        );
        // each end on its own: not a number, beyond MAX_COORD; MAX_COORD itself is allowed
        let reason = |lo: f64, hi: f64| check_interval("u", (lo, hi), false).err().and_then(|e| e.details().reason);
        for (lo, hi) in [(f64::NAN, 0.0), (0.0, f64::NAN), (-2.0 * MAX_COORD, 0.0), (0.0, 2.0 * MAX_COORD)] {
            assert_eq!(reason(lo, hi), Some("interval-not-finite"), "({lo}, {hi})");
        }
        assert_eq!(reason(-MAX_COORD, MAX_COORD), None);
    }
}
