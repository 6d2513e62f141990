#!/bin/bash
D=$(cd "$(dirname "$0")" && pwd)  # this folder, home of the other scripts
# C ax quantization false alarm: reproduce on the fitted record, then with a model fitted on 15 min, and --kind latent
W=${WORK:-/tmp/probe_60/work}; cd $W; B=${SINSIM:-/tmp/probe_bin60/sinsim}
/usr/bin/python3 "$D"/gen.py C 0 rec/C0.csv --clean
/usr/bin/python3 "$D"/gen.py C 11 rec/C11.csv --clean
$B fit rec/C0.csv -o out/C_auto_again.yaml --threads 1 -q > out/extra_C.txt 2>&1
cmp out/C_auto.yaml out/C_auto_again.yaml >> out/extra_C.txt 2>&1 && echo "fit reproducible: identical file" >> out/extra_C.txt
$B fit rec/C0.csv --duration "15 min" -o out/C_auto_15min.yaml --threads 1 -q >> out/extra_C.txt 2>&1
$B fit rec/C0.csv --kind latent -o out/C_latent.yaml --threads 1 -q >> out/extra_C.txt 2>&1
for m in C_auto_15min C_latent; do
  echo "== C11 long vs $m" >> out/extra_C.txt
  $B diagnose rec/C11.csv --model out/$m.yaml --channels ax --threads 1 2>&1 | sed -n 1,6p >> out/extra_C.txt
  echo "== C11 15 min vs $m" >> out/extra_C.txt
  $B diagnose rec/C11.csv --model out/$m.yaml --duration "15 min" --channels ax --threads 1 2>&1 | sed -n 1,6p >> out/extra_C.txt
done
rm -f rec/C0.csv rec/C11.csv
