#!/usr/bin/env bash
# Installs the Debian packages dpdrng needs, only if some are missing (we run as root on a fresh machine).
# Optional groups, any of them: `fuzz` also installs what the libFuzzer harnesses need (clang, and libFuzzer
# itself, which Debian ships in libclang-rt-14-dev); `slurm` a single-node Slurm with munge, for
# tests/slurm/roundtrip.sh.
set -euo pipefail
pkgs=(build-essential cmake ninja-build pkgconf libgsl-dev libfftw3-dev libeigen3-dev libhdf5-dev hdf5-tools
      libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev librandom123-dev
      libgmp-dev libmpfr-dev gnuplot-nox)
for group in "$@"; do
  case $group in
    fuzz) pkgs+=(clang libclang-rt-14-dev) ;;
    slurm) pkgs+=(slurm-wlm munge) ;;
    *) echo "install-deps.sh: unknown group '$group' (known: fuzz, slurm)" >&2; exit 2 ;;
  esac
done
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
((${#missing[@]} == 0)) && exit 0
echo "installing: ${missing[*]}" >&2
SUDO=""
[[ $(id -u) -eq 0 ]] || SUDO=sudo
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
