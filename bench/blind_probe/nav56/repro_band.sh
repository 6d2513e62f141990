#!/bin/bash
# Defect 1: "driving band" is not the fewest octaves holding >= 50 %
cd "${WORK:-.}"; S=${SINSIM:-sinsim}
[ -f rec_T_102.csv ] || $S synth T.yaml --rate 100 --duration "20 min" --seed 102 -o rec_T_102.csv
$S diagnose rec_T_102.csv --model noRW.yaml --nav static20.yaml --threads 1 --json repro_band.json | grep 'drives the drift'
/usr/bin/python3 band_view.py repro_band.json
