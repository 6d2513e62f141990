#!/usr/bin/python3
"""Third, independent record generator for the `sinsim diagnose` challenge.

Written from the issue text, docs/model-format.md and docs/error-models.md only (no look at the
diagnosis, its tests or the two other generators).  Each call of `make` writes one static
six-channel IMU record (CSV) and the exact model of its BASE noise (sinsim YAML); on one channel
0, 1 or 2 hidden effects are added that the model does not contain.

Record
------
* Rate: half the time a real output data rate (50, 52, 100, 104, 125, 200, 208, 250, 400, 416,
  500, 800, 833, 1000, 1600, 1666, 2000 Hz), else an integer log-uniform in 50-2000 Hz.
  Duration log-uniform 20 min - 4 h; n = min(duration*rate, max_samples) samples, T = n/rate.
  Time stamps t_k = (k+1)/rate (end of each output interval, as `sinsim synth`).
* Static: Earth rate and WGS-84 normal gravity (Somigliana) at a random latitude (-65..70 deg),
  sensor attitude random: yaw uniform, and either nearly level (roll, pitch ~ N(0, 1.5 deg)) or
  mounted on a side / upside down (roll or pitch a multiple of 90 deg plus the same small tilt).
  Body axes x fwd, y right, z down; f_b = -C_bn g_n, w_b = C_bn w_ie_n (gyro rad/s, accel m/s^2).
* Printed with %.15g (%.17g on time and on lattice-quantized channels, so these stay exact:
  the time stamps give the rate back to the last bit, the channels stay on k*LSB).
* A `temp` column (degC, 1/256 degC resolution, 0.01-0.03 degC reading noise) when a channel
  carries a temperature effect, and as a distractor on 30 % of the other records (no channel
  follows it there).

Base families (`FAMILIES`; one family per sensor triad, parameters jittered per axis)
---------------------------------------------------------------------------------------
Noise density N: gyro log-U 0.003-1 deg/sqrt(h), accel log-U 0.005-0.3 m/s/sqrt(h).
* `ar`       random stable AR(p) at the IMU rate, p = 1..6, a random number of complex pole pairs
             (radius 0.3-0.97, angle 0.03-0.95 pi) and real poles (at most one "slow",
             1 - 10^U(-3.5,-1), drawn with probability 1/2; the others U(-0.8, 0.9)); driving sigma
             N/sqrt(h); plus white on 40 %.  Started from its exact stationary distribution (the
             first p samples drawn from the Levinson predictors of orders 0..p-1).  Model: `ar` (sigma, rate = IMU).
* `lowpass`  a sensor with an internal digital low-pass: white noise at an internal rate M*fs
             (M = 2, 4, 8, 16) through an all-pole Butterworth-like filter of order 1-4
             (matched-z poles, cut-off 0.08-0.5 fs), then integrate-and-dump decimation (mean of
             M internal samples).  Plus a slow continuous GM (40 %) or random walk (40 %) and
             ADC white after the filter (40 %).  Model: `ar` at rate M*fs (sinsim holds AR
             samples and integrates them into each IMU interval = the same mean of M), exact.
* `gmwm`     as a GMWM / simts user composes a model, all discrete at the sampling rate:
             white (`sigma` + `rate`), 1-2 AR1 (`ar` a=[-phi] at fs), discrete random walk
             (`random_walk` with `rate`) on 60 %, GMWM quantization noise QN (`quantization`,
             increment LSB, `dithered: yes`, carried: e_k = (r_{k-1}-r_k)/h, r ~ U(+-LSB/2)) on
             40 % of channels whose sensor has no lattice, and a known drift (`ramp`) on 25 %.
* `white_gm` white (density) + 1-2 continuous first-order Gauss-Markov processes (no `rate`:
             sinsim integrates them exactly; here the joint (state, interval integral) is drawn
             from its exact covariance), correlation times 5 h .. T/3.
* `white_rw_flicker` white + continuous random walk (step and interval integral drawn jointly)
             + flicker `bias_instability` (B, tau_range = [10^floor(log10 h), 10^ceil(log10 T)]).
             The flicker is synthesised as the documented sum of continuous GM processes over
             tau_range widened by 1.5 decades, here 4 per decade (denser than sinsim's 2), each of
             variance B^2 ln10/(4 pi), which gives the documented floor 0.664 B.  (Note:
             error-models.md gave each of sinsim's 2-per-decade components the variance
             B^2 ln10/(2 pi 2), a 0.47 B floor, while sinsim's own output has the 0.664 B floor -
             measured - so the floor is what is matched here; the docs now say B^2 ln10/(2 pi).)
Common: a turn-on `bias` (sigma given, drawn once per channel) on 50 % of sensors, and a
lattice `quantization` (rate LSB, rounding of the total output, each sample alone) on 25 % of
sensors, LSB 0.1-1.5 x the smallest axis' one-sample deviation.

Size definition
---------------
The base ADEV is the THEORETICAL overlapping Allan deviation of the model (exact ACF of the output
samples for white/AR/GM/QN, K^2 tau/3 for a continuous walk, K^2 h(2m^2+1)/(6m) for a discrete
one, R^2 tau^2/2 for a drift; a lattice as white of variance LSB^2/12).  The effect ADEV is that of
the effect's REALISED signal in the record.  Both are taken on the octave grid tau = h 2^j,
tau <= T/10.  size = max over that grid of ADEV_effect / ADEV_base, tau_c = the argmax: "somewhere
in the well-measured tau range the effect is `size` times the base".  Every effect is linear in
its amplitude, so a shape is drawn and then scaled to the target size.  Sizes are log-uniform in
1.5-10.  Quantization: size = LSB / one-sample deviation of the base (its theoretical ADEV at
tau = h), log-uniform 0.5-5, tau_c = h.  On two-effect channels each entry also gets
`visibility` = max over the grid of ADEV(its realised signal) / ADEV(realised base + the other
effect's signal) (for quantization its rounding error is the signal).

Hidden effects (catalogue) and their synthesis
----------------------------------------------
* white          Gaussian white noise added per sample.
* quantization   rounding of the channel's total (ideal + base + other effect) to k*LSB.
* gauss_markov   continuous GM, correlation time log-U 10 h .. T/5, exact interval averages.
* random_walk    discrete cumulative sum of Gaussian steps at the IMU rate.
* bias_instability  flicker by Kasdin-Walter fractional integration (1 - z^-1)^(-1/2) of white
                 noise (impulse response via FFT, 2T of pre-history).
* ramp           R t (interval means).
* warmup         A1 exp(-t/tau1) [+ A2 exp(-t/tau2)]: one or two settling exponentials (fast
                 electronics, slower thermal), tau1 log-U T/100 .. T/8, tau2 = 3-10 tau1 <= T/3,
                 the second of the same sign on 80 %.
* temperature    bias c1 (T_die - T0) [+ c2 (T_die - T0)^2 on 40 %] with T_die the `temp`
                 profile through a first-order thermal lag (T/400 .. T/40); the column is the
                 lag-free reading with noise.  Profiles: self-heating 1-exp (+ small HVAC ripple),
                 a climatic-chamber hold-ramp-hold (5-40 degC), or an HVAC cycle (rounded
                 triangle, 0.5-2 degC, period T/12 .. T/3).
* sinusoid       1 line (60 %), else 2-3 lines (harmonics of one source or independent),
                 f log-U 20/T .. 0.45 fs, random phases, exact interval means.
* outliers       isolated single-sample spikes (never adjacent), fraction log-U 0.2-3 % of the
                 samples, random sign, amplitudes A exp(0.4 N(0,1)).

Out-of-catalogue effects (`OUT_OF_CATALOGUE`) and acceptable answers (`EQUIVALENT`)
-------------------------------------------------------------------------------------
* random_telegraph  popcorn / RTS noise: two levels, exponential dwell times (mean T/400..T/15,
                 up/down asymmetry 1/4..4), exact interval means.  Accept gauss_markov (its
                 autocovariance is exactly exponential, tau = 1/(r_up + r_down): as a second-order
                 process it IS a GM), bias_jumps (it is a jump process) or unexplained.
* bias_step      1 (70 %) or 2 abrupt bias shifts (a shock on the mount, a mode hop) at uniform
                 instants in 0.15-0.85 T.  Accept bias_jumps (a level step is exactly what it
                 models) or unexplained.
* vibration_bursts  a nearby machine switching on and off: a line (f log-U 50/T .. 0.45 fs) gated
                 into 2-6 bursts of 5-20 % of T with short raised-cosine on/off ramps.  Accept
                 sinusoid (the energy is a spectral line; a constant-amplitude line is its nearest
                 model) or unexplained.

Parameters in the returned `hidden` entries are SI (rad/s or m/s^2, s, Hz; temperature
coefficients per degC); `lines` are [frequency, amplitude, phase].  Randomness only from the
`rng` passed in.  Run `/usr/bin/python3 generate_third.py` for the
self-test (`_check`).
"""

