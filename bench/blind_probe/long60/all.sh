#!/bin/bash
# all.sh: the whole long-record probe in the helper's order, one sinsim at a time on one thread
# (about 1.5 h on an idle core; records up to 160 MB are made and deleted one by one).
#   SINSIM  the binary (default /tmp/probe_bin60/sinsim)   WORK  scratch folder (default /tmp/probe_60/work)
# Then: score.py $WORK/out A B C  (the README's table) and by_size.py $WORK/out A long.
set -euo pipefail
D=$(cd "$(dirname "$0")" && pwd)
export WORK=${WORK:-/tmp/probe_60/work} SINSIM=${SINSIM:-/tmp/probe_bin60/sinsim}
mkdir -p "$WORK/out" "$WORK/rec"; cd "$WORK"
/usr/bin/python3 "$D"/gen.py A 0 rec/A_clean0.csv --clean
"$SINSIM" fit rec/A_clean0.csv -o out/A_auto.yaml --threads 1 > out/A_fit.txt 2>&1
rm -f rec/A_clean0.csv
"$D"/run_set.sh A out/A_auto.yaml 2 3 4 5 6 7 8 9 > out/runA.log 2>&1
CLEAN=1 "$D"/run_set.sh A out/A_auto.yaml 11 12 >> out/runA.log 2>&1
/usr/bin/python3 "$D"/gen.py B 0 rec/B_clean0.csv --clean
"$D"/chainB.sh
"$D"/chainC.sh
"$D"/chainD.sh
echo "all.sh: done; outputs in $WORK/out"
