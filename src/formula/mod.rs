//! Formulas typed by a person: "cos(u)", "2*sin(u)", "u^2 + a*v", for surfaces and congruences
//! of one's own (beyond the paper's examples; the lecturer's tool).
//!
//! Grammar: numbers (`2`, `0.5`, `.5`, `1e-3`), the variables of the use (u, or u and v) and
//! the named parameters a, b, c, the constants `pi` and `e`, the operators `+ − * / ^`
//! (powers bind tighter than unary minus: −u^2 = −(u²); a^b^c must be parenthesised),
//! parentheses, and the functions sin cos tan asin acos atan atan2(y, x) sinh cosh tanh exp ln
//! log sqrt abs (`log` is the natural logarithm, as `ln` and JavaScript's Math.log).
//!
//! Text is checked first ([`check`]): at most 1000 characters and 64 levels of parentheses,
//! every character, name and operator order, each problem named with its column. evalexpr
//! (a maintained expression crate, used without default features, so without regex) then
//! builds the operator tree, which [`program`] compiles to a postfix program evaluated on
//! [`dual::Dual`] numbers: value and exact first partial derivatives in one pass
//! (forward-mode automatic differentiation), no finite differences.

pub mod check;
pub mod dual;
pub mod program;

use crate::error::{Error, Result};
use dual::Dual;
use program::Program;

/// Named parameters a formula may use besides its variables (the page shows them as sliders).
pub const PARAMETERS: [&str; 3] = ["a", "b", "c"];

/// A checked, compiled formula.
#[derive(Debug, Clone, PartialEq)]
pub struct Formula {
    text: String,
    program: Program,
}

impl Formula {
    /// Parses `text`, called `source` in messages (e.g. `"a[1]"`), over `variables` (their
    /// order is the order of values given to [`Formula::eval`]).
    pub fn parse(source: &str, text: &str, variables: &[&str]) -> Result<Self> {
        check::check(source, text, variables)?;
        let tree = evalexpr::build_operator_tree::<evalexpr::DefaultNumericTypes>(text)
            .map_err(|e| Error::parse(source, None, None, crate::msg!("unreadable", detail = e.to_string())))?;
        let program = Program::compile(source, &tree, variables)?;
        Ok(Formula { text: text.to_string(), program })
    }

    /// The text it was made from.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Value and derivatives at `vars`; `stack` is reusable scratch space.
    pub fn eval(&self, vars: &[Dual], stack: &mut Vec<Dual>) -> Dual {
        self.program.eval(vars, stack)
    }

    /// The plain value at `vars` (derivatives computed and dropped).
    pub fn value(&self, vars: &[f64]) -> f64 {
        let duals: Vec<Dual> = vars.iter().map(|&x| Dual::constant(x)).collect();
        self.program.eval(&duals, &mut Vec::new()).re
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;

    fn eval(text: &str, u: f64) -> Dual {
        Formula::parse("f", text, &["u", "a"]).unwrap().eval(&[Dual::u(u), Dual::constant(2.0)], &mut Vec::new())
    }

    #[test]
    fn values_follow_the_usual_precedence() {
        assert_eq!(eval("1/2", 0.0).re, 0.5, "integers divide as numbers");
        assert_eq!(eval("-u^2", 3.0).re, -9.0);
        assert_eq!(eval("2^-1", 0.0).re, 0.5);
        assert_eq!(eval("2*3+4", 0.0).re, 10.0);
        assert_eq!(eval("2+3*4", 0.0).re, 14.0);
        assert_eq!(eval("(2^3)^2", 0.0).re, 64.0);
        assert_eq!(eval("2^(3^2)", 0.0).re, 512.0);
        assert_eq!(eval("8/2/2", 0.0).re, 2.0);
        assert_eq!(eval("1 - 2 - 3", 0.0).re, -4.0);
        assert_eq!(eval("a*u", 1.5).re, 3.0);
        assert_near!(eval("e^1", 0.0).re, std::f64::consts::E, 1e-15);
        assert_near!(eval("cos(pi)", 0.0).re, -1.0, 1e-15);
        assert_near!(eval("atan2(1, -1)", 0.0).re, 0.75 * std::f64::consts::PI, 1e-15);
        assert_eq!(eval("log(e)", 0.0).re, 1.0);
        assert_eq!(eval("1.5e-3*u", 2.0).re, 3e-3);
        assert_eq!(eval("sqrt(abs(-16))", 0.0).re, 4.0);
        assert!(Formula::parse("f", "2^3^2", &["u"]).unwrap_err().to_string().contains("ambiguous"));
    }

    #[test]
    fn derivatives_are_exact() {
        // d/du (u² sin u) = 2u sin u + u² cos u
        let u = 0.8;
        let d = eval("u^2*sin(u)", u);
        assert_near!(d.du, 2.0 * u * u.sin() + u * u * u.cos(), 1e-15);
        // d/du atan2(sin u, cos u) = 1
        assert_near!(eval("atan2(sin(u), cos(u))", 0.3).du, 1.0, 1e-15);
        // d/du exp(a u) = a exp(a u), with a = 2
        assert_near!(eval("exp(a*u)", 0.4).du, 2.0 * (0.8f64).exp(), 1e-14);
    }

    #[test]
    fn a_formula_keeps_its_text_and_gives_values_at_plain_numbers() {
        let f = Formula::parse("x(u, v)", " u^2*cos(v) + a ", &["u", "v", "a"]).unwrap();
        assert_eq!(f.text(), " u^2*cos(v) + a ");
        assert_eq!(f.value(&[3.0, 0.0, 0.5]), 9.5);
        assert_near!(f.value(&[2.0, std::f64::consts::PI, -1.0]), -5.0, 1e-15);
        // value is eval's real part at constants
        let at = [Dual::constant(1.5), Dual::constant(0.25), Dual::constant(2.0)];
        assert_eq!(f.value(&[1.5, 0.25, 2.0]), f.eval(&at, &mut Vec::new()).re);
    }

    #[test]
    fn bad_text_is_refused_with_a_column() {
        let e = Formula::parse("a[1]", "sni(u)", &["u"]).unwrap_err();
        assert_eq!(e.code(), "parse-error");
        assert!(e.to_string().starts_with("a[1]: unknown function \"sni\" at column 1"), "{e}");
    }
}
