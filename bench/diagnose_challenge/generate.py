"""Static IMU records with hidden effects, made without any sinsim code.

The challenge benchmark's generator (docs/diagnose.md, "Challenge benchmark"): a random base
process per channel (white + Gauss-Markov, white + random walk + flicker, a random stable AR(p),
each with or without output quantization), a model file that describes exactly that base, and 0,
1 or 2 hidden effects on one channel, drawn from the diagnosis catalogue and from outside it. An
effect's size is k times the base: k = max over tau of ADEV_effect(tau) / ADEV_base(tau), both
computed here with a plain overlapping Allan deviation on an octave grid.

Everything is NumPy/SciPy; nothing here imports or calls sinsim, so the records are independent
of the simulator whose diagnosis they test.
"""
import math

import numpy as np
from scipy.signal import lfilter

CHANNELS = ["gx", "gy", "gz", "ax", "ay", "az"]
CATALOGUE = ["random_walk", "ramp", "warmup", "sinusoid", "quantization", "outliers",
             "bias_instability", "gauss_markov", "temperature"]
OUT_OF_CATALOGUE = ["telegraph", "bias_step"]
# what a diagnosis may call an out-of-catalogue effect and still be right
# (bias_jumps, the catalogue's name for a bias that steps or switches between two levels, since
# the twenty-fifth session: docs/diagnose-log.md)
EQUIVALENT = {"telegraph": {"gauss_markov", "bias_jumps", "unexplained"},
              "bias_step": {"bias_jumps", "unexplained", "warmup", "ramp"}}

EARTH_RATE = 7.292115e-5
LATITUDE = math.radians(45.0)
GRAVITY = 9.80665


def adev(x, dt, taus_m):
    """Overlapping Allan deviation of the rate series x at cluster sizes taus_m (samples)."""
    theta = np.concatenate(([0.0], np.cumsum(x) * dt))
    out = []
    for m in taus_m:
        d = theta[2 * m:] - 2.0 * theta[m:-m] + theta[:-2 * m]
        out.append(math.sqrt(np.mean(d * d) / (2.0 * (m * dt) ** 2)))
    return np.array(out)


def octave_grid(n):
    m, out = 1, []
    while m <= n // 10:
        out.append(m)
        m *= 2
    return out


# ---------------------------------------------------------------- base processes
def white(rng, n, fs, density):
    return density * math.sqrt(fs) * rng.standard_normal(n)


def gauss_markov(rng, n, fs, sigma, tau):
    phi = math.exp(-1.0 / (fs * tau))
    w = sigma * math.sqrt(1.0 - phi * phi) * rng.standard_normal(n)
    w[0] = sigma * rng.standard_normal()
    return lfilter([1.0], [1.0, -phi], w)


def random_walk(rng, n, fs, K):
    return np.cumsum(K / math.sqrt(fs) * rng.standard_normal(n))


