#!/usr/bin/env bash
# Installs the Debian packages dpdrng needs, only if some are missing (we run as root on a fresh machine).
# Optional groups, any of them: `fuzz` also installs what the libFuzzer harnesses need (clang, and libFuzzer
# itself, which Debian ships in libclang-rt-14-dev); `slurm` a single-node Slurm with munge, for
# tests/slurm/roundtrip.sh; `lammps` what lammps/build.sh needs to build LAMMPS from Debian's source package
# with pair_style dpd/hash (OpenMPI, ccache, dpkg-dev for `apt-get source`; jq for tests/lammps), and a deb-src entry for the
# distribution's main archive when apt has none.
set -euo pipefail
pkgs=(build-essential cmake ninja-build pkgconf libgsl-dev libfftw3-dev libeigen3-dev libhdf5-dev hdf5-tools
      libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev librandom123-dev
      libgmp-dev libmpfr-dev gnuplot-nox)
for group in "$@"; do
  case $group in
    fuzz) pkgs+=(clang libclang-rt-14-dev) ;;
    slurm) pkgs+=(slurm-wlm munge) ;;
    lammps) pkgs+=(dpkg-dev libopenmpi-dev openmpi-bin ccache jq) ;;
    *) echo "install-deps.sh: unknown group '$group' (known: fuzz, slurm, lammps)" >&2; exit 2 ;;
  esac
done
SUDO=""
[[ $(id -u) -eq 0 ]] || SUDO=sudo
need_update=0
if [[ " $* " == *" lammps "* ]] && ! grep -rqsE '^(deb-src|Types:.*deb-src)' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  # `apt-get source lammps` needs a source entry; Debian's images ship only binary ones.
  . /etc/os-release
  echo "install-deps.sh: adding deb-src for $VERSION_CODENAME (/etc/apt/sources.list.d/dpdrng-deb-src.sources)" >&2
  printf '%s\n' 'Types: deb-src' 'URIs: http://deb.debian.org/debian' "Suites: $VERSION_CODENAME $VERSION_CODENAME-updates" \
    'Components: main' 'Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg' |
    $SUDO tee /etc/apt/sources.list.d/dpdrng-deb-src.sources >/dev/null
  need_update=1
fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  ((need_update == 0)) || $SUDO apt-get update -qq
  exit 0
fi
echo "installing: ${missing[*]}" >&2
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
