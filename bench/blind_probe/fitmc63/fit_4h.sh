#!/bin/sh
# 4-h records (seeds 11, 12): does a longer record fix the slow terms?
SINSIM=${SINSIM:-/tmp/probe_bin63/sinsim}
cd /tmp/probe_63/work
for S in S1 S4; do for s in 11 12; do for k in auto gm; do
  $SINSIM fit rec4h/${S}_s$s.csv --threads 1 --kind $k -o models4h/${S}_s${s}_$k.yaml > models4h/${S}_s${s}_$k.log 2>&1; echo "rc=$?" >> models4h/${S}_s${s}_$k.log
done; done; done