import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy import signal

CATALOGUE = ["white", "quantization", "gauss_markov", "random_walk", "bias_instability",
             "ramp", "warmup", "temperature", "sinusoid", "outliers"]
OUT_OF_CATALOGUE = ["random_telegraph", "bias_step", "vibration_bursts"]
EQUIVALENT = {
    "random_telegraph": {"gauss_markov", "bias_jumps", "unexplained"},
    "bias_step": {"bias_jumps", "unexplained"},
    "vibration_bursts": {"sinusoid", "unexplained"},
}
FAMILIES = ["ar", "lowpass", "gmwm", "white_gm", "white_rw_flicker"]
CHANNELS = ["gx", "gy", "gz", "ax", "ay", "az"]

SINSIM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "sinsim")
ODRS = [50, 52, 100, 104, 125, 200, 208, 250, 400, 416, 500, 800, 833, 1000, 1600, 1666, 2000]
OOC_SHARE = 0.2          # share of out-of-catalogue draws with pool="all"
DEG = math.pi / 180.0
W_IE = 7.292115e-5


def _lu(rng, lo, hi):
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


# ---------------------------------------------------------------- Allan deviation helpers
def _grid(n):
    m, out = 1, []
    while m <= n // 10:
        out.append(m)
        m *= 2
    if len(out) < 3:
        out = [1, 2, 4]
    return np.array(out, dtype=int)


def _avar(x, ms):
    """Overlapping Allan variance of the samples x at cluster sizes ms."""
    c = np.concatenate(([0.0], np.cumsum(x - np.mean(x))))
    out = []
    for m in ms:
        a = (c[m:] - c[:-m]) / m
        d = a[m:] - a[:-m]
        out.append(0.5 * np.mean(d * d) if d.size else np.nan)
    return np.array(out)


def _avar_acf(R, m):
    k = np.arange(1, m)
    var = (m * R[0] + 2.0 * np.sum((m - k) * R[k])) / (m * m)
    kk = np.arange(-(m - 1), m)
    cov = np.sum((m - np.abs(kk)) * R[m + kk]) / (m * m)
    return var - cov


def _avar_theory(comps, ms, h):
    """Theoretical Allan variance of a sum of independent base components."""
    L = 2 * int(ms.max()) + 2
    R = np.zeros(L)
    out = np.zeros(len(ms))
    for c in comps:
        kind = c[0]
        if kind == "white":
            out += c[1] / ms
        elif kind == "acf":
            R += c[1](L)
        elif kind == "rwc":
            out += c[1] ** 2 * ms * h / 3.0
        elif kind == "rwd":
            out += c[1] ** 2 * h * (2.0 * ms ** 2 + 1.0) / (6.0 * ms)
        elif kind == "ramp":
            out += c[1] ** 2 * (ms * h) ** 2 / 2.0
        elif kind == "lattice":
            out += c[1] ** 2 / 12.0 / ms
    if np.any(R != 0.0):
        out += np.array([_avar_acf(R, int(m)) for m in ms])
    return out


# ---------------------------------------------------------------- base processes
def _step_down(a, se):
    """Levinson step-down of a stable AR: the order-m predictors a^(m) (m = 0..p) and their
    innovation variances E_m (E_p = se^2); numerically stable with poles near the unit circle."""
    p = len(a) - 1
    polys, Es = [None] * (p + 1), [0.0] * (p + 1)
    cur = np.asarray(a, float)
    E = se ** 2
    for m in range(p, 0, -1):
        polys[m], Es[m] = cur, E
        k = cur[-1]
        if not abs(k) < 1.0:
            raise ValueError("unstable AR polynomial")
        inner = cur[1:-1]
        cur = np.concatenate(([1.0], (inner - k * inner[::-1]) / (1.0 - k * k)))
        E = E / (1.0 - k * k)
    polys[0], Es[0] = cur, E
    return polys, Es


