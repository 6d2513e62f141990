#!/bin/bash
D=$(cd "$(dirname "$0")" && pwd)  # this folder, home of the other scripts
# SIGINT a long diagnose under a pseudo-terminal (script) after 15 s; then the same with stderr to a file.
W=${WORK:-/tmp/probe_60/work}; cd $W; B=${SINSIM:-/tmp/probe_bin60/sinsim}; REC=$1; M=$2
rm -f out/sigint.*
script -qfc "$B diagnose $REC --model $M --add found -o out/sigint.pty.yaml --json out/sigint.pty.json --html out/sigint.pty.html --threads 1; echo EXIT=\$?" out/sigint.pty.log > /dev/null 2>&1 &
SP=$!
sleep 15
CP=$(pgrep -P $(pgrep -P $SP | head -1) sinsim || pgrep -P $SP sinsim)
echo "script pid $SP sinsim pid $CP" > out/sigint.info
T0=$(date +%s.%N); kill -INT $CP
wait $SP; T1=$(date +%s.%N)
echo "pty: stop took $(echo "$T1 - $T0" | bc) s after SIGINT" >> out/sigint.info
ls -la out/ | grep sigint >> out/sigint.info
# no terminal
$B diagnose $REC --model $M --add found -o out/sigint.file.yaml --json out/sigint.file.json --threads 1 > out/sigint.file.out 2> out/sigint.file.err &
P=$!; sleep 15; T0=$(date +%s.%N); kill -INT $P; wait $P; echo "file: exit $? after $(echo "$(date +%s.%N) - $T0" | bc) s" >> out/sigint.info
ls -la out/ | grep sigint >> out/sigint.info
