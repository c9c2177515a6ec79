//! Dual numbers for exact first derivatives (forward-mode automatic differentiation).
//!
//! A [`Dual`] carries a value and its partial derivatives with respect to the two parameters
//! u and v: x + ε_u x_u + ε_v x_v with ε² = 0. Every arithmetic rule below is the chain rule
//! written once, so a formula evaluated on duals yields its derivatives exactly (to rounding),
//! with no step size: a′(u), e′(u) for the exact striction curve (Section 2) and p_u, p_v,
//! e_u, e_v for the focal geometry of a congruence.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// A value with its partial derivatives ∂/∂u and ∂/∂v.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Dual {
    /// The value.
    pub re: f64,
    /// ∂/∂u.
    pub du: f64,
    /// ∂/∂v.
    pub dv: f64,
}

impl Dual {
    /// A constant (zero derivatives).
    pub const fn constant(re: f64) -> Self {
        Dual { re, du: 0.0, dv: 0.0 }
    }

    /// The parameter u itself (∂u/∂u = 1).
    pub const fn u(re: f64) -> Self {
        Dual { re, du: 1.0, dv: 0.0 }
    }

    /// The parameter v itself (∂v/∂v = 1).
    pub const fn v(re: f64) -> Self {
        Dual { re, du: 0.0, dv: 1.0 }
    }

    /// Whether the value and both derivatives are finite.
    pub fn is_finite(&self) -> bool {
        self.re.is_finite() && self.du.is_finite() && self.dv.is_finite()
    }

    /// f(x) with f′(x) = `slope`: the chain rule (f ∘ x)′ = f′(x)·x′.
    fn chain(self, value: f64, slope: f64) -> Self {
        Dual { re: value, du: slope * self.du, dv: slope * self.dv }
    }

    /// Whether the derivatives are both zero (a constant, so xʸ may use the power rule).
    fn is_constant(&self) -> bool {
        self.du == 0.0 && self.dv == 0.0
    }

    /// xʸ: with a constant exponent the power rule y·xʸ⁻¹·x′ (valid for negative x);
    /// otherwise exp(y ln x), whose derivative xʸ(y′ ln x + y x′/x) needs x > 0.
    pub fn pow(self, y: Dual) -> Self {
        let value = self.re.powf(y.re);
        if y.is_constant() {
            let slope = if y.re == 0.0 { 0.0 } else { y.re * self.re.powf(y.re - 1.0) };
            return self.chain(value, slope);
        }
        let ln = self.re.ln();
        Dual {
            re: value,
            du: value * (y.du * ln + y.re * self.du / self.re),
            dv: value * (y.dv * ln + y.re * self.dv / self.re),
        }
    }

    /// sin x, with derivative cos x.
    pub fn sin(self) -> Self {
        let (s, c) = self.re.sin_cos();
        self.chain(s, c)
    }

    /// cos x, with derivative −sin x.
    pub fn cos(self) -> Self {
        let (s, c) = self.re.sin_cos();
        self.chain(c, -s)
    }

    /// tan x, with derivative 1 + tan² x.
    pub fn tan(self) -> Self {
        let t = self.re.tan();
        self.chain(t, 1.0 + t * t)
    }

    /// asin x, with derivative 1/√(1 − x²).
    pub fn asin(self) -> Self {
        self.chain(self.re.asin(), 1.0 / (1.0 - self.re * self.re).sqrt())
    }

    /// acos x, with derivative −1/√(1 − x²).
    pub fn acos(self) -> Self {
        self.chain(self.re.acos(), -1.0 / (1.0 - self.re * self.re).sqrt())
    }

    /// atan x, with derivative 1/(1 + x²).
    pub fn atan(self) -> Self {
        self.chain(self.re.atan(), 1.0 / (1.0 + self.re * self.re))
    }

    /// atan2(y, x) (`self` is y), with derivative (x y′ − y x′)/(x² + y²).
    pub fn atan2(self, x: Dual) -> Self {
        let r2 = x.re * x.re + self.re * self.re;
        Dual {
            re: self.re.atan2(x.re),
            du: (x.re * self.du - self.re * x.du) / r2,
            dv: (x.re * self.dv - self.re * x.dv) / r2,
        }
    }

    /// sinh x, with derivative cosh x.
    pub fn sinh(self) -> Self {
        self.chain(self.re.sinh(), self.re.cosh())
    }

    /// cosh x, with derivative sinh x.
    pub fn cosh(self) -> Self {
        self.chain(self.re.cosh(), self.re.sinh())
    }

    /// tanh x, with derivative 1 − tanh² x.
    pub fn tanh(self) -> Self {
        let t = self.re.tanh();
        self.chain(t, 1.0 - t * t)
    }

    /// eˣ, its own derivative.
    pub fn exp(self) -> Self {
        let e = self.re.exp();
        self.chain(e, e)
    }

    /// ln x, with derivative 1/x (NaN for x < 0, −∞ at 0).
    pub fn ln(self) -> Self {
        self.chain(self.re.ln(), 1.0 / self.re)
    }

    /// √x, with derivative 1/(2√x).
    pub fn sqrt(self) -> Self {
        let r = self.re.sqrt();
        self.chain(r, 0.5 / r)
    }