def _ar_acf(a, se, L):
    p = len(a) - 1
    polys, Es = _step_down(a, se)
    R = np.zeros(max(L, p + 1))
    R[0] = Es[0]
    for m in range(1, p + 1):
        am = polys[m]
        R[m] = -np.dot(am[1:], R[m - 1::-1][:m])
    if L > p + 1:
        zi = signal.lfiltic([1.0], a, y=R[p:0:-1] if p > 0 else [])
        R[p + 1:L], _ = signal.lfilter([1.0], a, np.zeros(L - p - 1), zi=zi)
    return R[:L]


def _ar_sim(rng, a, se, N):
    """AR from its exact stationary start: the first p samples from the order-m predictors."""
    p = len(a) - 1
    polys, Es = _step_down(a, se)
    y0 = np.zeros(p)
    for m in range(p):
        am = polys[m]
        y0[m] = -np.dot(am[1:], y0[m - 1::-1][:m]) + math.sqrt(Es[m]) * rng.standard_normal()
    zi = signal.lfiltic([1.0], a, y=y0[::-1])
    y, _ = signal.lfilter([1.0], a, se * rng.standard_normal(N - p), zi=zi)
    return np.concatenate((y0, y))


def _ar_avg_acf(a, se, M, L):
    """ACF of the means of M consecutive AR samples."""
    Ra = _ar_acf(a, se, M * (L + 1) + M)
    k = np.arange(L)
    R = np.zeros(L)
    for d in range(-(M - 1), M):
        R += (M - abs(d)) * Ra[np.abs(k * M + d)]
    return R / (M * M)


def _gm_consts(h, tau):
    x = h / tau
    a = -math.expm1(-x)
    if x < 1e-3:
        f3 = x ** 3 / 3.0 - x ** 4 / 4.0 + 7.0 * x ** 5 / 60.0
        f2 = x ** 2 / 2.0 - x ** 3 / 6.0 + x ** 4 / 24.0
    else:
        f3 = x - a - a * a / 2.0
        f2 = x - a
    return x, a, f2, f3


def _gm_sim(rng, n, h, sigma, tau):
    """Continuous first-order GM: exact interval means (state and integral drawn jointly)."""
    x, a, _, f3 = _gm_consts(h, tau)
    E = 1.0 - a
    beta = 1.0 / tau
    q2 = 2.0 * sigma ** 2 / tau
    vxx = sigma ** 2 * a * (2.0 - a)
    vxi = q2 * a * a / (2.0 * beta ** 2)
    vii = q2 / beta ** 3 * f3
    z1, z2 = rng.standard_normal(n), rng.standard_normal(n)
    u = math.sqrt(vxx) * z1
    cond = max(vii - vxi ** 2 / vxx, 0.0) if vxx > 0 else vii
    v = (vxi / vxx if vxx > 0 else 0.0) * u + math.sqrt(cond) * z2
    x0 = sigma * rng.standard_normal()
    xs, _ = signal.lfilter([1.0], [1.0, -E], u, zi=[E * x0])
    prev = np.concatenate(([x0], xs[:-1]))
    return (prev * a / beta + v) / h


def _gm_acf_fn(h, sigma, tau):
    def f(L):
        x, a, f2, _ = _gm_consts(h, tau)
        R = np.empty(L)
        R[0] = 2.0 * sigma ** 2 * f2 / x ** 2
        R[1:] = sigma ** 2 * a * a / x ** 2 * np.exp(-(np.arange(1, L) - 1) * x)
        return R
    return f


def _rw_cont_sim(rng, n, h, K):
    w1, w2 = rng.standard_normal(n), rng.standard_normal(n)
    s = K * math.sqrt(h)
    b = np.cumsum(s * w1)
    prev = np.concatenate(([0.0], b[:-1]))
    return prev + s * (w1 / 2.0 + w2 / (2.0 * math.sqrt(3.0)))


def _flicker_gms(B, tau_range):
    lo, hi = math.log10(tau_range[0]) - 1.5, math.log10(tau_range[1]) + 1.5
    k = int(round((hi - lo) * 4)) + 1
    taus = 10.0 ** np.linspace(lo, hi, k)
    var = B ** 2 * math.log(10.0) / (math.pi * 4.0)   # floor 0.664 B (see module doc)
    return taus, math.sqrt(var)


# ---------------------------------------------------------------- units / model file
def _u(sensor, what):
    g = sensor == "gyro"
    return {"level": "rad/s" if g else "m/s^2",
            "density": "rad/sqrt(s)" if g else "m/s/sqrt(s)",
            "walk": "rad/s/sqrt(s)" if g else "m/s^2/sqrt(s)",
            "incr": "rad" if g else "m/s",
            "slope": "rad/s^2" if g else "m/s^3"}[what]


def _q(v, sensor, what):
    return "%.17g %s" % (v, _u(sensor, what))


def _fmt_entry(e):
    parts = []
    for k, v in e.items():
        if isinstance(v, list):
            v = "[" + ", ".join(x if isinstance(x, str) else "%.17g" % x for x in v) + "]"
        parts.append("%s: %s" % (k, v))
    return "{" + ", ".join(parts) + "}"


