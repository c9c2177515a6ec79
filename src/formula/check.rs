//! Checking a formula before it is parsed: its length and nesting against the limits, every
//! character and name, and the order of operands and operators, each problem reported with
//! its 1-based column (`a[1]: unknown function "sni" at column 1`).
//!
//! evalexpr builds the expression tree afterwards; it reports no positions and accepts far
//! more than formulas of a surface need (strings, assignments, comparisons, comments). What
//! passes this check is exactly the grammar of [`crate::formula`], so the tree it builds holds
//! nothing else, and the checker's messages are the ones a student sees.

use crate::error::{Error, Message, Result};
use crate::msg;
use crate::tolerance::{MAX_FORMULA_CHARS, MAX_FORMULA_DEPTH, MAX_FORMULA_SIGNS};

/// Functions of one argument.
pub const FORMULA_FUNCTIONS: [&str; 14] =
    ["sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "exp", "ln", "log", "sqrt", "abs"];

/// Functions of two arguments.
pub const FUNCTIONS2: [&str; 1] = ["atan2"];

/// Named constants.
pub const FORMULA_CONSTANTS: [&str; 2] = ["pi", "e"];

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
    let fail = |column: usize, message: Message| Error::parse(source, None, Some(column + 1), message);
    if chars.iter().all(|c| c.is_whitespace()) {
        return Err(Error::parse(source, None, None, msg!("formula-empty")));
    }
    let known = || {
        let mut names: Vec<&str> = variables.to_vec();
        names.extend(FORMULA_CONSTANTS);
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
                return Err(fail(start, msg!("operator-before-number")));
            }
            if let Some(&next) = chars.get(i).filter(|n| n.is_ascii_alphabetic() || **n == '_') {
                let number: String = chars[start..i].iter().collect();
                return Err(fail(start, msg!("number-before-name", number = number, next = next)));
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
                return Err(fail(start, msg!("operator-before-name", name = name)));
            }
            let mut next = i;
            while next < chars.len() && chars[next].is_whitespace() {
                next += 1;
            }
            let call = chars.get(next) == Some(&'(');
            let is_function = FORMULA_FUNCTIONS.contains(&name.as_str()) || FUNCTIONS2.contains(&name.as_str());
            if is_function {
                if !call {
                    return Err(fail(start, msg!("function-needs-parentheses", name = name)));
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
            if variables.contains(&name.as_str()) || FORMULA_CONSTANTS.contains(&name.as_str()) {
                if call {
                    return Err(fail(start, msg!("not-a-function", name = name)));
                }
                expect_operand = false;
                mark_filled(&mut open);
                continue;
            }
            return Err(if call {
                fail(start, msg!("unknown-function", name = name))
                    .with_hint(msg!("known-names", names = format!("{}, atan2", FORMULA_FUNCTIONS.join(", "))))
            } else {
                fail(start, msg!("unknown-name", name = name)).with_hint(msg!("known-names", names = known()))
            });
        }
        match c {
            '(' => {
                signs = 0;
                if !expect_operand {
                    return Err(fail(i, msg!("operator-before-parenthesis")));
                }
                mark_filled(&mut open);
                open.push(Open { column: i, two_arguments: false, commas: 0, empty: true });
                if open.len() > MAX_FORMULA_DEPTH {
                    return Err(depth_error(source, i));
                }
            }
            ')' => {
                let Some(top) = open.pop() else {
                    return Err(fail(i, msg!("unmatched-close")));
                };
                if top.empty {
                    return Err(fail(top.column, msg!("empty-parentheses")));
                }
                if expect_operand {
                    return Err(fail(i, msg!("operand-before", sign = ')')));
                }
                if top.two_arguments && top.commas != 1 {
                    return Err(fail(top.column, msg!("atan2-arguments")));
                }
                expect_operand = false;
            }
            ',' => {
                match open.last_mut() {
                    Some(top) if top.two_arguments && top.commas == 0 => top.commas = 1,
                    _ => return Err(fail(i, msg!("comma-outside-atan2"))),
                }
                if expect_operand {
                    return Err(fail(i, msg!("operand-before", sign = ',')));
                }
                expect_operand = true;
            }
            '+' | '-' => {
                // binary, or unary where an operand is expected; runs of signs are bounded so
                // that the expression tree stays shallow (each sign is one level)
                if expect_operand {
                    signs += 1;
                    if signs > MAX_FORMULA_SIGNS {
                        return Err(fail(i, msg!("too-many-signs", max = MAX_FORMULA_SIGNS)));
                    }
                } else {
                    signs = 0;
                }
                expect_operand = true;
            }
            '*' | '/' | '^' => {
                signs = 0;
                if expect_operand {
                    let reason = match (chars.get(i.wrapping_sub(1)), c) {
                        (Some('*'), '*') => "operand-left-power",
                        (Some('/'), '/' | '*') => "operand-left-comment",
                        _ => "operand-left",
                    };
                    return Err(fail(i, Message::new(reason).with("sign", c)));
                }
                expect_operand = true;
            }
            _ => return Err(fail(i, unexpected(c))),
        }
        i += 1;
    }
    if let Some(top) = open.last() {
        return Err(fail(top.column, msg!("never-closed")));
    }
    if expect_operand {
        return Err(fail(chars.len(), msg!("ends-expecting-operand")));
    }
    Ok(())
}

