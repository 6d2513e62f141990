#!/bin/sh
# The outage study of docs/aided.md: how far does the position drift in a 30 s and a 60 s GNSS
# outage, and does the filter's sensor model matter? Truth {AR(5), GM} presets of the ADIS16355
# (scenarios/adis16355-*.yaml, 1 kHz) × filter {AR(5), GM, white-only} on scenarios/car.yaml's
# 34.6 min of city driving, GNSS 1 Hz (1, 1, 2 m), two 30 s and two 60 s outages per run, random
# initial errors; RUNS runs per cell (seed 1). Per cell: the maximum horizontal error inside each
# outage (median and 95 % over runs and the two outages of a length), the filter's predicted
# horizontal sigma then, and the NEES consistency (share of epochs whose run-averaged NEES lies
# inside its 99 % chi-square band, aiding and outage epochs apart).
#
#   sh examples/outage-study/run.sh [SINSIM] [RUNS] [OUT]     (defaults: build/sinsim 200 out/outage-study)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
sinsim=${1:-$root/build/sinsim}
runs=${2:-200}
out=${3:-out/outage-study}
mkdir -p "$out"
. "$here/study_scenario.sh"
for truth in ar5 gm; do
  for filter in ar5 gm white; do
    case $filter in
      white) fmodel=$here/filter-white.yaml ;;
      *) fmodel=$root/scenarios/adis16355-$filter.yaml ;;
    esac
    cell=truth-$truth-filter-$filter
    study_scenario "$cell" "$root/scenarios/adis16355-$truth.yaml" "$fmodel" > "$out/$cell.yaml"
    echo "$cell: $runs runs" >&2
    "$sinsim" mc "$out/$cell.yaml" --runs "$runs" --seed 1 --no-progress -o "$out/$cell" >/dev/null
  done
done
python3 "$here/table.py" "$out"