    /// |x|, with derivative sign x (and 0 at x = 0, where |x| has no derivative: the one-sided
    /// ones are ±1, and 0 is their mean).
    pub fn abs(self) -> Self {
        let slope = if self.re > 0.0 {
            1.0
        } else if self.re < 0.0 {
            -1.0
        } else {
            0.0
        };
        self.chain(self.re.abs(), slope)
    }
}

impl Add for Dual {
    type Output = Dual;
    fn add(self, o: Dual) -> Dual {
        Dual { re: self.re + o.re, du: self.du + o.du, dv: self.dv + o.dv }
    }
}

impl Sub for Dual {
    type Output = Dual;
    fn sub(self, o: Dual) -> Dual {
        Dual { re: self.re - o.re, du: self.du - o.du, dv: self.dv - o.dv }
    }
}

impl Mul for Dual {
    type Output = Dual;
    /// (xy)′ = x′y + xy′.
    fn mul(self, o: Dual) -> Dual {
        Dual { re: self.re * o.re, du: self.du * o.re + self.re * o.du, dv: self.dv * o.re + self.re * o.dv }
    }
}

impl Div for Dual {
    type Output = Dual;
    /// (x/y)′ = (x′ − (x/y) y′)/y.
    fn div(self, o: Dual) -> Dual {
        let q = self.re / o.re;
        Dual { re: q, du: (self.du - q * o.du) / o.re, dv: (self.dv - q * o.dv) / o.re }
    }
}

impl Neg for Dual {
    type Output = Dual;
    fn neg(self) -> Dual {
        Dual { re: -self.re, du: -self.du, dv: -self.dv }
    }
}