/// A formula written with decimal commas, as German readers write numbers, in the grammar's
/// spelling: a comma between two digits becomes a point ("0,5*u" → "0.5*u", columns
/// unchanged) unless it stands in the argument list of atan2, where it could as well separate
/// the two arguments ("atan2(1,5)"): `strict` refuses that one with the two ways to write it
/// (a German reader's formulas), otherwise it stays a separator (an English reader's, whose
/// decimal commas outside atan2 cannot mean anything else). Other commas stay.
pub fn decimal_commas(source: &str, text: &str, strict: bool) -> Result<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = chars.clone();
    // per open parenthesis: whether it holds the arguments of a function of two arguments
    let mut open: Vec<bool> = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_ascii_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let name: String = chars[start..i].iter().collect();
            let mut next = i;
            while next < chars.len() && chars[next].is_whitespace() {
                next += 1;
            }
            if chars.get(next) == Some(&'(') {
                open.push(FUNCTIONS2.contains(&name.as_str()));
                i = next + 1;
            }
            continue;
        }
        match c {
            '(' => open.push(false),
            ')' => {
                open.pop();
            }
            ',' if i > 0 && chars[i - 1].is_ascii_digit() && chars.get(i + 1).is_some_and(char::is_ascii_digit) => {
                if open.last() == Some(&true) && !strict {
                    i += 1;
                    continue;
                }
                if open.last() == Some(&true) {
                    let number = |k: usize| chars[k].is_ascii_digit() || chars[k] == '.';
                    let mut a = i;
                    while a > 0 && number(a - 1) {
                        a -= 1;
                    }
                    let mut b = i + 1;
                    while b < chars.len() && number(b) {
                        b += 1;
                    }
                    let (left, right): (String, String) =
                        (chars[a..i].iter().collect(), chars[i + 1..b].iter().collect());
                    return Err(Error::parse(
                        source,
                        None,
                        Some(i + 1),
                        msg!(
                            "ambiguous-comma",
                            text = format!("{left},{right}"),
                            point = format!("{left}.{right}"),
                            spaced = format!("{left}, {right}")
                        ),
                    ));
                }
                out[i] = '.';
            }
            _ => {}
        }
        i += 1;
    }
    Ok(out.into_iter().collect())
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
fn unexpected(c: char) -> Message {
    let hint = match c {
        'π' => "hint-pi",
        '²' => "hint-square",
        '³' => "hint-cube",
        '×' | '·' | '⋅' => "hint-times",
        '−' | '–' => "hint-minus",
        '÷' | ':' => "hint-divide",
        '[' | ']' | '{' | '}' => "hint-brackets",
        ';' => "hint-semicolon",
        _ => "hint-grammar",
    };
    // the hint is part of the sentence: its English here, its reason for other languages
    let text = Message::new(hint).english();
    msg!("unexpected-character", char = c, hint = text, hintReason = hint)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message(text: &str) -> String {
        check("a[1]", text, &["u", "a", "b"]).unwrap_err().to_string()
    }

    #[test]
    fn decimal_commas_are_points_outside_the_arguments_of_atan2() {
        let d = |t: &str| decimal_commas("e[0]", t, true);
        assert_eq!(d("0,5*u").unwrap(), "0.5*u");
        assert_eq!(d("sin(1,25*u) - 3,0").unwrap(), "sin(1.25*u) - 3.0");
        assert_eq!(d("atan2(sin(0,5*u), 1)").unwrap(), "atan2(sin(0.5*u), 1)");
        assert_eq!(d("atan2(u, 1)").unwrap(), "atan2(u, 1)");
        // a comma that is no decimal comma stays (and the checker speaks of it)
        assert_eq!(d("u,").unwrap(), "u,");
        let e = d("atan2(1,5)").unwrap_err();
        assert_eq!(e.code(), "parse-error");
        assert_eq!(e.details().column, Some(8));
        assert_eq!(
            e.to_string(),
            "e[0]: \"1,5\" could be two arguments or a decimal comma: write 1.5 for the number, or \"1, 5\" (a space after the comma) for two arguments at column 8"
        );
        assert!(d("atan2(0,5 , 2)").is_err());
        // the numbers on both sides, whole, also at the end of the text
        let e = d("atan2(12,50").unwrap_err();
        assert_eq!(e.details().column, Some(9));
        assert!(
            e.to_string().starts_with(
                "e[0]: \"12,50\" could be two arguments or a decimal comma: write 12.50 for the number, or \"12, 50\""
            ),
            "{e}"
        );
        // a space before atan2's parenthesis, and parentheses inside its arguments
        assert!(d("atan2 (1,5)").is_err());
        assert_eq!(d("atan2((1,5), 2)").unwrap(), "atan2((1.5), 2)");
        assert_eq!(d("sin ((1,5))").unwrap(), "sin ((1.5))");
        // only a comma between two digits is a decimal comma
        assert_eq!(d("atan2(u,5)").unwrap(), "atan2(u,5)");
        assert_eq!(d("atan2(5,u)").unwrap(), "atan2(5,u)");
        assert_eq!(d("u,5 + 5,u").unwrap(), "u,5 + 5,u");
        assert_eq!(d(",5").unwrap(), ",5");
        // read without strictness (an English reader): the comma in atan2's arguments separates
        assert_eq!(decimal_commas("e[0]", "atan2(1,5) + 0,5", false).unwrap(), "atan2(1,5) + 0.5");
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
        assert_eq!(message("u; u = 2"), "a[1]: unexpected character \";\" (separate the two arguments of atan2 with a comma: atan2(y, x)) at column 2");
        assert_eq!(message("u#"), "a[1]: unexpected character \"#\" (formulas use numbers, names, + - * / ^, parentheses and commas) at column 2");
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

    /// Each lookalike of an ASCII sign is named with the sign to write instead.
    #[test]
    fn lookalikes_get_their_ascii_spelling() {
        let cases = [
            ("π", "write pi"),
            ("²", "write ^2"),
            ("³", "write ^3"),
            ("×", "write * for products"),
            ("·", "write * for products"),
            ("⋅", "write * for products"),
            ("−", "write - (the ASCII minus)"),
            ("–", "write - (the ASCII minus)"),
            ("÷", "write / for quotients"),
            (":", "write / for quotients"),
            ("[", "use round parentheses"),
            ("}", "use round parentheses"),
            (";", "separate the two arguments of atan2 with a comma: atan2(y, x)"),
            ("$", "formulas use numbers, names, + - * / ^, parentheses and commas"),
        ];
        for (c, hint) in cases {
            assert_eq!(message(&format!("u{c}2")), format!("a[1]: unexpected character \"{c}\" ({hint}) at column 2"));
        }
    }

    #[test]
    fn limits_are_checked_first() {
        let long = "u+".repeat(600) + "u";
        let e = check("a[0]", &long, &["u"]).unwrap_err();
        assert_eq!(e.code(), "too-large");
        assert_eq!(e.to_string(), "a[0]: 1201 characters exceed the limit of 1000");
        let longest = "u+".repeat(499) + "u ";
        assert_eq!(longest.chars().count(), MAX_FORMULA_CHARS);
        assert!(check("a[0]", &longest, &["u"]).is_ok());
        let deep = "(".repeat(65) + "u" + &")".repeat(65);
        let e = check("a[0]", &deep, &["u"]).unwrap_err();
        assert_eq!(e.to_string(), "a[0]: 65 levels of nesting exceed the limit of 64 (first at column 65)");
        let ok = "(".repeat(64) + "u" + &")".repeat(64);
        assert!(check("a[0]", &ok, &["u"]).is_ok());
        // a function's parenthesis is a level too (the 65th "(" is at column 64·4 + 4)
        let calls = |n: usize| "sin(".repeat(n) + "u" + &")".repeat(n);
        assert!(check("a[0]", &calls(64), &["u"]).is_ok());
        let e = check("a[0]", &calls(65), &["u"]).unwrap_err();
        assert_eq!(e.to_string(), "a[0]: 65 levels of nesting exceed the limit of 64 (first at column 260)");
    }
}
