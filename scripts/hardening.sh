#!/usr/bin/env bash
# Hardening check (CI, after scripts/test.sh): builds with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer (float-cast-overflow included, no recovery: any report fails) into
# build-hardening/; first the libFuzzer targets (tests/fuzz), each fuzzed for FUZZ_SECONDS (default
# 60) from the seed corpus of scripts/fuzz_seeds.sh, then the rest, and the whole ctest suite once
# under the sanitizers. A fuzz finding (crash, sanitizer report, leak, > 1 GB, > 10 s on one input,
# an exception other than sinsim::InputError) fails the script and leaves the input in
# build-hardening/fuzz/findings/.
# See docs/fuzzing.md.
#
# HARDENING_DEADLINE (epoch seconds, set by .ci/run to keep CI under its 20 minutes): a stage
# that would not finish before it is cut short and reported as "skipped (CI time budget)" with
# exit 0 — only a real finding turns CI red; the fuzz time per target shrinks to what is left.
#
# --suite: only the whole ctest suite under the sanitizers, built to run fast rather than to compile
# fast (build-sanitize/: -O2, Eigen's small functions always inlined, no fuzzing instrumentation;
# 2.7x quicker tests for 1.4x the compile time, docs/fuzzing.md). The check to run before a release
# or after touching memory-heavy code; it does not fit CI's 20 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
suite_only=0
if [ "${1:-}" = --suite ]; then suite_only=1; elif [ $# -gt 0 ]; then
  echo "usage: scripts/hardening.sh [--suite]" >&2; exit 2
fi
FUZZ_SECONDS=${FUZZ_SECONDS:-60}
# Seconds one input may take before it is a finding (docs/fuzzing.md: 10 s on a 64 KB input).
FUZZ_TIMEOUT=${FUZZ_TIMEOUT:-10}
build=build-hardening
deadline=${HARDENING_DEADLINE:-0}
left() { if ((deadline)); then echo $((deadline - $(date +%s))); else echo 999999; fi; }
# Runs "$@" with what is left of the budget minus $1 s kept for later stages; exit 0 and a note
# when the budget runs out (timeout's 124), the command's own status otherwise.
budgeted() {
  local keep=$1 stage=$2; shift 2
  local t=$(($(left) - keep))
  if ((t < 30)); then echo "hardening: $stage skipped (CI time budget)"; exit 0; fi
  local rc=0
  timeout "$t" "$@" || rc=$?
  if ((rc == 124)); then echo "hardening: $stage stopped after $t s (CI time budget)"; exit 0; fi
  return $rc
}

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
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
if ((suite_only)); then
  # The sanitizers' instrumentation makes Eigen's small functions too big for the inliner: forced
  # inline (EIGEN_STRONG_INLINE) and -O2 give the suite back most of its speed.
  build=build-sanitize
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2 -g1" \
    "-DCMAKE_CXX_FLAGS=-DEIGEN_STRONG_INLINE='inline __attribute__((always_inline))'" \
    -DCMAKE_CXX_COMPILER=clang++ -DSINSIM_UNITY=ON -DSINSIM_SANITIZE=ON -DSINSIM_FUZZ=OFF \
    -DSINSIM_MPI=OFF -DSINSIM_BUILD_BENCH=OFF -DSINSIM_PYTHON=OFF >/dev/null
  cmake --build "$build" -j "$(nproc)"
  echo "hardening: sanitizer build $(($(date +%s) - start)) s"
  t=$(date +%s)
  ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
  echo "hardening: test suite under ASan+UBSan $(($(date +%s) - t)) s"
  exit 0
fi
# -O1 -g1 with sanitizers: compiles much faster than -O3, runs far faster than -O0, and stack
# traces keep file:line.
# No MPI, no benchmarks and no Python module here (an ASan extension needs libasan preloaded into
# python3): the plain build tests those.
# SINSIM_UNITY: the libraries as unity units: UBSan's checks make every Eigen instantiation
# expensive, and a unit compiles each one once (docs/fuzzing.md has the numbers).
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1" \
  -DCMAKE_CXX_COMPILER=clang++ -DSINSIM_UNITY=ON \
  -DSINSIM_SANITIZE=ON -DSINSIM_FUZZ=ON -DSINSIM_MPI=OFF -DSINSIM_BUILD_BENCH=OFF -DSINSIM_PYTHON=OFF >/dev/null
# Fuzz targets first (the libraries and four small programs), so that the fuzzing always fits.
budgeted 60 "sanitizer build of the fuzz targets" \
  cmake --build "$build" -j "$(nproc)" --target fuzz_config fuzz_model fuzz_scenario fuzz_record
echo "hardening: sanitizer build of the fuzz targets $(($(date +%s) - start)) s"

fuzz=$build/fuzz
rm -rf "$fuzz/seeds"
scripts/fuzz_seeds.sh "$fuzz/seeds"
targets=(config model scenario record)
# One target per core at a time (2 cores: two pairs), each for FUZZ_SECONDS.
jobs=$(nproc)
fuzz_one() {  # target seconds -> 0, or 1 with the finding's log shown
  local target=$1 seconds=$2
  mkdir -p "$fuzz/corpus/$target" "$fuzz/findings/$target"
  # 64 KB inputs, 1 GB, FUZZ_TIMEOUT s per input: anything beyond is a finding (docs/fuzzing.md).
  if "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -max_len=65536 \
      -rss_limit_mb=1024 -timeout="$FUZZ_TIMEOUT" -print_final_stats=1 \
      -artifact_prefix="$fuzz/findings/$target/" \
      "$fuzz/corpus/$target" "$fuzz/seeds/$target" 2>"$fuzz/$target.log"; then
    echo "hardening: fuzz_$target ${seconds} s:" \
      "$(grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$fuzz/$target.log" | tr '\n' ' ')" \
      "corpus: $(ls "$fuzz/corpus/$target" | wc -l) inputs"
  else
    tail -n 60 "$fuzz/$target.log"; echo "hardening: FINDING in fuzz_$target"; return 1
  fi
}
rounds=$(( (${#targets[@]} + jobs - 1) / jobs ))
for ((r = 0; r < rounds; ++r)); do
  seconds=$(( ($(left) - 20) / (rounds - r) - 15 ))  # 15 s: start-up and seed replay
  ((seconds > FUZZ_SECONDS)) && seconds=$FUZZ_SECONDS
  round=("${targets[@]:r*jobs:jobs}")
  if ((seconds < 10)); then echo "hardening: fuzzing ${round[*]} skipped (CI time budget)"; continue; fi
  echo "hardening: fuzzing ${round[*]} for ${seconds} s each, side by side"
  pids=()
  for target in "${round[@]}"; do fuzz_one "$target" "$seconds" & pids+=($!); done
  failed=0
  for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
  if ((failed)); then exit 1; fi
done

# Then the rest (command line, tests) and the whole suite under the sanitizers.
t=$(date +%s)
budgeted 120 "sanitizer build of the tests" cmake --build "$build" -j "$(nproc)"
echo "hardening: sanitizer build of the tests $(($(date +%s) - t)) s"
t=$(date +%s)
# The suite's own budget: when it runs out, a test that failed before the cut still fails the
# script (the log is searched for ctest's failure markers); only an unfinished suite is let pass.
suite_budget=$(left)
if ((suite_budget < 30)); then echo "hardening: test suite skipped (CI time budget)"; exit 0; fi
rc=0
timeout "$suite_budget" ctest --test-dir "$build" --output-on-failure -j "$(nproc)" 2>&1 |
  tee "$build/suite.log" || rc=$?
if ((rc == 124)); then
  if grep -qE '\*\*\*(Failed|Exception|Timeout)|Subprocess aborted|SEGFAULT|Child aborted' "$build/suite.log"; then
    echo "hardening: test suite stopped after $suite_budget s (CI time budget) with failures before the cut"
    exit 1
  fi
  echo "hardening: test suite stopped after $suite_budget s (CI time budget), no failure before the cut"
  exit 0
fi
((rc == 0)) || exit "$rc"
echo "hardening: test suite under ASan+UBSan $(($(date +%s) - t)) s"
echo "hardening: done in $(($(date +%s) - start)) s"
