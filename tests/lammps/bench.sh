#!/usr/bin/env bash
# Cost per step of pair_style dpd/hash against LAMMPS's pair_style dpd on the water scene
# (lammps/examples/in.water) at N beads on one rank: the styles alternate, `repeats` rounds, so that a load that
# comes and goes hits both alike. Prints each run's time per step (the whole step and LAMMPS's "Pair" share),
# then per variant the median ratio to pair_style dpd and the range of the ratios. Measures only: no verdict.
# Times are CPU times (LAMMPS's `timer full`: a section's wall time × its CPU share), which a machine shared with
# other jobs distorts less than wall times.
# Usage: tests/lammps/bench.sh LMP_DPDRNG [N] [steps] [repeats]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lmp=$(realpath "$1")
n=${2:-24000}
steps=${3:-500}
repeats=${4:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# 32TEA(1) under pair-step seeding is left out: its ζ barely changes from step to step, the fluid freezes
# (k_BT ≈ 0.0005, in dpdrng's engine as in LAMMPS) and its neighbour lists stop changing: no comparable cost.
variants=("ranmars 0 distance halves" "tea32 1 distance halves" "tea32 1 canonical halves"
          "tea32 8 pair-step halves" "philox4x32 10 pair-step halves")
declare -A ratios step_ratios
printf 'timer full\ninclude %s\n' "$here/../../lammps/examples/in.water" >"$work/in.bench"
for ((r = 1; r <= repeats; r++)); do
  declare -A pair_ms=() all_ms=()
  for v in "${variants[@]}"; do
    read -r gen rounds seeding feed <<<"$v"
    log=$work/log
    "$lmp" -in "$work/in.bench" -log "$log" -screen none -var gen "$gen" -var rounds "$rounds" \
      -var seeding "$seeding" -var feed "$feed" -var N "$n" -var nequil 50 -var nsteps "$steps" -var nblocks 1 \
      -var thermo_every "$steps"
    # The production run's timing: its loop time × the CPU share of the run, and the Pair row's average time ×
    # its CPU share (min | avg | max | %varavg | %CPU | %total).
    loop=$(awk '/^Loop time of/ {t = $4} /% CPU use with/ {c = $1} END {print t * c / 100}' "$log")
    pair=$(awk -F'|' '/^Pair +\|/ {t = $3 * $6 / 100} END {print t + 0}' "$log")
    step_ms=$(awk -v t="$loop" -v s="$steps" 'BEGIN {printf "%.4f", 1000 * t / s}')
    pair_ms[$v]=$(awk -v t="$pair" -v s="$steps" 'BEGIN {printf "%.4f", 1000 * t / s}')
    all_ms[$v]=$step_ms
    ratio=$(awk -v a="${pair_ms[$v]}" -v b="${pair_ms["ranmars 0 distance halves"]}" 'BEGIN {printf "%.3f", a / b}')
    sratio=$(awk -v a="$step_ms" -v b="${all_ms["ranmars 0 distance halves"]}" 'BEGIN {printf "%.3f", a / b}')
    echo "round $r  $v: step $step_ms ms, pair ${pair_ms[$v]} ms; / pair_style dpd: step $sratio, pair $ratio"
    ratios[$v]+="$ratio "
    step_ratios[$v]+="$sratio "
  done
done
summary() { tr ' ' '\n' <<<"$1" | grep . | sort -g |
  awk '{x[NR] = $1} END {printf "median %.3f (%.3f .. %.3f)", x[int((NR + 1) / 2)], x[1], x[NR]}'; }
for v in "${variants[@]:1}"; do
  echo "$v / pair_style dpd over $repeats rounds: step $(summary "${step_ratios[$v]}"), pair $(summary "${ratios[$v]}")"
done
