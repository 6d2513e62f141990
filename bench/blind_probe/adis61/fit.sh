#!/bin/sh
# Fit the run-1 model (kind auto, default) skipping warm-up
/tmp/probe_bin28/sinsim fit /work/shared/data/adis16405/run1.csv.gz --rate 100 --gyro-unit deg/s --accel-unit g --skip "10 min" --threads 1 -o run1-auto.yaml
