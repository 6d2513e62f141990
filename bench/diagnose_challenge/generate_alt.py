#!/usr/bin/python3
"""A second, independent record generator for the diagnosis challenge (challenge.py --generator alt).

Designed from physics and from the model format (docs/model-format.md) only, without reading the
first generator or the diagnosis, so that `sinsim diagnose` is scored on records whose design did
not come from the people who wrote it. NumPy / SciPy only; nothing here calls sinsim.

Records
-------
Static IMU at latitude 45 deg (gx = Omega cos(lat), gz = -Omega sin(lat), az = -9.80665, others 0),
rates 64 / 125 / 256 / 400 / 800 / 1600 Hz, durations log-uniform 20 min .. 4 h, capped at
max_samples. Every channel draws its own base family (one of FAMILIES):

  w2gm   white + two Gauss-Markov processes, correlation times 1-2 decades apart
  wgmrw  white + Gauss-Markov + random walk
  wflk   white + flicker synthesised as 4-6 Gauss-Markov processes spread over the decades
         (written into the model as those gauss_markov terms, so the model is exact), sometimes + RW
  ar     a random stable AR(p), p = 1..4, at the record rate (real and complex poles), mostly + white

and, on ~20 % of the channels, output quantization (LSB 0.3-1.5 one-sample sd; the whole output,
truth included, is rounded; the model lists it last). Gauss-Markov and AR start stationary (exact
discrete recursions via lfilter). The model YAML lists exactly these terms per axis.

A temp column (deg C, with sensor noise and a 1/16, 1/100 or 1/256 deg C resolution) is written
whenever a temperature effect is hidden, and on ~40 % of the other records as a distractor
(a climatic-chamber cycle that no channel follows).

Hidden effects
--------------
0, 1 or 2 (probabilities 0.15 / 0.60 / 0.25) on one channel, drawn without repetition from the
pool. Catalogue effects and how they are made:

  white            extra Gaussian white noise
  random_walk      cumulative sum of N(0, K^2 dt)
  ramp             R t
  warmup           A exp(-t/tau1) (+ with probability 0.4 a faster B exp(-t/tau2), same sign),
                   tau1 3-30 % of the record
  sinusoid         one line at f log-uniform in [20/T, fs/8], random phase; with probability 0.3 a
                   second line
  quantization     output rounding (LSB 0.5-5 one-sample sd)
  outliers         3-40 isolated one-sample spikes, Pareto (alpha 1.5) amplitudes, random sign
  bias_instability flicker by FFT shaping (1/f over [1/(4T), fs/2], synthesised on 4 T and cut)
  gauss_markov     first-order GM, tau log-uniform in [30 samples, T/20]
  temperature      temp profile (warming curve / chamber cycling / ambient wander) and a bias
                   c1 (T' - T0) + c2 (T' - T0)^2 where T' is the true temperature, through a
                   first-order thermal lag on half of the records

Size (this generator's own definition)
--------------------------------------
size = ADEV(effect) / ADEV(base) at ONE characteristic averaging time tau_c of the effect, both the
expected (ensemble) values: the base's from its exact discrete autocovariance, a stochastic
effect's from its own (white, RW, GM, telegraph) or its spectrum (flicker), a deterministic
effect's from the signal itself. tau_c:

  ramp, random_walk, bias_instability, temperature, bias_step   T / 10 (the long-term drift)
  warmup                                                        tau1 (its time constant)
  gauss_markov, telegraph                                       1.89 tau (the ADEV peak of a GM)
  sinusoid, square_wave                                         0.371 / f (the ADEV peak of a line)
  white                                                         one sample

Two exceptions, not ADEV ratios: quantization: size = LSB / sigma1; outliers: size = median spike
amplitude / (5 sigma1), where sigma1 = the base's one-sample ADEV (its sample-to-sample sd; for
white noise the one-sample sd). Sizes are log-uniform in [1.5, 10] (quantization [0.5, 5]).

Two-effect channels also carry "visibility": max over an octave tau grid of ADEV(effect) /
ADEV(base + the other effect), both from this module's overlapping ADEV of the realisations.

Out of catalogue
----------------
  telegraph    random telegraph (two-level, Markov switching, possibly asymmetric) bias
  bias_step    one bias step at 15-85 % of the record, logistic edge 0-0.5 % of the record wide
  square_wave  a heater's on/off cycling: a square wave (duty 35-65 %), on half of the records
               through a first-order thermal lag
"""
import math
import os

