#!/usr/bin/env bash
# Every test of ruledlab, after installing whatever is missing:
#   1. lint: rustfmt, clippy -D warnings (native and wasm32), rustdoc -D warnings; Biome (the
#      JavaScript linter and formatter, biome.json) over www/, scripts, tests and benches
#   2. native Rust: unit, property and integration tests, doctests (the README's Rust snippets
#      among them), benches in test mode
#   3. build pkg/ and dist/; types: tsc --strict over www/, the scripts and tests with JSDoc types;
#      the Python package (python/: the compiled core, crates/ruledlab-py, and the notebook widget
#      with dist/ruledlab-embed.js inside) built into one wheel and installed into .venv/; its
#      pytest tests (the core against NumPy baselines and against the JavaScript API in Node, the
#      wheel in a fresh venv, mypy --strict on an example, the book's Python, the widget)
#   4. docs: every JS/TS snippet of the book and the README verbatim under tsc --strict against
#      the package's declarations; the site (book, typedoc, rustdoc) built into site/; every
#      link and anchor of it checked
#   then three lanes side by side:
#   5. wasm: the same integration tests and the bindings tests in headless Chromium and in
#      headless Firefox ESR (geckodriver)
#   6. the page in headless Chromium (playwright-core driving Debian's chromium), and the example
#      notebook run in a real JupyterLab and Notebook 7 (.venv/)
#   7. Node: the built package's JS API; short runs of the cargo-fuzz targets (fuzz/); a smoke
#      test of every scene in Firefox ESR, headed under Xvfb (headless Firefox has no WebGL2 here)
# Exits non-zero on the first failing step, or after the lanes when one of them failed.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

# each step prints the seconds since the start, so slow steps show in the log
START=$SECONDS
step() { printf '\n\033[1m== %s\033[0m (at %d s)\n' "$*" $((SECONDS - START)); }
trap 'printf "\n== done in %d s\n" $((SECONDS - START))' EXIT

step "setup"
bash scripts/setup.sh --browser

step "lint: rustfmt, clippy (native and wasm32), rustdoc, Biome"
cargo fmt --check
npx biome ci .
cargo clippy --quiet --workspace --all-targets -- -D warnings
cargo clippy --quiet --workspace --target wasm32-unknown-unknown --lib --tests -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc --quiet --workspace --no-deps

step "native: cargo test, every crate (with LinuxCNC's rs274 reading the G-code: crates/ruledlab-cam/tests/controller.rs)"
RULEDLAB_REQUIRE_RS274=1 RULEDLAB_REQUIRE_READERS=1 cargo test --workspace --all-targets
cargo test --workspace --doc
# the native invariants the Node tests compare the wasm build's with, written now: a cargo run in
# the Node lane would wait for the build directory as long as the wasm lane holds it
cargo run -q --example dump_invariants > target/native-invariants.json
export RULEDLAB_NATIVE_INVARIANTS="$PWD/target/native-invariants.json"

step "build: pkg/"
bash scripts/build.sh

step "types: tsc --strict over www/, scripts and tests"
npx tsc -p tsconfig.json
npx tsc -p tsconfig.tests.json

step "python: the wheel (python/ and crates/ruledlab-py into dist/python/, installed into .venv/), pytest"
bash scripts/wheel.sh
# (not in a lane: its wheel built in a plain venv is a release build of the core that slowed the
# lanes beside it from 370 to 946 s)
.venv/bin/python -m pytest -q -p no:cacheprovider python/tests

step "docs: the snippets of the book and the README; the site (book, typedoc, rustdoc); its links"
node tests/types/snippets.mjs
bash scripts/docs.sh
node tests/docs/links.mjs

# The rest runs as three lanes side by side (the machine has idle cores while browsers wait for
# frames): each lane's log is printed when it ends, and the run fails if any lane fails.
step "three lanes: [wasm tests in Chromium, Firefox] [page tests] [Node tests, fuzz, Firefox smoke]"
LOGS=$(mktemp -d)
lane() {
  local name=$1; shift
  ( set -e; t0=$SECONDS; "$@"; echo "lane $name: done in $((SECONDS - t0)) s" ) > "$LOGS/$name.log" 2>&1
}
wasm_lane() {
  # the geometry's integration tests, the CAM crate's, and each module's bindings
  WASM_TESTS=(-p ruledlab --test kernels --test section2 --test section3 --test section4 --test section5 --test line_space --test formula --test focal --test visibility --test snap --test developable -p ruledlab-cam --test milling -p ruledlab-wasm --test bindings)
  CHROMEDRIVER="$(command -v chromedriver)" cargo test --target wasm32-unknown-unknown "${WASM_TESTS[@]}"
  GECKODRIVER="$(command -v geckodriver)" cargo test --target wasm32-unknown-unknown "${WASM_TESTS[@]}"
}
page_lane() {
  # two files at a time: most of a page test is waiting for frames
  node --test --test-concurrency=2 tests/page/*.test.mjs
}
other_lane() {
  node --expose-gc --test tests/node/*.test.mjs
  bash scripts/fuzz.sh 3
  LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1280x1024x24" node tests/firefox/smoke.mjs
}
lane wasm wasm_lane & WASM=$!
lane page page_lane & PAGE=$!
lane other other_lane & OTHER=$!
failed=0
for pair in "wasm:$WASM" "page:$PAGE" "other:$OTHER"; do
  name=${pair%%:*}
  if wait "${pair#*:}"; then status=ok; else status=FAILED; failed=1; fi
  printf '\n\033[1m== lane %s: %s\033[0m (at %d s)\n' "$name" "$status" $((SECONDS - START))
  cat "$LOGS/$name.log"
done
rm -rf "$LOGS"
exit $failed
