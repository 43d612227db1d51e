#!/usr/bin/env bash
# LAMMPS with pair_style dpd/hash, checked: installs what is missing (./study/install-deps.sh lammps), builds
# lmp_dpdrng (lammps/build.sh; LAMMPS itself comes from the cache, or is built once, ≈ 15 min on 2 cores), then
#  - basic.sh: lammps/examples/in.water with 32TEA(1), distance seeding, halves feed on 1 and 2 MPI ranks; a
#    plug-in draws the built-in's ζ; momentum with newton_pair off; bad input refused with the reason;
#  - zeta.sh: ζ of every pair bit for bit on 1, 2 and 4 ranks, newton_pair on and off;
#  - omp.sh: dpd/hash/omp (`-sf omp`) on 1 and 2 OpenMP threads: the serial style's ζ, its forces (bit for bit on
#    one thread, to round-off on two), momentum conserved;
#  - physics.sh: T, P and D against dpdrng's engine, and 32TEA(1)'s temperature shift;
#  - bench_dpd.sh: dpdrng bench dpd beside LAMMPS (pair_style dpd and dpd/hash) on 1 and 2 threads.
# Needs build/release configured with the tests and built (./tests/run.sh). Any failure ends the script with a
# non-zero status.
set -euo pipefail
cd "$(dirname "$0")/../.."
step() { echo "== lammps: $1 ($SECONDS s so far)" >&2; }
./study/install-deps.sh lammps
step "build (lammps/build.sh)"
./lammps/build.sh >/dev/null
# The checks are ctest entries (label lammps, CMakeLists.txt), each a script of tests/lammps/; here the launcher
# was just built, so a check that finds none fails instead of reporting itself skipped.
step "the checks (ctest -L lammps)"
DPDRNG_LAMMPS_REQUIRED=1 ctest --test-dir build/release -L lammps --no-tests=error --output-on-failure -V
step "done"
