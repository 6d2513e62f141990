#!/bin/sh
# Scale-factor states (docs/aided.md, "Scale-factor states"): scenarios/car-10min-aided.yaml with
# truth {with, without} 3000 ppm scale factors x filter {with, without} scale-factor states (three
# cells), RUNS runs each (seed 1); per cell the NEES consistency and the outage drift from mc's
# summary.json.
#
#   sh examples/scale-factor/run.sh [SINSIM] [RUNS] [OUT]     (defaults: build/sinsim 200 out/scale-factor)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
sinsim=${1:-$root/build/sinsim}
runs=${2:-200}
out=${3:-out/scale-factor}
mkdir -p "$out"
plain=$root/scenarios/aided-model.yaml
sf=$here/model-sf.yaml
for cell in "truthsf-filtersf $sf $sf" "truthsf-filter18 $sf $plain" "truth18-filtersf $plain $sf"; do
  set -- $cell
  sed -e "s|^errors: .*|errors: $2|" -e "s|^filter: .*|filter: {model: $3}|" \
    "$root/scenarios/car-10min-aided.yaml" > "$out/$1.yaml"
  echo "$1: $runs runs" >&2
  "$sinsim" mc "$out/$1.yaml" --runs "$runs" --seed 1 --no-progress -o "$out/$1" >/dev/null
done
python3 "$root/examples/aided_cells.py" "$out" truthsf-filtersf truthsf-filter18 truth18-filtersf
