//! What the compiler cannot keep. The crates are walls the compiler keeps (ARCHITECTURE.md):
//! `ruledlab` depends on no other crate of the workspace, `ruledlab-cam` only on it, the
//! bindings on both. Within the geometry crate, the modules form layers: each module uses only
//! modules of lower layers — the shared vocabulary at the bottom, the catalogue of analytic
//! surfaces and congruences at the top, which no algorithm imports. This test reads every source
//! file of the core (test code aside), finds the modules each uses (`crate::…` paths), and fails
//! on a use that points sideways or up — so a new cycle, or an algorithm reaching into the
//! catalogue, cannot land.
//!
//! The bindings (`crates/ruledlab-wasm/`, `crates/ruledlab-cam-wasm/`, `crates/ruledlab-py/`) are
//! read too: in each, the files use each other without a cycle and each JavaScript or Python
//! class is declared and bound in the one file named after it; `crates/ruledlab-js/` declares
//! nothing to JavaScript; neither the geometry nor the CAM crate names wasm-bindgen or PyO3, and
//! only the Python bindings name PyO3.

use std::collections::BTreeMap;
use std::fs;
use std::path::Path;

/// The layers, bottom first. A module may use modules of its own layer's predecessors only.
const LAYERS: &[&[&str]] = &[
    &["error", "tolerance", "line"],
    &["base", "formula", "linalg", "linear_complex", "line_fit", "snap"],
    &["ruled", "mesh", "visibility"],
    &["subdivision", "developable"],
    &["congruence"],
    &["klein"],
    &["catalogue", "io"],
];

fn layer(module: &str) -> Option<usize> {
    LAYERS.iter().position(|l| l.contains(&module))
}

/// The `crate::<module>` paths of a source text outside its `#[cfg(test)]` module (the
/// `msg!` macro belongs to `error`).
fn uses(text: &str) -> Vec<String> {
    let code = text.split("#[cfg(test)]\nmod tests").next().unwrap_or(text);
    let mut out = Vec::new();
    for line in code.lines().map(str::trim_start).filter(|l| !l.starts_with("//")) {
        let mut rest = line;
        while let Some(k) = rest.find("crate::") {
            rest = &rest[k + 7..];
            let name: String = rest.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
            out.push(if name == "msg" || name == "assert_near" { "error".to_string() } else { name });
        }
    }
    out
}

/// Every source file of the core below `dir`, with the top-level module it belongs to.
fn sources(root: &Path, dir: &Path, out: &mut Vec<(String, String)>) {
    for entry in fs::read_dir(dir).expect("src is readable") {
        let path = entry.expect("an entry").path();
        let relative = path.strip_prefix(root).expect("below src").to_string_lossy().replace('\\', "/");
        if relative == "lib.rs" {
            continue;
        }
        if path.is_dir() {
            sources(root, &path, out);
        } else if relative.ends_with(".rs") {
            let module = relative.split('/').next().expect("a name").trim_end_matches(".rs").to_string();
            out.push((module, fs::read_to_string(&path).expect("a source file")));
        }
    }
}

#[test]
fn every_module_uses_only_lower_layers() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&root, &root, &mut files);
    assert!(files.len() > 40, "only {} source files found", files.len());
    let mut graph: BTreeMap<String, BTreeMap<String, usize>> = BTreeMap::new();
    let mut wrong = Vec::new();
    for (module, text) in &files {
        let own = layer(module).unwrap_or_else(|| panic!("module {module} is in no layer of tests/architecture.rs"));
        for used in uses(text) {
            if &used == module {
                continue;
            }
            *graph.entry(module.clone()).or_default().entry(used.clone()).or_default() += 1;
            match layer(&used) {
                Some(l) if l < own => {}
                Some(l) => wrong.push(format!("{module} (layer {own}) uses {used} (layer {l})")),
                None => wrong.push(format!("{module} uses {used}, which is in no layer")),
            }
        }
    }
    wrong.sort();
    wrong.dedup();
    assert!(wrong.is_empty(), "uses against the layers:\n{}\nthe graph: {graph:#?}", wrong.join("\n"));
}

