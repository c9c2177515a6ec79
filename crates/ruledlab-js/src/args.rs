//! Checking what JavaScript passed in, and writing what goes back.
//!
//! Options objects are read by serde-wasm-bindgen into `#[derive(Deserialize)]` structs
//! ([`options`], [`required`]); structured results are written by it from `#[derive(Serialize)]`
//! structs ([`to_js`]), typed arrays travelling as themselves (`serde_wasm_bindgen::preserve`).
//! Numbers, coordinates and indices passed as arguments are taken as `JsValue`s and checked
//! here, so that a wrong type (a string, a BigInt) is an `Error` with a `code` like any other.

use js_sys::{Array, Float32Array, Float64Array, Object, Reflect, Uint32Array};
use serde::de::{self, DeserializeOwned, Visitor};
use serde::Serialize;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

pub use super::error::{fail, fail_option};

/// Numbers (coordinates, parameters, amounts) given as a `Float64Array`, a `Float32Array` or
/// an array of numbers: the f32 buffers the core hands out can come back as they are.
pub fn numbers(func: &str, name: &str, value: &JsValue) -> Result<Vec<f64>, JsValue> {
    if let Some(a) = value.dyn_ref::<Float64Array>() {
        return Ok(a.to_vec());
    }
    if let Some(a) = value.dyn_ref::<Float32Array>() {
        return Ok(a.to_vec().into_iter().map(f64::from).collect());
    }
    if let Some(a) = value.dyn_ref::<Array>() {
        return a
            .iter()
            .enumerate()
            .map(|(k, x)| {
                x.as_f64().ok_or_else(|| fail(func, format!("{name}[{k}] must be a number, got {}", describe(&x))))
            })
            .collect();
    }
    Err(fail(func, format!("{name} must be a Float64Array, Float32Array or array of numbers, got {}", describe(value))))
}

/// Vertex indices given as a `Uint32Array` or an array of non-negative integers.
pub fn indices(func: &str, name: &str, value: &JsValue) -> Result<Vec<u32>, JsValue> {
    if let Some(a) = value.dyn_ref::<Uint32Array>() {
        return Ok(a.to_vec());
    }
    if let Some(a) = value.dyn_ref::<Array>() {
        return a
            .iter()
            .enumerate()
            .map(|(k, x)| match x.as_f64() {
                Some(i) if i >= 0.0 && i <= u32::MAX as f64 && i.fract() == 0.0 => Ok(i as u32),
                _ => Err(fail(
                    func,
                    format!("{name}[{k}] must be an integer from 0 to {}, got {}", u32::MAX, describe(&x)),
                )),
            })
            .collect();
    }
    Err(fail(func, format!("{name} must be a Uint32Array or array of integers, got {}", describe(value))))
}

/// What a JS value is for a number message: the number itself, or "a string", "a bigint" ….
pub fn number_or_kind(value: &JsValue) -> String {
    match value.as_f64() {
        Some(x) => format!("{x}"),
        None => describe(value),
    }
}

/// A finite number passed as an argument.
pub fn number(func: &str, name: &str, value: &JsValue) -> Result<f64, JsValue> {
    match value.as_f64() {
        Some(x) if x.is_finite() => Ok(x),
        _ => Err(fail(func, format!("{name} must be a finite number, got {}", number_or_kind(value)))),
    }
}

/// An integer in [min, max] passed as an argument.
pub fn integer(func: &str, name: &str, value: &JsValue, min: usize, max: usize) -> Result<usize, JsValue> {
    match value.as_f64() {
        Some(x) if x.fract() == 0.0 && x >= min as f64 && x <= max as f64 => Ok(x as usize),
        _ => Err(fail(func, format!("{name} must be an integer from {min} to {max}, got {}", number_or_kind(value)))),
    }
}

/// A catalogue's entry by its name (`byName(name)` of a class): `find` of the string, refused
/// when the argument is not a string or `find` knows no such name.
pub fn by_name<T>(func: &str, name: &JsValue, find: impl FnOnce(&str) -> ruledlab::Result<T>) -> Result<T, JsValue> {
    let Some(name) = name.as_string() else {
        return Err(fail(func, format!("name must be a string, got {}", describe(name))));
    };
    find(&name).map_err(|e| fail(func, e))
}

/// As [`integer`], `default` when the argument is left out (`undefined`).
pub fn optional_integer(
    func: &str,
    name: &str,
    value: &JsValue,
    min: usize,
    max: usize,
    default: usize,
) -> Result<usize, JsValue> {
    if value.is_undefined() {
        Ok(default)
    } else {
        integer(func, name, value, min, max)
    }
}

/// A boolean passed as an argument, `default` when left out (`undefined`).
pub fn optional_bool(func: &str, name: &str, value: &JsValue, default: bool) -> Result<bool, JsValue> {
    if value.is_undefined() {
        return Ok(default);
    }
    value.as_bool().ok_or_else(|| fail(func, format!("{name} must be true or false, got {}", describe(value))))
}

