"""Records for the latent-fit round-trip study, made without any sinsim code (NumPy only).

Issue 11's five cases at a given rate and length, one gyro-like channel per record [rad/s]:
  white+gm            white + first-order GM
  white+gm+rw         white + GM + random walk
  white+2gm           white + two GMs, taus a decade apart
  white+flicker+rw    white + 1/f flicker + random walk
  quantization+white  white noise whose increments are output-quantized with carry
and, only when asked by --case (the `--kind ar+slow` study, fit/ar_slow_fit.hpp):
  ar2+rw              AR(2) + random walk
  ar2+gm              AR(2) + a slow first-order GM
  qn+white            white noise + quantization noise as GMWM makes it (no value lattice)
  white+drift         white + a deterministic ramp R t
  white+gm+drift      white + GM + the ramp
  white+rw+drift      white + random walk + a ramp above the walk's chance trend

How each process is made (on purpose not the way the fit models it, where there is a choice):
  white        N / sqrt(dt) * normal samples
  GM           the sampled Ornstein-Uhlenbeck process, x_k = phi x_{k-1} + sigma sqrt(1-phi^2) e_k,
               started from its stationary law, computed blockwise in closed form
               (x_k = phi^k (x_0 + sum phi^-j w_j)), not by a loop or a filter routine
  random walk  sampled discrete walk b_k = b_{k-1} + K sqrt(dt) e_k (the fit assumes the continuous
               walk averaged over each interval; they differ by K^2 dt / (6 m), far below the white)
  flicker      spectral synthesis: white noise shaped in the frequency domain by sqrt(h / (2 dt f))
               (one-sided PSD h / f, h = B^2 / pi, so that the Allan floor is 2 ln 2 h = (2 ln 2 / pi)
               B^2 in IEEE 952's convention) over an FFT twice the record's length, first half kept.
               No sum of GMs, no AR: nothing the fit is built from.
  quantization the angle (cumulative increment) rounded to an LSB, the rate = difference / dt;
               qn+white: GMWM's (simts) QN process sqrt(12) Q (U_k - U_{k-1}) / dt, U uniform on
               (0, 1), added to the white noise (the same Q; the record has no value lattice)
  drift        R t with t = k dt from the record's first sample (the fit sees no sign; R > 0 here)
  AR(2)        scipy.signal.lfilter of normal driving noise through 1 / A(z), after a burn-in of
               20 x the slower pole's time constant (the fit uses Burg and closed forms)

Output (stdout): per record one JSON line (case, rate, duration, seed, term set, true parameters
in SI with the fit's parameter names, n) followed by n little-endian float64 samples. Read by
`latent_fit_study --stdin`. Seeds: numpy.random.default_rng([seed, case index, rate, duration]).

    python3 bench/latent_study/generate.py --rate 100 --duration 1200 --seeds 200 \
        | build/bench/latent_fit_study --stdin
"""
import argparse
import json
import math
import sys

import numpy as np

CASES = ["white+gm", "white+gm+rw", "white+2gm", "white+flicker+rw", "quantization+white"]
AR_CASES = ["ar2+rw", "ar2+gm", "qn+white"]
DRIFT_CASES = ["white+drift", "white+gm+drift", "white+rw+drift"]
DEG = math.pi / 180.0


