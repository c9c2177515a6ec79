#!/usr/bin/env bash
# Benchmarks: criterion natively, then the same kernels through the wasm package in Node, their
# instructions per ruling (valgrind), the core from Python against careful NumPy (bench/python.py),
# frame times in the page, and Lighthouse on the production page
# and the one-file build (installed on demand into target/lighthouse/).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
bash scripts/setup.sh
bash scripts/build.sh
# glibc maps every allocation above 32 MB afresh (and unmaps it on free), so each native call
# would pay page faults that wasm, reusing its linear memory, does not: keep freed memory in the
# heap so native and wasm compare like with like
GLIBC_TUNABLES=glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967295 \
  cargo bench --bench invariants --bench subdivision --bench congruence
# the native side of bench/wasm.mjs's table, measured beside each wasm operation
cargo build --release --example count --quiet
node bench/wasm.mjs
# instructions per ruling (valgrind): the repeatable measure beside the times above
if command -v valgrind >/dev/null; then
  node bench/instructions.mjs
else
  echo "bench: valgrind not found; the instruction counts (bench/instructions.mjs) are skipped"
fi
# the core from Python against careful NumPy (the wheel built and installed into .venv/)
[ -x .venv/bin/python ] || bash scripts/setup.sh --browser
bash scripts/wheel.sh
.venv/bin/python bench/python.py
node bench/page.mjs
node bench/drag.mjs
node bench/klein.mjs
node bench/lighthouse.mjs
