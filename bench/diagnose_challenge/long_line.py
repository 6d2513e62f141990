#!/usr/bin/python3
"""A slow line on records longer than the benchmark's 30000-sample cap.

Each record: the white + GM base of long_base.py (the model handed to the diagnosis) plus a
sinusoid of C cycles per record, C log-uniform between 20 and 3 n / L (n samples, L the
diagnosis's Welch segment: the largest power of two <= n / 8 and <= 4096), i.e. below the Welch
test's third bin, its amplitude such that max over tau of its Allan deviation is SIZE x the
base's (closed forms: a line A^2 sin^4(pi f tau) / (pi f tau)^2, the base's
long_base.base_avar). NumPy/SciPy only, no sinsim code. Counts how often `sinsim diagnose` names
sinusoid first (docs/diagnose-log.md, "lines below the Welch bins").

    /usr/bin/python3 bench/diagnose_challenge/long_line.py --sinsim build/sinsim \
        --seeds 16 --size 3 --rate 100 --duration 3600 --work /tmp/long_line
"""
import math

import numpy as np

import long_base as lb


def record(path, seed, size, fs, duration):
    rng, n, dt, x = lb.base_record(seed, fs, duration)
    L = 16
    while L * 2 <= n // 8 and L * 2 <= 4096:
        L *= 2
    cycles = 10 ** rng.uniform(math.log10(20.0), math.log10(3.0 * n / L))
    f = cycles / duration
    tau = np.geomspace(2 * dt, duration / 8, 400)
    shape = np.sin(math.pi * f * tau) ** 4 / (math.pi * f * tau) ** 2  # per unit A^2
    A = size * math.sqrt(1.0 / np.max(shape / lb.base_avar(tau)))
    x += A * np.sin(2 * math.pi * f * np.arange(n) * dt + rng.uniform(0, 2 * math.pi))
    lb.write_record(path, x, dt)
    return f"{cycles:.0f} cycles ({f:.4g} Hz): "


def main():
    a = lb.options(__doc__, 3600.0, "/tmp/long_line")
    first = lb.count_first(a, lambda path, seed: record(path, seed, a.size, a.rate, a.duration), "sinusoid")
    print(f"sinusoid first: {first}/{a.seeds} ({a.size}x, {a.rate:g} Hz, {a.duration:g} s)")


if __name__ == "__main__":
    main()
