#!/bin/bash
# usage: nav_batch.sh RECMODEL MODEL SEEDS... ; writes dn_<rec>_<model>_<seed>.json
S=${SINSIM:-sinsim}; cd "${WORK:-.}"
rm=$1; m=$2; shift 2
for s in "$@"; do
  rec=rec_${rm%.yaml}_$s.csv
  [ -f $rec ] || $S synth $rm --rate 100 --duration "20 min" --seed $s -o $rec >/dev/null
  $S diagnose $rec --model $m --nav static20.yaml --threads 1 --json dn_${rm%.yaml}_${m%.yaml}_$s.json > dn_${rm%.yaml}_${m%.yaml}_$s.txt 2>&1 || echo "FAIL $rec $m rc=$?"
done
