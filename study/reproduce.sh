#!/usr/bin/env bash
# The README's main command: from a fresh machine to results/.
#   ./study/reproduce.sh [CONFIG]     (default: study/okada2021.toml)
# Installs missing Debian packages, builds the release binary, runs the study (resuming if results/<name>
# already holds finished cells of the same config) and writes results/<name>/report/report.md.
# DPDRNG_THREADS sets the cells run side by side (default: all cores).
set -euo pipefail
cd "$(dirname "$0")/.."
./study/install-deps.sh
cmake --preset release -DDPDRNG_BUILD_TESTS=OFF >/dev/null
cmake --build --preset release -j "$(nproc)" --target dpdrng
config=${1:-study/okada2021.toml}
name=$(sed -n 's/^name *= *"\(.*\)"/\1/p' "$config" | head -n 1)
name=${name:-$(basename "$config" .toml)}
threads=${DPDRNG_THREADS:-$(nproc)}
start=$(date +%s)
./build/release/dpdrng study run "$config" --out "results/$name" --threads "$threads"
./build/release/dpdrng study report "results/$name"
echo "study $name: $(($(date +%s) - start)) s; report: results/$name/report/report.md" >&2
