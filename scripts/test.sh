#!/usr/bin/env bash
# Every test of ruledlab, after installing whatever is missing. First, in order:
#   1. setup; build pkg/ and dist/; the Python package (python/: the compiled core,
#      crates/ruledlab-py, and the notebook widget with dist/ruledlab-embed.js inside) built into
#      one wheel and installed into .venv/
# then three lanes side by side, each in order:
#   2. page: the page in headless Chromium (playwright-core driving Debian's chromium), and the
#      example notebook run in a real JupyterLab and Notebook 7 (.venv/)
#   3. Rust: lint (rustfmt, clippy -D warnings natively and for wasm32; Biome, the JavaScript
#      linter and formatter, biome.json, over www/, scripts, tests and benches); native Rust (unit,
#      property and integration tests, doctests — the README's Rust snippets among them —, benches
#      in test mode); the integration tests and the bindings tests in headless Chromium and
#      headless Firefox ESR (geckodriver); docs (every JS/TS snippet of the book and the README
#      verbatim under tsc --strict against the package's declarations; the site — book, typedoc,
#      rustdoc -D warnings — built into site/; every link and anchor of it checked)
#   4. the rest: types (tsc --strict over www/, the scripts and tests with JSDoc types); the
#      wheel's pytest tests (the core against NumPy baselines and against the JavaScript API in
#      Node, the wheel in a fresh venv, mypy --strict on an example, the book's Python, the
#      widget); a smoke test of every scene in Firefox ESR, headed under Xvfb (headless Firefox
#      has no WebGL2 here); short runs of the cargo-fuzz targets (fuzz/); the built package's JS
#      API in Node
# Exits non-zero on the first failing step before the lanes, or after the lanes when one of them
# failed.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

# each step prints the seconds since the start, so slow steps show in the log
START=$SECONDS
step() { printf '\n\033[1m== %s\033[0m (at %d s)\n' "$*" $((SECONDS - START)); }
trap 'printf "\n== done in %d s\n" $((SECONDS - START))' EXIT

step "setup"
bash scripts/setup.sh --browser

step "build: pkg/"
bash scripts/build.sh

step "python: the wheel (python/ and crates/ruledlab-py into dist/python/, installed into .venv/)"
bash scripts/wheel.sh

# The rest runs as three lanes side by side, each lane's steps in order. The page tests (the
# longest lane, and what the built page and the wheel were needed for) start as early as they can;
# the Rust lane's builds fill the cores while browsers wait for frames. Each lane's log is printed
# when it ends, and the run fails if any lane fails.
step "three lanes: [page tests] [lint, native Rust, wasm tests, docs] [types, pytest, Firefox smoke, fuzz, Node tests]"
LOGS=$(mktemp -d)
NATIVE_INVARIANTS="$PWD/target/native-invariants.json"
rm -f "$NATIVE_INVARIANTS"
lane() {
  local name=$1; shift
  ( set -e; t0=$SECONDS; "$@"; echo "lane $name: done in $((SECONDS - t0)) s" ) > "$LOGS/$name.log" 2>&1
}
# each step of a lane says when it starts, in seconds since the lane began
at() { echo "== $* (at $((SECONDS - t0)) s of the lane)"; }
page_lane() {
  at "the page in headless Chromium; the example notebook in JupyterLab and Notebook 7"
  # two files at a time: most of a page test is waiting for frames (five files, two at a time on
  # an idle machine, kept 0.65 of its 2 cores busy); three at a time beside the other lanes
  # starved the Rust lane's builds
  node --test --test-concurrency=2 tests/page/*.test.mjs
}
rust_lane() {
  at "lint: rustfmt, clippy (native and wasm32), Biome"
  cargo fmt --check
  npx biome ci .
  cargo clippy --quiet --workspace --all-targets -- -D warnings
  cargo clippy --quiet --workspace --target wasm32-unknown-unknown --lib --tests -- -D warnings
  at "native: cargo test, every crate (with LinuxCNC's rs274 reading the G-code: crates/ruledlab-cam/tests/controller.rs)"
  RULEDLAB_REQUIRE_RS274=1 RULEDLAB_REQUIRE_READERS=1 cargo test --workspace --all-targets
  cargo test --workspace --doc
  # the native invariants the Node tests (the third lane) compare the wasm build's with
  cargo run -q --example dump_invariants > "$NATIVE_INVARIANTS.part"
  mv "$NATIVE_INVARIANTS.part" "$NATIVE_INVARIANTS"
  at "wasm: the integration tests (gathered into one binary: tests/browser.rs), the CAM crate's and the bindings' in headless Chromium and Firefox ESR"
  WASM_TESTS=(-p ruledlab --test browser -p ruledlab-cam --test milling -p ruledlab-wasm --test bindings)
  CHROMEDRIVER="$(command -v chromedriver)" cargo test --target wasm32-unknown-unknown "${WASM_TESTS[@]}"
  GECKODRIVER="$(command -v geckodriver)" cargo test --target wasm32-unknown-unknown "${WASM_TESTS[@]}"
  # here, not in the third lane: its rustdoc would wait for this lane's builds (cargo's build
  # directory is one at a time), and hold them up
  at "docs: the snippets of the book and the README; the site (book, typedoc, rustdoc -D warnings); its links"
  node tests/types/snippets.mjs
  bash scripts/docs.sh
  node tests/docs/links.mjs
}
other_lane() {
  at "types: tsc --strict over www/, scripts and tests"
  npx tsc -p tsconfig.json
  npx tsc -p tsconfig.tests.json
  at "python: pytest (the core against NumPy and the JavaScript API, the wheel in a fresh venv, mypy, the book's Python, the widget)"
  .venv/bin/python -m pytest -q -p no:cacheprovider python/tests
  at "Firefox smoke test of every scene, headed under Xvfb"
  LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1280x1024x24" node tests/firefox/smoke.mjs
  # fuzz before the Node tests: they wait for the Rust lane's native step, and the fuzz targets
  # build in their own build directory (fuzz/target), so they fill that wait
  at "fuzz: short runs of the cargo-fuzz targets"
  bash scripts/fuzz.sh 3
  at "Node: the built package's JS API (after the Rust lane has written the native invariants)"
  while [ ! -s "$NATIVE_INVARIANTS" ] && kill -0 "$RUST" 2>/dev/null; do sleep 5; done
  if [ -s "$NATIVE_INVARIANTS" ]; then export RULEDLAB_NATIVE_INVARIANTS="$NATIVE_INVARIANTS"; fi
  node --expose-gc --test tests/node/*.test.mjs
}
lane page page_lane & PAGE=$!
lane rust rust_lane & RUST=$!
lane other other_lane & OTHER=$!
failed=0
for pair in "page:$PAGE" "rust:$RUST" "other:$OTHER"; do
  name=${pair%%:*}
  if wait "${pair#*:}"; then status=ok; else status=FAILED; failed=1; fi
  printf '\n\033[1m== lane %s: %s\033[0m (at %d s)\n' "$name" "$status" $((SECONDS - START))
  cat "$LOGS/$name.log"
done
rm -rf "$LOGS"
exit $failed
