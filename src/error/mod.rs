//! The core's error type: every way an input can be rejected, one variant per kind of
//! failure, with a message that says what is wrong and what was expected.
//!
//! The bindings layer turns these into JavaScript `Error`s with the same message, a stable
//! [`Error::code`] a program can branch on, and [`Error::details`] (the option, index, line,
//! column or limit at fault, and the message's reason and arguments, [`Message`]). The English
//! messages are written for the person calling from JS; a page in another language builds
//! its sentence from the reason.

use std::fmt;

mod message;
mod problem;
#[cfg(feature = "serde")]
mod serialize;
pub use message::{message_number, message_template, Arg, Catalogue, Message, MESSAGES, TEXT_REASON};
pub use problem::Problem;

/// Why an input was rejected or a computation could not be carried out.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// A flat coordinate array whose length is not a multiple of the record size.
    BadLength {
        /// What the array holds, e.g. "segment coordinates".
        what: &'static str,
        /// The length that was given.
        len: usize,
        /// The record size the length must be a multiple of.
        multiple: usize,
    },
    /// Fewer items than the computation needs.
    TooFew {
        /// What is counted, e.g. "rulings".
        what: &'static str,
        /// How many were given.
        got: usize,
        /// The minimum.
        min: usize,
    },
    /// More items than the documented size limit allows (checked before allocating).
    TooMany {
        /// What is counted.
        what: &'static str,
        /// How many were asked for.
        got: usize,
        /// The documented maximum.
        max: usize,
    },
    /// A coordinate that is NaN or infinite.
    NonFinite {
        /// Index of the offending number in the flat input array.
        index: usize,
        /// The value (NaN or ±∞).
        value: f64,
        /// What the array's records are, for naming the coordinate.
        record: Record,
    },
    /// A finite coordinate too large in magnitude to compute with safely.
    OutOfRange {
        /// Index of the offending number in the flat input array.
        index: usize,
        /// The value.
        value: f64,
        /// The largest magnitude accepted.
        max: f64,
        /// What the array's records are, for naming the coordinate.
        record: Record,
    },
    /// A segment whose endpoints coincide (to working precision), so it has no direction.
    ZeroLength {
        /// Which ruling (0-based).
        ruling: usize,
    },
    /// A parameter outside its allowed range or of the wrong kind.
    InvalidParameter {
        /// The parameter's name as the caller spells it.
        name: &'static str,
        /// What is wrong and what is expected.
        message: Message,
    },
    /// Text that could not be read: CSV, JSON, a formula, G-code.
    Parse {
        /// What was being read, e.g. "csv", "json", `"a[1]"` (a formula field).
        source: String,
        /// 1-based line, where the text has lines.
        line: Option<usize>,
        /// 1-based column (in characters) of the problem.
        column: Option<usize>,
        /// What is wrong.
        message: Message,
        /// What to do about it, said after the position (boxed: most errors have none, and
        /// every `Result` of the core carries the largest variant's size).
        hint: Option<Box<Message>>,
    },
    /// A text longer or more deeply nested than the documented limit (checked before parsing).
    TextLimit {
        /// What was being read.
        source: String,
        /// What is limited, e.g. "characters", "levels of nesting".
        what: &'static str,
        /// The value found.
        got: usize,
        /// The limit.
        max: usize,
        /// 1-based column where the limit was first exceeded, if one place is at fault.
        column: Option<usize>,
    },
    /// Geometry for which the quantity asked for does not exist: a formula whose value is not
    /// finite or whose ruling direction vanishes, lines that cancel, parallel rulings where
    /// skew ones are needed.
    Degenerate {
        /// What is degenerate, e.g. "e(u)", "lines".
        what: String,
        /// What happened and where.
        message: Message,
    },
    /// A formula whose value (or derivative) is not finite at a parameter of its range.
    NotFiniteAt {
        /// The formula, e.g. `"a[1]"`.
        what: String,
        /// The parameter u where it happens (6 significant digits).
        u: f64,
        /// And v, for a congruence p(u, v) + t·e(u, v).
        v: Option<f64>,
        /// The value found.
        value: f64,
        /// Whether it is the derivative (the value itself being finite).
        derivative: bool,
    },
    /// An iterative solver that did not reach its tolerance.
    NotConverged {
        /// Which solve.
        what: &'static str,
        /// Iterations spent.
        iterations: usize,
    },
    /// A tool pose a machine cannot serve: beyond an axis limit, or a path the controller's
    /// linear interpolation cannot follow within the tolerance (the G-code post).
    Unreachable {
        /// The pose (0-based, in the path given to the post, or the pose of the input it was
        /// refined from where the post was told the input's numbering).
        pose: usize,
        /// The 1-based line of that pose in the file it was read from, where known.
        line: Option<usize>,
        /// What is out of reach, and by how much.
        message: Message,
    },
    /// A linear system that should be symmetric positive definite but is not (numerically).
    Singular {
        /// Which system.
        what: &'static str,
        /// The failing pivot.
        pivot: usize,
        /// Its value.
        value: f64,
    },
}

