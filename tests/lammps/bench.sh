#!/usr/bin/env bash
# Cost per step of pair_style dpd/hash against LAMMPS's pair_style dpd on the water scene
# (lammps/examples/in.water) at N beads on one rank: the styles alternate, `repeats` rounds, so that a load that
# comes and goes hits both alike. Prints each run's time per step (the whole step and LAMMPS's "Pair" share),
# then per variant the median ratio to pair_style dpd and the range of the ratios. Measures only: no verdict.
# Usage: tests/lammps/bench.sh LMP_DPDRNG [N] [steps] [repeats]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lmp=$(realpath "$1")
n=${2:-24000}
steps=${3:-500}
repeats=${4:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
variants=("ranmars 0 distance halves" "tea32 1 distance halves" "tea32 1 canonical halves"
          "tea32 1 pair-step halves" "tea32 8 distance halves" "philox4x32 10 pair-step halves")
declare -A ratios
for ((r = 1; r <= repeats; r++)); do
  declare -A pair_ms=()
  for v in "${variants[@]}"; do
    read -r gen rounds seeding feed <<<"$v"
    log=$work/log
    "$lmp" -in "$here/../../lammps/examples/in.water" -log "$log" -screen none -var gen "$gen" -var rounds "$rounds" \
      -var seeding "$seeding" -var feed "$feed" -var N "$n" -var nequil 50 -var nsteps "$steps" -var nblocks 1 \
      -var thermo_every "$steps"
    # The production run's timing: its loop time and the Pair row (min | avg | max | %varavg | %total).
    loop=$(awk '/^Loop time of/ {t = $4} END {print t}' "$log")
    pair=$(awk -F'|' '/^Pair +\|/ {t = $3} END {print t + 0}' "$log")
    step_ms=$(awk -v t="$loop" -v s="$steps" 'BEGIN {printf "%.4f", 1000 * t / s}')
    pair_ms[$v]=$(awk -v t="$pair" -v s="$steps" 'BEGIN {printf "%.4f", 1000 * t / s}')
    base=${pair_ms["ranmars 0 distance halves"]}
    ratio=$(awk -v a="${pair_ms[$v]}" -v b="$base" 'BEGIN {printf "%.3f", a / b}')
    echo "round $r  $v: $step_ms ms/step, pair ${pair_ms[$v]} ms/step, pair / pair_style dpd $ratio"
    ratios[$v]+="$ratio "
  done
done
for v in "${variants[@]:1}"; do
  printf '%s: pair time / pair_style dpd: ' "$v"
  tr ' ' '\n' <<<"${ratios[$v]}" | grep . | sort -g |
    awk '{x[NR] = $1} END {printf "median %.3f, range %.3f .. %.3f over %d rounds\n", x[int((NR + 1) / 2)], x[1], x[NR], NR}'
done
