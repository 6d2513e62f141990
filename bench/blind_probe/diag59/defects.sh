#!/bin/bash
# Individual defect / doc-check reproductions. Needs $SINSIM. One sinsim at a time.
set -u
: "${SINSIM:?set SINSIM}"
D=/tmp/probe_59/work/defects; mkdir -p $D; cd $D
G="/usr/bin/python3 /tmp/probe_59/work/scripts/gen.py"
$G clean.csv --base wgm --seed 100000 >/dev/null
$SINSIM fit clean.csv --rate 100 --threads 1 -o model.yaml -q
echo "== A: --add found on a record where nothing is found (null)"
$G null.csv --base wgm --seed 100001 >/dev/null
$SINSIM diagnose null.csv --rate 100 --model model.yaml --threads 1 --add found -o A.yaml; echo "rc=$?"; ls -la A.yaml 2>&1
echo "== B: --add ramp:ax on a gyro-only record"
$SINSIM diagnose null.csv --rate 100 --model model.yaml --threads 1 --add ramp:ax -o B.yaml 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
echo "== C: --add bias_jumps:gx with no steps"
$SINSIM diagnose null.csv --rate 100 --model model.yaml --threads 1 --add bias_jumps:gx -o C.yaml 2>&1 | tail -4; echo "rc=${PIPESTATUS[0]}"
echo "== D: --realisations 4"
$SINSIM diagnose null.csv --rate 100 --model model.yaml --threads 1 --realisations 4 2>&1 | tail -2; echo "rc=${PIPESTATUS[0]}"
echo "== E: chirp (line sweeping 2->6 Hz) at 6x on gx: named gauss_markov, --add found does not lower the misfit"
$G chirp.csv --base wgm --seed 100301 --fx chirp:6
$SINSIM diagnose chirp.csv --rate 100 --model model.yaml --threads 1 --channels gx --add found -o E.yaml 2>&1 | grep -v "^\s*$" | head -30
echo "== F: noise burst (white variance x37 in the middle 30 %) on gx: named outliers + white"
$G burst.csv --base wgm --seed 100401 --fx noiseburst:6
$SINSIM diagnose burst.csv --rate 100 --model model.yaml --threads 1 --channels gx 2>&1 | head -20
echo "== G: triangle wave (3 cycles) on gx: named random_walk + ramp"
$G tri.csv --base wgm --seed 100501 --fx triangle:6
$SINSIM diagnose tri.csv --rate 100 --model model.yaml --threads 1 --channels gx --add found -o G.yaml 2>&1 | head -20
