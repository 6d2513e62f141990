#!/usr/bin/python3
"""A slow line on records longer than the benchmark's 30000-sample cap.

Each record: one gyro channel (gz) of white noise (0.3 deg/sqrt(h)) plus a first-order
Gauss-Markov bias (3e-3 deg/s, tau 60 s) -- the model handed to the diagnosis -- plus a sinusoid
of C cycles per record, C log-uniform between 20 and 3 n / L (n samples, L the diagnosis's Welch
segment: the largest power of two <= n / 8 and <= 4096), i.e. below the Welch test's third bin,
its amplitude such that max over tau of its Allan deviation is SIZE x the base's (closed forms:
a line A^2 sin^4(pi f tau) / (pi f tau)^2, GM 2 s^2 T / tau [1 - T / (2 tau) (3 - 4 e^-tau/T +
e^-2tau/T)], white N^2 / tau). NumPy/SciPy only, no sinsim code. Counts how often
`sinsim diagnose` names sinusoid first (docs/diagnose.md, "lines below the Welch bins").

    /usr/bin/python3 bench/diagnose_challenge/long_line.py --sinsim build/sinsim \
        --seeds 12 --size 3 --rate 100 --duration 3600 --work /tmp/long_line
"""
import argparse
import math
import os
import subprocess

import numpy as np
from scipy.signal import lfilter

D2R = math.pi / 180.0
N_WHITE, GM_SIGMA, GM_TAU = 0.3 * D2R / 60.0, 3e-3 * D2R, 60.0
MODEL = f"""description: white + GM base of long_line.py
gyro:
  z: [{{type: white, density: 0.3 deg/sqrt(h)}}, {{type: gauss_markov, sigma: 0.003 deg/s, tau: 60 s}}]
"""


def base_avar(tau):
    r = tau / GM_TAU
    gm = 2 * GM_SIGMA ** 2 * GM_TAU / tau * (1 - (3 - 4 * np.exp(-r) + np.exp(-2 * r)) / (2 * r))
    return gm + N_WHITE ** 2 / tau


def record(path, seed, size, fs, duration):
    rng = np.random.default_rng(seed)
    n, dt = int(fs * duration), 1.0 / fs
    phi = math.exp(-dt / GM_TAU)
    x = N_WHITE / math.sqrt(dt) * rng.standard_normal(n)
    drive = GM_SIGMA * math.sqrt(1 - phi * phi) * rng.standard_normal(n)
    x += lfilter([1.0], [1.0, -phi], drive, zi=[phi * GM_SIGMA * rng.standard_normal()])[0]
    L = 16
    while L * 2 <= n // 8 and L * 2 <= 4096:
        L *= 2
    cycles = 10 ** rng.uniform(math.log10(20.0), math.log10(3.0 * n / L))
    f = cycles / duration
    tau = np.geomspace(2 * dt, duration / 8, 400)
    shape = np.sin(math.pi * f * tau) ** 4 / (math.pi * f * tau) ** 2  # per unit A^2
    A = size * math.sqrt(1.0 / np.max(shape / base_avar(tau)))
    x += A * np.sin(2 * math.pi * f * np.arange(n) * dt + rng.uniform(0, 2 * math.pi))
    with open(path, "w") as fh:
        fh.write("t[s],gz[rad/s]\n")
        np.savetxt(fh, np.column_stack([np.arange(n) * dt, x]), delimiter=",", fmt="%.10e")
    return cycles, f


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--seeds", type=int, default=12)
    ap.add_argument("--first-seed", type=int, default=1)
    ap.add_argument("--size", type=float, default=3.0)
    ap.add_argument("--rate", type=float, default=100.0)
    ap.add_argument("--duration", type=float, default=3600.0, help="[s]")
    ap.add_argument("--work", default="/tmp/long_line")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    model = os.path.join(a.work, "base.yaml")
    with open(model, "w") as fh:
        fh.write(MODEL)
    first = 0
    for seed in range(a.first_seed, a.first_seed + a.seeds):
        path = os.path.join(a.work, "r.csv")
        cycles, f = record(path, seed, a.size, a.rate, a.duration)
        out = subprocess.run([a.sinsim, "diagnose", path, "--model", model, "--channels", "gz",
                              "--threads", "1"], capture_output=True, text=True, check=True).stdout
        row = next(l.split() for l in out.splitlines() if l.startswith("gz "))
        chi2 = next(i for i, t in enumerate(row) if "/" in t)  # chi2/K, then Ljung-Box p
        findings = " ".join(row[chi2 + 2:])
        first += findings.startswith("sinusoid")
        print(f"seed {seed}: {cycles:.0f} cycles ({f:.4g} Hz): {findings}", flush=True)
    print(f"sinusoid first: {first}/{a.seeds} ({a.size}x, {a.rate:g} Hz, {a.duration:g} s)")


if __name__ == "__main__":
    main()
