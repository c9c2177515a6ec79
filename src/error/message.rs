//! The core's messages: each a stable *reason* (a kebab-case key) with named arguments, and
//! its English text from one catalogue ([`MESSAGES`]). The English is the API's (an
//! `Error`'s `message` in JS); a page speaking another language builds its own sentence from
//! the reason and the arguments (`details.reason`, `details.args` in JS), so a German student
//! reads "Die Formel endet, wo ein Operand erwartet wird" while a developer's console keeps
//! "the formula ends where an operand is expected". The page has a text for every reason of
//! this catalogue in every language (tests/node/messages.test.mjs checks it, placeholders
//! included).

use std::fmt;
use std::fmt::Write as _;

/// A value of a message: text (a name, a formula's piece) or a number (formatted by the
/// reader's language: a decimal comma in German).
#[derive(Debug, Clone, PartialEq)]
pub enum Arg {
    /// Text, shown as it is.
    Text(String),
    /// A number.
    Number(f64),
}

impl From<&str> for Arg {
    fn from(s: &str) -> Self {
        Arg::Text(s.to_string())
    }
}
impl From<&&str> for Arg {
    fn from(s: &&str) -> Self {
        Arg::Text((*s).to_string())
    }
}
impl From<String> for Arg {
    fn from(s: String) -> Self {
        Arg::Text(s)
    }
}
impl From<char> for Arg {
    fn from(c: char) -> Self {
        Arg::Text(c.to_string())
    }
}
impl From<f64> for Arg {
    fn from(x: f64) -> Self {
        Arg::Number(x)
    }
}
impl From<usize> for Arg {
    fn from(n: usize) -> Self {
        Arg::Number(n as f64)
    }
}

impl Arg {
    /// The English form: text as it is; a number in Rust's shortest form, in scientific
    /// notation from 1e15 and below 1e-4.
    pub fn english(&self) -> String {
        match self {
            Arg::Text(s) => s.clone(),
            Arg::Number(x) => message_number(*x),
        }
    }
}

/// A number for an English message.
pub fn message_number(x: f64) -> String {
    let a = x.abs();
    if x.is_finite() && a != 0.0 && !(1e-4..1e15).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// A catalogue of messages: each reason with its English template (`{name}`: an argument).
pub type Catalogue = &'static [(&'static str, &'static str)];

/// A reason and its arguments.
#[derive(Clone)]
pub struct Message {
    /// The stable key of what is wrong (a key of [`MESSAGES`], or of the catalogue of the crate
    /// that made the message: ruledlab-cam has its own).
    pub reason: &'static str,
    /// The values its text names, in order.
    pub args: Vec<(&'static str, Arg)>,
    /// The catalogue that has the reason's English template.
    pub catalogue: Catalogue,
}

/// The reason of a message that is only text (for callers of the API who pass their own
/// wording; no page shows it, tests/node/messages.test.mjs keeps it off every page path).
pub const TEXT_REASON: &str = "text";

// (a message is its reason and arguments: the catalogue only says where its template is)
impl PartialEq for Message {
    fn eq(&self, other: &Self) -> bool {
        self.reason == other.reason && self.args == other.args
    }
}

impl fmt::Debug for Message {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Message").field("reason", &self.reason).field("args", &self.args).finish()
    }
}

impl Message {
    /// A message of the core's catalogue, without arguments yet.
    pub fn new(reason: &'static str) -> Self {
        Message { reason, args: Vec::new(), catalogue: MESSAGES }
    }

    /// A message of another crate's catalogue (its reasons are that crate's own), without arguments yet.
    pub fn of(catalogue: Catalogue, reason: &'static str) -> Self {
        Message { reason, args: Vec::new(), catalogue }
    }

    /// The same message with one more argument.
    pub fn with(mut self, name: &'static str, value: impl Into<Arg>) -> Self {
        self.args.push((name, value.into()));
        self
    }

    /// The argument called `name`.
    pub fn arg(&self, name: &str) -> Option<&Arg> {
        self.args.iter().find(|(n, _)| *n == name).map(|(_, v)| v)
    }

    /// The English text: the catalogue's template with `{name}` replaced by the arguments.
    pub fn english(&self) -> String {
        let template = self.catalogue.iter().find(|(r, _)| *r == self.reason).map(|(_, t)| *t);
        let Some(template) = template else {
            // a reason missing from the catalogue is a bug the tests catch; say what there is
            let mut out = self.reason.to_string();
            for (n, v) in &self.args {
                let _ = write!(out, " {n}={}", v.english());
            }
            return out;
        };
        let mut out = String::with_capacity(template.len() + 16);
        let mut rest = template;
        while let Some(open) = rest.find('{') {
            out.push_str(&rest[..open]);
            let after = &rest[open + 1..];
            match after.find('}') {
                Some(close) => {
                    let name = &after[..close];
                    match self.arg(name) {
                        Some(v) => out.push_str(&v.english()),
                        None => {
                            out.push('{');
                            out.push_str(name);
                            out.push('}');
                        }
                    }
                    rest = &after[close + 1..];
                }
                None => {
                    out.push_str(&rest[open..]);
                    rest = "";
                }
            }
        }
        out.push_str(rest);
        out
    }
}

impl From<String> for Message {
    fn from(text: String) -> Self {
        Message::new(TEXT_REASON).with("text", text)
    }
}

impl From<&str> for Message {
    fn from(text: &str) -> Self {
        Message::new(TEXT_REASON).with("text", text)
    }
}

/// `msg!("unknown-function", name = name)`: a [`Message`] with named arguments.
#[macro_export]
macro_rules! msg {
    ($reason:literal $(, $name:ident = $value:expr)* $(,)?) => {
        $crate::error::Message::new($reason)$(.with(stringify!($name), $value))*
    };
}

/// The English template of `reason`.
pub fn message_template(reason: &str) -> Option<&'static str> {
    MESSAGES.iter().find(|(r, _)| *r == reason).map(|(_, t)| *t)
}