import numpy as np
from scipy import fft as sfft
from scipy.signal import lfilter

CATALOGUE = ["white", "random_walk", "ramp", "warmup", "sinusoid", "quantization", "outliers",
             "bias_instability", "gauss_markov", "temperature"]
OUT_OF_CATALOGUE = ["telegraph", "bias_step", "square_wave"]
EQUIVALENT = {
    # Markov two-level switching has the autocovariance var * exp(-|t| / tau) of a first-order
    # Gauss-Markov process (Lorentzian PSD, the same ADEV); only its two-level amplitude
    # distribution differs, which a second-order (ADEV/PSD) test cannot see; its switches, where
    # the record shows them, are bias jumps between two levels (bias_jumps, telegraph: yes).
    "telegraph": {"gauss_markov", "bias_jumps", "unexplained"},
    # a single step: its largest-scale component is a linear trend (what a least-squares ramp
    # fits), and a step-like settling of the bias is what an exponential settling with a short
    # time constant away from t = 0 approximates; the exact term is a bias jump (bias_jumps, since
    # the twenty-fifth session), and a diagnosis may leave it unexplained.
    "bias_step": {"bias_jumps", "unexplained", "warmup", "ramp"},
    # a periodic non-sinusoidal bias is a set of lines at f, 3f, 5f...; the fundamental carries
    # >= 80 % of a 35-65 % duty square wave's power (more through the lag), so a sinusoid at f is
    # the right first-order description; the harmonics may leave it unexplained.
    "square_wave": {"sinusoid", "unexplained"},
}
FAMILIES = ["w2gm", "wgmrw", "wflk", "ar"]
RATES = [64.0, 125.0, 256.0, 400.0, 800.0, 1600.0]
CHANNELS = ["gx", "gy", "gz", "ax", "ay", "az"]
OMEGA = 7.292115e-5
LAT = math.radians(45.0)
TRUTH = {"gx": OMEGA * math.cos(LAT), "gy": 0.0, "gz": -OMEGA * math.sin(LAT),
         "ax": 0.0, "ay": 0.0, "az": -9.80665}
GYRO_N = (math.radians(0.002), math.radians(0.02))  # rad/s/sqrt(Hz)
ACCEL_N = (0.3e-3, 3e-3)                             # m/s^2/sqrt(Hz)
SIZE_RANGE = (1.5, 10.0)
LSB_RANGE = (0.5, 5.0)


def logu(rng, lo, hi):
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


# ---------------------------------------------------------------- Allan deviation (own code)

def adev(x, ms):
    """Overlapping Allan deviation of x at cluster sizes ms (samples)."""
    x = np.asarray(x, float)
    x = x - x.mean()
    c = np.concatenate(([0.0], np.cumsum(x)))
    out = []
    for m in ms:
        m = int(m)
        y = (c[m:] - c[:-m]) / m  # averages of m samples, start 0..n-m
        d = y[m:] - y[:-m]
        out.append(math.sqrt(0.5 * np.mean(d * d)) if len(d) else float("nan"))
    return np.array(out)


def octave_grid(n):
    ms, m = [], 1
    while m <= n // 4:
        ms.append(m)
        m *= 2
    return ms


def avar_acov(r, m):
    """Expected AVAR at m samples of a stationary process with autocovariance r[0..] (zero beyond)."""
    j = np.arange(1, 2 * m)
    rr = np.zeros(2 * m)
    k = min(len(r), 2 * m)
    rr[:k] = r[:k]
    first = m * rr[0] + 2.0 * np.sum((m - j[:m - 1]) * rr[1:m])
    second = np.sum((m - np.abs(j - m)) * rr[1:2 * m])
    return (first - second) / (m * m)


