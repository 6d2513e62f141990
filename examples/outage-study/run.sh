#!/bin/sh
# The outage study of docs/aided.md: how far does the position drift in a 30 s and a 60 s GNSS
# outage, and does the filter's sensor model matter? Truth {AR(5), GM} presets of the ADIS16355
# (scenarios/adis16355-*.yaml) × filter {GM, white-only} on 10 min of city driving
# (bench/car-10min.yaml's drive, GNSS 1 Hz, outages 150-180 s and 400-460 s), RUNS runs per cell.
# The AR(5) filter cell is not run: see docs/aided.md ("Not yet").
#
#   sh examples/outage-study/run.sh [SINSIM] [RUNS] [OUT]     (defaults: build/sinsim 200 out/outage-study)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
sinsim=${1:-$root/build/sinsim}
runs=${2:-200}
out=${3:-out/outage-study}
mkdir -p "$out"
drive=$(sed -n '/^start:/,$p' "$root/bench/car-10min.yaml")
for truth in ar5 gm; do
  for filter in gm white; do
    case $filter in
      gm) fmodel=$root/scenarios/adis16355-gm.yaml ;;
      white) fmodel=$here/filter-white.yaml ;;
    esac
    scen=$out/truth-$truth-filter-$filter.yaml
    cat > "$scen" <<YAML
name: truth-$truth-filter-$filter
$drive
errors: $root/scenarios/adis16355-$truth.yaml
initial_errors: {position: {sigma: 3 m}, velocity: {sigma: 0.1 m/s}, attitude: {sigma: [0.3 deg, 0.3 deg, 2 deg]}}
gnss: {rate: 1 Hz, position_sigma: [1 m, 1 m, 2 m], outages: [{start: 150 s, duration: 30 s}, {start: 400 s, duration: 60 s}]}
filter: {model: $fmodel}
YAML
    "$sinsim" mc "$scen" --runs "$runs" --seed 1 --times 179,459 --no-progress -o "$out/truth-$truth-filter-$filter" >/dev/null
  done
done
# The table: horizontal error at the last second of each outage, median and 95 %, over the runs.
python3 - "$out" "$runs" <<'PY'
import json, sys
out, runs = sys.argv[1], sys.argv[2]
print("| truth | filter | runs | 30 s outage: median / 95 % [m] | 60 s outage: median / 95 % [m] |")
print("|---|---|---|---|---|")
for truth in ("ar5", "gm"):
    for filt in ("gm", "white"):
        j = json.load(open(f"{out}/truth-{truth}-filter-{filt}/summary.json"))
        at = j["models"][0]["at"]
        cells = [f'{a["horizontal_m"]["p50"]:.2f} / {a["horizontal_m"]["p95"]:.2f}' for a in at]
        print(f"| {truth.upper()} | {filt} | {j['runs_per_model']} | {cells[0]} | {cells[1]} |")
PY
