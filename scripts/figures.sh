#!/bin/sh
# Regenerates every figure the README and docs/ show, from the commands the README gives.
#   scripts/figures.sh            -> out/figures/   (the repository is not touched)
#   scripts/figures.sh docs       -> docs/          (to update the committed pictures)
# Needs a build (scripts/setup.sh), ../shared/data, and for the PNGs headless Chromium and
# python3-pil (installed here from Debian when missing). About 4 minutes on 2 cores.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
dest=${1:-out/figures}
work=out/figures-work
mkdir -p "$dest" "$dest/diagnose" "$work"
need=""
command -v chromium >/dev/null 2>&1 || need="$need chromium"
/usr/bin/python3 -c "import PIL" 2>/dev/null || need="$need python3-pil"
if [ -n "$need" ]; then
  sudo_cmd=""; [ "$(id -u)" -eq 0 ] || sudo_cmd=sudo
  $sudo_cmd apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq $need >/dev/null
fi
data=../shared/data/adis16405/run1.csv.gz
units="--rate 100 --gyro-unit deg/s --accel-unit g"

shot() {  # shot HTML PNG WIDTH HEIGHT: a headless-Chromium screenshot of a report
  profile=$(mktemp -d)
  chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$profile" \
    --window-size="$3,$4" --screenshot="$2" "file://$here/$1" >/dev/null 2>&1
  rm -rf "$profile"
}
crop() {  # crop SRC LEFT TOP RIGHT BOTTOM DST
  /usr/bin/python3 - "$@" <<'PY'
import sys
from PIL import Image
src, l, t, r, b, dst = sys.argv[1:]
Image.open(src).crop((int(l), int(t), int(r), int(b))).convert("RGB").quantize(colors=64).save(dst, optimize=True)
PY
}

# analyze --html on run 1: the gyro x panel.
build/sinsim analyze "$data" $units --html "$work/run1-analyze.html"
shot "$work/run1-analyze.html" "$work/run1-analyze.png" 1200 2400
crop "$work/run1-analyze.png" 0 0 1200 820 "$dest/analyze-adis16405-gx.png"

# AR(5) vs GM on car.yaml, 500 paired runs: the "models together" plot of the mc report.
# --resume: a figures run stopped with Ctrl-C continues from the runs it saved.
build/sinsim mc scenarios/car.yaml --runs 500 --model scenarios/adis16355-ar5.yaml \
    --model scenarios/adis16355-gm.yaml --times "5 min,10 min,20 min,2078 s" -o "$work/ar-vs-gm" --resume
/usr/bin/python3 - "$work/ar-vs-gm/report.html" "$dest/mc-ar-vs-gm.svg" <<'PY'
import re, sys
html = open(sys.argv[1], encoding="utf-8").read()
svgs = re.findall(r"<svg.*?</svg>", html, flags=re.S)
pick = [s for s in svgs if "Models together" in s]
if not pick:
    sys.exit("figures: no 'Models together' plot in the mc report")
open(sys.argv[2], "w", encoding="utf-8").write(pick[0] + "\n")
PY

# The mc report's first screen: the answer in words, the drift envelopes on log axes.
shot "$work/ar-vs-gm/report.html" "$work/mc-report.png" 1200 1500
crop "$work/mc-report.png" 0 0 1200 1000 "$dest/mc-report.png"

# run --html on the car drive with a navigation-grade IMU: summary, track map, errors against time.
build/sinsim run scenarios/car.yaml --model scenarios/grade-navigation.yaml -o "$work/car-nav" \
    --html "$work/car-nav/report.html"
shot "$work/car-nav/report.html" "$work/run-report.png" 1200 2000
crop "$work/run-report.png" 0 0 1200 1500 "$dest/run-report.png"

# The diagnose walkthrough (fit AR(5), diagnose, add what was found) and its two pictures.
scripts/diagnose_walkthrough.sh build "$work/walkthrough" "$dest/diagnose"
# The improved diagnosis page: before → after, what still fails, the command to run next.
shot "$work/walkthrough/improve.html" "$work/diagnose-next.png" 1200 2000
crop "$work/diagnose-next.png" 0 420 1200 1480 "$dest/diagnose/what-next.png"
echo "figures in $dest"
