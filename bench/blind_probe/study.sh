#!/bin/bash
# The blind probe's diagnosis study (docs/diagnose-log.md, "Fifty-third session"): styles A
# (400 Hz, anti-aliased, ms time, a Temp_C column) and B (125 Hz delta-angle output, ';', deg/h,
# mg, a temp column), the model `sinsim fit` writes from a clean record of seed 1, then each hidden
# effect on gx (seeds 301-306) diagnosed against it. Prints "style effect seed | gx's row".
# usage: bench/blind_probe/study.sh SINSIM WORKDIR   (~10 min on two cores)
set -e
S=$(realpath "$1"); W=$2; G=$(dirname "$(realpath "$0")")/gen.py
mkdir -p "$W"; cd "$W"
optsA='--columns t=Time[ms],gx=GyroX[deg/s],gy=GyroY[deg/s],gz=GyroZ[deg/s],ax=AccX[g],ay=AccY[g],az=AccZ[g],temp=Temp_C'
optsB=''
for st in A B; do
  eval "o=\$opts$st"
  [ -f ${st}1.csv ] || /usr/bin/python3 "$G" $st 1 none ${st}1.csv
  "$S" fit ${st}1.csv $o -o ${st}1.yaml -q > /dev/null
  for eff in step temp ramp warmup none; do for s in 301 302 303 304 305 306; do
    f=${st}${s}_$eff.csv
    [ -f $f ] || /usr/bin/python3 "$G" $st $s $eff $f > /dev/null
    echo "$st $eff $s | $("$S" diagnose $f $o --model ${st}1.yaml --channels gx 2>&1 | grep '^gx  ' | sed 's/  */ /g' | cut -d' ' -f7-)"
  done; done
done
