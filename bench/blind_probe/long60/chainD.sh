#!/bin/bash
D=$(cd "$(dirname "$0")" && pwd)  # this folder, home of the other scripts
# speed: plain diagnose (no --add) of a 1.08 M x 6 record, one thread
W=${WORK:-/tmp/probe_60/work}; cd $W
while pgrep -f "chainC.sh" >/dev/null; do sleep 3; done
/usr/bin/python3 "$D"/gen.py C 0 rec/C_clean0.csv --clean
uptime > out/speed.txt
/usr/bin/time -f "%e s wall %U s user %M KB" "${SINSIM:-/tmp/probe_bin60/sinsim}" diagnose rec/C_clean0.csv --model out/C_auto.yaml --json out/speed.json --threads 1 >> out/speed.txt 2>&1
uptime >> out/speed.txt
rm -f rec/C_clean0.csv
