#!/bin/sh
# Reproduces the ADIS16405 numbers of the README "Identify" section (data not in the repo:
# ../shared/data/adis16405, SMAC-Group imudata, CC BY-NC-SA 4.0). Run from the repository root
# after building (scripts/setup.sh)
set -e
DATA=${DATA:-../shared/data/adis16405}
OUT=${OUT:-out/adis16405}
mkdir -p "$OUT"
for run in 1 2; do
  /usr/bin/time -f "fit run $run: %e s wall, %M kB" \
    build/sinsim fit "$DATA/run$run.csv.gz" --rate 100 --gyro-unit deg/s --accel-unit g \
      --skip "10 min" -o "$OUT/run$run.yaml"
done
# Without the warm-up skip, for comparison:
build/sinsim fit "$DATA/run1.csv.gz" --rate 100 --gyro-unit deg/s --accel-unit g -o "$OUT/run1-noskip.yaml"
# Paper-style: db5 denoising before the ACF (AR still fitted on raw data; the denoised AR is a comment):
build/sinsim fit "$DATA/run1.csv.gz" --rate 100 --gyro-unit deg/s --accel-unit g --skip "10 min" \
  --denoise db5 --kind ar --order 5 -o "$OUT/run1-db5-ar5.yaml"
# Run-1 model vs run-2 Allan curve (z and relative difference per octave tau):
build/examples/adis16405_predict "$DATA" 600 | grep -E '^(# tau|[ga][xyz]:)'
SELF=1 build/examples/adis16405_predict "$DATA" 600 | grep -E '^(# tau|[ga][xyz]:)'
