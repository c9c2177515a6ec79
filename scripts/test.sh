#!/usr/bin/env bash
# Every test of ruledlab, after installing whatever is missing:
#   1. native Rust: unit, property and integration tests, doctests, benches in test mode
#   2. wasm: the same integration tests and the bindings tests in headless Chromium
#   3. Node: the built package's JS API
#   4. the page in headless Chromium (playwright-core driving Debian's chromium)
#   5. short runs of the cargo-fuzz targets (fuzz/)
# Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

step() { printf '\n\033[1m== %s\033[0m\n' "$*"; }

step "setup"
bash scripts/setup.sh --browser

step "native: cargo test"
cargo test --all-targets
cargo test --doc

step "wasm: wasm-bindgen-test in headless Chromium"
CHROMEDRIVER="$(command -v chromedriver)" cargo test --target wasm32-unknown-unknown --test section2 --test section3 --test section4 --test section5 --test milling --test line_space --test formula --test bindings

step "build: pkg/"
bash scripts/build.sh

step "node: the package's API"
node --expose-gc --test tests/node/*.test.mjs

step "page: headless Chromium"
node --test tests/page/*.test.mjs

step "fuzz: short runs of every cargo-fuzz target"
bash scripts/fuzz.sh 5