def parameters(case, rate, duration):
    """True parameters (SI) and the term set. Sizes: every term carries >= ~40 % of the Allan
    variance on at least one octave of tau <= duration / 10 at both rates and lengths."""
    N = 0.2 * DEG / 60.0                  # white [rad/sqrt(s)], 0.2 deg/sqrt(h)
    T1 = duration / 2400.0                # GM tau [s]: 0.5 s (20 min), 3 s (2 h)
    s1 = 0.005 * DEG                      # GM sigma [rad/s]
    T2, s2 = 10.0 * T1, 0.003 * DEG       # second GM, a decade slower
    K = 200.0 * N / duration              # random walk [rad/s/sqrt(s)]
    B = 40.0 * N / math.sqrt(duration)    # flicker [rad/s]
    Kf = 2.0 * K                          # the random walk beside the flicker
    Q = N * math.sqrt(1.0 / rate) / math.sqrt(12.0)  # LSB = per-sample white increment sd
    terms = {"quantization": False, "white": True, "gm": 0, "flicker": False,
             "random_walk": False, "drift": False, "ar": False}
    if case == "white+gm":
        terms["gm"] = 1
        p = {"white": N, "gm1.sigma": s1, "gm1.tau": T1}
    elif case == "white+gm+rw":
        terms.update(gm=1, random_walk=True)
        p = {"white": N, "gm1.sigma": s1, "gm1.tau": T1, "random_walk": K}
    elif case == "white+2gm":
        terms["gm"] = 2
        p = {"white": N, "gm1.sigma": s1, "gm1.tau": T1, "gm2.sigma": s2, "gm2.tau": T2}
    elif case == "white+flicker+rw":
        terms.update(flicker=True, random_walk=True)
        p = {"white": N, "flicker": B, "random_walk": Kf}
    elif case in ("quantization+white", "qn+white"):
        terms["quantization"] = True
        p = {"white": N, "quantization": Q}
    elif case in AR_CASES:
        # AR(2) with real poles 0.9^(100 Hz / rate) and 0.5^(100 Hz / rate) (slower pole: 95 ms),
        # driving variance E set so that its long-tau white density is N (E = N^2 A(1)^2 / dt).
        r1, r2 = 0.9 ** (100.0 / rate), 0.5 ** (100.0 / rate)
        a = [-(r1 + r2), r1 * r2]
        E = N * N * (1.0 + a[0] + a[1]) ** 2 * rate
        terms.update(white=False, ar=True)
        p = {"ar.a": a, "ar.sigma": math.sqrt(E)}
        if case == "ar2+rw":
            # K = 600 N / duration: the walk crosses the AR's white level at tau = sqrt(3) N / K
            # = duration / 346, so it dominates the last ~5 octaves of tau <= duration / 10.
            terms["random_walk"] = True
            p["random_walk"] = 3.0 * K
        else:
            # GM tau duration / 60 (20 s at 20 min), sigma 0.002 deg/s: its hump (~0.4 sigma^2
            # near 2 tau) is ~5x the AR's white level there.
            terms["gm"] = 1
            p.update({"gm1.sigma": 0.002 * DEG, "gm1.tau": duration / 60.0})
    elif case in DRIFT_CASES:
        # The ramp's Allan variance R^2 tau^2 / 2 is 4x the white's (N^2 / tau) at the top octave
        # tau_top = duration / 10 (beside the walk: 4x the walk's K^2 tau / 3 there; the walk's
        # own least-squares trend over the record has sd ~1.1 K / sqrt(duration), the ramp ~5x it).
        tau_top = duration / 10.0
        terms["drift"] = True
        p = {"white": N, "drift": math.sqrt(8.0) * N * tau_top ** -1.5}
        if case == "white+gm+drift":
            terms["gm"] = 1
            p.update({"gm1.sigma": s1, "gm1.tau": T1})
        elif case == "white+rw+drift":
            terms["random_walk"] = True
            p.update({"random_walk": K, "drift": math.sqrt(8.0 / 3.0) * K / math.sqrt(tau_top)})
    else:
        raise SystemExit(f"unknown case {case!r}; known: {', '.join(CASES + AR_CASES + DRIFT_CASES)}")
    return terms, p


def ar_process(rng, n, a, sigma):
    from scipy.signal import lfilter
    burn = int(20.0 / (1.0 - max(abs(r) for r in np.roots([1.0] + a)))) + 10
    e = sigma * rng.standard_normal(n + burn)
    return lfilter([1.0], [1.0] + a, e)[burn:]


