#!/usr/bin/env bash
# Reproduces the README's speed figures: every Google Benchmark in bench/ plus the timed commands
# (sinsim fit and sinsim diagnose on the real ADIS16405 record). Run on a quiet machine after
# scripts/setup.sh; results go to build/bench-results/ and a summary to the terminal.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/bench-results
mkdir -p "$out"
data=../shared/data/adis16405/run1.csv.gz
units=(--rate 100 --gyro-unit deg/s --accel-unit g)

for b in nav sim errormodels stats fit mc; do
  echo "== bench_$b"
  build/bench/bench_$b --benchmark_out="$out/bench_$b.json" --benchmark_out_format=json \
    | tee "$out/bench_$b.txt" | grep -E "^BM_|^-|^Benchmark"
done

if [ -f "$data" ]; then
  echo "== sinsim fit (1 M x 6, gzip)"
  /usr/bin/time -f "fit: %e s wall, %U s user CPU, %M kB max RSS" \
    build/sinsim fit "$data" "${units[@]}" --skip "10 min" -o "$out/run1.yaml" -q
  echo "== sinsim diagnose (1 M x 6, 32 Monte Carlo realisations, 2 threads)"
  build/sinsim fit "$data" "${units[@]}" --kind ar --order 5 --lines warn -o "$out/ar5.yaml" -q
  /usr/bin/time -f "diagnose: %e s wall, %U s user CPU, %M kB max RSS" \
    build/sinsim diagnose "$data" "${units[@]}" --model "$out/ar5.yaml" --threads 2 \
      --json "$out/diagnose.json" >/dev/null
fi
