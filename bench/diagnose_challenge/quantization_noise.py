#!/usr/bin/python3
"""Quantization noise without a value lattice (IEEE Std 952's Q, GMWM's QN) on the benchmark's bases.

GMWM (R packages gmwm / simts) and IEEE Std 952 treat quantization noise as a process: the rate
error sqrt(12 Q^2) (U[k] - U[k-1]) / dt, U independent uniform on (0, 1), Allan variance
3 Q^2 / tau^2. A record made that way has no value lattice, so the diagnosis must see it from the
Allan slope -1 alone. Per record: a clean record of the benchmark's main (generate.py) or
independent (generate_alt.py) generator (their null draws: bases, rates, lengths, 25 % quantized
channels), and on one channel whose base is not quantized that process, sized k x the channel's
own Allan deviation at one sample (where Q's is largest against any base), k log-uniform in
1.5-10. Scores: the quantization named first (by size), the misfit at least halved by
`--add quantization`, and findings on the five clean channels of each record.

    /usr/bin/python3 bench/diagnose_challenge/quantization_noise.py --sinsim build/sinsim \\
        --generator alt --records 60 --work out/qn
"""
import argparse
import json
import math
import os
import sys
from collections import Counter

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import challenge as C  # noqa: E402
import generate as g  # noqa: E402


def inject(row, rng):
    """Adds the QN process to a channel of row's record whose model has no quantization; returns
    the channel and the truth (size, Q [SI x s])."""
    data = np.genfromtxt(row["record"], delimiter=",", names=True)
    model = open(row["model"]).read().split("\n")
    quantized, sensor, axis = set(), None, None
    for line in model:
        s = line.strip()
        if s in ("gyro:", "accel:"):
            sensor = s[0]
        elif s.endswith(":") and s[:-1] in ("x", "y", "z"):
            axis = s[:-1]
        elif "quantization" in s:
            quantized.add(sensor + axis)
    free = [c for c in g.CHANNELS if c not in quantized]
    ch = str(rng.choice(free))
    fs, x = row["rate_hz"], data[ch]
    k = float(10 ** rng.uniform(math.log10(1.5), math.log10(10.0)))
    base_adev1 = float(g.adev(x - x.mean(), 1.0 / fs, [1])[0])
    # ADEV of the process at tau = dt: sqrt(3) Q_rate with Q_rate = Q / dt.
    q_rate = k * base_adev1 / math.sqrt(3.0)
    u = rng.uniform(0.0, 1.0, len(x) + 1)
    data[ch] = x + math.sqrt(12.0) * q_rate * (u[1:] - u[:-1])
    names = data.dtype.names
    np.savetxt(row["record"], np.column_stack([data[n] for n in names]), delimiter=",",
               header=",".join(names), comments="", fmt="%.12g")
    return ch, {"effect": "quantization", "size": k, "Q": q_rate / fs}


def run_one(a, i):
    rng = np.random.default_rng([a.seed, i])
    row = C.null_record(a.generator, rng, i, a.work, a.max_samples)
    row["channel"], h = inject(row, rng)
    row["hidden"] = [h]
    row["result"] = C.diagnose(a.sinsim, row, a)
    first = (row["result"].get(row["channel"], {}).get("findings") or [None])[0]
    if a.add and first == "quantization":
        row["add"] = C.diagnose(a.sinsim, row, a, f"quantization:{row['channel']}")
    os.remove(row["record"])
    return row


def report(rows):
    bins = [(1.5, 3.0), (3.0, 6.0), (6.0, 10.01)]
    top, named, halved, clean, found_q = Counter(), Counter(), [0, 0], [0, 0], []
    for r in rows:
        res = r["result"]
        if "error" in res:
            continue
        k = r["hidden"][0]["size"]
        b = next(b for b in bins if b[0] <= k < b[1])
        for ch, c in res.items():
            if ch != r["channel"]:
                clean[1] += 1
                clean[0] += bool(c["findings"])
                continue
            first = c["findings"][0] if c["findings"] else ("unexplained" if c.get("unexplained") else "none")
            top[b, "n"] += 1
            top[b, "hit"] += first == "quantization"
            named[first] += 1
            add = r.get("add", {}).get(ch)
            if add and add["misfit_before"] > 0:
                halved[1] += 1
                halved[0] += add["misfit_after"] <= 0.5 * add["misfit_before"]
    for b in bins:
        n = top[b, "n"]
        print(f"quantization noise {b[0]:g}-{min(b[1], 10):g}x: named first {top[b, 'hit']}/{n}"
              + (f" ({100 * top[b, 'hit'] / n:.1f} %)" if n else ""))
    print("named first:", dict(named.most_common()))
    print(f"misfit halved by --add quantization: {halved[0]}/{halved[1]}")
    print(f"clean channels with a finding: {clean[0]}/{clean[1]}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--records", type=int, default=60)
    ap.add_argument("--first", type=int, default=0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--generator", choices=["main", "alt"], default="alt")
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--work", default="out/qn")
    ap.add_argument("--max-samples", type=int, default=30000)
    ap.add_argument("--realisations", type=int, default=16)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--threshold", type=float, default=None)
    ap.add_argument("--add", action="store_true", help="also --add quantization where it came first")
    ap.add_argument("--report", nargs="+", metavar="RESULTS_JSON")
    a = ap.parse_args()
    if a.report:
        report([r for p in a.report for r in json.load(open(p))])
        return
    report(C.run_records(a, run_one))


if __name__ == "__main__":
    main()
