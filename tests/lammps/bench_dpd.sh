#!/usr/bin/env bash
# dpdrng bench dpd beside a real LAMMPS (a small cells scene, one round, on 1 thread and on 2, LAMMPS with
# -sf omp; and the 256-bead all-pairs scene, on one): LAMMPS's pair_style dpd and dpd/hash report
# particle-steps/s, and every row its ratio to LAMMPS on its scene. Prints the figures; speeds are not judged (a small scene on a shared machine).
# Usage: tests/lammps/bench_dpd.sh LMP_DPDRNG DPDRNG
set -euo pipefail
lmp=$(realpath "$1")
dpdrng=$(realpath "$2")
for threads in 1 2; do
  out=$("$dpdrng" bench dpd --lammps "$lmp" --generators tea32 --rounds 1 --pairs all,cells --particles-cells 3000 \
    --steps-cells 20 --steps-all 200 --repeat 1 --no-scaling --threads "$threads" --json)
  jq -e '([.lammps, .lammps_all_pairs | .own_particle_steps_per_s > 0 and .hash_particle_steps_per_s > 0] | all)
         and ([.throughput[] | .dpdrng_over_lammps > 0] | all)' <<<"$out" >/dev/null ||
    { echo "bench_dpd.sh: no LAMMPS figures with $threads thread(s):" >&2; jq '.lammps, .lammps_all_pairs' <<<"$out" >&2
      exit 1; }
  jq -r '.lammps, .lammps_all_pairs | "\(.scene_label), \(.threads) thread(s), \(.scene.particles) beads: LAMMPS pair_style dpd \(.own_particle_steps_per_s | floor), dpd/hash \(.hash_particle_steps_per_s | floor), dpdrng \(.dpdrng_particle_steps_per_s | floor) particle-steps/s; dpdrng/LAMMPS \(.dpdrng_over_own)"' <<<"$out"
done