def flicker(rng, n, fs, B):
    """1/f noise by spectral shaping, scaled so that its Allan floor is 0.664 B."""
    spec = np.fft.rfft(rng.standard_normal(n))
    f = np.fft.rfftfreq(n, 1.0 / fs)
    f[0] = f[1]
    x = np.fft.irfft(spec / np.sqrt(f), n)
    grid = octave_grid(n)
    mid = adev(x, 1.0 / fs, grid)[len(grid) // 3: 2 * len(grid) // 3 + 1]
    return x * (0.664 * B / np.median(mid))


def random_stable_ar(rng):
    p = int(rng.integers(1, 6))
    poles = []
    while len(poles) < p:
        r = rng.uniform(0.2, 0.95)
        if p - len(poles) >= 2 and rng.random() < 0.5:
            ang = rng.uniform(0.1, 2.8)
            poles += [r * np.exp(1j * ang), r * np.exp(-1j * ang)]
        else:
            poles.append(r * (1 if rng.random() < 0.7 else -1))
    return np.real(np.poly(poles))  # [1, a1, ..., ap]


def make_base(rng, n, fs, unit_scale, kind):
    """A base process and the model-file effects that describe it (SI units)."""
    N = unit_scale * 10 ** rng.uniform(-0.5, 0.5)  # white density
    T = n / fs
    effects = []
    if kind == "white+gm":
        sigma = N * 10 ** rng.uniform(-1.0, 0.5)
        tau = 10 ** rng.uniform(math.log10(20.0 / fs), math.log10(T / 30.0))
        x = white(rng, n, fs, N) + gauss_markov(rng, n, fs, sigma, tau)
        effects = [("white", {"density": N}), ("gauss_markov", {"sigma": sigma, "tau": tau})]
    elif kind == "white+rw+flicker":
        B = N * 10 ** rng.uniform(-1.5, -0.5)
        K = B * 10 ** rng.uniform(-3.0, -1.5)
        x = white(rng, n, fs, N) + random_walk(rng, n, fs, K) + flicker(rng, n, fs, B)
        effects = [("white", {"density": N}), ("random_walk", {"K": K}),
                   ("bias_instability", {"B": B, "tau_range": [1.0 / fs, T]})]
    else:  # ar
        a = random_stable_ar(rng)
        sigma = N * math.sqrt(fs)
        x = lfilter([1.0], a, sigma * rng.standard_normal(n))
        effects = [("ar", {"a": list(a[1:]), "sigma": sigma, "rate": fs})]
    return x, effects


# ---------------------------------------------------------------- hidden effects (unit size)
def unit_effect(rng, name, n, fs, t, temp):
    T = n / fs
    if name == "random_walk":
        return random_walk(rng, n, fs, 1.0), {}
    if name == "ramp":
        return t / T * rng.choice([-1.0, 1.0]), {}
    if name == "warmup":
        tw = T * 10 ** rng.uniform(-2.0, -0.7)
        return np.exp(-t / tw) * rng.choice([-1.0, 1.0]), {"tau_s": tw}
    if name == "sinusoid":
        f0 = 10 ** rng.uniform(math.log10(20.0 / T), math.log10(fs / 10.0))
        return np.sin(2 * math.pi * f0 * t + rng.uniform(0, 2 * math.pi)), {"frequency_hz": f0}
    if name == "outliers":
        x = np.zeros(n)
        k = rng.choice(n, size=max(5, int(n * 2e-5)), replace=False)
        x[k] = rng.choice([-1.0, 1.0], size=len(k))
        return x, {"count": int(len(k))}
    if name == "bias_instability":
        return flicker(rng, n, fs, 1.0), {}
    if name == "gauss_markov":
        tau = 10 ** rng.uniform(math.log10(20.0 / fs), math.log10(T / 30.0))
        return gauss_markov(rng, n, fs, 1.0, tau), {"tau_s": tau}
    if name == "temperature":
        c2 = rng.uniform(-0.5, 0.5)
        d = temp - 25.0
        return (d + c2 * d * d / 10.0) / 10.0, {}
    if name == "telegraph":
        rate = 10 ** rng.uniform(math.log10(5.0 / T), math.log10(200.0 / T))
        flips = rng.random(n) < rate / fs
        return np.where(np.cumsum(flips) % 2 == 0, 1.0, -1.0), {"switch_rate_hz": rate}
    if name == "bias_step":
        k = int(rng.uniform(0.2, 0.8) * n)
        return np.where(np.arange(n) >= k, 1.0, 0.0), {"at_s": k / fs}
    raise ValueError(name)


def scale_to(effect, base, fs, k):
    """The factor that makes max_tau ADEV_effect / ADEV_base equal to k."""
    grid = octave_grid(len(base))
    ratio = adev(effect, 1.0 / fs, grid) / adev(base, 1.0 / fs, grid)
    return k / max(float(np.max(ratio)), 1e-300)


def quantize(x, q):
    return np.round(x / q) * q
