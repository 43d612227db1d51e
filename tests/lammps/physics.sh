#!/usr/bin/env bash
# The water scene (lammps/examples/in.water) in LAMMPS with pair_style dpd/hash against dpdrng's own engine:
#  1. an MT-equivalent generator (32TEA(8), halves feed; canonical seeding in LAMMPS on 2 ranks, distance seeding
#     in dpdrng, which is the same input undecomposed): k_BT, P and D agree, each within the 99.9 % CI of the
#     difference (Welch; LAMMPS's errors from its production blocks, dpdrng's from its own error model, D's a
#     jackknife over 20 groups of beads: 19 degrees of freedom);
#  2. 32TEA(1) under the halves feed against LAMMPS's own pair_style dpd (the force of Groot & Warren 1997 as the
#     LAMMPS documentation of pair_style dpd states it, Marsaglia's generator, one stream per rank) at the same
#     settings: the k_BT shift's 95 % CI excludes 0 and overlaps the CI of the shift that
#     dpdrng's engine measures for 32TEA(1) against MT19937 at the same size (its ≈ −3.5 %).
# A failure prints the numbers. Usage: tests/lammps/physics.sh LMP_DPDRNG DPDRNG [N]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lmp=$(realpath "$1")
dpdrng=$(realpath "$2")
n=${3:-3000}
water=$here/../../lammps/examples/in.water
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
lammps() {  # lammps NAME NP ARGS...: runs in.water, prints "blocks B T mean se P mean se D mean se"
  local name=$1 np=$2
  shift 2
  mpirun --oversubscribe --allow-run-as-root -np "$np" "$lmp" -in "$water" -log "$work/log.$name" -screen none \
    -var N "$n" "$@" || { tail -20 "$work/log.$name" >&2; echo "physics.sh: LAMMPS run $name failed" >&2; exit 1; }
  awk -v dt=0.04 -f "$here/thermo_stats.awk" "$work/log.$name"
}
engine() {  # engine NAME ARGS...: dpdrng simulate --json into $work/NAME.json
  local name=$1
  shift
  "$dpdrng" simulate -n "$n" --pairs cells --json -q "$@" >"$work/$name.json"
}
field() { jq -r "$2" "$work/$1.json"; }

# 1. The same physics: 500 equilibration steps, 6 000 production steps in 12 blocks of 500 (20 τ, D's fit from 2 τ).
read -r _ blocks _ lt lts _ lp lps _ ld lds < <(lammps tea8 2 -var gen tea32 -var rounds 8 -var seeding canonical \
  -var feed halves -var nequil 500 -var nsteps 6000 -var nblocks 12 -var thermo_every 10)
engine tea8 -g tea32 -r 8 --seeding distance --feed halves --equilibrate 500 --steps 6500
dof=$((blocks - 1))
while read -r name d se ndof low high; do
  verdict=agree
  awk -v l="$low" -v h="$high" 'BEGIN {exit !(l <= 0 && 0 <= h)}' || { verdict=DIFFER; fail=1; }
  echo "32TEA(8) $name, LAMMPS − dpdrng: $d ± $se [$low, $high] (99.9 %, $ndof dof): $verdict"
done < <(printf '%s\n' \
  "k_BT $lt $lts $dof $(field tea8 .temperature.mean) $(field tea8 .temperature.sem) $(field tea8 .temperature.sem_dof) 0.999" \
  "P $lp $lps $dof $(field tea8 .pressure.mean) $(field tea8 .pressure.sem) $(field tea8 .pressure.sem_dof) 0.999" \
  "D $ld $lds $dof $(field tea8 .diffusion_coefficient) $(field tea8 .diffusion_coefficient_sem) 19 0.999" |
  awk -f "$here/stats.awk")
echo "LAMMPS 32TEA(8): k_BT $lt ± $lts, P $lp ± $lps, D $ld ± $lds; dpdrng: k_BT $(field tea8 .temperature.mean)" \
  "± $(field tea8 .temperature.sem), P $(field tea8 .pressure.mean) ± $(field tea8 .pressure.sem)," \
  "D $(field tea8 .diffusion_coefficient) ± $(field tea8 .diffusion_coefficient_sem)"

# 2. 32TEA(1), halves: its shift against the reference in LAMMPS and in dpdrng, 3 000 production steps each.
read -r _ blocks _ t1 t1s _ < <(lammps tea1 2 -var gen tea32 -var rounds 1 -var seeding distance -var feed halves \
  -var nequil 500 -var nsteps 3000 -var nblocks 6)
read -r _ blocks _ tr trs _ < <(lammps ranmars 2 -var gen ranmars -var nequil 500 -var nsteps 3000 -var nblocks 6)
engine tea1 -g tea32 -r 1 --feed halves --equilibrate 500 --steps 3500 --compare mt19937
dof=$((blocks - 1))
read -r _ d se ndof low high < <(echo "k_BT $t1 $t1s $dof $tr $trs $dof 0.95" | awk -f "$here/stats.awk")
# dpdrng's --compare document: the shift of each observable against the reference, with its 95 % CI.
shift_sel='.shifts[] | select(.observable == "k_BT (kinetic)") | .shift'
elow=$(field tea1 "$shift_sel.ci95[0]")
ehigh=$(field tea1 "$shift_sel.ci95[1]")
echo "32TEA(1) halves, k_BT: LAMMPS $t1 ± $t1s, pair_style dpd $tr ± $trs; shift $d [$low, $high] (95 %, $ndof dof);" \
  "dpdrng's engine against MT19937: $(field tea1 "$shift_sel.mean") [$elow, $ehigh]"
awk -v l="$low" -v h="$high" 'BEGIN {exit !(h < 0 || l > 0)}' ||
  { echo "physics.sh: the 32TEA(1) shift in LAMMPS is not distinguishable from 0" >&2; fail=1; }
awk -v l="$low" -v h="$high" -v a="$elow" -v b="$ehigh" 'BEGIN {exit !(l <= b && a <= h)}' ||
  { echo "physics.sh: the 32TEA(1) shift in LAMMPS and in dpdrng's engine differ" >&2; fail=1; }
((fail == 0)) || { echo "physics.sh: FAILED" >&2; exit 1; }
echo "physics.sh: LAMMPS with pair_style dpd/hash agrees with dpdrng's engine"
