#!/usr/bin/env python3
"""False settling warnings of `sinsim fit` on records without a settling, from the diagnosis
challenge's three generators (bench/diagnose_challenge/generate.py, generate_alt.py,
generate_third.py: NumPy/SciPy, written for the diagnosis without this test in view) with their
null option: six channels per record, bases white + GM, white + walk + flicker, random stable AR(p)
and the others' own families, rates 50 Hz - 2 kHz, 20 min - 4 h capped at --max-samples.

Each record is fitted with --kind latent and --kind gm; a channel counts when fit warns of a
settling on it (a warning names the channel). The AR bases are where --kind latent approximates
the record with the terms it has.

  /usr/bin/python3 bench/fit_settling/null_records.py --generator main --records 40 --work /tmp/null
"""
import argparse, os, re, subprocess, sys
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "diagnose_challenge"))
import challenge  # noqa: E402

WARN = re.compile(r"warning: (\w\w): the record starts with a settling: .*?tau (\S+) s.*?z (\S+),")


def one(a, i):
    rng = np.random.default_rng([a.seed, i])
    if a.generator == "main":
        row = challenge.make(rng, i, a.work, a.max_samples, null=True)
    else:
        row = challenge.gen_module(a.generator).make(rng, i, a.work, a.max_samples, None, True)
    out = {"rate": row["rate_hz"], "samples": row["samples"], "kinds": {}}
    for kind in a.kinds.split(","):
        r = subprocess.run([a.sinsim, "fit", row["record"], "--kind", kind, "-o", row["record"][:-4] + f".{kind}.yaml"],
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        out["kinds"][kind] = {"error": r.returncode != 0, "warned": WARN.findall(r.stderr)}
    os.remove(row["record"])
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--generator", default="main", choices=["main", "alt", "third"])
    ap.add_argument("--records", type=int, default=40)
    ap.add_argument("--seed", type=int, default=3)
    ap.add_argument("--max-samples", type=int, default=400000)
    ap.add_argument("--kinds", default="latent,gm")
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--work", default="/tmp/settling_null")
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    count = defaultdict(lambda: defaultdict(int))
    with ThreadPoolExecutor(a.jobs) as pool:
        for k, r in enumerate(pool.map(lambda i: one(a, i), range(a.records))):
            for kind, v in r["kinds"].items():
                c = count[kind]
                c["records"] += 1
                c["errors"] += v["error"]
                c["channels"] += 0 if v["error"] else 6
                c["warned"] += len(v["warned"])
            print(f"record {k}: {r['rate']:g} Hz, {r['samples']} samples: "
                  + "; ".join(f"{kind} {v['warned'] or '-'}" for kind, v in r["kinds"].items()),
                  file=sys.stderr, flush=True)
    for kind, c in count.items():
        print(f"{a.generator} --kind {kind}: settling warned on {c['warned']}/{c['channels']} channels "
              f"({c['records']} records, {c['errors']} fits failed)")


if __name__ == "__main__":
    main()
