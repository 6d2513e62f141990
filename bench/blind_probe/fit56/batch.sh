#!/bin/bash
# usage: batch.sh "cases" "seeds"
cd "${WORK:-.}"
for c in $1; do for s in $2; do
  f=${c}_$s.csv
  [ -f $f ] || /usr/bin/python3 gen.py $c $s $f
  for k in auto gm; do
    [ -f ${c}_$s.$k.yaml ] && continue
    /usr/bin/time -f "%e s" timeout 300 ${SINSIM:-sinsim} fit $f --threads 1 --kind $k -o ${c}_$s.$k.yaml > ${c}_$s.$k.out 2> ${c}_$s.$k.err
    echo "$c $s $k rc=$? $(tail -1 ${c}_$s.$k.err)"
  done
done; done
