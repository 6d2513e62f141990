#!/bin/bash
D=$(cd "$(dirname "$0")" && pwd)  # this folder, home of the other scripts
W=${WORK:-/tmp/probe_60/work}; cd $W
while pgrep -f "run_set.sh A" >/dev/null; do sleep 3; done
/usr/bin/time -f "%e %M" -o out/B_fit.time "${SINSIM:-/tmp/probe_bin60/sinsim}" fit rec/B_clean0.csv -o out/B_auto.yaml --threads 1 > out/B_fit.txt 2>&1
rm -f rec/B_clean0.csv
"$D"/run_set.sh B out/B_auto.yaml 1 2 3 4 5 6 > out/runB.log 2>&1
CLEAN=1 "$D"/run_set.sh B out/B_auto.yaml 11 >> out/runB.log 2>&1