/// What the records of a flat coordinate array are, so that a message can name a number:
/// "(ruling 2, b.y)", "(point 5, y)", "(line (1, 3), q.x)".
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Record {
    /// 6 numbers per ruling: a.x a.y a.z b.x b.y b.z.
    Segment,
    /// 3 numbers per point.
    Point,
    /// 6 numbers per line of a congruence grid with this many columns: p then q.
    GridLine {
        /// Columns of the grid.
        cols: usize,
    },
}

impl Record {
    /// The record of `stride` numbers (6: segments, otherwise points).
    pub fn of_stride(stride: usize) -> Self {
        if stride == 6 {
            Record::Segment
        } else {
            Record::Point
        }
    }
}

/// Short for `Result<T, Error>`.
pub type Result<T> = std::result::Result<T, Error>;

/// Where an error points: the fields of a JS error's `details` (all optional).
#[derive(Debug, Clone, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "camelCase"))]
pub struct Details {
    /// The option or parameter at fault.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub option: Option<String>,
    /// Index into the flat input array (or of the ruling, for zero-length rulings).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub index: Option<usize>,
    /// 1-based line of a text.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub line: Option<usize>,
    /// 1-based column of a text.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub column: Option<usize>,
    /// The limit that was exceeded (or not reached).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub limit: Option<f64>,
    /// What is wrong, as a stable key of [`MESSAGES`] (for a page that says it in its language).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub reason: Option<&'static str>,
    /// The values the reason's text names (numbers stay numbers).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub args: Option<Args>,
    /// What to do about it: `{ reason, args }`, said after the position.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub hint: Option<Hint>,
}

/// A message's arguments, written to JS as an object `{ name: value }`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Args(pub Vec<(&'static str, Arg)>);

/// A hint for JS: `{ reason, args }`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Hint {
    /// The hint's reason.
    pub reason: &'static str,
    /// Its arguments.
    pub args: Args,
}

impl Error {
    /// Shorthand for [`Error::InvalidParameter`].
    pub fn parameter(name: &'static str, message: impl Into<Message>) -> Self {
        Error::InvalidParameter { name, message: message.into() }
    }

    /// Shorthand for [`Error::Parse`].
    pub fn parse(
        source: impl Into<String>,
        line: Option<usize>,
        column: Option<usize>,
        message: impl Into<Message>,
    ) -> Self {
        Error::Parse { source: source.into(), line, column, message: message.into(), hint: None }
    }

    /// The same error with `hint` (what to do) added after its position; other kinds unchanged.
    pub fn with_hint(self, text: impl Into<Message>) -> Self {
        match self {
            Error::Parse { source, line, column, message, .. } => {
                Error::Parse { source, line, column, message, hint: Some(Box::new(text.into())) }
            }
            other => other,
        }
    }

    /// Shorthand for [`Error::Degenerate`].
    pub fn degenerate(what: impl Into<String>, message: impl Into<Message>) -> Self {
        Error::Degenerate { what: what.into(), message: message.into() }
    }

