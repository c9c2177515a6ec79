//! Checking a formula before it is parsed: its length and nesting against the limits, every
//! character and name, and the order of operands and operators, each problem reported with
//! its 1-based column (`a[1]: unknown function "sni" at column 1`).
//!
//! evalexpr builds the expression tree afterwards; it reports no positions and accepts far
//! more than formulas of a surface need (strings, assignments, comparisons, comments). What
//! passes this check is exactly the grammar of [`crate::formula`], so the tree it builds holds
//! nothing else, and the checker's messages are the ones a student sees.

use crate::error::{Error, Result};
use crate::tolerance::{MAX_FORMULA_CHARS, MAX_FORMULA_DEPTH};

/// Functions of one argument.
pub const FUNCTIONS: [&str; 14] =
    ["sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "exp", "ln", "log", "sqrt", "abs"];

/// Functions of two arguments.
pub const FUNCTIONS2: [&str; 1] = ["atan2"];

/// Named constants.
pub const CONSTANTS: [&str; 2] = ["pi", "e"];

/// Most signs in a row ("--u" is fine, "-----u" is refused).
const MAX_SIGNS: usize = 4;

/// One open parenthesis: where it is, and whether it holds the arguments of atan2.
struct Open {
    column: usize,
    two_arguments: bool,
    commas: usize,
    empty: bool,
}

/// Checks `text` (the formula called `source` in messages) with the variables `variables`.
pub fn check(source: &str, text: &str, variables: &[&str]) -> Result<()> {
    let chars: Vec<char> = text.chars().collect();
    if chars.len() > MAX_FORMULA_CHARS {
        return Err(Error::TextLimit {
            source: source.into(),
            what: "characters",
            got: chars.len(),
            max: MAX_FORMULA_CHARS,
            column: None,
        });
    }
    let fail = |column: usize, message: String| Error::parse(source, None, Some(column + 1), message);
    if chars.iter().all(|c| c.is_whitespace()) {
        return Err(Error::parse(source, None, None, "is empty; write a formula such as cos(u)"));
    }
    let known = || {
        let mut names: Vec<&str> = variables.to_vec();
        names.extend(CONSTANTS);
        names.join(", ")
    };
    let mut open: Vec<Open> = Vec::new();
    let mut expect_operand = true;
    let mut signs = 0;
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        if c.is_ascii_digit() || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit)) {
            let start = i;
            i = number_end(&chars, i);
            if !expect_operand {
                return Err(fail(start, "missing operator before this number (write * for products)".into()));
            }
            if let Some(&next) = chars.get(i).filter(|n| n.is_ascii_alphabetic() || **n == '_') {
                let number: String = chars[start..i].iter().collect();
                return Err(fail(start, format!("write {number}*{next}…, not {number}{next}… (products need *)")));
            }
            expect_operand = false;
            signs = 0;
            mark_filled(&mut open);
            continue;
        }
        if c.is_ascii_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let name: String = chars[start..i].iter().collect();
            if !expect_operand {
                return Err(fail(start, format!("missing operator before \"{name}\" (write * for products)")));
            }
            let mut next = i;
            while next < chars.len() && chars[next].is_whitespace() {
                next += 1;
            }
            let call = chars.get(next) == Some(&'(');
            let is_function = FUNCTIONS.contains(&name.as_str()) || FUNCTIONS2.contains(&name.as_str());
            if is_function {
                if !call {
                    return Err(fail(start, format!("{name} needs its argument in parentheses: {name}(…)")));
                }
                // the "(" that follows opens the argument list
                mark_filled(&mut open);
                open.push(Open {
                    column: next,
                    two_arguments: FUNCTIONS2.contains(&name.as_str()),
                    commas: 0,
                    empty: true,
                });
                if open.len() > MAX_FORMULA_DEPTH {
                    return Err(depth_error(source, next));
                }
                i = next + 1;
                expect_operand = true;
                signs = 0;
                continue;
            }
            if variables.contains(&name.as_str()) || CONSTANTS.contains(&name.as_str()) {
                if call {
                    return Err(fail(start, format!("\"{name}\" is not a function; write {name}*(…) for a product")));
                }
                expect_operand = false;
                mark_filled(&mut open);
                continue;
            }
            return Err(if call {
                fail(start, format!("unknown function \"{name}\""))
                    .with_hint(format!("known: {}, atan2", FUNCTIONS.join(", ")))
            } else {
                fail(start, format!("unknown name \"{name}\"")).with_hint(format!("known: {}", known()))
            });
        }
        match c {
            '(' => {
                signs = 0;
                if !expect_operand {
                    return Err(fail(i, "missing operator before \"(\" (write * for products)".into()));
                }
                mark_filled(&mut open);
                open.push(Open { column: i, two_arguments: false, commas: 0, empty: true });
                if open.len() > MAX_FORMULA_DEPTH {
                    return Err(depth_error(source, i));
                }
            }
            ')' => {
                let Some(top) = open.pop() else {
                    return Err(fail(i, "\")\" without a matching \"(\"".into()));
                };
                if top.empty {
                    return Err(fail(top.column, "empty parentheses".into()));
                }
                if expect_operand {
                    return Err(fail(i, "an operand is missing before \")\"".into()));
                }
                if top.two_arguments && top.commas != 1 {
                    return Err(fail(top.column, "atan2 takes two arguments: atan2(y, x)".into()));
                }
                expect_operand = false;
            }
            ',' => {
                match open.last_mut() {
                    Some(top) if top.two_arguments && top.commas == 0 => top.commas = 1,
                    _ => {
                        return Err(fail(i, "a comma is allowed only between the two arguments of atan2(y, x)".into()))
                    }
                }
                if expect_operand {
                    return Err(fail(i, "an operand is missing before \",\"".into()));
                }
                expect_operand = true;
            }
            '+' | '-' => {
                // binary, or unary where an operand is expected; runs of signs are bounded so
                // that the expression tree stays shallow (each sign is one level)
                if expect_operand {
                    signs += 1;
                    if signs > MAX_SIGNS {
                        return Err(fail(i, format!("more than {MAX_SIGNS} signs in a row")));
                    }
                } else {
                    signs = 0;
                }
                expect_operand = true;
            }
            '*' | '/' | '^' => {
                signs = 0;
                if expect_operand {
                    let hint = match (chars.get(i.wrapping_sub(1)), c) {
                        (Some('*'), '*') => " (write ^ for powers)",
                        (Some('/'), '/' | '*') => " (comments are not part of formulas)",
                        _ => "",
                    };
                    return Err(fail(i, format!("\"{c}\" needs an operand on its left{hint}")));
                }
                expect_operand = true;
            }
            _ => return Err(fail(i, unexpected(c))),
        }
        i += 1;
    }
    if let Some(top) = open.last() {
        return Err(fail(top.column, "\"(\" is never closed".into()));
    }
    if expect_operand {
        return Err(fail(chars.len(), "the formula ends where an operand is expected".into()));
    }
    Ok(())
}

