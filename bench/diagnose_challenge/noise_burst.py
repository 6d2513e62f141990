#!/usr/bin/python3
"""What the diagnosis names when a channel's noise level changes over the record.

No effect of the catalogue changes the noise's level with time; a stationary white term is the
catalogue's nearest, and before the sixty-second session a burst of noise was named `white` first
(8/8 on a blind probe's real ADIS16405 windows). Four cases, each on clean records of the alt
generator (generate_alt.py, its exact base model) with one channel changed:

  burst        white noise added in one stretch of 5-20 % of the record, sized so that the burst
               alone has k x the base ADEV at the tau where it stands out most (k 2..6)
  burst+white  the same, plus a stationary white the model lacks (k_w 1.5..3 over the base at the
               shortest tau): white is then a finding of its own
  white        the stationary white alone (the control: named white)
  growing      white noise whose sd grows linearly from 0 over the record (k 2..6 at its end)

With --adis RUN2 MODEL the records are instead 1000-s windows of the real ADIS16405 run 2 (after
its first 10 min) with a 100-s burst (k 2 or 5) on one channel, dithered within each LSB cell and
re-rounded to the sensor's lattice (0.05 deg/s, 3.33 mg), diagnosed against MODEL (a fit of run 1),
and the same windows clean (case "clean": what the windows show without a burst).

Prints, per case, how often white is reported, the first reported finding, and how often the
noise-level change is said. NumPy + the alt generator; sinsim only as the diagnosing binary.

  noise_burst.py --records 20 --seed 1 --work /tmp/burst --sinsim build/sinsim --jobs 2
  noise_burst.py --records 24 --seed 1 --work /tmp/burst-adis --sinsim build/sinsim \
      --adis ../shared/data/adis16405/run2.csv.gz bench/blind_probe/adis61/run1-auto.yaml
"""
import argparse
import json
import os
import subprocess
import sys
from collections import Counter
from concurrent.futures import ThreadPoolExecutor

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate_alt as ga  # noqa: E402

CASES = ["burst", "burst+white", "white", "growing"]


def white_sized(rng, base, fs, k, gate):
    """White noise gated by `gate` (0..1 per sample), scaled so that its ADEV is k x the base's at
    the tau where their ratio peaks."""
    w = rng.standard_normal(len(base)) * gate
    ms = ga.octave_grid(len(base))
    r = ga.adev(w, ms) / ga.adev(base - base.mean(), ms)
    return w * k / np.max(r)


def make(rng, idx, work, max_samples, case):
    row = ga.make(rng, idx, work, max_samples, None, True)
    ch = row["channel"]
    data = np.loadtxt(row["record"], delimiter=",", skiprows=1)
    with open(row["record"]) as f:
        header = f.readline().strip()
    j = ga.CHANNELS.index(ch) + 1
    y = data[:, j].copy()
    n, fs = len(y), row["rate_hz"]
    info = {"case": case}
    if case in ("burst", "burst+white"):
        frac = rng.uniform(0.05, 0.2)
        start = int(rng.uniform(0.05, 0.95 - frac) * n)
        gate = np.zeros(n)
        gate[start:start + int(frac * n)] = 1.0
        k = float(rng.uniform(2, 6))
        y = y + white_sized(rng, y, fs, k, gate)
        info.update(k=k, from_s=start / fs, to_s=(start + int(frac * n)) / fs)
    if case in ("burst+white", "white"):
        kw = float(rng.uniform(1.5, 3))
        # k_w: the channel's ADEV at the shortest tau rises k_w-fold
        ms = [1]
        a0 = ga.adev(data[:, j] - data[:, j].mean(), ms)[0]
        w = rng.standard_normal(n)
        y = y + w * a0 * np.sqrt(kw * kw - 1) / ga.adev(w, ms)[0]
        info["k_white"] = kw
    if case == "growing":
        k = float(rng.uniform(2, 6))
        y = y + white_sized(rng, y, fs, k, np.linspace(0, 1, n))
        info["k"] = k
    data[:, j] = y
    fmt = ["%.8f"] + ["%.12g"] * 6 + (["%.6f"] if data.shape[1] > 7 else [])
    np.savetxt(row["record"], data, fmt=fmt, delimiter=",", header=header, comments="")
    row.update(info)
    return row


ADIS_LSB = {"gx": 0.05, "gy": 0.05, "gz": 0.05, "ax": 0.00333, "ay": 0.00333, "az": 0.00333}


