#!/usr/bin/env bash
# Writes that fail part-way: `study run`, `study report`, `study merge`, `simulate --series`, `simulate --tap-zeta`
# and `nist` under the write-fault shim (write_fault.c), whose writes to regular files fail with ENOSPC or EIO
# after N bytes. Each run must exit 1 with "write error" (no signal), leave no temporary file, lose no cell that
# was stored before it, and a rerun without the fault must complete the study with the results of a clean run;
# the taps' files are all whole or all absent.
# Usage: run.sh DPDRNG SHIM SCRATCH_DIR
set -uo pipefail
bin=$(realpath "$1") shim=$(realpath "$2") work=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

# The shim must take effect (a sanitizer runtime that intercepts write() itself would bypass it): skipped, not
# passed, when it does not.
if DPDRNG_FAULT_AFTER=0 LD_PRELOAD=$shim "$bin" gen --count 4 >probe.bin 2>/dev/null; then
  echo "the write-fault shim has no effect on this build: skipped" >&2
  exit 77
fi

cat >study.toml <<'EOF'
[study]
name = "fault"
replicas = 2
seed = 7

[sweep]
distributions = ["gauss"]
seedings = ["distance"]

[[sweep.generator]]
name = "tea32"
rounds = [1]

[scene]
particles = 64
steps = 60
equilibrate = 10

[tests]
chi2_steps = 20
ttest_pairs = 20
nist_sequences = 2
nist_bits = 4096
nist_generators = ["tea32"]
nist_distributions = ["gauss"]
nist_replicas = 1
EOF

# A dump of an HDF5 file without the wall-clock attributes (the only values that differ between two runs).
results() {
  h5dump "$1" 2>&1 | tail -n +2 | awk '
    /ATTRIBUTE "(seconds|cost\.(ns_per_number|particle_steps_per_second|rng_share|run_seconds|step_seconds))"/ {
      skip = 1; depth = 0 }
    skip { depth += gsub(/{/, "{"); depth -= gsub(/}/, "}"); if (depth <= 0) skip = 0; next }
    { print }'
}
same_results() {  # dir_a dir_b: the same cells and study.h5, up to wall-clock attributes
  local a=$1 b=$2 f
  [[ "$(cd "$a/cells" && ls)" == "$(cd "$b/cells" && ls)" ]] || { echo "cell lists differ"; return 1; }
  for f in "$a"/cells/*.h5; do
    [[ "$(results "$f")" == "$(results "$b/cells/${f##*/}")" ]] || { echo "${f##*/} differs"; return 1; }
  done
  [[ "$(results "$a/study.h5")" == "$(results "$b/study.h5")" ]] || { echo "study.h5 differs"; return 1; }
}
# Runs "$@" with writes failing after $N bytes ($ERR); checks exit 1, "write error", no temporaries in $dir.
faulty() {
  local label=$1 dir=$2
  shift 2
  DPDRNG_FAULT_AFTER=$N DPDRNG_FAULT_ERRNO=$ERR LD_PRELOAD=$shim "$@" >"$work/out.txt" 2>"$work/err.txt"
  local rc=$?
  if ((rc == 0)); then
    echo "$label N=$N $ERR: completed (the fault came after its last write)"
    return 0
  fi
  ((rc >= 128)) && fail "$label N=$N $ERR: killed by signal $((rc - 128))"
  ((rc != 1)) && fail "$label N=$N $ERR: exit $rc, not 1"
  grep -q "write error" "$work/err.txt" || fail "$label N=$N $ERR: no 'write error' in: $(head -c 300 "$work/err.txt")"
  local tmp
  tmp=$(find "$dir" -name '*.tmp*' 2>/dev/null)
  [[ -z $tmp ]] || fail "$label N=$N $ERR: temporaries left: $tmp"
  echo "$label N=$N $ERR: exit $rc, $(grep -o 'write error.*' "$work/err.txt" | head -c 160)"
}
checksums() { (cd "$1/cells" && sha256sum -- *.h5 2>/dev/null); }

for step in "study run study.toml --out clean -t 1" "study run study.toml --out half --shard 1/2 -t 1" \
    "study run study.toml --out other --shard 2/2 -t 1"; do
  # shellcheck disable=SC2086
  "$bin" $step 2>/dev/null || { echo "FAIL: $step without a fault" >&2; exit 1; }
