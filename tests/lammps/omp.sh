#!/usr/bin/env bash
# pair_style dpd/hash/omp (LAMMPS's OPENMP package, `-sf omp -pk omp T`) against the serial dpd/hash, one rank:
#  - lammps/examples/in.water runs with 2 threads;
#  - one force evaluation of one configuration (tests/lammps/in.zeta) under distance seeding (newton_pair on)
#    and pair-step seeding (newton_pair off): the same pairs with the same ζ, bit for bit, on 1 and 2 threads as
#    in the serial style, and on 1 thread the same forces bit for bit. On 2 threads the atoms whose force
#    differs from the serial force (two threads' partial sums added in another order) are counted and the
#    largest difference relative to the largest force is reported; above 1e-12 it fails;
#  - newton_pair off, 2 threads, 200 steps (tests/lammps/in.momentum): the total momentum stays at round-off
#    under canonical and pair-step seeding.
# Usage: tests/lammps/omp.sh LMP_DPDRNG [N]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lmp=$(realpath "$1")
n=${2:-3000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
run() {  # run NAME ARGS...: one rank; on failure, the run's log
  local name=$1
  shift
  "$lmp" -log "log.$name" -screen none "$@" || { tail -20 "log.$name" >&2; echo "omp.sh: run $name failed" >&2; exit 1; }
}
fail=0

run water -in "$here/../../lammps/examples/in.water" -sf omp -pk omp 2 -var N "$n" -var nequil 100 -var nsteps 400 \
  -var nblocks 2 -var gen tea32 -var rounds 1 -var seeding distance -var feed halves
grep -q 'dpd/hash/omp' log.water || { echo "omp.sh: in.water did not run dpd/hash/omp" >&2; exit 1; }
grep -Eq '^ *Step +Temp ' log.water || { echo "omp.sh: no thermo header in the omp run of in.water" >&2; exit 1; }
echo "in.water, dpd/hash/omp, 2 threads: $(awk -v dt=0.04 -f "$here/thermo_stats.awk" log.water)"

run config -in "$here/in.config" -var N "$n" -var data config.data
for case in "distance on" "pair-step off"; do
  read -r seeding newton <<<"$case"
  common=(-in "$here/in.zeta" -var seeding "$seeding" -var newton "$newton" -var data config.data)
  run "serial.$seeding" "${common[@]}" -var zeta "z.serial" -var forces fserial
  sort z.serial.0 >zs
  for t in 1 2; do
    run "omp$t.$seeding" "${common[@]}" -sf omp -pk omp "$t" -var zeta "z.omp$t" -var forces "fomp$t"
    grep -q 'dpd/hash/omp' "log.omp$t.$seeding" || { echo "omp.sh: the omp run used another style" >&2; exit 1; }
    sort "z.omp$t.0" >zo
    if cmp -s zs zo; then
      echo "$seeding seeding, newton_pair $newton, $t thread(s): ζ of all $(wc -l <zs) pair evaluations as in the serial style"
    else
      echo "omp.sh: $seeding seeding, $t thread(s): ζ differs from the serial style's" >&2
      fail=1
    fi
    # The dump's per-atom lines (after ITEM: ATOMS): id fx fy fz, exact.
    counts=$(awk -f "$here/force_compare.awk" fserial "fomp$t")
    read -r _ atoms _ differ _ rel <<<"$counts"
    echo "$seeding seeding, newton_pair $newton, $t thread(s): forces of $differ of $atoms atoms differ from the" \
      "serial style's; largest difference / largest force: $rel"
    ((atoms > 0)) || { echo "omp.sh: no forces compared" >&2; fail=1; }
    if ((t == 1 && differ > 0)); then echo "omp.sh: one thread must give the serial forces bit for bit" >&2; fail=1; fi
    awk -v r="$rel" 'BEGIN {exit !(r <= 1e-12)}' || { echo "omp.sh: forces beyond round-off" >&2; fail=1; }
  done
done

for seeding in canonical pair-step; do
  run "momentum.$seeding" -in "$here/in.momentum" -sf omp -pk omp 2 -var gen tea32 -var seeding "$seeding" \
    -var data config.data
  p=$(awk '/^momentum_per_bead/ {print $2}' "log.momentum.$seeding")
  echo "|total momentum| / bead after 200 steps, newton_pair off, dpd/hash/omp on 2 threads, $seeding: $p"
  awk -v p="$p" 'BEGIN {exit !(p != "" && p < 1e-12)}' || { echo "omp.sh: momentum not conserved" >&2; fail=1; }
done
((fail == 0)) || { echo "omp.sh: FAILED" >&2; exit 1; }
echo "omp.sh: dpd/hash/omp draws the serial style's ζ on 1 and 2 threads and conserves momentum"
