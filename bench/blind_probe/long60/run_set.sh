#!/bin/bash
D=$(cd "$(dirname "$0")" && pwd)  # this folder, home of the other scripts
# usage: run_set.sh SENSOR MODEL.yaml SEED... : generate, diagnose long + first-15-min cut, delete record
# one sinsim at a time, --threads 1. Outputs in $WORK/out/ (default /tmp/probe_60/work)
W=${WORK:-/tmp/probe_60/work}; S=$1; M=$2; shift 2
B=${SINSIM:-/tmp/probe_bin60/sinsim}
for seed in "$@"; do
  r=$S$seed
  /usr/bin/python3 $D/gen.py $S $seed $W/rec/$r.csv ${CLEAN:+--clean}
  cp $W/rec/$r.json $W/out/$r.truth.json
  /usr/bin/time -f "%e %M" -o $W/out/$r.long.time $B diagnose $W/rec/$r.csv --model $M --add found -o $W/out/$r.long.yaml --json $W/out/$r.long.json --threads 1 > $W/out/$r.long.txt 2> $W/out/$r.long.err
  echo "rc=$?" >> $W/out/$r.long.time
  /usr/bin/time -f "%e %M" -o $W/out/$r.short.time $B diagnose $W/rec/$r.csv --model $M --duration "15 min" --add found -o $W/out/$r.short.yaml --json $W/out/$r.short.json --threads 1 > $W/out/$r.short.txt 2> $W/out/$r.short.err
  echo "rc=$?" >> $W/out/$r.short.time
  rm -f $W/rec/$r.csv
  echo "$r done $(date +%T)"
done
