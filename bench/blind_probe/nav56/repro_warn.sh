#!/bin/bash
# Defect 2: a <1/2 drift-ratio warning names no group; Defect 3: --nav-bias-window error names --bias-window
cd "${WORK:-.}"; S=${SINSIM:-sinsim}
[ -f rec_T_101.csv ] || $S synth T.yaml --rate 100 --duration "20 min" --seed 101 -o rec_T_101.csv
$S diagnose rec_T_101.csv --model T.yaml --edited noRW.yaml --nav static20.yaml --threads 1 | grep WARNING
$S synth T.yaml --rate 100 --duration "10 min" --seed 201 --latitude "45 deg" -o rec10_T_201.csv >/dev/null
$S diagnose rec10_T_201.csv --model T.yaml --nav static20.yaml --nav-bias-window "30 min" --threads 1; echo rc=$?
