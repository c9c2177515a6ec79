#!/usr/bin/env bash
# Mutation testing of core modules (issue 34): scripts/mutants.sh [src/file.rs ...].
# cargo-mutants changes the code one small way at a time (an operator, a comparison, a return
# value) and runs the native tests; a mutant they still pass is "missed". Not part of `npm test`:
# a module takes minutes to an hour on 2 cores. Without arguments it takes the modules added last
# (focal geometry, linear complexes, formulas). MUTANTS_TESTS narrows the tests run for each
# mutant (cargo test's arguments, e.g. "--lib --test focal"; default: all native tests).
# mutants/equivalent.txt names the mutants that change nothing observable, each with its reason:
# they are listed but not counted; a timeout counts as caught (the mutant did not pass). Results:
# target/mutants/<path with - for />/mutants.out.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
command -v cargo-mutants >/dev/null || cargo install cargo-mutants --version 27.1.0 --locked
files=("$@")
[ ${#files[@]} -gt 0 ] || files=(src/congruence/focal.rs src/linear_complex.rs src/formula/*.rs)
equivalent=mutants/equivalent.txt
read -r -a tests <<< "${MUTANTS_TESTS:-}"
status=0
for file in "${files[@]}"; do
  name=$(printf '%s' "${file%.rs}" | tr / -)
  out="target/mutants/$name"
  mkdir -p "$out"
  # each equivalent mutant that this file still has; an entry that matches none is stale
  grep -v '^#' "$equivalent" | grep "^$file:" | sed 's/  *#.*//' | sort -u > "$out/equivalent" || true
  cargo mutants --list --file "$file" | sort -u > "$out/all"
  comm -23 "$out/equivalent" "$out/all" | sed "s#^#mutants: stale entry in $equivalent: #" >&2
  # exit 0: all caught, 2: some missed, 3: some timed out; anything else (a failing baseline,
  # a usage error) stops here
  code=0
  cargo mutants --file "$file" --output "$out" --no-shuffle -- "${tests[@]}" || code=$?
  case $code in 0 | 2 | 3) ;; *) echo "mutants: cargo mutants failed on $file (exit $code)" >&2; exit "$code" ;; esac
  missed=$(sort -u "$out/mutants.out/missed.txt" | comm -23 - "$out/equivalent" | wc -l)
  caught=$(wc -l < "$out/mutants.out/caught.txt")
  unviable=$(wc -l < "$out/mutants.out/unviable.txt")
  timeout=$(wc -l < "$out/mutants.out/timeout.txt")
  equiv=$(sort -u "$out/mutants.out/missed.txt" | comm -12 - "$out/equivalent" | wc -l)
  viable=$((caught + missed + timeout))
  percent=$(awk -v c=$((caught + timeout)) -v v="$viable" 'BEGIN { printf "%.1f", v ? 100 * c / v : 100 }')
  echo "mutants: $file: $percent % caught ($((caught + timeout)) of $viable viable; $equiv equivalent, $unviable unviable)"
  if [ "$missed" -gt 0 ]; then
    sort -u "$out/mutants.out/missed.txt" | comm -23 - "$out/equivalent" | sed 's/^/  missed: /'
    status=1
  fi
done
exit $status
