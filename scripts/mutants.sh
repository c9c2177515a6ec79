#!/usr/bin/env bash
# Mutation testing of the modules of the geometry crate and the CAM crate (the book, "Mutation
# testing"): scripts/mutants.sh [file.rs ...], a file named from the workspace's root
# (src/snap/meet.rs, crates/ruledlab-cam/src/stock.rs).
# cargo-mutants changes the code one small way at a time (an operator, a comparison, a return
# value) and runs the native tests of the mutant's crate; a mutant they still pass is "missed".
# Not part of `npm test`: it takes hours over both crates on 2 cores. Without arguments it takes
# every module of both (PACKAGES below: src/**/*.rs and crates/ruledlab-cam/src/**/*.rs; the
# bindings are not measured).
# Two passes: first the fast in-file unit tests (`--lib`) on every mutant, then what they missed
# once more with the whole native suite (MUTANTS_TESTS, cargo test's arguments; default
# "--lib --tests", all but the doctests); a timeout counts as caught at once (the mutant did
# not pass). All files share one copy of the tree and one baseline build per pass; builds use
# the `mutants` profile (no debug info). Do not edit the sources during a run: the second pass
# finds mutants by line.
# The test selection is given to the build as well as to the run (`--cargo-arg`): `cargo test
# --no-run` would otherwise build every test target, example and bench for each mutant.
# The files the native build does not compile (WASM_ONLY below: the simd128 lanes, the
# serialisation of a message's arguments) are built for wasm32 instead and tested in headless
# Chromium by the wasm tests that reach them; a mutant counts as caught there only when its log
# shows a failing test (not a browser that failed to start).
# mutants/equivalent.txt names the mutants that change nothing observable, each with its reason:
# they are listed but not counted.
# Results: target/mutants/mutants.out (the first pass: target/mutants/lib/mutants.out; the
# browser's: target/mutants/wasm/mutants.out) and a line per module in
# target/mutants/summary.txt. MUTANTS_OUT=dir puts them in dir instead (two runs, say a long
# one and an --again of an earlier one, each with its own).
# `scripts/mutants.sh --again` (after writing tests for what was missed): the second pass once
# more over the last run's missed mutants alone, then the summary. Tests may be added, but the
# code above them must not move: mutants are found by line.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
command -v cargo-mutants >/dev/null || cargo install cargo-mutants --version 27.1.0 --locked
# the crates measured: cargo-mutants mutates these (from the root it would take the root package
# alone) and runs each mutant's own crate's tests
PACKAGES=(--package ruledlab --package ruledlab-cam)
WASM_ONLY=(src/base/lanes/simd128.rs src/error/serialize.rs)
WASM_TESTS=(--test kernels --test bindings)
out=${MUTANTS_OUT:-target/mutants}
again=0
if [ "${1:-}" = --again ]; then
  again=1
  [ $# -eq 1 ] || { echo "mutants: --again takes no files (it re-tries the last run's)" >&2; exit 1; }
  [ -s "$out/files" ] && [ -s "$out/all" ] ||
    { echo "mutants: --again needs an earlier run in $out" >&2; exit 1; }
  mapfile -t files < "$out/files"
else
  files=("$@")
  if [ ${#files[@]} -eq 0 ]; then
    mapfile -t files < <(cargo mutants --list-files "${PACKAGES[@]}" | sort)
  fi
  rm -rf "$out"
  mkdir -p "$out/lib" "$out/wasm"
  printf '%s\n' "${files[@]}" > "$out/files"
fi
native=() wasm=()
for file in "${files[@]}"; do
  if printf '%s\n' "${WASM_ONLY[@]}" | grep -qxF "$file"; then wasm+=("$file"); else native+=("$file"); fi
done
equivalent=mutants/equivalent.txt
read -r -a tests <<< "${MUTANTS_TESTS:---lib --tests}"
selection=("${PACKAGES[@]}")
for file in "${files[@]}"; do selection+=(--file "$file"); done
# exit 0: all caught, 2: some missed, 3: some timed out; anything else (a failing baseline,
# a usage error) stops here
run() {
  local code=0
  cargo mutants "$@" || code=$?
  case $code in 0 | 2 | 3) ;; *) echo "mutants: cargo mutants failed (exit $code)" >&2; exit "$code" ;; esac
}
# the equivalent mutants that the files still have; an entry that matches none is stale
[ $again = 1 ] || cargo mutants --list "${selection[@]}" | sort -u > "$out/all"
grep -v '^#' "$equivalent" | sed 's/  *#.*//' | sort -u > "$out/named"
for file in "${files[@]}"; do grep "^$file:" "$out/named" || true; done | sort -u > "$out/equivalent"
comm -23 "$out/equivalent" "$out/all" | sed "s#^#mutants: stale entry in $equivalent: #" >&2
first="$out/lib/mutants.out"
result="$first"
if [ ${#native[@]} -gt 0 ]; then
  common=(--no-shuffle --profile mutants "${PACKAGES[@]}")
  for file in "${native[@]}"; do common+=(--file "$file"); done
  [ $again = 1 ] || run --output "$out/lib" "${common[@]}" --cargo-arg=--lib
  touch "$first/missed.txt" "$first/timeout.txt" "$first/caught.txt" "$first/unviable.txt"
  [ ! -d "$out/mutants.out" ] || result="$out/mutants.out"
  if [ -s "$result/missed.txt" ]; then
    # the second pass: only what the unit tests (or, again, the last second pass) let through,
    # with every native test (a timeout is caught already, so it is not tried again)
    if [ "$result" = "$first" ]; then
      cp -r "$first" "$out/mutants.out"
      cat "$first/timeout.txt" >> "$out/mutants.out/previously_caught.txt"
    else
      cat "$result/timeout.txt" >> "$result/previously_caught.txt"
    fi
    if [ $again = 1 ] && [ "${tests[*]}" != --lib ]; then
      # after new tests: the unit tests first (a cheap build), the whole suite on what is left
      run --output "$out" "${common[@]}" --iterate --cargo-arg=--lib
      cat "$result/timeout.txt" >> "$result/previously_caught.txt"
    fi
    run --output "$out" "${common[@]}" --iterate "${tests[@]/#/--cargo-arg=}"
    result="$out/mutants.out"
  fi
fi
browser="$out/wasm/mutants.out"
if [ ${#wasm[@]} -gt 0 ]; then
  # the wasm-only files, in Chromium (again: only what the last browser pass missed)
  chromium=(--no-shuffle --profile mutants --package ruledlab --cargo-arg=--target=wasm32-unknown-unknown)
  for file in "${wasm[@]}"; do chromium+=(--file "$file"); done
  for t in "${WASM_TESTS[@]}"; do chromium+=(--cargo-arg="$t"); done
  if [ $again = 1 ] && [ -d "$browser" ]; then
    cat "$browser/timeout.txt" >> "$browser/previously_caught.txt"
    chromium+=(--iterate)
  fi
  CHROMEDRIVER="$(command -v chromedriver)" run --output "$out/wasm" "${chromium[@]}"
  # a caught mutant's log must show a failing test, not a browser or driver that failed
  node -e '
    const o = require(process.argv[1] + "/outcomes.json").outcomes;
    const fs = require("fs");
    const bad = o.filter((x) => x.summary === "CaughtMutant" &&
      !/test result: FAILED|panicked at/.test(fs.readFileSync(process.argv[1] + "/" + x.log_path, "utf8")));
    for (const x of bad) console.error("mutants: counted caught, but no test failed: " + x.scenario.Mutant.name);
    process.exit(bad.length ? 1 : 0);
  ' "$PWD/$browser" || { echo "mutants: run the browser pass again" >&2; exit 1; }
fi
# every mutant has an outcome (an interrupted run would otherwise count as caught below)
for d in "$result" "$first" "$browser"; do
  mkdir -p "$d" && touch "$d"/{caught,missed,timeout,unviable,previously_caught}.txt
done
outcomes() { sort -u "$result"/{caught,missed,timeout,unviable,previously_caught}.txt "$browser"/{caught,missed,timeout,unviable,previously_caught}.txt; }
untried=$(comm -23 "$out/all" <(outcomes) | grep -c . || true)
if [ "$untried" -gt 0 ]; then
  echo "mutants: $untried mutants have no outcome (an interrupted run?): run again" >&2
  exit 1
fi
count() { { grep "^$1:" "$2" || true; } | sort -u | wc -l; }
: > "$out/summary.txt"
status=0
# every viable mutant ends caught, timed out or missed, and the first pass sorts out the
# unviable ones: what is neither unviable nor missed in the end was caught
for file in "${files[@]}"; do
  total=$(count "$file" "$out/all")
  unviable=$(cat "$first/unviable.txt" "$browser/unviable.txt" | { grep "^$file:" || true; } | sort -u | wc -l)
  missed_all=$(cat "$result/missed.txt" "$browser/missed.txt" | { grep "^$file:" || true; } | sort -u)
  missed=$(comm -23 <(printf '%s\n' "$missed_all" | sed '/^$/d') "$out/equivalent" | sed '/^$/d')
  n_missed=$(printf '%s' "$missed" | grep -c . || true)
  equiv=$(comm -12 <(printf '%s\n' "$missed_all" | sed '/^$/d') "$out/equivalent" | grep -c . || true)
  caught=$((total - unviable - n_missed - equiv))
  viable=$((caught + n_missed))
  percent=$(awk -v c="$caught" -v v="$viable" 'BEGIN { printf "%.1f", v ? 100 * c / v : 100 }')
  where=""
  printf '%s\n' "${wasm[@]}" | grep -qxF "$file" && where=" (in Chromium)"
  echo "mutants: $file: $percent % caught ($caught of $viable viable; $equiv equivalent, $unviable unviable; $total in all)$where" | tee -a "$out/summary.txt"
  if [ "$n_missed" -gt 0 ]; then
    printf '%s\n' "$missed" | sed 's/^/  missed: /'
    status=1
  fi
done
exit $status