/// An integer option in [min, max], if given (read by serde as a number, checked here so the
/// message names the range).
pub fn integer_option(
    func: &str,
    name: &str,
    value: Option<f64>,
    min: usize,
    max: usize,
) -> Result<Option<usize>, JsValue> {
    match value {
        None => Ok(None),
        Some(x) if x.fract() == 0.0 && x >= min as f64 && x <= max as f64 => Ok(Some(x as usize)),
        Some(x) => {
            Err(fail_option(func, name, format!("options.{name} must be an integer from {min} to {max}, got {x}")))
        }
    }
}

/// A finite number option, if given.
pub fn finite_option(func: &str, name: &str, value: Option<f64>) -> Result<Option<f64>, JsValue> {
    match value {
        Some(x) if !x.is_finite() => {
            Err(fail_option(func, name, format!("options.{name} must be a finite number, got {x}")))
        }
        other => Ok(other),
    }
}

/// Refuses option `name` (given as `present`) unless the chosen scheme is `scheme`: an option
/// of another scheme is a likely mistake that would otherwise be silently ignored.
pub fn only_for(func: &str, name: &str, present: bool, scheme: &str, chosen: Option<&str>) -> Result<(), JsValue> {
    if present && chosen != Some(scheme) {
        let chosen = chosen.map(|c| format!(", not to \"{c}\"")).unwrap_or_default();
        return Err(fail_option(func, name, format!("options.{name} applies to the \"{scheme}\" scheme only{chosen}")));
    }
    Ok(())
}

/// An options object that may be left out (`undefined` or `null` read as `{}`), read by
/// serde-wasm-bindgen into `T`; see [`required`].
pub fn options<T: DeserializeOwned + Default>(func: &str, value: JsValue) -> Result<T, JsValue> {
    if value.is_undefined() || value.is_null() {
        return Ok(T::default());
    }
    required(func, "options", value, &[])
}

/// An object argument (`what`: its name in messages) read by serde-wasm-bindgen into `T`,
/// after checking that it is a plain object whose keys are all fields of `T`, and that every
/// nested object named in `nested` has only the fields of its type. serde-wasm-bindgen reads a
/// struct field by field, so it never sees an unknown key: a typo ("step" for "steps") would
/// otherwise be silently ignored. Wrong types are reported with the option's path
/// (`options.levels: expected a number, got a string`).
pub fn required<T: DeserializeOwned>(
    func: &str,
    what: &str,
    value: JsValue,
    nested: &[(&str, &'static [&'static str])],
) -> Result<T, JsValue> {
    let known = fields::<T>();
    let plain = |v: &JsValue| v.is_object() && !Array::is_array(v) && !v.is_function();
    if !plain(&value) {
        return Err(fail(
            func,
            format!("{what} must be an object {{ {} }}, got {}", known.join(", "), describe(&value)),
        ));
    }
    let check_keys = |object: &JsValue, prefix: &str, known: &[&str]| -> Result<(), JsValue> {
        for key in Object::keys(object.unchecked_ref::<Object>()).iter() {
            let key = key.as_string().unwrap_or_default();
            if !known.contains(&key.as_str()) {
                return Err(fail_option(
                    func,
                    &format!("{prefix}{key}"),
                    format!("unknown option \"{prefix}{key}\"; known options: {}", known.join(", ")),
                ));
            }
        }
        Ok(())
    };
    check_keys(&value, "", known)?;
    for (name, keys) in nested {
        let inner = Reflect::get(&value, &JsValue::from_str(name)).unwrap_or(JsValue::UNDEFINED);
        if plain(&inner) {
            check_keys(&inner, &format!("{name}."), keys)?;
        }
    }
    serde_path_to_error::deserialize(serde_wasm_bindgen::Deserializer::from(value)).map_err(|e| {
        let path = e.path().to_string();
        let message = plain_words(&e.into_inner().to_string());
        if path == "." {
            fail(func, format!("{what}: {message}"))
        } else {
            fail_option(func, &path, format!("{what}.{path}: {message}"))
        }
    })
}

/// serde's messages in the words of the book's chapter on errors: "expected a number, got the string \"x\"",
/// not "invalid type: string `x`, expected f64".
pub fn plain_words(message: &str) -> String {
    let message = message.strip_prefix("Error: ").unwrap_or(message);
    let words = |text: &str| -> String {
        let mut out = text.to_string();
        for (code, words) in [
            ("f64", "a number"),
            ("a boolean", "true or false"),
            ("floating point", "the number"),
            ("unknown variant", "unknown value"),
            ("`", "\""),
        ] {
            out = out.replace(code, words);
        }
        out
    };
    // serde's `Unexpected` as words: floating point `4.0` → the number 4, string "x" → the string "x"
    let unexpected = |got: &str| -> String {
        let value = |prefix: &str| got.strip_prefix(prefix).map(|v| v.trim_matches(['`', '"']).to_string());
        if let Some(v) = value("floating point ").or_else(|| value("integer ")) {
            format!("the number {}", v.strip_suffix(".0").unwrap_or(&v))
        } else if let Some(v) = value("string ") {
            format!("the string \"{v}\"")
        } else if let Some(v) = value("boolean ") {
            v
        } else {
            match got {
                "sequence" => "an array".into(),
                "map" => "an object".into(),
                "unit value" => "null".into(),
                other => words(other),
            }
        }
    };
    match message.strip_prefix("invalid type: ").and_then(|rest| rest.split_once(", expected ")) {
        Some((got, expected)) => format!("expected {}, got {}", words(expected), unexpected(got)),
        None => words(message),
    }
}