    /// What is wrong, as a reason with its arguments (the English of [`fmt::Display`] is made
    /// from it, after the field and the position).
    pub fn message(&self) -> Message {
        match self {
            Error::BadLength { what, len, multiple } => {
                crate::msg!("bad-length", what = *what, len = *len, multiple = *multiple)
            }
            Error::TooFew { what, got, min } => crate::msg!("too-few", what = *what, got = *got, min = *min),
            Error::TooMany { what, got, max } => crate::msg!("too-many", what = *what, got = *got, max = *max),
            Error::NonFinite { index, value, record } => {
                coordinate(record_reason("not-finite", *record), *index, *record).with("value", *value)
            }
            Error::OutOfRange { index, value, max, record } => {
                coordinate(record_reason("out-of-range", *record), *index, *record)
                    .with("value", *value)
                    .with("max", *max)
            }
            Error::ZeroLength { ruling } => crate::msg!("zero-length", ruling = *ruling),
            Error::InvalidParameter { message, .. }
            | Error::Parse { message, .. }
            | Error::Degenerate { message, .. }
            | Error::Unreachable { message, .. } => message.clone(),
            Error::TextLimit { what, got, max, .. } => {
                crate::msg!("text-too-long", what = *what, got = *got, max = *max)
            }
            Error::NotFiniteAt { u, v, value, derivative, .. } => {
                let reason = match (derivative, v) {
                    (false, None) => "not-finite-at-u",
                    (false, Some(_)) => "not-finite-at-uv",
                    (true, None) => "derivative-not-finite-at-u",
                    (true, Some(_)) => "derivative-not-finite-at-uv",
                };
                let m = Message::new(reason).with("u", *u);
                let m = match v {
                    Some(v) => m.with("v", *v),
                    None => m,
                };
                m.with("value", *value)
            }
            Error::NotConverged { iterations, .. } => crate::msg!("not-converged", iterations = *iterations),
            Error::Singular { pivot, value, .. } => crate::msg!("singular", pivot = *pivot, value = *value),
        }
    }

