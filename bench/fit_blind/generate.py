#!/usr/bin/env python3
"""Blind record generator for `sinsim fit` (written without reading the fit's code).

Each record is a static single-gyro record (deg/s, CSV) made of independent terms:

  white         N   [rad/s/sqrt(Hz) = rad/sqrt(s)]   AVAR = N^2/tau
  quantization  the integrated angle rounded to an LSB D [rad] and differenced;
                Q = D/sqrt(12), AVAR = 3 Q^2/tau^2
  gm            first-order Gauss-Markov, stationary sd sigma [rad/s], correlation time tc [s]
  random_walk   K [rad/s/sqrt(s)]                    AVAR = K^2 tau/3
  flicker       1/f noise, Allan floor F [rad/s], B = F/0.664

Discretisation (my own choice):
  * white, GM and RW are continuous-time processes and each sample is the exact *average* of
    the process over the sample interval h (what an integrating sensor outputs).  The GM uses
    the exact joint Gaussian law of (x(t+h), integral of x over [t, t+h]) given x(t); the RW the
    same for Brownian motion.  Averaged samples make the Allan formulas above exact at tau = m h.
  * flicker: FFT shaping of white Gaussian noise to a one-sided PSD h_-1/f on a 2x padded grid
    (first half kept), AVAR floor = 2 ln2 h_-1 for tau well inside (h, T).  Default
    (--flicker-mode sampled) the 1/f PSD runs up to Nyquist (point samples of 1/f noise: at
    tau = h its AVAR is ~15 % above the floor); --flicker-mode averaged gives the interval
    average of a continuous 1/f process (spectrum times the aliased sinc^2), AVAR = floor at all
    tau = m h, the same convention as white/GM/RW.
  * --gm-mode sampled replaces the averaged GM by point samples (an exact AR(1)), for the
    convention study in RESULTS.md.
  * quantization: the true angle (integral of all rate terms plus a constant bias) is rounded to
    the LSB, differenced and divided by h, so the output rate lies on the lattice D/h.
  * Every record also has a constant bias (Earth rate + turn-on, uniform +-20 deg/h) that is not
    a noise term and is not scored.

Strength ("contrast"): each term's size is drawn so that at its reference tau its Allan
deviation is r times the Allan deviation of the terms already in the record, r log-uniform in
[1.5, 10] (the terms are added in the order white, quantization, gm1, gm2, flicker, rw):
  gm: reference tau = the GM's ADEV peak, 1.893 tc; tc log-uniform [20 h, T/10]
      (second GM: tc2 = tc1 * U(8, 15), tc1 drawn in [20 h, T/10/ratio])
  rw: reference tau log-uniform in [T/100, T/10]
  flicker: reference tau log-uniform in [max(100 h, T/1000), T/30]
  quantization: reference tau = h
After all terms are drawn, each term's *visibility* = max over tau in [h, T/10] of
ADEV_term / ADEV_(all other terms) is computed; a draw with any visibility < 1.5 is redrawn
(so every term is at least 1.5x the rest somewhere in the measured range).
White density N is log-uniform over two decades, 0.05 .. 5 deg/sqrt(h).
"""
import argparse, json, math, os, sys, gzip
import numpy as np

DEG = math.pi / 180.0
CASES = ["white", "white+rw", "white+gm", "white+gm+rw", "white+2gm", "white+flicker+rw",
         "quant+white"]
CASE_ID = {c: i for i, c in enumerate(CASES)}
RATE_ID = {100.0: 1, 1000.0: 2, 208.0: 3}


def loguni(rng, a, b):
    return math.exp(rng.uniform(math.log(a), math.log(b)))


# ---------------------------------------------------------------- analytic Allan variances
def avar_white(tau, N):
    return N * N / tau


def avar_gm(tau, s, tc):
    u = tau / tc
    u = np.asarray(u, float)
    out = np.empty_like(u)
    small = u < 1e-3
    ub = u[~small]
    out[~small] = (2 * s * s / ub ** 2) * (ub - 1.5 + 2 * np.exp(-ub) - 0.5 * np.exp(-2 * ub))
    us = u[small]
    out[small] = 2 * s * s * (us / 3 - us ** 2 / 4 + 7 * us ** 3 / 60)
    return out


