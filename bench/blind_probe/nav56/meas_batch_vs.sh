#!/bin/bash
# mc --measured uniformity: records synthesized from T.yaml (seed s), replayed against T.yaml (mc seed 777)
S=${SINSIM:-sinsim}; cd "${WORK:-.}"
for s in "$@"; do
  rec=rec10_T_$s.csv
  [ -f $rec ] || $S synth T.yaml --rate 100 --duration "10 min" --seed $s --latitude "45 deg" -o $rec >/dev/null
  rm -rf mv_$s
  $S mc --measured $rec --latitude "45 deg" --longitude "7 deg" --height "0 m" --runs 40 --seed $((5000+s)) --threads 1 --no-progress \
     --times "2 min,5 min,10 min" --model T.yaml -o mv_$s > mv_$s.log 2>&1 || echo "FAIL $s"
done