def avar_gm(s2, phi, m):
    """Discrete GM x_k = phi x_(k-1) + w, stationary variance s2."""
    jmax = 2 * m
    if phi > 0:
        # the terms fall below 1e-18 s2 after this many lags
        jmax = min(jmax, int(-41.5 / math.log(phi)) + 2) if phi < 1 else jmax
    r = s2 * phi ** np.arange(max(jmax, 1))
    return avar_acov(r, m)


def avar_rw(q, m):
    """Discrete random walk with increment variance q."""
    return q * (2.0 * m * m + 1.0) / (6.0 * m)


def avar_spec(P, f, m):
    """Expected AVAR of a sum of random-phase cosines: variance P at f cycles/sample."""
    s = np.sin(np.pi * f)
    h = 2.0 * np.sin(np.pi * f * m) ** 4 / (m * m * s * s)
    return float(np.sum(P * h))


def ar_acov(a, sigma, tol=1e-13):
    """Autocovariance of x with A(z) x = e, A = 1 + a1 z^-1 + ..., var(e) = sigma^2."""
    rho = np.max(np.abs(np.roots(np.concatenate(([1.0], a)))))
    L = int(math.log(tol) / math.log(max(rho, 1e-3))) + 16
    imp = np.zeros(L)
    imp[0] = 1.0
    h = lfilter([1.0], np.concatenate(([1.0], a)), imp)
    N = sfft.next_fast_len(2 * L)
    H = sfft.rfft(h, N)
    r = sfft.irfft(np.abs(H) ** 2, N)[:L]
    return sigma * sigma * r


# ---------------------------------------------------------------- base

class Base:
    """One channel's base: terms (for the model) and its expected AVAR."""

    def __init__(self, fs, n):
        self.fs, self.n, self.dt = fs, n, 1.0 / fs
        self.white = 0.0      # one-sample variance
        self.gms = []         # (sigma, tau)
        self.rw = 0.0         # K
        self.ar = None        # (a, sigma)
        self.ar_r = None
        self.lsb = None       # base quantization

    def avar(self, m):
        v = self.white / m
        for s, tau in self.gms:
            v += avar_gm(s * s, math.exp(-self.dt / tau), m)
        if self.rw:
            v += avar_rw(self.rw ** 2 * self.dt, m)
        if self.ar is not None:
            if self.ar_r is None:
                self.ar_r = ar_acov(*self.ar)
            v += avar_acov(self.ar_r, m)
        if self.lsb:
            v += self.lsb ** 2 / 12.0 / m  # rounding noise, white to first order
        return v

    def adev(self, m):
        return math.sqrt(self.avar(int(m)))

    def sigma1(self):
        """The base's one-sample ADEV: its sample-to-sample sd (white noise: the one-sample sd)."""
        return self.adev(1)

    def simulate(self, rng):
        n, dt = self.n, self.dt
        x = np.zeros(n)
        if self.white:
            x += rng.standard_normal(n) * math.sqrt(self.white)
        for s, tau in self.gms:
            phi = math.exp(-dt / tau)
            w = rng.standard_normal(n) * s * math.sqrt(1.0 - phi * phi)
            x0 = rng.standard_normal() * s
            x += lfilter([1.0], [1.0, -phi], w, zi=[phi * x0])[0]
        if self.rw:
            x += np.cumsum(rng.standard_normal(n)) * self.rw * math.sqrt(dt)
        if self.ar is not None:
            a, sig = self.ar
            rho = np.max(np.abs(np.roots(np.concatenate(([1.0], a)))))
            burn = int(math.log(1e-12) / math.log(max(rho, 1e-3))) + 64
            e = rng.standard_normal(n + burn) * sig
            x += lfilter([1.0], np.concatenate(([1.0], a)), e)[burn:]
        return x

    def yaml_terms(self, su):
        t = []
        if self.white:
            t.append(f"{{type: white, density: {math.sqrt(self.white * self.dt)!r} {su}/sqrt(Hz)}}")
        for s, tau in self.gms:
            t.append(f"{{type: gauss_markov, sigma: {s!r} {su}, tau: {tau!r} s}}")
        if self.rw:
            t.append(f"{{type: random_walk, K: {self.rw!r} {su}/sqrt(s)}}")
        if self.ar is not None:
            a, sig = self.ar
            aa = ", ".join(repr(float(v)) for v in a)
            t.append(f"{{type: ar, a: [{aa}], sigma: {sig!r} {su}, rate: {self.fs!r} Hz}}")
        if self.lsb:
            t.append(f"{{type: quantization, lsb: {self.lsb!r} {su}}}")
        return t


