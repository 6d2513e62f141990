#!/bin/bash
D=$(cd "$(dirname "$0")" && pwd)  # this folder, home of the other scripts
W=${WORK:-/tmp/probe_60/work}; cd $W
while pgrep -f "chainB.sh" >/dev/null; do sleep 3; done
/usr/bin/python3 "$D"/gen.py C 0 rec/C_clean0.csv --clean
/usr/bin/time -f "%e %M" -o out/C_fit.time "${SINSIM:-/tmp/probe_bin60/sinsim}" fit rec/C_clean0.csv -o out/C_auto.yaml --threads 1 > out/C_fit.txt 2>&1
"$D"/sigint_test.sh rec/C_clean0.csv out/C_auto.yaml
rm -f rec/C_clean0.csv
"$D"/run_set.sh C out/C_auto.yaml 1 2 3 4 > out/runC.log 2>&1
CLEAN=1 "$D"/run_set.sh C out/C_auto.yaml 11 >> out/runC.log 2>&1
