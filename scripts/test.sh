#!/usr/bin/env bash
# Builds (via setup.sh) and runs every test with ctest. Test-only dependencies (headless Chromium
# and python3 for the report-rendering tests, pytest and matplotlib for the Python module's tests
# and example) are installed here when missing, so that those tests run rather than silently drop
# out.
set -euo pipefail
cd "$(dirname "$0")/.."

test_packages=(chromium python3 python3-pytest python3-matplotlib python3-numpy python3-scipy)  # + the Python module's tests, the diagnosis challenge slice
missing=()
for p in "${test_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "test: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq \
    "${missing[@]}" >/dev/null
fi

scripts/setup.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