# ---------------------------------------------------------------- base families
def _base_channel(rng, family, sensor, N, n, h, T, allow_qn, fs):
    """One channel's base: (signal, model entries, theory components, family string)."""
    ent, comps = [], []
    x = np.zeros(n)
    desc = family
    if family == "ar":
        p = int(rng.integers(1, 7))
        c = int(rng.integers(0, p // 2 + 1))
        poles, slow = [], False
        for _ in range(c):
            r, th = rng.uniform(0.3, 0.97), rng.uniform(0.03, 0.95) * math.pi
            poles += [r * np.exp(1j * th), r * np.exp(-1j * th)]
        for _ in range(p - 2 * c):
            if not slow and rng.random() < 0.5:       # at most one slow real pole
                poles.append(1.0 - 10.0 ** rng.uniform(-3.5, -1.0))
                slow = True
            else:
                poles.append(rng.uniform(-0.8, 0.9))
        a = np.real(np.poly(poles))
        se = N / math.sqrt(h)
        x += _ar_sim(rng, a, se, n)
        ent.append({"type": "ar", "a": [float(v) for v in a[1:]], "sigma": _q(se, sensor, "level"),
                    "rate": "%.17g Hz" % fs})
        comps.append(("acf", lambda L, a=a, se=se: _ar_acf(a, se, L)))
        desc = "ar(%d,%dc)" % (p, c)
        if rng.random() < 0.4:
            Nw = N * rng.uniform(0.3, 1.5)
            x += Nw / math.sqrt(h) * rng.standard_normal(n)
            ent.append({"type": "white", "density": _q(Nw, sensor, "density")})
            comps.append(("white", Nw ** 2 / h))
            desc += "+white"
    elif family == "lowpass":
        M = int(rng.choice([2, 4, 8, 16]))
        order = int(rng.integers(1, 5))
        fc = rng.uniform(0.08, 0.5) * fs
        Rint = M * fs
        k = np.arange(order)
        sp = np.exp(1j * math.pi * (2 * k + order + 1) / (2 * order)) * 2 * math.pi * fc
        a = np.real(np.poly(np.exp(sp / Rint)))
        se = N * math.sqrt(Rint) * abs(np.sum(a))
        y = _ar_sim(rng, a, se, n * M)
        x += y.reshape(n, M).mean(axis=1)
        ent.append({"type": "ar", "a": [float(v) for v in a[1:]], "sigma": _q(se, sensor, "level"),
                    "rate": "%.17g Hz" % Rint})
        comps.append(("acf", lambda L, a=a, se=se, M=M: _ar_avg_acf(a, se, M, L)))
        desc = "lowpass(o%d,M%d)" % (order, M)
        u = rng.random()
        if u < 0.4:
            tau = _lu(rng, T / 50, T / 2)
            sig = _lu(rng, 0.5, 3.0) * N / math.sqrt(1.89 * tau) / 0.62
            x += _gm_sim(rng, n, h, sig, tau)
            ent.append({"type": "gauss_markov", "sigma": _q(sig, sensor, "level"),
                        "tau": "%.17g s" % tau})
            comps.append(("acf", _gm_acf_fn(h, sig, tau)))
            desc += "+gm"
        elif u < 0.8:
            K = N * math.sqrt(3.0) / _lu(rng, T / 20, 3 * T)
            x += _rw_cont_sim(rng, n, h, K)
            ent.append({"type": "random_walk", "K": _q(K, sensor, "walk")})
            comps.append(("rwc", K))
            desc += "+rw"
        if rng.random() < 0.4:
            Nw = N * rng.uniform(0.1, 0.5)
            x += Nw / math.sqrt(h) * rng.standard_normal(n)
            ent.append({"type": "white", "density": _q(Nw, sensor, "density")})
            comps.append(("white", Nw ** 2 / h))
            desc += "+adc"
    elif family == "gmwm":
        s = N / math.sqrt(h)
        x += s * rng.standard_normal(n)
        ent.append({"type": "white", "sigma": _q(s, sensor, "level"), "rate": "%.17g Hz" % fs})
        comps.append(("white", s * s))
        parts = ["wn"]
        for _ in range(1 if rng.random() < 0.6 else 2):
            tau = _lu(rng, 5 * h, T / 3)
            phi = math.exp(-h / tau)
            sig = _lu(rng, 0.3, 4.0) * N / math.sqrt(1.89 * tau) / 0.62
            se = sig * math.sqrt(1.0 - phi * phi)
            a = np.array([1.0, -phi])
            x += _ar_sim(rng, a, se, n)
            ent.append({"type": "ar", "a": [-phi], "sigma": _q(se, sensor, "level"),
                        "rate": "%.17g Hz" % fs})
            comps.append(("acf", lambda L, a=a, se=se: _ar_acf(a, se, L)))
            parts.append("ar1")
        if rng.random() < 0.6:
            K = N * math.sqrt(3.0) / _lu(rng, T / 30, 10 * T)
            x += np.cumsum(K * math.sqrt(h) * rng.standard_normal(n))
            ent.append({"type": "random_walk", "K": _q(K, sensor, "walk"), "rate": "%.17g Hz" % fs})
            comps.append(("rwd", K))
            parts.append("rw")
        if allow_qn and rng.random() < 0.4:
            step = 2.0 * h * s * rng.uniform(0.3, 1.5)
            r = rng.uniform(-step / 2, step / 2, n + 1)
            x += (r[:-1] - r[1:]) / h
            ent.append({"type": "quantization", "lsb": _q(step, sensor, "incr"), "dithered": "yes"})
            v = step ** 2 / 12.0 / h ** 2
            comps.append(("acf", lambda L, v=v: np.concatenate(([2 * v, -v], np.zeros(L - 2)))))
            parts.append("qn")
        if rng.random() < 0.25:
            ms = _grid(n)
            base = math.sqrt(_avar_theory(comps, ms[-1:], h)[0])
            R = rng.choice([-1, 1]) * _lu(rng, 0.5, 3.0) * base / (ms[-1] * h / math.sqrt(2))
            x += R * (np.arange(n) + 0.5) * h
            ent.append({"type": "ramp", "slope": _q(R, sensor, "slope")})
            comps.append(("ramp", R))
            parts.append("drift")
        desc = "gmwm(" + "+".join(parts) + ")"
    elif family == "white_gm":
        x += N / math.sqrt(h) * rng.standard_normal(n)
        ent.append({"type": "white", "density": _q(N, sensor, "density")})
        comps.append(("white", N ** 2 / h))
        k = 1 if rng.random() < 0.65 else 2
        for _ in range(k):
            tau = _lu(rng, 5 * h, T / 3)
            sig = _lu(rng, 0.3, 5.0) * N / math.sqrt(1.89 * tau) / 0.62
            x += _gm_sim(rng, n, h, sig, tau)
            ent.append({"type": "gauss_markov", "sigma": _q(sig, sensor, "level"),
                        "tau": "%.17g s" % tau})
            comps.append(("acf", _gm_acf_fn(h, sig, tau)))
        desc = "white+%dgm" % k
    elif family == "white_rw_flicker":
        x += N / math.sqrt(h) * rng.standard_normal(n)
        ent.append({"type": "white", "density": _q(N, sensor, "density")})
        comps.append(("white", N ** 2 / h))
        tw = _lu(rng, 10 * h, max(T / 10, 20 * h))
        F = N / math.sqrt(tw)
        B = F / 0.664
        tr = [10.0 ** math.floor(math.log10(h)), 10.0 ** math.ceil(math.log10(T))]
        taus, sg = _flicker_gms(B, tr)
        for tau in taus:
            x += _gm_sim(rng, n, h, sg, tau)
            comps.append(("acf", _gm_acf_fn(h, sg, tau)))
        ent.append({"type": "bias_instability", "B": _q(B, sensor, "level"),
                    "tau_range": ["%.6g s" % tr[0], "%.6g s" % tr[1]]})
        K = F * math.sqrt(3.0 / (tw * 10.0 ** rng.uniform(0.5, 3.0)))
        x += _rw_cont_sim(rng, n, h, K)
        ent.append({"type": "random_walk", "K": _q(K, sensor, "walk")})
        comps.append(("rwc", K))
    else:
        raise ValueError("unknown base family %r" % family)
    return x, ent, comps, desc


# ---------------------------------------------------------------- static ideal signal
def _ideal(lat, roll, pitch, yaw):
    s2 = math.sin(lat) ** 2
    g = 9.7803253359 * (1 + 0.00193185265241 * s2) / math.sqrt(1 - 0.00669437999013 * s2)
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch),
                              math.cos(yaw), math.sin(yaw))
    Rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    Ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    Rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    Cbn = (Rz @ Ry @ Rx).T
    w = Cbn @ np.array([W_IE * math.cos(lat), 0.0, -W_IE * math.sin(lat)])
    f = -Cbn @ np.array([0.0, 0.0, g])
    return np.concatenate((w, f))


