#!/usr/bin/env bash
# Hardening check (CI, after scripts/test.sh): builds everything with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer (float-cast-overflow included, no recovery: any report fails) into
# build-hardening/, runs the whole ctest suite once under them, then fuzzes each libFuzzer target
# (tests/fuzz) for FUZZ_SECONDS (default 60) from the seed corpus of scripts/fuzz_seeds.sh.
# A fuzz finding (crash, sanitizer report, leak, > 1 GB, > 10 s on one input, an exception other
# than sinsim::InputError) fails the script and leaves the input in build-hardening/fuzz/.
# See docs/fuzzing.md.
set -euo pipefail
cd "$(dirname "$0")/.."
FUZZ_SECONDS=${FUZZ_SECONDS:-60}
build=build-hardening

# clang with the libFuzzer runtime (Debian: clang + libclang-rt-dev of the same version), and the
# project's own packages (scripts/setup.sh lists them; installed there when CI ran test.sh first).
packages=(clang)
clang_version=$(clang --version 2>/dev/null | sed -n 's/.*clang version \([0-9]*\).*/\1/p' || true)
[ -n "$clang_version" ] && packages+=("libclang-rt-${clang_version}-dev")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "hardening: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
  if [ -z "$clang_version" ]; then  # clang came with this install: its runtime now
    clang_version=$(clang --version | sed -n 's/.*clang version \([0-9]*\).*/\1/p')
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq \
      "libclang-rt-${clang_version}-dev" >/dev/null
  fi
fi

start=$(date +%s)
# Release (-O3) with sanitizers: the suite runs at a fraction of its plain speed instead of -O0's.
# No MPI and no benchmarks here: the plain build tests those.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
  -DSINSIM_SANITIZE=ON -DSINSIM_FUZZ=ON -DSINSIM_MPI=OFF -DSINSIM_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j "$(nproc)"
echo "hardening: sanitizer build $(($(date +%s) - start)) s"

t=$(date +%s)
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
echo "hardening: test suite under ASan+UBSan $(($(date +%s) - t)) s"

fuzz=$build/fuzz
rm -rf "$fuzz/seeds"
scripts/fuzz_seeds.sh "$fuzz/seeds"
for target in config model scenario record; do
  mkdir -p "$fuzz/corpus/$target" "$fuzz/findings/$target"
  echo "hardening: fuzzing $target for ${FUZZ_SECONDS} s"
  # 64 KB inputs, 1 GB, 10 s per input: anything beyond is a finding (docs/fuzzing.md).
  "$build/tests/fuzz/fuzz_$target" -max_total_time="$FUZZ_SECONDS" -max_len=65536 \
    -rss_limit_mb=1024 -timeout=10 -print_final_stats=1 \
    -artifact_prefix="$fuzz/findings/$target/" \
    "$fuzz/corpus/$target" "$fuzz/seeds/$target" 2>"$fuzz/$target.log" ||
    { tail -n 60 "$fuzz/$target.log"; echo "hardening: FINDING in fuzz_$target"; exit 1; }
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$fuzz/$target.log" | tr '\n' ' '
  echo "corpus: $(ls "$fuzz/corpus/$target" | wc -l) inputs"
done
echo "hardening: done in $(($(date +%s) - start)) s"
