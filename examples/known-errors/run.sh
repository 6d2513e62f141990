#!/bin/sh
# Known errors (docs/aided.md, "Known errors"): scenarios/aircraft.yaml (32.5 min) with GNSS
# position and velocity at 5 Hz, a lever arm, a 2-min and a 5-min outage; the truth is
# model-known.yaml (a tactical unit with misalignment, g-sensitivity and temperature
# coefficients), the filter's model either the same file (it compensates what is known) or
# scenarios/grade-tactical.yaml (not told); RUNS runs each (seed 1); per cell the NEES
# consistency and the outage drift from mc's summary.json.
#
#   sh examples/known-errors/run.sh [SINSIM] [RUNS] [OUT]     (defaults: build/sinsim 40 out/known-errors)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
sinsim=${1:-$root/build/sinsim}
runs=${2:-40}
out=${3:-out/known-errors}
mkdir -p "$out"
for cell in "told $here/model-known.yaml" "untold $root/scenarios/grade-tactical.yaml"; do
  set -- $cell
  sed -e "s|^errors: .*|errors: $here/model-known.yaml\ntemperature: {start: 15 degC, end: 45 degC}|" \
    "$root/scenarios/aircraft.yaml" > "$out/$1.yaml"
  cat >> "$out/$1.yaml" <<YAML
initial_errors:
  position: {sigma: 3 m}
  velocity: {sigma: 0.1 m/s}
  attitude: {sigma: [0.2 deg, 0.2 deg, 1 deg]}
gnss:
  rate: 5 Hz
  position_sigma: [1.5 m, 1.5 m, 3 m]
  velocity_sigma: 0.1 m/s
  lever_arm: [2 m, 0 m, -1.5 m]
  outages: [{start: 600 s, duration: 120 s}, {start: 1500 s, duration: 300 s}]
filter: {model: $2}
YAML
  echo "$1: $runs runs" >&2
  "$sinsim" mc "$out/$1.yaml" --runs "$runs" --seed 1 --no-progress -o "$out/$1" >/dev/null
done
python3 "$root/examples/aided_cells.py" "$out" told untold