    /// The stable code of this kind of error, for programs to branch on:
    ///
    /// | code | when |
    /// |---|---|
    /// | `invalid-argument` | a value of the wrong type, outside its range, or an unknown option |
    /// | `not-finite` | NaN or ±∞ where a finite number is needed |
    /// | `out-of-range` | a coordinate above 1e150 in magnitude |
    /// | `too-large` | a size limit (rulings, steps, text length, nesting) |
    /// | `too-small` | fewer items than the computation needs |
    /// | `parse-error` | malformed CSV, JSON, formula or G-code |
    /// | `degenerate` | geometry without the quantity asked for (zero-length ruling, e(u) = 0, …) |
    /// | `not-converged` | an iterative solver missed its tolerance |
    /// | `singular` | a system that should be positive definite is not |
    /// | `unreachable` | a tool pose beyond a machine's limits, or a path its interpolation cannot follow |
    pub fn code(&self) -> &'static str {
        match self {
            Error::BadLength { .. } | Error::InvalidParameter { .. } => "invalid-argument",
            Error::TooFew { .. } => "too-small",
            Error::TooMany { .. } | Error::TextLimit { .. } => "too-large",
            Error::NonFinite { .. } | Error::NotFiniteAt { .. } => "not-finite",
            Error::OutOfRange { .. } => "out-of-range",
            Error::ZeroLength { .. } | Error::Degenerate { .. } => "degenerate",
            Error::Parse { .. } => "parse-error",
            Error::NotConverged { .. } => "not-converged",
            Error::Singular { .. } => "singular",
            Error::Unreachable { .. } => "unreachable",
        }
    }

    /// Where the error points (empty fields are omitted in JS).
    pub fn details(&self) -> Details {
        let mut d = Details::default();
        match self {
            Error::BadLength { multiple, .. } => d.limit = Some(*multiple as f64),
            Error::TooFew { min, .. } => d.limit = Some(*min as f64),
            Error::TooMany { max, .. } => d.limit = Some(*max as f64),
            Error::NonFinite { index, .. } => d.index = Some(*index),
            Error::OutOfRange { index, max, .. } => {
                d.index = Some(*index);
                d.limit = Some(*max);
            }
            Error::ZeroLength { ruling } => d.index = Some(*ruling),
            Error::InvalidParameter { name, .. } => d.option = Some((*name).to_string()),
            Error::Parse { source, line, column, .. } => {
                d.option = Some(source.clone());
                d.line = *line;
                d.column = *column;
            }
            Error::TextLimit { source, max, column, .. } => {
                d.option = Some(source.clone());
                d.limit = Some(*max as f64);
                d.column = *column;
            }
            Error::Degenerate { what, .. } | Error::NotFiniteAt { what, .. } => d.option = Some(what.clone()),
            Error::NotConverged { iterations, .. } => d.limit = Some(*iterations as f64),
            Error::Singular { pivot, .. } => d.index = Some(*pivot),
            Error::Unreachable { pose, line, .. } => {
                d.index = Some(*pose);
                d.line = *line;
            }
        }
        let message = self.message();
        d.reason = Some(message.reason);
        d.args = Some(Args(message.args));
        if let Error::Parse { hint: Some(h), .. } = self {
            d.hint = Some(Hint { reason: h.reason, args: Args(h.args.clone()) });
        }
        d
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = self.message().english();
        match self {
            Error::InvalidParameter { name, .. } => write!(f, "{name}: {text}"),
            Error::Parse { source, line, column, hint, .. } => {
                write!(f, "{source}: ")?;
                match (line, column) {
                    (Some(l), Some(c)) => write!(f, "line {l}, column {c}: {text}")?,
                    (Some(l), None) => write!(f, "line {l}: {text}")?,
                    (None, Some(c)) => write!(f, "{text} at column {c}")?,
                    (None, None) => write!(f, "{text}")?,
                }
                match hint {
                    Some(h) => write!(f, "; {}", h.english()),
                    None => Ok(()),
                }
            }
            Error::TextLimit { source, column, .. } => {
                write!(f, "{source}: {text}")?;
                match column {
                    Some(c) => write!(f, " (first at column {c})"),
                    None => Ok(()),
                }
            }
            Error::Degenerate { what, .. } => write!(f, "{what}: {text}"),
            Error::NotFiniteAt { what, derivative: false, .. } => write!(f, "{what} is {text}"),
            Error::NotFiniteAt { what, derivative: true, .. } => write!(f, "{what}: {text}"),
            Error::NotConverged { what, .. } | Error::Singular { what, .. } => write!(f, "{what}: {text}"),
            Error::Unreachable { line: Some(l), .. } => write!(f, "{text} (line {l})"),
            _ => write!(f, "{text}"),
        }
    }
}

impl std::error::Error for Error {}

