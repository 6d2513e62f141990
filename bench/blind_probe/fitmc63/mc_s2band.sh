#!/bin/sh
# S2 again with the band-matched truth (flicker tau_range [0.1 s, 24 s]: no content below ~1/4800 Hz, as my generator)
SINSIM=${SINSIM:-/tmp/probe_bin63/sinsim}
D=/tmp/probe_63/docs/scenarios
cd /tmp/probe_63/work
M="--model rec/S2_truthband.yaml"
for s in 1 2 3; do for k in auto gm ar arpslow; do M="$M --model models/S2_s${s}_$k.yaml"; done; done
$SINSIM mc $D/car.yaml --runs 200 --threads 1 --seed 11 $M --no-progress \
   --times "2 min,5 min,10 min,20 min,30 min" -o mc/carband_S2 > mc/carband_S2.log 2>&1; echo "rc=$?" >> mc/carband_S2.log
