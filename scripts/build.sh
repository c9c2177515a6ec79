#!/usr/bin/env bash
# Builds the package into pkg/ (the two wasm modules — the teaching module pkg/ruledlab.js and
# the CAM module pkg/cam/ruledlab_cam.js — release with LTO, wasm-bindgen --target web, wasm-opt;
# skipped when pkg/ is newer than the compiled wasm; pkg/catalogue.js, the catalogue's formula
# texts for the page; pkg/zip.js, fflate's zip writer and reader as one module; pkg/scorm-schemas.js, the schema files a SCORM package carries; pkg/view/, the declarations of ruledlab/view generated from www/'s JSDoc),
# the one-file builds into dist/ and the production page into dist/web/ (bundled, minified,
# split, hashed, precompressed: scripts/web.mjs).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

# the two modules: the teaching module (crates/ruledlab-wasm → pkg/ruledlab.js) and the CAM
# module (crates/ruledlab-cam-wasm → pkg/cam/ruledlab_cam.js), loaded when asked for
raw=target/wasm32-unknown-unknown/release/ruledlab_wasm.wasm
raw_cam=target/wasm32-unknown-unknown/release/ruledlab_cam_wasm.wasm
cargo build --release --target wasm32-unknown-unknown -p ruledlab-wasm -p ruledlab-cam-wasm --lib --quiet
if [ pkg/ruledlab_bg.wasm -nt "$raw" ] && [ pkg/ruledlab.js -nt "$raw" ] && [ pkg/cam/ruledlab_cam_bg.wasm -nt "$raw_cam" ]; then
  echo "build: pkg/ is up to date"
  [ pkg/catalogue.js -nt pkg/ruledlab_bg.wasm ] || node scripts/catalogue.mjs
  node scripts/zip.mjs
  node scripts/scorm-schemas.mjs
  node scripts/view-types.mjs
  node scripts/onefile.mjs
  node scripts/web.mjs
  exit 0
fi
# one module: wasm-bindgen's glue, the glue's errors given codes, wasm-opt; its size said
bind() {
  local input=$1 dir=$2 name=$3
  wasm-bindgen --target web --weak-refs --out-dir "$dir" --out-name "$name" \
    --remove-name-section --remove-producers-section "$input"
  node scripts/glue.mjs "$dir/$name.js"
  # (--converge: -O3 again until the module stops shrinking; --low-memory-unused: the first KiB
  # of memory is never read or written — Rust lays the stack first, growing down from 1 MiB to 0,
  # and the data after it — so address arithmetic folds into the loads' offsets; floating point
  # untouched: wasm-opt never reorders it)
  node_modules/.bin/wasm-opt -O3 --converge --low-memory-unused "$dir/${name}_bg.wasm" -o "$dir/${name}_bg.wasm"
  local size gz
  size=$(stat -c %s "$dir/${name}_bg.wasm")
  gz=$(gzip -9 -c "$dir/${name}_bg.wasm" | wc -c)
  echo "build: $dir/${name}_bg.wasm $((size / 1024)) KiB, $((gz / 1024)) KiB gzipped"
}
# the two modules side by side: wasm-opt works on one core, and each waits for nothing of the other
bind "$raw" pkg ruledlab &
teaching=$!
bind "$raw_cam" pkg/cam ruledlab_cam &
cam=$!
wait "$teaching"
wait "$cam"
node scripts/catalogue.mjs
node scripts/zip.mjs
node scripts/scorm-schemas.mjs
node scripts/view-types.mjs
node scripts/onefile.mjs
node scripts/web.mjs
node scripts/sizes.mjs
