//! Errors thrown to JavaScript: a real `Error` whose `message` names the function and the
//! problem, with a stable `code` (see [`ruledlab::Error::code`]) and, where it helps, `details`
//! (`{ option, index, line, column, limit, reason, args, hint }`), so a page can tell "too
//! large" from "malformed" and say what is wrong in its own language (`reason` is a key of
//! [`ruledlab::MESSAGES`] or `ruledlab_cam::CAM_MESSAGES`, `args` its values).

use js_sys::Reflect;
pub use ruledlab::Problem;
use wasm_bindgen::JsValue;

/// The JS `Error` for `problem`, its message prefixed by `func` (e.g. "RuledSurface.fromSegments").
pub fn fail(func: &str, problem: impl Into<Problem>) -> JsValue {
    let (message, code, details) = problem.into().parts();
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
