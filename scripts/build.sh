#!/usr/bin/env bash
# Builds the package into pkg/ (release wasm with LTO, wasm-bindgen --target web, wasm-opt;
# skipped when pkg/ is newer than the compiled wasm; pkg/catalogue.js, the catalogue's formula
# texts for the page; pkg/zip.js, fflate's zip writer and reader as one module; pkg/scorm-schemas.js, the schema files a SCORM package carries; pkg/view/, the declarations of ruledlab/view generated from www/'s JSDoc),
# the one-file builds into dist/ and the production page into dist/web/ (bundled, minified,
# split, hashed, precompressed: scripts/web.mjs).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

raw=target/wasm32-unknown-unknown/release/ruledlab.wasm
cargo build --release --target wasm32-unknown-unknown --lib --quiet
if [ pkg/ruledlab_bg.wasm -nt "$raw" ] && [ pkg/ruledlab.js -nt "$raw" ]; then
  echo "build: pkg/ is up to date"
  [ pkg/catalogue.js -nt pkg/ruledlab_bg.wasm ] || node scripts/catalogue.mjs
  node scripts/zip.mjs
  node scripts/scorm-schemas.mjs
  node scripts/view-types.mjs
  node scripts/onefile.mjs
  node scripts/web.mjs
  exit 0
fi
wasm-bindgen --target web --weak-refs --out-dir pkg --out-name ruledlab \
  --remove-name-section --remove-producers-section "$raw"
node scripts/glue.mjs pkg/ruledlab.js
node_modules/.bin/wasm-opt -O3 pkg/ruledlab_bg.wasm -o pkg/ruledlab_bg.wasm
size=$(stat -c %s pkg/ruledlab_bg.wasm)
gz=$(gzip -9 -c pkg/ruledlab_bg.wasm | wc -c)
echo "build: pkg/ruledlab_bg.wasm $((size / 1024)) KiB, $((gz / 1024)) KiB gzipped"
node scripts/catalogue.mjs
node scripts/zip.mjs
node scripts/scorm-schemas.mjs
node scripts/view-types.mjs
node scripts/onefile.mjs
node scripts/web.mjs
