//! Jets: a smooth ruled surface x(u, v) = a(u) + v·d(u) to first order at one u (Section 2's
//! exact invariants need a, a′, d, d′), and a smooth line congruence p(u, v) + t·d(u, v) to
//! first order at one (u, v) (Section 5's focal geometry needs p, d and their partials).

use glam::DVec3;

/// a(u), a′(u), d(u), d′(u): what the exact invariants need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jet {
    /// Directrix point a(u).
    pub a: DVec3,
    /// a′(u).
    pub da: DVec3,
    /// Ruling vector d(u) (not necessarily unit).
    pub d: DVec3,
    /// d′(u).
    pub dd: DVec3,
}

impl Jet {
    /// Unit ruling direction e and its derivative e′ = (d′ − (d′·e)e)/|d| (docs/src/conventions.md, Section 2).
    pub fn frame(&self) -> (DVec3, DVec3) {
        let len = self.d.length();
        let e = self.d / len;
        (e, (self.dd - self.dd.dot(e) * e) / len)
    }

    /// Whether every value and derivative is finite.
    pub fn is_finite(&self) -> bool {
        [self.a, self.da, self.d, self.dd].iter().all(|x| x.is_finite())
    }
}

/// p, d and their first partial derivatives at one (u, v).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CongruenceJet {
    /// p(u, v) on the director surface d₁.
    pub p: DVec3,
    /// ∂p/∂u.
    pub p_u: DVec3,
    /// ∂p/∂v.
    pub p_v: DVec3,
    /// Line direction d(u, v) (not necessarily unit).
    pub d: DVec3,
    /// ∂d/∂u.
    pub d_u: DVec3,
    /// ∂d/∂v.
    pub d_v: DVec3,
}

impl CongruenceJet {
    /// Whether every value and derivative is finite.
    pub fn is_finite(&self) -> bool {
        [self.p, self.p_u, self.p_v, self.d, self.d_u, self.d_v].iter().all(|x| x.is_finite())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_jet_is_finite_when_every_value_and_derivative_is() {
        let jet = Jet { a: DVec3::X, da: DVec3::Y, d: DVec3::Z, dd: DVec3::ZERO };
        assert!(jet.is_finite());
        assert!(!Jet { dd: DVec3::new(0.0, f64::NAN, 0.0), ..jet }.is_finite());
        assert!(!Jet { a: DVec3::new(f64::INFINITY, 0.0, 0.0), ..jet }.is_finite());
        let c =
            CongruenceJet { p: DVec3::X, p_u: DVec3::Y, p_v: DVec3::Z, d: DVec3::Z, d_u: DVec3::X, d_v: DVec3::ZERO };
        assert!(c.is_finite());
        assert!(!CongruenceJet { d_v: DVec3::new(0.0, 0.0, f64::NEG_INFINITY), ..c }.is_finite());
        assert!(!CongruenceJet { p_u: DVec3::NAN, ..c }.is_finite());
    }
}
