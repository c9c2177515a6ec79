//! The core's modules form layers (ARCHITECTURE.md): each module uses only modules of lower
//! layers — the shared vocabulary at the bottom, the catalogue of analytic surfaces and
//! congruences at the top, which no algorithm imports. This test reads every source file of
//! the core (the bindings layer `src/wasm/` and test code aside), finds the modules each uses
//! (`crate::…` paths), and fails on a use that points sideways or up — so a new cycle, or an
//! algorithm reaching into the catalogue, cannot land.

use std::collections::BTreeMap;
use std::fs;
use std::path::Path;

/// The layers, bottom first. A module may use modules of its own layer's predecessors only.
const LAYERS: &[&[&str]] = &[
    &["error", "tolerance", "line"],
    &["base", "formula", "linalg", "linear_complex", "line_fit"],
    &["ruled", "mesh", "visibility"],
    &["subdivision"],
    &["congruence"],
    &["milling"],
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
        if relative == "wasm" || relative == "lib.rs" {
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

/// The bindings (`src/wasm/`) split by concern, one file per area of the core, named after it
/// (ARCHITECTURE.md, "The bindings"): a file that names no module of the core is a new concern
/// without a home. Besides them only the helpers every binding shares.
#[test]
fn each_binding_file_names_an_area_of_the_core() {
    const HELPERS: &[&str] = &["mod", "args", "error", "live", "buffers", "timing"];
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut core = Vec::new();
    sources(&root, &root, &mut core);
    let mut names: Vec<String> = LAYERS.iter().flat_map(|l| l.iter().map(|m| m.to_string())).collect();
    fn files(dir: &Path, out: &mut Vec<String>) {
        for entry in fs::read_dir(dir).expect("readable") {
            let path = entry.expect("an entry").path();
            if path.is_dir() && !path.ends_with("wasm") {
                files(&path, out);
            }
            if let Some(stem) = path.file_stem() {
                out.push(stem.to_string_lossy().into_owned());
            }
        }
    }
    files(&root, &mut names);
    let mut homeless = Vec::new();
    for entry in fs::read_dir(root.join("wasm")).expect("src/wasm is readable") {
        let stem = entry.expect("an entry").path().file_stem().expect("a name").to_string_lossy().into_owned();
        if !HELPERS.contains(&stem.as_str()) && !names.contains(&stem) {
            homeless.push(stem);
        }
    }
    assert!(homeless.is_empty(), "src/wasm/ files that name no area of the core: {homeless:?}");
    // the core knows nothing of JavaScript: only the bindings name wasm-bindgen or js-sys
    // (a TypeScript description of a result type, derived under wasm, is not JavaScript)
    for (module, text) in &core {
        for js in ["wasm_bindgen", "js_sys", "web_sys", "JsValue"] {
            assert!(!text.contains(js), "the core module {module} names {js}");
        }
    }
}