def draw_base(rng, family, fs, n, N):
    """family's base on one channel; N = white density (signal/sqrt(Hz))."""
    b = Base(fs, n)
    dt, T = 1.0 / fs, n / fs
    sw = N * math.sqrt(fs)  # one-sample sd of the white

    def white_adev(tau):
        return N / math.sqrt(tau)

    def gm_at_peak(tau, ratio):  # sigma whose ADEV peak (0.62 sigma at 1.89 tau) is ratio * white there
        return ratio * white_adev(1.89 * tau) / 0.62

    if family == "w2gm":
        b.white = sw * sw
        t1 = logu(rng, 20 * dt, max(T / 300, 25 * dt))
        t2 = min(t1 * logu(rng, 10, 100), T / 5)
        for tau in (t1, t2):
            b.gms.append((gm_at_peak(tau, logu(rng, 0.5, 4.0)), tau))
    elif family == "wgmrw":
        b.white = sw * sw
        tau = logu(rng, 20 * dt, T / 20)
        b.gms.append((gm_at_peak(tau, logu(rng, 0.5, 4.0)), tau))
        b.rw = logu(rng, 0.5, 3.0) * white_adev(T / 10) / math.sqrt(T / 10 / 3)
    elif family == "wflk":
        b.white = sw * sw
        k = int(rng.integers(4, 7))
        lo = logu(rng, 3 * dt, 30 * dt)
        hi = T / logu(rng, 3, 10)
        taus = np.logspace(math.log10(lo), math.log10(hi), k) * 10 ** rng.uniform(-0.1, 0.1, k)
        mid = math.sqrt(lo * hi)
        # equal sigmas give 1/f; the floor of such a comb is ~0.45 sigma (spacing ~ a decade)
        s0 = logu(rng, 0.5, 3.0) * white_adev(mid) / 0.45
        for tau in sorted(taus):
            b.gms.append((s0 * logu(rng, 0.8, 1.25), float(tau)))
        if rng.random() < 0.3:
            b.rw = logu(rng, 0.3, 2.0) * white_adev(T / 10) / math.sqrt(T / 10 / 3)
    elif family == "ar":
        p = int(rng.integers(1, 5))
        poles = []
        while len(poles) < p:
            if p - len(poles) >= 2 and rng.random() < 0.5:
                r, th = rng.uniform(0.5, 0.98), rng.uniform(0.05, 0.9) * math.pi
                poles += [r * np.exp(1j * th), r * np.exp(-1j * th)]
            else:
                r = rng.uniform(0.5, 0.995) if rng.random() < 0.8 else -rng.uniform(0.2, 0.8)
                poles.append(r)
        a = np.real(np.poly(poles))[1:]
        r0 = ar_acov(a, 1.0)[0]
        if rng.random() < 0.7:
            b.white = sw * sw
            sd = logu(rng, 0.5, 3.0) * sw
        else:
            sd = logu(rng, 1.0, 3.0) * sw
        b.ar = (np.array([float(v) for v in a]), sd / math.sqrt(r0))
    else:
        raise ValueError(family)
    return b


# ---------------------------------------------------------------- temperature

