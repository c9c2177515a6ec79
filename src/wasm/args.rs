//! Checking what JavaScript passed in, and building what goes back.

use js_sys::{Array, Float32Array, Float64Array, Object, Reflect, Uint32Array};
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

/// A non-negative integer given as a JS number.
pub fn integer(func: &str, name: &str, x: f64, min: usize, max: usize) -> Result<usize, JsValue> {
    if x.is_finite() && x.fract() == 0.0 && x >= min as f64 && x <= max as f64 {
        Ok(x as usize)
    } else {
        Err(fail(func, format!("{name} must be an integer from {min} to {max}, got {x}")))
    }
}

/// An options object read key by key, so that every message names the option at fault.
/// `undefined` or `null` stand for `{}`; keys outside `known` are rejected (typos would
/// otherwise be silently ignored).
pub struct Options {
    func: &'static str,
    object: Option<Object>,
}

impl Options {
    /// Checks that `value` is a plain object with only `known` keys.
    pub fn new(func: &'static str, value: JsValue, known: &[&str]) -> Result<Self, JsValue> {
        if value.is_undefined() || value.is_null() {
            return Ok(Options { func, object: None });
        }
        if !value.is_object() || js_sys::Array::is_array(&value) || value.is_function() {
            return Err(fail(func, format!("options must be an object, got {}", describe(&value))));
        }
        let object: Object = value.unchecked_into();
        for key in Object::keys(&object).iter() {
            let key = key.as_string().unwrap_or_default();
            if !known.contains(&key.as_str()) {
                return Err(fail_option(
                    func,
                    &key,
                    format!("unknown option \"{key}\"; known options: {}", known.join(", ")),
                ));
            }
        }
        Ok(Options { func, object: Some(object) })
    }

    fn get(&self, key: &str) -> Option<JsValue> {
        let v = Reflect::get(self.object.as_ref()?, &JsValue::from_str(key)).ok()?;
        (!v.is_undefined()).then_some(v)
    }

    fn wrong(&self, key: &str, expected: &str, v: &JsValue) -> JsValue {
        let got = match v.as_f64() {
            Some(x) => format!("{x}"),
            None => describe(v),
        };
        fail_option(self.func, key, format!("options.{key} must be {expected}, got {got}"))
    }

    /// A finite number, if given.
    pub fn number(&self, key: &str) -> Result<Option<f64>, JsValue> {
        match self.get(key) {
            None => Ok(None),
            Some(v) => match v.as_f64() {
                Some(x) if x.is_finite() => Ok(Some(x)),
                _ => Err(self.wrong(key, "a finite number", &v)),
            },
        }
    }

    /// An integer in [min, max], if given.
    pub fn integer(&self, key: &str, min: usize, max: usize) -> Result<Option<usize>, JsValue> {
        match self.get(key) {
            None => Ok(None),
            Some(v) => match v.as_f64() {
                Some(x) if x.fract() == 0.0 && x >= min as f64 && x <= max as f64 => Ok(Some(x as usize)),
                _ => Err(self.wrong(key, &format!("an integer from {min} to {max}"), &v)),
            },
        }
    }

    /// A string, if given.
    pub fn string(&self, key: &str) -> Result<Option<String>, JsValue> {
        match self.get(key) {
            None => Ok(None),
            Some(v) => v.as_string().map(Some).ok_or_else(|| self.wrong(key, "a string", &v)),
        }
    }

    /// Whether `key` was given (not undefined).
    pub fn has(&self, key: &str) -> bool {
        self.get(key).is_some()
    }

    /// Rejects `key` when given for a scheme other than `scheme` (a likely mistake that would
    /// otherwise be silently ignored).
    pub fn only_for(&self, key: &str, scheme: &str, chosen: Option<&str>) -> Result<(), JsValue> {
        if self.has(key) && chosen != Some(scheme) {
            let chosen = chosen.map(|c| format!(", not to \"{c}\"")).unwrap_or_default();
            return Err(fail_option(
                self.func,
                key,
                format!("options.{key} applies to the \"{scheme}\" scheme only{chosen}"),
            ));
        }
        Ok(())
    }

    /// A boolean, if given.
    pub fn boolean(&self, key: &str) -> Result<Option<bool>, JsValue> {
        match self.get(key) {
            None => Ok(None),
            Some(v) => v.as_bool().map(Some).ok_or_else(|| self.wrong(key, "true or false", &v)),
        }
    }
}

/// Reads an options object with serde-wasm-bindgen into `T`, after checking that it is a
/// plain object (`undefined`/`null` read as `{}` when `optional`) whose keys are all in
/// `known`, and that every nested object named in `nested` has only its known keys.
/// (serde-wasm-bindgen reads struct fields by name, so it never sees unknown keys: a typo
/// would otherwise be silently ignored.) serde's messages name the field and what it expects.
pub fn read_options<T: serde::de::DeserializeOwned>(
    func: &str,
    value: JsValue,
    known: &[&str],
    nested: &[(&str, &[&str])],
    optional: bool,
) -> Result<T, JsValue> {
    let value = if optional && (value.is_undefined() || value.is_null()) { Object::new().into() } else { value };
    let plain = |v: &JsValue| v.is_object() && !js_sys::Array::is_array(v) && !v.is_function();
    if !plain(&value) {
        return Err(fail(
            func,
            format!("options must be an object {{ {} }}, got {}", known.join(", "), describe(&value)),
        ));
    }
    let check_keys = |object: &JsValue, prefix: &str, known: &[&str]| -> Result<(), JsValue> {
        for key in Object::keys(object.unchecked_ref::<Object>()).iter() {
            let key = key.as_string().unwrap_or_default();
            if !known.contains(&key.as_str()) {
                return Err(fail_option(
                    func,
                    &key,
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
    serde_wasm_bindgen::from_value(value).map_err(|e| {
        let text = e.to_string();
        fail(func, text.strip_prefix("Error: ").unwrap_or(&text).to_string())
    })
}

/// What a JS value is, for messages: "a string", "an Array", "undefined", ….
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

/// A plain object under construction.
pub struct ObjectBuilder(Object);

impl ObjectBuilder {
    /// An empty `{}`.
    pub fn new() -> Self {
        ObjectBuilder(Object::new())
    }

    /// Sets `key` (setting a property of a fresh plain object cannot fail; if it ever
    /// did, the key would simply be missing, which the JS tests would catch).
    pub fn set(self, key: &str, value: impl Into<JsValue>) -> Self {
        let _ = Reflect::set(&self.0, &JsValue::from_str(key), &value.into());
        self
    }

    /// Sets `key` to a `Float64Array` copy of `values`.
    pub fn f64s(self, key: &str, values: &[f64]) -> Self {
        self.set(key, Float64Array::from(values))
    }

    /// The finished object.
    pub fn build(self) -> JsValue {
        self.0.into()
    }
}
