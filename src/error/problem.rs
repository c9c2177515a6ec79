//! What a binding refuses a call for, in either language (the JavaScript bindings'
//! `ruledlab-js`, the Python extension's `ruledlab-py`): an error of the core, or a problem with
//! an argument itself (a wrong type, an unknown option), which has the code `invalid-argument`
//! and, as its reason, plain text ([`TEXT_REASON`]: the argument checks speak to programmers).

use super::{Arg, Args, Details, Error, TEXT_REASON};

/// A reason to refuse a call.
#[derive(Debug, Clone, PartialEq)]
pub enum Problem {
    /// An error of the core.
    Core(Error),
    /// A problem with an argument, optionally naming the option at fault.
    Argument {
        /// The option or argument name.
        option: Option<String>,
        /// What is wrong.
        message: String,
    },
}

impl Problem {
    /// The message, the stable code and the details a binding raises.
    pub fn parts(self) -> (String, &'static str, Details) {
        match self {
            Problem::Core(e) => (e.to_string(), e.code(), e.details()),
            Problem::Argument { option, message } => {
                let details = Details {
                    option,
                    reason: Some(TEXT_REASON),
                    args: Some(Args(vec![("text", Arg::Text(message.clone()))])),
                    ..Details::default()
                };
                (message, "invalid-argument", details)
            }
        }
    }
}

impl From<Error> for Problem {
    fn from(e: Error) -> Self {
        Problem::Core(e)
    }
}

impl From<String> for Problem {
    fn from(message: String) -> Self {
        Problem::Argument { option: None, message }
    }
}

impl From<&str> for Problem {
    fn from(message: &str) -> Self {
        Problem::Argument { option: None, message: message.to_string() }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_argument_problem_is_invalid_argument_with_its_text_and_option() {
        let (message, code, d) =
            Problem::Argument { option: Some("feed".into()), message: "feed must be > 0".into() }.parts();
        assert_eq!((message.as_str(), code), ("feed must be > 0", "invalid-argument"));
        assert_eq!((d.option.as_deref(), d.reason), (Some("feed"), Some(TEXT_REASON)));
        assert_eq!(d.args, Some(Args(vec![("text", Arg::Text("feed must be > 0".into()))])));
        let e = Error::TooFew { what: "rulings", got: 1, min: 2 };
        assert_eq!(Problem::from(e.clone()).parts(), (e.to_string(), e.code(), e.details()));
        assert_eq!(Problem::from("x"), Problem::Argument { option: None, message: "x".into() });
    }
}
