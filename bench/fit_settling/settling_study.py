#!/usr/bin/env python3
"""The start-settling warning of `sinsim fit` (errormodels/fit/start_settling.hpp) on issue 11's
round-trip records (bench/latent_study/generate.py, NumPy only, written for the latent fit long
before this test), plain and with an exponential settling A exp(-t / tau_w) added.

tau_w is log-uniform in [T / 300, T / 20]; A (either sign) makes the settling's largest ratio of
overlapping Allan deviation to the plain record's, over octaves of tau up to T / 10, equal --size
(issue 12's sizing of a hidden effect). Each record is fitted with `--kind latent` (the default
--lines fit); the settling one again with the --skip the warning suggests. Counts per case:
  plain       records warned of a settling (false warnings)
  settling    records warned, with the warned tau within a factor 3 of tau_w
  right set   the written noise terms equal the generator's: plain / with the settling / refitted
              with the suggested --skip (where one was suggested, else the same fit)

  /usr/bin/python3 bench/latent_study/generate.py --rate 100 --duration 1200 --seeds 40 \\
      | /usr/bin/python3 bench/fit_settling/settling_study.py --size 3 --work /tmp/settling
"""
import argparse, math, os, re, subprocess, sys
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "latent_study"))
sys.path.insert(0, os.path.join(HERE, "..", "fit_lines"))
from auto_grid import records  # noqa: E402  (the generator's stream: a JSON line, then n float64)
from latent_lines import truth_terms, written  # noqa: E402

WARN = re.compile(r"settling: (\S+) (\S+) decaying with tau (\S+) s.*?z (\S+),.*?--skip (\S+) \(s\)")


def adev(x, m):
    """Overlapping Allan deviation of x at m samples (NumPy, from the cumulative sum)."""
    c = np.concatenate([[0.0], np.cumsum(x)])
    d = c[2 * m:] - 2 * c[m:-m] + c[:-2 * m]
    return math.sqrt(np.mean(d * d) / (2.0 * m * m))


def fit(sinsim, csv, out, skip=None):
    cmd = [sinsim, "fit", csv, "--kind", "latent", "-o", out]
    if skip is not None:
        cmd += ["--skip", str(skip)]
    r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, check=True)
    m = WARN.search(r.stderr)
    terms, _ = written(out)
    return terms, (None if not m else {"tau": float(m.group(3)), "z": float(m.group(4)), "skip": float(m.group(5))})


def one(a, i, meta, x):
    rng = np.random.default_rng([a.seed, i])
    rate, n = meta["rate"], meta["n"]
    t = np.arange(n) / rate
    T = n / rate
    tau_w = math.exp(rng.uniform(math.log(T / 300), math.log(T / 20)))
    shape = np.exp(-(t + 0.5 / rate) / tau_w)
    ms = [2 ** k for k in range(int(math.log2(n / 10)) + 1)]
    ratio = max(adev(shape, m) / adev(x, m) for m in ms)
    A = a.size / ratio * (1 if rng.random() < 0.5 else -1)
    y = x + A * shape
    d = os.path.join(a.work, f"r{i}")
    os.makedirs(d, exist_ok=True)
    res = {"case": meta["case"], "truth": truth_terms(meta), "tau_w": tau_w}
    for name, series in (("plain", x), ("settling", y)):
        csv = os.path.join(d, f"{name}.csv")
        np.savetxt(csv, np.column_stack([t, series]), delimiter=",", fmt="%.12g",
                   header="t[s],gx[rad/s]", comments="")
        res[name] = fit(a.sinsim, csv, os.path.join(d, f"{name}.yaml"))
        if name == "settling":
            w = res[name][1]
            res["skipped"] = fit(a.sinsim, csv, os.path.join(d, "skipped.yaml"), w["skip"]) if w else res[name]
        os.remove(csv)
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--work", default="/tmp/settling")
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--size", type=float, default=3.0)
    ap.add_argument("--seed", type=int, default=5)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    score = defaultdict(lambda: defaultdict(int))
    with ThreadPoolExecutor(a.jobs) as pool:
        futures = [pool.submit(one, a, i, meta, x.copy()) for i, (meta, x) in enumerate(records(sys.stdin.buffer))]
        for k, f in enumerate(futures):
            r = f.result()
            s = score[r["case"]]
            s["n"] += 1
            s["false"] += r["plain"][1] is not None
            w = r["settling"][1]
            s["found"] += w is not None and abs(math.log(w["tau"] / r["tau_w"])) <= math.log(3)
            s["warned"] += w is not None
            for name in ("plain", "settling", "skipped"):
                s["right " + name] += r[name][0] == r["truth"]
            print(f"record {k + 1}: {r['case']} tau_w {r['tau_w']:.3g} s, plain {r['plain'][1]}, "
                  f"settling {w}", file=sys.stderr, flush=True)
    print(f"size {a.size}: case | plain warned | settling warned (tau within 3x) | right set plain / "
          "with the settling / refitted with the suggested --skip")
    tot = defaultdict(int)
    for case in sorted(score):
        s = score[case]
        for k, v in s.items():
            tot[k] += v
        print(f"{case} | {s['false']}/{s['n']} | {s['warned']} ({s['found']})/{s['n']} | "
              f"{s['right plain']} / {s['right settling']} / {s['right skipped']}")
    print(f"all | {tot['false']}/{tot['n']} | {tot['warned']} ({tot['found']})/{tot['n']} | "
          f"{tot['right plain']} / {tot['right settling']} / {tot['right skipped']}")


if __name__ == "__main__":
    main()