def avar_rw(tau, K):
    return K * K * tau / 3.0


def avar_flicker(tau, F):
    return F * F * np.ones_like(np.asarray(tau, float))


def avar_quant(tau, D):
    Q = D / math.sqrt(12)
    return 3 * Q * Q / tau ** 2


def term_avar(term, tau):
    k = term["type"]
    if k == "white":
        return avar_white(tau, term["N"])
    if k == "gm":
        return avar_gm(tau, term["sigma"], term["tau"])
    if k == "random_walk":
        return avar_rw(tau, term["K"])
    if k == "flicker":
        return avar_flicker(tau, term["floor"])
    if k == "quantization":
        return avar_quant(tau, term["lsb_angle"])
    raise ValueError(k)


# ---------------------------------------------------------------- draw the parameters
def draw_truth(case, rate, duration, rng):
    h = 1.0 / rate
    T = duration
    taus = np.exp(np.linspace(math.log(h), math.log(T / 10), 200))

    def rest_adev(terms, tau):
        return math.sqrt(sum(float(term_avar(t, np.array([tau]))[0]) for t in terms))

    for attempt in range(200):
        terms = []
        N = loguni(rng, 0.05, 5.0) * DEG / 60.0  # deg/sqrt(h) -> rad/sqrt(s)
        terms.append({"type": "white", "N": N})
        contrasts = {}
        if case == "quant+white":
            r = loguni(rng, 1.5, 10)
            # 3 Q^2/h^2 = r^2 N^2/h  ->  D = sqrt(12) * r N sqrt(h) / sqrt(3) = 2 r N sqrt(h)
            D = 2 * r * N * math.sqrt(h)
            terms.append({"type": "quantization", "lsb_angle": D, "Q": D / math.sqrt(12)})
            contrasts["quantization"] = r
        if case in ("white+gm", "white+gm+rw", "white+2gm"):
            ratio2 = rng.uniform(8, 15) if case == "white+2gm" else 1.0
            tc1 = loguni(rng, 20 * h, T / 10 / ratio2)
            tcs = [tc1] if case != "white+2gm" else [tc1, tc1 * ratio2]
            for i, tc in enumerate(tcs):
                r = loguni(rng, 1.5, 10)
                tref = 1.893 * tc  # the GM's Allan-deviation peak
                target = r * rest_adev(terms, tref)
                unit = math.sqrt(float(avar_gm(np.array([tref]), 1.0, tc)[0]))
                terms.append({"type": "gm", "sigma": target / unit, "tau": tc})
                contrasts["gm%d" % (i + 1)] = r
        if case == "white+flicker+rw":
            r = loguni(rng, 1.5, 10)
            tref = loguni(rng, max(100 * h, T / 1000), T / 30)
            F = r * rest_adev(terms, tref)
            terms.append({"type": "flicker", "floor": F, "B": F / 0.664})
            contrasts["flicker"] = r
        if case in ("white+rw", "white+gm+rw", "white+flicker+rw"):
            r = loguni(rng, 1.5, 10)
            tref = loguni(rng, T / 100, T / 10)
            target = r * rest_adev(terms, tref)
            K = target * math.sqrt(3.0 / tref)
            terms.append({"type": "random_walk", "K": K})
            contrasts["random_walk"] = r
        # visibility of every term against all the others
        vis = []
        for i, t in enumerate(terms):
            a_t = term_avar(t, taus)
            a_r = sum(term_avar(o, taus) for j, o in enumerate(terms) if j != i)
            with np.errstate(divide="ignore"):
                vis.append(float(np.sqrt(np.max(a_t / a_r))))
            t["visibility"] = vis[-1] if math.isfinite(vis[-1]) else None
        if len(terms) == 1 or min(v for v in vis if math.isfinite(v)) >= 1.5:
            break
    bias = rng.uniform(-20, 20) * DEG / 3600.0
    return {"case": case, "rate_hz": rate, "duration_s": duration, "terms": terms,
            "bias": bias, "draw_attempts": attempt + 1, "contrasts": contrasts}


