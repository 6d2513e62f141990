#!/bin/bash
# Reproductions for the defects reported (run from anywhere)
cd "${WORK:-.}"; B=${SINSIM:-sinsim}
echo "--- D1: --html onto an output file overwrites it (exit 0)"
rm -rf r_d1; $B run st1.yaml -o r_d1 --html r_d1/truth.csv >/dev/null; echo "rc=$?"; head -c 15 r_d1/truth.csv; echo
rm -rf r_d1b; $B run st1.yaml -o r_d1b --imu --html r_d1b/imu.csv >/dev/null; echo "rc=$?"; head -c 15 r_d1b/imu.csv; echo
echo "--- D2: refused --html target -> exit 1 but complete outputs left"
for h in /tmp /dev/null st1.yaml; do rm -rf r_d2; $B run st1.yaml -o r_d2 --html $h 2>&1 | tail -1; echo "rc=${PIPESTATUS[0]} left: $(ls r_d2 2>/dev/null | tr '\n' ' ')"; done
echo "--- D3: stale imu.csv of an earlier run survives a new run in the same folder"
rm -rf r_d3; $B run st1.yaml -o r_d3 --imu >/dev/null; $B run cn.yaml -o r_d3 >/dev/null; ls r_d3 | tr '\n' ' '; echo; echo "truth ends $(tail -1 r_d3/truth.csv | cut -c1-30) ; imu.csv rows $(($(wc -l < r_d3/imu.csv)-1)) (st1: 1000 rows; cn: 3000)"
echo "--- D4: scenario duration silently rounded to whole IMU samples"
printf 'start: {latitude: 45 deg, longitude: 7 deg}\nimu_rate: 100 Hz\noutput_rate: 100 Hz\nsegments:\n  - {type: accelerate, speed: 10 m/s, duration: 1.005 s}\n' > r_d4.yaml
rm -rf r_d4; $B run r_d4.yaml -o r_d4 >/dev/null; echo "rc=$? duration_s=$(grep '"duration_s"' r_d4/summary.json) last truth row: $(tail -1 r_d4/truth.csv | cut -d, -f1,5)"
echo "--- D5: '10 us' (the documented minimum 10 µs) refused, '0.01 ms'/'1e-5 s' pass this check"
for d in "10 us" "0.01 ms"; do printf 'start: {latitude: 45 deg, longitude: 7 deg}\nimu_rate: 100 kHz\noutput_rate: 100 kHz\nsegments:\n  - {type: static, duration: 1 s}\n  - {type: static, duration: %s}\n' "$d" > r_d5.yaml; rm -rf r_d5; $B run r_d5.yaml -o r_d5 2>&1 | tail -1 | cut -c1-160; done
