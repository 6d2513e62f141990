"""A second, independent generator for the latent-fit study (NumPy only), built differently from
generate.py where there is a choice, with the parameters jittered per seed:

  oversampling  every random term is made at 8x the record's rate and averaged down to it (the
                record's sample is the mean over its interval, as an IMU's increment is)
  white         normal samples at the fine rate (variance N^2 / dt_fine), averaged
  GM            exact AR(1) recursion at the fine rate (phi_fine = exp(-dt_fine / T), stationary
                start) by scipy.signal.lfilter, averaged: a continuous-like GM, not the discrete
                AR(1) at the record's rate that the fit models
  random walk   cumulative sum of fine-rate steps, averaged
  flicker       1/f power-law shaping of an FFT of 4x the record's length (random amplitudes and
                phases: complex normal coefficients scaled by sqrt(S(f))), a random window of the
                record's length taken from it; S(f) = B^2 / (2 pi f) two-sided, i.e. the Allan
                floor (2 ln 2 / pi) B^2 of IEEE 952
  quantization  the cumulative angle rounded to the LSB after averaging, rate = difference / dt
  jitter        each amplitude and correlation time of generate.py's design is multiplied by
                exp(U(-0.35, 0.35)) per seed (about x0.7..x1.4), so the study is not one design point

Output: generate.py's format (one JSON line per record with the true parameters, then n float64
samples), read by `latent_fit_study --stdin`. Seeds: numpy.random.default_rng([7, seed, case,
rate, duration]).

    python3 bench/latent_study/generate_alt.py --rate 100 --duration 7200 --seeds 40 \\
        | build/bench/latent_fit_study --stdin
"""
import math
import sys

import numpy as np
from scipy.signal import lfilter

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import generate  # noqa: E402  the design point and the record writer only
from generate import CASES, parameters  # noqa: E402

OVERSAMPLE = 8


def averaged(fine):
    return fine.reshape(-1, OVERSAMPLE).mean(axis=1)


def gm_fine(rng, n_fine, dt_fine, sigma, tau):
    phi = math.exp(-dt_fine / tau)
    e = sigma * math.sqrt(1.0 - phi * phi) * rng.standard_normal(n_fine)
    zi = [phi * sigma * rng.standard_normal()]  # x_{-1} from the stationary law
    return lfilter([1.0], [1.0, -phi], e, zi=zi)[0]


def flicker(rng, n, dt, B):
    M = 4 * n
    f = np.fft.rfftfreq(M, dt)
    S = np.zeros_like(f)
    S[1:] = B * B / (2.0 * math.pi * f[1:])  # two-sided PSD [U^2/Hz]
    # x = irfft(c) with c_k complex normal of E|c_k|^2 = M S(f_k) / (2 dt) (Parseval for a
    # two-sided S and irfft's 1/M): var x = sum over +-f of S df.
    c = (rng.standard_normal(len(f)) + 1j * rng.standard_normal(len(f))) * np.sqrt(M * S / (2.0 * dt))
    c[0] = 0.0
    c[-1] = c[-1].real * math.sqrt(2.0)
    x = np.fft.irfft(c, M)
    start = rng.integers(0, M - n)
    return x[start:start + n]


def record(case, rate, duration, seed):
    terms, p = parameters(case, rate, duration)
    rng = np.random.default_rng([7, seed, CASES.index(case), int(rate), int(duration)])
    p = {k: v * math.exp(rng.uniform(-0.35, 0.35)) for k, v in p.items()}
    dt = 1.0 / rate
    n = int(round(duration * rate))
    nf, dtf = n * OVERSAMPLE, dt / OVERSAMPLE
    fine = p["white"] / math.sqrt(dtf) * rng.standard_normal(nf)
    for g in (1, 2):
        if f"gm{g}.sigma" in p:
            fine += gm_fine(rng, nf, dtf, p[f"gm{g}.sigma"], p[f"gm{g}.tau"])
    if "random_walk" in p:
        fine += np.cumsum(p["random_walk"] * math.sqrt(dtf) * rng.standard_normal(nf))
    x = averaged(fine)
    if "flicker" in p:
        x += flicker(rng, n, dt, p["flicker"])
    if "quantization" in p:
        lsb = p["quantization"] * math.sqrt(12.0)
        angle = np.round(np.cumsum(x * dt) / lsb) * lsb
        x = np.diff(angle, prepend=0.0) / dt
    return terms, p, x


if __name__ == "__main__":
    try:
        generate.main(record, rates=(100.0,), durations=(1200.0,), seeds=40, doc=__doc__)
    except BrokenPipeError:
        pass
