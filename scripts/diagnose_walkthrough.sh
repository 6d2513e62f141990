#!/bin/sh
# Reproduces the README walkthrough "Diagnose: why a model misses the measurement" on the
# ADIS16405 static record (run 1; ../shared/data, SMAC group / U Calgary, CC BY-NC-SA 4.0):
#   1. fit AR(5) per channel as the seed paper does (Burg, order 5, raw record)
#   2. diagnose the AR(5) model against the record (JSON + HTML)
#   3. add every reported finding and the warm-up, refit, diagnose again (before -> after)
#   4. screenshots of the reports (headless Chromium), cropped into PICTURE_DIR
# Usage: scripts/diagnose_walkthrough.sh [BUILD_DIR] [OUT_DIR] [PICTURE_DIR]
#        (defaults build, build/walkthrough, OUT_DIR; scripts/figures.sh docs passes docs/diagnose)
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
out=${2:-$build/walkthrough}
pictures=${3:-$out}
data=${SINSIM_DATA:-$here/../shared/data/adis16405/run1.csv.gz}
units="--rate 100 --gyro-unit deg/s --accel-unit g"
mkdir -p "$out" "$pictures"
out=$(cd "$out" && pwd)  # Chromium needs an absolute file:// URL
"$build/sinsim" fit "$data" $units --kind ar --order 5 --lines warn -o "$out/ar5.yaml" -q
/usr/bin/time -f "diagnose wall %e s, CPU %U s user" \
  "$build/sinsim" diagnose "$data" $units --model "$out/ar5.yaml" \
    --json "$out/diagnose.json" --html "$out/diagnose.html" | tee "$out/diagnose.txt"
"$build/sinsim" diagnose "$data" $units --model "$out/ar5.yaml" --add found warmup \
    -o "$out/ar5.improved.yaml" --json "$out/improve.json" --html "$out/improve.html" | tee "$out/improve.txt"
if command -v chromium >/dev/null 2>&1; then
  profile=$(mktemp -d)
  for page in diagnose improve; do
    chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$profile" \
      --window-size=1150,3600 --screenshot="$out/$page.png" "file://$out/$page.html" >/dev/null 2>&1
  done
  rm -rf "$profile"
  # The docs' pictures (Debian python3-pil): the overview with gx, and gx before -> after.
  # The crop boxes fit the page as laid out for this record.
  /usr/bin/python3 - "$out" "$pictures" <<'PY' || echo "(no PIL: pictures not cropped)"
import sys
from PIL import Image
out, docs = sys.argv[1], sys.argv[2]
for src, box, dst in (("diagnose.png", (0, 0, 1150, 1100), "diagnose-gx.png"),
                      ("improve.png", (0, 3105, 760, 3545), "before-after-gx.png")):
    Image.open(f"{out}/{src}").crop(box).convert("RGB").quantize(colors=64).save(f"{docs}/{dst}", optimize=True)
PY
fi
echo "outputs in $out"
