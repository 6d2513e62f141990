#!/bin/sh
# Reproduces the table "On ADIS16405 run 1" of docs/diagnose.md, "Navigation-relevant verdict":
# the paper's AR(5) and the GM model, both fitted on the whole of run 1, diagnosed against run 1
# with --nav (the README's car, 32 runs, the default seed) before and after the additions, and the
# run-1 GM model against run 2 (a record it was not fitted to). Prints one markdown row per model.
# Usage: scripts/diagnose_nav_table.sh [BUILD_DIR] [OUT_DIR]   (defaults build, build/nav_table)
# ~15 min on two cores.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
out=${2:-$build/nav_table}
data=${SINSIM_DATA:-$here/../shared/data/adis16405}
units="--rate 100 --gyro-unit deg/s --accel-unit g"
mkdir -p "$out"
cd "$here"  # --nav's default scenario is scenarios/car.yaml, relative to the repository root
"$build/sinsim" fit "$data/run1.csv.gz" $units --kind ar --order 5 --lines warn -o "$out/ar5.yaml" -q
"$build/sinsim" fit "$data/run1.csv.gz" $units --kind gm -o "$out/gm.yaml" -q
diag() {  # NAME RECORD MODEL [options...]
  name=$1 record=$2 model=$3
  shift 3
  "$build/sinsim" diagnose "$data/$record" $units --model "$out/$model" --nav \
    -o "$out/$name.improved.yaml" --json "$out/$name.json" "$@" > "$out/$name.txt"
}
diag ar5_found run1.csv.gz ar5.yaml --add found
diag ar5_found_warmup run1.csv.gz ar5.yaml --add found warmup
diag gm_found run1.csv.gz gm.yaml --add found
diag gm_warmup run1.csv.gz gm.yaml --add warmup
diag gm_warmup_bw0 run1.csv.gz gm.yaml --add warmup --nav-bias-window 0
diag gm_run2 run2.csv.gz gm.yaml
/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]

def km(m):
    return f"{m / 1e3:.0f}"

def row(label, nav, key, ratio=None):
    m = nav[key]
    sc = m["scenario_drift"]
    terms = ", ".join(f"{t['sensor']} {t['effect']} {100 * t['share']:.0f} %"
                      for t in sorted(m["terms"], key=lambda t: -t["share"])[:3])
    b = m["bands_at_rest"]
    band = (f"{b['driving_tau_from_s']:.0f}–{b['driving_tau_to_s']:.0f} s: {km(b['driving_record_m'])} vs "
            f"{km(b['driving_model_p50_m'])} km → {b['driving_record_percentile']:.3g}, {b['driving_direction']}")
    ratio_text = f" (×{ratio:.2f})" if ratio else ""
    print(f"| {label} | {km(sc['horizontal_p50_m'][-1])} / {km(sc['horizontal_p95_m'][-1])} km{ratio_text} | "
          f"{terms} | {band} | {m['record_percentile']:.3g} ({m['record_median_percentile_over_time']:.3g}), "
          f"{m['direction']} |")

def load(name):
    return json.load(open(f"{out}/{name}.json"))["navigation"]

print("| model | car: median / 95 % | driven by (share) | driving τ at rest: record vs model median → pct | record at rest: pct (median over time) |")
print("|---|---|---|---|---|")
n = load("ar5_found")
print(f"(record at rest: {km(n['record_drift']['horizontal_m'][-1])} km)")
row("AR(5)", n, "model")
row("AR(5) + found", n, "improved", n["drift_ratio"])
n = load("ar5_found_warmup")
row("AR(5) + found + warmup", n, "improved", n["drift_ratio"])
n = load("gm_found")
row("GM", n, "model")
row("GM + found", n, "improved", n["drift_ratio"])
n = load("gm_warmup")
row("GM + warmup", n, "improved", n["drift_ratio"])
n = load("gm_warmup_bw0")
print(f"(bias window 0: record at rest {km(n['record_drift']['horizontal_m'][-1])} km)")
row("GM, bias window 0", n, "model")
row("GM + warmup, bias window 0", n, "improved", n["drift_ratio"])
print("warning (bias window 0):", n.get("warning", ""))
n = load("gm_run2")
print(f"(run 2 at rest: {km(n['record_drift']['horizontal_m'][-1])} km)")
row("run-1 GM against run 2", n, "model")
PY
