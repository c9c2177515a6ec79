//! Lines and segments: the elements of a discrete ruled surface (Section 2).
//!
//! A ruling R_i is given as a segment a_i → b_i; its unit direction
//! e_i = (b_i − a_i)/|b_i − a_i| keeps the given orientation (docs/src/conventions.md, Section 2).

use glam::DVec3;

/// A segment a → b; as a ruling it stands for the whole line through a and b.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// First endpoint (on the boundary curve a, or the director surface d₁).
    pub a: DVec3,
    /// Second endpoint (on the boundary curve b, or the director surface d₂).
    pub b: DVec3,
}

/// An oriented line: a point on it and a unit direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    /// A point on the line.
    pub point: DVec3,
    /// Unit direction.
    pub dir: DVec3,
}

impl Segment {
    /// The segment a → b.
    pub fn new(a: DVec3, b: DVec3) -> Self {
        Segment { a, b }
    }

    /// b − a.
    pub fn vector(&self) -> DVec3 {
        self.b - self.a
    }

    /// |b − a|.
    pub fn length(&self) -> f64 {
        self.vector().length()
    }

    /// The oriented line through a and b. The caller guarantees a ≠ b (validated surfaces do).
    pub fn line(&self) -> Line {
        Line { point: self.a, dir: self.vector().normalize() }
    }

    /// The point a + t (b − a).
    pub fn at(&self, t: f64) -> DVec3 {
        self.a + t * self.vector()
    }
}

impl Line {
    /// The orthogonal projection of `p` onto the line.
    pub fn project(&self, p: DVec3) -> DVec3 {
        self.point + (p - self.point).dot(self.dir) * self.dir
    }

    /// Distance of `p` from the line.
    pub fn distance_to(&self, p: DVec3) -> f64 {
        (p - self.point).reject_from_normalized(self.dir).length()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn projection_onto_a_line_off_the_origin() {
        let line = Line { point: DVec3::new(1.0, 2.0, 3.0), dir: DVec3::X };
        assert_eq!(line.project(DVec3::new(5.0, 7.0, -1.0)), DVec3::new(5.0, 2.0, 3.0));
        assert_eq!(line.distance_to(DVec3::new(5.0, 5.0, 7.0)), 5.0);
    }

    #[test]
    fn line_of_segment_keeps_orientation() {
        let s = Segment::new(DVec3::new(1.0, 2.0, 3.0), DVec3::new(1.0, 2.0, 1.0));
        assert_eq!(s.line().dir, DVec3::new(0.0, 0.0, -1.0));
        assert_eq!(s.at(0.5), DVec3::new(1.0, 2.0, 2.0));
    }

    #[test]
    fn projection_and_distance() {
        let l = Line { point: DVec3::ZERO, dir: DVec3::X };
        let p = DVec3::new(3.0, 4.0, 0.0);
        assert_eq!(l.project(p), DVec3::new(3.0, 0.0, 0.0));
        assert_eq!(l.distance_to(p), 4.0);
    }
}