def make_adis(rng, idx, work, run2, model, case):
    """A 1000-s window of run 2 (deg/s, g) with a 100-s burst on one channel (case "burst"), or
    clean (case "clean"); the channel's samples dithered in their LSB cell and re-rounded."""
    fs, n = 100.0, 100000
    w = idx % ((len(run2) - 60000) // n)
    x = run2[60000 + w * n:60000 + (w + 1) * n].copy()
    ch = ga.CHANNELS[int(rng.integers(0, 6))]
    j = ga.CHANNELS.index(ch)
    info = {"case": case, "channel": ch, "rate_hz": fs, "window": w}
    if case == "burst":
        start = int(rng.uniform(0.05, 0.85) * n)
        gate = np.zeros(n)
        gate[start:start + int(100 * fs)] = 1.0
        k = float(rng.choice([2.0, 5.0]))
        lsb = ADIS_LSB[ch]
        y = x[:, j] + rng.uniform(-0.5, 0.5, n) * lsb + white_sized(rng, x[:, j], fs, k, gate)
        x[:, j] = np.round(y / lsb) * lsb
        info.update(k=k, from_s=start / fs, to_s=start / fs + 100)
    os.makedirs(work, exist_ok=True)
    rec = os.path.join(work, f"a{idx:04d}.csv")
    np.savetxt(rec, x, fmt=["%.2f"] * 3 + ["%.5f"] * 3, delimiter=",", header=",".join(ga.CHANNELS), comments="")
    info.update(record=rec, model=model, adis=True)
    return info


def diagnose(sinsim, row, realisations):
    out = row["record"][:-4] + ".json"
    cmd = ["nice", sinsim, "diagnose", row["record"], "--model", row["model"], "--json", out, "--threads", "1",
           "--realisations", str(realisations), "--channels", row["channel"], "-o", row["record"][:-4] + ".improved.yaml"]
    if row.get("adis"):
        cmd += ["--rate", "100", "--gyro-unit", "deg/s", "--accel-unit", "g"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        return {"error": p.stderr.strip()[-300:]}
    a = json.load(open(out))["axes"][0]
    rep = [f["effect"] for f in a["findings"] if f.get("reported")]
    return {"findings": rep, "noise_level": bool(a.get("noise_level_change")),
            "unexplained": bool(a.get("unexplained") or a.get("unexplained_steps") or a.get("noise_level_change"))}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--records", type=int, default=20, help="records per case")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--max-samples", type=int, default=60000)
    ap.add_argument("--realisations", type=int, default=16)
    ap.add_argument("--work", required=True)
    ap.add_argument("--sinsim", required=True)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--cases", nargs="*", default=CASES, choices=CASES)
    ap.add_argument("--adis", nargs=2, metavar=("RUN2", "MODEL"), help="real ADIS16405 windows instead")
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    rows = []
    if a.adis:
        a.cases = ["burst", "clean"]
        run2 = np.loadtxt(a.adis[0], delimiter=",", skiprows=1)
        for c in a.cases:
            for i in range(a.records):
                rows.append(make_adis(rng, i, os.path.join(a.work, c), run2, os.path.abspath(a.adis[1]), c))
    else:
        for c in a.cases:
            for i in range(a.records):
                rows.append(make(rng, len(rows), os.path.join(a.work, c.replace("+", "_")), a.max_samples, c))
    with ThreadPoolExecutor(a.jobs) as ex:
        for row, res in zip(rows, ex.map(lambda r: diagnose(a.sinsim, r, a.realisations), rows)):
            row.update(res)
    with open(os.path.join(a.work, "results.json"), "w") as f:
        json.dump(rows, f, indent=1, default=float)
    for c in a.cases:
        rs = [r for r in rows if r["case"] == c and "error" not in r]
        first = Counter(r["findings"][0] if r["findings"] else ("unexplained" if r["unexplained"] else "nothing")
                        for r in rs)
        print(f"{c:12s} n={len(rs):3d}  white reported {sum('white' in r['findings'] for r in rs):3d}  "
              f"level change said {sum(r['noise_level'] for r in rs):3d}  first: {dict(first.most_common())}")
        errors = [r for r in rows if r["case"] == c and "error" in r]
        if errors:
            print(f"  errors: {len(errors)}: {errors[0]['error']}")


if __name__ == "__main__":
    main()