# ---------------------------------------------------------------- simulate
def ar1(w, phi, x0):
    """x[k+1] = phi x[k] + w[k], x[0] = x0; returns x[0..n] (n+1 values)."""
    from scipy.signal import lfilter
    y, _ = lfilter([1.0], [1.0, -phi], w, zi=[phi * x0])
    return np.concatenate([[x0], y])


def sim_gm_avg(n, h, s, tc, rng):
    u = h / tc
    phi = math.exp(-u)
    q = 2 * s * s / tc
    var_x = s * s * (-math.expm1(-2 * u))
    if u < 1e-3:
        var_i = q * tc ** 3 * (u ** 3 / 3 - u ** 4 / 4 + 7 * u ** 5 / 60)
    else:
        var_i = q * tc ** 3 * (u - 2 * (-math.expm1(-u)) + 0.5 * (-math.expm1(-2 * u)))
    one_m_phi = -math.expm1(-u)
    cov = q * tc * tc * one_m_phi ** 2 / 2
    w = rng.standard_normal(n) * math.sqrt(var_x)
    x = ar1(w, phi, rng.standard_normal() * s)
    resid = max(var_i - cov * cov / var_x, 0.0)
    integ = tc * one_m_phi * x[:-1] + (cov / var_x) * w + math.sqrt(resid) * rng.standard_normal(n)
    return integ / h


def sim_rw_avg(n, h, K, rng):
    d = rng.standard_normal(n) * K * math.sqrt(h)
    b = np.concatenate([[0.0], np.cumsum(d)])
    return b[:-1] + 0.5 * d + K * math.sqrt(h / 12) * rng.standard_normal(n)


_ALIAS = None


def _alias_factor(x):
    """S_avg,aliased(f) / (h_-1/f) for the average over h of a continuous 1/f process, sampled
    at 1/h: sum_k |x|/|x+k| sinc^2(x+k), x = f h in (0, 1/2]."""
    global _ALIAS
    if _ALIAS is None:
        xs = np.linspace(1e-6, 0.5, 4001)
        ks = np.arange(-2000, 2001)[:, None]
        z = xs[None, :] + ks
        _ALIAS = (xs, np.sum(xs[None, :] / np.abs(z) * np.sinc(z) ** 2, axis=0))
    return np.interp(x, _ALIAS[0], _ALIAS[1])


def sim_flicker(n, h, F, rng, mode="sampled"):
    L = 2 * n
    hm1 = F * F / (2 * math.log(2))
    f = np.fft.rfftfreq(L, h)
    df = 1.0 / (L * h)
    S = np.zeros_like(f)
    S[1:] = hm1 / f[1:]
    S[-1] = 0.0
    if mode == "averaged":
        S[1:] *= _alias_factor(f[1:] * h)
    amp = (L / 2) * np.sqrt(S * df)
    Y = amp * (rng.standard_normal(f.size) - 1j * rng.standard_normal(f.size))
    x = np.fft.irfft(Y, n=L)
    return x[:n]


def sim_gm_sampled(n, h, s, tc, rng):
    phi = math.exp(-h / tc)
    w = rng.standard_normal(n) * s * math.sqrt(-math.expm1(-2 * h / tc))
    return ar1(w, phi, rng.standard_normal() * s)[:-1]


def simulate(truth, seed):
    flicker_mode = truth.get("flicker_mode", "sampled")
    gm_mode = truth.get("gm_mode", "averaged")
    rng = np.random.default_rng(seed)
    h = 1.0 / truth["rate_hz"]
    n = int(round(truth["duration_s"] * truth["rate_hz"]))
    y = np.full(n, truth["bias"])
    quant = None
    for t in truth["terms"]:
        k = t["type"]
        if k == "white":
            y += rng.standard_normal(n) * t["N"] / math.sqrt(h)
        elif k == "gm":
            if gm_mode == "sampled":
                y += sim_gm_sampled(n, h, t["sigma"], t["tau"], rng)
            else:
                y += sim_gm_avg(n, h, t["sigma"], t["tau"], rng)
        elif k == "random_walk":
            y += sim_rw_avg(n, h, t["K"], rng)
        elif k == "flicker":
            y += sim_flicker(n, h, t["floor"], rng, flicker_mode)
        elif k == "quantization":
            quant = t["lsb_angle"]
    if quant is not None:
        theta = np.concatenate([[rng.uniform(0, quant)], np.cumsum(y * h)])  # random start phase
        # rounding of the absolute angle, then differenced: output on the lattice D/h
        qi = np.round(theta / quant)
        y = np.diff(qi) * (quant / h)
    return y