def temp_profile(rng, t, kind):
    """True temperature (deg C) along t."""
    T = t[-1] + (t[1] - t[0])
    if kind == "warming":
        amb, dT, th = rng.uniform(15, 30), rng.uniform(3, 15), rng.uniform(0.05, 0.3) * T
        x = amb + dT * (1 - np.exp(-t / th))
        x += rng.uniform(0, 0.5) * np.sin(2 * np.pi * t / (rng.uniform(0.5, 2) * T) + rng.uniform(0, 2 * np.pi))
    elif kind == "chamber":
        lo = rng.uniform(-20, 10)
        hi = lo + rng.uniform(15, 50)
        ncyc = rng.uniform(1.5, 4)
        P = T / ncyc
        fr = rng.dirichlet([2, 1, 2, 1])  # ramp up, soak hot, ramp down, soak cold
        knots_t, knots_v = [], []
        t0 = -rng.uniform(0, 1) * P
        while t0 < T + P:
            knots_t += [t0, t0 + fr[0] * P, t0 + (fr[0] + fr[1]) * P, t0 + (fr[0] + fr[1] + fr[2]) * P]
            knots_v += [lo, hi, hi, lo]
            t0 += P
        x = np.interp(t, knots_t, knots_v)
        lag = rng.uniform(0.002, 0.01) * T
        x = first_order_lag(x, t[1] - t[0], lag, x[0])
    elif kind == "ambient":
        tau = rng.uniform(0.05, 0.2) * T
        dt = t[1] - t[0]
        phi = math.exp(-dt / tau)
        s = rng.uniform(0.5, 3.0)
        w = rng.standard_normal(len(t)) * s * math.sqrt(1 - phi * phi)
        x = 20 + lfilter([1.0], [1.0, -phi], w, zi=[phi * rng.standard_normal() * s])[0]
        x += rng.uniform(-2, 2) * t / T
    else:
        raise ValueError(kind)
    return x


def first_order_lag(x, dt, tau, x0):
    a = math.exp(-dt / tau)
    return lfilter([1 - a], [1.0, -a], x, zi=[a * x0])[0]


def measured_temp(rng, x):
    res = [0.0625, 0.01, 0.00390625][int(rng.integers(0, 3))]
    return np.round((x + rng.standard_normal(len(x)) * rng.uniform(0.005, 0.05)) / res) * res


# ---------------------------------------------------------------- effects

