#!/usr/bin/env bash
# The README's test command: installs what is missing (Debian packages), builds, runs the test suite, and builds
# and runs examples/pair_force and the example plug-ins (examples/plugin_*) against the package installed into a
# temporary prefix.
# DPDRNG_SANITIZE=1 also builds and runs the whole suite under AddressSanitizer + UBSan, and DPDRNG_PORTABLE=1
# builds the portable preset's dpdrng and checks its results bit for bit against the release build's
# (tests/portable.sh; x86-64 only). .ci/run sets both. Any failure in a build, a ctest run or the check ends the
# script with a non-zero status.
set -euo pipefail
cd "$(dirname "$0")/.."
./study/install-deps.sh
jobs=$(nproc)
step() { echo "== $1 ($SECONDS s so far)" >&2; }
step "release build"
# Explicitly on: ./study/reproduce.sh configures the same build directory without the tests.
cmake --preset release -DDPDRNG_BUILD_TESTS=ON >/dev/null
cmake --build --preset release -j "$jobs"
step "release tests"
ctest --preset release -j "$jobs" --no-tests=error
if [[ "${DPDRNG_PORTABLE:-0}" == 1 && "$(uname -m)" == x86_64 ]]; then
  step "portable build (x86-64-v3), results bit for bit against the release build"
  DPDRNG_JOBS=$jobs ./tests/portable.sh
fi
step "install, and the example consumer built against it"
# A throw-away prefix: examples/pair_force finds the package there through find_package(dpdrng).
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install build/release --prefix "$prefix/install" >/dev/null
cmake -S examples/pair_force -B "$prefix/build" -DCMAKE_PREFIX_PATH="$prefix/install" >/dev/null
cmake --build "$prefix/build" -j "$jobs"
"$prefix/build/pair_force"
step "the example plug-ins built against it, run by the installed dpdrng"
# examples/plugin_tea32 (32TEA(4) in plain C) gives the built-in's stream bit for bit; examples/plugin_fmix64
# (two words a block) runs a short simulation.
cmake -S examples/plugin_tea32 -B "$prefix/tea32" -DCMAKE_PREFIX_PATH="$prefix/install" -DTEA32_CYCLES=4 >/dev/null
cmake --build "$prefix/tea32" -j "$jobs"
cmake -S examples/plugin_fmix64 -B "$prefix/fmix64" -DCMAKE_PREFIX_PATH="$prefix/install" >/dev/null
cmake --build "$prefix/fmix64" -j "$jobs"
installed="$prefix/install/bin/dpdrng"
cmp <("$installed" gen -g "ext:$prefix/tea32/libtea32.so" --count 100000 --format raw) \
    <("$installed" gen -g tea32 -r 4 --count 100000 --format raw)
"$installed" simulate -g "ext:$prefix/fmix64/libfmix64.so" -n 256 --steps 200 --equilibrate 50 -q >/dev/null
# A two-cell study of the plug-in (its variant and the MT19937 reference), pinned by its digest.
digest=$(sha256sum "$prefix/tea32/libtea32.so" | cut -d' ' -f1)
printf '%s\n' '[study]' 'name = "plugin"' 'replicas = 1' '[sweep]' 'distributions = ["gauss"]' '[[sweep.generator]]' \
  "name = \"ext:$prefix/tea32/libtea32.so\"" "sha256 = \"$digest\"" '[scene]' 'particles = 32' 'steps = 100' \
  'equilibrate = 10' '[tests]' 'ttest_pairs = 4' 'chi2_steps = 4' 'nist_generators = []' >"$prefix/plugin.toml"
"$installed" study run "$prefix/plugin.toml" --out "$prefix/plugin-study" >/dev/null
[[ $(ls "$prefix/plugin-study/cells" | wc -l) == 2 ]]
if [[ "${DPDRNG_SANITIZE:-0}" == 1 ]]; then
  step "ASan+UBSan build"
  cmake --preset asan -DDPDRNG_BUILD_TESTS=ON >/dev/null
  cmake --build --preset asan -j "$jobs"
  step "ASan+UBSan tests"
  ctest --preset asan -j "$jobs" --no-tests=error
fi
step "done"
