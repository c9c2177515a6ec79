//! Errors thrown to JavaScript: a real `Error` whose `message` names the function and the
//! problem, with a stable `code` (see [`ruledlab::Error::code`]) and, where it helps, `details`
//! (`{ option, index, line, column, limit, reason, args, hint }`), so a page can tell "too
//! large" from "malformed" and say what is wrong in its own language (`reason` is a key of
//! [`ruledlab::MESSAGES`] or `ruledlab_cam::CAM_MESSAGES`, `args` its values).

use js_sys::Reflect;
use ruledlab::{Arg, Args, Details, Error};
use wasm_bindgen::JsValue;

/// A reason to throw: a core error, or a problem with the arguments themselves (a wrong type,
/// an unknown option), which has the code `invalid-argument`.
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

/// The JS `Error` for `problem`, its message prefixed by `func` (e.g. "RuledSurface.fromSegments").
pub fn fail(func: &str, problem: impl Into<Problem>) -> JsValue {
    let (message, code, details) = match problem.into() {
        Problem::Core(e) => (e.to_string(), e.code(), e.details()),
        Problem::Argument { option, message } => {
            // the argument checks speak to programmers: their reason is plain text
            let details = Details {
                option,
                reason: Some(ruledlab::TEXT_REASON),
                args: Some(Args(vec![("text", Arg::Text(message.clone()))])),
                ..Details::default()
            };
            (message, "invalid-argument", details)
        }
    };
    let error = js_sys::Error::new(&format!("{func}: {message}"));
    // Setting a property of a fresh Error cannot fail; were it to, the message still stands.
    let _ = Reflect::set(&error, &"code".into(), &code.into());
    let details = serde_wasm_bindgen::to_value(&details).unwrap_or(JsValue::UNDEFINED);
    let _ = Reflect::set(&error, &"details".into(), &details);
    error.into()
}

/// A problem with the option `option` (its name goes into `details.option`).
pub fn fail_option(func: &str, option: &str, message: impl Into<String>) -> JsValue {
    fail(func, Problem::Argument { option: Some(option.to_string()), message: message.into() })
}
