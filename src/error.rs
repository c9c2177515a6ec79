//! The core's error type: every way an input can be rejected, with a message that says
//! what is wrong and what was expected. The bindings layer turns these into JavaScript
//! `Error`s verbatim, so the messages are written for the person calling from JS.

use std::fmt;

/// Why an input was rejected.
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
        /// Numbers per record: 6 for segments, 3 for points.
        stride: usize,
    },
    /// A finite coordinate too large in magnitude to compute with safely.
    OutOfRange {
        /// Index of the offending number in the flat input array.
        index: usize,
        /// The value.
        value: f64,
        /// The largest magnitude accepted.
        max: f64,
        /// Numbers per record: 6 for segments, 3 for points.
        stride: usize,
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
        message: String,
    },
}

/// Short for `Result<T, Error>`.
pub type Result<T> = std::result::Result<T, Error>;

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::BadLength { what, len, multiple } => write!(
                f,
                "{what}: length {len} is not a multiple of {multiple} ({multiple} numbers per item)"
            ),
            Error::TooFew { what, got, min } => {
                write!(f, "{what}: got {got}, need at least {min}")
            }
            Error::TooMany { what, got, max } => {
                write!(f, "{what}: {got} exceeds the limit of {max}")
            }
            Error::NonFinite { index, value, stride } => write!(
                f,
                "coordinate {index} {} is {value}; all coordinates must be finite numbers",
                coordinate_name(*index, *stride)
            ),
            Error::OutOfRange { index, value, max, stride } => write!(
                f,
                "coordinate {index} {} is {value:e}; magnitudes above {max:e} are not accepted",
                coordinate_name(*index, *stride)
            ),
            Error::ZeroLength { ruling } => write!(
                f,
                "ruling {ruling} has zero length (its two endpoints coincide), so it has no direction"
            ),
            Error::InvalidParameter { name, message } => write!(f, "{name}: {message}"),
        }
    }
}

impl std::error::Error for Error {}

/// "(ruling 2, b.y)" for index 16 of a flat array of 6 numbers per ruling, "(point 5, y)"
/// for index 16 of 3 numbers per point.
fn coordinate_name(index: usize, stride: usize) -> String {
    const SEGMENT: [&str; 6] = ["a.x", "a.y", "a.z", "b.x", "b.y", "b.z"];
    const POINT: [&str; 3] = ["x", "y", "z"];
    match stride {
        6 => format!("(ruling {}, {})", index / 6, SEGMENT[index % 6]),
        3 => format!("(point {}, {})", index / 3, POINT[index % 3]),
        _ => String::new(),
    }
}

impl Error {
    /// Shorthand for [`Error::InvalidParameter`].
    pub fn parameter(name: &'static str, message: impl Into<String>) -> Self {
        Error::InvalidParameter { name, message: message.into() }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_problem() {
        let e = Error::NonFinite { index: 16, value: f64::NAN, stride: 6 };
        assert_eq!(
            e.to_string(),
            "coordinate 16 (ruling 2, b.y) is NaN; all coordinates must be finite numbers"
        );
        let e = Error::NonFinite { index: 16, value: f64::INFINITY, stride: 3 };
        assert!(e.to_string().starts_with("coordinate 16 (point 5, y) is inf"));
        let e = Error::BadLength { what: "segment coordinates", len: 7, multiple: 6 };
        assert!(e.to_string().contains("not a multiple of 6"));
        let e = Error::ZeroLength { ruling: 3 };
        assert!(e.to_string().starts_with("ruling 3 has zero length"));
    }
}
