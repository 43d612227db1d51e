#!/usr/bin/env bash
# Builds the `fuzz` preset (clang, ASan + UBSan) and runs every libFuzzer harness for SECONDS each (default 60)
# on a scratch copy of the committed seed corpus, one after the other, niced. Each harness first replays every
# committed seed (fuzz/corpus/<name>/, which holds every past finding), then searches. A crash, a sanitizer
# report or a violated invariant fails the script and leaves the input in build/fuzz/run/artifacts/.
# FUZZ_TARGETS="values nist" picks harnesses; the summary line per harness gives executions/s and coverage.
# fuzz_argv runs whole command lines through `dpdrng --validate-only` (every subcommand; arguments separated by
# NUL bytes in its corpus, fuzz/argv.dict written by build/fuzz/fuzz/make_argv_dict): exit 0 or 2 with one
# printable line, no file created in its scratch directory under $DPDRNG_FUZZ_TMP.
set -euo pipefail
cd "$(dirname "$0")/.."
secs=${1:-60}
names=${FUZZ_TARGETS:-"values bits nist study_config decomp_config cell_h5 argv"}
targets=()
for n in $names; do targets+=("fuzz_$n"); done
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)" --target "${targets[@]}"
work=build/fuzz/run
rm -rf "$work"
mkdir -p "$work/artifacts"
shm=/dev/shm
[[ -d $shm && -w $shm ]] || shm=$work
export DPDRNG_FUZZ_TMP=$shm/dpdrng-fuzz-$$
trap 'rm -rf "$DPDRNG_FUZZ_TMP"' EXIT
for n in $names; do
  mkdir -p "$work/corpus/$n"
  cp fuzz/corpus/"$n"/* "$work/corpus/$n/"
  dict=()
  [[ -f fuzz/$n.dict ]] && dict=(-dict="fuzz/$n.dict")
  if ! nice -n 10 "build/fuzz/fuzz/fuzz_$n" "$work/corpus/$n" "${dict[@]}" -max_total_time="$secs" -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/artifacts/$n-" >"$work/$n.log" 2>&1 </dev/null; then
    echo "fuzz_$n: FINDING (input in $work/artifacts/)" >&2
    tail -n 60 "$work/$n.log" >&2
    exit 1
  fi
  last=$(grep -E '^#[0-9]+' "$work/$n.log" | tail -n 1)
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$n.log")
  echo "fuzz_$n: ${secs} s, ${runs} runs, no finding; last status: ${last}"
done