def record_seed(case, rate, duration, idx, base=20261203):
    return int(base + 1000003 * CASE_ID[case] + 10007 * RATE_ID[float(rate)]
               + 101 * (1 if duration > 3000 else 0) + 7919 * idx)


def make(case, rate, duration, idx, outdir, gz=False, flicker_mode="sampled", gm_mode="averaged"):
    seed = record_seed(case, rate, duration, idx)
    rng = np.random.default_rng(seed)
    truth = draw_truth(case, float(rate), float(duration), rng)
    truth["flicker_mode"] = flicker_mode
    truth["gm_mode"] = gm_mode
    truth["seed"] = seed
    truth["index"] = idx
    y = simulate(truth, seed + 1)
    name = "%s_%gHz_%gs_%03d" % (case.replace("+", "-"), rate, duration, idx)
    os.makedirs(outdir, exist_ok=True)
    path = os.path.join(outdir, name + (".csv.gz" if gz else ".csv"))
    write_csv(path, y / DEG, rate)
    truth["record"] = path
    with open(os.path.join(outdir, name + ".truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
    return path, truth


def write_csv(path, gx_degs, rate):
    """One column `gx` in deg/s, no time column (give `--rate` to sinsim); 10 significant
    digits, far below any LSB used here."""
    op = gzip.open if path.endswith(".gz") else open
    with op(path, "wt") as f:
        f.write("gx\n")
        f.write(("%.9e\n" * gx_degs.size) % tuple(gx_degs.tolist()))


# ---------------------------------------------------------------- self test
def oadev(y, h, ms):
    x = np.concatenate([[0.0], np.cumsum(y) * h])
    out = []
    for m in ms:
        d = x[2 * m:] - 2 * x[m:-m] + x[:-2 * m]
        out.append(math.sqrt(np.mean(d * d) / (2 * (m * h) ** 2)))
    return np.array(out)


def selftest():
    for case in CASES:
        for (rate, dur) in [(100.0, 1200.0), (1000.0, 1200.0)]:
            rs = []
            for idx in range(6):
                seed = record_seed(case, rate, dur, 900 + idx)
                truth = draw_truth(case, rate, dur, np.random.default_rng(seed))
                y = simulate(truth, seed + 1)
                h = 1 / rate
                n = y.size
                ms = np.unique(np.round(np.exp(np.linspace(0, math.log(n / 10), 12))).astype(int))
                taus = ms * h
                a = oadev(y, h, ms)
                th = np.sqrt(sum(term_avar(t, taus) for t in truth["terms"]))
                rs.append(a / th)
            rs = np.array(rs)
            print("%-18s %6g Hz  mean(meas/theory) over tau: %s" % (
                case, rate, " ".join("%.2f" % v for v in np.exp(np.mean(np.log(rs), axis=0)))))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--case", choices=CASES)
    ap.add_argument("--rate", type=float, default=100.0)
    ap.add_argument("--duration", type=float, default=1200.0)
    ap.add_argument("--index", type=int, default=0)
    ap.add_argument("--out", default="/tmp/fit_blind/records")
    ap.add_argument("--gz", action="store_true")
    ap.add_argument("--selftest", action="store_true")
    ap.add_argument("--flicker-mode", choices=["sampled", "averaged"], default="sampled",
                    help="sampled: 1/f PSD up to Nyquist (default, the main run); averaged: the "
                         "interval average of a continuous 1/f process (aliased sinc^2 spectrum)")
    ap.add_argument("--gm-mode", choices=["averaged", "sampled"], default="averaged",
                    help="averaged: interval average of the continuous GM (default); sampled: point "
                         "samples (exact AR(1))")
    a = ap.parse_args()
    if a.selftest:
        selftest()
        return
    p, t = make(a.case, a.rate, a.duration, a.index, a.out, a.gz, a.flicker_mode, a.gm_mode)
    print(p)
    print(json.dumps(t, indent=1))


if __name__ == "__main__":
    main()