# ---------------------------------------------------------------- temperature profile
def _temperature(rng, n, h, T):
    t = (np.arange(n) + 0.5) * h
    kind = rng.choice(["self_heating", "chamber", "hvac"])
    Ta = rng.uniform(18.0, 28.0)
    if kind == "self_heating":
        dT, ts = rng.uniform(2, 12), _lu(rng, T / 30, T / 3)
        P = _lu(rng, T / 20, T / 4)
        Tt = (Ta + dT * -np.expm1(-t / ts) + rng.uniform(0.05, 0.3) * np.sin(2 * np.pi * t / P + rng.uniform(0, 2 * np.pi))
              + rng.normal(0, 0.5) * t / T)
    elif kind == "chamber":
        dT = rng.choice([-1, 1]) * rng.uniform(5, 40)
        t1, t2 = rng.uniform(0.05, 0.3) * T, rng.uniform(0.6, 0.95) * T
        prog = Ta + dT * np.clip((t - t1) / (t2 - t1), 0, 1)
        lag = 1.0 - math.exp(-h / _lu(rng, T / 200, T / 30))
        Tt, _ = signal.lfilter([lag], [1, lag - 1], prog, zi=[(1 - lag) * Ta])
    else:
        A, P = rng.uniform(0.5, 2.0), _lu(rng, T / 12, T / 3)
        ph = rng.uniform(0, 1)
        tri = 2 * np.abs(2 * ((t / P + ph) % 1.0) - 1) - 1
        lag = 1.0 - math.exp(-h / (P / 20))
        Tt, _ = signal.lfilter([lag], [1, lag - 1], Ta + A * tri, zi=[(1 - lag) * (Ta + A * tri[0])])
    col = np.round((Tt + rng.uniform(0.01, 0.03) * rng.standard_normal(n)) * 256) / 256
    return np.asarray(Tt), col, str(kind)


# ---------------------------------------------------------------- hidden effects (shapes)
def _piecewise_avg(switch_t, levels, n, h):
    """Interval means of a piecewise-constant signal: levels[i] on [switch_t[i-1], switch_t[i])."""
    st = np.concatenate(([0.0], np.asarray(switch_t, float)))
    lv = np.asarray(levels, float)
    F = np.concatenate(([0.0], np.cumsum(lv[:-1] * np.diff(st))))  # integral at each switch

    def integ(t):
        i = np.searchsorted(st, t, side="right") - 1
        return F[i] + lv[i] * (t - st[i])
    edges = np.arange(n + 1) * h
    I = integ(edges)
    return np.diff(I) / h


def _line(t0, h, f, A, ph):
    """Exact interval means of A sin(2 pi f t + ph) over [t0, t0 + h]."""
    return A * np.sinc(f * h) * np.sin(2 * np.pi * f * (t0 + h / 2) + ph)


