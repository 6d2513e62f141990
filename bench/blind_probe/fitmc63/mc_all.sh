#!/bin/sh
# per sensor: one paired mc over truth + every fitted model, car (200 runs) and static (100 runs)
SINSIM=${SINSIM:-/tmp/probe_bin63/sinsim}
D=/tmp/probe_63/docs/scenarios
cd /tmp/probe_63/work
for S in ${SENSORS:-S1 S2 S3 S4}; do
  M="--model rec/${S}_truth.yaml"
  for s in 1 2 3; do for k in auto gm ar arpslow; do M="$M --model models/${S}_s${s}_$k.yaml"; done; done
  /usr/bin/time -f "%e s %M KB" $SINSIM mc $D/car.yaml --runs 200 --threads 1 --seed 11 $M --no-progress \
     --times "2 min,5 min,10 min,20 min,30 min" -o mc/car_$S > mc/car_$S.log 2>&1; echo "rc=$?" >> mc/car_$S.log
  /usr/bin/time -f "%e s %M KB" $SINSIM mc $D/static.yaml --runs 100 --threads 1 --seed 11 $M --no-progress \
     --times "2 min,5 min,10 min,20 min,30 min,60 min" -o mc/static_$S > mc/static_$S.log 2>&1; echo "rc=$?" >> mc/static_$S.log
done