/// A result written by serde-wasm-bindgen: structs become plain objects, `None` is left out
/// (`undefined`), fields marked `#[serde(with = "serde_wasm_bindgen::preserve")]` stay typed
/// arrays.
pub fn to_js<T: Serialize>(func: &str, value: &T) -> Result<JsValue, JsValue> {
    value.serialize(&serde_wasm_bindgen::Serializer::new()).map_err(|e| fail(func, e.to_string()))
}

/// `base` written by [`to_js`], with `more` fields set on it: a result that shares `base`'s
/// type with others and adds its own fields. Its TypeScript type is a struct that flattens
/// `base` (`#[serde(flatten)]`, for tsify alone): serde's flatten itself would write a `Map`,
/// or, with maps written as objects, bring about 1 KiB gzipped of map serializer into a module.
pub fn to_js_with<T: Serialize>(func: &str, base: &T, more: &[(&str, JsValue)]) -> Result<JsValue, JsValue> {
    let object = to_js(func, base)?;
    for (key, value) in more {
        // a plain object serde has just made: no setter, not frozen, so setting cannot fail
        Reflect::set(&object, &JsValue::from_str(key), value).ok();
    }
    Ok(object)
}

/// The field names of a `#[derive(Deserialize)]` struct, as serde passes them to
/// `deserialize_struct` (renames applied): the keys an options object may have.
pub fn fields<T: DeserializeOwned>() -> &'static [&'static str] {
    struct Recorder<'a>(&'a mut &'static [&'static str]);
    #[derive(Debug)]
    struct Stop;
    impl std::fmt::Display for Stop {
        fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("fields recorded")
        }
    }
    impl std::error::Error for Stop {}
    impl de::Error for Stop {
        fn custom<M: std::fmt::Display>(_: M) -> Self {
            Stop
        }
    }
    impl<'de> de::Deserializer<'de> for Recorder<'_> {
        type Error = Stop;
        fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Stop> {
            Err(Stop)
        }
        fn deserialize_struct<V: Visitor<'de>>(
            self,
            _: &'static str,
            fields: &'static [&'static str],
            _: V,
        ) -> Result<V::Value, Stop> {
            *self.0 = fields;
            Err(Stop)
        }
        serde::forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf option unit
            unit_struct newtype_struct seq tuple tuple_struct map enum identifier ignored_any
        }
    }
    let mut fields: &'static [&'static str] = &[];
    let _ = T::deserialize(Recorder(&mut fields));
    fields
}

/// What a JS value is, for messages: "a string", "an array", "a Float32Array", "undefined", ….
pub fn describe(value: &JsValue) -> String {
    if value.is_undefined() {
        return "undefined".into();
    }
    if value.is_null() {
        return "null".into();
    }
    if Array::is_array(value) {
        return "an array".into();
    }
    let name = value
        .dyn_ref::<Object>()
        .and_then(|o| Reflect::get(&o.constructor(), &"name".into()).ok())
        .and_then(|n| n.as_string())
        .map(|n| if n == "Object" { "object".to_string() } else { n })
        .unwrap_or_else(|| value.js_typeof().as_string().unwrap_or_default());
    // "an array", "an object", but "a Uint8Array" (said "you-int")
    let article = if name.starts_with(['a', 'e', 'i', 'o', 'u', 'A', 'E', 'I', 'O']) { "an" } else { "a" };
    format!("{article} {name}")
}

/// The parameter interval [uMin, uMax] of the distance searches: finite, uMin < uMax.
pub fn interval(func: &str, u_min: &JsValue, u_max: &JsValue) -> Result<(f64, f64), JsValue> {
    let (a, b) = (number(func, "uMin", u_min)?, number(func, "uMax", u_max)?);
    if a < b {
        Ok((a, b))
    } else {
        Err(fail(func, format!("need uMin < uMax, got {a} and {b}")))
    }
}

/// A progress callback `on_progress` as a function called with the fraction done (0 to 1);
/// undefined or null: none. What it throws is ignored (it cannot stop the computation).
pub fn progress_reporter(func: &str, on_progress: JsValue) -> Result<impl FnMut(f64), JsValue> {
    let report = if on_progress.is_undefined() || on_progress.is_null() {
        None
    } else {
        Some(
            on_progress
                .dyn_into::<js_sys::Function>()
                .map_err(|v| fail(func, format!("onProgress must be a function, got {}", describe(&v))))?,
        )
    };
    Ok(move |f: f64| {
        if let Some(r) = &report {
            let _ = r.call1(&JsValue::NULL, &JsValue::from_f64(f));
        }
    })
}
