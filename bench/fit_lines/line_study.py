#!/usr/bin/env python3
"""Does `sinsim fit` take a record's narrow lines out before fitting its noise terms, and does that
help? Records made here with NumPy alone (no sinsim code): on each gyro channel white noise plus a
first-order Gauss-Markov bias (tau 2-60 s, its Allan hump 3-10x the white noise's Allan deviation
at 1.89 tau), and 0, 1 or 2 point-sampled lines at 0.3 Hz .. 0.4 x rate (--line-freq; log-uniform)
with amplitude 0.05-0.5 x the white noise's sample sd (--line-size). Each record is fitted twice
with `fit --kind gm` (white + GM, + random walk where selected): `--lines fit` (the default) and
`--lines warn` (lines left in); with --before, a third time by that binary with `--lines fit`.

Per channel it counts: the term set white + gm chosen; the GM's tau and sigma within 2 of their
stated 1-sigma of the truth; lines found (frequency within 2 Fourier spacings 1/T of a true one) and
their sampled amplitude within 20 %; lines written that are not there.

  /usr/bin/python3 bench/fit_lines/line_study.py --records 60 --rate 100 --work /tmp/lines100
  /usr/bin/python3 bench/fit_lines/line_study.py --records 60 --rate 100 --line-freq 0.01 0.29 \
      --line-size 0.1 1 --work /tmp/lowlines     # below the fit's Welch reach at 20 min
"""
import argparse, json, math, os, re, subprocess, sys
import numpy as np
from scipy.signal import lfilter


def gm_sigma_for(k, white_density, T):
    # GM Allan deviation peaks at tau = 1.89 T at 0.617 sigma; white's there is N / sqrt(tau).
    return k * white_density / math.sqrt(1.89 * T) / 0.617


def make(seed, rate, seconds, size, freq):
    rng = np.random.default_rng(seed)
    n = int(round(rate * seconds))
    dt = 1.0 / rate
    t = np.arange(n) * dt
    N = 0.01  # deg/s/sqrt(Hz)
    sd = N * math.sqrt(rate)
    cols, truth = [], []
    for c in range(3):
        T = math.exp(rng.uniform(math.log(2), math.log(60)))
        k = rng.uniform(3, 10)
        s = gm_sigma_for(k, N, T)
        phi = math.exp(-dt / T)
        w = rng.normal(0, s * math.sqrt(1 - phi * phi), n)
        w[0] = rng.normal(0, s)
        gm = lfilter([1.0], [1.0, -phi], w)
        y = rng.normal(0, sd, n) + gm
        lines = []
        for _ in range(int(rng.integers(0, 3))):
            f = math.exp(rng.uniform(math.log(freq[0]), math.log(freq[1] if freq[1] > 0 else 0.4 * rate)))
            A = rng.uniform(size[0], size[1]) * sd
            ph = rng.uniform(0, 2 * math.pi)
            y += A * np.sin(2 * math.pi * f * t + ph)
            lines.append({"f": f, "A": A})
        cols.append(y)
        truth.append({"tau": T, "sigma": s, "k": k, "lines": lines})
    acc = rng.normal(0, 1e-3, (n, 3))
    data = np.column_stack([t] + cols + [acc[:, 0], acc[:, 1], acc[:, 2]])
    return data, truth


NUM = r"([-+0-9.eE]+)"


def parse(path, rate):
    """Per gyro axis: terms, GM sigma/tau with 1-sigma, lines (frequency, sampled amplitude)."""
    out, axis = {}, None
    text = open(path).read()
    sec = text[text.index("\ngyro:"):]
    sec = sec[:sec.index("\naccel:")] if "\naccel:" in sec else sec
    for line in sec.splitlines():
        m = re.match(r"^  ([xyz]):", line)
        if m:
            axis = m.group(1)
            out[axis] = {"types": [], "lines": []}
            continue
        if axis is None:
            continue
        a = out[axis]
        m = re.search(r"# gm1: sigma \+- " + NUM + r" deg/s .*tau \+- " + NUM + " s", line)
        if m:
            a["sigma_sd"], a["tau_sd"] = float(m.group(1)), float(m.group(2))
        m = re.search(r"- \{type: (\w+)", line)
        if m:
            a["types"].append(m.group(1))
        m = re.search(r"type: gauss_markov, sigma: " + NUM + r" deg/s, tau: " + NUM + " s", line)
        if m:
            a["sigma"], a["tau"] = float(m.group(1)), float(m.group(2))
        m = re.search(r"type: sinusoid, amplitude: " + NUM + r" deg/s, frequency: " + NUM + " Hz", line)
        if m:
            A, f = float(m.group(1)), float(m.group(2))
            x = math.pi * f / rate
            a["lines"].append({"f": f, "A": A * math.sin(x) / x})
    return out


