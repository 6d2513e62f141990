#!/usr/bin/python3
"""Effects injected into the real ADIS16405 run 2: the challenge benchmark on a real sensor.

A window of the record (default 2000 s after the first 10 min, 100 Hz) is the base. Its model is
fitted by `sinsim fit --kind gm` (white, quantization, GM, random walk, flicker, drift; the
composite fit) and the plain window diagnosed: its reported findings are what the real sensor
already shows. Then, per record, one effect of the catalogue or from outside it is added to one
channel, sized k x the channel's own ADEV where the effect's is largest (generate.scale_to,
k in 1.5, 3, 6, 10), the result put back on the sensor's LSB lattice (the ADIS16405 outputs
0.05 deg/s and 3.33 mg steps), and diagnosed against the same model. Where in its LSB cell the
sensor's value was before rounding is not in the record: each sample is placed at a uniformly
drawn point of its cell (one draw for the whole run, so the plain window rounds back to itself),
the effect added there, and the sum rounded, as the converter rounds an effect that is there
before it. (Rounding the recorded value plus the effect instead returns the plain window exactly
for an effect below half an LSB: a 1.5-3x line on an accelerometer was no injection at all.) An
effect counts as found when it is the first reported finding that the plain window does not have
on that channel.

    /usr/bin/python3 bench/diagnose_challenge/adis_inject.py --sinsim build/sinsim --work out/adis
"""
import argparse
import gzip
import json
import math
import os
import subprocess
import sys
from collections import Counter, defaultdict

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate as g  # noqa: E402

FS = 100.0
LSB = {"g": 0.05, "a": 0.00333}  # deg/s, g: the record's value lattice
EFFECTS = ["random_walk", "ramp", "warmup", "sinusoid", "outliers", "bias_instability",
           "gauss_markov", "telegraph", "bias_step"]
SIZES = [1.5, 3.0, 6.0, 10.0]


def load(path, skip, n):
    with gzip.open(path, "rt") as f:
        data = np.loadtxt(f, delimiter=",", skiprows=1 + skip, max_rows=n)
    return data


def write(path, data):
    np.savetxt(path, data, delimiter=",", header="gx,gy,gz,ax,ay,az", comments="", fmt="%.6g")


def run(cmd):
    p = subprocess.run(["nice"] + cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(" ".join(cmd) + ": " + p.stderr[-400:])


def diagnose(a, rec, model, out):
    run([a.sinsim, "diagnose", rec, "--rate", "100", "--gyro-unit", "deg/s", "--accel-unit", "g",
         "--model", model, "--json", out, "--threads", str(a.threads), "--realisations",
         str(a.realisations), "-o", out + ".improved.yaml"])
    d = json.load(open(out))
    return {ax["channel"]: {"findings": [f["effect"] for f in ax["findings"] if f["reported"]],
                            "unexplained": ax.get("unexplained") or ax.get("unexplained_steps")}
            for ax in d["axes"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--data", default="../shared/data/adis16405/run2.csv.gz")
    ap.add_argument("--work", default="out/adis")
    ap.add_argument("--seconds", type=float, default=2000.0)
    ap.add_argument("--skip", type=float, default=600.0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--repeats", type=int, default=1, help="records per effect and size")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--realisations", type=int, default=32)
    ap.add_argument("--sizes", default="1.5,3,6,10", help="k values, comma separated")
    ap.add_argument("--kind", default="gm",
                    help="the plain window's model: sinsim fit --kind (gm, latent, auto, ...)")
    ap.add_argument("--report", nargs="+", metavar="RESULTS_JSON",
                    help="only print the scores of earlier runs' results.json files, pooled")
    a = ap.parse_args()
    if a.report:
        report([row for path in a.report for row in json.load(open(path))])
        return
    sizes = [float(v) for v in a.sizes.split(",")]
    os.makedirs(a.work, exist_ok=True)
    n = int(a.seconds * FS)
    base = load(a.data, int(a.skip * FS), n)
    plain = os.path.join(a.work, "plain.csv")
    write(plain, base)
    model = os.path.join(a.work, f"plain-{a.kind}.yaml")
    run([a.sinsim, "fit", plain, "--rate", "100", "--gyro-unit", "deg/s", "--accel-unit", "g",
         "--kind", a.kind, "-o", model, "-q"])
    ref = diagnose(a, plain, model, os.path.join(a.work, "plain.json"))
    print("plain window: " + "; ".join(f"{c} {v['findings']}" for c, v in ref.items()))
    t = np.arange(1, n + 1) / FS
    temp = 25.0 + np.zeros(n)
    # the values before rounding: a uniform point of each sample's LSB cell (module docstring)
    cell = np.random.default_rng([a.seed, 1 << 20]).uniform(-0.5, 0.5, size=base.shape)
    cell *= np.array([LSB[ch[0]] for ch in g.CHANNELS])
    rows, i = [], 0
    for rep in range(a.repeats):
        for name in EFFECTS:
            for k in sizes:
                rng = np.random.default_rng([a.seed, i])
                i += 1
                c = int(rng.integers(0, 6))
                ch = g.CHANNELS[c]
                x = base[:, c] - base[:, c].mean()
                e, info = g.unit_effect(rng, name, n, FS, t, temp)
                rec = base.copy()
                lsb = LSB[ch[0]]
                rec[:, c] = np.round((base[:, c] + cell[:, c] + e * g.scale_to(e, x, FS, k)) / lsb) * lsb
                path = os.path.join(a.work, f"i{i:03d}.csv")
                write(path, rec)
                res = diagnose(a, path, model, path[:-4] + ".json")
                os.remove(path)
                named = first_new(res[ch]["findings"], ref[ch]["findings"], res[ch]["unexplained"])
                rows.append({"effect": name, "size": k, "channel": ch, "named": named,
                             "findings": res[ch]["findings"], "plain": ref[ch]["findings"], **info})
                print(f"\r{len(rows)} records", end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)
    json.dump(rows, open(os.path.join(a.work, "results.json"), "w"), indent=1, default=float)
    report(rows)


def first_new(found, plain, unexplained):
    """The first finding that the plain window does not explain: an effect it lacks, one more of
    an effect than it has (a second line beside the stand's 0.564 Hz one), or one it has that now
    leads and did not (a stronger line, a GM that leads)."""
    seen = Counter()
    for i, f in enumerate(found):
        seen[f] += 1
        if seen[f] > plain.count(f) or (i == 0 and plain and plain[0] != f):
            return f
    return "unexplained" if unexplained else "none"


def report(rows):
    by_size = defaultdict(lambda: [0, 0])
    ooc = [0, 0]
    conf = defaultdict(Counter)
    for r in rows:
        r["named"] = first_new(r["findings"], r["plain"], r["named"] == "unexplained")
        conf[r["effect"]][r["named"]] += 1
        if r["effect"] in g.OUT_OF_CATALOGUE:
            ooc[1] += 1
            ooc[0] += r["named"] in g.EQUIVALENT[r["effect"]]
        else:
            by_size[r["size"]][1] += 1
            by_size[r["size"]][0] += r["named"] == r["effect"]
    for k in sorted(by_size):
        h, tot = by_size[k]
        print(f"ADIS run 2, injected at {k:4.1f}x: top-1 (new finding) {h}/{tot}")
    print(f"ADIS run 2, out-of-catalogue as equivalent/unexplained: {ooc[0]}/{ooc[1]}")
    for e in sorted(conf):
        print(f"  {e:18s} " + ", ".join(f"{k} {v}" for k, v in conf[e].most_common()))


if __name__ == "__main__":
    main()
