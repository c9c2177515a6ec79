#!/usr/bin/env bash
# Benchmarks: criterion natively, then the same kernels through the wasm package in Node.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
bash scripts/setup.sh
bash scripts/build.sh
cargo bench --bench invariants --bench subdivision --bench congruence
node bench/wasm.mjs
node bench/page.mjs