/// The reason for a coordinate of a record kind: "not-finite-segment", "out-of-range-line", …
fn record_reason(kind: &'static str, record: Record) -> &'static str {
    match (kind, record) {
        ("not-finite", Record::Segment) => "not-finite-segment",
        ("not-finite", Record::Point) => "not-finite-point",
        ("not-finite", Record::GridLine { .. }) => "not-finite-line",
        (_, Record::Segment) => "out-of-range-segment",
        (_, Record::Point) => "out-of-range-point",
        (_, Record::GridLine { .. }) => "out-of-range-line",
    }
}

/// The arguments naming number `index` of a flat array: ruling 2, b.y for index 16 of
/// segments; point 5, y of points; line (0, 2), q.y of a grid of 4 columns.
fn coordinate(reason: &'static str, index: usize, record: Record) -> Message {
    const SEGMENT: [&str; 6] = ["a.x", "a.y", "a.z", "b.x", "b.y", "b.z"];
    const LINE: [&str; 6] = ["p.x", "p.y", "p.z", "q.x", "q.y", "q.z"];
    const POINT: [&str; 3] = ["x", "y", "z"];
    let m = Message::new(reason).with("index", index);
    match record {
        Record::Segment => m.with("item", index / 6).with("coordinate", SEGMENT[index % 6]),
        Record::Point => m.with("item", index / 3).with("coordinate", POINT[index % 3]),
        Record::GridLine { cols } => {
            let line = index / 6;
            m.with("row", line / cols.max(1)).with("col", line % cols.max(1)).with("coordinate", LINE[index % 6])
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_problem() {
        let e = Error::NonFinite { index: 16, value: f64::NAN, record: Record::Segment };
        assert_eq!(e.to_string(), "coordinate 16 (ruling 2, b.y) is NaN; all coordinates must be finite numbers");
        let e = Error::NonFinite { index: 16, value: f64::INFINITY, record: Record::Point };
        assert!(e.to_string().starts_with("coordinate 16 (point 5, y) is inf"));
        let e = Error::BadLength { what: "segment coordinates", len: 7, multiple: 6 };
        assert!(e.to_string().contains("not a multiple of 6"));
        let e = Error::ZeroLength { ruling: 3 };
        assert!(e.to_string().starts_with("ruling 3 has zero length"));
        let e = Error::NonFinite { index: 16, value: f64::NAN, record: Record::GridLine { cols: 2 } };
        assert!(e.to_string().starts_with("coordinate 16 (line (1, 0), q.y) is NaN"), "{e}");
        let e = Error::parse("a[1]", None, Some(1), "unknown function \"sni\"");
        assert_eq!(e.to_string(), "a[1]: unknown function \"sni\" at column 1");
        let e = Error::parse("csv", Some(3), Some(7), "\"x\" is not a number");
        assert_eq!(e.to_string(), "csv: line 3, column 7: \"x\" is not a number");
    }

    #[test]
    fn every_kind_has_its_code_and_details() {
        let cases = [
            (Error::BadLength { what: "x", len: 7, multiple: 6 }, "invalid-argument"),
            (Error::TooFew { what: "x", got: 1, min: 2 }, "too-small"),
            (Error::TooMany { what: "x", got: 9, max: 8 }, "too-large"),
            (Error::NonFinite { index: 2, value: f64::NAN, record: Record::Point }, "not-finite"),
            (Error::OutOfRange { index: 2, value: 1e200, max: 1e150, record: Record::Point }, "out-of-range"),
            (Error::ZeroLength { ruling: 4 }, "degenerate"),
            (Error::parameter("w", "bad"), "invalid-argument"),
            (Error::parse("json", Some(1), Some(2), "bad"), "parse-error"),
            (
                Error::TextLimit { source: "a[0]".into(), what: "characters", got: 2000, max: 1000, column: None },
                "too-large",
            ),
            (Error::degenerate("e(u)", "vanishes"), "degenerate"),
            (Error::NotConverged { what: "system", iterations: 10 }, "not-converged"),
            (
                Error::NotFiniteAt { what: "a[0]".into(), u: 0.0, v: None, value: f64::INFINITY, derivative: false },
                "not-finite",
            ),
            (Error::Singular { what: "system", pivot: 3, value: -1.0 }, "singular"),
        ];
        for (e, code) in cases {
            assert_eq!(e.code(), code, "{e}");
        }
        let d = Error::parse("json", Some(3), Some(9), "x").details();
        assert_eq!((d.line, d.column, d.option.as_deref()), (Some(3), Some(9), Some("json")));
        assert_eq!(Error::TooMany { what: "x", got: 9, max: 8 }.details().limit, Some(8.0));
        assert_eq!(Error::NonFinite { index: 7, value: f64::NAN, record: Record::Segment }.details().index, Some(7));
        assert_eq!(Error::parameter("steps", "bad").details().option.as_deref(), Some("steps"));
    }

    #[test]
    fn the_kinds_that_name_their_subject_say_it_first() {
        assert_eq!(Record::of_stride(6), Record::Segment);
        assert_eq!(Record::of_stride(3), Record::Point);
        let e = Error::OutOfRange { index: 4, value: 1e200, max: 1e150, record: Record::of_stride(3) };
        assert!(e.to_string().starts_with("coordinate 4 (point 1, y)"), "{e}");
        assert!(Error::parameter("steps", "bad").to_string().starts_with("steps: "));
        let e = Error::NotConverged { what: "the development", iterations: 10 };
        assert!(e.to_string().starts_with("the development: "), "{e}");
        let e = Error::Singular { what: "the fairing system", pivot: 3, value: -1.0 };
        assert!(e.to_string().starts_with("the fairing system: "), "{e}");
    }
}
