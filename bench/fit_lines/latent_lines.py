#!/usr/bin/env python3
"""Issue 11's round-trip records (bench/latent_study/generate.py, NumPy only, written in an earlier
session for the latent fit) with one or two point-sampled lines added (0.3 Hz .. 0.4 x rate, or
--line-freq, log-uniform; amplitude --line-size x the record's sample sd, random phase), fitted by `sinsim fit --kind latent`
with `--lines fit` (the default) and `--lines warn`. Counts, per case, the records whose written
noise terms are the generator's term set, and the lines written (frequency within 2 / T of a true
one) and written where there is none.

  /usr/bin/python3 bench/latent_study/generate.py --rate 100 --duration 1200 --seeds 20 \\
      | /usr/bin/python3 bench/fit_lines/latent_lines.py --work /tmp/latent_lines
  (lines below the fit's Welch reach at 20 min, 100 Hz: --line-freq 0.01 0.29)
"""
import argparse, math, os, re, subprocess, sys
from collections import defaultdict
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "latent_study"))
from auto_grid import records  # noqa: E402  (the generator's stream: a JSON line, then n float64)

TYPES = {"white": "white", "gauss_markov": "gm", "random_walk": "random_walk",
         "bias_instability": "flicker", "quantization": "quantization", "ramp": "drift"}


def written(path):
    terms, lines = defaultdict(int), []
    for line in open(path):
        m = re.search(r"- \{type: (\w+)", line)
        if not m:
            continue
        t = m.group(1)
        if t == "sinusoid":
            lines.append(float(re.search(r"frequency: ([-+0-9.eE]+) Hz", line).group(1)))
        else:
            terms[TYPES.get(t, t)] += 1
    return dict(terms), lines


def truth_terms(meta):
    t = meta["terms"]
    out = {}
    for k in ("quantization", "white", "flicker", "random_walk", "drift"):
        if t.get(k):
            out[k] = 1
    if t.get("gm"):
        out["gm"] = int(t["gm"])
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--work", default="/tmp/latent_lines")
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--line-size", type=float, nargs=2, default=[0.5, 3.0], metavar=("LO", "HI"))
    ap.add_argument("--line-freq", type=float, nargs=2, default=[0.3, 0.0], metavar=("LO", "HI"),
                    help="line frequency range [Hz] (HI 0: 0.4 x rate)")
    ap.add_argument("--seed", type=int, default=7)
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    score = defaultdict(lambda: defaultdict(int))
    for i, (meta, x) in enumerate(records(sys.stdin.buffer)):
        rng = np.random.default_rng([a.seed, i])
        rate, n = meta["rate"], meta["n"]
        t = np.arange(n) / rate
        sd = float(np.std(x))
        y = x.copy()
        true_lines = []
        for _ in range(int(rng.integers(1, 3))):
            hi = a.line_freq[1] if a.line_freq[1] > 0 else 0.4 * rate
            f = math.exp(rng.uniform(math.log(a.line_freq[0]), math.log(hi)))
            y += rng.uniform(*a.line_size) * sd * np.sin(2 * math.pi * f * t + rng.uniform(0, 2 * math.pi))
            true_lines.append(f)
        csv = os.path.join(a.work, "r.csv")
        for name, series in (("plain", x), ("lines", y)):
            np.savetxt(csv, np.column_stack([t, series]), delimiter=",", fmt="%.12g",
                       header="t[s],gx[rad/s]", comments="")
            for mode in ("fit", "warn"):
                if name == "plain" and mode == "warn":
                    continue
                out = os.path.join(a.work, f"m-{name}-{mode}.yaml")
                subprocess.run([a.sinsim, "fit", csv, "--kind", "latent", "--lines", mode, "-o", out, "-q"],
                               check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                terms, lines = written(out)
                s = score[(meta["case"], name, mode)]
                s["n"] += 1
                s["right"] += terms == truth_terms(meta)
                T = n / rate
                if name == "lines":
                    s["lines"] += len(true_lines)
                    s["found"] += sum(any(abs(f - g) <= 2 / T for g in lines) for f in true_lines)
                    s["false"] += sum(not any(abs(f - g) <= 2 / T for f in true_lines) for g in lines)
                else:
                    s["false"] += len(lines)
        print(f"record {i + 1}", file=sys.stderr, flush=True)
    print("case | plain record, --lines fit: right set (lines written) | with lines, fit: right set, "
          "lines found, not there | with lines, warn: right set")
    for case in sorted({k[0] for k in score}):
        p, f, w = score[(case, "plain", "fit")], score[(case, "lines", "fit")], score[(case, "lines", "warn")]
        print(f"{case} | {p['right']}/{p['n']} ({p['false']}) | {f['right']}/{f['n']}, {f['found']}/{f['lines']}, "
              f"{f['false']} | {w['right']}/{w['n']}")


if __name__ == "__main__":
    main()
