"""The white + Gauss-Markov base of the long-record studies (long_walk.py, long_line.py).

One gyro channel (gz) of white noise (0.3 deg/sqrt(h)) plus a first-order Gauss-Markov bias
(3e-3 deg/s, tau 60 s): the model handed to the diagnosis, its series, its Allan variance in closed
form, and the loop that diagnoses one record per seed and counts the first findings. NumPy/SciPy
only, no sinsim code.
"""
import argparse
import math
import os
import subprocess

import numpy as np
from scipy.signal import lfilter

D2R = math.pi / 180.0
N_WHITE, GM_SIGMA, GM_TAU = 0.3 * D2R / 60.0, 3e-3 * D2R, 60.0
MODEL = """description: white + GM base of the long-record studies (long_base.py)
gyro:
  z: [{type: white, density: 0.3 deg/sqrt(h)}, {type: gauss_markov, sigma: 0.003 deg/s, tau: 60 s}]
"""


def base_series(rng, n, dt):
    """n samples of the base [rad/s], the GM started in its stationary law."""
    phi = math.exp(-dt / GM_TAU)
    x = N_WHITE / math.sqrt(dt) * rng.standard_normal(n)
    drive = GM_SIGMA * math.sqrt(1 - phi * phi) * rng.standard_normal(n)
    return x + lfilter([1.0], [1.0, -phi], drive, zi=[phi * GM_SIGMA * rng.standard_normal()])[0]


def base_record(seed, fs, duration):
    """The generator of one seed, the samples n, the interval dt [s] and the base's n samples."""
    rng = np.random.default_rng(seed)
    n, dt = int(fs * duration), 1.0 / fs
    return rng, n, dt, base_series(rng, n, dt)


def base_avar(tau):
    """The base's Allan variance [rad^2/s^2]: GM 2 s^2 T / tau [1 - T / (2 tau) (3 - 4 e^-tau/T +
    e^-2tau/T)] plus white N^2 / tau."""
    r = np.asarray(tau) / GM_TAU
    gm = 2 * GM_SIGMA ** 2 * GM_TAU / np.asarray(tau) * (1 - (3 - 4 * np.exp(-r) + np.exp(-2 * r)) / (2 * r))
    return gm + N_WHITE ** 2 / np.asarray(tau)


def write_record(path, x, dt):
    with open(path, "w") as fh:
        fh.write("t[s],gz[rad/s]\n")
        np.savetxt(fh, np.column_stack([np.arange(len(x)) * dt, x]), delimiter=",", fmt="%.10e")


def options(doc, duration, work):
    """The studies' command line: sinsim, seeds, size, rate, duration [s], work folder."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--seeds", type=int, default=12)
    ap.add_argument("--first-seed", type=int, default=1)
    ap.add_argument("--size", type=float, default=3.0)
    ap.add_argument("--rate", type=float, default=100.0)
    ap.add_argument("--duration", type=float, default=duration, help="[s]")
    ap.add_argument("--work", default=work)
    return ap.parse_args()


def count_first(a, make, effect):
    """For seeds a.first_seed.., writes make(path, seed) (returns a note), diagnoses it against the
    base and prints its findings; returns how often `effect` comes first."""
    os.makedirs(a.work, exist_ok=True)
    model = os.path.join(a.work, "base.yaml")
    with open(model, "w") as fh:
        fh.write(MODEL)
    first = 0
    for seed in range(a.first_seed, a.first_seed + a.seeds):
        path = os.path.join(a.work, "r.csv")
        note = make(path, seed)
        out = subprocess.run([a.sinsim, "diagnose", path, "--model", model, "--channels", "gz",
                              "--threads", "1"], capture_output=True, text=True, check=True).stdout
        row = next(l.split() for l in out.splitlines() if l.startswith("gz "))
        chi2 = next(i for i, t in enumerate(row) if "/" in t)  # chi2/K, then Ljung-Box p
        findings = " ".join(row[chi2 + 2:])
        first += findings.startswith(effect)
        print(f"seed {seed}: {note}{findings}", flush=True)
    return first
