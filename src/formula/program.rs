//! A formula compiled to a postfix program and evaluated on [`Dual`] numbers.
//!
//! evalexpr's operator tree (built from text that [`super::check`] has accepted) is walked
//! once into a flat list of operations; evaluation runs that list over a small stack, with no
//! recursion and no loop that depends on the values, so it always ends after `ops.len()` steps.

use super::check::FORMULA_CONSTANTS;
use super::dual::Dual;
use crate::error::{Error, Result};
use evalexpr::{Node, Operator, Value};

/// A function of one argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Function {
    /// sin
    Sin,
    /// cos
    Cos,
    /// tan
    Tan,
    /// asin
    Asin,
    /// acos
    Acos,
    /// atan
    Atan,
    /// sinh
    Sinh,
    /// cosh
    Cosh,
    /// tanh
    Tanh,
    /// exp
    Exp,
    /// ln, and log (also the natural logarithm, as JavaScript's Math.log)
    Ln,
    /// sqrt
    Sqrt,
    /// abs
    Abs,
}

impl Function {
    fn by_name(name: &str) -> Option<Self> {
        Some(match name {
            "sin" => Self::Sin,
            "cos" => Self::Cos,
            "tan" => Self::Tan,
            "asin" => Self::Asin,
            "acos" => Self::Acos,
            "atan" => Self::Atan,
            "sinh" => Self::Sinh,
            "cosh" => Self::Cosh,
            "tanh" => Self::Tanh,
            "exp" => Self::Exp,
            "ln" | "log" => Self::Ln,
            "sqrt" => Self::Sqrt,
            "abs" => Self::Abs,
            _ => return None,
        })
    }

    fn apply(self, x: Dual) -> Dual {
        match self {
            Self::Sin => x.sin(),
            Self::Cos => x.cos(),
            Self::Tan => x.tan(),
            Self::Asin => x.asin(),
            Self::Acos => x.acos(),
            Self::Atan => x.atan(),
            Self::Sinh => x.sinh(),
            Self::Cosh => x.cosh(),
            Self::Tanh => x.tanh(),
            Self::Exp => x.exp(),
            Self::Ln => x.ln(),
            Self::Sqrt => x.sqrt(),
            Self::Abs => x.abs(),
        }
    }
}

/// One step of a program.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Op {
    /// Push a number.
    Const(f64),
    /// Push variable k.
    Var(usize),
    /// Negate the top.
    Neg,
    /// The two top entries x, y replaced by x + y.
    Add,
    /// x − y.
    Sub,
    /// x · y.
    Mul,
    /// x / y.
    Div,
    /// xʸ.
    Pow,
    /// A function of the top.
    Call(Function),
    /// atan2(y, x) of the two top entries y, x.
    Atan2,
}

/// A compiled formula.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    ops: Vec<Op>,
    /// The most entries the stack holds during evaluation.
    depth: usize,
}

impl Program {
    /// Compiles evalexpr's tree of a checked formula; `variables` are the names in the order
    /// [`Program::eval`] receives their values.
    pub fn compile(source: &str, tree: &Node, variables: &[&str]) -> Result<Self> {
        let mut ops = Vec::new();
        emit(source, tree, variables, &mut ops)?;
        let (mut depth, mut now) = (0usize, 0usize);
        for op in &ops {
            match op {
                Op::Const(_) | Op::Var(_) => now += 1,
                Op::Neg | Op::Call(_) => {}
                _ => now -= 1,
            }
            depth = depth.max(now);
        }
        Ok(Program { ops, depth })
    }

    /// The value (with derivatives) for the variables' values `vars`; `stack` is scratch space
    /// reused between calls.
    pub fn eval(&self, vars: &[Dual], stack: &mut Vec<Dual>) -> Dual {
        stack.clear();
        stack.reserve(self.depth);
        for &op in &self.ops {
            let value = match op {
                Op::Const(c) => Dual::constant(c),
                Op::Var(k) => vars[k],
                Op::Neg => {
                    let x = stack.pop().unwrap_or_default();
                    -x
                }
                Op::Call(f) => {
                    let x = stack.pop().unwrap_or_default();
                    f.apply(x)
                }
                _ => {
                    let y = stack.pop().unwrap_or_default();
                    let x = stack.pop().unwrap_or_default();
                    match op {
                        Op::Add => x + y,
                        Op::Sub => x - y,
                        Op::Mul => x * y,
                        Op::Div => x / y,
                        Op::Pow => x.pow(y),
                        _ => x.atan2(y),
                    }
                }
            };
            stack.push(value);
        }
        stack.pop().unwrap_or_default()
    }
}

/// What is left to do while walking the tree: visit a node, or emit an operation after its
/// operands. An explicit work list instead of recursion, so long chains (u+u+…+u, up to the
/// length limit) cannot exhaust the stack.
enum Work<'a> {
    Visit(&'a Node),
    Emit(Op),
}