#[test]
fn the_layers_name_each_module_once() {
    let all: Vec<&str> = LAYERS.iter().flat_map(|l| l.iter().copied()).collect();
    for (i, m) in all.iter().enumerate() {
        assert!(!all[..i].contains(m), "{m} twice");
    }
    // and a use the test must catch is caught
    assert_eq!(uses("use crate::catalogue::AnalyticSurface;\nfn f() { crate::msg!(\"x\"); }"), ["catalogue", "error"]);
    assert!(
        uses("use crate::ruled::RuledSurface;\n#[cfg(test)]\nmod tests {\n    use crate::catalogue::X;\n}").len() == 1
    );
}

/// A module's name in Rust for a JavaScript class: `ruled_surface` for `RuledSurface`.
fn snake(class: &str) -> String {
    let mut out = String::new();
    for (i, c) in class.chars().enumerate() {
        if c.is_ascii_uppercase() && i > 0 {
            out.push('_');
        }
        out.push(c.to_ascii_lowercase());
    }
    out
}

/// The lines of a source text that are code (comments left out).
fn code_lines(text: &str) -> impl Iterator<Item = &str> {
    text.lines().map(str::trim_start).filter(|l| !l.starts_with("//"))
}

/// The sibling modules a file of a binding crate uses: the first name after each `super::` or
/// `crate::`, each name of a group (`use super::{export, focal::focal_js}`).
fn sibling_uses(text: &str) -> Vec<String> {
    let ident = |s: &str| -> String { s.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect() };
    let mut out = Vec::new();
    for line in code_lines(text) {
        let mut rest = line;
        while let Some(k) = ["super::", "crate::"].iter().filter_map(|p| rest.find(p).map(|k| k + p.len())).min() {
            rest = &rest[k..];
            if let Some(group) = rest.strip_prefix('{') {
                let mut depth = 0;
                let mut item = String::new();
                for c in group.chars() {
                    match c {
                        '{' => depth += 1,
                        '}' if depth == 0 => break,
                        '}' => depth -= 1,
                        ',' if depth == 0 => {
                            out.push(ident(item.trim()));
                            item.clear();
                            continue;
                        }
                        _ => {}
                    }
                    item.push(c);
                }
                out.push(ident(item.trim()));
            } else {
                out.push(ident(rest));
            }
        }
    }
    out.retain(|m| !m.is_empty() && m != "self");
    out
}

/// The types a source text binds with `#[wasm_bindgen]`: the structs it declares as
/// JavaScript classes, and the types of its `#[wasm_bindgen] impl` blocks.
fn bound(text: &str) -> (Vec<String>, Vec<String>) {
    bound_by(text, &["#[wasm_bindgen"])
}

/// The types a source text binds with an attribute of `markers` (`#[wasm_bindgen`; `#[pyclass`
/// and `#[pymethods` for Python): the structs it declares as classes, and the types of the `impl`
/// blocks the attribute marks.
fn bound_by(text: &str, markers: &[&str]) -> (Vec<String>, Vec<String>) {
    let (mut classes, mut impls) = (Vec::new(), Vec::new());
    let mut bindgen = false; // the item being read carries a marker
    let mut open = 0i32; // brackets of an attribute running over lines
    for line in code_lines(text) {
        if open > 0 || line.starts_with("#[") {
            bindgen |= markers.iter().any(|m| line.starts_with(m));
            open += line.matches('[').count() as i32 - line.matches(']').count() as i32;
            continue;
        }
        let name = |rest: &str| -> String {
            // `impl<T> Path::Name<T>`: the generics left out, the path's last name
            let rest = match rest.strip_prefix('<') {
                Some(generic) => generic.split_once('>').map_or("", |(_, r)| r.trim_start()),
                None => rest,
            };
            let path: String =
                rest.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == ':').collect();
            path.rsplit("::").next().unwrap_or_default().to_string()
        };
        if bindgen {
            // `pub`, `pub(crate)` … left out
            let item = match line.strip_prefix("pub") {
                Some(rest) if rest.starts_with('(') => rest.split_once(')').map_or("", |(_, r)| r).trim_start(),
                Some(rest) => rest.trim_start(),
                None => line,
            };
            if let Some(rest) = item.strip_prefix("struct ") {
                classes.push(name(rest));
            } else if let Some(rest) = line.strip_prefix("impl").filter(|r| r.starts_with([' ', '<'])) {
                impls.push(name(rest.trim_start()));
            }
        }
        bindgen = false;
    }
    (classes, impls)
}