done
"$bin" gen --count 20000 --format raw >bits.raw || { echo "FAIL: gen without a fault" >&2; exit 1; }
taps=(simulate --particles 64 --steps 40 --equilibrate 10)
mkdir -p tapsclean
"$bin" "${taps[@]}" --tap-zeta tapsclean/z.f64 --tap-words tapsclean/w.u64 >/dev/null ||
  { echo "FAIL: simulate --tap-zeta without a fault" >&2; exit 1; }
# The taps' files after a faulty run: all four whole (as a clean run's) or none.
taps_whole_or_absent() {
  local d=$1 f present=0
  for f in z.f64 z.f64.json w.u64 w.u64.json; do [[ -e $d/$f ]] && present=$((present + 1)); done
  ((present == 0)) && return 0
  ((present == 4)) || { fail "simulate --tap-zeta N=$N: $present of the 4 tap files left"; return 1; }
  for f in z.f64 w.u64; do cmp -s "$d/$f" "tapsclean/$f" || fail "simulate --tap-zeta N=$N: $f differs"; done
}

k=0
for N in 0 700 5000 40000 120000 190000 250000; do
  ERR=ENOSPC
  ((k++ % 2)) && ERR=EIO
  # study run from nothing, then resumed without the fault: the cells stored before the fault are kept.
  d=run$N
  faulty "study run" "$d" "$bin" study run study.toml --out "$d" -t 1
  before=$(checksums "$d")
  "$bin" study run study.toml --out "$d" -t 1 2>/dev/null || fail "rerun after study run N=$N"
  after=$(checksums "$d")
  while read -r line; do
    [[ -z $line ]] || grep -qxF -- "$line" <<<"$after" || fail "study run N=$N: stored cell changed: $line"
  done <<<"$before"
  msg=$(same_results clean "$d") || fail "study run N=$N: rerun differs from the clean run: $msg"

  # study report on a whole store: cells untouched, study.h5 whole (old or new).
  d=report$N
  cp -r clean "$d"
  before=$(checksums "$d")
  faulty "study report" "$d" "$bin" study report "$d" --no-charts
  [[ "$(checksums "$d")" == "$before" ]] || fail "study report N=$N: a cell file changed"
  msg=$(same_results clean "$d") || fail "study report N=$N: store damaged: $msg"

  # study merge of two shards into a third directory, then again without the fault.
  d=merge$N
  faulty "study merge" "$d" "$bin" study merge half other --out "$d"
  "$bin" study merge half other --out "$d" 2>/dev/null || fail "merge after the fault N=$N"
  msg=$(same_results clean "$d") || fail "study merge N=$N: merged store differs from the clean run: $msg"

  # simulate --series and nist (its report on standard output, redirected to the full disk).
  d=series$N
  faulty "simulate --series" "$d" "$bin" simulate --particles 64 --steps 40 --equilibrate 10 --series "$d"
  d=taps$N
  mkdir -p "$d"
  faulty "simulate --tap-zeta" "$d" "$bin" "${taps[@]}" --tap-zeta "$d/z.f64" --tap-words "$d/w.u64"
  taps_whole_or_absent "$d"
  d=nist$N
  mkdir -p "$d"
  DPDRNG_FAULT_AFTER=$N DPDRNG_FAULT_ERRNO=$ERR LD_PRELOAD=$shim "$bin" nist --input bits.raw --format raw \
    --tests frequency,runs >"$d/report.txt" 2>"$work/err.txt"
  rc=$?
  if ((rc == 0)); then
    echo "nist N=$N $ERR: completed ($(wc -c <"$d/report.txt") bytes)"
  else
    ((rc == 1)) || fail "nist N=$N $ERR: exit $rc, not 1"
    grep -q "write error" "$work/err.txt" || fail "nist N=$N $ERR: no 'write error' in: $(head -c 300 "$work/err.txt")"
    echo "nist N=$N $ERR: exit $rc, $(grep -o 'write error.*' "$work/err.txt" | head -c 160)"
  fi
done
((fails == 0)) || { echo "$fails failure(s)" >&2; exit 1; }
echo "all write faults handled"
