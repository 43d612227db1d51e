#!/usr/bin/env bash
# Results bit for bit across builds: the portable preset's dpdrng (-march=x86-64-v3, AVX2) against the release
# build's (-march=native, which may be AVX-512), on an all-pairs run (the paper's scene: the all-pairs loop and
# the g(r) sampler without a grid, 32TEA's one-word blocks through the vectorised Box–Muller) and two-thread
# cells runs (the sorted cells, the layer queue and the gridded g(r) sampler; two- and one-word blocks). Every
# field of the JSON records must match to the last digit (17 significant digits, so to the bit), wall-clock
# timings aside. Needs build/release/dpdrng; builds only the portable dpdrng.
set -euo pipefail
cd "$(dirname "$0")/.."
native=build/release/dpdrng
portable=build/portable/dpdrng
[[ -x $native ]] || { echo "portable check: $native is missing (build the release preset first)" >&2; exit 1; }
cmake --preset portable >/dev/null
cmake --build --preset portable -j "${DPDRNG_JOBS:-$(nproc)}" --target dpdrng
# Wall-clock figures differ from run to run; the counts of numbers drawn do not.
results() {
  "$@" | python3 -c '
import json, sys
j = json.load(sys.stdin)
t = j.pop("timings", {})
j["random_numbers"] = t.get("random_numbers")
print(json.dumps(j, indent=1, sort_keys=True))'
}
fail=0
while read -r name args; do
  a=$(mktemp) b=$(mktemp)
  # shellcheck disable=SC2086
  results "$native" $args >"$a"
  # shellcheck disable=SC2086
  results "$portable" $args >"$b"
  if cmp -s "$a" "$b"; then
    echo "portable check: $name: identical ($(wc -l <"$a") lines)"
  else
    echo "portable check: MISMATCH in $name between $native and $portable (dpdrng $args):" >&2
    diff "$a" "$b" | head -40 >&2
    fail=1
  fi
  rm -f "$a" "$b"
done <<'RUNS'
all-pairs simulate --json -q -n 256 --steps 300 --equilibrate 50 -g tea32 -r 1 --threads 1
cells simulate --json -q --pairs cells -n 3000 --steps 40 --equilibrate 10 -g tea64 -r 8 --threads 2 --sample-every 5
cells-tea32 simulate --json -q --pairs cells -n 3000 --steps 40 --equilibrate 10 -g tea32 -r 1 --threads 2 --sample-every 5
RUNS
if [[ $fail != 0 ]]; then
  echo "portable check: FAILED: the portable and native builds' results differ" >&2
  exit 1
fi
