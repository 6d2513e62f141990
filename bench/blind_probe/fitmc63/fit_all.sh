#!/bin/sh
# fit every record with every kind; logs in models/*.log
SINSIM=${SINSIM:-/tmp/probe_bin63/sinsim}
cd /tmp/probe_63/work
for S in S1 S2 S3 S4; do for s in 1 2 3; do for k in auto gm ar ar+slow; do
  kk=$(echo $k | tr '+' 'p')
  /usr/bin/time -f "%e s %M KB" $SINSIM fit rec/${S}_s$s.csv --threads 1 --kind $k -o models/${S}_s${s}_$kk.yaml > models/${S}_s${s}_$kk.log 2>&1
  echo "rc=$?" >> models/${S}_s${s}_$kk.log
done; done; done