def flicker_unit(rng, n):
    """Unit 1/f noise by FFT shaping on 4n (cut to n) and its exact expected-AVAR function."""
    L = sfft.next_fast_len(4 * n)
    b = np.arange(1, L // 2)
    S = 1.0 / b
    X = np.zeros(L // 2 + 1, complex)
    X[1:L // 2] = np.sqrt(S / 2) * (rng.standard_normal(len(b)) + 1j * rng.standard_normal(len(b)))
    x = sfft.irfft(X, L)[:n]
    P, f = 2 * S / L ** 2, b / L
    return x, (lambda m: avar_spec(P, f, m))


def telegraph(rng, n, dt, tau, p):
    """Two-level Markov switching, fraction p of the time high, correlation time tau; zero mean,
    levels -p and 1-p (variance p(1-p))."""
    T = n * dt
    up, down = tau / p, tau / (1 - p)  # mean dwell low, high
    state = rng.random() < p
    times, states, t = [0.0], [state], 0.0
    while t < T:
        t += rng.exponential(down if state else up)
        state = not state
        times.append(t)
        states.append(state)
    idx = np.searchsorted(np.array(times), np.arange(n) * dt, side="right") - 1
    return np.array(states, float)[idx] - p


def make_effect(rng, name, base, t, temp_true):
    """(signal at unit-free final scale, info dict). Scales to a drawn size with this module's
    definition."""
    n, fs, dt = base.n, base.fs, base.dt
    T = n * dt
    size = logu(rng, *SIZE_RANGE)
    info = {"effect": name}

    def mc(tau):
        return int(min(max(round(tau * fs), 1), n // 4))

    def scale_det(sig, tau_c):  # deterministic: numeric ADEV of the signal itself
        m = mc(tau_c)
        return sig * (size * base.adev(m) / adev(sig, [m])[0]), m

    if name == "white":
        m = 1
        s = size * base.adev(1)
        x = rng.standard_normal(n) * s
        info.update(density=s * math.sqrt(dt))
    elif name == "random_walk":
        m = mc(T / 10)
        K = size * base.adev(m) / math.sqrt(avar_rw(dt, m))
        x = np.cumsum(rng.standard_normal(n)) * K * math.sqrt(dt)
        info.update(K=K)
    elif name == "ramp":
        x, m = scale_det(t.copy(), T / 10)
        info.update(slope=float(x[1] - x[0]) / dt)
    elif name == "warmup":
        t1 = rng.uniform(0.03, 0.3) * T
        sig = np.exp(-t / t1)
        if rng.random() < 0.4:
            t2 = t1 / rng.uniform(3, 10)
            sig = sig + rng.uniform(0.3, 1.5) * np.exp(-t / t2)
            info.update(tau2=t2)
        sig *= rng.choice([-1.0, 1.0])
        x, m = scale_det(sig, t1)
        info.update(tau=t1, amplitude=float(x[0]))
    elif name == "sinusoid":
        f = logu(rng, 20 / T, fs / 8)
        sig = np.sin(2 * np.pi * f * t + rng.uniform(0, 2 * np.pi))
        info.update(frequency=f)
        if rng.random() < 0.3:
            f2 = f * logu(rng, 1.5, 8)
            if f2 > fs / 8:
                f2 = f / logu(rng, 1.5, 8)
            if f2 > 2 / T:
                sig = sig + rng.uniform(0.3, 1.0) * np.sin(2 * np.pi * f2 * t + rng.uniform(0, 2 * np.pi))
                info.update(frequency2=f2)
        x, m = scale_det(sig, 0.371 / f)
    elif name == "square_wave":
        f = logu(rng, 20 / T, fs / 20)
        duty = rng.uniform(0.35, 0.65)
        ph = (f * t + rng.uniform(0, 1)) % 1.0
        sig = np.where(ph < duty, 1.0 - duty, -duty)
        if rng.random() < 0.5:
            lag = rng.uniform(0.02, 0.15) / f
            sig = first_order_lag(sig, dt, lag, sig[0])
            info.update(lag=lag)
        info.update(frequency=f, duty=duty)
        x, m = scale_det(sig - sig.mean(), 0.371 / f)
    elif name == "bias_step":
        ts = rng.uniform(0.15, 0.85) * T
        w = rng.uniform(0, 0.005) * T
        if w < 2 * dt:
            sig = (t >= ts).astype(float)
        else:
            sig = 0.5 * (1 + np.tanh((t - ts) / w))
        sig *= rng.choice([-1.0, 1.0])
        x, m = scale_det(sig - sig.mean(), T / 10)
        info.update(time=ts, width=w, step=float(x[-1] - x[0]))
    elif name == "gauss_markov" or name == "telegraph":
        tau = logu(rng, 30 * dt, T / (20 if name == "gauss_markov" else 30))
        m = mc(1.89 * tau)
        phi = math.exp(-dt / tau)
        s = size * base.adev(m) / math.sqrt(avar_gm(1.0, phi, m))
        if name == "gauss_markov":
            w = rng.standard_normal(n) * s * math.sqrt(1 - phi * phi)
            x = lfilter([1.0], [1.0, -phi], w, zi=[phi * rng.standard_normal() * s])[0]
            info.update(sigma=s, tau=tau)
        else:
            p = rng.uniform(0.3, 0.7)
            x = telegraph(rng, n, dt, tau, p) * (s / math.sqrt(p * (1 - p)))
            info.update(tau=tau, high_fraction=p, levels_apart=s / math.sqrt(p * (1 - p)))
    elif name == "bias_instability":
        m = mc(T / 10)
        u, av = flicker_unit(rng, n)
        k = size * base.adev(m) / math.sqrt(av(m))
        x = u * k
        info.update(floor=k * math.sqrt(av(mc(math.sqrt(T * dt)))))  # the flat part, for reference
    elif name == "temperature":
        m = mc(T / 10)
        tt = temp_true
        if rng.random() < 0.5:
            lag = rng.uniform(0.001, 0.01) * T
            tt = first_order_lag(tt, dt, lag, tt[0])
            info.update(lag=lag)
        T0 = float(np.round(rng.uniform(15, 30), 1))
        d = tt - T0
        span = max(float(np.ptp(tt)), 1e-6)
        c1 = rng.choice([-1.0, 1.0])
        c2 = rng.uniform(-0.5, 0.5) * abs(c1) / span
        sig = c1 * d + c2 * d * d
        x, m = scale_det(sig, T / 10)
        kk = float(x[1] / sig[1]) if sig[1] != 0 else float(np.dot(x, sig) / np.dot(sig, sig))
        info.update(T0=T0, c1=c1 * kk, c2=c2 * kk)
    elif name == "outliers":
        s1 = base.sigma1()
        cnt = int(round(logu(rng, 3, 40)))
        cnt = min(cnt, n // 50)
        pos = np.sort(rng.choice(np.arange(5, n - 5, 10), size=cnt, replace=False))  # >= 10 apart
        alpha = 1.5
        med = size * 5 * s1
        amp = np.minimum(med / 2 ** (1 / alpha) * rng.random(cnt) ** (-1 / alpha), 20 * med)
        x = np.zeros(n)
        x[pos] = amp * rng.choice([-1.0, 1.0], cnt)
        info.update(size=size, count=cnt, median_amplitude=float(np.median(amp)), tau_c=dt)
        return x, info
    else:
        raise ValueError(name)
    info.update(size=size, tau_c=m * dt)
    return x, info


# ---------------------------------------------------------------- record

def fmt_num(v):
    return repr(float(v))


def make(rng, idx, work, max_samples, bases=None, null=False, effects=None, pool="all"):
    families = list(bases) if bases else FAMILIES
    for f in families:
        if f not in FAMILIES:
            raise ValueError(f"alt generator: unknown base family {f!r} (one of {FAMILIES})")
    pools = {"all": CATALOGUE + OUT_OF_CATALOGUE, "catalogue": CATALOGUE, "ooc": OUT_OF_CATALOGUE}
    fs = float(RATES[int(rng.integers(0, len(RATES)))])
    dur = logu(rng, 20 * 60, 4 * 3600)
    n = int(min(round(dur * fs), max_samples))
    t = np.arange(n) / fs
    ch = CHANNELS[int(rng.integers(0, 6))]
    if null:
        k = 0
    elif effects is not None:
        k = int(effects)
    else:
        k = int(rng.choice([0, 1, 2], p=[0.15, 0.6, 0.25]))
    names = [str(x) for x in rng.choice(pools[pool], size=k, replace=False)] if k else []

    temp_kind = None
    if "temperature" in names:
        temp_kind = str(rng.choice(["warming", "chamber", "ambient"], p=[0.25, 0.45, 0.3]))
    elif rng.random() < 0.4:
        temp_kind = "chamber"
    temp_true = temp_profile(rng, t, temp_kind) if temp_kind else None

    cols, model = {}, {"gyro": {}, "accel": {}}
    hidden = []
    for c in CHANNELS:
        gyro = c[0] == "g"
        N = logu(rng, *(GYRO_N if gyro else ACCEL_N))
        b = draw_base(rng, families[int(rng.integers(0, len(families)))], fs, n, N)
        if rng.random() < 0.2 and not (c == ch and "quantization" in names):
            b.lsb = logu(rng, 0.3, 1.5) * b.sigma1()
        x = b.simulate(rng)
        lsb = b.lsb
        if c == ch and names:
            sigs = []
            for name in names:
                if name == "quantization":
                    size = logu(rng, *LSB_RANGE)
                    lsb = size * b.sigma1()
                    hidden.append({"effect": name, "size": size, "lsb": lsb, "tau_c": 1.0 / fs})
                    sigs.append(None)
                    continue
                e, info = make_effect(rng, name, b, t, temp_true)
                hidden.append(info)
                sigs.append(e)
            if len(names) == 2:
                for i in range(2):
                    if sigs[i] is None:  # quantization: its ADEV is its rounding noise
                        own = np.round((x + TRUTH[c]) / lsb) * lsb - TRUTH[c] - x
                        if sigs[1 - i] is not None:
                            own = np.round((x + sigs[1 - i] + TRUTH[c]) / lsb) * lsb - TRUTH[c] - x - sigs[1 - i]
                        rest = x + (sigs[1 - i] if sigs[1 - i] is not None else 0)
                    else:
                        own = sigs[i]
                        rest = x + (sigs[1 - i] if sigs[1 - i] is not None else 0)
                    ms = octave_grid(n)
                    hidden[i]["visibility"] = float(np.max(adev(own, ms) / adev(rest, ms)))
            for e in sigs:
                if e is not None:
                    x = x + e
        y = x + TRUTH[c]
        if lsb:
            y = np.round(y / lsb) * lsb
        cols[c] = y
        su = "rad/s" if gyro else "m/s^2"
        model["gyro" if gyro else "accel"][c[1]] = (b.yaml_terms(su), b)

    os.makedirs(work, exist_ok=True)
    csv = os.path.join(work, f"r{idx:04d}.csv")
    yml = os.path.join(work, f"r{idx:04d}.yaml")
    data = [t] + [cols[c] for c in CHANNELS]
    header = "t,gx,gy,gz,ax,ay,az"
    fmt = ["%.8f"] + ["%.12g"] * 6
    if temp_true is not None:
        data.append(measured_temp(rng, temp_true))
        header += ",temp"
        fmt.append("%.6f")
    np.savetxt(csv, np.column_stack(data), fmt=fmt, delimiter=",", header=header, comments="")
    with open(yml, "w") as f:
        f.write(f"# generate_alt.py record {idx}: the base of every channel, exactly\n")
        f.write(f'description: "alt challenge record {idx}, {fs:g} Hz, {n} samples"\n')
        for sensor in ("gyro", "accel"):
            f.write(f"{sensor}:\n")
            for ax in "xyz":
                f.write(f"  {ax}:\n")
                for term in model[sensor][ax][0]:
                    f.write(f"    - {term}\n")
    for h in hidden:
        for k2, v in list(h.items()):
            if isinstance(v, (np.floating, np.integer)):
                h[k2] = v.item()
    return {"record": csv, "model": yml, "rate_hz": fs, "samples": n, "channel": ch, "hidden": hidden,
            "temp": temp_kind,
            "bases": {c: type_of(model["gyro" if c[0] == "g" else "accel"][c[1]][1]) for c in CHANNELS}}


def type_of(b):
    parts = []
    if b.white:
        parts.append("white")
    if b.gms:
        parts.append(f"{len(b.gms)}gm")
    if b.rw:
        parts.append("rw")
    if b.ar is not None:
        parts.append(f"ar{len(b.ar[0])}")
    if b.lsb:
        parts.append("q")
    return "+".join(parts)


# ---------------------------------------------------------------- self-check

def _check(seed=3, n=200000, fs=400.0):
    """Sizes mean what the docstring says: numeric ADEV of effect / base realisations at tau_c."""
    rng = np.random.default_rng(seed)
    t = np.arange(n) / fs
    temp = temp_profile(rng, t, "chamber")
    # the expected base AVAR against realisations
    for fam in FAMILIES:
        b = draw_base(rng, fam, fs, n, 1e-3)
        ms = [1, 16, 256, 4096, n // 10]
        reals = np.array([adev(b.simulate(rng), ms) for _ in range(8)])
        rms = np.sqrt(np.mean(reals ** 2, axis=0))
        print(f"base {fam:6s} {type_of(b):14s} expected/realised ADEV at m={ms}: "
              + " ".join(f"{b.adev(m) / r:.3f}" for m, r in zip(ms, rms)))
    for name in CATALOGUE + OUT_OF_CATALOGUE:
        if name == "quantization":
            continue
        b = draw_base(rng, FAMILIES[int(rng.integers(0, 4))], fs, n, 1e-3)
        e, info = make_effect(rng, name, b, t, temp)
        m = max(1, int(round(info["tau_c"] * fs)))
        base_real = adev(b.simulate(rng), [m])[0]
        if name == "outliers":
            print(f"{name:17s} size {info['size']:5.2f}  median spike / (5 sigma1) = "
                  f"{info['median_amplitude'] / (5 * b.sigma1()):5.2f}  ({info['count']} spikes)")
            continue
        print(f"{name:17s} size {info['size']:5.2f}  tau_c {info['tau_c']:9.3f} s  ADEV effect/base "
              f"realised {adev(e, [m])[0] / base_real:5.2f}  (base expected/realised "
              f"{b.adev(m) / base_real:4.2f})")


if __name__ == "__main__":
    _check()
