#!/bin/sh
# after the third batch: run 1 diagnosed against its own fit (same record, skip 10 min) - self-consistency
while kill -0 $(cat /tmp/probe_28/work/chain2.pid) 2>/dev/null; do sleep 5; done
cd /tmp/probe_28/work && /tmp/probe_bin28/sinsim diagnose /work/shared/data/adis16405/run1.csv.gz --model run1-auto.yaml --rate 100 --gyro-unit deg/s --accel-unit g --skip "10 min" --threads 1 --json self_run1.json > self_run1.log 2>&1