/// A cycle of `graph`, as the modules along it (the first again at the end), if it has one.
fn cycle(graph: &BTreeMap<String, Vec<String>>) -> Option<Vec<String>> {
    fn visit(
        m: &str,
        graph: &BTreeMap<String, Vec<String>>,
        path: &mut Vec<String>,
        done: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        if let Some(k) = path.iter().position(|p| p == m) {
            let mut found = path[k..].to_vec();
            found.push(m.to_string());
            return Some(found);
        }
        if done.iter().any(|d| d == m) {
            return None;
        }
        path.push(m.to_string());
        for used in graph.get(m).into_iter().flatten() {
            if let Some(found) = visit(used, graph, path, done) {
                return Some(found);
            }
        }
        path.pop();
        done.push(m.to_string());
        None
    }
    let mut done = Vec::new();
    graph.keys().find_map(|m| visit(m, graph, &mut Vec::new(), &mut done))
}

/// The crates of the bindings, and the one that shares their helpers.
const BINDINGS: [&str; 2] = ["crates/ruledlab-wasm/src", "crates/ruledlab-cam-wasm/src"];
const SHARED: &str = "crates/ruledlab-js/src";
/// The Python bindings (the extension `ruledlab._core`).
const PYTHON: &str = "crates/ruledlab-py/src";

/// The files of a crate of the bindings (`lib.rs` aside: it only declares and re-exports), by
/// module name.
fn binding_files(crate_src: &str) -> BTreeMap<String, String> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(crate_src);
    let mut out = BTreeMap::new();
    for entry in fs::read_dir(&dir).unwrap_or_else(|_| panic!("{crate_src} is readable")) {
        let path = entry.expect("an entry").path();
        assert!(path.extension().is_some_and(|e| e == "rs"), "{} is not a Rust file of {crate_src}/", path.display());
        let stem = path.file_stem().expect("a name").to_string_lossy().into_owned();
        if stem != "lib" {
            out.insert(stem, fs::read_to_string(&path).expect("a source file"));
        }
    }
    out
}

/// The bindings (`src/wasm/`) use each other without a cycle (ARCHITECTURE.md, "The
/// bindings"): a class file may use the helpers and the file of a class its methods take or
/// return, never the other way round. A file names its siblings directly (`super::args`), not
/// through a re-export of `mod.rs`, so every use is an edge of the graph.
#[test]
fn the_bindings_use_each_other_without_a_cycle() {
    for crate_src in BINDINGS.into_iter().chain([SHARED, PYTHON]) {
        let files = binding_files(crate_src);
        assert!(files.len() >= 4, "only {} files in {crate_src}/", files.len());
        let mut graph: BTreeMap<String, Vec<String>> = BTreeMap::new();
        let mut wrong = Vec::new();
        for (module, text) in &files {
            let mut used = sibling_uses(text);
            used.sort();
            used.dedup();
            used.retain(|u| u != module);
            for u in &used {
                if !files.contains_key(u) {
                    wrong.push(format!("{module} uses crate::{u}, which is no file of {crate_src}/"));
                }
            }
            graph.insert(module.clone(), used);
        }
        assert!(wrong.is_empty(), "{}", wrong.join("\n"));
        if let Some(found) = cycle(&graph) {
            panic!("the files of {crate_src}/ use each other in a cycle: {}\nthe graph: {graph:#?}", found.join(" → "));
        }
    }
}

