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
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
command -v cargo-mutants >/dev/null || cargo install cargo-mutants --version 27.1.0 --locked
files=("$@")
if [ ${#files[@]} -eq 0 ]; then
  mapfile -t files < <(cargo mutants --list-files | grep -v '^src/wasm/' | sort)
fi
equivalent=mutants/equivalent.txt
read -r -a tests <<< "${MUTANTS_TESTS:---lib --tests}"
out=target/mutants
rm -rf "$out"
mkdir -p "$out/lib"
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
cargo mutants --list "${selection[@]}" | sort -u > "$out/all"
grep -v '^#' "$equivalent" | sed 's/  *#.*//' | sort -u > "$out/named"
for file in "${files[@]}"; do grep "^$file:" "$out/named" || true; done | sort -u > "$out/equivalent"
comm -23 "$out/equivalent" "$out/all" | sed "s#^#mutants: stale entry in $equivalent: #" >&2
run --output "$out/lib" "${common[@]}" -- --lib
first="$out/lib/mutants.out"
touch "$first/missed.txt" "$first/timeout.txt" "$first/caught.txt" "$first/unviable.txt"
second=0
if [ -s "$first/missed.txt" ]; then
  # the second pass: only what the unit tests let through, with every native test (a timeout
  # is caught already, so it is not tried again)
  cp -r "$first" "$out/mutants.out"
  cat "$first/timeout.txt" >> "$out/mutants.out/previously_caught.txt"
  run --output "$out" "${common[@]}" --iterate -- "${tests[@]}"
  second=1
fi
result="$first"
[ $second = 0 ] || result="$out/mutants.out"
touch "$result/missed.txt" "$result/timeout.txt" "$result/caught.txt"
count() { { grep "^$1:" "$2" || true; } | sort -u | wc -l; }
status=0
for file in "${files[@]}"; do
  caught=$(count "$file" "$first/caught.txt")
  [ $second = 0 ] || caught=$((caught + $(count "$file" "$result/caught.txt")))
  unviable=$(count "$file" "$first/unviable.txt")
  timeout=$(count "$file" "$first/timeout.txt")
  [ $second = 0 ] || timeout=$((timeout + $(count "$file" "$result/timeout.txt")))
  missed_all=$({ grep "^$file:" "$result/missed.txt" || true; } | sort -u)
  missed=$(comm -23 <(printf '%s\n' "$missed_all" | sed '/^$/d') "$out/equivalent" | sed '/^$/d')
  n_missed=$(printf '%s' "$missed" | grep -c . || true)
  equiv=$(comm -12 <(printf '%s\n' "$missed_all" | sed '/^$/d') "$out/equivalent" | grep -c . || true)
  viable=$((caught + n_missed + timeout))
  total=$(count "$file" "$out/all")
  percent=$(awk -v c=$((caught + timeout)) -v v="$viable" 'BEGIN { printf "%.1f", v ? 100 * c / v : 100 }')
  echo "mutants: $file: $percent % caught ($((caught + timeout)) of $viable viable; $equiv equivalent, $unviable unviable; $total in all)" | tee -a "$out/summary.txt"
  if [ "$n_missed" -gt 0 ]; then
    printf '%s\n' "$missed" | sed 's/^/  missed: /'
    status=1
  fi
done
exit $status
