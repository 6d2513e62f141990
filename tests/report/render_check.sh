#!/bin/sh
# render_check.sh <write_sample_report> <chromium> <python3> <png_not_blank.py> <work dir>
# Renders the sample report in headless Chromium and checks the screenshot shows ink and the
# first three palette colours (the plots rendered, not just the text). A blank page is rendered
# first and must FAIL the same check, so the check itself is shown able to fail.
set -eu
writer=$1 chromium=$2 python=$3 checker=$4 work=$5
mkdir -p "$work"
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
shot() {  # shot <html> <png>
  rm -f "$2"
  "$chromium" --headless --no-sandbox --disable-gpu --disable-background-networking \
    --disable-component-update --disable-sync --no-first-run --hide-scrollbars \
    --user-data-dir="$profile" --screenshot="$2" --window-size=1200,900 "file://$1" \
    >"$work/chromium.log" 2>&1
  test -s "$2" || { echo "chromium wrote no screenshot; log:"; cat "$work/chromium.log"; exit 1; }
}
colors="--color #1f77b4 --color #ff7f0e"

printf '<!DOCTYPE html><html><body></body></html>\n' >"$work/blank.html"
shot "$work/blank.html" "$work/blank.png"
if "$python" "$checker" "$work/blank.png" $colors; then
  echo "the checker accepted a blank page"; exit 1
fi

"$writer" "$work/sample.html"
shot "$work/sample.html" "$work/sample.png"
"$python" "$checker" "$work/sample.png" --min-ink 0.03 $colors
