#!/usr/bin/env bash
# Installs the Debian packages thinlayer needs (only those missing), then configures and
# builds the command line (build/thinlayer, Release) — all the main job runs; scripts/test.sh builds
# the rest (the tests, the benchmark drivers). Safe to run again: it does only what is left to do.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ make ninja-build libeigen3-dev libsuitesparse-dev libblas-dev libgmsh-dev libhdf5-dev
          libsiconos-numerics-dev libgtest-dev libbenchmark-dev python3-matplotlib python3-h5py
          libcli11-dev nlohmann-json3-dev libopenmpi-dev openmpi-bin libseccomp-dev libglpk-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Ninja on a new build folder: a library's files may start before the library they use is archived,
# where Make waits at the end of each library with a core idle. A folder configured before keeps its
# generator.
generator=()
[ -f build/CMakeCache.txt ] || generator=(-G Ninja)
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" --target thinlayer
