#!/bin/sh
# run_all.sh: re-run every probe of README.probe.md (one sinsim at a time, --threads 1 for mc). ~6 min.
set -e
cd "$(dirname "$0")"
P=/usr/bin/python3; B=${SINSIM:-/tmp/probe_bin27/sinsim}
for s in air65 city stopgo jet ship; do echo "=== $s"; $P probe.py $s.yaml 40; done > stats_matched.txt
for y in 1 3; do $P probe.py stopgo_y$y.yaml 40 > stats_stopgo_y$y.txt; done
$P probe.py obs.yaml 30 > stats_obs.txt; $P obsphase.py obs >> stats_obs.txt
$P probe.py straight.yaml 40 > stats_straight.txt; $P profile.py straight 300 >> stats_straight.txt
for s in city_ps1cm city_ps1mm city_ie1km city_ie10km; do echo "=== $s"; $P probe.py $s.yaml 30; done > stats_rtk_ie.txt
for s in air65_half air65_double air65_gmwrw air65_gmgm air65_gmbrw city_half city_gmwrw air85 stopgo; do
  echo "=== $s"; $B run $s.yaml -o out/$s --seed 1 2>&1 | grep -i warn || true
  $B mc $s.yaml --runs 40 --threads 1 -o mc/$s --no-progress 2>&1 | sed -n '3,20p'
done > mismatch_tool.txt
for s in city city_y05; do $B mc $s.yaml --runs 300 --seed 2 --threads 1 -o mc/${s}_300 --no-progress | sed -n 3,8p; $P mcwin.py mc/${s}_300 0-30 76-106 160-220 480-600; done > heading_prior.txt
$B mc ship.yaml --runs 100 --seed 3 --threads 1 -o mc/ship_100 --no-progress > ship100.txt 2>&1
for s in air85 air65; do $B mc $s.yaml --runs 200 --seed 5 --threads 1 -o mc/${s}_200 --no-progress | sed -n 3,8p; done > lat.txt
$P badgen.py; ./badrun.sh > bad_results.txt 2>&1
