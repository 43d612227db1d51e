#!/usr/bin/env bash
# One LAMMPS check as a ctest entry (label lammps: ctest -L lammps): runs CHECK with the launcher LMP and ARGS.
# Without the launcher (lammps/build.sh builds it) the check reports itself skipped (77), unless
# DPDRNG_LAMMPS_REQUIRED=1 (tests/lammps/run.sh, which has just built it): then a missing launcher fails.
# Usage: tests/lammps/ctest.sh LMP CHECK ARGS...
set -euo pipefail
lmp=$1 check=$2
shift 2
if [[ ! -x $lmp ]]; then
  if [[ ${DPDRNG_LAMMPS_REQUIRED:-0} == 1 ]]; then
    echo "no LAMMPS launcher at $lmp" >&2
    exit 1
  fi
  echo "skipped: no LAMMPS launcher at $lmp (lammps/build.sh builds it)"
  exit 77
fi
exec "$check" "$lmp" "$@"