def judge(fit, tr, seconds):
    r = {}
    r["set"] = sorted(t for t in fit["types"] if t != "sinusoid") == ["gauss_markov", "white"]
    r["tau_ok"] = "tau" in fit and abs(fit["tau"] - tr["tau"]) <= 2 * fit.get("tau_sd", 0)
    r["sigma_ok"] = "sigma" in fit and abs(fit["sigma"] - tr["sigma"]) <= 2 * fit.get("sigma_sd", 0)
    r["tau_ratio"] = fit["tau"] / tr["tau"] if "tau" in fit else None
    found, amp_ok, used = 0, 0, set()
    for L in tr["lines"]:
        for j, F in enumerate(fit["lines"]):
            if j not in used and abs(F["f"] - L["f"]) <= 2 / seconds:
                used.add(j)
                found += 1
                amp_ok += abs(F["A"] / L["A"] - 1) <= 0.2
                break
    r["lines_true"], r["lines_found"], r["amp_ok"] = len(tr["lines"]), found, amp_ok
    r["lines_false"] = len(fit["lines"]) - len(used)
    return r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--records", type=int, default=60)
    ap.add_argument("--rate", type=float, default=100.0)
    ap.add_argument("--seconds", type=float, default=1200.0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--line-size", type=float, nargs=2, default=[0.05, 0.5], metavar=("LO", "HI"),
                    help="line amplitude range, in units of the white noise's sample sd")
    ap.add_argument("--line-freq", type=float, nargs=2, default=[0.3, 0.0], metavar=("LO", "HI"),
                    help="line frequency range [Hz] (HI 0: 0.4 x rate)")
    ap.add_argument("--before", default=None, help="another sinsim binary, fitted with --lines fit as 'before'")
    ap.add_argument("--work", default="/tmp/line_study")
    ap.add_argument("--sinsim", default="build/sinsim")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    rows = []
    for i in range(a.records):
        seed = a.seed * 100000 + i
        data, truth = make(seed, a.rate, a.seconds, a.line_size, a.line_freq)
        csv = os.path.join(a.work, "r%04d.csv" % i)
        np.savetxt(csv, data, delimiter=",", fmt="%.9g",
                   header="t[s],gx[deg/s],gy[deg/s],gz[deg/s],ax[g],ay[g],az[g]", comments="")
        res = {}
        runs = [("fit", a.sinsim, "fit"), ("warn", a.sinsim, "warn")] + ([("before", a.before, "fit")] if a.before else [])
        for mode, binary, lines in runs:
            out = os.path.join(a.work, "r%04d-%s.yaml" % (i, mode))
            subprocess.run([binary, "fit", csv, "--kind", "gm", "--axes", "gx,gy,gz", "--lines", lines,
                            "-o", out, "--quiet"], check=True, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
            res[mode] = parse(out, a.rate)
        os.remove(csv)
        for c, ax in enumerate("xyz"):
            rows.append({"record": i, "axis": ax, "truth": truth[c],
                         **{mode: judge(res[mode][ax], truth[c], a.seconds) for mode in res}})
        print("record %d/%d" % (i + 1, a.records), file=sys.stderr, flush=True)
    json.dump(rows, open(os.path.join(a.work, "results.json"), "w"), indent=1)
    report(rows)


def report(rows):
    for label, sel in (("channels with lines", lambda r: r["truth"]["lines"]),
                       ("channels without", lambda r: not r["truth"]["lines"])):
        rs = [r for r in rows if sel(r)]
        if not rs:
            continue
        print("%s: %d" % (label, len(rs)))
        for mode in [m for m in ("fit", "warn", "before") if m in rs[0]]:
            n = len(rs)
            s = sum(r[mode]["set"] for r in rs)
            t = sum(r[mode]["tau_ok"] for r in rs)
            g = sum(r[mode]["sigma_ok"] for r in rs)
            lt = sum(r[mode]["lines_true"] for r in rs)
            lf = sum(r[mode]["lines_found"] for r in rs)
            la = sum(r[mode]["amp_ok"] for r in rs)
            fa = sum(r[mode]["lines_false"] for r in rs)
            print("  %-6s white+gm %d/%d, tau within 2 sd %d/%d, sigma within 2 sd %d/%d, "
                  "lines found %d/%d (amplitude within 20 %%: %d), lines not there %d"
                  % (mode, s, n, t, n, g, n, lf, lt, la, fa))


if __name__ == "__main__":
    main()