/// Marks the innermost parenthesis as holding something.
fn mark_filled(open: &mut [Open]) {
    if let Some(top) = open.last_mut() {
        top.empty = false;
    }
}

fn depth_error(source: &str, at: usize) -> Error {
    Error::TextLimit {
        source: source.into(),
        what: "levels of nesting",
        got: MAX_FORMULA_DEPTH + 1,
        max: MAX_FORMULA_DEPTH,
        column: Some(at + 1),
    }
}

/// The end of the number starting at `i`: digits, an optional fraction, an optional
/// exponent `e` or `E` with sign and digits (an `e` not followed by digits is left alone).
fn number_end(chars: &[char], mut i: usize) -> usize {
    let digits = |mut i: usize| {
        while i < chars.len() && chars[i].is_ascii_digit() {
            i += 1;
        }
        i
    };
    i = digits(i);
    if chars.get(i) == Some(&'.') {
        i = digits(i + 1);
    }
    if matches!(chars.get(i), Some('e' | 'E')) {
        let mut j = i + 1;
        if matches!(chars.get(j), Some('+' | '-')) {
            j += 1;
        }
        if chars.get(j).is_some_and(char::is_ascii_digit) {
            i = digits(j);
        }
    }
    i
}

/// A message for a character outside the grammar, with the ASCII spelling of common lookalikes.
fn unexpected(c: char) -> String {
    let hint = match c {
        'π' => "write pi",
        '²' => "write ^2",
        '³' => "write ^3",
        '×' | '·' | '⋅' => "write * for products",
        '−' | '–' => "write - (the ASCII minus)",
        '÷' | ':' => "write / for quotients",
        '[' | ']' | '{' | '}' => "use round parentheses",
        _ => "formulas use numbers, names, + - * / ^, parentheses and commas",
    };
    format!("unexpected character \"{c}\" ({hint})")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message(text: &str) -> String {
        check("a[1]", text, &["u", "a", "b"]).unwrap_err().to_string()
    }

    #[test]
    fn accepts_the_grammar() {
        for ok in [
            "cos(u)",
            "2*sin(u)",
            "u^2",
            "-u^-2",
            "1.5e-3*u + .5",
            "atan2(sin(u), cos(u))",
            "a*b - e^(pi*u)",
            "((u))",
            " u ",
        ] {
            assert!(check("x", ok, &["u", "a", "b"]).is_ok(), "{ok}");
        }
    }

    #[test]
    fn names_the_problem_and_its_column() {
        assert_eq!(message("sni(u)"), "a[1]: unknown function \"sni\" at column 1; known: sin, cos, tan, asin, acos, atan, sinh, cosh, tanh, exp, ln, log, sqrt, abs, atan2");
        assert_eq!(message("2*x"), "a[1]: unknown name \"x\" at column 3; known: u, a, b, pi, e");
        assert_eq!(message("2u"), "a[1]: write 2*u…, not 2u… (products need *) at column 1");
        assert_eq!(message("2 (u)"), "a[1]: missing operator before \"(\" (write * for products) at column 3");
        assert_eq!(message("u (u)"), "a[1]: \"u\" is not a function; write u*(…) for a product at column 1");
        assert_eq!(message("sin u"), "a[1]: sin needs its argument in parentheses: sin(…) at column 1");
        assert_eq!(message("u(2)"), "a[1]: \"u\" is not a function; write u*(…) for a product at column 1");
        assert_eq!(message("(u"), "a[1]: \"(\" is never closed at column 1");
        assert_eq!(message("u)"), "a[1]: \")\" without a matching \"(\" at column 2");
        assert_eq!(message("u +"), "a[1]: the formula ends where an operand is expected at column 4");
        assert_eq!(message("u**2"), "a[1]: \"*\" needs an operand on its left (write ^ for powers) at column 3");
        assert_eq!(
            message("u // c"),
            "a[1]: \"/\" needs an operand on its left (comments are not part of formulas) at column 4"
        );
        assert_eq!(message("2πu"), "a[1]: unexpected character \"π\" (write pi) at column 2");
        assert_eq!(message("u; u = 2"), "a[1]: unexpected character \";\" (formulas use numbers, names, + - * / ^, parentheses and commas) at column 2");
        assert_eq!(message("atan2(u)"), "a[1]: atan2 takes two arguments: atan2(y, x) at column 6");
        assert_eq!(
            message("sin(u, u)"),
            "a[1]: a comma is allowed only between the two arguments of atan2(y, x) at column 6"
        );
        assert_eq!(message("()"), "a[1]: empty parentheses at column 1");
        assert!(message("\"s\"").contains("unexpected character"));
        assert!(message("true").contains("unknown name \"true\""));
        assert!(message("inf").contains("unknown name \"inf\""));
        assert_eq!(message("   "), "a[1]: is empty; write a formula such as cos(u)");
        assert!(check("x", "--+-u", &["u"]).is_ok());
        assert_eq!(message("-+-+-u"), "a[1]: more than 4 signs in a row at column 5");
        assert!(check("x", "-u*-u^-u", &["u"]).is_ok());
    }

    #[test]
    fn limits_are_checked_first() {
        let long = "u+".repeat(600) + "u";
        let e = check("a[0]", &long, &["u"]).unwrap_err();
        assert_eq!(e.code(), "too-large");
        assert_eq!(e.to_string(), "a[0]: 1201 characters exceed the limit of 1000");
        let deep = "(".repeat(65) + "u" + &")".repeat(65);
        let e = check("a[0]", &deep, &["u"]).unwrap_err();
        assert_eq!(e.to_string(), "a[0]: 65 levels of nesting exceed the limit of 64 (first at column 65)");
        let ok = "(".repeat(64) + "u" + &")".repeat(64);
        assert!(check("a[0]", &ok, &["u"]).is_ok());
    }
}
