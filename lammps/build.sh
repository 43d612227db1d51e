#!/usr/bin/env bash
# Builds lmp_dpdrng into build/lammps/: LAMMPS from Debian's source package (a static liblammps with MPI, OpenMP,
# DPD-BASIC and OPENMP, nothing else) plus pair_style dpd/hash and dpd/hash/omp (lammps/src/), linked against the
# dpdrng installed from build/release. The LAMMPS library is kept outside the clone, in
# ${DPDRNG_LAMMPS_CACHE:-/var/cache/dpdrng/lammps}, in a folder named by the Debian source version and a hash of
# everything that shapes it (the configure options, the compiler, the MPI); a second run finds it and only compiles our
# style and the launcher (seconds).
# Needs: ./study/install-deps.sh lammps (OpenMPI, dpkg-dev, a deb-src entry) and a configured build/release.
# Prints the launcher's path on its last line. DPDRNG_JOBS sets the build's parallelism (default: nproc);
# DPDRNG_LAMMPS_STYLE_FLAGS adds compiler flags for the style alone, e.g. -march=x86-64-v3: dpdrng's one-word
# Box–Muller calls fmaf, a library call on the x86-64 baseline and one instruction with FMA (the ζ are the same
# bit for bit either way; docs/lammps.md has the cost of both).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
cache=${DPDRNG_LAMMPS_CACHE:-/var/cache/dpdrng/lammps}
jobs=${DPDRNG_JOBS:-$(nproc)}
say() { echo "lammps/build.sh: $*" >&2; }

# apt-cache fails without a deb-src entry; the message below says what to run then.
version=$( { apt-cache showsrc lammps 2>/dev/null || true; } | sed -n 's/^Version: //p' | sort -V | tail -1)
[[ -n $version ]] || { say "apt knows no source package 'lammps' (run ./study/install-deps.sh lammps)"; exit 1; }
# Everything that changes the library's objects or its ABI goes into the key. -O2 as in Debian's own build;
# lmp_dpdrng compiles our style with the same flags so that the cost comparison with pair_style dpd is fair.
opt_flags="-O2 -DNDEBUG"
lmp_options=(-D CMAKE_BUILD_TYPE=Release "-D CMAKE_CXX_FLAGS_RELEASE=$opt_flags" -D BUILD_MPI=on -D BUILD_OMP=on
             -D BUILD_SHARED_LIBS=off -D LAMMPS_SIZES=smallbig -D LAMMPS_EXCEPTIONS=off -D PKG_DPD-BASIC=on
             -D PKG_OPENMP=on -D WITH_JPEG=off -D WITH_PNG=off -D WITH_GZIP=off -D WITH_FFMPEG=off
             -D BUILD_TOOLS=off -D BUILD_DOC=off -D ENABLE_TESTING=off)
key=$( { echo "$version"; printf '%s\n' "${lmp_options[@]}"; c++ --version | head -1; mpicxx --showme:version 2>&1 || true; } |
       sha256sum | cut -c1-16)
dir="$cache/${version//[^A-Za-z0-9.+-]/_}-$key"

mkdir -p "$cache"
# One build at a time per cache (two clones on one machine share it); the lock goes with this process.
exec 9>"$cache/.lock"
flock 9
if [[ ! -f $dir/complete ]]; then
  say "no cached LAMMPS in $dir: building it (about 6 CPU-minutes)"
  rm -rf "$dir"
  mkdir -p "$dir/download"
  (cd "$dir/download" && apt-get source --download-only -qq "lammps=$version" >/dev/null 2>&1) ||
    { say "apt-get source lammps=$version failed"; exit 1; }
  # apt checked the files against the archive's signed index; dpkg-source's own signature check needs a keyring
  # Debian does not install, and only warns.
  dpkg-source -x "$dir"/download/*.dsc "$dir/source" >/dev/null 2>&1 ||
    { say "dpkg-source -x failed on $(ls "$dir"/download/*.dsc)"; exit 1; }
  # Only cmake/ and src/ take part in this build; the rest (docs, examples, potentials) is 300 MB.
  find "$dir/source" -mindepth 1 -maxdepth 1 ! -name cmake ! -name src ! -name LICENSE -exec rm -rf {} +
  rm -rf "$dir/download" "$dir"/*.orig.tar.*
  launcher=()
  command -v ccache >/dev/null && launcher=(-D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D CMAKE_C_COMPILER_LAUNCHER=ccache)
  cmake -S "$dir/source/cmake" -B "$dir/build" -G Ninja "${lmp_options[@]}" "${launcher[@]}" >"$dir/configure.log"
  # The library and LAMMPS's own launcher `lmp` (one file more); the reference runs use lmp_dpdrng all the same.
  CCACHE_BASEDIR=$dir nice cmake --build "$dir/build" -j "$jobs" --target lmp >"$dir/build.log" ||
    { tail -30 "$dir/build.log" >&2; say "LAMMPS build failed (log: $dir/build.log)"; exit 1; }
  touch "$dir/complete"
else
  say "cached LAMMPS: $dir"
fi

# Our side: dpdrng installed from build/release into a prefix of its own (the consumer's view, through
# find_package(dpdrng)), then the style and the launcher against it and the cached library.
[[ -f build/release/build.ninja ]] || { say "build/release is not configured (cmake --preset release)"; exit 1; }
out=$root/build/lammps
mkdir -p "$out"
cmake --build build/release -j "$jobs" >"$out/release-build.log" ||
  { tail -30 "$out/release-build.log" >&2; say "the build of build/release failed"; exit 1; }
cmake --install build/release --prefix "$out/dpdrng" >/dev/null
cmake -S lammps -B "$out/build" -G Ninja -D CMAKE_BUILD_TYPE=Release "-D CMAKE_CXX_FLAGS_RELEASE=$opt_flags" \
  "-D CMAKE_CXX_FLAGS=${DPDRNG_LAMMPS_STYLE_FLAGS:-}" \
  -D LAMMPS_DIR="$dir" -D CMAKE_PREFIX_PATH="$out/dpdrng" >"$out/configure.log" ||
  { cat "$out/configure.log" >&2; exit 1; }
cmake --build "$out/build" -j "$jobs" >&2
ln -sf build/lmp_dpdrng "$out/lmp_dpdrng"
echo "$out/lmp_dpdrng"