/// Every reason of the core with its English template (`{name}`: an argument). The page's
/// language files (www/i18n) have a text for each, under `error.<reason>`.
pub const MESSAGES: Catalogue = &[
    (TEXT_REASON, "{text}"),
    // the kinds with fields of their own (Error::message)
    ("bad-length", "{what}: length {len} is not a multiple of {multiple} ({multiple} numbers per item)"),
    ("too-few", "{what}: got {got}, need at least {min}"),
    ("too-many", "{what}: {got} exceeds the limit of {max}"),
    ("not-finite-segment", "coordinate {index} (ruling {item}, {coordinate}) is {value}; all coordinates must be finite numbers"),
    ("not-finite-point", "coordinate {index} (point {item}, {coordinate}) is {value}; all coordinates must be finite numbers"),
    ("not-finite-line", "coordinate {index} (line ({row}, {col}), {coordinate}) is {value}; all coordinates must be finite numbers"),
    ("out-of-range-segment", "coordinate {index} (ruling {item}, {coordinate}) is {value}; magnitudes above {max} are not accepted"),
    ("out-of-range-point", "coordinate {index} (point {item}, {coordinate}) is {value}; magnitudes above {max} are not accepted"),
    ("out-of-range-line", "coordinate {index} (line ({row}, {col}), {coordinate}) is {value}; magnitudes above {max} are not accepted"),
    ("zero-length", "ruling {ruling} has zero length (its two endpoints coincide), so it has no direction"),
    ("text-too-long", "{got} {what} exceed the limit of {max}"),
    ("not-finite-at-u", "not finite at u = {u} (value {value}: a division by zero, or a function outside its domain?)"),
    ("not-finite-at-uv", "not finite at (u, v) = ({u}, {v}) (value {value}: a division by zero, or a function outside its domain?)"),
    ("derivative-not-finite-at-u", "the derivative is not finite at u = {u} (it is {value}), so the exact invariants do not exist there"),
    ("derivative-not-finite-at-uv", "the derivative is not finite at (u, v) = ({u}, {v}) (it is {value}), so the exact invariants do not exist there"),
    ("not-converged", "conjugate gradients did not converge in {iterations} iterations"),
    ("singular", "matrix is not positive definite (pivot {pivot} is {value})"),
    // formulas: the checker (src/formula/check.rs) and the compiler (program.rs)
    ("formula-empty", "is empty; write a formula such as cos(u)"),
    ("operator-before-number", "missing operator before this number (write * for products)"),
    ("number-before-name", "write {number}*{next}…, not {number}{next}… (products need *)"),
    ("operator-before-name", "missing operator before \"{name}\" (write * for products)"),
    ("function-needs-parentheses", "{name} needs its argument in parentheses: {name}(…)"),
    ("not-a-function", "\"{name}\" is not a function; write {name}*(…) for a product"),
    ("unknown-function", "unknown function \"{name}\""),
    ("unknown-name", "unknown name \"{name}\""),
    ("known-names", "known: {names}"),
    ("operator-before-parenthesis", "missing operator before \"(\" (write * for products)"),
    ("unmatched-close", "\")\" without a matching \"(\""),
    ("empty-parentheses", "empty parentheses"),
    ("operand-before", "an operand is missing before \"{sign}\""),
    ("atan2-arguments", "atan2 takes two arguments: atan2(y, x)"),
    ("comma-outside-atan2", "a comma is allowed only between the two arguments of atan2(y, x)"),
    (
        "ambiguous-comma",
        "\"{text}\" could be two arguments or a decimal comma: write {point} for the number, or \"{spaced}\" (a space after the comma) for two arguments",
    ),
    ("too-many-signs", "more than {max} signs in a row"),
    ("operand-left", "\"{sign}\" needs an operand on its left"),
    ("operand-left-power", "\"{sign}\" needs an operand on its left (write ^ for powers)"),
    ("operand-left-comment", "\"{sign}\" needs an operand on its left (comments are not part of formulas)"),
    ("unexpected-character", "unexpected character \"{char}\" ({hint})"),
    ("hint-pi", "write pi"),
    ("hint-square", "write ^2"),
    ("hint-cube", "write ^3"),
    ("hint-times", "write * for products"),
    ("hint-minus", "write - (the ASCII minus)"),
    ("hint-divide", "write / for quotients"),
    ("hint-brackets", "use round parentheses"),
    ("hint-semicolon", "separate the two arguments of atan2 with a comma: atan2(y, x)"),
    ("hint-grammar", "formulas use numbers, names, + - * / ^, parentheses and commas"),
    ("never-closed", "\"(\" is never closed"),
    ("ends-expecting-operand", "the formula ends where an operand is expected"),
    ("not-in-formulas", "\"{operator}\" is not part of formulas"),
    ("ambiguous-power", "a^b^c is ambiguous"),
    ("power-parentheses", "write (a^b)^c or a^(b^c)"),
    ("unreadable", "cannot be read ({detail})"),
    // intervals and parameters of formula surfaces and congruences
    ("interval-not-finite", "needs two finite numbers, got [{lo}, {hi}]"),
    ("interval-order", "needs min < max, got [{lo}, {hi}]"),
    ("interval-equal", "needs different numbers, got [{lo}, {hi}]"),
    ("parameter-not-finite", "{name} must be a finite number, got {value}"),
    ("grid-size", "must be an integer from {min} to {max}, got {value}"),
    ("direction-vanishes-u", "e(u) vanishes at u = {u}, so the ruling there has no direction"),
    ("direction-vanishes-uv", "e(u, v) vanishes at (u, v) = ({u}, {v}), so the line there has no direction"),
    // geometry
    ("line-zero-length", "line ({row}, {col}) has zero length (p = q), so it has no direction"),
    ("lines-cancel", "a refined line has no direction: the weights cancel opposite lines"),
    ("parallel-at-step", "rulings at step {h} are parallel"),
    ("no-striction-point", "{name} has no striction point at u = {u} (cylindrical ruling)"),
    // developable strips and flat patterns (src/developable)
    ("span-crosses-regression", "must start at 0 or beyond, got {from}: the strip would cross its edge of regression (or the apex)"),
    ("directrix-edge-zero", "points {edge} and {next} of the directrix coincide: the edge between them has no direction"),
    ("directrix-no-turn-at", "the directrix does not turn at point {point}: the lines of the edges meeting there coincide and bound no face"),
    ("directrix-straight", "the directrix is straight: it turns nowhere, so it has no rectifying developable"),
    ("apex-not-finite", "the apex must be three finite numbers"),
    ("apex-on-directrix", "the apex lies on point {point} of the directrix: the ruling there has no direction"),
    ("apex-in-line", "points {edge} and {next} of the directrix are in line with the apex: the face between their rulings has no width"),
    ("direction-zero", "must be a nonzero vector of finite numbers"),
    ("edge-along-rulings", "edge {edge} of the directrix runs along the rulings: the face there has no width"),
    ("edge-along-ruling", "the edge of the directrix at point {point} runs along the ruling there: the next ruling is not defined"),
    ("not-developable", "rulings {i} and {j} are not coplanar (an end lies {height} off the plane of the other three, more than {max}; δ = {delta}): the strip is not developable; Section 3's approximate development maps it with gaps"),
    ("rulings-collinear", "rulings {i} and {j} lie on one line: the face between them has no width"),
    ("out-of-interval", "must be a number from {min} to {max}, got {value}"),
    ("pattern-points", "needs {need} numbers (x, y of both ends of every ruling), got {got}"),
    ("sheet-too-large", "the sheet would be {width} × {height} mm, more than {max} mm a side: choose fewer millimetres per unit"),
    ("paper-too-small", "a page of {width} × {height} mm leaves no room inside its margins"),
    // CSV and JSON (src/io)
    ("not-a-number", "\"{text}\" is not a number"),
    ("not-finite-number", "{text} is not a finite number"),
    ("csv-six-numbers", "expected 6 numbers (a.x a.y a.z b.x b.y b.z), found {found}"),
    ("csv-no-data", "no data lines (6 numbers each) found"),
    ("import-too-few", "{found} record(s) of 6 numbers: at least 2 are needed (a ruled surface has two rulings or more)"),
    ("import-zero-length", "record {record} has zero length (its two endpoints coincide), so it has no direction"),
    ("json-too-deep", "nested deeper than {max} levels"),
    ("json-end", "unexpected end of the text"),
    ("json-array-separator", "expected , or ] in an array"),
    ("json-string-key", "expected a string key"),
    ("json-colon", "expected : after a key"),
    ("json-object-separator", "expected , or } in an object"),
    ("json-unterminated", "unterminated string"),
    ("json-word", "unexpected word"),
    ("json-character", "unexpected character '{char}'"),
    ("json-trailing", "unexpected text after the JSON value"),
    ("json-segments-missing", "an object needs a \"segments\" array"),
    ("json-grid-integer", "\"{key}\" must be an integer from 2 to {max}"),
    ("json-rows-and-cols", "give both \"rows\" and \"cols\", or neither"),
    ("json-segments-array", "segments must be an array"),
    ("json-segment-six", "a segment needs 6 numbers, found {found}"),
    ("json-number", "expected a number"),
    ("json-segment", "expected [ax, ay, az, bx, by, bz]"),
    ("json-whole-segments", "{count} numbers are not a whole number of segments (6 each)"),
    ("json-grid-count", "a {rows} × {cols} grid needs {need} segments, found {found}"),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// The argument names of a template, in order (each once).
    fn placeholders(template: &str) -> Vec<&str> {
        let mut names = Vec::new();
        let mut rest = template;
        while let Some(open) = rest.find('{') {
            let after = &rest[open + 1..];
            let Some(close) = after.find('}') else { break };
            let name = &after[..close];
            if !name.is_empty() && !names.contains(&name) {
                names.push(name);
            }
            rest = &after[close + 1..];
        }
        names
    }

    #[test]
    fn a_message_fills_its_template() {
        let m = msg!("number-before-name", number = "2", next = 'u');
        assert_eq!(m.english(), "write 2*u…, not 2u… (products need *)");
        assert_eq!(msg!("too-many-signs", max = 4usize).english(), "more than 4 signs in a row");
        assert_eq!(Message::from("free text").english(), "free text");
        assert_eq!(msg!("interval-order", lo = 1.5, hi = 1.0).english(), "needs min < max, got [1.5, 1]");
    }

    #[test]
    fn numbers_read_as_numbers() {
        assert_eq!(message_number(3.0), "3");
        assert_eq!(message_number(0.25), "0.25");
        assert_eq!(message_number(1e300), "1e300");
        assert_eq!(message_number(-2.5e-7), "-2.5e-7");
        assert_eq!(message_number(f64::NAN), "NaN");
        assert_eq!(message_number(f64::INFINITY), "inf");
        assert_eq!(message_number(0.0), "0");
    }

    #[test]
    fn the_catalogue_has_each_reason_once_and_closed_placeholders() {
        for (i, (reason, template)) in MESSAGES.iter().enumerate() {
            assert!(MESSAGES[..i].iter().all(|(r, _)| r != reason), "{reason} twice");
            assert!(reason.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-'), "{reason}");
            // every "{" opens a placeholder that closes before the next one opens
            for piece in template.split('{').skip(1) {
                let name = piece.split('}').next().unwrap_or("");
                assert!(
                    piece.contains('}') && !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric()),
                    "{reason}: {template}"
                );
            }
        }
        assert_eq!(placeholders("{a} and {b}, {a}"), ["a", "b"]);
    }

    #[test]
    fn a_reason_outside_the_catalogue_still_says_what_it_has() {
        let m = Message::new("no-such-reason").with("x", 2.0);
        assert_eq!(m.english(), "no-such-reason x=2");
    }
}
