//! The JS bindings, tested inside headless Chromium: bad input of every kind becomes a
//! JS `Error` with a clear message (no trap), and the module keeps working afterwards.
#![cfg(target_family = "wasm")]

use js_sys::{Array, Float64Array, Reflect, Uint8Array};
use ruledlab_wasm::{AnalyticSurface, RuledSurface};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

fn f64s(v: &[f64]) -> JsValue {
    Float64Array::from(v).into()
}

fn error<T>(r: Result<T, JsValue>) -> js_sys::Error {
    match r {
        Ok(_) => panic!("expected an error"),
        Err(e) => e.dyn_into().expect("a JS Error"),
    }
}

fn message<T>(r: Result<T, JsValue>) -> String {
    error(r).message().into()
}

/// The `code` property of the thrown error.
fn code<T>(r: Result<T, JsValue>) -> String {
    Reflect::get(&error(r), &"code".into()).unwrap().as_string().expect("a string code")
}

/// Asserts that `r` failed with a message containing `expected`.
fn assert_fails<T>(r: Result<T, JsValue>, expected: &str) {
    let m = message(r);
    assert!(m.contains(expected), "{m:?} does not contain {expected:?}");
}

const GOOD: [f64; 12] = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0];

#[wasm_bindgen_test]
fn bad_inputs_become_errors_with_messages() {
    let cases: Vec<(JsValue, &str)> = vec![
        (JsValue::from_str("1,2,3"), "must be a Float64Array, Float32Array or array of numbers, got a string"),
        (Array::of1(&1.0.into()).into(), "length 1 is not a multiple of 6"),
        (Array::of1(&"1".into()).into(), "coords[0] must be a number, got a string"),
        (JsValue::UNDEFINED, "got undefined"),
        (f64s(&GOOD[..11]), "length 11 is not a multiple of 6"),
        (f64s(&GOOD[..6]), "rulings: got 1, need at least 2"),
        (f64s(&[]), "rulings: got 0, need at least 2"),
        (
            f64s(&[GOOD[0], f64::NAN, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0]),
            "coordinate 1 (ruling 0, a.y) is NaN",
        ),
        (f64s(&[0.0, 0.0, 0.0, f64::INFINITY, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0]), "is inf"),
        (f64s(&[0.0, 0.0, 0.0, 1e300, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0]), "magnitudes above 1e150"),
        (f64s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0]), "ruling 1 has zero length"),
    ];
    for (input, expected) in cases {
        let m = message(RuledSurface::from_segments(input));
        assert!(m.contains(expected), "{m:?} does not contain {expected:?}");
        assert!(m.starts_with("RuledSurface.fromSegments: "), "{m}");
    }
    // every kind of failure has its code, and details point at the culprit
    assert_eq!(code(RuledSurface::from_segments(f64s(&GOOD[..11]))), "invalid-argument");
    assert_eq!(code(RuledSurface::from_segments(f64s(&GOOD[..6]))), "too-small");
    let nan = f64s(&[GOOD[0], f64::NAN, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0]);
    let e = error(RuledSurface::from_segments(nan));
    assert_eq!(Reflect::get(&e, &"code".into()).unwrap(), "not-finite");
    let details = Reflect::get(&e, &"details".into()).unwrap();
    assert_eq!(Reflect::get(&details, &"index".into()).unwrap(), 1);
    // the reason's arguments are a plain object a page reads by name: ruling 0, a.y, NaN
    let args = Reflect::get(&details, &"args".into()).unwrap();
    assert_eq!(Reflect::get(&details, &"reason".into()).unwrap(), "not-finite-segment");
    assert_eq!(Reflect::get(&args, &"item".into()).unwrap(), 0);
    assert_eq!(Reflect::get(&args, &"coordinate".into()).unwrap(), "a.y");
    assert!(Reflect::get(&args, &"value".into()).unwrap().as_f64().is_some_and(f64::is_nan));
    let big = f64s(&[0.0, 0.0, 0.0, 1e300, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0]);
    assert_eq!(code(RuledSurface::from_segments(big)), "out-of-range");
    let flat = f64s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0]);
    assert_eq!(code(RuledSurface::from_segments(flat)), "degenerate");
    // still usable
    let s = RuledSurface::from_segments(f64s(&GOOD)).unwrap();
    assert_eq!(s.length(), 2);
}

#[wasm_bindgen_test]
fn invariants_object_has_every_array_with_the_documented_length() {
    let hyp = AnalyticSurface::by_name("hyperboloid".into()).unwrap();
    let s = hyp.sample(10.0.into(), JsValue::UNDEFINED).unwrap();
    let inv = s.invariants(None).unwrap();
    let len = |k: &str| -> u32 {
        let v = Reflect::get(&inv, &k.into()).unwrap();
        if let Some(a) = v.dyn_ref::<Float64Array>() {
            a.length()
        } else {
            v.dyn_ref::<Uint8Array>().expect(k).length()
        }
    };
    for (k, n) in [
        ("angle", 9),
        ("distance", 9),
        ("distribution", 9),
        ("footpoints", 54),
        ("centralNormal", 27),
        ("striction", 24),
        ("distributionMean", 8),
        ("perpendicularMidpoints", 27),
        ("parallel", 9),
    ] {
        assert_eq!(len(k), n, "{k}");
    }
}

#[wasm_bindgen_test]
fn analytic_surface_arguments_are_checked() {
    assert_fails(AnalyticSurface::by_name(JsValue::from(3)), "name must be a string, got a number");
    assert_fails(AnalyticSurface::by_name("torus".into()), "unknown surface \"torus\"");
    let hyp = AnalyticSurface::by_name("hyperboloid".into()).unwrap();
    for (count, expected) in [
        (1.0, "count must be an integer from 2"),
        (2.5, "got 2.5"),
        (f64::NAN, "got NaN"),
        (-3.0, "got -3"),
        (1e12, "got 1000000000000"),
    ] {
        let m = message(hyp.sample(count.into(), JsValue::UNDEFINED));
        assert!(m.contains(expected), "{m}");
    }
    let opts = js_sys::Object::new();
    Reflect::set(&opts, &"vMin".into(), &"low".into()).unwrap();
    assert_fails(hyp.sample(5.0.into(), opts.into()), "options.vMin: expected a number, got the string \"low\"");
    let opts = js_sys::Object::new();
    Reflect::set(&opts, &"colour".into(), &1.into()).unwrap();
    assert_fails(hyp.sample(5.0.into(), opts.into()), "unknown option \"colour\"; known options: uMin");
    assert_fails(
        hyp.sample(5.0.into(), JsValue::from(7)),
        "options must be an object { uMin, uMax, vMin, vMax, closed }, got a number",
    );
    assert_fails(
        hyp.sample("5".into(), JsValue::UNDEFINED),
        "count must be an integer from 2 to 4194304, got a string",
    );
    assert_fails(hyp.striction(f64s(&[0.1, f64::NAN])), "every u must be finite");
    assert!(message(
        hyp.convergence(JsValue::NULL)
            .and_then(|_| { AnalyticSurface::by_name("cylinder".into()).unwrap().convergence(JsValue::UNDEFINED) })
    )
    .contains("no striction point"));
    // still usable after all of that
    assert_eq!(hyp.sample(5.0.into(), JsValue::UNDEFINED).unwrap().length(), 5);
}