fn emit<'a>(source: &str, tree: &'a Node, variables: &[&str], ops: &mut Vec<Op>) -> Result<()> {
    let mut work: Vec<Work<'a>> = vec![Work::Visit(tree)];
    while let Some(item) = work.pop() {
        let node = match item {
            Work::Emit(op) => {
                ops.push(op);
                continue;
            }
            Work::Visit(node) => node,
        };
        let children = node.children();
        let unsupported =
            || Error::parse(source, None, None, crate::msg!("not-in-formulas", operator = node.operator().to_string()));
        // operands are pushed last-first, so the first is visited (and emitted) first
        let mut then = |op: Op, operands: &[&'a Node]| {
            work.push(Work::Emit(op));
            work.extend(operands.iter().rev().map(|n| Work::Visit(n)));
        };
        match (node.operator(), children) {
            (Operator::RootNode, [only]) => work.push(Work::Visit(only)),
            (Operator::Add, [x, y]) => then(Op::Add, &[x, y]),
            (Operator::Sub, [x, y]) => then(Op::Sub, &[x, y]),
            (Operator::Mul, [x, y]) => then(Op::Mul, &[x, y]),
            (Operator::Div, [x, y]) => then(Op::Div, &[x, y]),
            (Operator::Exp, [x, y]) => {
                // evalexpr reads a^b^c as (a^b)^c, mathematics as a^(b^c): ask for parentheses
                if matches!(x.operator(), Operator::Exp) {
                    return Err(Error::parse(source, None, None, crate::msg!("ambiguous-power"))
                        .with_hint(crate::msg!("power-parentheses")));
                }
                then(Op::Pow, &[x, y]);
            }
            (Operator::Neg, [x]) => then(Op::Neg, &[x]),
            (Operator::Const { value }, []) => ops.push(Op::Const(match value {
                Value::Int(i) => *i as f64,
                Value::Float(x) => *x,
                _ => return Err(unsupported()),
            })),
            (Operator::VariableIdentifierRead { identifier }, []) => {
                ops.push(match variables.iter().position(|v| v == identifier) {
                    Some(k) => Op::Var(k),
                    None => Op::Const(match identifier.as_str() {
                        "pi" => std::f64::consts::PI,
                        "e" => std::f64::consts::E,
                        _ => return Err(unsupported()),
                    }),
                });
                debug_assert!(FORMULA_CONSTANTS.len() == 2);
            }
            (Operator::FunctionIdentifier { identifier }, [argument]) if identifier == "atan2" => {
                let mut inner = argument;
                while matches!(inner.operator(), Operator::RootNode) && inner.children().len() == 1 {
                    inner = &inner.children()[0];
                }
                let (Operator::Tuple, [y, x]) = (inner.operator(), inner.children()) else {
                    return Err(Error::parse(source, None, None, crate::msg!("atan2-arguments")));
                };
                then(Op::Atan2, &[y, x]);
            }
            (Operator::FunctionIdentifier { identifier }, [argument]) => {
                let f = Function::by_name(identifier).ok_or_else(unsupported)?;
                then(Op::Call(f), &[argument]);
            }
            _ => return Err(unsupported()),
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn compile(text: &str) -> Program {
        let tree = evalexpr::build_operator_tree::<evalexpr::DefaultNumericTypes>(text).unwrap();
        Program::compile(text, &tree, &["u", "v"]).unwrap()
    }

    /// Each name of [`super::super::check::FORMULA_FUNCTIONS`] calls its own function: its value at 0.5.
    #[test]
    fn every_function_name_calls_its_function() {
        let x = 0.5f64;
        let functions: [(&str, f64); 14] = [
            ("sin", x.sin()),
            ("cos", x.cos()),
            ("tan", x.tan()),
            ("asin", x.asin()),
            ("acos", x.acos()),
            ("atan", x.atan()),
            ("sinh", x.sinh()),
            ("cosh", x.cosh()),
            ("tanh", x.tanh()),
            ("exp", x.exp()),
            ("ln", x.ln()),
            ("log", x.ln()),
            ("sqrt", x.sqrt()),
            ("abs", x.abs()),
        ];
        let names: Vec<&str> = functions.iter().map(|(name, _)| *name).collect();
        assert_eq!(names, super::super::check::FORMULA_FUNCTIONS);
        for (name, value) in functions {
            let program = compile(&format!("{name}(u)"));
            assert_eq!(program.eval(&[Dual::u(x), Dual::v(2.0)], &mut Vec::new()).re, value, "{name}");
        }
        assert_eq!(Function::by_name("sni"), None);
    }

    /// atan2 takes the two entries of a parenthesised pair, not of a pair inside anything else
    /// (text that [`super::super::check`] refuses, compiled here without it).
    #[test]
    fn atan2_takes_a_pair_in_parentheses_only() {
        let program = compile("atan2(((u, v)))");
        assert_eq!(program.eval(&[Dual::constant(1.0), Dual::constant(-1.0)], &mut Vec::new()).re, 1f64.atan2(-1.0));
        for text in ["atan2(-(u, v))", "atan2(sin((u, v)))", "atan2(u)", "atan2((u, v, u))"] {
            let tree = evalexpr::build_operator_tree::<evalexpr::DefaultNumericTypes>(text).unwrap();
            let e = Program::compile(text, &tree, &["u", "v"]).unwrap_err();
            assert_eq!(e.code(), "parse-error", "{text}");
        }
    }

    /// The depth is the most operands waiting at once: u, v, u before the product.
    #[test]
    fn the_depth_is_the_most_operands_at_once() {
        assert_eq!(compile("u + v*u").depth, 3);
        assert_eq!(compile("u*v + u").depth, 2);
        assert_eq!(compile("-sin(u)").depth, 1);
        assert_eq!(compile("atan2(u, v)^2 - 1").depth, 2);
        let mut stack = Vec::new();
        let program = compile("u + v*u");
        assert_eq!(program.eval(&[Dual::constant(2.0), Dual::constant(3.0)], &mut stack).re, 8.0);
        assert!(stack.capacity() >= 3);
    }
}
