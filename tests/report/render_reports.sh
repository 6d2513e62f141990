#!/bin/sh
# render_reports.sh <sinsim> <chromium> <python3> <png_not_blank.py> <source dir> <shared dir> <work>
# Every report sinsim writes (run, mc, analyze, diagnose), made by the command line from small
# inputs, rendered by headless Chromium: the screenshot must show ink and the palette colours of
# its plots (png_not_blank.py), and the page Chromium built (--dump-dom, after parsing and layout)
# must hold the report's key sentences — the answer, the readouts — not only some SVG text.
set -eu
sinsim=$1 chromium=$2 python=$3 checker=$4 src=$5 shared=$6 work=$7
rm -rf "$work"
mkdir -p "$work"
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
flags="--headless --no-sandbox --disable-gpu --disable-background-networking
  --disable-component-update --disable-sync --no-first-run --hide-scrollbars"
shot() {  # shot NAME: NAME.html -> NAME.png (1200 x 2400) and NAME.dom
  # shellcheck disable=SC2086
  "$chromium" $flags --user-data-dir="$profile" --screenshot="$work/$1.png" \
    --window-size=1200,2400 "file://$work/$1.html" >"$work/$1.log" 2>&1
  test -s "$work/$1.png" || { echo "$1: chromium wrote no screenshot"; cat "$work/$1.log"; exit 1; }
  # shellcheck disable=SC2086
  "$chromium" $flags --user-data-dir="$profile" --dump-dom "file://$work/$1.html" \
    >"$work/$1.dom" 2>"$work/$1.log"
}
has() {  # has NAME TEXT: the rendered page holds TEXT
  grep -qF -- "$2" "$work/$1.dom" || { echo "$1: the rendered page lacks \"$2\""; exit 1; }
}
lacks() {  # lacks NAME REGEX: the rendered page's text has no match
  if sed 's/<[^>]*>/ /g' "$work/$1.dom" | grep -qE -- "$2"; then
    echo "$1: the rendered page shows \"$2\":"; sed 's/<[^>]*>/ /g' "$work/$1.dom" | grep -oE -- ".{30}$2.{10}" | head -3
    exit 1
  fi
}
palette="--color #1f77b4 --color #ff7f0e"

# run --html: the 30 s drive of the CLI tests with the GM sensor.
"$sinsim" run "$src/tests/sim/fixtures/good_short.yaml" --model "$src/scenarios/adis16355-gm.yaml" \
  -o "$work/run" --html "$work/run.html" >/dev/null
shot run
"$python" "$checker" "$work/run.png" --min-ink 0.03 $palette --color "#2ca02c" --color "#d62728"
has run "Track: truth and navigation"
has run "Attitude error (navigation − truth)"
has run " travelled, the navigation is "

# mc: AR(5) against GM, 16 paired runs, a budget, two report times.
cat >"$work/mc.yaml" <<YAML
name: mc-render
start: {latitude: 48 deg, longitude: 11 deg, height: 500 m, heading: 90 deg}
imu_rate: 100 Hz
output_rate: 1 Hz
segments:
  - {type: static, duration: 10 s}
  - {type: accelerate, speed: 15 m/s, duration: 20 s}
  - {type: turn, heading_change: 90 deg, duration: 30 s}
YAML
"$sinsim" mc "$work/mc.yaml" --runs 16 --budget --times "30 s,1 min" --model "$src/scenarios/adis16355-ar5.yaml" \
  --model "$src/scenarios/adis16355-gm.yaml" -o "$work/mc" >/dev/null
cp "$work/mc/report.html" "$work/mc.html"
shot mc
"$python" "$checker" "$work/mc.png" --min-ink 0.03 $palette
has mc "Answer"
has mc "paired runs, paired t-test p = "
has mc "Error budget of adis16355-gm"
lacks mc "[0-9][.][0-9]+e[+-]|e[+]"  # no "4.998e+04" in the text (p-values read "p = 4e-07")

# analyze and diagnose on the first 20 min of the real ADIS16405 record.
rec="$shared/data/adis16405/run1.csv.gz"
units="--rate 100 --gyro-unit deg/s --accel-unit g --duration 1200"
# shellcheck disable=SC2086
"$sinsim" analyze "$rec" $units --html "$work/analyze.html" >/dev/null
shot analyze
"$python" "$checker" "$work/analyze.png" --min-ink 0.03 $palette
has analyze "Allan deviation gx"
# shellcheck disable=SC2086
"$sinsim" fit "$rec" $units --kind ar --order 5 -o "$work/ar5.yaml" -q >/dev/null
# shellcheck disable=SC2086
"$sinsim" diagnose "$rec" $units --model "$work/ar5.yaml" --channels gx --realisations 8 \
  --html "$work/diagnose.html" >/dev/null 2>&1
shot diagnose
"$python" "$checker" "$work/diagnose.png" --min-ink 0.03 $palette
has diagnose "gx"
echo "run, mc, analyze and diagnose reports rendered and inspected"
