#!/usr/bin/env bash
# Installs what sinsim needs from Debian packages (when missing), configures and builds into
# build/ (Release, with MPI). Safe to re-run: it only installs what is absent and rebuilds what
# changed.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config libeigen3-dev libgeographiclib-dev libyaml-cpp-dev
          catch2 libcli11-dev librandom123-dev libfftw3-dev nlohmann-json3-dev zlib1g-dev
          libbenchmark-dev libopenmpi-dev openmpi-bin
          pybind11-dev python3-dev python3-numpy)  # the Python module (docs/python.md)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# SINSIM_MPI: `sinsim mc` also runs under mpirun (runs split across ranks, same bytes).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSINSIM_MPI=ON >/dev/null
cmake --build build -j "$(nproc)"