def gauss_markov(rng, n, dt, sigma, tau):
    phi = math.exp(-dt / tau)
    w = sigma * math.sqrt(1.0 - phi * phi) * rng.standard_normal(n)
    x = np.empty(n)
    prev = sigma * rng.standard_normal()
    block = max(1, min(n, int(300.0 * tau / dt)))  # phi^-block <= e^300: no overflow
    for s in range(0, n, block):
        j = np.arange(1, min(block, n - s) + 1, dtype=float)
        decay = np.exp(-j * dt / tau)                      # phi^j
        acc = np.cumsum(w[s:s + len(j)] / decay)           # sum phi^-i w_i
        x[s:s + len(j)] = decay * (prev + acc)
        prev = x[s + len(j) - 1]
    return x


def flicker(rng, n, dt, B):
    h = B * B / math.pi
    M = 2 * n
    W = np.fft.rfft(rng.standard_normal(M))
    f = np.fft.rfftfreq(M, dt)
    G = np.zeros_like(f)
    G[1:] = np.sqrt(h / (2.0 * dt * f[1:]))
    return np.fft.irfft(W * G, M)[:n]


def record(case, rate, duration, seed):
    terms, p = parameters(case, rate, duration)
    dt = 1.0 / rate
    n = int(round(duration * rate))
    rng = np.random.default_rng([seed, (CASES + AR_CASES + DRIFT_CASES).index(case), int(rate), int(duration)])
    if "ar.a" in p:
        x = ar_process(rng, n, p["ar.a"], p["ar.sigma"])
    else:
        x = p["white"] / math.sqrt(dt) * rng.standard_normal(n)
    for g in (1, 2):
        if f"gm{g}.sigma" in p:
            x += gauss_markov(rng, n, dt, p[f"gm{g}.sigma"], p[f"gm{g}.tau"])
    if "random_walk" in p:
        x += np.cumsum(p["random_walk"] * math.sqrt(dt) * rng.standard_normal(n))
    if "flicker" in p:
        x += flicker(rng, n, dt, p["flicker"])
    if "drift" in p:
        x += p["drift"] * dt * np.arange(n)
    if "quantization" in p and case == "qn+white":
        u = rng.uniform(0.0, 1.0, n + 1)
        x += math.sqrt(12.0) * p["quantization"] / dt * (u[1:] - u[:-1])
    elif "quantization" in p:
        lsb = p["quantization"] * math.sqrt(12.0)  # [rad]
        angle = np.round(np.cumsum(x * dt) / lsb) * lsb
        x = np.diff(angle, prepend=0.0) / dt
    return terms, p, x


def main(make=None, rates=(100.0, 1000.0), durations=(1200.0, 7200.0), seeds=200, doc=__doc__):
    """Writes records of make(case, rate, duration, seed) -> (terms, params, x) (default `record`)
    for the command line's cells; generate_alt.py calls it with its own generator and defaults."""
    make = make or record
    ap = argparse.ArgumentParser(description=doc.split("\n")[0])
    ap.add_argument("--rate", type=float, action="append", help=f"Hz (repeatable; default {rates})")
    ap.add_argument("--duration", type=float, action="append", help=f"s (repeatable; default {durations})")
    ap.add_argument("--case", action="append", help="(repeatable; default the five latent cases)")
    ap.add_argument("--seeds", type=int, default=seeds)
    ap.add_argument("--first-seed", type=int, default=0)
    a = ap.parse_args()
    out = sys.stdout.buffer
    # seed-major order: a stream cut short still has every cell at a similar number of seeds
    for seed in range(a.first_seed, a.first_seed + a.seeds):
        for rate in a.rate or list(rates):
            for duration in a.duration or list(durations):
                for case in a.case or CASES:
                    terms, p, x = make(case, rate, duration, seed)
                    head = {"case": case, "rate": rate, "duration": duration, "seed": seed,
                            "terms": terms, "params": p, "n": len(x)}
                    out.write((json.dumps(head) + "\n").encode())
                    out.write(x.astype("<f8").tobytes())
                    out.flush()


if __name__ == "__main__":
    try:
        main()
    except BrokenPipeError:
        pass