/// Arithmetic with plain numbers (constants), so closed forms read as formulas:
/// `0.5 * (2.0 * u + 1.5 * v).sin()`.
macro_rules! with_constants {
    ($($trait:ident $method:ident),*) => {$(
        impl $trait<f64> for Dual {
            type Output = Dual;
            fn $method(self, c: f64) -> Dual {
                self.$method(Dual::constant(c))
            }
        }
        impl $trait<Dual> for f64 {
            type Output = Dual;
            fn $method(self, x: Dual) -> Dual {
                Dual::constant(self).$method(x)
            }
        }
    )*};
}
with_constants!(Add add, Sub sub, Mul mul, Div div);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;

    /// Every rule against a central difference of its own value (step 1e-6, so agreement to
    /// ~1e-9 confirms the formula; the rules themselves are exact).
    #[test]
    fn derivatives_match_central_differences() {
        type F = fn(Dual) -> Dual;
        let rules: [(&str, F, f64); 14] = [
            ("sin", Dual::sin, 0.7),
            ("cos", Dual::cos, 0.7),
            ("tan", Dual::tan, 0.7),
            ("asin", Dual::asin, 0.3),
            ("acos", Dual::acos, 0.3),
            ("atan", Dual::atan, 0.7),
            ("sinh", Dual::sinh, 0.7),
            ("cosh", Dual::cosh, 0.7),
            ("tanh", Dual::tanh, 0.7),
            ("exp", Dual::exp, 0.7),
            ("ln", Dual::ln, 0.7),
            ("sqrt", Dual::sqrt, 0.7),
            ("abs", Dual::abs, -0.7),
            ("pow", |x| x.pow(Dual::constant(3.0)), -0.7),
        ];
        let h = 1e-6;
        for (name, f, x) in rules {
            let d = f(Dual::u(x));
            let fd = (f(Dual::constant(x + h)).re - f(Dual::constant(x - h)).re) / (2.0 * h);
            assert!((d.du - fd).abs() < 1e-8, "{name}: {} vs {fd}", d.du);
            assert_eq!(d.dv, 0.0, "{name}");
        }
    }

    #[test]
    fn two_variable_rules() {
        // f(u, v) = u^v · atan2(v, u) / (u − v) at (1.3, 0.4)
        let f = |u: Dual, v: Dual| u.pow(v) * v.atan2(u) / (u - v);
        let (u, v) = (1.3, 0.4);
        let d = f(Dual::u(u), Dual::v(v));
        let h = 1e-6;
        let g = |u: f64, v: f64| f(Dual::constant(u), Dual::constant(v)).re;
        assert_near!(d.du, (g(u + h, v) - g(u - h, v)) / (2.0 * h), 1e-8);
        assert_near!(d.dv, (g(u, v + h) - g(u, v - h)) / (2.0 * h), 1e-8);
    }

    #[test]
    fn exact_on_polynomials() {
        // (u² + 3u)′ = 2u + 3, exactly
        let u = Dual::u(1.25);
        let p = u * u + Dual::constant(3.0) * u;
        assert_eq!(p.du, 2.0 * 1.25 + 3.0);
        assert_eq!(u.pow(Dual::constant(2.0)).du, 2.5);
    }

    /// Each part of `got` within `tol` of `want`'s, relative to 1 or the part's size.
    fn near(got: Dual, want: Dual, tol: f64, what: &str) {
        for (a, b) in [(got.re, want.re), (got.du, want.du), (got.dv, want.dv)] {
            assert!((a - b).abs() <= tol * b.abs().max(1.0), "{what}: {got:?} vs {want:?}");
        }
    }

    /// Each rule once more, on operands that depend on both parameters, against derivatives
    /// worked out by hand: x = 1.5 + 2ε_u − ε_v, y = −0.5 + 0.25ε_u + 3ε_v.
    #[test]
    fn both_derivatives_follow_the_rules() {
        let x = Dual { re: 1.5, du: 2.0, dv: -1.0 };
        let y = Dual { re: -0.5, du: 0.25, dv: 3.0 };
        let d = |re: f64, du: f64, dv: f64| Dual { re, du, dv };
        assert_eq!(x + y, d(1.0, 2.25, 2.0));
        assert_eq!(x - y, d(2.0, 1.75, -4.0));
        assert_eq!(-x, d(-1.5, -2.0, 1.0));
        // (xy)′ = x′y + xy′
        assert_eq!(x * y, d(-0.75, -1.0 + 0.375, 0.5 + 4.5));
        // (x/y)′ = (x′ − (x/y)y′)/y with x/y = −3
        assert_eq!(x / y, d(-3.0, -5.5, -16.0));
        assert_eq!(2.0 - x, d(0.5, -2.0, 1.0));
        assert_eq!(x - 2.0, d(-0.5, 2.0, -1.0));
        assert_eq!(2.0 + x, d(3.5, 2.0, -1.0));
        assert_eq!(x + 2.0, d(3.5, 2.0, -1.0));
        assert_eq!(4.0 * x, d(6.0, 8.0, -4.0));
        assert_eq!(x * 4.0, d(6.0, 8.0, -4.0));
        assert_eq!(x / 4.0, d(0.375, 0.5, -0.25));
        // 3/x: −3x′/x² = −(4/3)x′
        near(3.0 / x, d(2.0, -8.0 / 3.0, 4.0 / 3.0), 1e-15, "3/x");
        // x^y with both depending on u and v: xʸ(y′ ln x + y x′/x); at x = 2, y = 3
        let (x2, y3) = (d(2.0, 0.5, 2.0), d(3.0, 0.25, -1.0));
        let ln2 = 2f64.ln();
        near(x2.pow(y3), d(8.0, 2.0 * ln2 + 6.0, 24.0 - 8.0 * ln2), 1e-14, "x^y");
        // constant exponents: the power rule, also for x < 0; x⁰ = 1 with no slope
        near(y.pow(Dual::constant(3.0)), d(-0.125, 0.1875, 2.25), 1e-15, "y^3");
        assert_eq!(y.pow(Dual::constant(0.0)), d(1.0, 0.0, 0.0));
        // atan2(y, x)′ = (x y′ − y x′)/(x² + y²) = (0.375 + 1, 4.5 − 0.5)/2.5
        near(y.atan2(x), d((-0.5f64).atan2(1.5), 0.55, 1.6), 1e-15, "atan2");
        // one-argument rules: (f(x), f′(x)·2, f′(x)·(−1)) at x = 0.5 + 2ε_u − ε_v
        let h = d(0.5, 2.0, -1.0);
        let chain = |f: f64, slope: f64| d(f, 2.0 * slope, -slope);
        let r = (1.0f64 - 0.25).sqrt();
        let cases = [
            (h.sin(), chain(0.5f64.sin(), 0.5f64.cos())),
            (h.cos(), chain(0.5f64.cos(), -0.5f64.sin())),
            (h.tan(), chain(0.5f64.tan(), 1.0 / 0.5f64.cos().powi(2))),
            (h.asin(), chain(0.5f64.asin(), 1.0 / r)),
            (h.acos(), chain(0.5f64.acos(), -1.0 / r)),
            (h.atan(), chain(0.5f64.atan(), 0.8)),
            (h.sinh(), chain(0.5f64.sinh(), 0.5f64.cosh())),
            (h.cosh(), chain(0.5f64.cosh(), 0.5f64.sinh())),
            (h.tanh(), chain(0.5f64.tanh(), 1.0 / 0.5f64.cosh().powi(2))),
            (h.exp(), chain(0.5f64.exp(), 0.5f64.exp())),
            (h.ln(), chain(0.5f64.ln(), 2.0)),
            (h.sqrt(), chain(0.5f64.sqrt(), 0.5 / 0.5f64.sqrt())),
            (h.abs(), chain(0.5, 1.0)),
            ((-h).abs(), d(0.5, 2.0, -1.0)),
            (d(0.0, 2.0, -1.0).abs(), d(0.0, 0.0, 0.0)),
        ];
        for (k, (got, want)) in cases.into_iter().enumerate() {
            near(got, want, 1e-15, &format!("rule {k}"));
        }
    }

    #[test]
    fn singularities_are_not_finite() {
        assert!(!Dual::u(0.0).sqrt().is_finite());
        assert!(!(Dual::constant(1.0) / Dual::u(0.0)).is_finite());
        assert!(!Dual::u(-1.0).ln().is_finite());
        assert!(Dual::u(0.0).abs().is_finite());
    }
}
