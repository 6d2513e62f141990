#!/bin/sh
# Why the matched cells' outage NEES of the outage study (docs/aided.md) sits above 9: per state,
# the run-averaged e_i^2 / sigma_i^2 beside the NEES, per 10-s phase of the outages, for
#   ar5    truth = filter = the AR(5) preset (scenarios/adis16355-ar5.yaml)
#   gm     truth = filter = the Gauss-Markov preset
#   white  truth = filter = white noise of the GM preset's low-frequency density (continuous)
#   white10 the same white noise at 1/10 of the density
# on car.yaml's drive with the study's GNSS and outages, N seeds each (`sinsim run`, filter.csv).
#
#   sh bench/outage_nees/run.sh [SINSIM] [N] [OUT]      (defaults: build/sinsim 100 out/outage-nees)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
sinsim=${1:-$root/build/sinsim}
n=${2:-100}
out=${3:-out/outage-nees}
mkdir -p "$out"
. "$root/examples/outage-study/study_scenario.sh"
white=$root/examples/outage-study/filter-white.yaml
# the model beside the cell's scenario, not at its name (white10.yaml is the scenario)
sed 's/density: \([0-9.]*\)/density: \1e-1/' "$white" > "$out/filter-white10.yaml"
for cell in ar5 gm white white10; do
  case $cell in
    ar5|gm) model=$root/scenarios/adis16355-$cell.yaml ;;
    white) model=$white ;;
    white10) model=$(cd "$out" && pwd)/filter-white10.yaml ;;
  esac
  study_scenario "$cell" "$model" "$model" > "$out/$cell.yaml"
  echo "$cell: $n seeds" >&2
  for s in $(seq 1 "$n"); do
    "$sinsim" run "$out/$cell.yaml" --seed "$s" -o "$out/$cell/s$s" >/dev/null
    rm -f "$out/$cell/s$s/truth.csv" "$out/$cell/s$s/nav.csv" "$out/$cell/s$s/errors.csv"
  done
  /usr/bin/python3 "$here/components.py" "$out/$cell"
done