/// One file per JavaScript class (ARCHITECTURE.md, "The bindings"): the class `RuledSurface`
/// is declared in `src/wasm/ruled_surface.rs`, and every `#[wasm_bindgen] impl RuledSurface`
/// (every method JavaScript sees) is in that file.
#[test]
fn each_javascript_class_has_one_file_named_after_it() {
    let mut classes = Vec::new();
    let mut wrong = Vec::new();
    let files = BINDINGS.into_iter().flat_map(binding_files);
    for (module, text) in files {
        let module = &module;
        let (declared, impls) = bound(&text);
        for class in declared {
            if snake(&class) != *module {
                wrong.push(format!("the class {class} is declared in {module}.rs, not {}.rs", snake(&class)));
            }
            classes.push(class);
        }
        for class in impls {
            if snake(&class) != *module {
                wrong.push(format!("methods of {class} are bound in {module}.rs, not {}.rs", snake(&class)));
            }
        }
    }
    assert!(classes.len() >= 7, "only {} JavaScript classes found: {classes:?}", classes.len());
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    // what both modules share exports nothing: each module declares its own classes and functions
    // (a `macro_rules!` of it binds methods only where a module invokes it, in the class's file)
    for (module, text) in binding_files(SHARED) {
        assert!(
            !without_macro_rules(&text).contains("#[wasm_bindgen"),
            "crates/ruledlab-js/src/{module}.rs declares something to JavaScript"
        );
    }
}

