#!/usr/bin/env bash
# Every test of ruledlab, after installing whatever is missing:
#   1. lint: rustfmt, clippy -D warnings (native and wasm32), rustdoc -D warnings
#   2. native Rust: unit, property and integration tests, doctests, benches in test mode
#   3. wasm: the same integration tests and the bindings tests in headless Chromium and in
#      headless Firefox ESR (geckodriver)
#   4. types: tsc --strict over www/, the scripts and tests with JSDoc types, and every README
#      snippet verbatim against the package's declarations
#   5. Node: the built package's JS API
#   6. the page in headless Chromium (playwright-core driving Debian's chromium), and a smoke
#      test of every scene in Firefox ESR, headed under Xvfb (headless Firefox has no WebGL2 here)
#   7. short runs of the cargo-fuzz targets (fuzz/)
# Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

# each step prints the seconds since the start, so slow steps show in the log
START=$SECONDS
step() { printf '\n\033[1m== %s\033[0m (at %d s)\n' "$*" $((SECONDS - START)); }
trap 'printf "\n== done in %d s\n" $((SECONDS - START))' EXIT

step "setup"
bash scripts/setup.sh --browser

step "lint: rustfmt, clippy (native and wasm32), rustdoc"
cargo fmt --check
cargo clippy --quiet --all-targets -- -D warnings
cargo clippy --quiet --target wasm32-unknown-unknown --lib --tests -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc --quiet --no-deps

step "native: cargo test"
cargo test --all-targets
cargo test --doc

step "wasm: wasm-bindgen-test in headless Chromium and headless Firefox ESR"
WASM_TESTS=(--test section2 --test section3 --test section4 --test section5 --test milling --test line_space --test formula --test focal --test bindings)
CHROMEDRIVER="$(command -v chromedriver)" cargo test --target wasm32-unknown-unknown "${WASM_TESTS[@]}"
GECKODRIVER="$(command -v geckodriver)" cargo test --target wasm32-unknown-unknown "${WASM_TESTS[@]}"

step "build: pkg/"
bash scripts/build.sh

step "types: tsc --strict over www/, scripts and tests; the README's snippets"
npx tsc -p tsconfig.json
npx tsc -p tsconfig.tests.json
node tests/types/readme.mjs
bash scripts/docs.sh

step "node: the package's API"
node --expose-gc --test tests/node/*.test.mjs

step "page: headless Chromium"
# two files at a time: most of a page test is waiting for frames (191 s → 139 s here)
node --test --test-concurrency=2 tests/page/*.test.mjs

step "page: Firefox ESR under Xvfb"
LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1280x1024x24" node tests/firefox/smoke.mjs

step "fuzz: short runs of every cargo-fuzz target"
bash scripts/fuzz.sh 3
