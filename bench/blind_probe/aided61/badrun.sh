#!/bin/sh
# badrun.sh: run each bad/*.yaml with a 60-s timeout; print exit code, stderr, and whether an output folder appeared
cd "$(dirname "$0")"
for f in bad/*.yaml; do
  n=$(basename $f .yaml); [ $n = tac ] && continue
  d=badout/$n; rm -rf $d
  timeout 60 ${SINSIM:-/tmp/probe_bin27/sinsim} run $f -o $d > badout_$n.stdout 2> badout_$n.stderr; rc=$?
  ex=no; [ -e $d ] && ex="yes($(ls $d | tr '\n' ' '))"
  echo "### $n rc=$rc out=$ex"; head -c 700 badout_$n.stderr; echo
done