def _shape(rng, name, n, h, T):
    """Unit-scale shape of one effect: (signal, params, amplitude keys, extra)."""
    t0 = np.arange(n) * h
    tm = t0 + h / 2
    fs = 1.0 / h
    if name == "white":
        return rng.standard_normal(n), {"sigma": 1.0}, ["sigma"], None
    if name == "gauss_markov":
        tau = _lu(rng, 10 * h, T / 5)
        return _gm_sim(rng, n, h, 1.0, tau), {"sigma": 1.0, "tau": tau}, ["sigma"], None
    if name == "random_walk":
        return np.cumsum(rng.standard_normal(n)) * math.sqrt(h), {"K": 1.0}, ["K"], None
    if name == "bias_instability":
        L = 2 * n
        k = np.arange(1, L + n)
        hk = np.concatenate(([1.0], np.cumprod((k - 0.5) / k)))
        w = rng.standard_normal(L + n)
        y = signal.fftconvolve(w, hk, mode="full")[L:L + n]
        return y, {"scale": 1.0, "method": "kasdin_alpha1"}, ["scale"], None
    if name == "ramp":
        return tm.copy(), {"slope": 1.0}, ["slope"], None
    if name == "warmup":
        t1 = _lu(rng, T / 100, T / 8)
        y = np.exp(-tm / t1) * rng.choice([-1, 1])
        p = {"amplitude": float(y[0] / abs(y[0])), "tau": t1}
        keys = ["amplitude"]
        if rng.random() < 0.5:
            t2 = min(t1 * rng.uniform(3, 10), T / 3)
            A2 = rng.uniform(0.3, 2.0) * (1 if rng.random() < 0.8 else -1) * p["amplitude"]
            y = y + A2 * np.exp(-tm / t2)
            p.update({"amplitude2": A2, "tau2": t2})
            keys.append("amplitude2")
        return y, p, keys, None
    if name == "temperature":
        Tt, col, kind = _temperature(rng, n, h, T)
        tl = _lu(rng, T / 400, T / 40)
        lag = 1.0 - math.exp(-h / tl)
        Td, _ = signal.lfilter([lag], [1, lag - 1], Tt, zi=[(1 - lag) * Tt[0]])
        T0 = 25.0
        span = float(np.ptp(Td)) or 1.0
        c1 = rng.choice([-1.0, 1.0])
        c2 = 0.0
        if rng.random() < 0.4:
            c2 = rng.choice([-1, 1]) * rng.uniform(0.1, 0.5) / span
        y = c1 * (Td - T0) + c2 * (Td - T0) ** 2
        p = {"c1": c1, "c2": c2, "T0": T0, "thermal_lag": tl, "profile": kind}
        return y, p, ["c1", "c2"], col
    if name == "sinusoid":
        k = 1 if rng.random() < 0.6 else int(rng.integers(2, 4))
        harmonic = k > 1 and rng.random() < 0.5
        f0 = _lu(rng, 20 / T, 0.45 * fs / (k if harmonic else 1))
        y = np.zeros(n)
        lines = []
        for i in range(k):
            f = f0 * (i + 1) if harmonic else (f0 if i == 0 else _lu(rng, 20 / T, 0.45 * fs))
            A = 1.0 if i == 0 else rng.uniform(0.2, 1.0) * (0.6 ** i if harmonic else 1.0)
            ph = rng.uniform(0, 2 * np.pi)
            y += _line(t0, h, f, A, ph)
            lines.append([f, A, ph])
        return y, {"lines": lines, "amplitude": 1.0}, ["amplitude"], None
    if name == "outliers":
        frac = _lu(rng, 0.002, 0.03)
        cnt = max(1, int(rng.poisson(frac * n)))
        pos = np.unique(rng.integers(1, n - 1, cnt))
        keep = np.concatenate(([True], np.diff(pos) > 2))
        pos = pos[keep]
        y = np.zeros(n)
        y[pos] = rng.choice([-1.0, 1.0], pos.size) * np.exp(0.4 * rng.standard_normal(pos.size))
        return y, {"amplitude": 1.0, "count": int(pos.size), "rate_hz": pos.size / T}, ["amplitude"], None
    if name == "random_telegraph":
        dwell = _lu(rng, T / 400, T / 15)
        asym = _lu(rng, 0.25, 4.0)
        d_up, d_dn = dwell * math.sqrt(asym), dwell / math.sqrt(asym)
        state = 1 if rng.random() < d_up / (d_up + d_dn) else 0
        ts, lv, t = [], [float(state)], 0.0
        while True:
            t += rng.exponential(d_up if state else d_dn)
            if t >= n * h:
                break
            state = 1 - state
            ts.append(t)
            lv.append(float(state))
        y = _piecewise_avg(ts, lv, n, h)
        return y, {"amplitude": 1.0, "dwell_up": d_up, "dwell_down": d_dn,
                   "switches": len(ts)}, ["amplitude"], None
    if name == "bias_step":
        k = 1 if rng.random() < 0.7 else 2
        ts = np.sort(rng.uniform(0.15, 0.85, k) * T)
        steps = rng.choice([-1.0, 1.0], k) * rng.uniform(0.5, 1.0, k)
        lv = np.concatenate(([0.0], np.cumsum(steps)))
        return _piecewise_avg(ts, lv, n, h), {"amplitude": 1.0, "times": [float(v) for v in ts],
                                               "steps": [float(v) for v in steps]}, ["amplitude"], None
    if name == "vibration_bursts":
        f = _lu(rng, 50 / T, 0.45 * fs)
        nb = int(rng.integers(2, 7))
        env = np.zeros(n)
        bursts = []
        for _ in range(nb):
            d = rng.uniform(0.05, 0.2) * T
            s = rng.uniform(0, T - d)
            r = min(d / 10, max(1.0, 3 / f))
            e = np.clip(np.minimum(tm - s, s + d - tm) / r, 0, 1)
            env = np.maximum(env, 0.5 - 0.5 * np.cos(np.pi * e))
            bursts.append([s, d])
        y = env * _line(t0, h, f, 1.0, rng.uniform(0, 2 * np.pi))
        return y, {"amplitude": 1.0, "frequency": f, "bursts": bursts}, ["amplitude"], None
    raise ValueError("unknown effect %r" % name)


# ---------------------------------------------------------------- record
def _draw_names(rng, k, pool, forbid):
    if pool not in ("all", "catalogue", "ooc"):
        raise ValueError("pool must be all, catalogue or ooc, got %r" % pool)
    out = []
    while len(out) < k:
        if pool == "ooc" or (pool == "all" and rng.random() < OOC_SHARE):
            name = str(rng.choice(OUT_OF_CATALOGUE))
        else:
            name = str(rng.choice(CATALOGUE))
        if name in out or name in forbid:
            continue
        out.append(name)
    return out


