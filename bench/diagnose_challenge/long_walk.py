#!/usr/bin/python3
"""A random walk the model lacks, on records longer than the benchmark's 30000-sample cap.

Each record: one gyro channel (gz) of white noise (0.3 deg/sqrt(h)) plus a first-order
Gauss-Markov bias (3e-3 deg/s, tau 60 s) -- the model handed to the diagnosis -- plus a random
walk whose Allan deviation at T/8 is SIZE x the base's there (closed forms: walk K^2 tau / 3,
GM 2 sigma^2 T_gm / tau + white N^2 / tau). NumPy/SciPy only, no sinsim code. Counts how often
`sinsim diagnose` names random_walk first (docs/diagnose.md, "a long record's walk is no level step").

    /usr/bin/python3 bench/diagnose_challenge/long_walk.py --sinsim build/sinsim \
        --seeds 12 --size 3 --rate 100 --duration 7200 --work /tmp/long_walk
"""
import argparse
import math
import os
import subprocess

import numpy as np
from scipy.signal import lfilter

D2R = math.pi / 180.0
N_WHITE, GM_SIGMA, GM_TAU = 0.3 * D2R / 60.0, 3e-3 * D2R, 60.0
MODEL = f"""description: white + GM base of long_walk.py
gyro:
  z: [{{type: white, density: 0.3 deg/sqrt(h)}}, {{type: gauss_markov, sigma: 0.003 deg/s, tau: 60 s}}]
"""


def record(path, seed, size, fs, duration):
    rng = np.random.default_rng(seed)
    n, dt = int(fs * duration), 1.0 / fs
    phi = math.exp(-dt / GM_TAU)
    x = N_WHITE / math.sqrt(dt) * rng.standard_normal(n)
    drive = GM_SIGMA * math.sqrt(1 - phi * phi) * rng.standard_normal(n)
    x += lfilter([1.0], [1.0, -phi], drive, zi=[phi * GM_SIGMA * rng.standard_normal()])[0]
    tau8 = duration / 8
    base = math.sqrt(GM_SIGMA ** 2 * 2 * GM_TAU / tau8 + N_WHITE ** 2 / tau8)
    k = size * base / math.sqrt(tau8 / 3)
    x += np.cumsum(k * math.sqrt(dt) * rng.standard_normal(n))
    with open(path, "w") as f:
        f.write("t[s],gz[rad/s]\n")
        np.savetxt(f, np.column_stack([np.arange(n) * dt, x]), delimiter=",", fmt="%.10e")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--seeds", type=int, default=12)
    ap.add_argument("--first-seed", type=int, default=1)
    ap.add_argument("--size", type=float, default=3.0)
    ap.add_argument("--rate", type=float, default=100.0)
    ap.add_argument("--duration", type=float, default=7200.0, help="[s]")
    ap.add_argument("--work", default="/tmp/long_walk")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    model = os.path.join(a.work, "base.yaml")
    with open(model, "w") as f:
        f.write(MODEL)
    first = 0
    for seed in range(a.first_seed, a.first_seed + a.seeds):
        path = os.path.join(a.work, "r.csv")
        record(path, seed, a.size, a.rate, a.duration)
        out = subprocess.run([a.sinsim, "diagnose", path, "--model", model, "--channels", "gz",
                              "--threads", "1"], capture_output=True, text=True, check=True).stdout
        row = next(l.split() for l in out.splitlines() if l.startswith("gz "))
        chi2 = next(i for i, t in enumerate(row) if "/" in t)  # chi2/K, then Ljung-Box p
        findings = " ".join(row[chi2 + 2:])
        first += findings.startswith("random_walk")
        print(f"seed {seed}: {findings}", flush=True)
    print(f"random_walk first: {first}/{a.seeds} ({a.size}x at T/8, {a.rate:g} Hz, {a.duration:g} s)")


if __name__ == "__main__":
    main()