/// `text` without the bodies of its `macro_rules!` (what they declare is declared where they
/// are invoked).
fn without_macro_rules(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(at) = rest.find("macro_rules!") {
        out.push_str(&rest[..at]);
        let open = at + rest[at..].find('{').expect("a macro_rules! has a body");
        let mut depth = 0;
        let mut end = rest.len();
        for (i, c) in rest[open..].char_indices() {
            depth += match c {
                '{' => 1,
                '}' => -1,
                _ => 0,
            };
            if depth == 0 {
                end = open + i + 1;
                break;
            }
        }
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

#[test]
fn a_macro_rules_body_is_set_aside_and_what_follows_it_kept() {
    let text = "a\nmacro_rules! m { ($x:ident) => { #[wasm_bindgen] impl $x {} }; }\n#[wasm_bindgen] b";
    assert_eq!(without_macro_rules(text), "a\n\n#[wasm_bindgen] b");
}

/// One file per Python class: the class `RuledSurface` is declared (`#[pyclass]`) in
/// `crates/ruledlab-py/src/ruled_surface.rs`, and its `#[pymethods]` (every method Python sees)
/// are in that file.
#[test]
fn each_python_class_has_one_file_named_after_it() {
    let mut classes = Vec::new();
    let mut wrong = Vec::new();
    for (module, text) in binding_files(PYTHON) {
        let (declared, impls) = bound_by(&text, &["#[pyclass", "#[pymethods"]);
        for class in declared {
            if snake(&class) != module {
                wrong.push(format!("the class {class} is declared in {module}.rs, not {}.rs", snake(&class)));
            }
            classes.push(class);
        }
        for class in impls {
            if snake(&class) != module {
                wrong.push(format!("methods of {class} are bound in {module}.rs, not {}.rs", snake(&class)));
            }
        }
    }
    assert!(classes.len() >= 5, "only {} Python classes found: {classes:?}", classes.len());
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// Only the Python bindings name PyO3 or rust-numpy: the geometry, the CAM crate and the wasm
/// bindings build without Python.
#[test]
fn only_the_python_bindings_name_python() {
    for dir in ["src", "crates/ruledlab-cam/src"] {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
        let mut files = Vec::new();
        sources(&root, &root, &mut files);
        files.push(("lib.rs".to_string(), fs::read_to_string(root.join("lib.rs")).expect("lib.rs")));
        for (module, text) in &files {
            for py in ["pyo3", "numpy::", "pythonize"] {
                assert!(!text.contains(py), "{dir}: the module {module} names {py}");
            }
        }
    }
    for crate_src in BINDINGS.into_iter().chain([SHARED]) {
        for (module, text) in binding_files(crate_src) {
            assert!(!text.contains("pyo3"), "{crate_src}/{module}.rs names pyo3");
        }
    }
}

/// The geometry and the CAM crate know nothing of JavaScript: only the bindings name
/// wasm-bindgen, js-sys or web-sys (a TypeScript description of a result type, derived under the
/// `tsify` feature, is not JavaScript).
#[test]
fn only_the_bindings_name_javascript() {
    for dir in ["src", "crates/ruledlab-cam/src"] {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
        let mut core = Vec::new();
        sources(&root, &root, &mut core);
        core.push(("lib.rs".to_string(), fs::read_to_string(root.join("lib.rs")).expect("lib.rs")));
        assert!(core.len() > 10, "only {} source files found in {dir}", core.len());
        for (module, text) in &core {
            for js in ["wasm_bindgen", "js_sys", "web_sys", "JsValue"] {
                assert!(!text.contains(js), "{dir}: the module {module} names {js}");
            }
        }
    }
}

/// The checks of the bindings catch what they guard.
#[test]
fn the_binding_checks_catch_what_they_guard() {
    assert_eq!(snake("RuledSurface"), "ruled_surface");
    assert_eq!(snake("CongruenceFocal"), "congruence_focal");
    assert_eq!(snake("ToolPath"), "tool_path");
    assert_eq!(
        sibling_uses("use super::args::{self, fail};\nuse super::{buffers::points_f32, live};\n// super::timing\nlet x = crate::focal::f();"),
        ["args", "buffers", "live", "focal"]
    );
    let text = "/// A class.\n#[wasm_bindgen]\n#[derive(Debug)]\npub struct FooBar {\n}\n#[wasm_bindgen(\n    js_name = Other\n)]\npub(crate) struct Baz;\n\
                #[derive(Tsify)]\nstruct Options;\n#[wasm_bindgen]\nimpl FooBar {\n    #[wasm_bindgen(getter)]\n    pub fn x() {}\n}\nimpl Baz {}\n\
                #[wasm_bindgen]\nimpl super::ToolPath {}\n";
    let (classes, impls) = bound(text);
    assert_eq!(classes, ["FooBar", "Baz"]);
    assert_eq!(impls, ["FooBar", "ToolPath"]);
    let graph = |edges: &[(&str, &str)]| {
        let mut g: BTreeMap<String, Vec<String>> = BTreeMap::new();
        for (a, b) in edges {
            g.entry(a.to_string()).or_default().push(b.to_string());
            g.entry(b.to_string()).or_default();
        }
        g
    };
    assert_eq!(cycle(&graph(&[("a", "b"), ("b", "c"), ("a", "c")])), None);
    assert_eq!(bound("#[wasm_bindgen]\nimpl<T> Wrapper<T> {}").1, ["Wrapper"]);
    let python =
        "#[pyclass(module = \"m\", frozen)]\npub struct FooBar {}\n#[pymethods]\nimpl FooBar {}\nimpl Other {}\n";
    assert_eq!(bound_by(python, &["#[pyclass", "#[pymethods"]), (vec!["FooBar".into()], vec!["FooBar".into()]));
    assert_eq!(cycle(&graph(&[("a", "b"), ("b", "c"), ("c", "b")])).unwrap(), ["b", "c", "b"]);
    assert_eq!(cycle(&graph(&[("x", "x")])).unwrap(), ["x", "x"]);
}