def _build(rng, idx, work, max_samples, bases=None, null=False, effects=None, pool="all",
           force=None, keep=False):
    fams = list(FAMILIES) if bases is None else list(bases)
    for f in fams:
        if f not in FAMILIES:
            raise ValueError("unknown base family %r (known: %s)" % (f, ", ".join(FAMILIES)))
    if not fams:
        raise ValueError("empty list of base families")
    if pool not in ("all", "catalogue", "ooc"):
        raise ValueError("pool must be all, catalogue or ooc, got %r" % pool)
    rate = float(rng.choice(ODRS)) if rng.random() < 0.5 else float(round(_lu(rng, 50, 2000)))
    dur = _lu(rng, 20 * 60, 4 * 3600)
    n = int(min(round(dur * rate), max_samples))
    h = 1.0 / rate
    T = n * h
    lat = rng.uniform(-65, 70) * DEG
    yaw = rng.uniform(0, 360) * DEG
    roll, pitch = rng.normal(0, 1.5) * DEG, rng.normal(0, 1.5) * DEG
    if rng.random() < 0.4:
        if rng.random() < 0.5:
            roll += float(rng.choice([90, 180, -90])) * DEG
        else:
            pitch += float(rng.choice([90, -90])) * DEG
    ideal = _ideal(lat, roll, pitch, yaw)
    ms = _grid(n)

    base, models, theory, famdesc = {}, {}, {}, {}
    lattice = {}
    for sensor, chs in (("gyro", CHANNELS[:3]), ("accel", CHANNELS[3:])):
        fam = str(rng.choice(fams))
        if sensor == "gyro":
            N0 = _lu(rng, 0.003, 1.0) * DEG / 60.0
        else:
            N0 = _lu(rng, 0.005, 0.3) / 60.0
        quant = rng.random() < 0.25
        bias_sig = N0 * 10.0 ** rng.uniform(0.0, 2.0) if rng.random() < 0.5 else 0.0
        for c in chs:
            N = N0 * math.exp(0.2 * rng.standard_normal())
            x, ent, comps, desc = _base_channel(rng, fam, sensor, N, n, h, T, not quant, rate)
            if bias_sig > 0:
                x = x + bias_sig * rng.standard_normal()
                ent.insert(0, {"type": "bias", "sigma": _q(bias_sig, sensor, "level")})
            base[c], models[c], theory[c], famdesc[c] = x, ent, comps, desc
        if quant:
            sd = min(math.sqrt(_avar_theory(theory[c], ms[:1], h)[0]) for c in chs)
            lsb = sd * _lu(rng, 0.1, 1.5)
            for c in chs:
                lattice[c] = lsb
                models[c].append({"type": "quantization", "lsb": _q(lsb, sensor, "level")})
                theory[c].append(("lattice", lsb))
                famdesc[c] += "+lattice"
    adev_b = {c: np.sqrt(_avar_theory(theory[c], ms, h)) for c in CHANNELS}

    # hidden effects
    def no_quant(c):
        return c in lattice or any(e["type"] == "quantization" for e in models[c])
    if force is not None and "quantization" in force:
        ch = str(rng.choice([c for c in CHANNELS if not no_quant(c)] or CHANNELS))
    else:
        ch = str(rng.choice(CHANNELS))
    if null:
        k = 0
    elif effects is not None:
        k = int(effects)
        if k not in (0, 1, 2):
            raise ValueError("effects must be 0, 1 or 2")
    elif force is not None:
        k = len(force)
    else:
        u = rng.random()
        k = 0 if u < 0.15 else (1 if u < 0.75 else 2)
    forbid = set()
    if no_quant(ch):
        forbid.add("quantization")
    names = list(force) if force is not None else _draw_names(rng, k, pool, forbid)
    hidden, sigs, temp_col = [], {}, None
    qsize = None
    for name in names:
        if name == "quantization":
            qsize = _lu(rng, 0.5, 5.0)
            hidden.append({"effect": name, "size": qsize, "tau_c": h,
                           "lsb": qsize * float(adev_b[ch][0])})
            continue
        y, p, keys, extra = _shape(rng, name, n, h, T)
        ratio = np.sqrt(_avar(y, ms)) / adev_b[ch]
        j = int(np.nanargmax(ratio))
        size = _lu(rng, 1.5, 10.0)
        scale = size / ratio[j]
        y = y * scale
        for kk in keys:
            p[kk] = p[kk] * scale
        if name == "sinusoid":
            for ln in p["lines"]:
                ln[1] *= p["amplitude"]
        if extra is not None:
            temp_col = extra
        sigs[name] = y
        d = {"effect": name, "size": float(size), "tau_c": float(ms[j] * h)}
        d.update(p)
        hidden.append(d)
    if temp_col is None and rng.random() < 0.3:
        temp_col = _temperature(rng, n, h, T)[1]

    data = {}
    for i, c in enumerate(CHANNELS):
        v = ideal[i] + base[c]
        if c == ch:
            for y in sigs.values():
                v = v + y
        raw = v
        if c in lattice:
            v = np.round(v / lattice[c]) * lattice[c]
        if c == ch and qsize is not None:
            q = [e for e in hidden if e["effect"] == "quantization"][0]["lsb"]
            v = np.round(v / q) * q
            sigs["quantization"] = v - raw
        data[c] = v

    if len(hidden) == 2:
        for e in hidden:
            other = [o for o in hidden if o is not e][0]["effect"]
            ae = np.sqrt(_avar(sigs[e["effect"]], ms))
            ab = np.sqrt(_avar(base[ch] + sigs[other], ms))
            e["visibility"] = float(np.nanmax(ae / ab))

    os.makedirs(work, exist_ok=True)
    csv = os.path.join(work, "r%04d.csv" % idx)
    yml = os.path.join(work, "r%04d.yaml" % idx)
    t = (np.arange(n) + 1) / rate
    cols = [t] + [data[c] for c in CHANNELS]
    fmt = ["%.17g"] + ["%.17g" if (c in lattice or (c == ch and qsize is not None)) else "%.15g"
                       for c in CHANNELS]
    header = "t,gx,gy,gz,ax,ay,az"
    if temp_col is not None:
        cols.append(temp_col)
        fmt.append("%.10g")
        header += ",temp"
    tmp = csv + ".tmp"
    np.savetxt(tmp, np.column_stack(cols), fmt=fmt, delimiter=",", header=header, comments="")
    os.replace(tmp, csv)
    lines = ["# generate_third.py record %d: base model only (no hidden effect)" % idx,
             'description: "third-generator base, record %d"' % idx]
    for sensor, chs in (("gyro", CHANNELS[:3]), ("accel", CHANNELS[3:])):
        lines.append(sensor + ":")
        for c, ax in zip(chs, "xyz"):
            lines.append("  %s:" % ax)
            for e in models[c]:
                lines.append("    - " + _fmt_entry(e))
    with open(yml, "w") as fh:
        fh.write("\n".join(lines) + "\n")

    def clean(o):
        if isinstance(o, dict):
            return {str(k): clean(v) for k, v in o.items()}
        if isinstance(o, (list, tuple)):
            return [clean(v) for v in o]
        if isinstance(o, (np.floating, float)):
            return float(o)
        if isinstance(o, (np.integer,)):
            return int(o)
        return o
    out = {"record": csv, "model": yml, "rate_hz": float(rate), "samples": int(n),
           "duration_s": float(T), "channel": ch, "hidden": clean(hidden),
           "bases": {c: famdesc[c] for c in CHANNELS}, "temp_column": temp_col is not None,
           "latitude_deg": float(lat / DEG),
           "attitude_deg": [float(roll / DEG), float(pitch / DEG), float(yaw / DEG)]}
    if keep:
        out["_internal"] = {"base": base, "sigs": sigs, "ms": ms, "h": h, "adev_b": adev_b,
                            "lattice": lattice, "ideal": ideal}
    return out


