#!/usr/bin/env bash
# The first LAMMPS checks (tests/lammps/run.sh runs them, and ctest -L lammps as lammps_basic):
#  - lammps/examples/in.water with 32TEA(1), distance seeding, halves feed on 1 and 2 MPI ranks;
#  - a plug-in (examples/plugin_tea32, 32TEA(4) in C) draws the same ζ for every pair as the built-in tea32 4;
#  - newton_pair off on 2 ranks keeps the total momentum at round-off under pair-step and canonical seeding;
#  - bad input stops LAMMPS with a message naming the problem.
# Usage: tests/lammps/basic.sh LMP_DPDRNG DPDRNG_PREFIX (the dpdrng that lammps/build.sh installed, for the plug-in)
set -euo pipefail
cd "$(dirname "$0")/../.."
lmp=$(realpath "$1")
prefix=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
step() { echo "== lammps: $1 ($SECONDS s so far)" >&2; }
mpi() { mpirun --oversubscribe --allow-run-as-root "$@"; }

step "the example, 32TEA(1) distance halves, on 1 and 2 ranks (its defaults: 3 000 beads, 3 500 steps)"
for np in 1 2; do
  mpi -np "$np" "$lmp" -in lammps/examples/in.water -log "$work/water.$np" -screen none -var gen tea32 -var rounds 1 \
    -var seeding distance -var feed halves || { tail -20 "$work/water.$np" >&2; exit 1; }
  grep -Eq '^ *Step +Temp ' "$work/water.$np" || { echo "no thermo header in the $np-rank run" >&2; exit 1; }
  echo "in.water on $np rank(s): $(awk -v dt=0.04 -f tests/lammps/thermo_stats.awk "$work/water.$np")"
done

step "a plug-in through pair_style dpd/hash"
cmake -S examples/plugin_tea32 -B "$work/plugin" -DCMAKE_PREFIX_PATH="$prefix" -DTEA32_CYCLES=4 \
  >/dev/null
cmake --build "$work/plugin" >/dev/null
mpi -np 1 "$lmp" -in tests/lammps/in.config -log none -screen none -var N 1500 -var data "$work/config.data"
for gen in "ext:$work/plugin/libtea32.so 0" "tea32 4"; do
  read -r g r <<<"$gen"
  tag=${g%%:*}
  mpi -np 2 "$lmp" -in tests/lammps/in.zeta -log "$work/log.$tag" -screen none -var gen "$g" -var rounds "$r" \
    -var seeding canonical -var data "$work/config.data" -var zeta "$work/z.$tag" 2>/dev/null ||
    { tail -20 "$work/log.$tag" >&2; exit 1; }
  sort "$work"/z."$tag".* >"$work/all.$tag"
done
cmp "$work/all.ext" "$work/all.tea32"
echo "plug-in 32TEA(4) and built-in tea32 4: the same ζ for all $(wc -l <"$work/all.ext") pair evaluations"

step "momentum with newton_pair off on 2 ranks, 200 steps"
# Each owner of a boundary pair adds the force to its own atom: the total momentum stays at round-off only if
# both drew the same ζ. pair-step and canonical must; plain distance and LAMMPS's pair_style dpd are reported.
for g in "tea32 canonical" "tea32 pair-step" "tea32 distance" "ranmars -"; do
  read -r gen seeding <<<"$g"
  p=$(mpi -np 2 "$lmp" -in tests/lammps/in.momentum -log "$work/log.momentum" -screen none -var gen "$gen" \
    -var seeding "$seeding" -var data "$work/config.data" && awk '/^momentum_per_bead/ {print $2}' "$work/log.momentum")
  [[ -n $p ]] || { tail -20 "$work/log.momentum" >&2; exit 1; }
  echo "|total momentum| / bead after 200 steps, $gen $seeding: $p"
  if [[ $seeding == canonical || $seeding == pair-step ]]; then
    awk -v p="$p" 'BEGIN {exit !(p < 1e-12)}' || { echo "momentum not conserved with $gen $seeding" >&2; exit 1; }
  fi
done

step "bad input"
bad() {  # bad EXPECTED-TEXT PAIR-STYLE-ARGS...: LAMMPS must stop and say EXPECTED-TEXT
  local want=$1
  shift
  if "$lmp" -in tests/lammps/in.zeta -log "$work/log.bad" -screen none -var data "$work/config.data" \
      -var zeta "$work/zbad" "$@" \
      >/dev/null 2>&1; then
    echo "accepted: $*" >&2
    exit 1
  fi
  grep -q "$want" "$work/log.bad" || { echo "no '$want' for: $*" >&2; tail -5 "$work/log.bad" >&2; exit 1; }
  echo "refused ($want): $*"
}
bad "unknown generator" -var gen nosuch
bad "not a keyed hash" -var gen mt19937 -var rounds 0
bad "rounds 99 out of range" -var gen tea32 -var rounds 99
bad "unknown seeding .nearby. (known: pair-step, distance, canonical)" -var seeding nearby
bad "unknown seeding .counter." -var seeding counter
bad "unknown feed .pairs." -var feed pairs
bad "lag-1 defect" -var gen defect:lag1=0.2 -var rounds 0 -var seeding distance
bad "uniform noise takes one word" -var distribution uniform -var feed blocks
bad "plug-in .*nonexistent.so" -var gen "ext:$work/nonexistent.so" -var rounds 0

