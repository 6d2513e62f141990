#!/usr/bin/env python3
"""Where a blind quantization + white record's Allan variance leaves its truth.

Usage: allan_vs_truth.py RECORD.csv RECORD.truth.json [SIMULATIONS]

Simulates SIMULATIONS (default 100) independent records of the truth's white noise + bias rounded
on its angle LSB (uniform start phase, the integral rounded and differenced, as generate.py makes
them) and prints, at octave m, the record's overlapping Allan variance over the simulations' mean
and its z score against their spread: a record far outside (|z| > 3 over several m) holds
structure its truth does not, and a fit that adds a term there reads the data, not a method error
(docs/fitting-log.md, "Quantization below one LSB per sample"). Independent of sinsim's code.
"""
import json
import sys

import numpy as np


def oavar(y, m, dt):
    c = np.concatenate([[0.0], np.cumsum(y)]) * dt
    d = c[2 * m:] - 2 * c[m:-m] + c[:-2 * m]
    return np.mean(d * d) / (2 * (m * dt) ** 2)


def main():
    rec, truth = sys.argv[1], sys.argv[2]
    sims = int(sys.argv[3]) if len(sys.argv) > 3 else 100
    t = json.load(open(truth))
    dt = 1.0 / t["rate_hz"]
    x = np.deg2rad(np.loadtxt(rec, skiprows=1)[1:])  # deg/s; the first sample holds the start
    D = next(q for q in t["terms"] if q["type"] == "quantization")["lsb_angle"]
    N = next(q for q in t["terms"] if q["type"] == "white")["N"]
    ms = [2 ** i for i in range(0, 30) if 2 ** i * 10 < len(x)]
    a = np.array([oavar(x, m, dt) for m in ms])
    rng = np.random.default_rng(1)
    s = []
    for _ in range(sims):
        th = (rng.uniform(0, D) + np.cumsum(N * np.sqrt(dt) * rng.standard_normal(len(x) + 1))
              + t["bias"] * dt * np.arange(len(x) + 1))
        y = np.diff(D * np.round(th / D)) / dt
        s.append([oavar(y, m, dt) for m in ms])
    s = np.array(s)
    mu, sd = s.mean(0), s.std(0)
    print(f"motion {N * np.sqrt(dt) / D:.4f} LSB per sample, {sims} simulations")
    for m, ai, mi, si in zip(ms, a, mu, sd):
        print(f"m {m:7d}  record/mean {ai / mi:.4f}  z {(ai - mi) / si:+.2f}")


if __name__ == "__main__":
    main()
