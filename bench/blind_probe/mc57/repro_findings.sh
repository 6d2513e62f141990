#!/bin/bash
# Reproduces the findings of the mc probe (run from /tmp/probe_mc). ~1 min.
B=/tmp/probe_bin57/sinsim; S=/work/main/scenarios; cd /tmp/probe_mc
echo "== F1: exponent notation / inconsistent wording in the answer sentence (ratio 2.0 both times)"
rm -rf f1; $B mc static120.yaml --runs 200 --model acc_white_x.yaml --model accx2.yaml --times 30,120 --no-progress --threads 2 -o f1 | grep predicts
grep -o 'accx2 predicts[^(]*' f1/report.html
echo "== F2: duplicate --times -> duplicated rows in per_run.csv (same model, run, t)"
rm -rf f2; $B mc static120.yaml --runs 8 --model acc_white_x.yaml --times "30,30 s,0.5 min" --no-progress --threads 2 -o f2 >/dev/null
awk -F, '$1=="acc_white_x" && $2==0' f2/per_run.csv | cut -c1-60
echo "== F3: extending a batch whose --runs is not a multiple of 8 calls the intact short chunk 'damaged'"
M="--model $S/adis16355-ar5.yaml --model $S/adis16355-gm.yaml --times 2min,5min --threads 2 --no-progress"
rm -rf f3; $B mc static600.yaml --runs 100 $M -o f3 >/dev/null; $B mc static600.yaml --runs 160 $M -o f3 --resume 2>&1 | head -2
echo "== F4: --model takes several values and swallows the scenario when options come first"
$B mc --runs 8 --model acc_white_x.yaml static120.yaml -o f4; echo rc=$?
echo "== F5: MPI + Ctrl-C: 'N runs computed this session' is rank 0's only (fewer than saved)"
rm -rf f5; mpirun --allow-run-as-root --oversubscribe -np 2 $B mc static600.yaml --runs 160 ${M/--threads 2/--threads 1} -o f5 > /dev/null 2> f5.err & P=$!
sleep 6; kill -INT $P; wait $P; echo "mpirun rc=$?"; cat f5.err
echo "== F6: Ctrl-C before the first chunk: folder without checkpoints, then refused as 'holds the checkpoints'"
rm -rf f6; $B mc static600.yaml --runs 160 $M -o f6 2> f6.err & P=$!; sleep 0.15; kill -INT $P; wait $P; cat f6.err; find f6 -type f | wc -l
$B mc static600.yaml --runs 8 $M -o f6; echo rc=$?
echo "== F7: --runs 1: terminal 'p = nan', sd reported 0 (undefined for n-1=0); --runs 0 exit 1 but message says 'from 0'"
rm -rf f7; $B mc static120.yaml --runs 1 --model acc_white_x.yaml --model gyro_white_x.yaml --no-progress -o f7 | tail -1
$B mc static120.yaml --runs 0 --model acc_white_x.yaml -o f7b; echo rc=$?; $B mc static120.yaml --runs -1 --model acc_white_x.yaml -o f7b; echo rc=$?
echo "== F8: --budget on a one-effect model: '(+ budget variants)' but no budget, no message"
rm -rf f8; $B mc static120.yaml --runs 8 --model acc_white_x.yaml --budget --no-progress -o f8 | head -1; /usr/bin/python3 -c "import json;print('budget in json:', 'budget' in json.load(open('f8/summary.json')))"
echo "== F9: 'p = < 1e-300' wording (4000 runs)"
grep -o 'paired t-test p = &lt; 1e-300' out_cf2/report.html 2>/dev/null | head -1
