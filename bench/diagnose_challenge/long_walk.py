#!/usr/bin/python3
"""A random walk the model lacks, on records longer than the benchmark's 30000-sample cap.

Each record: the white + GM base of long_base.py (the model handed to the diagnosis) plus a random
walk whose Allan deviation at T/8 is SIZE x the base's there (closed forms: walk K^2 tau / 3, the
base's GM by its long-tau asymptote 2 sigma^2 T_gm / tau, white N^2 / tau; the sizes of
docs/diagnose.md were measured so). NumPy/SciPy only, no sinsim code. Counts how often
`sinsim diagnose` names random_walk first (docs/diagnose-log.md, "a long record's walk is no level step").

    /usr/bin/python3 bench/diagnose_challenge/long_walk.py --sinsim build/sinsim \
        --seeds 12 --size 3 --rate 100 --duration 7200 --work /tmp/long_walk
"""
import math

import numpy as np

import long_base as lb


def record(path, seed, size, fs, duration):
    rng, n, dt, x = lb.base_record(seed, fs, duration)
    tau8 = duration / 8
    base = math.sqrt(lb.GM_SIGMA ** 2 * 2 * lb.GM_TAU / tau8 + lb.N_WHITE ** 2 / tau8)
    k = size * base / math.sqrt(tau8 / 3)
    x += np.cumsum(k * math.sqrt(dt) * rng.standard_normal(n))
    lb.write_record(path, x, dt)
    return ""


def main():
    a = lb.options(__doc__, 7200.0, "/tmp/long_walk")
    first = lb.count_first(a, lambda path, seed: record(path, seed, a.size, a.rate, a.duration), "random_walk")
    print(f"random_walk first: {first}/{a.seeds} ({a.size}x at T/8, {a.rate:g} Hz, {a.duration:g} s)")


if __name__ == "__main__":
    main()
