#!/usr/bin/env bash
# The README's main command: from a fresh machine to results/.
#   ./study/reproduce.sh [CONFIG]     (default: study/okada2021.toml)
set -euo pipefail
cd "$(dirname "$0")/.."
./study/install-deps.sh
cmake --preset release -DDPDRNG_BUILD_TESTS=OFF >/dev/null
cmake --build --preset release -j "$(nproc)" --target dpdrng
config=${1:-study/okada2021.toml}
name=$(basename "$config" .toml)
./build/release/dpdrng study run "$config" --out "results/$name"
./build/release/dpdrng study report "results/$name"
