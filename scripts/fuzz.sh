#!/usr/bin/env bash
# Short runs of every fuzz target (cargo fuzz, libFuzzer): scripts/fuzz.sh [seconds per target].
# cargo-fuzz needs unstable rustc flags: RUSTC_BOOTSTRAP=1 lets the stable toolchain accept them;
# no sanitizer is needed (the core has no unsafe code; the one allowed place is the wasm
# bindings' views of wasm memory, which the fuzzed native core does not build): the bugs to find
# are panics. The seed
# corpora live in fuzz/seeds/; what a run discovers goes to a temporary directory.
set -euo pipefail
cd "$(dirname "$0")/../fuzz"
export PATH="$HOME/.cargo/bin:$PATH"
seconds=${1:-5}
command -v cargo-fuzz >/dev/null || cargo install cargo-fuzz --version 0.13.2
for target in import_text surface congruence toolpath formula visibility; do
  corpus=$(mktemp -d)
  if ! RUSTC_BOOTSTRAP=1 cargo fuzz run -s none "$target" "$corpus" "seeds/$target" -- \
      -max_total_time="$seconds" -print_final_stats=0 > "$corpus.log" 2>&1; then
    tail -40 "$corpus.log"
    echo "fuzz: $target failed (crash input in fuzz/artifacts/$target)" >&2
    exit 1
  fi
  echo "fuzz: $target: $(grep -E '^Done' "$corpus.log")"
  rm -rf "$corpus" "$corpus.log"
done
