#!/usr/bin/env bash
# The API reference: typedoc over the package's declarations (pkg/ruledlab.d.ts, the wasm core,
# and pkg/view/www/index.d.ts, `ruledlab/view`, generated from the JSDoc of www/) into site/api/, and rustdoc for the Rust core into
# target/doc/ruledlab/. Builds pkg/ first if it is missing. Warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
[ -f pkg/ruledlab.d.ts ] || { bash scripts/setup.sh && bash scripts/build.sh; }
npx typedoc --logLevel Warn --treatWarningsAsErrors --name "ruledlab $(node -p "require('./package.json').version")" \
  --readme none --disableSources --out site/api --tsconfig tests/types/docs.tsconfig.json pkg/ruledlab.d.ts pkg/view/www/index.d.ts
RUSTDOCFLAGS="-D warnings" cargo doc --quiet --no-deps
echo "docs: site/api/index.html (JavaScript and TypeScript), target/doc/ruledlab/index.html (Rust)"
