#!/usr/bin/env bash
# The documentation as one site in site/: the book (mdBook, sources in docs/) at the root, the
# JavaScript and TypeScript reference (typedoc over pkg/ruledlab.d.ts, the teaching module,
# pkg/cam/ruledlab_cam.d.ts, the CAM module `ruledlab/cam`, and pkg/view/www/index.d.ts,
# `ruledlab/view`, and pkg/view/www/course/index.d.ts, `ruledlab/course`, generated from the JSDoc
# of www/) in site/api/, and the Rust reference of the crates ruledlab and ruledlab-cam (rustdoc,
# copied from target/doc; the binding crates are the modules' inside) in site/rust/. The book's API pages link
# into both. Installs mdBook and builds pkg/ first when they are missing. Warnings are errors.
# `npm test` then checks every link and anchor of the site (tests/docs/links.mjs).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
bash scripts/setup.sh --docs
[ -f pkg/ruledlab.d.ts ] || bash scripts/build.sh
rm -rf site
mdbook build docs
npx typedoc --logLevel Warn --treatWarningsAsErrors --name "ruledlab $(node -p "require('./package.json').version")" \
  --readme none --disableSources --out site/api --tsconfig tests/types/docs.tsconfig.json pkg/ruledlab.d.ts pkg/cam/ruledlab_cam.d.ts pkg/view/www/index.d.ts pkg/view/www/course/index.d.ts
# (the lint step documents every crate of the workspace: the site takes the two users call)
rm -rf target/doc
RUSTDOCFLAGS="-D warnings" cargo doc --quiet --no-deps -p ruledlab -p ruledlab-cam
cp -r target/doc site/rust
# rustdoc's help and settings pages link to the index of all crates, which one crate has not
printf '<!doctype html><meta charset="utf-8"><title>ruledlab</title><meta http-equiv="refresh" content="0; url=ruledlab/index.html"><a href="ruledlab/index.html">ruledlab</a>\n' > site/rust/index.html
echo "docs: site/index.html (the book), site/api/index.html (JavaScript and TypeScript), site/rust/ruledlab/index.html (Rust)"
