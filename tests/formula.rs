//! Surfaces and congruences typed as formulas, against the built-in closed forms: the same
//! jets, exact invariants and measured orders, and every kind of bad formula refused with
//! its place, never a panic. Runs natively and in headless Chromium.

use ruledlab::assert_near;
use ruledlab::convergence_study;
use ruledlab::tolerance::test::{EXACT, ORDER};
use ruledlab::Formula;
use ruledlab::{AnalyticCongruence, AnalyticSurface, CongruenceSpec, FormulaSpec, SmoothRuled};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

fn surface(a: [&str; 3], e: [&str; 3], u: (f64, f64)) -> AnalyticSurface {
    let spec = FormulaSpec {
        a: a.map(String::from),
        e: e.map(String::from),
        u,
        v: (-1.0, 1.0),
        closed: false,
        parameters: [1.0, 2.0, 3.0],
    };
    AnalyticSurface::from_formulas(&spec).unwrap()
}

/// The helical surface of Fig. 5 (r = 1, p = 0.4, β = π/4) typed as formulas: exact striction
/// curve (the helix itself) and δ = p − r tan β, as the built-in surface.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn helical_surface_as_formulas() {
    let typed =
        surface(["cos(u)", "sin(u)", "0.4*u"], ["-cos(pi/4)*sin(u)", "cos(pi/4)*cos(u)", "sin(pi/4)"], (0.0, 9.0));
    let built = &AnalyticSurface::ALL[3];
    for u in [0.2, 1.7, 5.0] {
        assert_near!(typed.striction(u).unwrap(), built.striction(u).unwrap(), EXACT);
        assert_near!(typed.distribution(u), 0.4 - 1.0, EXACT);
        assert_near!(typed.central_tangent(u).unwrap(), built.central_tangent(u).unwrap(), EXACT);
    }
}

/// Propositions 1 and 2 measured on a surface only a formula defines (orders 1 and 2).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn convergence_orders_on_a_typed_surface() {
    let s = surface(["u", "u^2/2", "sin(u)"], ["1", "cosh(u)", "a*u - u^3/3"], (-1.0, 1.0));
    let study = convergence_study(&s, 0.3, 0.1, 7).unwrap();
    let order = |name: &str| study.series.iter().find(|x| x.name == name).unwrap().fitted_order;
    assert_near!(order("footpoint"), 1.0, ORDER);
    assert_near!(order("midpoint"), 2.0, ORDER);
    assert_near!(order("distribution"), 1.0, ORDER);
    assert_near!(order("distributionMean"), 2.0, ORDER);
}

/// Sampling a typed surface gives the same segments as sampling the built-in one.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn sampling_matches_the_built_in_surface() {
    let typed = surface(["1", "u^2/2", "u"], ["u^2", "u", "-1"], (-1.0, 1.0));
    let (a, b) = (
        typed.sample(12, typed.ranges()).unwrap(),
        AnalyticSurface::Quartic.sample(12, AnalyticSurface::Quartic.ranges()).unwrap(),
    );
    for i in 0..12 {
        assert_near!(a.segment(i).a, b.segment(i).a, EXACT);
        assert_near!(a.segment(i).b, b.segment(i).b, EXACT);
    }
}

/// Example 5 typed as formulas is Example 5, derivatives included.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn example_5_congruence_as_formulas() {
    let spec = CongruenceSpec {
        p: ["u", "v", "0.5*sin(2*u + 1.5*v)"].map(String::from),
        e: ["u", "v", "sin(u) + 1.3*cos(v)"].map(String::from),
        u: (-1.1, 1.1),
        v: (-1.1, 1.1),
        parameters: [1.0; 3],
        grid: (8, 7),
    };
    let typed = AnalyticCongruence::from_formulas(&spec).unwrap();
    for (u, v) in [(0.1, 0.2), (-0.7, 1.0)] {
        let (a, b) = (typed.jet(u, v), AnalyticCongruence::Example5.jet(u, v));
        for (x, y) in [(a.p, b.p), (a.p_u, b.p_u), (a.p_v, b.p_v), (a.d, b.d), (a.d_u, b.d_u), (a.d_v, b.d_v)] {
            assert_near!(x, y, EXACT);
        }
    }
}

/// Hostile text: deep nesting, long sums, huge numbers, unknown names, unicode, operators of
/// other languages. Every one is refused or evaluated; none panics; limits are named.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn hostile_formulas_never_panic() {
    let mut texts: Vec<String> = [
        "1e308*1e308",
        "-u^-u^",
        "u^^2",
        "((((u))))",
        ")(",
        "sin()",
        "atan2(,)",
        "atan2(u,)",
        "u,u",
        "2..3",
        "1e",
        "1e+",
        ".e1",
        "u = 3",
        "u; u",
        "\"u\"",
        "u == u",
        "u && u",
        "!u",
        "u % 2",
        "u // c",
        "u /* c */",
        "0x1F",
        "true",
        "NaN",
        "inf",
        "ü",
        "𝑢",
        "u\u{0}",
        "sin(u",
        "sin u)",
        "--------u",
        "+-+-u",
        "2^3^4",
        "e^e^e",
        "atan2(atan2(u,u),atan2(u,u))",
    ]
    .map(String::from)
    .to_vec();
    texts.push("(".repeat(64) + "u" + &")".repeat(64));
    texts.push("(".repeat(65) + "u" + &")".repeat(65));
    texts.push(["u"; 500].join("+"));
    texts.push(["u"; 501].join("+"));
    texts.push("-".repeat(999) + "u");
    texts.push("-(".repeat(64) + "u" + &")".repeat(64));
    texts.push("----(".repeat(64) + "u" + &")".repeat(64));
    texts.push("sin(-".repeat(64) + "u" + &")".repeat(64));
    texts.push("9".repeat(400));
    texts.push(["sin(", "u", ")"].concat().repeat(100));
    for t in &texts {
        match Formula::parse("f", t, &["u"]) {
            Ok(f) => {
                let _ = f.value(&[0.5]);
            }
            Err(e) => {
                assert!(!e.to_string().is_empty() && ["parse-error", "too-large"].contains(&e.code()), "{t}: {e}")
            }
        }
    }
    assert_eq!(Formula::parse("f", &texts[texts.len() - 9], &["u"]).unwrap_err().code(), "too-large");
}
