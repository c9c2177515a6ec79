//! Texts JavaScript hands in to be read as data (both modules read some): the text and its
//! format checked, and numbers converted by the host's `parseFloat`.

use crate::args::{describe, fail};
use wasm_bindgen::JsValue;

/// The host's `parseFloat` (correctly rounded), for tokens the core has checked to be decimal
/// numbers: keeps Rust's float-parsing tables out of the wasm file.
pub fn js_number(token: &str) -> f64 {
    js_sys::parse_float(token)
}

/// The text an import reads and whether it is JSON: `format` "json" or "csv", or, left out, JSON
/// when the text starts with `[` or `{`. Throws (as `f`) for a text that is not a string or
/// another format.
pub fn text_and_format(f: &str, text: JsValue, format: &JsValue) -> Result<(String, bool), JsValue> {
    let Some(text) = text.as_string() else {
        return Err(fail(f, format!("text must be a string, got {}", describe(&text))));
    };
    let json = match format.as_string().as_deref() {
        None if format.is_undefined() || format.is_null() => text.trim_start().starts_with(['[', '{']),
        Some("json") => true,
        Some("csv") => false,
        Some(other) => return Err(fail(f, format!("format must be \"csv\" or \"json\", got \"{other}\""))),
        None => return Err(fail(f, format!("format must be \"csv\" or \"json\", got {}", describe(format)))),
    };
    Ok((text, json))
}
