#!/bin/sh
SINSIM=${SINSIM:-/tmp/probe_bin63/sinsim}
D=/tmp/probe_63/docs/scenarios
cd /tmp/probe_63/work
for S in S1 S4; do
  M="--model rec/${S}_truth.yaml"
  for s in 11 12; do for k in auto gm; do M="$M --model models4h/${S}_s${s}_$k.yaml"; done; done
  $SINSIM mc $D/car.yaml --runs 200 --threads 1 --seed 11 $M --no-progress \
     --times "2 min,5 min,10 min,20 min,30 min" -o mc/car4h_$S > mc/car4h_$S.log 2>&1; echo "rc=$?" >> mc/car4h_$S.log
  $SINSIM mc $D/static.yaml --runs 100 --threads 1 --seed 11 $M --no-progress \
     --times "2 min,5 min,10 min,20 min,30 min,60 min" -o mc/static4h_$S > mc/static4h_$S.log 2>&1; echo "rc=$?" >> mc/static4h_$S.log
done
