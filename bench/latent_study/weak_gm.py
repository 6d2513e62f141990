"""White noise plus one weak, slow first-order GM, for `latent_fit_study --stdin` (NumPy/SciPy only).

The issue's round-trip cases size every term to carry >= ~40 % of the Allan variance somewhere;
this asks what the fit does when the GM barely shows: its Allan deviation at its hump (tau = 1.89 T)
is `--ratio` times the white noise's there, and T = duration / `--fraction`.
  white  N / sqrt(dt) * normal samples, N = 1e-3 [U sqrt(s)]
  GM     the sampled AR(1), x_k = phi x_{k-1} + sigma sqrt(1 - phi^2) e_k (scipy.signal.lfilter),
         started from its stationary law
Output: per record one JSON line (the format of generate.py) and n little-endian float64 samples.
    python3 bench/latent_study/weak_gm.py --rate 1000 --duration 7200 --ratio 0.75 --fraction 180 \\
        --seeds 20 | build/bench/latent_fit_study --stdin
"""
import argparse
import json
import math
import sys

import numpy as np
from scipy.signal import lfilter


def gm_allan_variance(s2, T, tau):
    """The continuous GM's Allan variance (IEEE Std 952 C), the size reference."""
    return 2.0 * s2 * T / tau * (1.0 - T / (2.0 * tau) * (3.0 - 4.0 * math.exp(-tau / T) + math.exp(-2.0 * tau / T)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rate", type=float, default=1000.0, help="sample rate [Hz]")
    ap.add_argument("--duration", type=float, default=1200.0, help="record length [s]")
    ap.add_argument("--ratio", type=float, default=0.75, help="GM ADEV / white ADEV at tau = 1.89 T")
    ap.add_argument("--fraction", type=float, default=100.0, help="T = duration / fraction")
    ap.add_argument("--seeds", type=int, default=20)
    a = ap.parse_args()
    dt, n, N = 1.0 / a.rate, int(round(a.rate * a.duration)), 1e-3
    T = a.duration / a.fraction
    hump = 1.89 * T
    sigma = a.ratio * N / math.sqrt(hump) / math.sqrt(gm_allan_variance(1.0, T, hump))
    phi = math.exp(-dt / T)
    out = sys.stdout.buffer
    for seed in range(a.seeds):
        rng = np.random.default_rng([seed, int(a.rate), int(a.duration), int(a.fraction)])
        e = rng.standard_normal(n)
        start = [phi * sigma * rng.standard_normal()]  # y_0 = phi y_-1 + ..., y_-1 ~ N(0, sigma^2)
        g = lfilter([sigma * math.sqrt(1.0 - phi * phi)], [1.0, -phi], e, zi=start)[0]
        x = N / math.sqrt(dt) * rng.standard_normal(n) + g
        head = {"case": "white+gm", "rate": a.rate, "duration": a.duration, "seed": seed,
                "terms": {"quantization": False, "white": True, "gm": 1, "flicker": False,
                          "random_walk": False, "drift": False, "ar": False},
                "params": {"white": N, "gm1.sigma": sigma, "gm1.tau": T}, "n": n}
        out.write((json.dumps(head) + "\n").encode())
        out.write(x.astype("<f8").tobytes())


if __name__ == "__main__":
    main()
