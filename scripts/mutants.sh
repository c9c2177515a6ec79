#!/usr/bin/env bash
# Mutation testing of core modules (issue 34): scripts/mutants.sh [src/file.rs ...].
# cargo-mutants changes the code one small way at a time (an operator, a comparison, a return
# value) and runs the native tests; a mutant they still pass is "missed". Not part of `npm test`:
# it takes hours over the whole core on 2 cores. Without arguments it takes every core module
# (src/**/*.rs but the bindings in src/wasm/).
# Two passes: first the fast in-file unit tests (`--lib`) on every mutant, then what they missed
# once more with the whole native suite (MUTANTS_TESTS, cargo test's arguments; default
# "--lib --tests", all but the doctests); a timeout counts as caught at once (the mutant did
# not pass). All files share one copy of the tree and one baseline build per pass; builds use
# the `mutants` profile (no debug info). Do not edit the sources during a run: the second pass
# finds mutants by line.
# mutants/equivalent.txt names the mutants that change nothing observable, each with its reason:
# they are listed but not counted.
# Results: target/mutants/mutants.out (the first pass: target/mutants/lib/mutants.out) and a
# line per module in target/mutants/summary.txt.
# `scripts/mutants.sh --again` (after writing tests for what was missed): the second pass once
# more over the last run's missed mutants alone, then the summary. Tests may be added, but the
# code above them must not move: mutants are found by line.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
command -v cargo-mutants >/dev/null || cargo install cargo-mutants --version 27.1.0 --locked
out=target/mutants
again=0
if [ "${1:-}" = --again ]; then
  again=1
  [ $# -eq 1 ] || { echo "mutants: --again takes no files (it re-tries the last run's)" >&2; exit 1; }
  [ -s "$out/files" ] && [ -s "$out/all" ] && [ -d "$out/lib/mutants.out" ] ||
    { echo "mutants: --again needs an earlier run in $out" >&2; exit 1; }
  mapfile -t files < "$out/files"
else
  files=("$@")
  if [ ${#files[@]} -eq 0 ]; then
    mapfile -t files < <(cargo mutants --list-files | grep -v '^src/wasm/' | sort)
  fi
  rm -rf "$out"
  mkdir -p "$out/lib"
  printf '%s\n' "${files[@]}" > "$out/files"
fi
equivalent=mutants/equivalent.txt
read -r -a tests <<< "${MUTANTS_TESTS:---lib --tests}"
selection=()
for file in "${files[@]}"; do selection+=(--file "$file"); done
common=(--no-shuffle --profile mutants "${selection[@]}")
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
[ $again = 1 ] || run --output "$out/lib" "${common[@]}" -- --lib
touch "$first/missed.txt" "$first/timeout.txt" "$first/caught.txt" "$first/unviable.txt"
result="$first"
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
  run --output "$out" "${common[@]}" --iterate -- "${tests[@]}"
  result="$out/mutants.out"
fi
# every mutant has an outcome (an interrupted run would otherwise count as caught below)
touch "$result"/{caught,missed,timeout,unviable,previously_caught}.txt
untried=$(comm -23 "$out/all" <(sort -u "$result"/{caught,missed,timeout,unviable,previously_caught}.txt) | grep -c . || true)
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
  unviable=$(count "$file" "$first/unviable.txt")
  missed_all=$({ grep "^$file:" "$result/missed.txt" || true; } | sort -u)
  missed=$(comm -23 <(printf '%s\n' "$missed_all" | sed '/^$/d') "$out/equivalent" | sed '/^$/d')
  n_missed=$(printf '%s' "$missed" | grep -c . || true)
  equiv=$(comm -12 <(printf '%s\n' "$missed_all" | sed '/^$/d') "$out/equivalent" | grep -c . || true)
  caught=$((total - unviable - n_missed - equiv))
  viable=$((caught + n_missed))
  percent=$(awk -v c="$caught" -v v="$viable" 'BEGIN { printf "%.1f", v ? 100 * c / v : 100 }')
  echo "mutants: $file: $percent % caught ($caught of $viable viable; $equiv equivalent, $unviable unviable; $total in all)" | tee -a "$out/summary.txt"
  if [ "$n_missed" -gt 0 ]; then
    printf '%s\n' "$missed" | sed 's/^/  missed: /'
    status=1
  fi
done
exit $status
