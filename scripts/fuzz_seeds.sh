#!/usr/bin/env bash
# Builds the seed corpora of the fuzz targets (tests/fuzz) from the repository's own inputs:
#   scenario: scenarios/*.yaml (the presets' `errors:` paths stay relative) and tests/sim/fixtures
#   model:    the sensor presets and grades in scenarios/, plus tests/fuzz/seeds/model
#   config:   every YAML above, plus tests/fuzz/seeds/config (regressions)
#   record:   tests/fuzz/seeds/record and the first 200 lines of the ADIS16405 record when
#             ../shared/data is there (option byte 0x01 prepended: rate given, 100 Hz)
# Usage: scripts/fuzz_seeds.sh OUTDIR   (creates OUTDIR/{config,model,scenario,record})
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: scripts/fuzz_seeds.sh OUTDIR}
mkdir -p "$out"/{config,model,scenario,record}

for f in scenarios/*.yaml tests/sim/fixtures/*.yaml; do
  if grep -q '^segments:' "$f"; then cp "$f" "$out/scenario/"; fi
  if grep -q '^gyro:\|^accel:' "$f"; then cp "$f" "$out/model/"; fi
  cp "$f" "$out/config/"
done
cp tests/fuzz/seeds/model/* "$out/model/"
cp tests/fuzz/seeds/scenario/* "$out/scenario/"
cp tests/fuzz/seeds/model/* tests/fuzz/seeds/scenario/* tests/fuzz/seeds/config/* "$out/config/"
# The first byte of a record input selects the options (tests/fuzz/fuzz_record.cpp).
for f in tests/fuzz/seeds/record/*; do
  { printf '\x04'; cat "$f"; } > "$out/record/$(basename "$f")"
done
adis=../shared/data/adis16405/run1.csv.gz
if [ -r "$adis" ]; then
  { printf '\x0b'; zcat "$adis" | head -n 200 || true; } > "$out/record/adis16405-head.csv"
fi
