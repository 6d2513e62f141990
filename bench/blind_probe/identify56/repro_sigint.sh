#!/bin/sh
# SIGINT after 2 s to a normal long fit: expect exit 130 quickly
cd "${WORK:-.}"
start=$(date +%s)
timeout -k 20 -s INT 2 ${SINSIM:-sinsim} fit /work/shared/data/adis16405/run1.csv.gz --rate 100 --gyro-unit deg/s --accel-unit g --threads 1 -q -o sigint.yaml
echo "rc=$? after $(( $(date +%s) - start )) s"; ls sigint.yaml* 2>&1