def make(rng, idx, work, max_samples, bases=None, null=False, effects=None, pool="all"):
    """Write work/r{idx:04d}.csv and .yaml; return the record's truth (see the module doc)."""
    return _build(rng, idx, work, max_samples, bases=bases, null=null, effects=effects, pool=pool)


# ---------------------------------------------------------------- self-test
def _read_csv(path):
    return np.genfromtxt(path, delimiter=",", skip_header=1)


def _check():
    work = tempfile.mkdtemp(prefix="gen3check_")
    rng = np.random.default_rng(20240611)
    maxn = 30000
    print("work directory:", work)
    print("\n1) base realisations against the model, per family (4 records x 6 channels), on the octave"
          "\n   grid, split into short tau (<= T/100) and long tau (T/100 .. T/10):"
          "\n   gen/theory   = ADEV of this generator's base realisation / theoretical ADEV of the model"
          "\n   synth/theory = ADEV of `sinsim synth MODEL` (mean Allan variance of 3 seeds, same rate,"
          "\n                  length, latitude and attitude) / the same theory"
          "\n   median [5 %..95 %] over grid points and channels")
    idx = 0

    def q(v):
        v = np.asarray(v)
        return "%.3f [%.2f..%.2f]" % (np.median(v), np.percentile(v, 5), np.percentile(v, 95))
    for fam in FAMILIES:
        acc = {"gs": [], "gl": [], "ss": [], "sl": []}
        for rep in range(4):
            r = _build(rng, idx, work, maxn, bases=[fam], null=True, keep=True)
            idx += 1
            I = r["_internal"]
            d = _read_csv(r["record"])
            att = ",".join("%.12g" % a for a in r["attitude_deg"])
            av = {c: [] for c in CHANNELS}
            for seed in range(3):
                syn = os.path.join(work, "synth.csv")
                subprocess.run([SINSIM, "synth", r["model"], "--rate", "%.17g" % r["rate_hz"],
                                "--duration", "%.17g" % r["duration_s"], "--seed", str(100 * idx + seed),
                                "--latitude", "%.12g deg" % r["latitude_deg"], "--attitude", att,
                                "-o", syn], check=True, capture_output=True)
                s = _read_csv(syn)
                for i, c in enumerate(CHANNELS):
                    av[c].append(_avar(s[:, i + 1], I["ms"]))
            short = I["ms"] * I["h"] <= r["duration_s"] / 100
            for i, c in enumerate(CHANNELS):
                g = np.sqrt(_avar(d[:, i + 1], I["ms"])) / I["adev_b"][c]
                sy = np.sqrt(np.mean(av[c], axis=0)) / I["adev_b"][c]
                acc["gs"] += list(g[short]); acc["gl"] += list(g[~short])
                acc["ss"] += list(sy[short]); acc["sl"] += list(sy[~short])
        print("  %-17s gen/theory short %s long %s" % (fam, q(acc["gs"]), q(acc["gl"])))
        print("  %-17s synth/theory short %s long %s" % ("", q(acc["ss"]), q(acc["sl"])))
    print("\n2) stated size against the realised ADEV ratio ADEV(effect signal)/ADEV(base realisation)"
          "\n   at the stated tau_c (quantization: LSB / realised one-sample deviation of the base);"
          "\n   median of realised/stated over 10 records per effect, and per family (2 records each)")
    for name in CATALOGUE + OUT_OF_CATALOGUE:
        rr, per = [], {}
        for rep in range(10):
            fam = FAMILIES[rep % len(FAMILIES)]
            r = _build(rng, idx, work, maxn, bases=[fam], force=[name], keep=True)
            idx += 1
            I = r["_internal"]
            e = r["hidden"][0]
            b = I["base"][r["channel"]]
            if name == "quantization":
                realised = e["lsb"] / math.sqrt(_avar(b, np.array([1]))[0])
            else:
                m = np.array([int(round(e["tau_c"] / I["h"]))])
                realised = math.sqrt(_avar(I["sigs"][name], m)[0] / _avar(b, m)[0])
            rr.append(realised / e["size"])
            per.setdefault(fam, []).append(realised / e["size"])
            os.remove(r["record"])
        rr = np.array(rr)
        print("  %-17s realised/stated median %.2f [%.2f..%.2f]  by family: %s" % (
            name, np.median(rr), rr.min(), rr.max(),
            " ".join("%s %.2f" % (f, np.median(v)) for f, v in per.items())))
    print("\n3) sizes drawn by make(): two-effect visibility example")
    for rep in range(3):
        r = make(rng, idx, work, maxn, effects=2)
        idx += 1
        print("  ", r["channel"], r["bases"][r["channel"]],
              [(e["effect"], round(e["size"], 2), round(e["visibility"], 2)) for e in r["hidden"]])
    print("\n4) sinsim diagnose on a null record with its model (must run, exit 0)")
    r = make(rng, idx, work, maxn, null=True)
    p = subprocess.run([SINSIM, "diagnose", r["record"], "--model", r["model"], "--realisations", "8",
                        "--json", os.path.join(work, "null.json"), "--threads", "1"],
                       capture_output=True, text=True)
    print("   bases:", r["bases"], " rate %.0f Hz, %d samples" % (r["rate_hz"], r["samples"]))
    print("   exit code", p.returncode)
    print("   " + "\n   ".join((p.stdout + p.stderr).strip().splitlines()[:30]))
    json.dumps(r)
    if p.returncode != 0:
        sys.exit(1)


if __name__ == "__main__":
    _check()
