#!/bin/sh
# mc --measured: each own record replayed, placed among truth and its own fitted models (100 runs, 30 min)
SINSIM=${SINSIM:-/tmp/probe_bin63/sinsim}
cd /tmp/probe_63/work
for S in ${SENSORS:-S1 S2 S3 S4}; do for s in 1 2 3; do
  M="--model rec/${S}_truth.yaml"
  for k in auto gm arpslow; do M="$M --model models/${S}_s${s}_$k.yaml"; done
  $SINSIM mc --measured rec/${S}_s$s.csv --latitude "45 deg" --longitude "7 deg" --height "0 m" --heading "0 deg" \
     --duration "30 min" --bias-window 60 --runs 100 --threads 1 --seed 11 --no-progress \
     --times "2 min,5 min,10 min,20 min,30 min" $M -o mc/meas_${S}_s$s > mc/meas_${S}_s$s.log 2>&1
  echo "rc=$?" >> mc/meas_${S}_s$s.log
done; done
