#!/usr/bin/env python3
"""Compare the white-density (and other) coverage of the main run with the convention-study runs
(same seeds, other discretisation): usage conv_compare.py MAIN_WORK CONV_WORK [CONV_WORK ...]"""
import json, sys, os
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate as gen  # noqa: E402


def load(work):
    rows = {}
    for l in open(os.path.join(work, "results.jsonl")):
        r = json.loads(l)
        if r["kind"] == "latent":
            rows[(r["case"], r["rate"], r["duration"], r["index"])] = r
    return rows


main = load(sys.argv[1])
for cw in sys.argv[2:]:
    conv = load(cw)
    mode = next(iter(conv.values()))
    print("\n## %s (flicker %s, gm %s) vs main run, same seeds, latent" % (cw, mode.get("flicker_mode"), mode.get("gm_mode")))
    print("| case | run | right set | param | covered (±σ) | mean z | median est/truth |")
    print("|---|---|---|---|---|---|---|")
    for case in sorted(set(k[0] for k in conv)):
        for name, rows in (("main", main), ("conv", conv)):
            keys = [k for k in conv if k[0] == case and k in main]
            rr = [rows[k] for k in keys]
            right = sum(1 for r in rr if r.get("right"))
            by = {}
            for r in rr:
                if r.get("right"):
                    for x in r["checks"]:
                        if "z" in x:
                            by.setdefault(x["term"] + "." + x["param"], []).append(x)
            for p, xs in sorted(by.items()):
                k = sum(1 for x in xs if x["cover2"])
                print("| %s | %s | %d/%d | %s | %d/%d | %+.2f | %.4f |" % (
                    case, name, right, len(rr), p, k, len(xs), np.mean([x["z"] for x in xs]),
                    np.median([x["ratio"] for x in xs])))
# white z against the shortest GM tau (main run), in samples
print("\n## main run, latent, right set: white-density z against the shortest GM tau / h")
bins = [(20, 40), (40, 100), (100, 1000), (1000, 1e9)]
acc = {b: [] for b in bins}
for k, r in main.items():
    if not r.get("right") or "gm" not in r["case"]:
        continue
    t = gen.draw_truth(r["case"], r["rate"], r["duration"], np.random.default_rng(r["seed"]))
    tcs = [x["tau"] for x in t["terms"] if x["type"] == "gm"]
    m = min(tcs) * r["rate"]
    z = [x["z"] for x in r["checks"] if x["param"] == "density" and "z" in x]
    for b in bins:
        if b[0] <= m < b[1] and z:
            acc[b].append(z[0])
print("| tau_min / h | n | mean z | covered |")
print("|---|---|---|---|")
for b in bins:
    v = np.array(acc[b])
    if len(v):
        print("| %g–%g | %d | %+.2f | %d/%d |" % (b[0], b[1], len(v), v.mean(), np.sum(np.abs(v) <= 2), len(v)))
