#!/usr/bin/env bash
# The README's test command: installs what is missing (Debian packages), builds, and runs the test suite.
# DPDRNG_SANITIZE=1 also builds and runs the suite under AddressSanitizer + UBSan (CI does).
set -euo pipefail
cd "$(dirname "$0")/.."
./study/install-deps.sh
jobs=$(nproc)
cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs"
ctest --preset release -j "$jobs"
if [[ "${DPDRNG_SANITIZE:-0}" == 1 ]]; then
  cmake --preset asan >/dev/null
  cmake --build --preset asan -j "$jobs"
  ctest --preset asan -j "$jobs"
fi
